#include "app/viewer/panels/edit_context.hpp"

#include "app/viewer/actions.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {

EditContext::EditContext(ViewerState& state) : state_(&state) {}

const Document& EditContext::doc() const {
  return state_->doc();
}

const editor::EditSession& EditContext::session() const {
  return state_->session;
}

editor::Selection& EditContext::selection() const {
  return state_->selection;
}

int EditContext::selected() const {
  return state_->selected();
}

const editor::ViewStates& EditContext::views() const {
  return state_->views;
}

bool EditContext::run_edit(const std::string& label, const editor::EditSession::Operation& operation) const {
  return viewer::run_edit(*state_, label, operation);
}

void EditContext::continuous_item(bool changed, const std::string& label,
                                  const editor::EditSession::Operation& operation) const {
  ViewerState& s = *state_;
  if (ImGui::IsItemActivated()) s.session.begin_step(label);
  if (changed) {
    if (!s.session.in_step()) s.session.begin_step(label);
    apply_continuous(s, operation);
  }
  if (ImGui::IsItemDeactivated() && !s.point_drag.active) s.session.end_step();
}

void EditContext::set_evaluation(const EvaluationOptions& options) const {
  viewer::set_evaluation(*state_, options);
}

TypedNumber& EditContext::typed_number() const {
  return state_->fields.typed_number;
}

std::string& EditContext::error() const {
  return state_->error;
}

std::string& EditContext::status() const {
  return state_->status;
}

ItemPositions* EditContext::item_positions() const {
  return state_->item_positions;
}

}  // namespace sweep::viewer::panels
