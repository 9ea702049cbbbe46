#pragma once
// Inserting a control point where the user clicks on a curve (the viewer's double-click): by the
// curve parameter of the clicked place (CurveSamples::parameters' units; editor/insert_at.hpp
// finds it under the pointer). Each kind keeps its shape as far as its basis allows.
#include "model/edit/edit.hpp"

namespace sweep {

/// Inserts a point into control-point curve `object` at curve parameter `parameter`, which must
/// lie strictly between 0 and the curve's piece count (piece_count), C = curve_position there:
///   bez2/bez3: split_bezier_piece(floor, fraction): the exact shape, 3 points more (a joint and
///     its two handles). At a joint (a whole parameter) there is a joint already: throws.
///   poly2/poly3: C on its segment, between the segment's points: the exact shape, 1 point more.
///   cr/kb: C as a new through-point between the two points of its segment: the curve still
///     passes through every old point and now C; the neighbouring segments change a little.
///     At a point (a whole parameter) throws: the point is there already.
///   bsp2/bsp3 (uniform cubic): no shape-preserving insertion exists with uniform knots (Boehm's
///     knot insertion needs a non-uniform knot), so the piece's two middle control points,
///     P[k+1] and P[k+2] of piece k (the two that weigh most on it), get a new point Q between
///     them with Q = (6C - P[k+1] - P[k+2]) / 4: the joint of the new curve that Q centres,
///     (P[k+1] + 4Q + P[k+2]) / 6, is exactly C, so the curve passes through the clicked place.
///     Four pieces around Q change; the rest keep their shape. Whole parameters are allowed.
/// A closed curve stays closed (insert_bspline_point's rule for the repeated seam points). Throws
/// EditError for other kinds, a parameter that is not finite or outside (0, pieces), an inserted
/// point equal to a neighbour, a position outside the coordinate range, or the caps.
Change insert_point_at(Document& doc, int object, double parameter);

/// The index of the point insert_point_at(doc, object, parameter) adds, in the curve's points
/// after the insertion (Bezier: the new joint), so the caller can select it; -1 where
/// insert_point_at would throw for the kind or the parameter's range.
int inserted_point_index(const Object& curve, double parameter);

}  // namespace sweep
