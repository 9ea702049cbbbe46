#pragma once
// SVG's `transform` attribute (SVG 1.1 section 7.6): a list of matrix, translate, scale, rotate
// (with an optional centre), skewX and skewY, separated by blanks and/or commas, applied right to
// left (the last one acts on the element's coordinates first).
#include <glm/vec2.hpp>

#include <string>
#include <string_view>

namespace sweep::io::svg_detail {

/// The affine map x' = a x + c y + e, y' = b x + d y + f (SVG's matrix(a b c d e f)).
struct Affine2 {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;
  glm::dvec2 apply(glm::dvec2 p) const { return {a * p.x + c * p.y + e, b * p.x + d * p.y + f}; }
  bool operator==(const Affine2&) const = default;
};

/// `outer` after `inner`: the map that applies `inner` first.
Affine2 compose(const Affine2& outer, const Affine2& inner);

/// A transform list, or the first problem ("expected '(' after 'rotate' in transform, found 'x'").
struct TransformParse {
  Affine2 matrix;
  std::string error;  // empty on success
};
TransformParse parse_transform(std::string_view text);

}  // namespace sweep::io::svg_detail
