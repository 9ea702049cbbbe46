#pragma once
// The edge between the document and geometry: the neutral descriptor of a curve object
// (geometry/curves/curve.hpp's CurveDescriptor) and of a mesh object's cage, and the document-level
// conveniences built on them. Geometry never sees an Object; this is where one is translated.
#include "geometry/curves/curve.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "model/document.hpp"

#include <span>

namespace sweep {

/// The descriptor of curve `object`, borrowing its points. Precondition: is_curve(object.kind()).
CurveDescriptor describe_curve(const Object& object);

/// evaluate_curve of the object's descriptor (geometry/curves/curve.hpp).
CurveSamples evaluate_curve(const Object& object, const FrameOptions& options = {},
                            const AdaptiveTolerance& tolerance = {});
/// evaluate_curve_at of the object's descriptor.
CurveSamples evaluate_curve_at(const Object& object, std::span<const double> parameters,
                               const FrameOptions& options = {});
/// curve_position of the object's descriptor.
glm::dvec3 curve_position(const Object& object, double parameter);
/// curve_derivatives of the object's descriptor.
PieceDerivatives curve_derivatives(const Object& object, double parameter);

/// The diagonal of the box around a curve: its control points, or for a circle, helix or torus
/// knot the box of the exact curve; a patch's or cage's net bounds it as a control polygon
/// bounds a curve. 0 for other surfaces and materials.
double curve_extent(const Object& object);
/// The scene's size: the diagonal of the box around every curve and net of the document (0 if
/// none).
double document_extent(const Document& doc);

/// The cage of a `mesh` object, borrowing nothing (a copy of its points and faces).
Cage cage_of(const Object& mesh);

}  // namespace sweep
