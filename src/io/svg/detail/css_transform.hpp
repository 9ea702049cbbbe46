#pragma once
// CSS transforms of SVG elements (CSS Transforms Level 1): the `transform` property in a `style`
// attribute, whose syntax differs from the attribute's (angles and lengths carry units, arguments
// are separated by commas), and `transform-origin`, the point the transform turns and scales
// about (its keywords and percentages refer to the viewport: transform-box view-box).
#include "io/svg/detail/length.hpp"
#include "io/svg/detail/transform.hpp"

#include <string>
#include <string_view>

namespace sweep::io::svg_detail {

/// The CSS `transform` property's value: none, or a list of matrix, translate, translateX,
/// translateY, scale, scaleX, scaleY, rotate, skew, skewX and skewY, angles in deg, rad, grad or
/// turn, lengths in px or another absolute unit (0 may go without one); or the first problem
/// ("expected an angle (deg, rad, grad or turn) in rotate(...) of the style's transform, found '45'").
/// Precondition: none.
TransformParse parse_css_transform(std::string_view text);

/// A transform-origin: the point, or the first problem.
struct OriginParse {
  glm::dvec2 origin{0.0};
  std::string error;  // empty on success
};

/// `transform-origin`: one to three values (keywords left, center, right, top, bottom, lengths,
/// percentages of the viewport's sides; a third, z, value is ignored). Precondition: none.
OriginParse parse_transform_origin(std::string_view text, const Viewport& viewport);

/// `matrix` turned about `origin`: translate(origin) matrix translate(-origin).
Affine2 about(const Affine2& matrix, glm::dvec2 origin);

}  // namespace sweep::io::svg_detail
