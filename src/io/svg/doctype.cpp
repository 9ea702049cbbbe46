#include "io/svg/detail/doctype.hpp"

#include "io/files/import_file.hpp"
#include "model/document.hpp"

#include <algorithm>

namespace sweep::io::svg_detail {
namespace {

/// The position after the quoted literal or comment starting at `at`, or `at` if none starts.
std::size_t after_literal(std::string_view text, std::size_t at) {
  if (text[at] == '"' || text[at] == '\'') {
    const std::size_t close = text.find(text[at], at + 1);
    return close == std::string_view::npos ? text.size() : close + 1;
  }
  if (text.substr(at).starts_with("<!--")) {
    const std::size_t close = text.find("-->", at + 4);
    return close == std::string_view::npos ? text.size() : close + 3;
  }
  return at;
}

int line_at(std::string_view text, std::size_t at) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n'));
}

}  // namespace

std::string without_internal_subset(const std::string& text, std::string_view file) {
  const std::string_view view = text;
  const std::size_t doctype = view.find("<!DOCTYPE");
  if (doctype == std::string_view::npos) return text;
  std::size_t at = doctype + 9;
  while (at < view.size() && view[at] != '[' && view[at] != '>') {
    const std::size_t next = after_literal(view, at);
    at = next == at ? at + 1 : next;
  }
  if (at >= view.size() || view[at] == '>') return text;
  const std::size_t open = at++;
  while (at < view.size() && view[at] != ']') {
    if (view.substr(at).starts_with("<!ENTITY")) {
      import_failure(file, line_at(view, at),
                     "expected no <!ENTITY> declarations in the DOCTYPE (entities are not supported), found '" +
                         printable_excerpt(view.substr(at, view.find('>', at) - at + 1), 60) + "'");
    }
    const std::size_t next = after_literal(view, at);
    at = next == at ? at + 1 : next;
  }
  if (at >= view.size()) return text;
  std::string out = text;
  for (std::size_t i = open; i <= at; ++i) {
    if (out[i] != '\n') out[i] = ' ';
  }
  return out;
}

}  // namespace sweep::io::svg_detail
