#pragma once
// How a kind's points are laid out and edited, declared by each kind beside its syntax as its
// traits' `points` (kind_*.hpp). The reader's count rule is the kind's `count_problem`; everything
// the editor does with points asks this declaration, so a kind with points states once what each
// entry is, what a closed list repeats, what an insertion or deletion adds or removes, and how
// its control polygon is drawn. PointLayout has no default: a kind that leaves it out does not
// compile.
#include <array>
#include <cstddef>
#include <cstdint>

namespace sweep {

/// How a kind's points are edited: none, a curve's control points (moved, inserted, deleted), or a
/// surface's fixed net (moved only).
enum class PointRole : std::uint8_t { None, ControlPoints, Net };

/// What one entry of a point list is.
enum class EntryRole : std::uint8_t {
  Position,  // a point of the shape (a joint, a B-spline or Catmull-Rom point, a net vertex)
  Handle,    // a Bezier handle: a position that shapes a piece
  Tangent,   // a Hermite tangent: a vector, shown and dragged as a handle at its position + tangent / 3
};

/// What inserting and deleting works on.
enum class EditUnit : std::uint8_t {
  Fixed,            // nothing is inserted or deleted (no points, or a surface's net)
  Point,            // one entry (bsp, cr, kb, poly)
  Piece,            // a piece: split in two (de Casteljau), or two joined at a joint (bez)
  PointAndTangent,  // a point and the tangent after it (herm)
};

/// How the control polygon is drawn.
enum class PolygonStyle : std::uint8_t {
  None,     // no polygon (no points; a net, which the renderer draws itself)
  Through,  // through the entries in order
  Handles,  // through the positions, each tangent a stick out to its handle and back (p, p + t/3, p, q, ...)
};

/// A kind's point layout and edit rules.
struct PointLayout {
  PointRole role;
  /// Entries per repeating group (Bezier: a joint and its two handles; Hermite: a point and its tangent).
  std::uint8_t stride;
  /// The role of entry i is entries[i % stride].
  std::array<EntryRole, 3> entries;
  /// Entries a closed list repeats at its end (B-spline: its first 3; Bezier, cr, kb, poly: the
  /// first; Hermite: the first point and its tangent).
  std::uint8_t seam_repeats;
  /// Groups (of `stride` entries) a deletion keeps at least: open, and distinct when closed.
  std::uint8_t least_open;
  std::uint8_t least_closed;
  EditUnit unit;
  PolygonStyle polygon;

  consteval PointLayout(PointRole role_, std::uint8_t stride_, std::array<EntryRole, 3> entries_,
                        std::uint8_t seam_repeats_, std::uint8_t least_open_, std::uint8_t least_closed_,
                        EditUnit unit_, PolygonStyle polygon_)
      : role(role_),
        stride(stride_),
        entries(entries_),
        seam_repeats(seam_repeats_),
        least_open(least_open_),
        least_closed(least_closed_),
        unit(unit_),
        polygon(polygon_) {}

  constexpr EntryRole entry(std::size_t index) const { return entries[index % stride]; }
  /// Snaps, and is moved by a transform, as a position (not a Hermite tangent).
  constexpr bool is_position(std::size_t index) const { return entry(index) != EntryRole::Tangent; }
  /// The Bezier joint rules of the editor (editor/bezier_joints.hpp) apply.
  constexpr bool has_joints() const { return unit == EditUnit::Piece; }
};

namespace point_layouts {
using E = EntryRole;
inline constexpr PointLayout kNone{
    PointRole::None, 1, {E::Position, E::Position, E::Position}, 0, 0, 0, EditUnit::Fixed, PolygonStyle::None};
/// A surface's net: moved only, drawn by the renderer.
inline constexpr PointLayout kNet{
    PointRole::Net, 1, {E::Position, E::Position, E::Position}, 0, 0, 0, EditUnit::Fixed, PolygonStyle::None};
/// Bezier curves: joint, handle, handle, ..., joint; a closed one repeats its first joint; a piece
/// is split or two joined (a deletion joins: at least one piece stays).
inline constexpr PointLayout kBezier{
    PointRole::ControlPoints, 3, {E::Position, E::Handle, E::Handle}, 1, 1, 1, EditUnit::Piece, PolygonStyle::Through};
/// Uniform B-splines: one point at a time; a closed one repeats its first three; at least 4.
inline constexpr PointLayout kBSpline{
    PointRole::ControlPoints, 1, {E::Position, E::Position, E::Position}, 3, 4, 4, EditUnit::Point,
    PolygonStyle::Through};
/// Curves through their points (cr, kb, poly): one point at a time; a closed one repeats its
/// first; at least 2 open, 3 distinct closed.
inline constexpr PointLayout kThrough{
    PointRole::ControlPoints, 1, {E::Position, E::Position, E::Position}, 1, 2, 3, EditUnit::Point,
    PolygonStyle::Through};
}  // namespace point_layouts

}  // namespace sweep
