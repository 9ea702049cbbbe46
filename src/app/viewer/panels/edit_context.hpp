#pragma once
// What a panel that edits the document sees of the viewer: the document and its session (to
// read), the selection, undoable edits, the evaluation options, the number being typed, the
// messages and the scripted tests' marks. Not the camera, the display, the files, the other
// panels' fields or the view's input: a panel that edits the document cannot reach them.
#include "app/viewer/state/panel_fields.hpp"
#include "editor/edit_session.hpp"
#include "editor/view_state.hpp"
#include "model/evaluation/scene.hpp"

#include <string>
#include <string_view>

namespace sweep::viewer {
struct ViewerState;
class ItemPositions;
}  // namespace sweep::viewer

namespace sweep::viewer::panels {

class EditContext {
 public:
  /// Implicit: a panel is called with the viewer's state (main_window.cpp, tests) and keeps this.
  EditContext(ViewerState& state);

  const Document& doc() const;
  const editor::EditSession& session() const;
  editor::Selection& selection() const;
  /// The selected object's index, or -1.
  int selected() const;
  const editor::ViewStates& views() const;
  /// One undoable edit (actions.hpp's run_edit); its error goes to the Error panel.
  bool run_edit(const std::string& label, const editor::EditSession::Operation& operation) const;
  /// For the last ImGui item: one undo step from its activation to its deactivation, with
  /// `operation` applied whenever `changed` says the value changed.
  void continuous_item(bool changed, const std::string& label, const editor::EditSession::Operation& operation) const;
  /// Re-evaluates the scene with `options` (actions.hpp's set_evaluation).
  void set_evaluation(const EvaluationOptions& options) const;
  /// The number field being typed in, whichever panel it is in.
  TypedNumber& typed_number() const;
  /// The Error panel's message and the status line's.
  std::string& error() const;
  std::string& status() const;
  /// Where scripted tests ask named widgets to be recorded (null: nobody asked).
  ItemPositions* item_positions() const;

 private:
  ViewerState* state_;
};

/// The same as the context's members, for panels written as functions of it.
inline bool run_edit(const EditContext& c, const std::string& label, const editor::EditSession::Operation& operation) {
  return c.run_edit(label, operation);
}
inline void set_evaluation(const EditContext& c, const EvaluationOptions& options) {
  c.set_evaluation(options);
}

/// For scripted tests: records where a click lands on the last ImGui item (the centre of its
/// frame-high square at the left, a checkbox's box) as `name`. Does nothing unless a script asked
/// (`positions` set), so normal frames pay only the null check. panel_support.cpp
void mark_item(ItemPositions* positions, std::string_view name);
inline void mark_item(const EditContext& c, std::string_view name) {
  mark_item(c.item_positions(), name);
}
/// The same for the current window: its lower-left corner.
void mark_window(ItemPositions* positions, std::string_view name);
inline void mark_window(const EditContext& c, std::string_view name) {
  mark_window(c.item_positions(), name);
}

}  // namespace sweep::viewer::panels
