#pragma once
// The parts of the viewer's state each panel is handed: what it shows and what it edits, and
// nothing else. A panel that edits the document is an EditContext (edit_context.hpp) with its own
// parts beside it. Each is built from the viewer's state where the panel is called (implicitly, so
// main_window.cpp and the tests call a panel with the state), and a panel that is drawn inside
// another is handed its parts by that one. The viewer-level panels (File, Display, the timeline,
// the questions, the browser) are not here: they run actions on the whole state (actions.hpp).
#include "app/viewer/panels/edit_context.hpp"
#include "app/viewer/state/curve_editing.hpp"
#include "app/viewer/state/panel_fields.hpp"
#include "app/viewer/state/view_requests.hpp"
#include "editor/viewport_layout.hpp"
#include "render/display_settings.hpp"

#include <glm/vec2.hpp>

#include <optional>
#include <string>

namespace sweep::viewer::panels {

/// Objects: the document to list; it changes what is shown and what is selected.
struct ObjectsParts {
  ObjectsParts(ViewerState& s);
  const editor::EditSession& session;
  editor::ViewStates& views;
  editor::Selection& selection;
  const Document& doc() const { return session.document(); }
};

/// Stats: it only reads.
struct StatsParts {
  StatsParts(const ViewerState& s);
  const editor::EditSession& session;
  const editor::ViewStates& views;
  const ViewerStats& stats;
  const Document& doc() const { return session.document(); }
};

/// The Error panel: the message, which Dismiss clears, placed by the layout.
struct ErrorParts {
  ErrorParts(ViewerState& s);
  std::string& error;
  const editor::ViewportLayout& layout;
};

/// The status bar: it only reads.
struct StatusParts {
  StatusParts(const ViewerState& s);
  const std::string& error;
  const std::string& status;
  const editor::ViewportLayout& layout;
  ItemPositions* item_positions;
  const std::optional<glm::dvec2>& cursor;  // shown at the bar's right end
};

/// The Help window: whether it shows (its close button hides it).
struct HelpParts {
  HelpParts(ViewerState& s);
  bool& show_help;
  const editor::ViewportLayout& layout;
  ItemPositions* item_positions;
};

/// Create: edits of the document, and its own fields.
struct CreateParts : EditContext {
  CreateParts(ViewerState& s);
  CreateFields& fields;
};

/// Material: edits of the document's materials, its own fields, and the display's default look
/// (the colour, light and background of surfaces without a material).
struct MaterialParts : EditContext {
  MaterialParts(ViewerState& s);
  MaterialFields& fields;
  render::DisplaySettings& display;
};

/// Edit: edits of the selected object, the Adaptive toggle's tolerance, its own fields (the name
/// row, the split), grid snapping and the curve-editing tools, which it hands to the point table
/// and the curve tools.
struct EditParts : EditContext {
  EditParts(ViewerState& s);
  EditFields& fields;
  double& adaptive_tolerance;
  bool& snap;
  double& snap_size;
  CurveEditing& curve_editing;
};

/// The point table: edits of the selected curve's points, the split's t and grid snapping.
struct PointTableParts : EditContext {
  PointTableParts(ViewerState& s);
  PointTableParts(const EditParts& p);
  double& split_t;
  bool& snap;
  double& snap_size;
};

/// The curve tools: the joint types, the curvature comb and the snap toggles they set.
struct CurveToolParts : EditContext {
  CurveToolParts(ViewerState& s);
  CurveToolParts(const EditParts& p);
  CurveEditing& editing;
};

}  // namespace sweep::viewer::panels
