// The basic shapes (SVG 1.1 chapter 9) as path data that svg/detail/path.hpp reads: line, polyline,
// polygon, circle, ellipse and rect (rounded corners too), their lengths with units or in percent.
#include "io/svg/detail/reader.hpp"
#include "model/file_limits.hpp"

#include <algorithm>
#include <charconv>

namespace sweep::io::svg_detail {
namespace {

/// Path data written command by command, its numbers exactly (shortest round trip).
class PathText {
 public:
  PathText& operator()(char command) {
    text_ += command;
    return *this;
  }
  PathText& operator()(double value) {
    char buffer[32];
    const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, value);
    text_.append(buffer, end);
    text_ += ' ';
    return *this;
  }
  /// A quarter of an ellipse's outline, clockwise on the page (sweep flag 1).
  PathText& arc(double rx, double ry, double x, double y) { return (*this)('A')(rx)(ry)(0.0)(0.0)(1.0)(x)(y); }
  std::string text() const { return text_; }

 private:
  std::string text_;
};

std::string ellipse_data(double cx, double cy, double rx, double ry) {
  PathText d;
  d('M')(cx + rx)(cy).arc(rx, ry, cx, cy + ry).arc(rx, ry, cx - rx, cy).arc(rx, ry, cx, cy - ry);
  return d.arc(rx, ry, cx + rx, cy)('Z').text();
}

/// A rectangle, its corners rounded by (rx, ry) (already clamped to half its sides).
std::string rect_data(double x, double y, double w, double h, double rx, double ry) {
  PathText d;
  if (rx == 0.0 || ry == 0.0) return d('M')(x)(y)('H')(x + w)('V')(y + h)('H')(x)('Z').text();
  const auto side = [&d](char command, double from, double to) {
    if (from != to) d(command)(to);
  };
  d('M')(x + rx)(y);
  side('H', x + rx, x + w - rx);
  d.arc(rx, ry, x + w, y + ry);
  side('V', y + ry, y + h - ry);
  d.arc(rx, ry, x + w - rx, y + h);
  side('H', x + w - rx, x + rx);
  d.arc(rx, ry, x, y + h - ry);
  side('V', y + h - ry, y + ry);
  return d.arc(rx, ry, x + rx, y)('Z').text();
}

}  // namespace

std::string DrawingReader::path_data(const XMLElement& e, std::string_view name, const Viewport& viewport) const {
  const auto get = [&](const char* attribute, LengthAxis axis) {
    return length_attribute(e, attribute, axis, viewport);
  };
  const auto optional = [&](const char* attribute, LengthAxis axis) {
    return length_or_auto(e, attribute, axis, viewport);
  };
  constexpr LengthAxis X = LengthAxis::X, Y = LengthAxis::Y;
  PathText d;
  if (name == "line") return d('M')(get("x1", X))(get("y1", Y))('L')(get("x2", X))(get("y2", Y)).text();
  if (name == "polyline" || name == "polygon") {
    const char* text = e.Attribute("points");
    // Each further point costs 3 control points: stop reading where the document's cap would.
    const auto most = static_cast<std::size_t>(2 * ((limits::kMaxControlPoints - points_) / 3 + 1));
    const NumberList list = parse_number_list(text ? text : "", "in points", most);
    if (!list.error.empty()) import_failure(file_, e.GetLineNum(), list.error);
    if (list.numbers.size() % 2 != 0) {
      import_failure(file_, e.GetLineNum(),
                     "expected an even number of coordinates in points, found " + std::to_string(list.numbers.size()));
    }
    if (list.numbers.size() < 4) return "";
    d('M');
    for (const double v : list.numbers) d(v);
    return name == "polygon" ? d('Z').text() : d.text();
  }
  if (name == "circle" || name == "ellipse") {
    // An ellipse's missing or auto radius is its other one (SVG 2 section 10.4).
    const std::optional<double> r = name == "circle" ? optional("r", LengthAxis::Other) : std::nullopt;
    const std::optional<double> given_rx = name == "circle" ? r : optional("rx", X);
    const std::optional<double> given_ry = name == "circle" ? r : optional("ry", Y);
    const double rx = given_rx.value_or(given_ry.value_or(0.0));
    const double ry = given_ry.value_or(rx);
    if (rx < 0.0 || ry < 0.0) import_failure(file_, e.GetLineNum(), "expected radii >= 0, found a negative one");
    if (rx == 0.0 || ry == 0.0) return "";
    return ellipse_data(get("cx", X), get("cy", Y), rx, ry);
  }
  // rect, its corners rounded by (rx, ry) clamped to half its size (SVG 1.1 section 9.2).
  const double w = get("width", X);
  const double h = get("height", Y);
  if (w < 0.0 || h < 0.0)
    import_failure(file_, e.GetLineNum(), "expected a width and height >= 0, found a negative one");
  if (w == 0.0 || h == 0.0) return "";
  const std::optional<double> given_rx = optional("rx", X);
  const std::optional<double> given_ry = optional("ry", Y);
  const double rx = given_rx.value_or(given_ry.value_or(0.0));
  const double ry = given_ry.value_or(rx);
  if (rx < 0.0 || ry < 0.0) import_failure(file_, e.GetLineNum(), "expected corner radii >= 0, found a negative one");
  return rect_data(get("x", X), get("y", Y), w, h, std::min(rx, w / 2.0), std::min(ry, h / 2.0));
}

}  // namespace sweep::io::svg_detail
