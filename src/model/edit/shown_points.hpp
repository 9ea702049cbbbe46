#pragma once
// Where a kind's point entries are shown, picked and dragged, from its layout (point_layout.hpp):
// a position where it is, a Hermite tangent as a handle at its point + tangent / 3 (the inner
// Bezier point of the piece it starts). The viewer draws, picks, snaps and transforms these
// places and hands its moves back through move_shown_points, which stores each tangent from the
// place of its handle; the point table and the file show the stored values.
#include "model/edit/edit.hpp"

#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace sweep {

/// A tangent t of the point p before it is shown at p + t / kTangentThirds.
inline constexpr double kTangentThirds = 3.0;

/// Where each entry of `object`'s points is shown (its stored points for every layout without
/// tangents); empty for an object without points. O(points).
std::vector<glm::dvec3> shown_points(const Object& object);

/// The control polygon as `object`'s layout draws it (PolygonStyle), a line strip whose corners
/// are all shown entries: the entries in order; through the positions with each tangent a stick
/// out to its handle and back (p0, p0 + t0/3, p0, p1, p1 + t1/3, p1, ...); or empty. O(points).
std::vector<glm::dvec3> control_polygon(const Object& object);

/// `moves` to shown places as the stored values move_points takes: a position is stored where it
/// is shown; a tangent as 3 (handle - its point), its point where the same moves put it (else
/// where it is), so a point dragged with its handle keeps its tangent. Preconditions: every
/// move's point indexes `object`'s points. O(points + moves).
std::vector<PointMove> stored_moves(const Object& object, std::span<const PointMove> moves);

/// move_points with moves to shown places (stored_moves): what the viewer's drags, nudges,
/// mirrors and transforms call. Throws as move_points does.
Change move_shown_points(Document& doc, int object, std::span<const PointMove> moves);

}  // namespace sweep
