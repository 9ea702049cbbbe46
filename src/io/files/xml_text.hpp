#pragma once
// Text as XML (and HTML) character data or a quoted attribute value: the SVG export's ids and
// title, the snapshot report's names and messages. Header-only.
#include <string>
#include <string_view>

namespace sweep::io {

/// `text` with & < > " ' written as entities.
inline std::string xml_escaped(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (const char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&#39;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace sweep::io
