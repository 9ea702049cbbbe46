#include "app/viewer/pen_actions.hpp"

#include "app/viewer/actions.hpp"
#include "editor/overlay_builder.hpp"
#include "model/edit/edit.hpp"
#include "render/camera.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace sweep::viewer {
namespace {

constexpr const char* kStepLabel = "draw curve";

std::string kind_word(ObjectKind kind) {
  return std::string(keyword(kind));
}

/// Forgets the stroke (its step already ended or cancelled).
void drop_stroke(PenTool& pen) {
  pen.stroke.reset();
  pen.object = editor::kNoObject;
  pen.holding = false;
  pen.targets.reset();
  pen.snap.reset();
}

/// Makes the document's curve match the stroke: added once the stroke has the nodes its kind
/// needs, reshaped after, and taken out again (the step started over) when it has too few.
/// False when the document refused the nodes (the error says why).
bool sync(ViewerState& s, bool closed) {
  PenTool& pen = s.pen;
  const editor::PenStroke& stroke = *pen.stroke;
  if (!stroke.complete(closed)) {
    if (pen.object != editor::kNoObject) {
      s.session.cancel_step();
      s.session.begin_step(kStepLabel);
      pen.object = editor::kNoObject;
      s.selection.fix(s.session);
    }
    return true;
  }
  std::vector<glm::dvec3> points = stroke.points(closed);
  const int index = s.session.index_of(pen.object);
  if (index >= 0) {
    return apply_continuous(s, [index, &points](Document& d) { return set_curve_points(d, index, points); });
  }
  const ObjectKind kind = stroke.kind();
  const std::string name = unique_name(s.doc(), is_planar_curve(kind) ? "profile" : "curve");
  int added = -1;
  if (!apply_continuous(s, [&](Document& d) {
        added = add_drawn_curve(d, kind, name, points);
        return Change{{added}, true};
      })) {
    return false;
  }
  pen.object = s.session.id_of(added);
  s.selection.select(pen.object);
  return true;
}

/// "a closed bsp2 needs 4 nodes (clicks)".
std::string needs(const PenTool& pen, bool closed) {
  const std::size_t least = editor::pen_least_nodes(pen.stroke->kind(), closed);
  return std::string(closed ? "a closed " : "a ") + kind_word(pen.stroke->kind()) + " needs " + std::to_string(least) +
         " clicks";
}

/// Ends the stroke: the curve stays (one undo step) or, when there is none, nothing was drawn.
void end_stroke(ViewerState& s, bool closed) {
  PenTool& pen = s.pen;
  const int index = s.session.index_of(pen.object);
  std::string said;
  if (index >= 0) {
    s.session.end_step();
    const Object& curve = s.doc().objects[std::size_t(index)];
    said = "drew " + kind_word(curve.kind()) + " '" + curve.name + "' (" +
           std::to_string(curve.as<PointsPart>().points.size()) + " points" + (closed ? ", closed)" : ")");
  } else {
    s.session.cancel_step();
    if (!pen.stroke->nodes().empty()) said = needs(pen, false) + ": nothing drawn";
  }
  drop_stroke(pen);
  s.status = said;
}

/// The open curve and end the selection's point is at, if it is one's first or last point.
std::optional<std::pair<int, CurveEnd>> selected_end(const ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || s.selection.point < 0) return std::nullopt;
  const std::optional<CurveEnd> end = end_at(*curve, s.selection.point);
  if (!end) return std::nullopt;
  return std::pair(s.selected(), *end);
}

/// "'NAME'" of the curve being continued.
std::string continued_name(const ViewerState& s) {
  std::string text = display_name(s.doc(), s.session.index_of(s.pen.extending));
  text.insert(text.begin(), '\'');  // not "'" + name: GCC 12 warns (-Wrestrict) about its inlined copy
  text.push_back('\'');
  return text;
}

/// A node put down at the continued end (its own undo step, left open until the release).
void extend_at(ViewerState& s, const glm::dvec3& at) {
  PenTool& pen = s.pen;
  const int index = s.session.index_of(pen.extending);
  if (index < 0 || s.session.in_step()) return;
  const CurveEnd end = pen.end;
  s.session.begin_step("extend curve");
  if (!apply_continuous(s, [index, end, at](Document& d) { return extend_curve(d, index, end, at); })) {
    s.session.cancel_step();
    return;
  }
  s.selection.select(pen.extending);
  s.selection.point = end_point(s.doc().objects[std::size_t(index)], end);
  pen.last = at;
  ++pen.added;
}

}  // namespace

int pen_continues(const ViewerState& s) {
  if (s.pen.extending != editor::kNoObject) return s.session.index_of(s.pen.extending);
  if (s.pen.stroke) return -1;
  const auto end = selected_end(s);
  return end ? end->first : -1;
}

void toggle_pen(ViewerState& s) {
  if (s.pen.drawing()) pen_finish(s);
  s.pen.on = !s.pen.on;
  s.status = s.pen.on ? "pen: click to put down points, drag for handles, click the first point to close; "
                        "Enter or Esc ends, Backspace takes a point back"
                      : "pen off";
  if (s.pen.on && selected_end(s)) s.status += " (from the selected end, it continues that curve)";
}

PenPlane pen_plane(const ViewerState& s) {
  const std::optional<std::pair<int, CurveEnd>> end =
      s.pen.extending != editor::kNoObject ? std::optional(std::pair(s.session.index_of(s.pen.extending), s.pen.end))
                                           : selected_end(s);
  if (end && end->first >= 0) {
    const Object& curve = s.doc().objects[std::size_t(end->first)];
    if (s.profile_view || is_planar_curve(curve.kind())) return {};
    const glm::dvec3 at = curve.as<PointsPart>().points[std::size_t(end_point(curve, end->second))];
    return {at, glm::dvec3(0.0, 1.0, 0.0)};
  }
  if (s.profile_view || is_planar_curve(s.pen.kind)) return {};
  const render::Bounds bounds = render::scene_bounds(s.session.scene(), s.views.visibility(s.doc()));
  const double height = editor::ground_height(editor::GroundGrid{bounds.min, bounds.max});
  return {glm::dvec3(0.0, height, 0.0), glm::dvec3(0.0, 1.0, 0.0)};
}

void pen_place(ViewerState& s, const glm::dvec3& at) {
  PenTool& pen = s.pen;
  if (!pen.drawing()) {
    if (const auto end = selected_end(s)) {
      pen.plane = pen_plane(s);
      pen.extending = s.session.id_of(end->first);
      pen.end = end->second;
      pen.added = 0;
    }
  }
  if (pen.extending != editor::kNoObject) {
    extend_at(s, at);
    return;
  }
  if (!pen.stroke) {
    if (s.session.in_step()) return;  // another edit is under way
    pen.stroke.emplace(pen.kind);
    pen.plane = pen_plane(s);
    s.session.begin_step(kStepLabel);
  }
  pen.stroke->press(at);
  if (!sync(s, false)) pen.stroke->remove_last();  // refused (out of range): the error says why
}

void pen_drag(ViewerState& s, const glm::dvec3& to) {
  PenTool& pen = s.pen;
  const int index = s.session.index_of(pen.extending);
  if (index >= 0 && s.session.in_step()) {
    const Object& curve = s.doc().objects[std::size_t(index)];
    std::vector<glm::dvec3> points =
        editor::pen_shape_end(curve.kind(), curve.as<PointsPart>().points, pen.end, to - pen.last);
    apply_continuous(s, [index, &points](Document& d) { return set_curve_points(d, index, points); });
    return;
  }
  if (!s.pen.stroke || s.pen.stroke->nodes().empty()) return;
  const editor::PenNode before = s.pen.stroke->nodes().back();
  s.pen.stroke->drag_to(to);
  if (!sync(s, false)) s.pen.stroke->drag_to(before.at + before.drag);
}

void pen_release(ViewerState& s) {
  s.pen.holding = false;
  if (s.pen.extending != editor::kNoObject && s.session.in_step()) s.session.end_step();
}

void pen_take_back(ViewerState& s) {
  PenTool& pen = s.pen;
  if (pen.extending != editor::kNoObject) {
    if (pen.added == 0) return;
    pen_release(s);
    undo(s);
    --pen.added;
    if (const int index = s.session.index_of(pen.extending); index >= 0) {
      s.selection.select(pen.extending);
      s.selection.point = end_point(s.doc().objects[std::size_t(index)], pen.end);
    }
    return;
  }
  if (!s.pen.stroke) return;
  s.pen.stroke->remove_last();
  s.pen.holding = false;
  sync(s, false);
}

bool pen_close(ViewerState& s) {
  if (!s.pen.stroke) return false;
  if (!s.pen.stroke->complete(true)) {
    s.status = needs(s.pen, true);
    return false;
  }
  if (!sync(s, true)) return false;
  end_stroke(s, true);
  return true;
}

void pen_finish(ViewerState& s) {
  PenTool& pen = s.pen;
  if (pen.extending != editor::kNoObject) {
    pen_release(s);
    const std::string name = continued_name(s);
    s.status = pen.added == 0
                   ? ""
                   : "continued " + name + " by " + std::to_string(pen.added) + (pen.added == 1 ? " node" : " nodes");
    pen.extending = editor::kNoObject;
    return;
  }
  if (pen.stroke) end_stroke(s, false);
}

}  // namespace sweep::viewer
