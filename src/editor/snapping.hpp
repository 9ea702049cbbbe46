#pragma once
// Snapping a dragged control point to other control points, to other curves and to the y axis,
// by distance on the window, as Inkscape snaps nodes to nodes and paths. The targets are taken
// from the document and its scene once, when a drag starts (gather_snap_targets: O(points +
// samples), a copy); each frame of the drag then asks snap_target, which projects them only
// when the camera or window changed since the last call. No GL.
#include "editor/picking.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace sweep::editor {

/// What a dragged point snapped to.
enum class SnapKind : std::uint8_t {
  Point,  // a control point (of any visible curve, patch or cage, its own curve's others too)
  Curve,  // the sample polyline of another visible curve
  Axis,   // the y axis (x = 0, z = 0), about which surfaces of revolution turn
};

/// Which targets count, each with its own toggle, and how near (window units) the pointer must
/// be. Holding Ctrl suspends snapping: the caller then does not call snap_target at all.
struct SnapOptions {
  bool points = true;
  bool curves = true;
  bool axis = true;
  double radius = 8.0;  // window units
};

/// The target found: its world position (for a planar curve being dragged the caller passes it
/// to move_point as it is: the model drops z), what it is, and where it is on the window (for
/// the marker shown before the button is let go).
struct SnapHit {
  glm::dvec3 position{0.0};
  SnapKind kind = SnapKind::Point;
  int object = -1;  // the object snapped to (Point, Curve); -1 for the axis
  int point = -1;   // Point: its control point's index; -1 otherwise
  glm::dvec2 screen{0.0};
  double distance = 0.0;  // from the pointer, window units
};

/// The point being dragged (document indices); object -1: none (every point is a target).
struct DraggedPoint {
  int object = -1;
  int point = -1;
};

/// A point on the window with its clip w (> 0 in front of the eye; <= 0: not on the window).
struct ScreenPoint {
  glm::dvec2 xy{0.0};
  double w = 0.0;
};
/// The window position and clip w of a world point (w = 0 where to_screen has none).
ScreenPoint project(const ScreenMapping& mapping, const glm::dvec3& world);

/// The place of a polyline (as projected points) nearest `pointer` on the window: segment
/// `segment` (from point segment to segment + 1) at `fraction` of the way along it in world
/// space (perspective-correct: the world point there lands on `screen`).
struct PolylineHit {
  std::size_t segment = 0;
  double fraction = 0.0;
  glm::dvec2 screen{0.0};
  double distance = 0.0;
};
/// The nearest place within `radius` (ties: the first), or nullopt. Segments with an end off the
/// window are skipped; a single point is a segment 0 of length 0. O(points).
std::optional<PolylineHit> nearest_on_polyline(std::span<const ScreenPoint> points, const glm::dvec2& pointer,
                                               double radius);

/// Everything a drag may snap to, taken when the drag starts. Later edits (other than the drag
/// itself, whose moving points are left out) are not seen: gather again after them.
struct SnapTargets {
  struct PointRef {
    int object = -1;
    int point = -1;
  };
  struct CurveRange {
    int object = -1;
    std::size_t first = 0;  // into samples
    std::size_t count = 0;
  };
  std::vector<glm::dvec3> points;  // control points, with point_refs[i] saying whose
  std::vector<PointRef> point_refs;
  std::vector<glm::dvec3> samples;  // the sample positions of every target curve, one after another
  std::vector<CurveRange> curves;

  /// The window positions of points and samples for the mapping they were projected with:
  /// snap_target's cache (so a const SnapTargets is not safe to share between threads).
  struct Projection {
    bool valid = false;
    glm::dmat4 view_projection{1.0};
    glm::dvec2 window_size{0.0};
    std::vector<ScreenPoint> points;
    std::vector<ScreenPoint> samples;
  };
  mutable Projection projection;
};

/// The targets of a drag of `dragged` (object -1: no drag): the control points of every visible
/// object with editable points (has_editable_points), its own other points included, but not
/// the dragged point, its seam partners (seam_partners: a closed curve's repeats, a patch's
/// copies), nor, when it is a Bezier joint (every third point), the handles beside it and its
/// partners, which belong to it; and the samples of every visible curve but the dragged one
/// (its samples follow the drag). `visible[i]`: object i is shown.
/// Preconditions: scene and visible have one entry per object; dragged is none or a valid point.
/// Cost: O(points + samples) time; memory 24 bytes a point or sample, 24 more for its window
/// position once projected, and 8 a point for whose it is.
SnapTargets gather_snap_targets(const Document& doc, const Scene& scene, const std::vector<bool>& visible,
                                DraggedPoint dragged);

/// The target nearest `handle` (the dragged handle's window position: the pointer plus the
/// grip's offset, HandleGrip) within options.radius, or nullopt. A control point within the
/// radius wins over any curve or the axis, even a nearer one: a point of an interpolating curve
/// lies on its curve, which is always at least as near, so "nearest wins" would never give the
/// point. Among curves and the axis the nearest wins, a curve at equal distance. A curve target
/// is the nearest place on its sample polyline on the window, its world position on the segment
/// between the two samples (perspective-correct), so it is on the samples the user sees, exactly
/// a sample's position where the nearest place is one. An axis target is the point of the axis
/// nearest the ray through `handle` (in perspective within a small fraction of a window unit of
/// the axis's nearest place on the window), x and z exactly 0.
/// Cost: O(points + samples) comparisons; their projection only when `mapping` changed.
/// Precondition: options.radius >= 0.
std::optional<SnapHit> snap_target(const SnapTargets& targets, const ScreenMapping& mapping, const glm::dvec2& handle,
                                   const SnapOptions& options);

}  // namespace sweep::editor
