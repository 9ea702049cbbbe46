#pragma once
// The vertex data a glb mesh holds, made with meshoptimizer: the order of a mesh's triangles and
// vertices a GPU reads best, and the quantized forms of its attributes that
// KHR_mesh_quantization allows (`sweep export --format glb --quantize`).
#include "geometry/mesh/mesh.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace sweep::io {

/// The order a GPU reads a mesh's triangles and vertices best in.
struct GpuOrder {
  std::vector<std::uint32_t> indices;  // the triangles in vertex-cache order, indexing the new order
  std::vector<std::uint32_t> remap;    // old vertex -> new vertex; ~0u for a vertex no triangle uses
  std::size_t vertex_count = 0;        // vertices some triangle uses: the new order's length
};

/// `mesh`'s GPU order: its triangles in vertex-cache order (meshopt_optimizeVertexCacheFifo), then
/// its vertices in the order the triangles first use them (meshopt_optimizeVertexFetchRemap), so
/// new vertex i's first use comes before i + 1's. Every triangle keeps its vertices and their
/// order (winding). Precondition: mesh.indices holds 3 per triangle, each < mesh.vertex_count().
GpuOrder gpu_order(const Mesh& mesh);

/// Writes the `count` elements of `size` bytes at `values`, one per old vertex, in `order` to
/// `destination` (order.vertex_count elements; vertices no triangle uses are left out).
/// Precondition: count == order.remap.size().
void reorder_into(const GpuOrder& order, const void* values, std::size_t count, std::size_t size, void* destination);

/// Positions as signed 16-bit integers on a uniform grid: position ~ step * (x, y, z), each
/// coordinate within step / 2, with step = the largest |coordinate| / 32767 (1 when all are 0).
/// The fourth integer is 0, padding each vertex to 8 bytes (glTF aligns vertex elements to 4).
/// The grid is uniform so one node scale (step) restores the positions without bending normals.
struct QuantizedPositions {
  std::vector<std::array<std::int16_t, 4>> values;
  double step = 1.0;
};

/// Precondition: every coordinate finite.
QuantizedPositions quantize_positions(std::span<const glm::vec3> positions);

/// Unit normals as normalized signed bytes (x, y, z, 0 padding): each component c as
/// round(127 c), which reads back as that / 127, within 0.5 / 127 of c.
std::vector<std::array<std::int8_t, 4>> quantize_normals(std::span<const glm::vec3> normals);

/// Texture coordinates as normalized unsigned 16-bit integers, round(65535 c), within 0.5 / 65535
/// of c; nullopt when a coordinate lies outside [0, 1] (a tiling texture), which stays float.
std::optional<std::vector<std::array<std::uint16_t, 2>>> quantize_uvs(std::span<const glm::vec2> uvs);

}  // namespace sweep::io
