#pragma once
// A DOCTYPE's internal subset (`<!DOCTYPE svg ... [ ... ]>`, as Illustrator writes), which
// tinyxml2 does not read: declarations other than entities are blanked out before parsing, and
// entity declarations, which would change the text tinyxml2 reads, are refused.
#include <string>
#include <string_view>

namespace sweep::io::svg_detail {

/// `text` with its DOCTYPE's internal subset replaced by blanks (newlines kept, so lines keep
/// their numbers). Throws ImportError "FILE:LINE: expected no <!ENTITY> declarations ..." when
/// the subset declares an entity. Precondition: none.
std::string without_internal_subset(const std::string& text, std::string_view file);

}  // namespace sweep::io::svg_detail
