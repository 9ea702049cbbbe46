// Importing an SVG drawing's paths and shapes as bez2 curves (the rules: svg/import.hpp): the
// walk of the elements and the curves they give (svg/detail/reader.hpp says where the other parts are).
#include "io/svg/import.hpp"

#include "base/number_text.hpp"
#include "io/svg/detail/doctype.hpp"
#include "io/svg/detail/reader.hpp"
#include "model/evaluation/revolve_curves.hpp"
#include "model/file_limits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace sweep::io::svg_detail {
namespace {

using tinyxml2::XMLElement;

/// Steps per cubic piece of every imported curve (the Create panel's default).
constexpr int kImportSteps = 16;

constexpr std::string_view kGroups[] = {"g", "a"};
constexpr std::string_view kShapes[] = {"path", "rect", "circle", "ellipse", "line", "polyline", "polygon"};

bool one_of(std::span<const std::string_view> names, std::string_view name) {
  return std::ranges::find(names, name) != names.end();
}

}  // namespace

Document DrawingReader::read(const XMLElement& root) {
  if (svg_name(root) != "svg") {
    import_failure(file_, root.GetLineNum(),
                   "expected an <svg> root element, found <" + std::string(root.Name()) + ">");
  }
  root_ = &root;
  const glm::dvec2 units = root_units(root);
  const Affine2 flip{units.x * scale_, 0.0, 0.0, -units.y * scale_, 0.0, 0.0};
  DrawContext context;
  context.viewport = root_viewport(root);
  context.to_swp = compose(flip, transform_of(root, context.viewport));
  context.visible = visibility(root, true);
  walk_children(root, context);
  if (doc_.objects.empty())
    throw NothingToImport(std::string(file_) + ": no paths or shapes to import; nothing written");
  return std::move(doc_);
}

glm::dvec2 DrawingReader::root_units(const XMLElement& root) const {
  const std::optional<Length> width = root_length(root, "width");
  const std::optional<Length> height = root_length(root, "height");
  const bool physical = (width && millimetres_per(width->unit)) || (height && millimetres_per(height->unit));
  const auto in_document_unit = [physical](const Length& l) {
    return physical ? l.value * millimetres_per(l.unit).value_or(25.4 / 96.0) : l.value * *pixels_per(l.unit);
  };
  const std::optional<std::array<double, 4>> box = view_box(root);
  if (!box) return glm::dvec2(physical ? 25.4 / 96.0 : 1.0);
  std::optional<double> sx;
  std::optional<double> sy;
  if (width && width->unit != "%") sx = in_document_unit(*width) / (*box)[2];
  if (height && height->unit != "%") sy = in_document_unit(*height) / (*box)[3];
  if (!sx && !sy) return glm::dvec2(1.0);
  if (!sx) return glm::dvec2(*sy);
  if (!sy) return glm::dvec2(*sx);
  const char* aspect = root.Attribute("preserveAspectRatio");
  if (aspect != nullptr && std::string_view(aspect).find("none") != std::string_view::npos) return {*sx, *sy};
  const bool slice = aspect != nullptr && std::string_view(aspect).find("slice") != std::string_view::npos;
  return glm::dvec2(slice ? std::max(*sx, *sy) : std::min(*sx, *sy));
}

Viewport DrawingReader::root_viewport(const XMLElement& root) const {
  if (const std::optional<std::array<double, 4>> box = view_box(root)) return {(*box)[2], (*box)[3]};
  // Without a viewBox a user unit is a px: the viewport is the width and height in px, unless
  // they are percentages of a window the file does not know.
  Viewport viewport;
  const std::optional<Length> width = root_length(root, "width");
  const std::optional<Length> height = root_length(root, "height");
  if (width && width->unit != "%") viewport.width = width->value * *pixels_per(width->unit);
  if (height && height->unit != "%") viewport.height = height->value * *pixels_per(height->unit);
  return viewport;
}

std::optional<Length> DrawingReader::root_length(const XMLElement& root, const char* name) const {
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

void DrawingReader::walk_children(const XMLElement& parent, const DrawContext& context) {
  for (const XMLElement* e = parent.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) visit(*e, context);
}

void DrawingReader::visit(const XMLElement& e, const DrawContext& context) {
  const std::string_view name = svg_name(e);
  if (name.empty() || !displayed(e) || !applies(e)) return;
  if (name == "svg") import_failure(file_, e.GetLineNum(), "expected paths or shapes, found a nested <svg>");
  const bool group = one_of(kGroups, name) || name == "switch";
  if (!group && name != "use" && !one_of(kShapes, name)) return;  // defs, symbol, text, image, ...: not drawn
  if (!uses_.empty() && ++cloned_elements_ > kMaxClonedElements) {
    import_failure(
        file_, uses_.back()->GetLineNum(),
        "expected at most " + std::to_string(kMaxClonedElements) + " elements drawn through <use> clones, found more");
  }
  DrawContext here = context;
  here.to_swp = compose(context.to_swp, transform_of(e, context.viewport));
  here.visible = visibility(e, context.visible);
  if (name == "switch") {
    if (const XMLElement* chosen = switch_choice(e)) visit(*chosen, here);
  } else if (group) {
    walk_children(e, here);
  } else if (name == "use") {
    draw_use(e, here);
  } else if (here.visible) {
    add_curves(e, name, here);
  }
}

void DrawingReader::add_curves(const XMLElement& e, std::string_view name, const DrawContext& context) {
  const std::string data =
      name == "path" ? std::string(e.Attribute("d") ? e.Attribute("d") : "") : path_data(e, name, context.viewport);
  const auto remaining = static_cast<std::size_t>(limits::kMaxControlPoints - points_);
  PathParse parsed = parse_path_data(data, remaining);
  if (!parsed.error.empty()) import_failure(file_, e.GetLineNum(), parsed.error);
  for (BezierSubpath& subpath : parsed.subpaths) add_curve(e, subpath, context.to_swp);
}

void DrawingReader::add_curve(const XMLElement& e, const BezierSubpath& subpath, const Affine2& to_swp) {
  Object curve;
  curve.set_kind(ObjectKind::Bezier2);
  curve.as<StepsPart>().steps = kImportSteps;
  std::vector<glm::dvec3>& points = curve.as<PointsPart>().points;
  points.reserve(subpath.points.size());
  for (const glm::dvec2& p : subpath.points) {
    const glm::dvec2 q = to_swp.apply(p) + glm::dvec2(0.0);  // + 0.0 turns -0 into 0
    if (!(std::abs(q.x) <= limits::kMaxCoordinate && std::abs(q.y) <= limits::kMaxCoordinate)) {
      import_failure(file_, e.GetLineNum(),
                     "expected coordinates of at most 1e12 after the transforms and units, found (" + number_text(q.x) +
                         ", " + number_text(q.y) + ")");
    }
    points.emplace_back(q, 0.0);
  }
  if (subpath.closed) points.back() = points.front();
  // A shape of no length (every control point at one place) draws nothing: it is no curve.
  if (std::ranges::all_of(points, [&](const glm::dvec3& p) { return p == points.front(); })) return;
  curve.name = unique_name(e.Attribute("id"));
  const auto count = static_cast<std::int64_t>(points.size());
  points_ += count;
  std::optional<CapBreach> breach = tally_.add_points(count, "this curve");
  if (!breach) breach = tally_.add_samples((count - 1) / 3 * kImportSteps + 1, "16 steps per piece give");
  if (breach) import_failure(file_, e.GetLineNum(), breach->expected + " (" + breach->note + ")");
  doc_.objects.push_back(std::move(curve));
}

std::string DrawingReader::unique_name(const char* id) {
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

}  // namespace sweep::io::svg_detail

namespace sweep::io {

Document parse_svg_drawing(const std::string& text, std::string_view file_name, const std::string& unnamed,
                           double scale, DrawingImport what) {
  if (!is_valid_object_name(unnamed)) throw std::invalid_argument("parse_svg_drawing: invalid default name");
  if (!(scale > 0.0) || !std::isfinite(scale)) throw std::invalid_argument("parse_svg_drawing: scale must be > 0");
  const std::string xml_text = svg_detail::without_internal_subset(text, file_name);
  tinyxml2::XMLDocument xml;
  if (xml.Parse(xml_text.data(), xml_text.size()) != tinyxml2::XML_SUCCESS) {
    // ErrorStr() is "Error=NAME ErrorID=N (0xN) Line number=N: DETAIL"; the detail is kept.
    const std::string_view full = xml.ErrorStr();
    const std::size_t colon = full.find(": ");
    std::string detail;
    if (colon != std::string_view::npos) detail = " (" + printable_excerpt(full.substr(colon + 2), 120) + ")";
    import_failure(file_name, xml.ErrorLineNum(),
                   std::string("expected well-formed XML, found ") + xml.ErrorName() + detail);
  }
  const tinyxml2::XMLElement* root = xml.RootElement();
  if (root == nullptr) import_failure(file_name, 0, "expected an <svg> root element, found none");
  Document curves = svg_detail::DrawingReader(file_name, unnamed, scale).read(*root);
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

}  // namespace sweep::io
