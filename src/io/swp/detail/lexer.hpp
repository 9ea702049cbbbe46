#pragma once
// The SWP reader's tokens: words (keywords, names, numbers, clause keys) and the brackets of
// points, each with its line and column, and the numbers they spell, read with the
// file:line:column message of what was expected. Internal to swp/read.cpp (the reader of
// objects); header-only so the reader is split over files without another translation unit.
#include "io/swp/read.hpp"
#include "model/document.hpp"
#include "model/file_limits.hpp"

#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace sweep::io::swp_detail {

enum class TokenType { Word, Open, Close, End };

struct Token {
  TokenType type = TokenType::End;
  std::string_view text;
  int line = 0;  // 0: no token (yet)
  int column = 0;
};

constexpr bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

/// The bytes that end a word: the spaces is_space names, and the brackets. A table, so the word
/// loop (the reader's hottest: every number of a file) takes one load and one branch per byte,
/// not six comparisons whose speed depended on where the linker put them (Intel's JCC erratum:
/// 27 or 37 ms for a 250,000-point file between two builds of the same code).
inline constexpr std::array<bool, 256> kEndsWord = [] {
  std::array<bool, 256> ends{};
  for (std::size_t byte = 0; byte < ends.size(); ++byte) {
    const auto c = static_cast<char>(byte);
    ends[byte] = is_space(c) || c == '[' || c == ']';
  }
  return ends;
}();

/// Splits SWP text into tokens. Copyable and cheap to copy: a copy is a lookahead that leaves
/// the original where it was.
class Lexer {
 public:
  explicit Lexer(std::string_view text) : text_(text) {}

  Token next() {
    skip_space();
    Token token;
    token.line = line_;
    token.column = column_;
    if (pos_ >= text_.size()) return token;
    const char c = text_[pos_];
    if (c == '[' || c == ']') {
      token.type = c == '[' ? TokenType::Open : TokenType::Close;
      token.text = text_.substr(pos_, 1);
      advance(1);
      return token;
    }
    std::size_t end = pos_;
    while (end < text_.size() && !kEndsWord[static_cast<unsigned char>(text_[end])]) ++end;
    token.type = TokenType::Word;
    token.text = text_.substr(pos_, end - pos_);
    advance(end - pos_);
    return token;
  }

  /// The next token, without consuming it.
  Token peek() const {
    Lexer ahead = *this;
    return ahead.next();
  }

  std::size_t remaining() const { return text_.size() - pos_; }
  /// Bytes read so far: the end of the last token taken (spaces after it are skipped by next()).
  std::size_t offset() const { return pos_; }
  /// Where `token` (one this lexer gave, not End) starts in the text.
  std::size_t offset_of(const Token& token) const { return static_cast<std::size_t>(token.text.data() - text_.data()); }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') {
        ++line_;
        column_ = 1;
      } else {
        ++column_;
      }
      ++pos_;
    }
  }
  void advance(std::size_t n) {  // n bytes, none of them a newline
    pos_ += n;
    column_ += static_cast<int>(n);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  int column_ = 1;
};

/// How a token is shown in a message: quoted, at most 32 bytes, control and non-ASCII bytes as \xHH.
inline std::string describe(const Token& token) {
  if (token.type == TokenType::End) return "end of file";
  // Appending rather than "'" + s + "'", which trips GCC 12's false -Wrestrict at -O3.
  std::string out(1, '\'');
  out += printable_excerpt(token.text, 32);
  out += '\'';
  return out;
}

/// "point 2 of 4".
inline std::string point_text(std::int64_t point, std::int64_t count) {
  return "point " + std::to_string(point) + " of " + std::to_string(count);
}

/// What a number is for, spelled out only when a message needs it: building the words for
/// every coordinate of a million-point curve would cost more than parsing it.
struct NumberRole {
  std::string_view what;   // "radius", "alpha", or the axis "x", "y", "z"
  std::int64_t point = 0;  // 1-based point number, 0 if not a point coordinate
  std::int64_t count = 0;
  std::string text() const {
    if (point == 0) return std::string(what);
    return std::string(what) + " of " + point_text(point, count);
  }
};

/// Reads tokens and numbers, and throws ParseError at the token that is not what was expected.
class TokenReader {
 public:
  TokenReader(std::string_view text, std::string_view file) : lexer_(text), file_(file) {}

  [[noreturn]] void fail(const Token& at, const std::string& expected, const std::string& note = {}) const {
    std::string detail = expected + ", found " + describe(at);
    if (!note.empty()) detail += " (" + note + ")";
    throw ParseError(std::string(file_), at.line, at.column, detail);
  }

  /// Fails at `at` with `problem` (the "expected ..." text of a curve_parameters check) unless it is "".
  void require(const Token& at, const std::string& problem) const {
    if (!problem.empty()) fail(at, problem);
  }

  /// A whole number from `low` to `high`; `what` names it in the message ("STEPS").
  std::int64_t read_integer(const std::string& what, std::int64_t low, std::int64_t high, Token* where = nullptr) {
    const Token token = lexer_.next();
    if (where) *where = token;
    const std::string expected =
        "expected " + what + ", a whole number from " + std::to_string(low) + " to " + std::to_string(high);
    if (token.type != TokenType::Word) fail(token, expected);
    std::string_view text = token.text;
    if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec != std::errc() || end != text.data() + text.size() || value < low || value > high) fail(token, expected);
    return value;
  }

  /// A finite number; `role` says what it is for ("x of point 2 of 4").
  double read_finite(const NumberRole& role, Token* where = nullptr) { return read_real(role, where, false); }

  /// A finite number within the coordinate cap (coordinates, radii, pitch, turns).
  double read_number(const NumberRole& role, Token* where = nullptr) { return read_real(role, where, true); }

 private:
  double read_real(const NumberRole& role, Token* where, bool capped) {
    const Token token = lexer_.next();
    if (where) *where = token;
    if (token.type != TokenType::Word) fail(token, "expected a number (" + role.text() + ")");
    std::string_view text = token.text;
    if (text.size() > 1 && text[0] == '+') text.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (ec == std::errc::result_out_of_range) fail(token, "expected a number (" + role.text() + ")", "out of range");
    if (ec != std::errc() || end != text.data() + text.size()) fail(token, "expected a number (" + role.text() + ")");
    if (!std::isfinite(value)) fail(token, "expected a finite number (" + role.text() + ")");
    if (capped && std::abs(value) > limits::kMaxCoordinate) {
      fail(token, "expected a number from -1e12 to 1e12 (" + role.text() + ")");
    }
    return value;
  }

 protected:
  Lexer lexer_;
  std::string_view file_;
};

}  // namespace sweep::io::swp_detail
