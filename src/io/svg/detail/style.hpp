#pragma once
// Presentation properties of SVG elements: a declaration in the `style` attribute
// ("display: none; transform: rotate(45deg)") wins over the attribute of the same name
// (display="none"), as CSS says (SVG 1.1 section 6.4). Style sheets (<style>) are not read.
#include <optional>
#include <string>
#include <string_view>

namespace tinyxml2 {
class XMLElement;
}

namespace sweep::io::svg_detail {

/// The value of property `name` (lower case) in CSS declarations such as a `style` attribute's:
/// the last declaration of it, trimmed, without "!important"; nullopt if none.
std::optional<std::string> style_declaration(std::string_view declarations, std::string_view name);

/// The value of presentation property `name` of `e`: its `style` declaration, else its attribute
/// (trimmed); nullopt if neither is there.
std::optional<std::string> presentation_property(const tinyxml2::XMLElement& e, std::string_view name);

}  // namespace sweep::io::svg_detail
