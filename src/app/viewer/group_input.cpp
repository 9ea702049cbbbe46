#include "app/viewer/group_input.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/curve_actions.hpp"
#include "editor/commands.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/shown_points.hpp"

#include <imgui.h>

#include <string>
#include <utility>

namespace sweep::viewer {
namespace {

constexpr const char* kStepLabels[] = {"grab points", "rotate points", "scale points"};

void apply_moves(ViewerState& s, std::vector<PointMove> moves) {
  const int object = s.session.index_of(s.curve_editing.transform_object);
  if (object < 0 || moves.empty()) return;
  apply_continuous(s, [object, moves = std::move(moves)](Document& d) { return move_shown_points(d, object, moves); });
}

/// Begins a transform of the selected points and their joints' handles. `anchor`: the handle a
/// drag moves them by (its window position `pointer`), else the pointer drives the keys' modes.
void start_transform(ViewerState& s, editor::TransformMode mode, const editor::ScreenMapping& mapping,
                     const glm::dvec2& pointer, std::optional<glm::dvec3> anchor) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr) return;
  editor::PointSelection moving;
  const std::vector<int> points = points_with_handles(s);
  if (points.empty()) return;
  moving.select(points);
  editor::TransformStart start =
      editor::transform_start(mode, shown_points(*curve), moving, is_planar_curve(curve->kind()));
  start.pointer = pointer;
  start.mapping = mapping;
  start.view_forward = s.camera.forward();
  start.anchor = anchor;
  start.grid = s.snap ? s.snap_size : 0.0;  // a dragged selection snaps as a dragged point does
  CurveEditing& editing = s.curve_editing;
  editing.transform.start(std::move(start));
  editing.transform_object = curve->id;
  editing.transform_by_drag = anchor.has_value();
  s.session.begin_step(kStepLabels[static_cast<int>(mode)]);
  s.status = editing.transform.status();
}

void finish_transform(ViewerState& s, bool confirmed) {
  editor::PointTransform& transform = s.curve_editing.transform;
  if (confirmed) {
    apply_moves(s, transform.confirm());
    s.session.end_step();
    s.status = kStepLabels[static_cast<int>(transform.mode())];
  } else {
    transform.cancel();
    s.session.cancel_step();
    s.status = "cancelled";
  }
}

/// X/Y/Z, Backspace, Enter and Esc, and the characters of a typed number. Returns false when
/// the transform ended.
bool transform_keys(ViewerState& s, const std::vector<KeyPress>& keys) {
  editor::PointTransform& transform = s.curve_editing.transform;
  using editor::Key;
  for (const KeyPress& k : keys) {
    const Key key = static_cast<Key>(k.key);
    if (key == Key::X || key == Key::Y || key == Key::Z) transform.toggle_axis(k.key - int(Key::X));
    if (key == Key::Backspace) transform.backspace();
    if (key == Key::Enter || key == Key::KeypadEnter || key == Key::Escape) {
      finish_transform(s, key != Key::Escape);
      return false;
    }
  }
  for (const ImWchar c : ImGui::GetIO().InputQueueCharacters) {
    if (c < 128) transform.type(char(c));
  }
  return true;
}

/// The pointer: moves the points; a click confirms (the release, for a drag), a right click cancels.
void transform_pointer(ViewerState& s, const glm::dvec2& mouse) {
  CurveEditing& editing = s.curve_editing;
  const bool released = editing.transform_by_drag && !ImGui::IsMouseDown(ImGuiMouseButton_Left);
  if (ImGui::IsMousePosValid()) apply_moves(s, editing.transform.update(mouse + editing.transform_grip));
  if (released || (!editing.transform_by_drag && ImGui::IsMouseClicked(ImGuiMouseButton_Left))) {
    finish_transform(s, true);
  } else if (ImGui::IsMouseClicked(ImGuiMouseButton_Right)) {
    finish_transform(s, false);
  } else {
    s.status = editing.transform.status();
  }
}

}  // namespace

bool handle_transform(ViewerState& s, const std::vector<KeyPress>& keys, const editor::ScreenMapping& mapping,
                      const glm::dvec2& mouse) {
  CurveEditing& editing = s.curve_editing;
  if (editing.requested && !editing.transform.active()) {
    editing.transform_grip = glm::dvec2(0.0);
    start_transform(s, *editing.requested, mapping, mouse, std::nullopt);
    editing.requested.reset();
    return editing.transform.active();  // this frame's keys started it
  }
  editing.requested.reset();
  if (!editing.transform.active()) return false;
  if (!transform_keys(s, keys)) return true;
  apply_moves(s, editing.transform.moves());  // a key may have changed the axis or the number
  transform_pointer(s, mouse);
  return true;
}

bool press_on_points(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int handle) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr) return false;
  editor::Selection& selection = s.selection;
  if (ImGui::GetIO().KeyShift && handle >= 0) {
    if (!selection.group.contains(selection.point) && selection.point >= 0) selection.group.click(selection.point);
    selection.group.toggle(handle);
    const int active = selection.group.active();
    selection.point = active >= 0 ? active : selection.group.empty() ? -1 : selection.group.points().front();
    return true;
  }
  if (ImGui::GetIO().KeyShift && s.display.control_points) {
    s.curve_editing.band = {true, mouse, mouse};
    return true;
  }
  if (handle < 0 || selection.points().size() < 2 || !selection.group.contains(handle)) return false;
  const glm::dvec3 anchor = shown_points(*curve)[std::size_t(handle)];
  const std::optional<glm::dvec2> centre = editor::to_screen(mapping, anchor);
  if (!centre) return false;
  s.curve_editing.transform_grip = *centre - mouse;  // the handle keeps its place under the pointer
  start_transform(s, editor::TransformMode::Grab, mapping, *centre, anchor);
  return true;
}

bool continue_rubber_band(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse) {
  RubberBand& band = s.curve_editing.band;
  if (!band.active) return false;
  if (ImGui::IsMousePosValid()) band.to = mouse;
  if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    ImDrawList* draw = ImGui::GetForegroundDrawList();
    const ImVec2 a(float(band.from.x), float(band.from.y));
    const ImVec2 b(float(band.to.x), float(band.to.y));
    draw->AddRectFilled(a, b, IM_COL32(60, 200, 255, 40));
    draw->AddRect(a, b, IM_COL32(60, 200, 255, 220));
    return true;
  }
  band.active = false;
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr) return false;
  const std::vector<int> inside = editor::points_in_rect(mapping, shown_points(*curve), band.from, band.to);
  s.selection.group.select(inside);
  s.selection.point = inside.empty() ? -1 : inside.front();
  s.status = std::to_string(inside.size()) + " points selected";
  return false;
}

}  // namespace sweep::viewer
