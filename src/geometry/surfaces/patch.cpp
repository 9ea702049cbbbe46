// Bicubic patch evaluation and meshing (tensor products of the cubic Bernstein and uniform
// B-spline bases; see Farin, "Curves and Surfaces for CAGD", ch. 16).
#include "geometry/surfaces/patch.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/weld.hpp"
#include "geometry/subdivision/subdivision.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep {
namespace {

struct Basis {
  std::array<double, 4> value;
  std::array<double, 4> derivative;
};

Basis bernstein(double t) {
  const double s = 1.0 - t;
  return {{s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t},
          {-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t}};
}

Basis uniform_bspline(double t) {
  const double s = 1.0 - t;
  const double t2 = t * t;
  const double t3 = t2 * t;
  return {{s * s * s / 6.0, (3.0 * t3 - 6.0 * t2 + 4.0) / 6.0, (-3.0 * t3 + 3.0 * t2 + 3.0 * t + 1.0) / 6.0, t3 / 6.0},
          {-s * s / 2.0, (3.0 * t2 - 4.0 * t) / 2.0, (-3.0 * t2 + 2.0 * t + 1.0) / 2.0, t2 / 2.0}};
}

Basis basis_at(PatchBasis basis, double t) {
  return basis == PatchBasis::Bezier ? bernstein(t) : uniform_bspline(t);
}

/// Positions and normals of sampled patches, before welding.
struct Samples {
  std::vector<glm::dvec3> positions;
  std::vector<glm::dvec3> normals;
  std::vector<std::uint32_t> indices;
};

/// Appends patch `points` sampled on a (steps + 1)^2 grid; `u0`, `v0` place it in a larger grid
/// of `grid_columns` samples per row (B-spline nets), or 0 for a separate grid per patch.
void sample_patch(const PatchPoints& points, PatchBasis basis, int steps, Samples& out) {
  const auto first = static_cast<std::uint32_t>(out.positions.size());
  const auto side = static_cast<std::uint32_t>(steps + 1);
  for (int i = 0; i <= steps; ++i) {
    const double u = double(i) / steps;
    for (int j = 0; j <= steps; ++j) {
      const double v = double(j) / steps;
      out.positions.push_back(evaluate_patch(points, basis, u, v).position);
      out.normals.push_back(patch_normal(points, basis, u, v));
    }
  }
  for (std::uint32_t i = 0; i + 1 < side; ++i) {
    for (std::uint32_t j = 0; j + 1 < side; ++j) {
      const std::uint32_t a = first + i * side + j;
      // b is one step in u (the next row), c one in v: (b - a) x (c - a) is dP/du x dP/dv.
      add_quad(out.indices, a, a + side, a + 1, a + side + 1, true);
    }
  }
}

/// Welds the samples into a mesh: one vertex per welded position with the normalized sum of its
/// normals; triangles that welding collapsed are dropped.
Mesh weld_samples(const Samples& samples) {
  const double tolerance = std::max(points_extent(samples.positions) * 1e-9, 1e-300);
  const std::vector<std::uint32_t> first = weld_points(samples.positions, tolerance);
  std::vector<std::uint32_t> compact(samples.positions.size());
  std::vector<glm::dvec3> normal_sum;
  Mesh mesh;
  for (std::size_t i = 0; i < samples.positions.size(); ++i) {
    if (first[i] == i) {
      compact[i] = static_cast<std::uint32_t>(mesh.positions.size());
      mesh.positions.emplace_back(samples.positions[i]);
      normal_sum.push_back(samples.normals[i]);
    } else {
      compact[i] = compact[first[i]];
      normal_sum[compact[i]] += samples.normals[i];
    }
  }
  mesh.normals.reserve(normal_sum.size());
  for (std::size_t i = 0; i < normal_sum.size(); ++i) {
    const double length = glm::length(normal_sum[i]);
    // Opposite normals welded together (a sheet folded onto itself) keep the first one.
    const glm::dvec3 n = length > 1e-9 ? normal_sum[i] / length : samples.normals[i];
    mesh.normals.emplace_back(n);
  }
  mesh.indices.reserve(samples.indices.size());
  for (std::size_t t = 0; t + 2 < samples.indices.size(); t += 3) {
    const std::uint32_t a = compact[samples.indices[t]];
    const std::uint32_t b = compact[samples.indices[t + 1]];
    const std::uint32_t c = compact[samples.indices[t + 2]];
    if (a == b || b == c || a == c) continue;
    mesh.indices.insert(mesh.indices.end(), {a, b, c});
  }
  return mesh;
}

}  // namespace

PatchSample evaluate_patch(const PatchPoints& points, PatchBasis basis, double u, double v) {
  const Basis bu = basis_at(basis, u);
  const Basis bv = basis_at(basis, v);
  PatchSample s;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const glm::dvec3& p = points[static_cast<std::size_t>(4 * i + j)];
      s.position += bu.value[i] * bv.value[j] * p;
      s.du += bu.derivative[i] * bv.value[j] * p;
      s.dv += bu.value[i] * bv.derivative[j] * p;
    }
  }
  return s;
}

glm::dvec3 patch_normal(const PatchPoints& points, PatchBasis basis, double u, double v) {
  const double extent = points_extent(points);
  const double floor = 1e-10 * extent * extent;
  // A step of 1e-6 towards the centre first (a first-order Taylor step into the patch), growing
  // tenfold while the cross product stays degenerate.
  for (double step = 0.0; step <= 0.5; step = step == 0.0 ? 1e-6 : step * 10.0) {
    const double su = u + step * (0.5 - u);
    const double sv = v + step * (0.5 - v);
    const PatchSample s = evaluate_patch(points, basis, su, sv);
    const glm::dvec3 n = glm::cross(s.du, s.dv);
    const double length = glm::length(n);
    if (length > floor && length > 0.0) return n / length;
  }
  return {0.0, 0.0, 1.0};  // a patch collapsed to a point or a curve has no normal anywhere
}

PatchPoints bspline_to_bezier(const PatchPoints& points) {
  // Rows of M: Bezier points of one cubic B-spline segment, from its four B-spline points.
  constexpr double m[4][4] = {{1.0 / 6, 4.0 / 6, 1.0 / 6, 0.0},
                              {0.0, 4.0 / 6, 2.0 / 6, 0.0},
                              {0.0, 2.0 / 6, 4.0 / 6, 0.0},
                              {0.0, 1.0 / 6, 4.0 / 6, 1.0 / 6}};
  PatchPoints out{};
  for (int a = 0; a < 4; ++a) {
    for (int b = 0; b < 4; ++b) {
      glm::dvec3 p(0.0);
      for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 4; ++j) p += m[a][i] * m[b][j] * points[static_cast<std::size_t>(4 * i + j)];
      }
      out[static_cast<std::size_t>(4 * a + b)] = p;
    }
  }
  return out;
}

PatchPoints bspline_patch_points(std::span<const glm::dvec3> points, int columns, int r, int c) {
  PatchPoints patch;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      patch[static_cast<std::size_t>(4 * i + j)] = points[static_cast<std::size_t>((r + i) * columns + c + j)];
    }
  }
  return patch;
}

namespace {

/// The samples' quads (add_quad pairs, none dropped yet) as a welded cage.
Cage quad_cage(const Samples& samples) {
  Cage cage;
  cage.points = samples.positions;
  for (std::size_t t = 0; t + 5 < samples.indices.size(); t += 6) {
    const auto at = [&](std::size_t k) { return static_cast<int>(samples.indices[t + k]); };
    cage.face_sizes.push_back(4);
    cage.face_vertices.insert(cage.face_vertices.end(), {at(0), at(1), at(4), at(2)});  // a b d c
  }
  return welded_cage(cage);
}

Samples bezier_samples(std::span<const glm::dvec3> points, int steps) {
  Samples samples;
  const std::size_t count = points.size() / 16;
  const auto per_patch = static_cast<std::size_t>(steps + 1) * static_cast<std::size_t>(steps + 1);
  samples.positions.reserve(count * per_patch);
  samples.normals.reserve(count * per_patch);
  samples.indices.reserve(count * static_cast<std::size_t>(steps) * static_cast<std::size_t>(steps) * 6);
  for (std::size_t k = 0; k < count; ++k) {
    PatchPoints patch;
    std::copy_n(points.begin() + static_cast<std::ptrdiff_t>(16 * k), 16, patch.begin());
    sample_patch(patch, PatchBasis::Bezier, steps, samples);
  }
  return samples;
}

Samples bspline_samples(std::span<const glm::dvec3> points, int rows, int columns, int steps) {
  // One grid over the whole net: sample (i, j) lies in patch (i / steps, j / steps), the last
  // sample of a patch being the first of the next one (welded).
  const int grid_rows = (rows - 3) * steps + 1;
  const int grid_columns = (columns - 3) * steps + 1;
  Samples samples;
  const auto total = static_cast<std::size_t>(grid_rows) * static_cast<std::size_t>(grid_columns);
  samples.positions.reserve(total);
  samples.normals.reserve(total);
  for (int i = 0; i < grid_rows; ++i) {
    const int r = std::min(i / steps, rows - 4);
    const double u = double(i - r * steps) / steps;
    for (int j = 0; j < grid_columns; ++j) {
      const int c = std::min(j / steps, columns - 4);
      const double v = double(j - c * steps) / steps;
      const PatchPoints patch = bspline_patch_points(points, columns, r, c);
      samples.positions.push_back(evaluate_patch(patch, PatchBasis::BSpline, u, v).position);
      samples.normals.push_back(patch_normal(patch, PatchBasis::BSpline, u, v));
    }
  }
  const auto side = static_cast<std::uint32_t>(grid_columns);
  samples.indices.reserve(total * 6);
  for (std::uint32_t i = 0; i + 1 < static_cast<std::uint32_t>(grid_rows); ++i) {
    for (std::uint32_t j = 0; j + 1 < side; ++j) {
      const std::uint32_t a = i * side + j;
      add_quad(samples.indices, a, a + side, a + 1, a + side + 1, true);
    }
  }
  return samples;
}

}  // namespace

Mesh build_bezier_patches(std::span<const glm::dvec3> points, int steps) {
  SWEEP_EXPECTS(points.size() % 16 == 0, "points: 16 per patch, size a multiple of 16");
  return weld_samples(bezier_samples(points, steps));
}

Mesh build_bspline_patch(std::span<const glm::dvec3> points, int rows, int columns, int steps) {
  SWEEP_EXPECTS(rows >= 4 && columns >= 4, "rows, columns >= 4");
  SWEEP_EXPECTS(points.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns),
                "rows x columns points");
  return weld_samples(bspline_samples(points, rows, columns, steps));
}

Cage bezier_patch_cage(std::span<const glm::dvec3> points, int steps) {
  SWEEP_EXPECTS(points.size() % 16 == 0, "points: 16 per patch, size a multiple of 16");
  return quad_cage(bezier_samples(points, steps));
}

Cage bspline_patch_cage(std::span<const glm::dvec3> points, int rows, int columns, int steps) {
  SWEEP_EXPECTS(rows >= 4 && columns >= 4, "rows, columns >= 4");
  SWEEP_EXPECTS(points.size() == static_cast<std::size_t>(rows) * static_cast<std::size_t>(columns),
                "rows x columns points");
  return quad_cage(bspline_samples(points, rows, columns, steps));
}

std::int64_t bezier_patch_vertex_count(std::int64_t patches, std::int64_t steps) {
  return patches * (steps + 1) * (steps + 1);
}

std::int64_t bspline_patch_vertex_count(std::int64_t rows, std::int64_t columns, std::int64_t steps) {
  return ((rows - 3) * steps + 1) * ((columns - 3) * steps + 1);
}

std::vector<glm::vec3> patch_net_lines(std::span<const glm::dvec3> points, int rows, int columns) {
  std::vector<glm::vec3> lines;
  const auto grid = [&](std::size_t first, int grid_rows, int grid_columns) {
    const auto at = [&](int i, int j) {
      return glm::vec3(points[first + static_cast<std::size_t>(i * grid_columns + j)]);
    };
    for (int i = 0; i < grid_rows; ++i) {
      for (int j = 0; j < grid_columns; ++j) {
        if (j + 1 < grid_columns) lines.insert(lines.end(), {at(i, j), at(i, j + 1)});
        if (i + 1 < grid_rows) lines.insert(lines.end(), {at(i, j), at(i + 1, j)});
      }
    }
  };
  if (columns > 0) {
    grid(0, rows, columns);
  } else {
    for (std::size_t k = 0; k + 16 <= points.size(); k += 16) grid(k, 4, 4);
  }
  return lines;
}

}  // namespace sweep
