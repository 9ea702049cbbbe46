#include "io/stl_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/obj_writer.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <stdexcept>

namespace sweep {
namespace {

/// Writes v little-endian at `at` and returns the next byte.
char* put_u32(char* at, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) *at++ = static_cast<char>((v >> shift) & 0xffu);
  return at;
}

char* put_vector(char* at, const glm::vec3& v) {
  for (int axis = 0; axis < 3; ++axis) at = put_u32(at, std::bit_cast<std::uint32_t>(v[axis]));
  return at;
}

}  // namespace

std::string stl_bytes(const Mesh& mesh, const std::string& comment) {
  // Every byte is written once into a string of the final size (the header's padding and the
  // attribute words are its zeros).
  std::string out(84 + 50 * mesh.triangle_count(), '\0');
  const std::string header = "sweep binary STL: " + comment;
  std::copy_n(header.begin(), std::min<std::size_t>(header.size(), 80), out.begin());
  char* at = put_u32(out.data() + 80, static_cast<std::uint32_t>(mesh.triangle_count()));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3& a = mesh.positions[mesh.indices[t]];
    const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double length = glm::length(n);
    at = put_vector(at, length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f));
    at = put_vector(at, a);
    at = put_vector(at, b);
    at = put_vector(at, c);
    at += 2;  // the attribute byte count: 0
  }
  return out;
}

void save_stl_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  write_file_atomically(path, stl_bytes(mesh, comment));
}

}  // namespace sweep
