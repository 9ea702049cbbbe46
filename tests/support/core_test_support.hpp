#pragma once
// Helpers shared by the core tests: the starter files, reference evaluations written from the
// textbook formulas (independent of src/core/bezier.cpp), and mesh topology counts.
#include "geometry/mesh.hpp"
#include "io/swp_parser.hpp"
#include "model/document.hpp"
#include "model/edit.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sweep::test {

/// Runs an edit that must fail; checks that the document did not change and returns the message.
inline std::string edit_error(Document& doc, const std::function<void()>& edit) {
  const Document before = doc;
  try {
    edit();
  } catch (const EditError& e) {
    EXPECT_EQ(doc, before) << "the failed edit changed the document";
    return e.what();
  }
  ADD_FAILURE() << "no EditError";
  return {};
}

/// Every *.swp file in `folder` (not below it), sorted.
inline std::vector<std::filesystem::path> swp_files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".swp") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Every *.swp file in swp/, sorted, so a new starter file is covered without touching the tests.
inline std::vector<std::filesystem::path> starter_files() {
  return swp_files_in(SWEEP_SWP_DIR);
}

/// Every *.swp file in swp/artifacts/ (the README's showcase models), sorted.
inline std::vector<std::filesystem::path> artifact_files() {
  return swp_files_in(std::filesystem::path(SWEEP_SWP_DIR) / "artifacts");
}

/// The message parsing `text` as `file` throws; "no error" if it parses.
inline std::string error_of(const std::string& text, const std::string& file = "bad.swp") {
  try {
    (void)parse_swp(text, file);
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

/// Expects parsing `text` as `file` to throw a ParseError at LINE:COLUMN whose message is exactly
/// "FILE:LINE:COLUMN: " + detail, and whose file(), line(), column() and detail() say the same.
inline void expect_error(const std::string& text, int line, int column, const std::string& detail,
                         const std::string& file = "bad.swp") {
  try {
    (void)parse_swp(text, file);
  } catch (const ParseError& e) {
    EXPECT_EQ(std::string(e.what()), file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + detail)
        << text;
    EXPECT_EQ(e.line(), line) << text;
    EXPECT_EQ(e.column(), column) << text;
    EXPECT_EQ(e.file(), file) << text;
    EXPECT_EQ(e.detail(), detail) << text;
    return;
  }
  ADD_FAILURE() << "no ParseError for: " << text;
}

/// The starter file swp/NAME, parsed.
inline Document load_starter(const char* name) {
  return load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / name);
}

/// Bernstein polynomials of degree 3 at t.
inline glm::dvec4 bernstein_weights(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

/// Uniform cubic B-spline blending functions at t (Bartels, Beatty, Barsky, "An Introduction to
/// Splines for Use in Computer Graphics and Geometric Modeling", 1987).
inline glm::dvec4 bspline_weights(double t) {
  const double s = 1.0 - t;
  return {s * s * s / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
          (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0};
}

/// Piece k of a piecewise Bezier curve at t, by de Casteljau's algorithm.
inline glm::dvec3 direct_bezier(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  glm::dvec3 p[4] = {points[3 * piece], points[3 * piece + 1], points[3 * piece + 2], points[3 * piece + 3]};
  for (int level = 3; level > 0; --level) {
    for (int i = 0; i < level; ++i) p[i] = (1.0 - t) * p[i] + t * p[i + 1];
  }
  return p[0];
}

/// Piece k of a uniform cubic B-spline at t, straight from the blending functions.
inline glm::dvec3 direct_bspline(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  const glm::dvec4 w = bspline_weights(t);
  return w[0] * points[piece] + w[1] * points[piece + 1] + w[2] * points[piece + 2] + w[3] * points[piece + 3];
}

/// Derivative of direct_bspline with respect to t.
inline glm::dvec3 direct_bspline_derivative(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  const double s = 1.0 - t;
  const glm::dvec4 w{-s * s / 2.0, (3.0 * t * t - 4.0 * t) / 2.0, (-3.0 * t * t + 2.0 * t + 1.0) / 2.0, t * t / 2.0};
  return w[0] * points[piece] + w[1] * points[piece + 1] + w[2] * points[piece + 2] + w[3] * points[piece + 3];
}

/// How many triangles use each undirected edge (smaller index first).
inline std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + k];
      const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  return uses;
}

/// How many triangles traverse each directed edge a -> b.
inline std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edge_uses(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) ++uses[{mesh.indices[t + k], mesh.indices[t + (k + 1) % 3]}];
  }
  return uses;
}

inline double distance(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(a - b);
}

}  // namespace sweep::test
