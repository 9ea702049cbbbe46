// Inserting a point at a clicked curve parameter: the kind decides how (edit_insert.hpp); the
// edits themselves are edit.cpp's split_bezier_piece and insert_bspline_point, which check the
// position, the caps and the users and keep a closed curve closed.
#include "model/edit/edit_insert.hpp"

#include "model/edit/edit_support.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace sweep {

using namespace edit_support;

namespace {

/// Where a parameter lies: piece `piece` at `fraction` in [0, 1).
struct PieceAt {
  int piece = 0;
  double fraction = 0.0;
};

/// The piece and fraction of `parameter` on a curve of `pieces` pieces, or nullopt when the
/// parameter is not strictly inside (0, pieces).
std::optional<PieceAt> piece_at(double parameter, std::int64_t pieces) {
  if (!(parameter > 0.0 && parameter < static_cast<double>(pieces))) return std::nullopt;
  const double whole = std::floor(parameter);
  return PieceAt{static_cast<int>(whole), parameter - whole};
}

/// The entries a B-spline or interpolating curve gains: before which index and what (a point;
/// a Hermite point and its tangent).
struct PointInsertion {
  int before = 0;
  std::vector<glm::dvec3> entries;
};

/// The insertion into a B-spline or interpolating curve (edit_insert.hpp says why these).
PointInsertion point_insertion(const Object& curve, double parameter, PieceAt at) {
  const std::vector<glm::dvec3>& p = curve.as<PointsPart>().points;
  const glm::dvec3 clicked = curve_position(curve, parameter);
  const std::size_t k = to_size(at.piece);
  if (!kind_info(curve.kind()).interpolating) {
    // The new joint centred on Q is (P[k+1] + 4Q + P[k+2]) / 6: make it the clicked point.
    return {at.piece + 2, {(6.0 * clicked - p[k + 1] - p[k + 2]) / 4.0}};
  }
  if (point_layout(curve.kind()).unit == EditUnit::PointAndTangent) {
    // Piece k becomes two of parameter length 1 each, over f and 1 - f of it: the new point's
    // one tangent takes the mean of the two scalings, half the derivative there.
    return {2 * at.piece + 2, {clicked, curve_derivatives(curve, parameter).d1 / 2.0}};
  }
  return {at.piece + 1, {clicked}};
}

/// The parameter's place, or EditError saying which range it must be in.
PieceAt checked_piece_at(const Document& doc, int object, double parameter) {
  const Object& o = doc.objects[to_size(object)];
  const std::int64_t pieces = piece_count(o.kind(), static_cast<std::int64_t>(o.as<PointsPart>().points.size()));
  const std::optional<PieceAt> at = piece_at(parameter, pieces);
  if (!at) {
    throw EditError("cannot insert a point at parameter " + number_text(parameter) + " of curve " +
                    quoted(doc, object) + ": it must be strictly between 0 and " + std::to_string(pieces));
  }
  return *at;
}

}  // namespace

Change insert_point_at(Document& doc, int object, double parameter) {
  const Object& o = control_point_curve(doc, object);
  const PieceAt at = checked_piece_at(doc, object, parameter);
  const bool whole = at.fraction == 0.0;
  const bool interpolating = kind_info(o.kind()).interpolating;
  if (point_layout(o.kind()).has_joints()) {
    if (whole) {
      throw EditError("parameter " + number_text(parameter) + " of curve " + quoted(doc, object) +
                      " is the joint at point " + std::to_string(3 * at.piece) + ": there is a point there already");
    }
    return split_bezier_piece(doc, object, at.piece, at.fraction);
  }
  if (whole && interpolating) {
    throw EditError("parameter " + number_text(parameter) + " of curve " + quoted(doc, object) + " is point " +
                    std::to_string(at.piece) + ": there is a point there already");
  }
  const PointInsertion insertion = point_insertion(o, parameter, at);
  const std::vector<glm::dvec3>& p = o.as<PointsPart>().points;
  const std::size_t stride = point_layout(o.kind()).stride;
  const glm::dvec3& position = insertion.entries.front();
  if (position == p[to_size(insertion.before) - stride] || position == p[to_size(insertion.before)]) {
    throw EditError("the point inserted at parameter " + number_text(parameter) + " of curve " + quoted(doc, object) +
                    " would repeat its neighbour");
  }
  for (const glm::dvec3& entry : insertion.entries) checked_position(o.kind(), entry);
  return insert_group(doc, object, insertion.before, insertion.entries);
}

int inserted_point_index(const Object& curve, double parameter) {
  if (!is_curve(curve.kind()) || !has_control_points(curve.kind())) return -1;
  const std::size_t n = curve.as<PointsPart>().points.size();
  const std::optional<PieceAt> at = piece_at(parameter, piece_count(curve.kind(), static_cast<std::int64_t>(n)));
  if (!at) return -1;
  const PointLayout& layout = point_layout(curve.kind());
  const bool interpolating = kind_info(curve.kind()).interpolating;
  if (layout.has_joints()) return at->fraction == 0.0 ? -1 : 3 * at->piece + 3;
  if (at->fraction == 0.0 && interpolating) return -1;
  const int before = layout.stride * (at->piece + (interpolating ? 1 : 2));
  if (!is_closed_polygon(curve)) return before;
  // insert_bspline_point inserts before a trailing repeat as before the point it repeats.
  const int distinct = to_int(n - seam_repeats(curve.kind()));
  return before > distinct ? before - distinct : before;
}

}  // namespace sweep
