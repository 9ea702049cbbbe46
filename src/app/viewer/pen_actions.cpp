#include "app/viewer/pen_actions.hpp"

#include "app/viewer/actions.hpp"
#include "editor/overlay_builder.hpp"
#include "model/edit/edit.hpp"
#include "render/camera.hpp"

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

}  // namespace

void toggle_pen(ViewerState& s) {
  if (s.pen.stroke) pen_finish(s);
  s.pen.on = !s.pen.on;
  s.status = s.pen.on ? "pen: click to put down points, drag for handles, click the first point to close; "
                        "Enter or Esc ends, Backspace takes a point back"
                      : "pen off";
}

PenPlane pen_plane(const ViewerState& s) {
  if (s.profile_view || is_planar_curve(s.pen.kind)) return {};
  const render::Bounds bounds = render::scene_bounds(s.session.scene(), s.views.visibility(s.doc()));
  const double height = editor::ground_height(editor::GroundGrid{bounds.min, bounds.max});
  return {glm::dvec3(0.0, height, 0.0), glm::dvec3(0.0, 1.0, 0.0)};
}

void pen_place(ViewerState& s, const glm::dvec3& at) {
  PenTool& pen = s.pen;
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
  if (!s.pen.stroke || s.pen.stroke->nodes().empty()) return;
  const editor::PenNode before = s.pen.stroke->nodes().back();
  s.pen.stroke->drag_to(to);
  if (!sync(s, false)) s.pen.stroke->drag_to(before.at + before.drag);
}

void pen_take_back(ViewerState& s) {
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
  if (s.pen.stroke) end_stroke(s, false);
}

}  // namespace sweep::viewer
