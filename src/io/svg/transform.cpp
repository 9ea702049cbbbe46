#include "io/svg/detail/transform.hpp"

#include "io/svg/detail/path.hpp"

#include <cctype>
#include <cmath>
#include <numbers>
#include <vector>

namespace sweep::io::svg_detail {
namespace {

bool is_blank_or_comma(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == ',';
}

std::string quoted(std::string_view text) {
  std::string out = "'";
  out += text;
  return out += '\'';
}

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

/// The matrix of one transform given its name and arguments; an error names what was expected.
TransformParse one_transform(std::string_view name, const std::vector<double>& v) {
  const std::size_t n = v.size();
  const auto wrong = [&](const char* counts) {
    return TransformParse{
        {},
        "expected " + std::string(counts) + " numbers in " + std::string(name) + "(...), found " + std::to_string(n)};
  };
  if (name == "matrix") {
    if (n != 6) return wrong("6");
    return {{v[0], v[1], v[2], v[3], v[4], v[5]}, ""};
  }
  if (name == "translate") {
    if (n != 1 && n != 2) return wrong("1 or 2");
    return {{1.0, 0.0, 0.0, 1.0, v[0], n == 2 ? v[1] : 0.0}, ""};
  }
  if (name == "scale") {
    if (n != 1 && n != 2) return wrong("1 or 2");
    return {{v[0], 0.0, 0.0, n == 2 ? v[1] : v[0], 0.0, 0.0}, ""};
  }
  if (name == "rotate") {
    if (n != 1 && n != 3) return wrong("1 or 3");
    const double c = std::cos(radians(v[0]));
    const double s = std::sin(radians(v[0]));
    const Affine2 turn{c, s, -s, c, 0.0, 0.0};
    if (n == 1) return {turn, ""};
    // rotate(a, cx, cy) = translate(cx, cy) rotate(a) translate(-cx, -cy)
    const Affine2 there{1.0, 0.0, 0.0, 1.0, v[1], v[2]};
    const Affine2 back{1.0, 0.0, 0.0, 1.0, -v[1], -v[2]};
    return {compose(there, compose(turn, back)), ""};
  }
  if (name == "skewX" || name == "skewY") {
    if (n != 1) return wrong("1");
    const double t = std::tan(radians(v[0]));
    return {name == "skewX" ? Affine2{1.0, 0.0, t, 1.0, 0.0, 0.0} : Affine2{1.0, t, 0.0, 1.0, 0.0, 0.0}, ""};
  }
  return {{},
          "expected matrix, translate, scale, rotate, skewX or skewY in transform, found '" + std::string(name) + "'"};
}

}  // namespace

Affine2 compose(const Affine2& outer, const Affine2& inner) {
  return {outer.a * inner.a + outer.c * inner.b,           outer.b * inner.a + outer.d * inner.b,
          outer.a * inner.c + outer.c * inner.d,           outer.b * inner.c + outer.d * inner.d,
          outer.a * inner.e + outer.c * inner.f + outer.e, outer.b * inner.e + outer.d * inner.f + outer.f};
}

TransformParse parse_transform(std::string_view text) {
  TransformParse out;
  std::size_t at = 0;
  const auto skip = [&] {
    while (at < text.size() && is_blank_or_comma(text[at])) ++at;
  };
  skip();
  while (at < text.size()) {
    std::size_t name_end = at;
    while (name_end < text.size() && std::isalpha(static_cast<unsigned char>(text[name_end]))) ++name_end;
    const std::string_view name = text.substr(at, name_end - at);
    at = name_end;
    while (at < text.size() && is_blank_or_comma(text[at]) && text[at] != ',') ++at;
    if (name.empty() || at >= text.size() || text[at] != '(') {
      const std::string found =
          at >= text.size() ? std::string("the end of the transform") : quoted(text.substr(at, 1));
      if (name.empty())
        return {{}, "expected matrix, translate, scale, rotate, skewX or skewY in transform, found " + found};
      return {{}, "expected '(' after '" + std::string(name) + "' in transform, found " + found};
    }
    const std::size_t close = text.find(')', at);
    if (close == std::string_view::npos) {
      return {{}, "expected ')' after '" + std::string(name) + "(' in transform, found the end of the transform"};
    }
    const NumberList args =
        parse_number_list(text.substr(at + 1, close - at - 1), "in " + std::string(name) + "(...)", 6);
    if (!args.error.empty()) return {{}, "transform: " + args.error};
    const TransformParse one = one_transform(name, args.numbers);
    if (!one.error.empty()) return one;
    out.matrix = compose(out.matrix, one.matrix);
    at = close + 1;
    skip();
  }
  return out;
}

}  // namespace sweep::io::svg_detail
