// The selected surface's clauses in the Edit panel: a generalized cylinder's scale and twist
// (a curve from a list, or degrees on a slider), caps for gcyl and srev, height for birail.
// Every change is one undoable edit; the reader's message shows when the core refuses one.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "model/edit/edit.hpp"

#include <imgui.h>

#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// Named 2D curves defined before `surface`: what a scale or twist may read as a graph.
std::vector<int> graph_candidates(const Document& doc, int surface) {
  std::vector<int> out;
  for (int i = 0; i < surface; ++i) {
    const Object& o = doc.objects[std::size_t(i)];
    if (is_planar_curve(o.kind()) && !o.name.empty()) out.push_back(i);
  }
  return out;
}

void scale_combo(const EditContext& s, int index, const std::vector<int>& candidates) {
  int choice = s.doc().objects[std::size_t(index)].as<CylinderSurface>().scale;
  if (!curve_combo(s.doc(), "scale", candidates, choice, "(none: scale 1)")) return;
  run_edit(s, "set scale",
           [index, choice](Document& d) { return set_surface_graph(d, index, SurfaceGraph::Scale, choice); });
}

/// "(degrees)" and the curves: a twist curve replaces the degrees, and back.
void twist_controls(const EditContext& s, int index, const std::vector<int>& candidates) {
  const Object& o = s.doc().objects[std::size_t(index)];
  int choice = o.as<CylinderSurface>().twist_curve;
  if (curve_combo(s.doc(), "twist", candidates, choice, "(degrees)")) {
    const double degrees = o.as<CylinderSurface>().twist;
    run_edit(s, "set twist", [index, choice, degrees](Document& d) {
      return choice >= 0 ? set_surface_graph(d, index, SurfaceGraph::Twist, choice) : set_twist(d, index, degrees);
    });
    return;
  }
  if (o.as<CylinderSurface>().twist_curve >= 0) return;
  // A double-click or Ctrl+click types any value (the reader takes up to 1e6 degrees).
  number_field(s, {"degrees", "twist degrees", o.as<CylinderSurface>().twist, false, "twist"},
               float_slider("degrees", -720.0f, 720.0f, "%.1f"), "set twist", [index](double degrees) {
                 return [index, degrees](Document& d) { return set_twist(d, index, degrees); };
               });
}

void flag_checkbox(const EditContext& s, int index, SurfaceFlag flag, const char* label, const char* tip) {
  bool on = flag_value(s.doc().objects[std::size_t(index)], flag);
  const bool clicked = ImGui::Checkbox(label, &on);
  mark_item(s, label);  // where scripted tests click
  if (clicked) {
    run_edit(s, std::string(on ? "set " : "clear ") + label,
             [index, flag, on](Document& d) { return set_surface_flag(d, index, flag, on); });
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
}

}  // namespace

/// A subd's level (an undoable slider), scheme and boundary rule.
void subdivision_fields(const EditContext& s, int index) {
  const SubdivisionSurface& subd = s.doc().objects[std::size_t(index)].as<SubdivisionSurface>();
  number_field(s, {"level", "subdivision level", double(subd.levels), true, "level"},
               int_slider("level", 0, kMaxSubdivisionLevel), "set subdivision level", [index](double levels) {
                 return [index, levels](Document& d) { return set_steps_or_levels(d, index, int(levels)); };
               });
  flag_checkbox(s, index, SurfaceFlag::Loop, "loop",
                "Loop subdivision (triangle cages) instead of Catmull-Clark (any polygons)");
  flag_checkbox(s, index, SurfaceFlag::SmoothBoundary, "smooth-boundary",
                "round the boundary's corners instead of keeping them");
  ImGui::TextDisabled("cage: %s (shown in the wire mode)", display_name(s.doc(), subd.source).c_str());
}

void surface_fields(const EditContext& s, int index) {
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  if (kind == ObjectKind::GeneralizedCylinder) {
    const std::vector<int> candidates = graph_candidates(s.doc(), index);
    scale_combo(s, index, candidates);
    twist_controls(s, index, candidates);
  }
  if (has_flag(kind, SurfaceFlag::Caps)) {
    flag_checkbox(s, index, SurfaceFlag::Caps, "caps",
                  "close the ends: flat caps on a closed profile along an open sweep, disks where a profile "
                  "of revolution ends off the axis");
  }
  if (has_flag(kind, SurfaceFlag::Height)) {
    flag_checkbox(s, index, SurfaceFlag::Height, "height",
                  "scale the profile only along its chord, keeping its height");
  }
  if (kind == ObjectKind::Subdivision) subdivision_fields(s, index);
}

}  // namespace sweep::viewer::panels
