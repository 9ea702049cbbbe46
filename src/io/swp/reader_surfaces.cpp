// The SWP reader's surfaces: revolutions, cylinders, birails, patches, cages, subdivision and
// materials (see swp/detail/reader.hpp).
#include "io/swp/detail/reader.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/surface.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"
#include "model/material.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

namespace sweep::io::swp_detail {

void Parser::read_bezier_patch(Object& object, const Document& doc) {
  BezierPatchSurface& surface = object.as<BezierPatchSurface>();
  surface.steps = read_steps();
  const Token steps_token = steps_token_;
  Token count_token;
  const std::int64_t patches = read_integer("a patch count K", 1, limits::kMaxControlPoints / 16, &count_token);
  count_points(16 * patches, count_token);
  check_mesh(steps_token, bezier_patch_vertex_count(patches, surface.steps));
  estimated_vertices_ = bezier_patch_vertex_count(patches, surface.steps);
  read_clauses(object, doc, "'[' to start " + point_text(1, 16 * patches));
  read_points(object, 16 * patches);
}

void Parser::read_bspline_patch(Object& object, const Document& doc) {
  BSplinePatchSurface& patch = object.as<BSplinePatchSurface>();
  patch.steps = read_steps();
  const Token steps_token = steps_token_;
  Token count_token;
  const std::int64_t rows = read_integer("a row count M", 4, limits::kMaxControlPoints / 4, &count_token);
  const std::int64_t columns = read_integer("a column count N", 4, limits::kMaxControlPoints / 4, &count_token);
  if (rows * columns > limits::kMaxControlPoints) {
    fail(count_token, "expected at most " + std::to_string(limits::kMaxControlPoints) + " control points",
         "M x N is " + std::to_string(rows * columns));
  }
  count_points(rows * columns, count_token);
  check_mesh(steps_token, bspline_patch_vertex_count(rows, columns, patch.steps));
  estimated_vertices_ = bspline_patch_vertex_count(rows, columns, patch.steps);
  patch.rows = static_cast<int>(rows);
  patch.columns = static_cast<int>(columns);
  read_clauses(object, doc, "'[' to start " + point_text(1, rows * columns));
  read_points(object, rows * columns);
}

/// `mesh NAME NV NF`, NV points, NF faces `[i j k ...]` of 0-based vertex indices.
void Parser::read_polygon_mesh(Object& object, const Document& doc) {
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
Token Parser::read_face(Object& object, std::int64_t face, std::int64_t faces, std::int64_t vertices) {
  PolygonMeshSurface& cage = object.as<PolygonMeshSurface>();
  const std::string which = "face " + std::to_string(face + 1) + " of " + std::to_string(faces);
  const Token open = lexer_.next();
  if (open.type != TokenType::Open) fail(open, "expected '[' to start " + which);
  int size = 0;
  for (Token next = lexer_.peek(); next.type != TokenType::Close; next = lexer_.peek()) {
    if (size == vertices) fail(next, "expected ']' to end " + which, "a face has at most NV vertices");
    cage.face_vertices.push_back(static_cast<int>(read_integer("a vertex index of " + which, 0, vertices - 1)));
    ++size;
  }
  if (size < 3) {
    fail(lexer_.peek(), "expected a vertex index of " + which,
         "a face has at least 3 vertices, this one " + std::to_string(size));
  }
  (void)lexer_.next();
  if (const auto breach = caps_.add_face_corners(size)) fail(open, breach->expected, breach->note);
  cage.face_sizes.push_back(size);
  return open;
}

/// `subd NAME LEVELS SOURCE`: SOURCE is an earlier mesh or grid surface.
void Parser::read_subdivision(Object& object, const Document& doc) {
  SubdivisionSurface& subd = object.as<SubdivisionSurface>();
  subd.levels = static_cast<int>(read_integer("LEVELS", 0, kMaxSubdivisionLevel, &levels_token_));
  const Token token = lexer_.next();
  const std::string expected = "expected the name of a surface defined above as the cage (" +
                               keyword_list([](ObjectKind kind) { return is_surface(kind); }) + ")";
  const int index = find_named(token, expected);
  const Object& source = doc.objects[static_cast<std::size_t>(index)];
  if (!is_surface(source.kind())) fail(token, expected, "it is " + kind_description(source.kind()));
  subd.source = index;
  source_vertices_ = vertex_estimates_[static_cast<std::size_t>(index)];
}

/// Loop needs triangles; the refined mesh must fit the caps (checked before refining).
void Parser::check_subdivision(const Object& object, const Document& doc) {
  const SubdivisionSurface& subd = object.as<SubdivisionSurface>();
  const Object& source = doc.objects[static_cast<std::size_t>(subd.source)];
  if (const auto problem = check_subdivision_scheme(subd, source, source.name)) {
    fail(loop_token_, problem->expected, problem->note);
  }
  check_mesh(levels_token_, subdivision_vertex_count(subd, source, source_vertices_));
}

int Parser::read_material_reference(const Document& doc) {
  const Token token = lexer_.next();
  const std::string expected = "expected the name of a material defined above";
  const int index = find_named(token, expected);
  const Object& target = doc.objects[static_cast<std::size_t>(index)];
  if (!is_material(target.kind())) fail(token, expected, "it is " + kind_description(target.kind()));
  return index;
}

int Parser::read_model_reference(const Document& doc) {
  const Token token = lexer_.next();
  const std::string expected = "expected the name of a surface defined above as the model (" +
                               keyword_list([](ObjectKind kind) { return is_surface(kind); }) + ")";
  const int index = find_named(token, expected);
  const Object& target = doc.objects[static_cast<std::size_t>(index)];
  if (!is_surface(target.kind())) fail(token, expected, "it is " + kind_description(target.kind()));
  return index;
}

/// `material NAME [color R G B] [shininess S] [texture FILE.png | checker N] [bump FILE.png H]`,
/// each clause at most once, in any order; image files are checked here (material.hpp).
void Parser::read_material(Object& object) {
  constexpr auto& kKeys = kMaterialKeys;
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

void Parser::read_material_clause(Object& object, std::string_view key) {
  MaterialLook& look = object.as<MaterialLook>();
  Token value;
  if (key == "color") {
    const char* channels[3] = {"red", "green", "blue"};
    for (int c = 0; c < 3; ++c) {
      look.color[c] = read_finite({channels[c]}, &value);
      if (look.color[c] < 0.0 || look.color[c] > 1.0) {
        fail(value, std::string("expected a colour component from 0 to 1 (") + channels[c] + ")");
      }
    }
  } else if (key == "shininess") {
    look.shininess = read_finite({"shininess"}, &value);
    if (look.shininess < 1.0 || look.shininess > 1000.0) fail(value, "expected a shininess from 1 to 1000");
  } else if (key == "checker") {
    look.checker = static_cast<int>(read_integer("the checker's cells per side", 1, 256));
  } else if (key == "texture") {
    look.texture = read_image_path("texture", "texture");
  } else {
    look.bump = read_image_path("bump", "bump image");
    look.bump_height = read_finite({"bump height"}, &value);
    if (look.bump_height < 0.0 || look.bump_height > limits::kMaxCoordinate) {
      fail(value, "expected a bump height from 0 to 1e12 (model units)");
    }
  }
}

/// An image file name, checked to be a PNG that stb_image reads, relative to the SWP file; a
/// missing one is a warning (MissingImage).
std::string Parser::read_image_path(const char* role, const char* image) {
  const Token token = lexer_.next();
  const std::string expected = std::string("expected a PNG image file (") + role + ")";
  if (token.type != TokenType::Word) fail(token, expected);
  const std::filesystem::path path = image_base(std::filesystem::path(file_)) / std::string(token.text);
  if (image_missing(path)) {
    std::string warning = std::string(file_) + ":" + std::to_string(token.line) + ":" + std::to_string(token.column) +
                          ": warning: " + image + " '";
    warning += printable_excerpt(token.text, kMaxWarnedPathBytes);
    warning += "' not found; drawn as a magenta checker";
    missing_images_.push_back({std::string(token.text), std::move(warning)});
    return std::string(token.text);
  }
  const std::string problem = image_problem(path);
  if (!problem.empty()) fail(token, expected, problem);
  return std::string(token.text);
}

}  // namespace sweep::io::swp_detail
