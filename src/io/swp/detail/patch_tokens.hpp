#pragma once
// The tokens the format-preserving writer (swp/preserving_write.cpp) compares and rewrites: an
// object's text as pieces with their bytes, when two say the same, and a changed number in the
// file's precision. Internal to sweep_io. Header-only.
#include "io/swp/detail/lexer.hpp"
#include "model/document.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace sweep::io::swp_detail {

struct Piece {  // a token of an object's text
  TokenType type = TokenType::End;
  std::string_view text;
  std::size_t begin = 0;  // in that text
  int line = 0;
  /// A word of the format (a keyword or clause key, which the reader takes in any case), not a
  /// name: set for the writer's tokens only.
  bool format_word = false;
  bool in_point = false;  // a word between '[' and ']': a coordinate, or a cage's face index
  std::size_t end() const { return begin + text.size(); }
};

inline std::vector<Piece> pieces_of(std::string_view text) {
  Lexer lexer(text);
  std::vector<Piece> out;
  int depth = 0;
  for (auto t = lexer.next(); t.type != TokenType::End; t = lexer.next()) {
    depth += t.type == TokenType::Open ? 1 : t.type == TokenType::Close ? -1 : 0;
    out.push_back({t.type, t.text, lexer.offset_of(t), t.line});
    out.back().in_point = t.type == TokenType::Word && depth > 0;
  }
  return out;
}

inline std::optional<double> number_in(std::string_view word) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

/// Digits after the point of a plain decimal number ("2.503360": 6, "3": 0); 0 for others.
inline int decimals_of(std::string_view word) {
  if (!number_in(word) || word.find_first_of("eEnNiI") != std::string_view::npos) return 0;
  const std::size_t point = word.find('.');
  return point == std::string_view::npos ? 0 : static_cast<int>(word.size() - point - 1);
}

/// True if the two tokens say the same: equal text, or numbers of equal value ("0.000000", "0").
inline bool same(const Piece& a, const Piece& b) {
  if (a.type != b.type) return false;
  if (a.text == b.text) return true;
  if (b.format_word && equal_ignoring_case(a.text, b.text)) return true;  // "BSP2" reads as bsp2
  const std::optional<double> x = number_in(a.text), y = number_in(b.text);
  return x && y && *x == *y;
}

/// How the file writes: its line end, what it puts between objects, its size for the precision.
struct Style {
  std::string eol = "\n";
  std::string between = "\n\n";  // before a new object
  double tolerance = 0.0;        // a rewritten number may move by this much
  int point_decimals = -1;       // the decimals most of the file's points use (0: none has any); -1: not known
};

/// `text` with its '\n's as the file's line ends.
inline std::string with_eol(std::string_view text, const Style& style) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') {
      out += style.eol;
    } else {
      out += c;
    }
  }
  return out;
}

/// A changed number: with `decimals` (its line's in the file), more while that moves it by more
/// than the tolerance, the shortest exact text past 17. An integer as written (STEPS, counts),
/// unless `coordinate` says it is a point's.
inline std::string number_text_like(std::string_view written, int decimals, const Style& style,
                                    bool coordinate = false) {
  const std::optional<double> value = number_in(written);
  if (!value || !std::isfinite(*value)) return std::string(written);
  if (!coordinate && written.find_first_of(".eE") == std::string_view::npos) return std::string(written);
  for (int d = decimals; d <= 17; ++d) {
    char buffer[400];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", d, *value);
    if (n <= 0 || n >= static_cast<int>(sizeof buffer)) break;
    std::string text(buffer, static_cast<std::size_t>(n));
    const double back = number_in(text).value_or(*value);
    if (std::abs(back - *value) > style.tolerance) continue;
    if (back == 0.0 && text.front() == '-') text.erase(0, 1);  // no "-0.000000"
    return text;
  }
  return std::string(written);  // write_swp's shortest exact text
}

}  // namespace sweep::io::swp_detail
