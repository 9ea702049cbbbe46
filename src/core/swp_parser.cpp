// SWP reader. A hand-written lexer (swp_lexer.hpp) and recursive reader: the format is a flat
// list of objects, so one pass with one token of lookahead is enough, and every error knows its
// line and column.
#include "core/swp_parser.hpp"

#include "core/birail.hpp"
#include "core/curve_parameters.hpp"
#include "core/limits.hpp"
#include "core/material.hpp"
#include "core/patch.hpp"
#include "core/subdivision.hpp"
#include "core/surface.hpp"
#include "core/sweep_controls.hpp"
#include "core/swp_clauses.hpp"
#include "core/swp_lexer.hpp"
#include "core/swp_writer.hpp"

#include <algorithm>
#include <array>
#include <cctype>
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

using swp_detail::Lexer;
using swp_detail::point_text;
using swp_detail::Token;
using swp_detail::TokenType;

/// Every kind, curves before surfaces, in the order messages list them.
constexpr std::array kKindsInMessages{
    ObjectKind::Bezier2,
    ObjectKind::Bezier3,
    ObjectKind::BSpline2,
    ObjectKind::BSpline3,
    ObjectKind::Circle,
    ObjectKind::CatmullRom2,
    ObjectKind::CatmullRom3,
    ObjectKind::KochanekBartels2,
    ObjectKind::KochanekBartels3,
    ObjectKind::Helix,
    ObjectKind::TorusKnot,
    ObjectKind::SurfaceOfRevolution,
    ObjectKind::GeneralizedCylinder,
    ObjectKind::Birail,
    ObjectKind::BezierPatch,
    ObjectKind::BSplinePatch,
    ObjectKind::PolygonMesh,
    ObjectKind::Subdivision,
    ObjectKind::Material,
};

/// "bez2, bez3, ..." for the kinds `wanted` accepts.
template <typename Predicate>
std::string keyword_list(Predicate wanted) {
  std::string out;
  for (const ObjectKind kind : kKindsInMessages) {
    if (!wanted(kind)) continue;
    if (!out.empty()) out += ", ";
    out += keyword(kind);
  }
  return out;
}

const std::string& expected_keyword() {
  static const std::string text = "a keyword (" + keyword_list([](ObjectKind) { return true; }) + ")";
  return text;
}

const std::string& expected_planar_curve() {
  static const std::string text = "expected the name of a 2D curve (" + keyword_list(is_planar_curve) + ")";
  return text;
}

std::string kind_description(ObjectKind kind) {
  const char* what = is_surface(kind) ? "a surface (" : is_material(kind) ? "a material (" : "a curve (";
  return std::string(what) + std::string(keyword(kind)) + ")";
}

/// Clause keys are case-insensitive, like keywords: both are words of the format, while names
/// are the user's and keep their case. The writer writes keys in lower case.
const SwpClause* find_clause(std::span<const SwpClause> clauses, std::string_view word) {
  for (const SwpClause& clause : clauses) {
    if (word.size() != clause.key.size()) continue;
    if (std::equal(word.begin(), word.end(), clause.key.begin(),
                   [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; })) {
      return &clause;
    }
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

/// "Catmull-Rom" or "Kochanek-Bartels" for an interpolating kind, "" otherwise.
const char* spline_family(ObjectKind kind) {
  if (kind == ObjectKind::CatmullRom2 || kind == ObjectKind::CatmullRom3) return "Catmull-Rom";
  if (kind == ObjectKind::KochanekBartels2 || kind == ObjectKind::KochanekBartels3) return "Kochanek-Bartels";
  return "";
}

class Parser : private swp_detail::TokenReader {
 public:
  Parser(std::string_view text, std::string_view file) : TokenReader(text, file) {}

  Document parse() {
    Document doc;
    for (Token token = lexer_.next(); token.type != TokenType::End; token = lexer_.next()) {
      const auto kind = token.type == TokenType::Word ? kind_from_keyword(token.text) : std::nullopt;
      if (!kind) {
        // A '[' here most often means a curve has more points than its count says.
        const bool extra_point =
            token.type == TokenType::Open && !doc.objects.empty() &&
            (has_control_points(doc.objects.back().kind) || doc.objects.back().kind == ObjectKind::BezierPatch ||
             doc.objects.back().kind == ObjectKind::BSplinePatch);
        fail(token, "expected " + expected_keyword(),
             extra_point ? "the " + std::string(keyword(doc.objects.back().kind)) + " above already has its " +
                               std::to_string(doc.objects.back().points.size()) + " points"
                         : std::string());
      }
      Object object;
      object.kind = *kind;
      object.location = {token.line, token.column};
      read_name(object, doc);
      read_fields(object, doc);
      // The tolerance's floor is relative to the curve's size, known once its points are read.
      if (object.tolerance > 0.0) {
        require(tolerance_token_, check_tolerance(object.tolerance, curve_extent(object), "the curve"));
      }
      if (!object.name.empty()) names_.emplace(object.name, static_cast<int>(doc.objects.size()));
      vertex_estimates_.push_back(estimated_vertices_);
      estimated_vertices_ = 0;
      doc.objects.push_back(std::move(object));
    }
    return doc;
  }

 private:
  /// The fields after the name, then the optional clauses (for point curves: before the points).
  void read_fields(Object& object, const Document& doc) {
    switch (object.kind) {
      case ObjectKind::Bezier2:
      case ObjectKind::Bezier3:
      case ObjectKind::BSpline2:
      case ObjectKind::BSpline3:
      case ObjectKind::CatmullRom2:
      case ObjectKind::CatmullRom3:
      case ObjectKind::KochanekBartels2:
      case ObjectKind::KochanekBartels3:
        read_control_point_curve(object, doc);
        return;  // its clauses come before the points
      case ObjectKind::Circle:
        read_circle(object);
        break;
      case ObjectKind::Helix:
        read_helix(object);
        break;
      case ObjectKind::TorusKnot:
        read_torus_knot(object);
        break;
      case ObjectKind::SurfaceOfRevolution:
        read_revolution(object, doc);
        break;
      case ObjectKind::GeneralizedCylinder:
        read_cylinder(object, doc);
        break;
      case ObjectKind::Birail:
        read_birail(object, doc);
        break;
      case ObjectKind::BezierPatch:
        read_bezier_patch(object, doc);
        return;  // its clauses come before the points
      case ObjectKind::BSplinePatch:
        read_bspline_patch(object, doc);
        return;
      case ObjectKind::PolygonMesh:
        read_polygon_mesh(object, doc);
        return;
      case ObjectKind::Material:
        read_material(object);
        return;
      case ObjectKind::Subdivision:
        read_subdivision(object, doc);
        break;
    }
    read_clauses(object, doc, expected_keyword());
    if (is_surface(object.kind)) check_curves(object, doc);
    if (object.kind == ObjectKind::Subdivision) check_subdivision(object, doc);
  }

  /// What the referenced curves' samples must satisfy (sweep_controls.hpp), reported at the
  /// reference or clause it is about.
  void check_curves(const Object& object, const Document& doc) {
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
  void read_clauses(Object& object, const Document& doc, const std::string& instead) {
    const std::span<const SwpClause> clauses = swp_clauses(object.kind);
    if (clauses.empty()) return;  // whatever comes next is read, and reported, by its own reader
    const bool points_follow = has_editable_points(object.kind);
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
      if (clause->flag == &Object::loop) loop_token_ = first;
      if (clause->flag) {
        object.*(clause->flag) = true;
        continue;
      }
      if (clause->reference == &Object::material) {
        object.material = read_material_reference(doc);
        continue;
      }
      if (clause->reference && (!clause->field || !starts_number(lexer_.peek()))) {
        Token& token = clause->reference == &Object::scale ? scale_token_ : twist_token_;
        token = lexer_.peek();
        object.*(clause->reference) =
            read_reference(doc, clause->field ? "a twist curve, or a number of degrees" : "a scale curve", true);
        continue;
      }
      Token value_token;
      const double value = read_finite({clause->key}, &value_token);
      require(value_token, clause->check(object.kind, value));
      object.*(clause->field) = value;
      if (clause->field == &Object::tolerance) tolerance_token_ = value_token;
      if (clause->field == &Object::twist) twist_token_ = value_token;
    }
  }

  /// `material` is both a keyword and a surface's clause key: it is the clause when the name after
  /// it is taken already (a new material needs a new name); the clause then says if it is not a
  /// material.
  bool material_clause_follows(std::span<const SwpClause> clauses) {
    if (!find_clause(clauses, "material")) return false;
    Lexer rest = lexer_;
    const Token key = rest.next();
    if (!equal_key(key.text, "material")) return false;
    const Token name = rest.next();
    const auto it = names_.find(std::string(name.text));
    return name.type == TokenType::Word && it != names_.end();
  }

  /// A clause value that is a number rather than a name: names start with a letter or '_'.
  static bool starts_number(const Token& token) {
    if (token.type != TokenType::Word || token.text.empty()) return false;
    const char c = token.text[0];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '+' || c == '-' || c == '.';
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

  int read_steps() { return static_cast<int>(read_integer("STEPS", 1, limits::kMaxSteps, &steps_token_)); }

  void read_control_point_curve(Object& object, const Document& doc) {
    object.steps = read_steps();
    Token count_token;
    const std::int64_t count = read_integer("a control point count", 0, limits::kMaxControlPoints, &count_token);
    check_point_count(object.kind, count, count_token);
    total_points_ += count;
    if (total_points_ > limits::kMaxControlPoints) {
      fail(count_token,
           "expected at most " + std::to_string(limits::kMaxControlPoints) + " control points in the whole document",
           "this curve brings the total to " + std::to_string(total_points_));
    }
    check_samples(piece_count(object.kind, count) * object.steps + 1);
    read_clauses(object, doc, "'[' to start " + point_text(1, count));
    read_points(object, count);
  }

  void check_point_count(ObjectKind kind, std::int64_t count, const Token& count_token) {
    if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) {
      if (count < 4 || (count - 1) % 3 != 0)
        fail(count_token, "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)");
    } else if (is_interpolating(kind)) {
      if (count < kMinInterpolatingPoints) {
        fail(count_token, "expected at least " + std::to_string(kMinInterpolatingPoints) + " " + spline_family(kind) +
                              " control points");
      }
    } else if (count < 4) {
      fail(count_token, "expected at least 4 B-spline control points");
    }
  }

  void read_points(Object& object, std::int64_t count) {
    const bool planar = is_planar_curve(object.kind);
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

  /// Checks a curve's sample count against the caps. The error is at STEPS, or for the
  /// document's total at `at` if given (a helix's TURNS).
  void check_samples(std::int64_t samples, const Token* at = nullptr) {
    if (samples > limits::kMaxCurveSamples) {
      fail(steps_token_, expected_samples_per_curve(),
           "STEPS " + std::string(steps_token_.text) + " gives " + std::to_string(samples));
    }
    total_samples_ += samples;
    if (total_samples_ > 2 * limits::kMaxCurveSamples) {
      fail(at ? *at : steps_token_,
           "expected at most " + std::to_string(2 * limits::kMaxCurveSamples) + " curve samples in the whole document",
           "this curve brings the total to " + std::to_string(total_samples_));
    }
  }
  static std::string expected_samples_per_curve() {
    return "expected at most " + std::to_string(limits::kMaxCurveSamples) + " samples per curve";
  }

  void read_circle(Object& object) {
    object.steps = read_steps();
    check_samples(std::int64_t{object.steps} + 1);
    Token radius_token;
    object.radius = read_number({"radius"}, &radius_token);
    require(radius_token, check_radius(object.radius));
  }

  void read_helix(Object& object) {
    object.steps = read_steps();
    Token token;
    object.radius = read_number({"radius"}, &token);
    require(token, check_radius(object.radius));
    object.pitch = read_number({"pitch"});
    object.turns = read_number({"turns"}, &token);
    require(token, check_turns(object.turns));
    // ceil(STEPS * TURNS) + 1: TURNS is what makes a helix long, so the error is there. Both
    // are capped (1e5, 1e12), so the product is far from the end of int64.
    const std::int64_t samples = helix_sample_count(object.steps, object.turns);
    if (samples > limits::kMaxCurveSamples) {
      const auto exact = static_cast<std::int64_t>(std::ceil(object.steps * object.turns)) + 1;
      fail(token, expected_samples_per_curve(),
           "STEPS " + std::string(steps_token_.text) + " and TURNS " + std::string(token.text) + " give " +
               std::to_string(exact));
    }
    check_samples(samples, &token);
  }

  void read_torus_knot(Object& object) {
    object.steps = read_steps();
    check_samples(std::int64_t{object.steps} + 1);
    object.knot_p = static_cast<int>(read_integer("P", 1, kMaxKnotWinding));
    Token token;
    object.knot_q = static_cast<int>(read_integer("Q", 1, kMaxKnotWinding, &token));
    require(token, check_knot_pq(object.knot_p, object.knot_q));
    object.major_radius = read_number({"torus radius R"});
    object.radius = read_number({"tube radius r"}, &token);
    require(token, check_knot_radii(object.major_radius, object.radius));
  }

  /// The index of the earlier object `token` names, or a failure saying `expected` and why not.
  int find_named(const Token& token, const std::string& expected) {
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

  int read_reference(const Document& doc, const char* role, bool planar_only) {
    const Token token = lexer_.next();
    const std::string expected = (planar_only ? expected_planar_curve() : std::string("expected the name of a curve")) +
                                 " defined above as " + role;
    const int index = find_named(token, expected);
    const Object& target = doc.objects[static_cast<std::size_t>(index)];
    if (!is_curve(target.kind)) fail(token, expected, "it is " + kind_description(target.kind));
    if (planar_only && !is_planar_curve(target.kind))
      fail(token, expected, "it is a 3D curve (" + std::string(keyword(target.kind)) + ")");
    return index;
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
    estimated_vertices_ = vertices;
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

  /// A count of 3D points that adds to the document's total (an error at `count_token` beyond it).
  void count_points(std::int64_t count, const Token& count_token) {
    total_points_ += count;
    if (total_points_ > limits::kMaxControlPoints) {
      fail(count_token,
           "expected at most " + std::to_string(limits::kMaxControlPoints) + " control points in the whole document",
           "this object brings the total to " + std::to_string(total_points_));
    }
  }

  void read_bezier_patch(Object& object, const Document& doc) {
    object.steps = read_steps();
    const Token steps_token = steps_token_;
    Token count_token;
    const std::int64_t patches = read_integer("a patch count K", 1, limits::kMaxControlPoints / 16, &count_token);
    count_points(16 * patches, count_token);
    check_mesh(steps_token, bezier_patch_vertex_count(patches, object.steps));
    estimated_vertices_ = bezier_patch_vertex_count(patches, object.steps);
    read_clauses(object, doc, "'[' to start " + point_text(1, 16 * patches));
    read_points(object, 16 * patches);
  }

  void read_bspline_patch(Object& object, const Document& doc) {
    object.steps = read_steps();
    const Token steps_token = steps_token_;
    Token count_token;
    const std::int64_t rows = read_integer("a row count M", 4, limits::kMaxControlPoints / 4, &count_token);
    const std::int64_t columns = read_integer("a column count N", 4, limits::kMaxControlPoints / 4, &count_token);
    if (rows * columns > limits::kMaxControlPoints) {
      fail(count_token, "expected at most " + std::to_string(limits::kMaxControlPoints) + " control points",
           "M x N is " + std::to_string(rows * columns));
    }
    count_points(rows * columns, count_token);
    check_mesh(steps_token, bspline_patch_vertex_count(rows, columns, object.steps));
    estimated_vertices_ = bspline_patch_vertex_count(rows, columns, object.steps);
    object.rows = static_cast<int>(rows);
    object.columns = static_cast<int>(columns);
    read_clauses(object, doc, "'[' to start " + point_text(1, rows * columns));
    read_points(object, rows * columns);
  }

  /// `mesh NAME NV NF`, NV points, NF faces `[i j k ...]` of 0-based vertex indices.
  void read_polygon_mesh(Object& object, const Document& doc) {
    Token count_token;
    const std::int64_t vertices = read_integer("a vertex count NV", 3, limits::kMaxControlPoints, &count_token);
    count_points(vertices, count_token);
    const std::int64_t faces = read_integer("a face count NF", 1, limits::kMaxControlPoints, &count_token);
    check_mesh(count_token, vertices);
    estimated_vertices_ = vertices;
    read_clauses(object, doc, "'[' to start " + point_text(1, vertices));
    read_points(object, vertices);
    std::vector<Token> opens;  // where each face starts, for the cage's messages
    for (std::int64_t f = 0; f < faces; ++f) {
      opens.push_back(read_face(object, f, faces, vertices));
    }
    if (const std::optional<CageProblem> problem = check_cage(cage_of(object))) {
      const Token& at = opens[static_cast<std::size_t>(problem->face)];
      throw ParseError(std::string(file_), at.line, at.column, problem->expected);
    }
  }

  /// One face: '[', at least 3 vertex indices, ']'. Returns its '['.
  Token read_face(Object& object, std::int64_t face, std::int64_t faces, std::int64_t vertices) {
    const std::string which = "face " + std::to_string(face + 1) + " of " + std::to_string(faces);
    const Token open = lexer_.next();
    if (open.type != TokenType::Open) fail(open, "expected '[' to start " + which);
    int size = 0;
    for (Token next = lexer_.peek(); next.type != TokenType::Close; next = lexer_.peek()) {
      if (size == vertices) fail(next, "expected ']' to end " + which, "a face has at most NV vertices");
      object.face_vertices.push_back(static_cast<int>(read_integer("a vertex index of " + which, 0, vertices - 1)));
      ++size;
    }
    if (size < 3) {
      fail(lexer_.peek(), "expected a vertex index of " + which,
           "a face has at least 3 vertices, this one " + std::to_string(size));
    }
    (void)lexer_.next();
    total_points_ += size;  // indices cost memory like points
    if (total_points_ > limits::kMaxControlPoints) {
      fail(open, "expected at most " + std::to_string(limits::kMaxControlPoints) +
                     " points and face corners in the whole document");
    }
    object.face_sizes.push_back(size);
    return open;
  }

  /// `subd NAME LEVELS SOURCE`: SOURCE is an earlier mesh or grid surface.
  void read_subdivision(Object& object, const Document& doc) {
    object.steps = static_cast<int>(read_integer("LEVELS", 0, kMaxSubdivisionLevel, &levels_token_));
    const Token token = lexer_.next();
    const std::string expected = "expected the name of a surface defined above as the cage (" +
                                 keyword_list([](ObjectKind kind) { return is_surface(kind); }) + ")";
    const int index = find_named(token, expected);
    const Object& source = doc.objects[static_cast<std::size_t>(index)];
    if (!is_surface(source.kind)) fail(token, expected, "it is " + kind_description(source.kind));
    object.source = index;
    source_vertices_ = vertex_estimates_[static_cast<std::size_t>(index)];
  }

  /// Loop needs triangles; the refined mesh must fit the caps (checked before refining).
  void check_subdivision(const Object& object, const Document& doc) {
    const Object& source = doc.objects[static_cast<std::size_t>(object.source)];
    const bool mesh = source.kind == ObjectKind::PolygonMesh;
    if (object.loop && mesh) {
      const auto it = std::find_if(source.face_sizes.begin(), source.face_sizes.end(), [](int n) { return n != 3; });
      if (it != source.face_sizes.end()) {
        fail(loop_token_, "expected a triangle cage for loop",
             "face " + std::to_string(it - source.face_sizes.begin() + 1) + " of " + source.name + " has " +
                 std::to_string(*it) + " vertices; Catmull-Clark, the default, takes any polygons");
      }
    } else if (object.loop && source.kind != ObjectKind::Subdivision) {
      fail(loop_token_, "expected a triangle cage for loop",
           source.name + " is a grid of quads (" + std::string(keyword(source.kind)) +
               "); Catmull-Clark, the default, takes them");
    }
    const SubdivisionScheme scheme = object.loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
    // A grid surface's cage has about as many faces as vertices and twice as many edges, so each
    // level multiplies its vertices by about 4.
    std::int64_t vertices = source_vertices_;
    if (mesh) {
      vertices = refined_counts(cage_of(source), object.steps, scheme).vertices;
    } else {
      for (int level = 0; level < object.steps && vertices <= limits::kMaxMeshVertices; ++level) vertices *= 4;
    }
    check_mesh(levels_token_, vertices);
    estimated_vertices_ = vertices;
  }

  int read_material_reference(const Document& doc) {
    const Token token = lexer_.next();
    const std::string expected = "expected the name of a material defined above";
    const int index = find_named(token, expected);
    const Object& target = doc.objects[static_cast<std::size_t>(index)];
    if (!is_material(target.kind)) fail(token, expected, "it is " + kind_description(target.kind));
    return index;
  }

  /// `material NAME [color R G B] [shininess S] [texture FILE.png | checker N] [bump FILE.png H]`,
  /// each clause at most once, in any order; image files are checked here (material.hpp).
  void read_material(Object& object) {
    static constexpr std::array<std::string_view, 5> kKeys = {"color", "shininess", "texture", "checker", "bump"};
    std::array<Token, kKeys.size()> given{};
    for (Token key = lexer_.peek(); key.type == TokenType::Word && !kind_from_keyword(key.text); key = lexer_.peek()) {
      std::size_t k = 0;
      while (k < kKeys.size() && !equal_key(key.text, kKeys[k])) ++k;
      if (k == kKeys.size()) {
        fail(key, "expected a material clause (color, shininess, texture, checker, bump) or a keyword");
      }
      if (given[k].line != 0) {
        fail(key, "expected each clause at most once",
             "already given at line " + std::to_string(given[k].line) + ", column " + std::to_string(given[k].column));
      }
      given[k] = lexer_.next();
      read_material_clause(object, kKeys[k]);
      if (given[2].line != 0 && given[3].line != 0) {
        fail(given[k], "expected a texture or a checker, not both");
      }
    }
  }

  static bool equal_key(std::string_view word, std::string_view key) {
    return word.size() == key.size() && std::equal(word.begin(), word.end(), key.begin(), [](char a, char b) {
             return std::tolower(static_cast<unsigned char>(a)) == b;
           });
  }

  void read_material_clause(Object& object, std::string_view key) {
    Token value;
    if (key == "color") {
      const char* channels[3] = {"red", "green", "blue"};
      for (int c = 0; c < 3; ++c) {
        object.color[c] = read_finite({channels[c]}, &value);
        if (object.color[c] < 0.0 || object.color[c] > 1.0) {
          fail(value, std::string("expected a colour component from 0 to 1 (") + channels[c] + ")");
        }
      }
    } else if (key == "shininess") {
      object.shininess = read_finite({"shininess"}, &value);
      if (object.shininess < 1.0 || object.shininess > 1000.0) fail(value, "expected a shininess from 1 to 1000");
    } else if (key == "checker") {
      object.checker = static_cast<int>(read_integer("the checker's cells per side", 1, 256));
    } else if (key == "texture") {
      object.texture = read_image_path("texture");
    } else {
      object.bump = read_image_path("bump");
      object.bump_height = read_finite({"bump height"}, &value);
      if (object.bump_height < 0.0 || object.bump_height > limits::kMaxCoordinate) {
        fail(value, "expected a bump height from 0 to 1e12 (model units)");
      }
    }
  }

  /// An image file name, checked to be a PNG that stb_image reads, relative to the SWP file.
  std::string read_image_path(const char* role) {
    const Token token = lexer_.next();
    const std::string expected = std::string("expected a PNG image file (") + role + ")";
    if (token.type != TokenType::Word) fail(token, expected);
    const std::string problem = image_problem(image_base(std::filesystem::path(file_)) / std::string(token.text));
    if (!problem.empty()) fail(token, expected, problem);
    return std::string(token.text);
  }

  void read_revolution(Object& object, const Document& doc) {
    object.steps = read_steps();
    const Token steps_token = steps_token_;
    profile_token_ = lexer_.peek();
    object.profile = read_reference(doc, "profile", true);
    const Object& profile = doc.objects[static_cast<std::size_t>(object.profile)];
    check_mesh(steps_token, revolution_vertex_count(curve_sample_count(profile), false, object.steps));
  }

  void read_cylinder(Object& object, const Document& doc) {
    const Token keyword_token{TokenType::Word, keyword(object.kind), object.location.line, object.location.column};
    profile_token_ = lexer_.peek();
    object.profile = read_reference(doc, "profile", true);
    object.sweep = read_reference(doc, "sweep", false);
    const Object& profile = doc.objects[static_cast<std::size_t>(object.profile)];
    const Object& sweep = doc.objects[static_cast<std::size_t>(object.sweep)];
    check_mesh(keyword_token,
               cylinder_vertex_count(curve_sample_count(profile), false, curve_sample_count(sweep), false));
  }

  void read_birail(Object& object, const Document& doc) {
    const Token keyword_token{TokenType::Word, keyword(object.kind), object.location.line, object.location.column};
    profile_token_ = lexer_.peek();
    object.profile = read_reference(doc, "profile", true);
    object.sweep = read_reference(doc, "the first rail", false);
    rail2_token_ = lexer_.peek();
    object.rail2 = read_reference(doc, "the second rail", false);
    const auto samples = [&doc](int index) { return curve_sample_count(doc.objects[static_cast<std::size_t>(index)]); };
    check_mesh(keyword_token,
               birail_vertex_count(samples(object.profile), samples(object.sweep), samples(object.rail2)));
  }

  std::unordered_map<std::string, int> names_;
  Token steps_token_;
  Token tolerance_token_;  // where the current object's tolerance clause gave its value
  // Where the current surface named its profile, second rail, scale and twist.
  Token profile_token_;
  Token rail2_token_;
  Token scale_token_;
  Token twist_token_;
  Token loop_token_;    // the current subd's `loop`
  Token levels_token_;  // and its LEVELS
  std::int64_t source_vertices_ = 0;
  // Vertices the current surface will have (0 for curves), and those of every object read.
  std::int64_t estimated_vertices_ = 0;
  std::vector<std::int64_t> vertex_estimates_;
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
