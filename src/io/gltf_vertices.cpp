#include "io/gltf_vertices.hpp"

#include "geometry/precondition.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

namespace sweep {
namespace {

/// `values` reordered by `remap` (old index -> new index, ~0u for a vertex left out) into `count`;
/// none unless there is one value per entry of `remap`.
template <typename T>
std::vector<T> remapped(const std::vector<T>& values, const std::vector<unsigned int>& remap, std::size_t count) {
  if (values.size() != remap.size()) return {};
  std::vector<T> out(count);
  meshopt_remapVertexBuffer(out.data(), values.data(), values.size(), sizeof(T), remap.data());
  return out;
}

bool indices_in_range(const Mesh& mesh) {
  return std::all_of(mesh.indices.begin(), mesh.indices.end(),
                     [n = mesh.vertex_count()](std::uint32_t i) { return i < n; });
}

}  // namespace

GlbVertices gpu_ordered(const Mesh& mesh) {
  SWEEP_EXPECTS(mesh.indices.size() % 3 == 0 && indices_in_range(mesh), "3 indices per triangle, each a vertex");
  GlbVertices out;
  const std::size_t n = mesh.vertex_count();
  std::vector<unsigned int> cached(mesh.indices.size());
  meshopt_optimizeVertexCache(cached.data(), mesh.indices.data(), mesh.indices.size(), n);
  std::vector<unsigned int> remap(n);
  const std::size_t used = meshopt_optimizeVertexFetchRemap(remap.data(), cached.data(), cached.size(), n);
  out.indices.resize(cached.size());
  meshopt_remapIndexBuffer(out.indices.data(), cached.data(), cached.size(), remap.data());
  out.positions = remapped(mesh.positions, remap, used);
  out.normals = remapped(mesh.normals, remap, used);
  out.uvs = remapped(mesh.uvs, remap, used);
  for (glm::vec2& uv : out.uvs) uv.y = 1.0f - uv.y;
  return out;
}

QuantizedPositions quantize_positions(std::span<const glm::vec3> positions) {
  double largest = 0.0;
  for (const glm::vec3& p : positions) {
    SWEEP_EXPECTS(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z), "finite positions");
    largest = std::max({largest, std::fabs(double{p.x}), std::fabs(double{p.y}), std::fabs(double{p.z})});
  }
  QuantizedPositions out;
  out.step = largest > 0.0 ? largest / 32767.0 : 1.0;
  out.values.reserve(positions.size());
  const auto grid = [step = out.step](float c) {
    return static_cast<std::int16_t>(std::clamp(std::lround(double{c} / step), -32767L, 32767L));
  };
  for (const glm::vec3& p : positions) out.values.push_back({grid(p.x), grid(p.y), grid(p.z), 0});
  return out;
}

std::vector<std::array<std::int8_t, 4>> quantize_normals(std::span<const glm::vec3> normals) {
  std::vector<std::array<std::int8_t, 4>> out;
  out.reserve(normals.size());
  const auto byte = [](float c) { return static_cast<std::int8_t>(meshopt_quantizeSnorm(c, 8)); };
  for (const glm::vec3& n : normals) out.push_back({byte(n.x), byte(n.y), byte(n.z), 0});
  return out;
}

std::optional<std::vector<std::array<std::uint16_t, 2>>> quantize_uvs(std::span<const glm::vec2> uvs) {
  const bool in_unit_square = std::all_of(uvs.begin(), uvs.end(), [](const glm::vec2& uv) {
    return uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f;
  });
  if (!in_unit_square) return std::nullopt;
  std::vector<std::array<std::uint16_t, 2>> out;
  out.reserve(uvs.size());
  const auto unorm = [](float c) { return static_cast<std::uint16_t>(meshopt_quantizeUnorm(c, 16)); };
  for (const glm::vec2& uv : uvs) out.push_back({unorm(uv.x), unorm(uv.y)});
  return out;
}

}  // namespace sweep
