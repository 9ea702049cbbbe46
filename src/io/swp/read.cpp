// SWP reader. A hand-written lexer (swp/detail/lexer.hpp) and recursive reader: the format is a flat
// list of objects, so one pass with one token of lookahead is enough, and every error knows its
// line and column.
#include "io/swp/read.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/sweep_controls.hpp"
#include "io/swp/detail/lexer.hpp"
#include "io/swp/detail/reader.hpp"
#include "io/swp/write.hpp"
#include "model/clauses.hpp"
#include "model/curve_parameters.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"
#include "model/material.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <unordered_map>

namespace sweep::io {

ParseError::ParseError(std::string file, int line, int column, std::string detail)
    : std::runtime_error(line > 0 ? file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + detail
                                  : file + ": " + detail),
      file_(std::move(file)),
      line_(line),
      column_(column),
      detail_(std::move(detail)) {}

namespace swp_detail {

const std::string& expected_keyword() {
  static const std::string text = "a keyword (" + keyword_list([](ObjectKind) { return true; }) + ")";
  return text;
}

bool equal_key(std::string_view word, std::string_view key) {
  return word.size() == key.size() && std::equal(word.begin(), word.end(), key.begin(), [](char a, char b) {
           return std::tolower(static_cast<unsigned char>(a)) == b;
         });
}

/// Clause keys are case-insensitive, like keywords: both are words of the format, while names
/// are the user's and keep their case. The writer writes keys in lower case.
const SwpClause* find_clause(std::span<const SwpClause> clauses, std::string_view word) {
  for (const SwpClause& clause : clauses) {
    if (equal_key(word, clause.key)) return &clause;
  }
  return nullptr;
}

/// "a clause (alpha, tension)".
std::string clause_list(std::span<const SwpClause> clauses) {
  std::string out = "a clause (";
  for (const SwpClause& clause : clauses) {
    if (&clause != clauses.data()) out += ", ";
    out += clause.key;
  }
  return out + ")";
}

Document Parser::parse() {
  Document doc;
  for (Token token = lexer_.next(); token.type != TokenType::End; token = lexer_.next()) {
    const auto kind = token.type == TokenType::Word ? kind_from_keyword(token.text) : std::nullopt;
    if (!kind) {
      // A '[' here most often means a curve has more points than its count says.
      const bool extra_point =
          token.type == TokenType::Open && !doc.objects.empty() &&
          (has_control_points(doc.objects.back().kind()) || doc.objects.back().kind() == ObjectKind::BezierPatch ||
           doc.objects.back().kind() == ObjectKind::BSplinePatch);
      fail(token, "expected " + expected_keyword(),
           extra_point ? "the " + std::string(keyword(doc.objects.back().kind())) + " above already has its " +
                             std::to_string(doc.objects.back().as<PointsPart>().points.size()) + " points"
                       : std::string());
    }
    Object object;
    object.set_kind(*kind);
    object.location = {token.line, token.column, lexer_.offset_of(token), 0};
    read_name(object, doc);
    read_fields(object, doc);
    object.location.end = lexer_.offset();
    // The tolerance's floor is relative to the curve's size, known once its points are read.
    if (const double tolerance = own_tolerance(object); tolerance > 0.0) {
      require(tolerance_token_, check_tolerance(tolerance, curve_extent(object), "the curve"));
    }
    if (!object.name.empty()) names_.emplace(object.name, static_cast<int>(doc.objects.size()));
    vertex_estimates_.push_back(estimated_vertices_);
    estimated_vertices_ = 0;
    doc.objects.push_back(std::move(object));
  }
  doc.missing_images = std::move(missing_images_);
  return doc;
}

/// What the referenced curves' samples must satisfy (sweep_controls.hpp), reported at the
/// reference or clause it is about.
void Parser::check_curves(const Object& object, const Document& doc) {
  const std::optional<CurveProblem> problem = check_surface_curves(doc, object);
  if (!problem) return;
  const Token* at = &profile_token_;
  if (problem->at == CurveProblem::At::Rail2) at = &rail2_token_;
  if (problem->at == CurveProblem::At::Scale) at = &scale_token_;
  if (problem->at == CurveProblem::At::Twist) at = &twist_token_;
  fail(*at, problem->expected, problem->note);
}

/// Reads the optional `key value` clauses of `object`, each at most once, in any order. They
/// end at the first token that cannot start one: a bracket, the end, or (where no points
/// follow) a keyword. `instead` says what else may come there, for the message.
void Parser::read_clauses(Object& object, const Document& doc, const std::string& instead) {
  const std::span<const SwpClause> clauses = swp_clauses(object.kind());
  if (clauses.empty()) return;  // whatever comes next is read, and reported, by its own reader
  const bool points_follow = has_editable_points(object.kind());
  std::array<Token, kMaxClausesPerKind> given{};  // where each clause was given, by its index in `clauses`
  for (Token key = lexer_.peek(); key.type == TokenType::Word; key = lexer_.peek()) {
    if (kind_from_keyword(key.text) && !material_clause_follows(clauses)) {
      if (!points_follow) return;
    }
    const SwpClause* clause = find_clause(clauses, key.text);
    if (!clause) fail(key, "expected " + clause_list(clauses) + " or " + instead);
    Token& first = given.at(static_cast<std::size_t>(clause - clauses.data()));
    if (first.line != 0) {
      fail(key, "expected each clause at most once",
           "already given at line " + std::to_string(first.line) + ", column " + std::to_string(first.column));
    }
    first = lexer_.next();
    if (clause->key == "loop") loop_token_ = first;
    if (clause->flag) {
      *clause->flag(object) = true;
      continue;
    }
    if (clause->key == "material") {
      object.as<MaterialPart>().material = read_material_reference(doc);
      continue;
    }
    if (clause->vector) {
      read_vector_clause(object, *clause);
      continue;
    }
    if (clause->reference && (!clause->field || !starts_number(lexer_.peek()))) {
      Token& token = clause->key == "scale" ? scale_token_ : twist_token_;
      token = lexer_.peek();
      *clause->reference(object) =
          read_reference(doc, clause->field ? "a twist curve, or a number of degrees" : "a scale curve", true);
      continue;
    }
    Token value_token;
    const double value = read_finite({clause->key}, &value_token);
    require(value_token, clause->check(object.kind(), value));
    *clause->field(object) = value;
    if (clause->key == "tolerance") tolerance_token_ = value_token;
    if (clause->key == "twist") twist_token_ = value_token;
  }
}

void Parser::read_vector_clause(Object& object, const SwpClause& clause) {
  static constexpr std::string_view kAxes[] = {"x", "y", "z"};
  glm::dvec3 value{0.0};
  Token first;
  for (int axis = 0; axis < 3; ++axis) {
    const std::string role = std::string(clause.key) + " " + std::string(kAxes[axis]);
    value[axis] = read_finite({role}, axis == 0 ? &first : nullptr);
  }
  require(first, clause.vector_check(value));
  *clause.vector(object) = value;
}

/// `material` is both a keyword and a surface's clause key: it is the clause when the name after
/// it is taken already (a new material needs a new name); the clause then says if it is not a
/// material.
bool Parser::material_clause_follows(std::span<const SwpClause> clauses) {
  if (!find_clause(clauses, "material")) return false;
  Lexer rest = lexer_;
  const Token key = rest.next();
  if (!equal_key(key.text, "material")) return false;
  const Token name = rest.next();
  const auto it = names_.find(std::string(name.text));
  return name.type == TokenType::Word && it != names_.end();
}

/// A clause value that is a number rather than a name: names start with a letter or '_'.
bool Parser::starts_number(const Token& token) {
  if (token.type != TokenType::Word || token.text.empty()) return false;
  const char c = token.text[0];
  return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
}

void Parser::read_name(Object& object, const Document& doc) {
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

/// The index of the earlier object `token` names, or a failure saying `expected` and why not.
int Parser::find_named(const Token& token, const std::string& expected) {
  if (token.type != TokenType::Word) fail(token, expected);
  const auto it = names_.find(std::string(token.text));
  if (it == names_.end()) {
    // '.' would otherwise match any later anonymous object and be called "defined further down".
    const char* why = token.text == "."           ? "'.' means no name; only named objects can be referenced"
                      : defined_later(token.text) ? "it is defined further down; references point backwards only"
                                                  : "no object has that name";
    fail(token, expected, why);
  }
  return it->second;
}

int Parser::read_reference(const Document& doc, const char* role, bool planar_only) {
  const Token token = lexer_.next();
  const int index = find_named(token, expected_reference(role, planar_only));
  const Object& target = doc.objects[static_cast<std::size_t>(index)];
  if (const auto problem = check_reference_kind(target, role, planar_only)) {
    fail(token, problem->expected, problem->note);
  }
  return index;
}

// Only on the error path: does a later object take this name?
bool Parser::defined_later(std::string_view name) {
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

void Parser::check_mesh(const Token& at, std::int64_t vertices) {
  estimated_vertices_ = vertices;
  if (const auto breach = caps_.add_vertices(vertices)) fail(at, breach->expected, breach->note);
}

/// A count of points that adds to the document's total (an error at `count_token` beyond it).
void Parser::count_points(std::int64_t count, const Token& count_token, const char* what) {
  if (const auto breach = caps_.add_points(count, what)) fail(count_token, breach->expected, breach->note);
}

/// Checks a curve's sample count against the caps. The error is at STEPS, or for the
/// document's total at `at` if given (a polyline's count).
void Parser::check_samples(std::int64_t samples, const Token* at) {
  if (const auto breach = caps_.add_samples(samples, "STEPS " + std::string(steps_token_.text) + " gives")) {
    fail(breach->whole_document && at ? *at : steps_token_, breach->expected, breach->note);
  }
}

}  // namespace swp_detail
Document parse_swp(std::string_view text, std::string_view file_name) {
  return swp_detail::Parser(text, file_name).parse();
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
  return parse_swp_keeping_source(std::move(text), name);
}

Document parse_swp_keeping_source(std::string text, std::string_view file_name) {
  auto source = std::make_shared<const std::string>(std::move(text));
  Document doc = parse_swp(*source, file_name);
  doc.source.text = std::move(source);
  doc.source.file_name = std::string(file_name);
  return doc;
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

}  // namespace sweep::io
