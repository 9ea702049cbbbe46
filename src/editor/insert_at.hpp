#pragma once
// Where on a curve the user clicked: the curve parameter under the pointer, for inserting a point
// there (model/edit/edit_insert.hpp's insert_point_at, the viewer's double-click). No GL.
#include "editor/picking.hpp"
#include "geometry/curves/curve.hpp"
#include "model/object.hpp"

#include <glm/vec2.hpp>

#include <optional>

namespace sweep::editor {

/// The curve parameter (CurveSamples::parameters' units) of the place of the sample polyline
/// nearest `pointer` on the window, if it passes within `radius` window units: the parameters
/// of the nearest segment's samples interpolated at the perspective-correct world fraction
/// along it (so exact for a polyline, and within the sampling's chord error otherwise). Ties:
/// the first segment. O(samples). Preconditions: parameters has one entry per frame; radius >= 0.
std::optional<double> parameter_at(const CurveSamples& samples, const ScreenMapping& mapping, glm::dvec2 pointer,
                                   double radius);

/// parameter_at refined on the exact curve (curve_position of `curve`, whose samples `samples`
/// are): the parameter, within the sample intervals around the polyline's nearest place, whose
/// curve point lands nearest `pointer` on the window (golden-section search on each interval),
/// or the polyline's parameter if that lands nearer. The curve point there may be a little
/// farther than `radius` where the polyline cuts a corner of the curve. About 150 curve
/// evaluations. Preconditions: as parameter_at; `samples` are the samples of `curve`.
std::optional<double> parameter_at(const Object& curve, const CurveSamples& samples, const ScreenMapping& mapping,
                                   glm::dvec2 pointer, double radius);

}  // namespace sweep::editor
