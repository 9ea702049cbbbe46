// What applies to every element of a drawing: its namespace, its conditions (conditional
// processing, <switch>), its display and visibility, its transform and its lengths.
#include "io/svg/detail/css_transform.hpp"
#include "io/svg/detail/reader.hpp"
#include "io/svg/detail/style.hpp"

#include <algorithm>
#include <cctype>

namespace sweep::io::svg_detail {
namespace {

using tinyxml2::XMLElement;

constexpr std::string_view kSvgNamespace = "http://www.w3.org/2000/svg";

/// The namespace that attribute `declaration` ("xmlns" or "xmlns:p") binds at `e`, from `e` or
/// its nearest ancestor that declares it; nullptr if none does.
const char* namespace_bound(const XMLElement& e, const std::string& declaration) {
  for (const XMLElement* at = &e; at != nullptr; at = at->Parent() ? at->Parent()->ToElement() : nullptr) {
    if (const char* uri = at->Attribute(declaration.c_str())) return uri;
  }
  return nullptr;
}

/// The elements a <switch> chooses among (SVG 1.1 section 5.8.2): the ones that draw something.
constexpr std::string_view kSwitchable[] = {"g",        "a",       "switch", "use",     "svg",
                                            "path",     "rect",    "circle", "ellipse", "line",
                                            "polyline", "polygon", "text",   "image",   "foreignObject"};

/// A systemLanguage list matches when a language in it is English ("en", "en-GB"): the import
/// reads a drawing as an English-speaking reader's browser draws it.
bool english_among(std::string_view languages) {
  while (!languages.empty()) {
    const std::size_t comma = std::min(languages.find(','), languages.size());
    std::string_view language = languages.substr(0, comma);
    languages.remove_prefix(std::min(comma + 1, languages.size()));
    while (!language.empty() && std::isspace(static_cast<unsigned char>(language.front()))) language.remove_prefix(1);
    if (language.size() >= 2 && std::tolower(static_cast<unsigned char>(language[0])) == 'e' &&
        std::tolower(static_cast<unsigned char>(language[1])) == 'n' &&
        (language.size() == 2 || language[2] == '-' || std::isspace(static_cast<unsigned char>(language[2])))) {
      return true;
    }
  }
  return false;
}

}  // namespace

std::string_view DrawingReader::svg_name(const XMLElement& e) {
  const std::string_view name = e.Name();
  const std::size_t colon = name.find(':');
  const std::string prefix(colon == std::string_view::npos ? std::string_view() : name.substr(0, colon));
  const char* uri = namespace_bound(e, prefix.empty() ? "xmlns" : "xmlns:" + prefix);
  const bool svg = uri == nullptr ? prefix.empty() || prefix == "svg" : uri == kSvgNamespace;
  if (!svg) return {};
  return colon == std::string_view::npos ? name : name.substr(colon + 1);
}

bool DrawingReader::applies(const XMLElement& e) {
  // No extension is supported (SVG 1.1 section 5.8.5: an empty list fails too); requiredFeatures
  // is no more (SVG 2) and passes, as in browsers.
  if (e.Attribute("requiredExtensions") != nullptr) return false;
  const char* languages = e.Attribute("systemLanguage");
  return languages == nullptr || english_among(languages);
}

bool DrawingReader::displayed(const XMLElement& e) {
  return presentation_property(e, "display") != "none";
}

bool DrawingReader::visibility(const XMLElement& e, bool inherited) {
  const std::optional<std::string> value = presentation_property(e, "visibility");
  if (value == "hidden" || value == "collapse") return false;
  if (value == "visible") return true;
  return inherited;
}

const XMLElement* DrawingReader::switch_choice(const XMLElement& e) {
  for (const XMLElement* child = e.FirstChildElement(); child != nullptr; child = child->NextSiblingElement()) {
    const std::string_view name = svg_name(*child);
    if (std::ranges::find(kSwitchable, name) != std::end(kSwitchable) && applies(*child)) return child;
  }
  return nullptr;
}

Affine2 DrawingReader::transform_of(const XMLElement& e, const Viewport& viewport) const {
  TransformParse parsed;
  const char* style = e.Attribute("style");
  if (const std::optional<std::string> css = style ? style_declaration(style, "transform") : std::nullopt) {
    parsed = parse_css_transform(*css);
  } else if (const char* text = e.Attribute("transform")) {
    parsed = parse_transform(text);
  }
  if (!parsed.error.empty()) import_failure(file_, e.GetLineNum(), parsed.error);
  if (parsed.matrix == Affine2{}) return parsed.matrix;
  if (const std::optional<std::string> box = presentation_property(e, "transform-box"); box && *box != "view-box") {
    import_failure(file_, e.GetLineNum(),
                   "expected transform-box view-box (the viewport), found '" + printable_excerpt(*box, 40) +
                       "' (the element's own box is not supported)");
  }
  const std::optional<std::string> origin = presentation_property(e, "transform-origin");
  if (!origin) return parsed.matrix;
  const OriginParse at = parse_transform_origin(*origin, viewport);
  if (!at.error.empty()) import_failure(file_, e.GetLineNum(), at.error);
  return about(parsed.matrix, at.origin);
}

std::optional<double> DrawingReader::length_or_auto(const XMLElement& e, const char* name, LengthAxis axis,
                                                    const Viewport& viewport) const {
  const char* text = e.Attribute(name);
  if (text == nullptr) return std::nullopt;
  const std::optional<Length> length = parse_length(text);
  if (!length) {
    std::string_view word = text;
    while (!word.empty() && std::isspace(static_cast<unsigned char>(word.front()))) word.remove_prefix(1);
    while (!word.empty() && std::isspace(static_cast<unsigned char>(word.back()))) word.remove_suffix(1);
    if (word == "auto") return std::nullopt;
  }
  if (length && length->unit == "%" && !percent_base(viewport, axis)) {
    import_failure(file_, e.GetLineNum(),
                   std::string("expected a viewBox or the root's width and height to resolve ") + name + "=\"" +
                       printable_excerpt(text, 40) + "\", found neither");
  }
  const std::optional<double> value = length ? user_units(*length, viewport, axis) : std::nullopt;
  if (!value) {
    import_failure(
        file_, e.GetLineNum(),
        std::string("expected ") + kLengthExpected + " as " + name + ", found '" + printable_excerpt(text, 40) + "'");
  }
  return value;
}

double DrawingReader::length_attribute(const XMLElement& e, const char* name, LengthAxis axis,
                                       const Viewport& viewport) const {
  const char* text = e.Attribute(name);
  if (text != nullptr && !parse_length(text)) {
    import_failure(
        file_, e.GetLineNum(),
        std::string("expected ") + kLengthExpected + " as " + name + ", found '" + printable_excerpt(text, 40) + "'");
  }
  return length_or_auto(e, name, axis, viewport).value_or(0.0);
}

std::optional<std::array<double, 4>> DrawingReader::view_box(const XMLElement& e) const {
  const char* text = e.Attribute("viewBox");
  if (text == nullptr) return std::nullopt;
  const NumberList box = parse_number_list(text, "in viewBox", 4);
  if (!box.error.empty() || box.numbers.size() != 4 || !(box.numbers[2] > 0.0) || !(box.numbers[3] > 0.0)) {
    import_failure(file_, e.GetLineNum(),
                   "expected a viewBox of 4 numbers (x y width height, both sizes > 0), found '" +
                       printable_excerpt(text, 60) + "'");
  }
  return std::array<double, 4>{box.numbers[0], box.numbers[1], box.numbers[2], box.numbers[3]};
}

}  // namespace sweep::io::svg_detail
