#pragma once
// Lengths of an SVG drawing (SVG 1.1 section 7.10, "Units"): a number and its unit, 96 px per
// inch and 1 px per user unit, and percentages of the viewport: x lengths of its width, y lengths
// of its height, other lengths (a circle's r) of its diagonal / sqrt(2).
#include <optional>
#include <string>
#include <string_view>

namespace sweep::io::svg_detail {

/// A length as written: a number and its unit in lower case ("", "px", "mm", ..., "%").
struct Length {
  double value = 0.0;
  std::string unit;
};

/// A finite number, optionally signed and surrounded by blanks, then its unit; nullopt if the
/// text does not start with a number.
std::optional<Length> parse_length(std::string_view text);

/// Millimetres per unit of a physical unit (mm, cm, in, pt, pc, q); nullopt for others.
std::optional<double> millimetres_per(std::string_view unit);

/// CSS pixels (user units) per unit: 1 for px and no unit, 96 per inch; nullopt for %, em and
/// unknown units.
std::optional<double> pixels_per(std::string_view unit);

/// The units that pixels_per knows, for messages.
inline constexpr const char* kLengthExpected = "a length (a number with px, mm, cm, in, pt, pc, q or no unit)";

/// The size of the viewport that percentages refer to, in the user units of the elements in it;
/// a side is nullopt when the drawing does not say it (a root without viewBox, width or height).
struct Viewport {
  std::optional<double> width;
  std::optional<double> height;
};

/// Which side of the viewport a percentage is of.
enum class LengthAxis { X, Y, Other };

/// A length in user units, a percentage resolved against `viewport` along `axis`; nullopt when
/// the unit is unknown or the viewport's side is not known. Precondition: none.
std::optional<double> user_units(const Length& length, const Viewport& viewport, LengthAxis axis);

/// The side of `viewport` a percentage along `axis` is of; nullopt when not known.
std::optional<double> percent_base(const Viewport& viewport, LengthAxis axis);

}  // namespace sweep::io::svg_detail
