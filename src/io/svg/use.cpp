// <use> clones (SVG 1.1 section 5.6): the referenced shape, group or <use> drawn again, moved by
// the clone's transform and then its x and y; a <symbol> drawn in a viewport of the clone's width
// and height, its viewBox fitted in as preserveAspectRatio says (section 7.8).
#include "io/svg/detail/reader.hpp"
#include "io/svg/detail/style.hpp"

#include <algorithm>
#include <cctype>

namespace sweep::io::svg_detail {
namespace {

using tinyxml2::XMLElement;

/// How deep clones of clones may go: deeper chains are refused, not recursed into.
constexpr std::size_t kMaxUseDepth = 64;

/// The clone's reference: `href` (SVG 2), else `xlink:href` (any prefix); nullptr if none.
const char* href_of(const XMLElement& use) {
  if (const char* href = use.Attribute("href")) return href;
  for (const tinyxml2::XMLAttribute* a = use.FirstAttribute(); a != nullptr; a = a->Next()) {
    if (std::string_view(a->Name()).ends_with(":href")) return a->Value();
  }
  return nullptr;
}

void collect_ids(const XMLElement& e, std::unordered_map<std::string, const XMLElement*>& ids) {
  if (const char* id = e.Attribute("id")) ids.emplace(id, &e);  // the first of an id wins
  for (const XMLElement* child = e.FirstChildElement(); child != nullptr; child = child->NextSiblingElement()) {
    collect_ids(*child, ids);
  }
}

/// The map from a viewBox to a viewport of `width` x `height` at the origin, aligned and fitted
/// as `aspect` (preserveAspectRatio, default "xMidYMid meet") says.
Affine2 view_box_transform(const std::array<double, 4>& box, double width, double height, std::string_view aspect) {
  double sx = width / box[2];
  double sy = height / box[3];
  if (aspect.find("none") != std::string_view::npos) return {sx, 0.0, 0.0, sy, -box[0] * sx, -box[1] * sy};
  const double s = aspect.find("slice") != std::string_view::npos ? std::max(sx, sy) : std::min(sx, sy);
  const auto align = [&aspect](std::string_view axis, double room) {
    if (aspect.find(std::string(axis) + "Min") != std::string_view::npos) return 0.0;
    if (aspect.find(std::string(axis) + "Max") != std::string_view::npos) return room;
    return room / 2.0;
  };
  const double tx = align("x", width - box[2] * s) - box[0] * s;
  const double ty = align("Y", height - box[3] * s) - box[1] * s;
  return {s, 0.0, 0.0, s, tx, ty};
}

Affine2 translation(double x, double y) {
  return {1.0, 0.0, 0.0, 1.0, x, y};
}

}  // namespace

const XMLElement& DrawingReader::referenced(const XMLElement& use) {
  const char* href = href_of(use);
  std::string_view reference = href ? href : "";
  while (!reference.empty() && std::isspace(static_cast<unsigned char>(reference.front()))) reference.remove_prefix(1);
  while (!reference.empty() && std::isspace(static_cast<unsigned char>(reference.back()))) reference.remove_suffix(1);
  const std::string expected = "expected a reference to an element of this file ('#id') as <use>'s href, found ";
  if (href == nullptr) import_failure(file_, use.GetLineNum(), expected + "none");
  if (!reference.starts_with('#')) {
    import_failure(file_, use.GetLineNum(), expected + "'" + printable_excerpt(reference, 60) + "'");
  }
  if (ids_.empty()) collect_ids(*root_, ids_);
  const auto found = ids_.find(std::string(reference.substr(1)));
  if (found == ids_.end()) {
    import_failure(file_, use.GetLineNum(),
                   expected + "'" + printable_excerpt(reference, 60) + "' (no element has that id)");
  }
  return *found->second;
}

void DrawingReader::draw_use(const XMLElement& use, const DrawContext& context) {
  const XMLElement& target = referenced(use);
  if (std::ranges::find(uses_, &use) != uses_.end()) {
    import_failure(file_, use.GetLineNum(),
                   "expected a <use> outside what it references, found '" + printable_excerpt(href_of(use), 60) +
                       "' (a reference cycle)");
  }
  if (uses_.size() >= kMaxUseDepth) {
    import_failure(file_, use.GetLineNum(),
                   "expected clones of clones at most " + std::to_string(kMaxUseDepth) + " deep, found deeper");
  }
  DrawContext here = context;
  const double x = length_attribute(use, "x", LengthAxis::X, context.viewport);
  const double y = length_attribute(use, "y", LengthAxis::Y, context.viewport);
  here.to_swp = compose(context.to_swp, translation(x, y));
  uses_.push_back(&use);
  if (svg_name(target) == "symbol") {
    draw_symbol(target, use, here);
  } else {
    visit(target, here);
  }
  uses_.pop_back();
}

void DrawingReader::draw_symbol(const XMLElement& symbol, const XMLElement& use, DrawContext context) {
  if (!displayed(symbol) || !applies(symbol)) return;
  context.visible = visibility(symbol, context.visible);
  // The viewport: the clone's width and height, else the symbol's (SVG 2), else 100%.
  const auto side = [&](const char* name, LengthAxis axis) {
    std::optional<double> value = length_or_auto(use, name, axis, context.viewport);
    if (!value) value = length_or_auto(symbol, name, axis, context.viewport);
    return value ? value : percent_base(context.viewport, axis);
  };
  const std::optional<double> width = side("width", LengthAxis::X);
  const std::optional<double> height = side("height", LengthAxis::Y);
  const double x = length_attribute(symbol, "x", LengthAxis::X, context.viewport);
  const double y = length_attribute(symbol, "y", LengthAxis::Y, context.viewport);
  context.to_swp = compose(context.to_swp, translation(x, y));
  if (const std::optional<std::array<double, 4>> box = view_box(symbol)) {
    if (!width || !height) {
      import_failure(file_, use.GetLineNum(),
                     "expected a width and height for the <symbol>'s viewBox, or a viewBox or the root's width and "
                     "height to take 100% of, found neither");
    }
    if (!(*width > 0.0) || !(*height > 0.0)) return;  // an empty viewport draws nothing
    const char* aspect = symbol.Attribute("preserveAspectRatio");
    context.to_swp = compose(context.to_swp, view_box_transform(*box, *width, *height, aspect ? aspect : ""));
    context.viewport = {(*box)[2], (*box)[3]};
  } else {
    context.viewport = {width, height};
  }
  walk_children(symbol, context);
}

}  // namespace sweep::io::svg_detail
