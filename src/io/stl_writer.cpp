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

void put_u32(std::string& out, std::uint32_t v) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((v >> shift) & 0xffu));
}

void put_vector(std::string& out, const glm::vec3& v) {
  for (int axis = 0; axis < 3; ++axis) put_u32(out, std::bit_cast<std::uint32_t>(v[axis]));
}

}  // namespace

std::string stl_bytes(const Mesh& mesh, const std::string& comment) {
  std::string out;
  out.reserve(84 + 50 * mesh.triangle_count());
  std::string header = "sweep binary STL: " + comment;
  header.resize(80, '\0');
  out += header;
  put_u32(out, static_cast<std::uint32_t>(mesh.triangle_count()));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3& a = mesh.positions[mesh.indices[t]];
    const glm::vec3& b = mesh.positions[mesh.indices[t + 1]];
    const glm::vec3& c = mesh.positions[mesh.indices[t + 2]];
    const glm::dvec3 n = glm::cross(glm::dvec3(b) - glm::dvec3(a), glm::dvec3(c) - glm::dvec3(a));
    const double length = glm::length(n);
    put_vector(out, length > 0.0 ? glm::vec3(n / length) : glm::vec3(0.0f));
    put_vector(out, a);
    put_vector(out, b);
    put_vector(out, c);
    out.append(2, '\0');
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
