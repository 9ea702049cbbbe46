#pragma once
// The continuity rules of a Bezier curve's joints (bez2, bez3), as the editor keeps them. A bez
// curve of n = 3k+1 points has its joints at 3, 6, ..., n-4 (and, when closed, the seam joint 0 =
// n-1); the handles of joint j are j-1 (in) and j+1 (out), of the seam 1 and n-2. A joint is a
// corner, smooth (handles collinear with it: G1) or symmetric (collinear and equally long: C1), as
// its points are: nothing of it is written to the SWP file. Dragging follows the joint's rule
// (drag_moves); the Edit panel converts a joint (convert_joint), and JointTypes remembers a type
// the user chose that the points alone do not say (a corner whose handles happen to line up).
// Other curve kinds have no handles: their points move alone. No GL, no ImGui.
#include "editor/edit_session.hpp"
#include "model/edit/edit.hpp"
#include "model/object.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

namespace sweep::editor {

/// Ordered weakest first: a symmetric joint is also smooth, and any joint may be a corner.
enum class JointType : std::uint8_t { Corner, Smooth, Symmetric };

/// "corner", "smooth" or "symmetric", as the Edit panel shows it.
std::string_view joint_type_label(JointType type);

/// Handles are collinear with their joint when the angle between (joint - in) and (out - joint)
/// is at most this (radians, ~0.06 degrees). Files written by Sweep round-trip exactly, but hand-
/// or tool-written files round to six digits (swp/corners.swp: 0.666667, 1.33333): that tilts a
/// handle of length L among coordinates of size C by up to ~1e-5 C / L, so 1e-3 keeps smooth
/// joints smooth for C / L up to ~100, while no corner anyone means is that straight.
inline constexpr double kCollinearAngle = 1e-3;
/// Collinear handles are equally long when their lengths differ by at most this fraction of the
/// longer one (six-digit rounding of handles down to ~0.01 long stays within it).
inline constexpr double kEqualLengthRatio = 1e-3;

/// The joints of `curve` in increasing order: 0 if the curve is closed (is_closed_polygon), then 3,
/// 6, ..., n-4; empty for a curve of one open piece and for every kind but bez2 and bez3. O(n).
std::vector<int> bezier_joints(const Object& curve);

/// The joint that `point` is or is a handle of (a closed curve's 0, 1, n-2, n-1: joint 0), or -1:
/// not a Bezier curve, or an open curve's end points 0, n-1 and their handles 1, n-2, which are
/// no joints (drag_moves carries an end's handle along with it, as Inkscape does).
/// Precondition: 0 <= point < number of points.
int joint_of(const Object& curve, int point);

/// The type the points of joint `joint` say: Corner when either handle has zero length (it has no
/// direction: the curve's tangent there comes from farther points) or the angle between the
/// handles' directions exceeds kCollinearAngle; else Symmetric when the lengths agree within
/// kEqualLengthRatio; else Smooth. Precondition: `joint` is one of bezier_joints(curve).
JointType classify_joint(const Object& curve, int joint);

/// The moves of dragging point `point` of `curve` (its points now) to `to`, the dragged point
/// first, for move_points (which moves a closed curve's seam partners too). `type` is the joint's
/// type decided when the drag began (JointTypes::type), since the drag changes the points.
/// - a joint: its two handles translate with it;
/// - an open curve's end point: its one handle translates with it;
/// - a handle of a Smooth joint: the opposite handle turns onto the line through the joint,
///   opposite the dragged one, keeping its length (it stays put while the dragged handle is on
///   the joint: no direction); of a Symmetric joint: the opposite becomes 2 joint - handle;
/// - a handle of a Corner, an open end's handle, a point of another kind, or `break_rule` (the
///   modifier is held): the dragged point alone.
/// A bez2's moves keep z = 0. Precondition: 0 <= point < number of points of a curve with points.
std::vector<PointMove> drag_moves(const Object& curve, int point, const glm::dvec3& to, JointType type,
                                  bool break_rule);

/// The moves that make joint `joint` of type `to`: Smooth turns both handles onto the line through
/// the joint along the bisector of their directions (the out direction if the in handle has zero
/// length, and vice versa; for a cusp, handles pointing back on each other, the out direction),
/// keeping each length; Symmetric does so and gives both their mean length; Corner moves nothing
/// (empty: the caller records the choice in JointTypes, since collinear handles classify smooth).
/// Empty too when both handles lie on the joint. Precondition: `joint` is one of bezier_joints.
std::vector<PointMove> convert_joint(const Object& curve, int joint, JointType to);

/// The joint types the user chose in this session, per object id and joint, over what the points
/// say. An object's choices are forgotten when its point count changes (a split or join renumbers
/// its joints). A choice applies only while the points allow it: Corner always; Smooth while the
/// handles are collinear or one has zero length; Symmetric while they classify symmetric (so an
/// undo that brings back a corner's points shows a corner again).
class JointTypes {
 public:
  /// The chosen type of the joint if any and allowed, else classify_joint. Preconditions as
  /// classify_joint.
  JointType type(const Object& curve, ObjectId id, int joint) const;
  /// Remembers `type` for joint `joint` of object `id` (with `curve`'s point count).
  /// Precondition: `joint` is one of bezier_joints(curve).
  void set(const Object& curve, ObjectId id, int joint, JointType type);
  /// Forgets every choice (a file was opened).
  void clear() { chosen_.clear(); }

 private:
  struct Chosen {
    std::size_t point_count = 0;
    std::map<int, JointType> joints;
  };
  std::map<ObjectId, Chosen> chosen_;
};

}  // namespace sweep::editor
