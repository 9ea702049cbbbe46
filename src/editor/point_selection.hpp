#pragma once
// Several selected control points of one curve: click, Shift+click, select all, the rubber band
// and the centre that group transforms turn and scale about. Composes with Selection
// (view_state.hpp): Selection names the curve and its single `point`, which the integrator keeps
// equal to active(); this class holds the rest of the set and is cleared when the curve changes.
// No GL.
#include "editor/picking.hpp"
#include "model/edit/edit.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace sweep::editor {

/// Selected point indices of one curve, sorted and unique, and the active point (the one last
/// clicked or added, which single-point commands act on): -1 or one of points().
class PointSelection {
 public:
  /// Click: selects only `point`, which becomes active. Precondition: point >= 0.
  void click(int point);
  /// Shift+click: adds `point` (it becomes active) or removes it (when it was active, no point
  /// is active: as Blender, the selection keeps no stand-in the user did not click).
  /// Precondition: point >= 0.
  void toggle(int point);
  /// A: selects points 0..count-1; the active point stays. Precondition: count >= 0.
  void select_all(int count);
  /// Rubber band: selects exactly `points` (any order, duplicates allowed), or with `add` (a
  /// modifier held) adds them to the selection. The active point stays if still selected.
  /// Precondition: every index >= 0.
  void select(std::span<const int> points, bool add = false);
  void clear() { *this = {}; }
  /// After an edit, undo or redo: drops the indices >= count (points deleted from the end).
  void fix(int count);

  bool contains(int point) const;
  bool empty() const { return points_.empty(); }
  std::size_t size() const { return points_.size(); }
  const std::vector<int>& points() const { return points_; }
  int active() const { return active_; }

 private:
  std::vector<int> points_;  // sorted, unique
  int active_ = -1;
};

/// The indices of `points` whose window positions lie in the rectangle with opposite corners
/// `corner_a` and `corner_b` (either order; edges count as inside), ascending. Points behind the
/// eye are never inside.
std::vector<int> points_in_rect(const ScreenMapping& mapping, std::span<const glm::dvec3> points, glm::dvec2 corner_a,
                                glm::dvec2 corner_b);

/// The pivot of group transforms: the mean of the selected points' distinct positions (Blender's
/// "median point"). The mean, not the centre of their box: it is carried along by every rotation,
/// scale and mirror (the mean of the moved points is the moved mean, up to rounding), so four
/// quarter turns about an oblique view axis, each about the then current pivot, bring the points
/// back; the box centre moves under such a turn (by 0.15 for weird.swp's sweep). Positions are
/// counted once however often they are selected, so the repeated seam points of a closed curve
/// (all selected by A) do not pull it towards the seam. A planar curve's centre has z = 0.
/// Preconditions: selection not empty; every selected index < points.size().
glm::dvec3 centre(std::span<const glm::dvec3> points, const PointSelection& selection);

/// The centre of the axis-aligned box of the selected points (Blender's "bounding box centre"):
/// the pivot to mirror about. A mirror maps the box onto itself, so this pivot stays put to the
/// bit (when the mirrored coordinates are representable) and mirroring twice gives the points
/// back exactly, where the mean can move by an ulp in between and leave 5.6e-17 where a 0 was.
/// Preconditions: selection not empty; every selected index < points.size().
glm::dvec3 box_centre(std::span<const glm::dvec3> points, const PointSelection& selection);

/// The moves that mirror the selected points about the plane through `pivot` (box_centre() for
/// the Edit panel's Mirror x/y/z) perpendicular to axis `axis` (0 x, 1 y, 2 z): coordinate
/// `axis` becomes 2 pivot - itself, the others stay exactly. Mirroring twice about the same pivot
/// is exact whenever 2 pivot - p is representable (e.g. the files' dyadic coordinates);
/// otherwise within rounding. For a `planar` curve axis z is refused: returns no moves (its
/// points have z = 0 and nothing would change). Preconditions: 0 <= axis <= 2; every selected
/// index < points.size().
std::vector<PointMove> mirror_moves(std::span<const glm::dvec3> points, const PointSelection& selection, int axis,
                                    const glm::dvec3& pivot, bool planar = false);

}  // namespace sweep::editor
