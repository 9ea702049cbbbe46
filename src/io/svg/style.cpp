#include "io/svg/detail/style.hpp"

#include <tinyxml2.h>

#include <algorithm>
#include <cctype>

namespace sweep::io::svg_detail {
namespace {

std::string_view trimmed(std::string_view text) {
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.front()))) text.remove_prefix(1);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.remove_suffix(1);
  return text;
}

bool same_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

/// The value without a trailing "!important".
std::string_view without_important(std::string_view value) {
  const std::size_t bang = value.rfind('!');
  if (bang != std::string_view::npos && same_ignoring_case(trimmed(value.substr(bang + 1)), "important")) {
    return trimmed(value.substr(0, bang));
  }
  return value;
}

}  // namespace

std::optional<std::string> style_declaration(std::string_view declarations, std::string_view name) {
  std::optional<std::string> found;
  while (!declarations.empty()) {
    const std::size_t end = std::min(declarations.find(';'), declarations.size());
    const std::string_view declaration = declarations.substr(0, end);
    declarations.remove_prefix(std::min(end + 1, declarations.size()));
    const std::size_t colon = declaration.find(':');
    if (colon == std::string_view::npos) continue;
    if (same_ignoring_case(trimmed(declaration.substr(0, colon)), name)) {
      found = std::string(without_important(trimmed(declaration.substr(colon + 1))));
    }
  }
  return found;
}

std::optional<std::string> presentation_property(const tinyxml2::XMLElement& e, std::string_view name) {
  if (const char* style = e.Attribute("style")) {
    if (std::optional<std::string> value = style_declaration(style, name)) return value;
  }
  const char* attribute = e.Attribute(std::string(name).c_str());
  if (attribute == nullptr) return std::nullopt;
  return std::string(trimmed(attribute));
}

}  // namespace sweep::io::svg_detail
