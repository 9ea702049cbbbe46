#include "app/viewer/pen_input.hpp"

#include "app/viewer/pen_actions.hpp"
#include "app/viewer/point_input.hpp"
#include "model/document.hpp"

#include <imgui.h>

#include <cmath>
#include <glm/geometric.hpp>

namespace sweep::viewer {
namespace {

constexpr double kCloseRadius = 9.0;    // window units from the first node: a click there closes
constexpr double kDragThreshold = 3.0;  // window units the pointer moves before a press is a drag

/// Where the ray under `mouse` meets the stroke's plane (or the plane the next stroke would use),
/// on the grid when snapping to it, or the snap target nearest the pointer (Ctrl suspends it).
std::optional<glm::dvec3> pen_target(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse) {
  PenTool& pen = s.pen;
  pen.snap.reset();
  const PenPlane plane = pen.drawing() ? pen.plane : pen_plane(s);
  const editor::Ray ray = editor::pointer_ray(mapping, mouse);
  const double along = glm::dot(ray.direction, plane.normal);
  if (std::abs(along) < 1e-12) return std::nullopt;  // looking along the plane
  glm::dvec3 hit = ray.origin + ray.direction * (glm::dot(plane.origin - ray.origin, plane.normal) / along);
  if (s.snap) hit = editor::snap_to_grid(hit, s.snap_size, glm::equal(plane.normal, glm::dvec3(0.0)));
  if (pen.targets && !ImGui::GetIO().KeyCtrl) {
    pen.snap = editor::snap_target(*pen.targets, mapping, mouse, s.curve_editing.snap);
    if (pen.snap) hit = pen.snap->position;
  }
  return hit;
}

/// The first node's window position, when a click there would close the stroke's curve.
std::optional<glm::dvec2> closing_node(const ViewerState& s, const editor::ScreenMapping& mapping,
                                       const glm::dvec2& mouse) {
  if (!s.pen.stroke || s.pen.stroke->nodes().size() < 2) return std::nullopt;
  const std::optional<glm::dvec2> first = editor::to_screen(mapping, s.pen.stroke->nodes().front().at);
  if (!first || glm::length(*first - mouse) > kCloseRadius) return std::nullopt;
  return first;
}

void gather_targets(ViewerState& s) {
  const editor::SnapOptions& options = s.curve_editing.snap;
  if (!options.points && !options.curves && !options.axis) return;
  s.pen.targets = std::make_shared<editor::SnapTargets>(
      editor::gather_snap_targets(s.doc(), s.session.scene(), s.views.visibility(s.doc()), {}));
}

ImVec2 im(const glm::dvec2& p) {
  return ImVec2(float(p.x), float(p.y));
}

}  // namespace

bool pen_key(ViewerState& s, const editor::Shortcut& pressed) {
  using editor::Key;
  const bool plain = !pressed.ctrl && !pressed.shift;
  if (plain && (pressed.key == Key::Enter || pressed.key == Key::KeypadEnter)) {
    pen_finish(s);
    return true;
  }
  if (plain && pressed.key == Key::Escape) {
    if (s.pen.drawing()) {
      pen_finish(s);
    } else {
      toggle_pen(s);
    }
    return true;
  }
  if (s.pen.drawing() && plain && (pressed.key == Key::Backspace || pressed.key == Key::Delete)) {
    pen_take_back(s);
    return true;
  }
  return s.pen.drawing();
}

void pen_pointer(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, bool over_view) {
  PenTool& pen = s.pen;
  if (pen.stroke && !s.session.in_step()) pen_finish(s);  // its step was ended elsewhere (a file opened)
  pen.hover.reset();
  if (pen.holding) {
    if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      pen_release(s);
    } else if (glm::length(mouse - pen.pressed) >= kDragThreshold) {
      if (const auto to = pen_target(s, mapping, mouse)) pen_drag(s, *to);
    }
    return;
  }
  if (!over_view || !ImGui::IsMousePosValid()) return;
  if (!pen.targets) gather_targets(s);
  pen.hover = pen_target(s, mapping, mouse);
  if (!ImGui::IsMouseClicked(ImGuiMouseButton_Left)) return;
  if (closing_node(s, mapping, mouse)) {
    pen_close(s);
    return;
  }
  if (!pen.hover) {
    s.status = "the view looks along the pen's plane: turn it to draw";
    return;
  }
  pen_place(s, *pen.hover);
  pen.holding = pen.drawing();
  pen.pressed = mouse;
}

void draw_pen(const ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse) {
  const PenTool& pen = s.pen;
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  const ImU32 node_colour = IM_COL32(255, 170, 40, 255);
  const ImU32 line_colour = IM_COL32(255, 170, 40, 150);
  std::optional<glm::dvec2> last;
  if (pen.stroke) {
    const PointLayout& layout = point_layout(pen.stroke->kind());
    const bool mirrored = layout.entry(1) == EntryRole::Handle;  // Bezier: both handles; Hermite: one
    const bool shaped = mirrored || layout.entry(1) == EntryRole::Tangent;
    for (const editor::PenNode& node : pen.stroke->nodes()) {
      const std::optional<glm::dvec2> at = editor::to_screen(mapping, node.at);
      if (!at) continue;
      if (last && pen.object == editor::kNoObject) draw->AddLine(im(*last), im(*at), line_colour, 1.5f);
      if (shaped && node.drag != glm::dvec3(0.0)) {
        for (const double side : {1.0, -1.0}) {
          if (side < 0.0 && !mirrored) continue;
          const auto handle = editor::to_screen(mapping, node.at + side * node.drag);
          if (!handle) continue;
          draw->AddLine(im(*at), im(*handle), line_colour, 1.0f);
          draw->AddCircleFilled(im(*handle), 3.5f, node_colour);
        }
      }
      draw->AddRect(ImVec2(float(at->x) - 4.0f, float(at->y) - 4.0f), ImVec2(float(at->x) + 4.0f, float(at->y) + 4.0f),
                    node_colour, 0.0f, 0, 2.0f);
      last = at;
    }
  }
  if (const auto first = closing_node(s, mapping, mouse)) {
    draw->AddCircle(im(*first), 9.0f, IM_COL32(40, 230, 255, 255), 0, 2.0f);
  } else if (pen.hover && !pen.holding) {
    const auto next = editor::to_screen(mapping, *pen.hover);
    if (last && next) draw->AddLine(im(*last), im(*next), line_colour, 1.0f);
    if (next) draw->AddCircle(im(*next), 3.0f, node_colour);
  }
  if (pen.snap) draw_snap_ring(*pen.snap);
}

}  // namespace sweep::viewer
