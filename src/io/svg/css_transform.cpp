#include "io/svg/detail/css_transform.hpp"

#include "model/document.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

namespace sweep::io::svg_detail {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && is_blank(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_blank(text.back())) text.remove_suffix(1);
  return text;
}

std::string quoted(std::string_view text) {
  std::string out = "'";
  out += printable_excerpt(text, 40);
  return out += '\'';
}

/// Degrees per unit of an angle; nullopt for others.
std::optional<double> degrees_per(std::string_view unit) {
  if (unit == "deg") return 1.0;
  if (unit == "rad") return 180.0 / std::numbers::pi;
  if (unit == "grad") return 0.9;
  if (unit == "turn") return 360.0;
  return std::nullopt;
}

enum class ArgKind { Number, Length, Angle };

/// One argument of a transform function in its unit (numbers as they are, lengths in px, angles
/// in degrees), or an error.
std::optional<double> argument(std::string_view text, ArgKind kind) {
  const std::optional<Length> length = parse_length(text);
  if (!length) return std::nullopt;
  if (kind == ArgKind::Number) return length->unit.empty() ? std::optional(length->value) : std::nullopt;
  if (length->unit.empty()) return length->value == 0.0 ? std::optional(0.0) : std::nullopt;
  const std::optional<double> per = kind == ArgKind::Angle ? degrees_per(length->unit) : pixels_per(length->unit);
  if (!per) return std::nullopt;
  return length->value * *per;
}

const char* expected_of(ArgKind kind) {
  if (kind == ArgKind::Number) return "a number";
  if (kind == ArgKind::Angle) return "an angle (deg, rad, grad or turn)";
  return "a length (px, mm, cm, in, pt, pc or q)";
}

struct FunctionShape {
  std::string_view name;
  ArgKind kind;
  std::size_t fewest, most;
};

constexpr FunctionShape kFunctions[] = {
    {"matrix", ArgKind::Number, 6, 6},     {"translate", ArgKind::Length, 1, 2}, {"translatex", ArgKind::Length, 1, 1},
    {"translatey", ArgKind::Length, 1, 1}, {"scale", ArgKind::Number, 1, 2},     {"scalex", ArgKind::Number, 1, 1},
    {"scaley", ArgKind::Number, 1, 1},     {"rotate", ArgKind::Angle, 1, 1},     {"skew", ArgKind::Angle, 1, 2},
    {"skewx", ArgKind::Angle, 1, 1},       {"skewy", ArgKind::Angle, 1, 1},
};

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

Affine2 matrix_of(std::string_view name, const std::vector<double>& v) {
  const std::size_t n = v.size();
  if (name == "matrix") return {v[0], v[1], v[2], v[3], v[4], v[5]};
  if (name == "translate") return {1.0, 0.0, 0.0, 1.0, v[0], n == 2 ? v[1] : 0.0};
  if (name == "translatex") return {1.0, 0.0, 0.0, 1.0, v[0], 0.0};
  if (name == "translatey") return {1.0, 0.0, 0.0, 1.0, 0.0, v[0]};
  if (name == "scale") return {v[0], 0.0, 0.0, n == 2 ? v[1] : v[0], 0.0, 0.0};
  if (name == "scalex") return {v[0], 0.0, 0.0, 1.0, 0.0, 0.0};
  if (name == "scaley") return {1.0, 0.0, 0.0, v[0], 0.0, 0.0};
  if (name == "rotate") {
    const double c = std::cos(radians(v[0]));
    const double s = std::sin(radians(v[0]));
    return {c, s, -s, c, 0.0, 0.0};
  }
  const double x = name == "skewy" ? 0.0 : std::tan(radians(v[0]));
  const double y = name == "skewy" ? std::tan(radians(v[0])) : (n == 2 ? std::tan(radians(v[1])) : 0.0);
  return {1.0, y, x, 1.0, 0.0, 0.0};
}

/// The arguments between the parentheses, separated by commas (and blanks).
TransformParse one_function(std::string_view name, std::string_view inside) {
  std::string lower;
  for (const char c : name) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const FunctionShape* shape = nullptr;
  for (const FunctionShape& f : kFunctions) {
    if (f.name == lower) shape = &f;
  }
  if (shape == nullptr) {
    return {{},
            "expected matrix, translate, scale, rotate or skew (2D) in the style's transform, found " + quoted(name)};
  }
  std::vector<double> values;
  std::string_view rest = inside;
  while (!trimmed(rest).empty()) {
    const std::size_t comma = std::min(rest.find(','), rest.size());
    const std::string_view text = trimmed(rest.substr(0, comma));
    rest.remove_prefix(std::min(comma + 1, rest.size()));
    const std::optional<double> value = argument(text, shape->kind);
    if (!value) {
      return {{},
              "expected " + std::string(expected_of(shape->kind)) + " in " + std::string(name) +
                  "(...) of the style's transform, found " + quoted(text)};
    }
    values.push_back(*value);
  }
  if (values.size() < shape->fewest || values.size() > shape->most) {
    const std::string counts = shape->fewest == shape->most
                                   ? std::to_string(shape->fewest)
                                   : std::to_string(shape->fewest) + " or " + std::to_string(shape->most);
    return {{},
            "expected " + counts + " arguments in " + std::string(name) + "(...) of the style's transform, found " +
                std::to_string(values.size())};
  }
  return {matrix_of(lower, values), ""};
}

}  // namespace

TransformParse parse_css_transform(std::string_view text) {
  text = trimmed(text);
  if (text == "none") return {};
  TransformParse out;
  while (!text.empty()) {
    const std::size_t open = text.find('(');
    const std::size_t close = text.find(')');
    if (open == std::string_view::npos || close == std::string_view::npos || close < open) {
      return {{}, "expected a function such as rotate(45deg) in the style's transform, found " + quoted(text)};
    }
    const TransformParse one = one_function(trimmed(text.substr(0, open)), text.substr(open + 1, close - open - 1));
    if (!one.error.empty()) return one;
    out.matrix = compose(out.matrix, one.matrix);
    text = trimmed(text.substr(close + 1));
  }
  return out;
}

namespace {

/// One value of transform-origin: a keyword's fraction of the viewport's side or a length.
struct OriginValue {
  std::optional<double> fraction;  // left/top 0, center 0.5, right/bottom 1
  std::optional<Length> length;
  bool vertical_keyword = false;    // top or bottom: only for y
  bool horizontal_keyword = false;  // left or right: only for x
};

std::optional<OriginValue> origin_value(std::string_view word) {
  if (word == "left" || word == "right") return OriginValue{word == "left" ? 0.0 : 1.0, {}, false, true};
  if (word == "top" || word == "bottom") return OriginValue{word == "top" ? 0.0 : 1.0, {}, true, false};
  if (word == "center") return OriginValue{0.5, {}, false, false};
  std::optional<Length> length = parse_length(word);
  if (!length || (length->unit != "%" && !pixels_per(length->unit))) return std::nullopt;
  return OriginValue{{}, std::move(length), false, false};
}

std::optional<double> resolve(const OriginValue& v, const Viewport& viewport, LengthAxis axis) {
  if (v.length) return user_units(*v.length, viewport, axis);
  const std::optional<double> side = percent_base(viewport, axis);
  if (*v.fraction == 0.0) return 0.0;
  if (!side) return std::nullopt;
  return *v.fraction * *side;
}

}  // namespace

OriginParse parse_transform_origin(std::string_view text, const Viewport& viewport) {
  std::vector<OriginValue> values;
  std::string_view rest = trimmed(text);
  while (!rest.empty()) {
    std::size_t end = 0;
    while (end < rest.size() && !is_blank(rest[end])) ++end;
    const std::optional<OriginValue> value = origin_value(rest.substr(0, end));
    if (!value || values.size() == 3) {
      return {{},
              "expected 1 to 3 keywords (left, center, right, top, bottom) or lengths in transform-origin, found " +
                  quoted(text)};
    }
    values.push_back(*value);
    rest = trimmed(rest.substr(end));
  }
  if (values.empty()) return {{}, "expected 1 to 3 keywords or lengths in transform-origin, found nothing"};
  OriginValue x = values[0];
  OriginValue y = values.size() > 1 ? values[1] : OriginValue{0.5, {}, false, false};
  if (values.size() == 1 && x.vertical_keyword) std::swap(x, y);
  if (values.size() > 1 && (x.vertical_keyword || y.horizontal_keyword)) std::swap(x, y);
  const std::optional<double> ox = resolve(x, viewport, LengthAxis::X);
  const std::optional<double> oy = resolve(y, viewport, LengthAxis::Y);
  if (!ox || !oy) {
    return {{},
            "expected a viewBox or the root's width and height to resolve transform-origin " + quoted(text) +
                ", found neither"};
  }
  return {{*ox, *oy}, ""};
}

Affine2 about(const Affine2& matrix, glm::dvec2 origin) {
  const Affine2 there{1.0, 0.0, 0.0, 1.0, origin.x, origin.y};
  const Affine2 back{1.0, 0.0, 0.0, 1.0, -origin.x, -origin.y};
  return compose(there, compose(matrix, back));
}

}  // namespace sweep::io::svg_detail
