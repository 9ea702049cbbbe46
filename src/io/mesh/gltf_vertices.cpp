#include "io/mesh/gltf_vertices.hpp"

#include "base/precondition.hpp"
#include "geometry/thread_pool.hpp"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <span>
#include <utility>

namespace sweep::io {
namespace {

bool indices_in_range(const Mesh& mesh) {
  return std::all_of(mesh.indices.begin(), mesh.indices.end(),
                     [n = mesh.vertex_count()](std::uint32_t i) { return i < n; });
}

/// The vertex cache the order is made for: 16 entries, first in first out, as GPUs have.
constexpr unsigned kCacheSize = 16;
/// Average cache misses per triangle below which a piece's order is kept: the FIFO optimizer
/// gives 0.6-0.69 on Sweep's grids, a grid made in bands 0.57-0.6.
constexpr float kGoodAcmr = 0.65f;

/// The triangles whose cache order is made alone: a piece of a grid in row order uses a narrow
/// band of vertices, so the optimizer's per-vertex tables are small and stay in the caches.
constexpr std::size_t kPieceIndices = 3 * 32768;

/// The least and greatest vertex that `indices` use (not empty).
std::pair<std::uint32_t, std::uint32_t> vertex_band(std::span<const std::uint32_t> indices) {
  const auto [low, high] = std::minmax_element(indices.begin(), indices.end());
  return {*low, *high};
}

/// True when every piece of kPieceIndices uses a band of at most 4 vertices per index: the
/// meshes Sweep makes (grids, fans, patches and subdivisions in face order) do.
bool pieces_are_local(const std::vector<std::uint32_t>& indices) {
  for (std::size_t begin = 0; begin < indices.size(); begin += kPieceIndices) {
    const std::size_t count = std::min(kPieceIndices, indices.size() - begin);
    const auto [low, high] = vertex_band({indices.data() + begin, count});
    if (high - low >= 4 * count) return false;
  }
  return true;
}

/// Writes `indices` in vertex-cache order into `destination` (as many), piece by piece, the
/// pieces on the worker threads: each piece's order depends on it alone, so the result is the same
/// whatever the thread count.
void cache_order_by_pieces(std::uint32_t* destination, const std::vector<std::uint32_t>& indices) {
  const std::size_t pieces = (indices.size() + kPieceIndices - 1) / kPieceIndices;
  parallel_chunks(pieces, 1, worker_count(), [&](std::size_t piece, std::size_t, int) {
    const std::size_t begin = piece * kPieceIndices;
    const std::size_t count = std::min(kPieceIndices, indices.size() - begin);
    const auto [low, high] = vertex_band({indices.data() + begin, count});
    std::uint32_t* out = destination + begin;
    for (std::size_t k = 0; k < count; ++k) out[k] = indices[begin + k] - low;
    // A grid made in bands (kBandQuads, mesh.hpp) is in cache order already: kept as it is.
    const std::size_t band = high - low + 1;
    if (meshopt_analyzeVertexCache(out, count, band, kCacheSize, 0, 0).acmr > kGoodAcmr) {
      meshopt_optimizeVertexCacheFifo(out, out, count, band, kCacheSize);
    }
    for (std::size_t k = 0; k < count; ++k) out[k] += low;
  });
}

}  // namespace

GpuOrder gpu_order(const Mesh& mesh) {
  SWEEP_EXPECTS(mesh.indices.size() % 3 == 0 && indices_in_range(mesh), "3 indices per triangle, each a vertex");
  GpuOrder order;
  const std::size_t n = mesh.vertex_count();
  // Kept when already in cache order (a grid made in bands, kBandQuads in mesh.hpp: ACMR ~0.58;
  // checking costs one pass). Otherwise meshoptimizer's FIFO variant (a 16-entry cache, as GPUs
  // have; about ten times faster than its full optimizer for an ACMR within a few percent:
  // gltf_quantize_test checks weird.swp's stays at most 0.69), by pieces in parallel where the
  // pieces use narrow bands of vertices, else in one go.
  if (meshopt_analyzeVertexCache(mesh.indices.data(), mesh.indices.size(), n, kCacheSize, 0, 0).acmr <= kGoodAcmr) {
    order.indices = mesh.indices;
  } else {
    order.indices.resize(mesh.indices.size());
    if (pieces_are_local(mesh.indices)) {
      cache_order_by_pieces(order.indices.data(), mesh.indices);
    } else {
      meshopt_optimizeVertexCacheFifo(order.indices.data(), mesh.indices.data(), mesh.indices.size(), n, kCacheSize);
    }
  }
  order.remap.resize(n);
  order.vertex_count =
      meshopt_optimizeVertexFetchRemap(order.remap.data(), order.indices.data(), order.indices.size(), n);
  // In place: each index is replaced by its own remapped value.
  meshopt_remapIndexBuffer(order.indices.data(), order.indices.data(), order.indices.size(), order.remap.data());
  return order;
}

void reorder_into(const GpuOrder& order, const void* values, std::size_t count, std::size_t size, void* destination) {
  SWEEP_EXPECTS(count == order.remap.size(), "one value per vertex of the ordered mesh");
  meshopt_remapVertexBuffer(destination, values, count, size, order.remap.data());
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

}  // namespace sweep::io
