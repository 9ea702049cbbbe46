#include "io/svg/detail/length.hpp"

#include <cctype>
#include <charconv>
#include <cmath>
#include <system_error>

namespace sweep::io::svg_detail {

std::optional<Length> parse_length(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  Length out;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), out.value);
  if (ec != std::errc() || !std::isfinite(out.value)) return std::nullopt;
  out.unit.assign(end, text.data() + text.size());
  for (char& c : out.unit) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

std::optional<double> millimetres_per(std::string_view unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "in") return 25.4;
  if (unit == "pt") return 25.4 / 72.0;
  if (unit == "pc") return 25.4 / 6.0;
  if (unit == "q") return 0.25;
  return std::nullopt;
}

std::optional<double> pixels_per(std::string_view unit) {
  if (unit.empty() || unit == "px") return 1.0;
  if (const std::optional<double> mm = millimetres_per(unit)) return *mm * 96.0 / 25.4;
  return std::nullopt;
}

std::optional<double> percent_base(const Viewport& viewport, LengthAxis axis) {
  if (axis == LengthAxis::X) return viewport.width;
  if (axis == LengthAxis::Y) return viewport.height;
  if (!viewport.width || !viewport.height) return std::nullopt;
  // SVG 1.1 section 7.10: sqrt(width^2 + height^2) / sqrt(2).
  return std::sqrt((*viewport.width * *viewport.width + *viewport.height * *viewport.height) / 2.0);
}

std::optional<double> user_units(const Length& length, const Viewport& viewport, LengthAxis axis) {
  if (length.unit == "%") {
    const std::optional<double> base = percent_base(viewport, axis);
    if (!base) return std::nullopt;
    return length.value / 100.0 * *base;
  }
  const std::optional<double> per = pixels_per(length.unit);
  if (!per) return std::nullopt;
  return length.value * *per;
}

}  // namespace sweep::io::svg_detail
