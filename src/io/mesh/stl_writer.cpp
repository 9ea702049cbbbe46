#include "io/mesh/stl_writer.hpp"

#include "io/files/atomic_file.hpp"
#include "io/mesh/obj_writer.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace sweep::io {
namespace {

/// Writes v little-endian at `at` and returns the next byte.
char* put_u32(char* at, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) *at++ = static_cast<char>((v >> shift) & 0xffu);
  return at;
}

/// Writes v's three floats, -0 as +0: readers that match corners by their bytes (admesh) see a
/// pole's copies (x = 0, z = -0 * sin) as the one point they are.
char* put_vector(char* at, const glm::vec3& v) {
  for (int axis = 0; axis < 3; ++axis) at = put_u32(at, std::bit_cast<std::uint32_t>(v[axis] + 0.0f));
  return at;
}

/// The 84 bytes before the triangles: the header, zero-padded, and the triangle count.
std::array<char, 84> stl_header(const Mesh& mesh, const std::string& comment) {
  std::array<char, 84> out{};
  const std::string header = "sweep binary STL: " + comment;
  std::copy_n(header.begin(), std::min<std::size_t>(header.size(), 80), out.begin());
  put_u32(out.data() + 80, static_cast<std::uint32_t>(mesh.triangle_count()));
  return out;
}

/// Writes the 50 bytes of the triangle whose indices start at `t` at `at`; returns the next byte.
char* put_triangle(char* at, const Mesh& mesh, std::size_t t) {
  const glm::vec3& a = mesh.positions[mesh.indices[t]];
  const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
  const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
  const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
  const double length = glm::length(n);
  at = put_vector(at, length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f));
  at = put_vector(at, a);
  at = put_vector(at, b);
  at = put_vector(at, c);
  *at++ = 0;  // the attribute byte count: 0
  *at++ = 0;
  return at;
}

}  // namespace

std::string stl_bytes(const Mesh& mesh, const std::string& comment) {
  std::string out(84 + 50 * mesh.triangle_count(), '\0');  // every byte written once, below
  const std::array<char, 84> header = stl_header(mesh, comment);
  char* at = std::copy(header.begin(), header.end(), out.data());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) at = put_triangle(at, mesh, t);
  return out;
}

bool write_stl(std::FILE* out, const Mesh& mesh, const std::string& comment) {
  // In 64 KB chunks of whole triangles: no buffer of the file's size is allocated, and the
  // kernel takes such writes faster than one of the whole file (files/atomic_file.cpp).
  constexpr std::size_t kChunkTriangles = 1310;  // 65,500 bytes
  const std::array<char, 84> header = stl_header(mesh, comment);
  if (std::fwrite(header.data(), 1, header.size(), out) != header.size()) return false;
  std::vector<char> chunk(50 * kChunkTriangles);
  for (std::size_t t = 0; t + 2 < mesh.indices.size();) {
    char* at = chunk.data();
    for (std::size_t k = 0; k < kChunkTriangles && t + 2 < mesh.indices.size(); ++k, t += 3) {
      at = put_triangle(at, mesh, t);
    }
    const auto bytes = static_cast<std::size_t>(at - chunk.data());
    if (std::fwrite(chunk.data(), 1, bytes, out) != bytes) return false;
  }
  return true;
}

void save_stl_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  write_file_atomically(path, [&](std::FILE* f) { return write_stl(f, mesh, comment); });
}

}  // namespace sweep::io
