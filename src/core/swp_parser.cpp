// SWP reader. A hand-written lexer and recursive reader: the format is a flat list of objects,
// so one pass with one token of lookahead is enough, and every error knows its line and column.
#include "core/swp_parser.hpp"

#include "core/limits.hpp"
#include "core/surface.hpp"
#include "core/swp_writer.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unordered_map>

namespace sweep {

ParseError::ParseError(std::string file, int line, int column, std::string detail)
    : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + detail
                                  : file + ": " + detail),
      file_(std::move(file)),
      line_(line),
      column_(column),
      detail_(std::move(detail)) {}

namespace {

enum class TokenType { Word, Open, Close, End };

struct Token {
  TokenType type = TokenType::End;
  std::string_view text;
  int line = 1;
  int column = 1;
};

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v';
}

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
    while (end < text_.size() && !is_space(text_[end]) && text_[end] != '[' && text_[end] != ']') ++end;
    token.type = TokenType::Word;
    token.text = text_.substr(pos_, end - pos_);
    advance(end - pos_);
    return token;
  }

  std::size_t remaining() const { return text_.size() - pos_; }

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
std::string describe(const Token& token) {
  if (token.type == TokenType::End) return "end of file";
  // Appending rather than "'" + s + "'", which trips GCC 12's false -Wrestrict at -O3.
  std::string out(1, '\'');
  out += printable_excerpt(token.text, 32);
  out += '\'';
  return out;
}

std::string kind_description(ObjectKind kind) {
  return std::string(is_surface(kind) ? "a surface (" : "a curve (") + std::string(keyword(kind)) + ")";
}

class Parser {
 public:
  Parser(std::string_view text, std::string_view file) : lexer_(text), file_(file) {}

  Document parse() {
    Document doc;
    for (Token token = lexer_.next(); token.type != TokenType::End; token = lexer_.next()) {
      const auto kind = token.type == TokenType::Word ? kind_from_keyword(token.text) : std::nullopt;
      if (!kind) {
        // A '[' here most often means a curve has more points than its count says.
        const bool extra_point =
            token.type == TokenType::Open && !doc.objects.empty() && has_control_points(doc.objects.back().kind);
        fail(token, "expected a keyword (bez2, bez3, bsp2, bsp3, circ, srev, gcyl)",
             extra_point ? "the " + std::string(keyword(doc.objects.back().kind)) + " above already has its " +
                               std::to_string(doc.objects.back().points.size()) + " points"
                         : std::string());
      }
      Object object;
      object.kind = *kind;
      object.location = {token.line, token.column};
      read_name(object, doc);
      switch (object.kind) {
        case ObjectKind::Bezier2:
        case ObjectKind::Bezier3:
        case ObjectKind::BSpline2:
        case ObjectKind::BSpline3:
          read_control_point_curve(object);
          break;
        case ObjectKind::Circle:
          read_circle(object);
          break;
        case ObjectKind::SurfaceOfRevolution:
          read_revolution(object, doc);
          break;
        case ObjectKind::GeneralizedCylinder:
          read_cylinder(object, doc);
          break;
      }
      if (!object.name.empty()) names_.emplace(object.name, static_cast<int>(doc.objects.size()));
      doc.objects.push_back(std::move(object));
    }
    return doc;
  }

 private:
  [[noreturn]] void fail(const Token& at, const std::string& expected, const std::string& note = {}) {
    std::string detail = expected + ", found " + describe(at);
    if (!note.empty()) detail += " (" + note + ")";
    throw ParseError(std::string(file_), at.line, at.column, detail);
  }

  void read_name(Object& object, const Document& doc) {
    const Token token = lexer_.next();
    if (token.type == TokenType::Word && token.text == ".") return;  // anonymous
    if (token.type != TokenType::Word || !is_valid_object_name(token.text)) {
      fail(token, "expected a name (a letter or '_', then letters, digits, '_', '-' or '.') or '.' for none");
    }
    if (const auto it = names_.find(std::string(token.text)); it != names_.end()) {
      fail(token, "expected a new name",
           "already used by the object at line " +
               std::to_string(doc.objects[static_cast<std::size_t>(it->second)].location.line));
    }
    object.name = std::string(token.text);
  }

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

  /// What a number is for, spelled out only when a message needs it: building the words for
  /// every coordinate of a million-point curve would cost more than parsing it.
  struct NumberRole {
    std::string_view what;   // "radius", or the axis "x", "y", "z"
    std::int64_t point = 0;  // 1-based point number, 0 if not a point coordinate
    std::int64_t count = 0;
    std::string text() const {
      if (point == 0) return std::string(what);
      return std::string(what) + " of " + point_text(point, count);
    }
  };
  static std::string point_text(std::int64_t point, std::int64_t count) {
    return "point " + std::to_string(point) + " of " + std::to_string(count);
  }

  /// Reads a finite number within the coordinate cap; `role` says what it is for ("x of point 2 of 4").
  double read_number(const NumberRole& role, Token* where = nullptr) {
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
    if (std::abs(value) > limits::kMaxCoordinate)
      fail(token, "expected a number from -1e12 to 1e12 (" + role.text() + ")");
    return value;
  }

  int read_steps() { return static_cast<int>(read_integer("STEPS", 1, limits::kMaxSteps, &steps_token_)); }

  void read_control_point_curve(Object& object) {
    const bool bezier = object.kind == ObjectKind::Bezier2 || object.kind == ObjectKind::Bezier3;
    const bool planar = is_planar_curve(object.kind);
    object.steps = read_steps();
    Token count_token;
    const std::int64_t count = read_integer("a control point count", 0, limits::kMaxControlPoints, &count_token);
    if (bezier && (count < 4 || (count - 1) % 3 != 0)) {
      fail(count_token, "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)");
    }
    if (!bezier && count < 4) fail(count_token, "expected at least 4 B-spline control points");
    total_points_ += count;
    if (total_points_ > limits::kMaxControlPoints) {
      fail(count_token,
           "expected at most " + std::to_string(limits::kMaxControlPoints) + " control points in the whole document",
           "this curve brings the total to " + std::to_string(total_points_));
    }
    const std::int64_t samples = piece_count(object.kind, count) * object.steps + 1;
    check_samples(samples);
    // Reserve no more than the rest of the file could hold ("[0 0]" is 5 bytes), so a huge count in
    // a short file costs nothing.
    object.points.reserve(
        static_cast<std::size_t>(std::min<std::int64_t>(count, static_cast<std::int64_t>(lexer_.remaining() / 5 + 1))));
    for (std::int64_t i = 0; i < count; ++i) {
      const Token open = lexer_.next();
      if (open.type != TokenType::Open) fail(open, "expected '[' to start " + point_text(i + 1, count));
      glm::dvec3 p{0.0};
      p.x = read_number({"x", i + 1, count});
      p.y = read_number({"y", i + 1, count});
      if (!planar) p.z = read_number({"z", i + 1, count});
      const Token close = lexer_.next();
      if (close.type != TokenType::Close) {
        fail(close, "expected ']' to end " + point_text(i + 1, count) +
                        (planar ? " (2D points have 2 coordinates)" : " (3D points have 3 coordinates)"));
      }
      object.points.push_back(p);
    }
  }

  void check_samples(std::int64_t samples) {
    if (samples > limits::kMaxCurveSamples) {
      fail(steps_token_, "expected at most " + std::to_string(limits::kMaxCurveSamples) + " samples per curve",
           "STEPS " + std::string(steps_token_.text) + " gives " + std::to_string(samples));
    }
    total_samples_ += samples;
    if (total_samples_ > 2 * limits::kMaxCurveSamples) {
      fail(steps_token_,
           "expected at most " + std::to_string(2 * limits::kMaxCurveSamples) + " curve samples in the whole document",
           "this curve brings the total to " + std::to_string(total_samples_));
    }
  }

  void read_circle(Object& object) {
    object.steps = read_steps();
    check_samples(std::int64_t{object.steps} + 1);
    Token radius_token;
    object.radius = read_number({"radius"}, &radius_token);
    if (object.radius <= 0.0) fail(radius_token, "expected a positive radius");
    if (object.radius < limits::kMinRadius) fail(radius_token, "expected a radius of at least 1e-12");
  }

  int read_reference(const Document& doc, const char* role, bool planar_only) {
    const Token token = lexer_.next();
    const std::string expected =
        planar_only ? std::string("expected the name of a 2D curve (bez2, bsp2, circ) defined above as ") + role
                    : std::string("expected the name of a curve defined above as ") + role;
    if (token.type != TokenType::Word) fail(token, expected);
    const auto it = names_.find(std::string(token.text));
    if (it == names_.end()) {
      // '.' would otherwise match any later anonymous object and be called "defined further down".
      const char* why = token.text == "."           ? "'.' means no name; only named objects can be referenced"
                        : defined_later(token.text) ? "it is defined further down; references point backwards only"
                                                    : "no object has that name";
      fail(token, expected, why);
    }
    const Object& target = doc.objects[static_cast<std::size_t>(it->second)];
    if (!is_curve(target.kind)) fail(token, expected, "it is " + kind_description(target.kind));
    if (planar_only && !is_planar_curve(target.kind))
      fail(token, expected, "it is a 3D curve (" + std::string(keyword(target.kind)) + ")");
    return it->second;
  }

  // Only on the error path: does a later object take this name?
  bool defined_later(std::string_view name) {
    Lexer rest = lexer_;
    Token previous;
    for (Token t = rest.next(); t.type != TokenType::End; t = rest.next()) {
      if (t.type == TokenType::Word && t.text == name && previous.type == TokenType::Word &&
          kind_from_keyword(previous.text)) {
        return true;
      }
      previous = t;
    }
    return false;
  }

  void check_mesh(const Token& at, std::int64_t vertices) {
    if (vertices > limits::kMaxMeshVertices) {
      fail(at, "expected a surface of at most " + std::to_string(limits::kMaxMeshVertices) + " vertices",
           "this one would have " + std::to_string(vertices));
    }
    total_vertices_ += vertices;
    if (total_vertices_ > limits::kMaxMeshVertices) {
      fail(at,
           "expected at most " + std::to_string(limits::kMaxMeshVertices) + " surface vertices in the whole document",
           "this surface brings the total to " + std::to_string(total_vertices_));
    }
  }

  void read_revolution(Object& object, const Document& doc) {
    object.steps = read_steps();
    const Token steps_token = steps_token_;
    object.profile = read_reference(doc, "profile", true);
    const Object& profile = doc.objects[static_cast<std::size_t>(object.profile)];
    check_mesh(steps_token, revolution_vertex_count(curve_sample_count(profile), false, object.steps));
  }

  void read_cylinder(Object& object, const Document& doc) {
    const Token keyword_token{TokenType::Word, keyword(object.kind), object.location.line, object.location.column};
    object.profile = read_reference(doc, "profile", true);
    object.sweep = read_reference(doc, "sweep", false);
    const Object& profile = doc.objects[static_cast<std::size_t>(object.profile)];
    const Object& sweep = doc.objects[static_cast<std::size_t>(object.sweep)];
    check_mesh(keyword_token,
               cylinder_vertex_count(curve_sample_count(profile), false, curve_sample_count(sweep), false));
  }

  Lexer lexer_;
  std::string_view file_;
  std::unordered_map<std::string, int> names_;
  Token steps_token_;
  std::int64_t total_points_ = 0;
  std::int64_t total_samples_ = 0;
  std::int64_t total_vertices_ = 0;
};

}  // namespace

Document parse_swp(std::string_view text, std::string_view file_name) {
  return Parser(text, file_name).parse();
}

Document load_swp_file(const std::filesystem::path& path) {
  const std::string name = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ParseError(name, 0, 0, std::string("cannot open: ") + std::strerror(errno));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw ParseError(name, 0, 0, "cannot open: it is a directory");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) throw ParseError(name, 0, 0, "cannot read: not a regular file");
  if (static_cast<std::uint64_t>(size) > limits::kMaxFileBytes) {
    // In bytes: a file just over the cap would read "at most 512 MiB, found 512 MiB" in MiB.
    throw ParseError(name, 0, 0,
                     "expected an SWP file of at most " + std::to_string(limits::kMaxFileBytes >> 20) + " MiB (" +
                         std::to_string(limits::kMaxFileBytes) + " bytes), found " + std::to_string(size) + " bytes");
  }
  in.seekg(0, std::ios::beg);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (!in.read(text.data(), size)) throw ParseError(name, 0, 0, "cannot read: " + std::string(std::strerror(errno)));
  return parse_swp(text, name);
}

void validate_document(const Document& doc, std::string_view file_name) {
  // The parser is the one definition of a valid document: write the document out and read it
  // back, then map an error's line to the object it belongs to.
  std::vector<int> first_lines;
  const std::string text = write_swp(doc, &first_lines);
  try {
    (void)parse_swp(text, file_name);
  } catch (const ParseError& e) {
    if (e.line() <= 0 || first_lines.empty()) throw;
    std::size_t index = 0;
    while (index + 1 < first_lines.size() && first_lines[index + 1] <= e.line()) ++index;
    const Object& o = doc.objects[index];
    throw ParseError(std::string(file_name), o.location.line, o.location.column,
                     e.detail() + " (in " + display_name(doc, static_cast<int>(index)) + ")");
  }
}

}  // namespace sweep
