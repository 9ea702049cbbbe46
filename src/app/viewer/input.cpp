#include "app/viewer/input.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/group_input.hpp"
#include "app/viewer/pen_input.hpp"
#include "app/viewer/point_input.hpp"
#include "editor/point_drag.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/shown_points.hpp"

#include <imgui.h>
#include <imgui_internal.h>  // ClosePopupsExceptModals

#include <cmath>

namespace sweep::viewer {
namespace {

constexpr double kHandlePickRadius = 9.0;  // screen units
constexpr double kCurvePickRadius = 7.0;

/// The handle under the pointer, or -1. Of overlapping handles the nearest to the pointer wins.
int handle_under(const ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& pointer) {
  int best = -1;
  double best_distance = kHandlePickRadius;
  const auto positions = handle_positions(s, mapping);
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!positions[i]) continue;
    const double d = glm::length(*positions[i] - pointer);
    if (d <= best_distance) {
      best_distance = d;
      best = int(i);
    }
  }
  return best;
}

/// Keeps `best` (an object index) if `points` pass nearer the pointer than `best_distance`.
template <typename Points>
void consider(int index, const Points& points, const editor::ScreenMapping& mapping, const glm::dvec2& pointer,
              int& best, double& best_distance) {
  std::optional<glm::dvec2> previous;
  for (const auto& point : points) {
    const std::optional<glm::dvec2> q = editor::to_screen(mapping, point);
    if (q) {
      const double d = previous ? editor::distance_to_segment(pointer, *previous, *q) : glm::length(pointer - *q);
      if (d < best_distance) {
        best_distance = d;
        best = index;
      }
    }
    previous = q;
  }
}

/// The visible curve whose samples (or control polygon, when shown) pass nearest the pointer
/// within kCurvePickRadius, or -1.
int curve_under(const ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& pointer) {
  int best = -1;
  double best_distance = kCurvePickRadius;
  std::vector<glm::dvec3> samples;
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    const Object& object = s.doc().objects[i];
    if (!has_editable_points(object.kind()) && !is_curve(object.kind())) continue;
    if (!s.views.visible(object.id)) continue;
    if (is_curve(object.kind()) && s.display.curves != render::CurveMode::Off) {
      samples.clear();
      for (const Frame& f : s.session.scene().objects[i].curve.frames) samples.push_back(f.V);
      consider(int(i), samples, mapping, pointer, best, best_distance);
    }
    if (s.display.control_points && has_editable_points(object.kind())) {
      consider(int(i), shown_points(object), mapping, pointer, best, best_distance);
    }
  }
  return best;
}

void camera_drag(ViewerState& s, const glm::dvec2& pointer) {
  CameraDrag& drag = s.camera_drag;
  if (!ImGui::IsMouseDown(drag.button) || !ImGui::IsMousePosValid()) {
    // A left click on empty space (no drag) clears the selection.
    if (drag.button == ImGuiMouseButton_Left && !drag.moved) s.selection.clear();
    drag.button = -1;
    return;
  }
  if (pointer == drag.last) return;
  drag.moved = true;
  stop_riding(s, true);  // orbiting leaves the ride, from where the camera is
  const glm::dvec2 from = render::arcball_point(drag.last, s.layout.free_size);
  const glm::dvec2 to = render::arcball_point(pointer, s.layout.free_size);
  const bool pan = drag.button == ImGuiMouseButton_Middle || (drag.button == ImGuiMouseButton_Left && s.profile_view);
  if (pan) {
    s.camera.pan(to - from);  // the profile view stays a front view: its left drag pans
  } else if (drag.button == ImGuiMouseButton_Left) {
    s.camera.arcball_rotate(from, to);
  } else if (drag.button == ImGuiMouseButton_Right) {
    s.camera.zoom(std::exp(2.0 * (from.y - to.y)));  // drag up: closer
  }
  drag.last = pointer;
}

/// A press in the view: a handle starts a point drag, a curve is selected, else a camera drag.
/// With the pen on the left button is the pen's (pen_input.hpp).
void press(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int held_axis) {
  if (!s.pen.on && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left) && s.camera_drag.button < 0 &&
      s.selection.hovered_point < 0 && insert_at_double_click(s, mapping, mouse, kCurvePickRadius)) {
    return;
  }
  if (!s.pen.on && ImGui::IsMouseClicked(ImGuiMouseButton_Left) && s.camera_drag.button < 0) {
    if (press_on_points(s, mapping, mouse, s.selection.hovered_point)) return;
    if (s.selection.hovered_point >= 0) {
      s.selection.group.click(s.selection.hovered_point);
      start_point_drag(s, mapping, mouse, s.selection.hovered_point, held_axis);
      return;
    }
    const int curve = curve_under(s, mapping, mouse);
    if (curve >= 0) {
      s.selection.select(s.session.id_of(curve));
      return;
    }
  }
  for (int button = s.pen.on ? 1 : 0; button < 3; ++button) {
    if (ImGui::IsMouseClicked(button) && s.camera_drag.button < 0) {
      s.camera_drag = {button, false, s.layout.in_free_part(mouse)};
    }
  }
  const float wheel = ImGui::GetIO().MouseWheel;
  if (wheel != 0.0f) {
    stop_riding(s, true);
    s.camera.zoom(std::pow(0.88, double(wheel)));
  }
}

/// Esc closes what is on top, one thing a press: a point drag (cancelled: the point goes back),
/// a camera drag, then the Help window. False when nothing was open (Esc then quits). Menus and
/// popups are ImGui's (interface_was_open); dialogs and the browser take their own Esc.
bool close_top(ViewerState& s) {
  if (s.point_drag.active) {
    s.point_drag = {};
    s.session.cancel_step();
    return true;
  }
  if (s.camera_drag.button >= 0) {
    s.camera_drag.button = -1;
    return true;
  }
  if (s.show_help) {
    s.show_help = false;
    return true;
  }
  return false;
}

}  // namespace

editor::ScreenMapping screen_mapping(const ViewerState& s, glm::ivec2 framebuffer) {
  const double aspect = framebuffer.y > 0 ? double(framebuffer.x) / double(framebuffer.y) : 1.0;
  return editor::screen_mapping(s.camera.projection_matrix(aspect) * s.camera.view_matrix(), s.layout.window);
}

std::vector<std::optional<glm::dvec2>> handle_positions(const ViewerState& s, const editor::ScreenMapping& mapping) {
  std::vector<std::optional<glm::dvec2>> positions;
  if (const Object* curve = selected_control_curve(s)) {
    for (const glm::dvec3& p : shown_points(*curve)) positions.push_back(editor::to_screen(mapping, p));
  }
  return positions;
}

namespace {

/// Where the pointer is on the plane z = 0 of the profile view, if it is over the view.
std::optional<glm::dvec2> profile_cursor(const ViewerState& s, const editor::ScreenMapping& mapping,
                                         const glm::dvec2& mouse) {
  if (!s.profile_view || ImGui::GetIO().WantCaptureMouse || !ImGui::IsMousePosValid()) return std::nullopt;
  const editor::Ray ray = editor::pointer_ray(mapping, mouse);
  if (ray.direction.z == 0.0) return std::nullopt;
  const glm::dvec3 hit = ray.origin - ray.direction * (ray.origin.z / ray.direction.z);
  return glm::dvec2(hit.x, hit.y);
}

}  // namespace

void handle_input(ViewerState& s, editor::CommandTable& commands, const std::vector<KeyPress>& keys, int held_axis,
                  glm::ivec2 framebuffer) {
  const ImGuiIO& io = ImGui::GetIO();
  const editor::ScreenMapping mapping = screen_mapping(s, framebuffer);
  const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
  s.cursor = profile_cursor(s, mapping, mouse);
  // A transform in progress has the keys and the mouse to itself until it ends.
  if (s.curve_editing.transform.active()) {
    handle_transform(s, keys, mapping, mouse);
    return;
  }
  // Keys typed into an ImGui field (or meant for a dialog) belong to it.
  if (!io.WantCaptureKeyboard) {
    for (const KeyPress& k : keys) {
      const editor::Shortcut pressed{static_cast<editor::Key>(k.key), k.ctrl, k.shift};
      const bool plain_escape = pressed.key == editor::Key::Escape && !pressed.ctrl && !pressed.shift;
      if (plain_escape && !s.interface_was_open && close_top(s)) continue;
      if (s.pen.on && !s.interface_was_open && pen_key(s, pressed)) continue;
      if (commands.press(pressed, s.interface_was_open)) continue;
      // Esc closes an open menu first (ImGui's own Esc closes only what has keyboard focus).
      if (pressed.key == editor::Key::Escape && s.interface_was_open) ImGui::ClosePopupsExceptModals();
    }
  }
  if (handle_transform(s, keys, mapping, mouse)) return;  // G, R or E was pressed
  if (continue_rubber_band(s, mapping, mouse)) return;
  if (s.point_drag.active) {
    continue_point_drag(s, mapping, mouse, held_axis);
    draw_snap_marker(s);
    return;
  }
  s.selection.hovered_point = -1;
  if (s.pen.on) {
    pen_pointer(s, mapping, mouse, !io.WantCaptureMouse && s.camera_drag.button < 0);
    draw_pen(s, mapping, mouse);
  }
  if (!s.pen.on && !io.WantCaptureMouse && s.camera_drag.button < 0 && ImGui::IsMousePosValid()) {
    s.selection.hovered_point = handle_under(s, mapping, mouse);
    if (s.selection.hovered_point >= 0) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
  }
  if (!io.WantCaptureMouse) press(s, mapping, mouse, held_axis);
  if (s.point_drag.active) return;
  if (s.camera_drag.button >= 0) camera_drag(s, s.layout.in_free_part(mouse));
}

}  // namespace sweep::viewer
