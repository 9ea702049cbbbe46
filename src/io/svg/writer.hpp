#pragma once
// SVG text of planar curves, for laser cutters, plotters and documents: one <path> or <circle>
// per curve, exactly as the curves are defined (cubic pieces as C, polylines as L). Pure: outlines
// in, text out; svg/export.hpp finds the outlines in a document and writes the file.
//
// Coordinates: 1 SVG user unit is 1 SWP unit, and the width and height say it is 1 mm. A point
// (x, y) of SWP (y up) is (x, -y) in SVG (y down), with no transform anywhere, so a reader gets the
// SWP point back by negating y. The viewBox is the curves' exact box plus a margin on every side.
#include "geometry/curves/curve_basis.hpp"

#include <glm/vec2.hpp>

#include <string>
#include <variant>
#include <vector>

namespace sweep::io {

/// A curve of consecutive pieces (piece k starts where piece k - 1 ends), in SWP coordinates (z
/// ignored): "M start", then per piece "C p1 p2 p3", or "L p3" when straight; "Z" when closed.
struct SvgPath {
  std::vector<BezierPiece> pieces;
  bool straight = false;  // the pieces are segments (a polyline)
  bool closed = false;    // the end meets the start (is_closed, geometry/curves/curve.hpp)
};

/// A circle, in SWP coordinates.
struct SvgCircle {
  glm::dvec2 center{0.0};
  double radius = 0.0;
};

/// One curve to draw: its shape and its id, the curve's SWP name (empty: written without an id).
/// SWP names (is_valid_object_name: an ASCII letter or '_', then letters, digits, '_', '-', '.')
/// are valid XML ids as they are.
struct SvgOutline {
  std::string id;
  std::variant<SvgPath, SvgCircle> shape;
};

/// The SVG document of `outlines` (in their order), `title` in its <title>. Numbers are the
/// shortest text that reads back as the same double. Stroke black, no fill, the stroke 1/500 of
/// the larger side of the viewBox. Preconditions: at least one outline; every path has a piece;
/// finite coordinates and radii >= 0.
std::string svg_text(const std::vector<SvgOutline>& outlines, const std::string& title);

}  // namespace sweep::io
