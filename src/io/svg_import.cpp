// Importing an SVG drawing's paths and shapes as bez2 curves (the rules: svg_import.hpp).
#include "io/svg_import.hpp"

#include "geometry/limits.hpp"
#include "geometry/number_text.hpp"
#include "io/svg_path.hpp"
#include "io/svg_transform.hpp"
#include "model/caps.hpp"
#include "model/revolve_curves.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <optional>
#include <set>
#include <system_error>

namespace sweep {
namespace {

using tinyxml2::XMLElement;

/// Steps per cubic piece of every imported curve (the Create panel's default).
constexpr int kImportSteps = 16;

/// A length attribute: a number and its unit ("", "px", "mm", ..., "%").
struct Length {
  double value = 0.0;
  std::string unit;
};

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

/// Millimetres per unit of a physical unit; nullopt for px, no unit and others.
std::optional<double> millimetres_per(std::string_view unit) {
  if (unit == "mm") return 1.0;
  if (unit == "cm") return 10.0;
  if (unit == "in") return 25.4;
  if (unit == "pt") return 25.4 / 72.0;
  if (unit == "pc") return 25.4 / 6.0;
  if (unit == "q") return 0.25;
  return std::nullopt;
}

/// CSS pixels (user units) per unit: 96 per inch; nullopt for %, em and unknown units.
std::optional<double> pixels_per(std::string_view unit) {
  if (unit.empty() || unit == "px") return 1.0;
  if (const std::optional<double> mm = millimetres_per(unit)) return *mm * 96.0 / 25.4;
  return std::nullopt;
}

const char* const kLengthExpected = "a length (a number with px, mm, cm, in, pt, pc, q or no unit)";

/// Where the walk is: the file's name for messages, the curves so far, their names and counts.
class DrawingReader {
 public:
  DrawingReader(std::string_view file, const std::string& unnamed, double scale)
      : file_(file), unnamed_(unnamed), scale_(scale) {}

  Document read(const XMLElement& root) {
    if (local_name(root) != "svg") {
      import_failure(file_, root.GetLineNum(),
                     "expected an <svg> root element, found <" + std::string(root.Name()) + ">");
    }
    const glm::dvec2 units = root_units(root);
    const Affine2 flip{units.x * scale_, 0.0, 0.0, -units.y * scale_, 0.0, 0.0};
    walk(root, compose(flip, transform_of(root)));
    if (doc_.objects.empty()) import_failure(file_, 0, "no paths or shapes to import; nothing written");
    return std::move(doc_);
  }

 private:
  /// The name without an "svg:" prefix; empty for elements of other namespaces (sodipodi:...).
  static std::string_view local_name(const XMLElement& e) {
    std::string_view name = e.Name();
    if (name.starts_with("svg:")) name.remove_prefix(4);
    return name.find(':') == std::string_view::npos ? name : std::string_view();
  }

  /// The length of one user unit in the document's unit, in x and y (svg_import.hpp).
  glm::dvec2 root_units(const XMLElement& root) const {
    const std::optional<Length> width = root_length(root, "width");
    const std::optional<Length> height = root_length(root, "height");
    const bool physical = (width && millimetres_per(width->unit)) || (height && millimetres_per(height->unit));
    const auto in_document_unit = [physical](const Length& l) {
      return physical ? l.value * millimetres_per(l.unit).value_or(25.4 / 96.0) : l.value * *pixels_per(l.unit);
    };
    const char* view_box = root.Attribute("viewBox");
    if (view_box == nullptr) return glm::dvec2(physical ? 25.4 / 96.0 : 1.0);
    const NumberList box = parse_number_list(view_box, "in viewBox", 4);
    if (!box.error.empty() || box.numbers.size() != 4 || !(box.numbers[2] > 0.0) || !(box.numbers[3] > 0.0)) {
      import_failure(file_, root.GetLineNum(),
                     "expected a viewBox of 4 numbers (x y width height, both sizes > 0), found '" +
                         printable_excerpt(view_box, 60) + "'");
    }
    std::optional<double> sx;
    std::optional<double> sy;
    if (width && width->unit != "%") sx = in_document_unit(*width) / box.numbers[2];
    if (height && height->unit != "%") sy = in_document_unit(*height) / box.numbers[3];
    if (!sx && !sy) return glm::dvec2(1.0);
    if (!sx) return glm::dvec2(*sy);
    if (!sy) return glm::dvec2(*sx);
    const char* aspect = root.Attribute("preserveAspectRatio");
    if (aspect != nullptr && std::string_view(aspect).find("none") != std::string_view::npos) return {*sx, *sy};
    const bool slice = aspect != nullptr && std::string_view(aspect).find("slice") != std::string_view::npos;
    return glm::dvec2(slice ? std::max(*sx, *sy) : std::min(*sx, *sy));
  }

  /// The root's width or height: nullopt if absent; a problem if it is no length or not > 0.
  std::optional<Length> root_length(const XMLElement& root, const char* name) const {
    const char* text = root.Attribute(name);
    if (text == nullptr) return std::nullopt;
    const std::optional<Length> length = parse_length(text);
    if (!length || (length->unit != "%" && !pixels_per(length->unit)) || !(length->value > 0.0)) {
      import_failure(file_, root.GetLineNum(),
                     std::string("expected ") + kLengthExpected + " > 0 or a percentage as the root's " + name +
                         ", found '" + printable_excerpt(text, 40) + "'");
    }
    return length;
  }

  Affine2 transform_of(const XMLElement& e) const {
    const char* text = e.Attribute("transform");
    if (text == nullptr) return {};
    const TransformParse parsed = parse_transform(text);
    if (!parsed.error.empty()) import_failure(file_, e.GetLineNum(), parsed.error);
    return parsed.matrix;
  }

  static bool hidden(const XMLElement& e) {
    const char* display = e.Attribute("display");
    if (display != nullptr && std::string_view(display) == "none") return true;
    const char* style = e.Attribute("style");
    if (style == nullptr) return false;
    std::string compact;
    for (const char* c = style; *c != '\0'; ++c) {
      if (!std::isspace(static_cast<unsigned char>(*c))) compact += *c;
    }
    return compact.find("display:none") != std::string::npos;
  }

  void walk(const XMLElement& parent, const Affine2& to_swp) {
    static constexpr std::string_view kGroups[] = {"g", "a", "switch"};
    static constexpr std::string_view kShapes[] = {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"};
    for (const XMLElement* e = parent.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view name = local_name(*e);
      if (name.empty() || hidden(*e)) continue;
      if (name == "use") {
        import_failure(file_, e->GetLineNum(),
                       "expected paths or shapes, found <use> (a clone; unlink clones in the drawing program first)");
      }
      if (name == "svg") import_failure(file_, e->GetLineNum(), "expected paths or shapes, found a nested <svg>");
      const bool group = std::ranges::find(kGroups, name) != std::end(kGroups);
      const bool shape = std::ranges::find(kShapes, name) != std::end(kShapes);
      if (!group && !shape) continue;  // defs, text, image, metadata, ...: nothing to import
      const Affine2 here = compose(to_swp, transform_of(*e));
      if (group) {
        walk(*e, here);
      } else {
        add_curves(*e, name, here);
      }
    }
  }

  /// A length attribute of a shape in user units (0 if absent).
  double length_attribute(const XMLElement& e, const char* name, std::optional<double> fallback = 0.0) const {
    const char* text = e.Attribute(name);
    if (text == nullptr) return fallback.value_or(0.0);
    const std::optional<Length> length = parse_length(text);
    const std::optional<double> per = length ? pixels_per(length->unit) : std::nullopt;
    if (!per) {
      import_failure(
          file_, e.GetLineNum(),
          std::string("expected ") + kLengthExpected + " as " + name + ", found '" + printable_excerpt(text, 40) + "'");
    }
    return length->value * *per;
  }

  std::string path_data(const XMLElement& e, std::string_view name) const;

  void add_curves(const XMLElement& e, std::string_view name, const Affine2& to_swp) {
    const std::string data =
        name == "path" ? std::string(e.Attribute("d") ? e.Attribute("d") : "") : path_data(e, name);
    const auto remaining = static_cast<std::size_t>(limits::kMaxControlPoints - points_);
    PathParse parsed = parse_path_data(data, remaining);
    if (!parsed.error.empty()) import_failure(file_, e.GetLineNum(), parsed.error);
    for (BezierSubpath& subpath : parsed.subpaths) add_curve(e, subpath, to_swp);
  }

  void add_curve(const XMLElement& e, const BezierSubpath& subpath, const Affine2& to_swp) {
    Object curve;
    curve.set_kind(ObjectKind::Bezier2);
    curve.name = unique_name(e.Attribute("id"));
    curve.as<StepsPart>().steps = kImportSteps;
    std::vector<glm::dvec3>& points = curve.as<PointsPart>().points;
    points.reserve(subpath.points.size());
    for (const glm::dvec2& p : subpath.points) {
      const glm::dvec2 q = to_swp.apply(p) + glm::dvec2(0.0);  // + 0.0 turns -0 into 0
      if (!(std::abs(q.x) <= limits::kMaxCoordinate && std::abs(q.y) <= limits::kMaxCoordinate)) {
        import_failure(file_, e.GetLineNum(),
                       "expected coordinates of at most 1e12 after the transforms and units, found (" +
                           number_text(q.x) + ", " + number_text(q.y) + ")");
      }
      points.emplace_back(q, 0.0);
    }
    if (subpath.closed) points.back() = points.front();
    const auto count = static_cast<std::int64_t>(points.size());
    points_ += count;
    std::optional<CapBreach> breach = tally_.add_points(count, "this curve");
    if (!breach) breach = tally_.add_samples((count - 1) / 3 * kImportSteps + 1, "16 steps per piece give");
    if (breach) import_failure(file_, e.GetLineNum(), breach->expected + " (" + breach->note + ")");
    doc_.objects.push_back(std::move(curve));
  }

  /// The element's id made a valid name, or the default name, with "_2", "_3", ... if taken.
  std::string unique_name(const char* id) {
    std::string base;
    if (id == nullptr || *id == '\0') {
      base = unnamed_;
    } else {
      if (!std::isalpha(static_cast<unsigned char>(id[0])) && id[0] != '_') base += '_';
      for (const char* c = id; *c != '\0' && base.size() < limits::kMaxNameLength; ++c) {
        const bool allowed = std::isalnum(static_cast<unsigned char>(*c)) || *c == '_' || *c == '-' || *c == '.';
        base += allowed ? *c : '_';
      }
    }
    std::string name = base;
    for (int n = 2; used_.contains(name); ++n) {
      std::string suffix = "_";
      suffix += std::to_string(n);
      name = base.substr(0, limits::kMaxNameLength - suffix.size()) + suffix;
    }
    used_.insert(name);
    return name;
  }

  std::string_view file_;
  std::string unnamed_;
  double scale_;
  Document doc_;
  std::set<std::string> used_;
  CapTally tally_;
  std::int64_t points_ = 0;
};

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

std::string DrawingReader::path_data(const XMLElement& e, std::string_view name) const {
  const auto get = [&](const char* attribute) { return length_attribute(e, attribute); };
  PathText d;
  if (name == "line") return d('M')(get("x1"))(get("y1"))('L')(get("x2"))(get("y2")).text();
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
    const double cx = get("cx");
    const double cy = get("cy");
    const double rx = name == "circle" ? get("r") : get("rx");
    const double ry = name == "circle" ? rx : get("ry");
    if (rx < 0.0 || ry < 0.0) import_failure(file_, e.GetLineNum(), "expected radii >= 0, found a negative one");
    if (rx == 0.0 || ry == 0.0) return "";
    d('M')(cx + rx)(cy).arc(rx, ry, cx, cy + ry).arc(rx, ry, cx - rx, cy).arc(rx, ry, cx, cy - ry);
    return d.arc(rx, ry, cx + rx, cy)('Z').text();
  }
  // rect, its corners rounded by (rx, ry) clamped to half its size (SVG 1.1 section 9.2).
  const double x = get("x");
  const double y = get("y");
  const double w = get("width");
  const double h = get("height");
  if (w < 0.0 || h < 0.0)
    import_failure(file_, e.GetLineNum(), "expected a width and height >= 0, found a negative one");
  if (w == 0.0 || h == 0.0) return "";
  const bool has_rx = e.Attribute("rx") != nullptr;
  const bool has_ry = e.Attribute("ry") != nullptr;
  double rx = has_rx ? get("rx") : (has_ry ? get("ry") : 0.0);
  double ry = has_ry ? get("ry") : rx;
  if (rx < 0.0 || ry < 0.0) import_failure(file_, e.GetLineNum(), "expected corner radii >= 0, found a negative one");
  rx = std::min(rx, w / 2.0);
  ry = std::min(ry, h / 2.0);
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

Document parse_svg_drawing(const std::string& text, std::string_view file_name, const std::string& unnamed,
                           double scale, DrawingImport what) {
  if (!is_valid_object_name(unnamed)) throw std::invalid_argument("parse_svg_drawing: invalid default name");
  if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("parse_svg_drawing: scale must be > 0");
  tinyxml2::XMLDocument xml;
  if (xml.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() is "Error=NAME ErrorID=N (0xN) Line number=N: DETAIL"; the detail is kept.
    const std::string_view full = xml.ErrorStr();
    const std::size_t colon = full.find(": ");
    std::string detail;
    if (colon != std::string_view::npos) detail = " (" + printable_excerpt(full.substr(colon + 2), 120) + ")";
    import_failure(file_name, xml.ErrorLineNum(),
                   std::string("expected well-formed XML, found ") + xml.ErrorName() + detail);
  }
  const XMLElement* root = xml.RootElement();
  if (root == nullptr) import_failure(file_name, 0, "expected an <svg> root element, found none");
  Document curves = DrawingReader(file_name, unnamed, scale).read(*root);
  if (what == DrawingImport::Curves) return curves;
  Document revolved = revolve_curves(std::move(curves), kRevolvedSteps);
  // The surfaces' vertices count against the caps as the reader would count them.
  const auto object_at = [&revolved](int index) -> const Object& {
    return revolved.objects[static_cast<std::size_t>(index)];
  };
  if (const auto breach = first_cap_breach(static_cast<int>(revolved.objects.size()), object_at)) {
    import_failure(file_name, 0,
                   breach->second.expected + " (surface " +
                       revolved.objects[static_cast<std::size_t>(breach->first)].name + ": " + breach->second.note +
                       ")");
  }
  return revolved;
}

Document import_svg_drawing(const std::filesystem::path& path, const std::string& unnamed, double scale,
                            DrawingImport what) {
  return parse_svg_drawing(read_import_file(path, "an SVG file"), path.string(), unnamed, scale, what);
}

}  // namespace sweep
