#include "io/svg/detail/path.hpp"

#include "geometry/curves/elliptical_arc.hpp"
#include "model/document.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <optional>
#include <span>

namespace sweep::io::svg_detail {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f';
}
bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

/// Reads the tokens of path data or a number list: numbers, flags and command letters, with the
/// blanks and single commas between them.
class Scanner {
 public:
  explicit Scanner(std::string_view text) : text_(text) {}

  bool at_end() const { return at_ >= text_.size(); }
  char peek() const { return at_end() ? '\0' : text_[at_]; }
  void advance() { ++at_; }
  /// Skips blanks, at most one comma, and blanks again.
  void skip_separators() {
    skip_blanks();
    if (peek() == ',') {
      ++at_;
      skip_blanks();
    }
  }
  void skip_blanks() {
    while (!at_end() && is_blank(text_[at_])) ++at_;
  }
  bool at_number() const {
    const char c = peek();
    return is_digit(c) || c == '+' || c == '-' || c == '.';
  }
  /// A number by SVG's grammar, then the separators after it; nullopt (nothing read) if none
  /// starts here or it is out of double's range.
  std::optional<double> number() {
    std::size_t end = at_;
    if (end < text_.size() && (text_[end] == '+' || text_[end] == '-')) ++end;
    const std::size_t digits_start = end;
    while (end < text_.size() && is_digit(text_[end])) ++end;
    bool digits = end > digits_start;
    if (end < text_.size() && text_[end] == '.') {
      const std::size_t fraction_start = ++end;
      while (end < text_.size() && is_digit(text_[end])) ++end;
      digits = digits || end > fraction_start;
    }
    if (!digits) return std::nullopt;
    if (end < text_.size() && (text_[end] == 'e' || text_[end] == 'E')) {
      std::size_t exponent = end + 1;
      if (exponent < text_.size() && (text_[exponent] == '+' || text_[exponent] == '-')) ++exponent;
      if (exponent < text_.size() && is_digit(text_[exponent])) {
        end = exponent;
        while (end < text_.size() && is_digit(text_[end])) ++end;
      }
    }
    const std::size_t first = text_[at_] == '+' ? at_ + 1 : at_;
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(text_.data() + first, text_.data() + end, value);
    if (ec != std::errc() || ptr != text_.data() + end || !std::isfinite(value)) return std::nullopt;
    at_ = end;
    skip_separators();
    return value;
  }
  /// An arc flag: the single character 0 or 1, then the separators after it.
  std::optional<bool> flag() {
    const char c = peek();
    if (c != '0' && c != '1') return std::nullopt;
    ++at_;
    skip_separators();
    return c == '1';
  }
  /// What stands here, for a message: "'x1'" (up to the next blank or comma, at most 20
  /// characters) or "the end of ...".
  std::string found(std::string_view what) const {
    if (at_end()) return "the end of " + std::string(what);
    std::size_t end = at_ + 1;
    while (end < text_.size() && end - at_ < 20 && !is_blank(text_[end]) && text_[end] != ',') ++end;
    std::string out = "'";
    out += printable_excerpt(text_.substr(at_, end - at_), 20);
    return out += '\'';
  }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
};

constexpr std::string_view kCommands = "MmLlHhVvCcSsQqTtAaZz";

/// The command interpreter: the current point, the subpath being built, the last handle for S
/// and T.
class PathBuilder {
 public:
  PathBuilder(std::string_view data, std::size_t max_points) : scan_(data), max_points_(max_points) {}

  PathParse run() {
    scan_.skip_blanks();
    if (scan_.at_end()) return {};
    if (scan_.peek() != 'M' && scan_.peek() != 'm') {
      return fail("expected 'M' or 'm' at the start of path data, found " + scan_.found("the path data"));
    }
    while (!scan_.at_end()) {
      const char command = scan_.peek();
      if (kCommands.find(command) == std::string_view::npos || command == '\0') {
        return fail("expected a path command (one of " + std::string("M L H V C S Q T A Z") + ") in path data, found " +
                    scan_.found("the path data"));
      }
      scan_.advance();
      scan_.skip_blanks();
      if (!command_with_repeats(command)) return std::move(result_);
    }
    flush();
    if (!result_.error.empty()) result_.subpaths.clear();
    return std::move(result_);
  }

 private:
  PathParse fail(std::string message) {
    result_.subpaths.clear();
    result_.error = std::move(message);
    return std::move(result_);
  }

  /// One command letter's argument groups: the first, then more while a number follows.
  bool command_with_repeats(char command) {
    const char upper = static_cast<char>(command & ~0x20);
    if (upper == 'Z') {
      close();
      if (scan_.at_number()) return error_after(command, "a path command");
      return true;
    }
    char current = command;
    do {
      if (!one_group(current)) return false;
      if (upper == 'M') current = command == 'M' ? 'L' : 'l';  // a moveto's further pairs are linetos
    } while (scan_.at_number());
    return count_ok();
  }

  bool error_after(char command, std::string_view expected) {
    result_.subpaths.clear();
    result_.error = "expected " + std::string(expected) + " after '" + std::string(1, command) +
                    "' in path data, found " + scan_.found("the path data");
    return false;
  }

  bool numbers(char command, std::span<double> out) {
    for (double& value : out) {
      const std::optional<double> number = scan_.number();
      if (!number) return error_after(command, "a number");
      value = *number;
    }
    return true;
  }

  bool count_ok() {
    if (points_ <= max_points_) return true;
    result_.subpaths.clear();
    result_.error = "expected at most " + std::to_string(max_points_) + " control points, found more in this path data";
    return false;
  }

  bool one_group(char command) {
    const bool relative = command >= 'a';
    const glm::dvec2 base = relative ? current_ : glm::dvec2(0.0);
    const char upper = static_cast<char>(command & ~0x20);
    double v[7] = {};
    const auto at = [&](int i) { return base + glm::dvec2(v[i], v[i + 1]); };
    switch (upper) {
      case 'M':
        if (!numbers(command, std::span(v, 2))) return false;
        move_to(at(0));
        return true;
      case 'L':
        if (!numbers(command, std::span(v, 2))) return false;
        line_to(at(0));
        return true;
      case 'H':
        if (!numbers(command, std::span(v, 1))) return false;
        line_to({(relative ? current_.x : 0.0) + v[0], current_.y});
        return true;
      case 'V':
        if (!numbers(command, std::span(v, 1))) return false;
        line_to({current_.x, (relative ? current_.y : 0.0) + v[0]});
        return true;
      case 'C':
        if (!numbers(command, std::span(v, 6))) return false;
        cubic_to(at(0), at(2), at(4));
        return true;
      case 'S':
        if (!numbers(command, std::span(v, 4))) return false;
        cubic_to(last_cubic_ ? 2.0 * current_ - *last_cubic_ : current_, at(0), at(2));
        return true;
      case 'Q':
        if (!numbers(command, std::span(v, 4))) return false;
        quad_to(at(0), at(2));
        return true;
      case 'T':
        if (!numbers(command, std::span(v, 2))) return false;
        quad_to(last_quad_ ? 2.0 * current_ - *last_quad_ : current_, at(0));
        return true;
      default:
        return arc(command, base);
    }
  }

  bool arc(char command, glm::dvec2 base) {
    double v[3] = {};
    if (!numbers(command, std::span(v, 3))) return false;
    const std::optional<bool> large = scan_.flag();
    if (!large) return error_after(command, "the large-arc flag (0 or 1)");
    const std::optional<bool> sweep = scan_.flag();
    if (!sweep) return error_after(command, "the sweep flag (0 or 1)");
    double end[2] = {};
    if (!numbers(command, std::span(end, 2))) return false;
    const EndpointArc endpoint{current_, base + glm::dvec2(end[0], end[1]), v[0], v[1], v[2], *large, *sweep};
    ensure_started();
    for (const glm::dvec2& p : arc_to_cubics(endpoint)) add(p);
    current_ = endpoint.to;
    forget_handles();
    return true;
  }

  void add(glm::dvec2 p) {
    subpath_.points.push_back(p);
    ++points_;
  }
  void forget_handles() {
    last_cubic_.reset();
    last_quad_.reset();
  }
  void flush() {
    if (subpath_.points.size() >= 4) {
      result_.subpaths.push_back(std::move(subpath_));
    } else {
      points_ -= subpath_.points.size();
    }
    subpath_ = {};
  }
  void move_to(glm::dvec2 p) {
    flush();
    start_ = current_ = p;
    add(p);
    forget_handles();
  }
  /// A drawing command after Z (or at a subpath's start) begins at the current point.
  void ensure_started() {
    if (subpath_.points.empty()) add(current_);
  }
  void line_to(glm::dvec2 p) {
    ensure_started();
    add(current_ + (p - current_) / 3.0);
    add(current_ + (p - current_) * (2.0 / 3.0));
    add(p);
    current_ = p;
    forget_handles();
  }
  void cubic_to(glm::dvec2 c1, glm::dvec2 c2, glm::dvec2 p) {
    ensure_started();
    add(c1);
    add(c2);
    add(p);
    current_ = p;
    forget_handles();
    last_cubic_ = c2;
  }
  void quad_to(glm::dvec2 q, glm::dvec2 p) {
    ensure_started();
    add(current_ + (q - current_) * (2.0 / 3.0));
    add(p + (q - p) * (2.0 / 3.0));
    add(p);
    current_ = p;
    forget_handles();
    last_quad_ = q;
  }
  /// Whether the current point is the subpath's first: equal, or within 1e-9 of its largest
  /// coordinate (relative coordinates summed up miss it by a rounding), so Z adds no piece of no
  /// length.
  bool back_at_start() const {
    double largest = 0.0;
    for (const glm::dvec2& p : subpath_.points) largest = std::max({largest, std::abs(p.x), std::abs(p.y)});
    const glm::dvec2 gap = glm::abs(current_ - start_);
    return std::max(gap.x, gap.y) <= 1e-9 * largest;
  }
  void close() {
    if (!subpath_.points.empty() && !back_at_start()) line_to(start_);
    if (subpath_.points.size() >= 4) {
      subpath_.points.back() = subpath_.points.front();
      subpath_.closed = true;
    }
    flush();
    current_ = start_;
    forget_handles();
  }

  Scanner scan_;
  std::size_t max_points_;
  std::size_t points_ = 0;
  PathParse result_;
  BezierSubpath subpath_;
  glm::dvec2 current_{0.0};
  glm::dvec2 start_{0.0};
  std::optional<glm::dvec2> last_cubic_;
  std::optional<glm::dvec2> last_quad_;
};

}  // namespace

PathParse parse_path_data(std::string_view data, std::size_t max_points) {
  return PathBuilder(data, max_points).run();
}

NumberList parse_number_list(std::string_view text, std::string_view what, std::size_t max_numbers) {
  Scanner scan(text);
  NumberList out;
  scan.skip_blanks();
  while (!scan.at_end()) {
    if (out.numbers.size() >= max_numbers) {
      return {{}, "expected at most " + std::to_string(max_numbers) + " numbers " + std::string(what)};
    }
    const std::optional<double> number = scan.number();
    if (!number) return {{}, "expected a number " + std::string(what) + ", found " + scan.found(what)};
    out.numbers.push_back(*number);
  }
  return out;
}

}  // namespace sweep::io::svg_detail
