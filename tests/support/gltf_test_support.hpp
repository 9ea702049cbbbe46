#pragma once
// Reading back what sweep's glb writer wrote, with tinygltf: an accessor's elements, and a
// primitive's triangles as numbers whatever the encoding (floats, or KHR_mesh_quantization's
// integers read by the glTF rules for normalized and plain integers).
#include "geometry/mesh/mesh.hpp"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace sweep::test {

/// The `count` elements of type T an accessor reads (tightly packed, as sweep writes them).
template <typename T>
std::vector<T> accessor_data(const tinygltf::Model& model, int index) {
  const tinygltf::Accessor& accessor = model.accessors.at(static_cast<std::size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(accessor.bufferView));
  const tinygltf::Buffer& buffer = model.buffers.at(static_cast<std::size_t>(view.buffer));
  std::vector<T> out(accessor.count);
  EXPECT_EQ(view.byteLength, accessor.count * sizeof(T));
  EXPECT_LE(view.byteOffset + accessor.byteOffset + view.byteLength, buffer.data.size());
  std::memcpy(out.data(), buffer.data.data() + view.byteOffset + accessor.byteOffset, out.size() * sizeof(T));
  return out;
}

/// Component `k` of element `i` of an accessor as a number: a float as it is, an integer as it is,
/// or, normalized, as glTF reads it (signed: max(c / max, -1); unsigned: c / max).
inline double accessor_number(const tinygltf::Model& model, int index, std::size_t i, int k) {
  const tinygltf::Accessor& a = model.accessors.at(static_cast<std::size_t>(index));
  const tinygltf::BufferView& view = model.bufferViews.at(static_cast<std::size_t>(a.bufferView));
  const std::size_t size = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(a.componentType));
  const std::size_t stride =
      view.byteStride ? view.byteStride : size * static_cast<std::size_t>(tinygltf::GetNumComponentsInType(a.type));
  const unsigned char* at = model.buffers.at(static_cast<std::size_t>(view.buffer)).data.data() + view.byteOffset +
                            a.byteOffset + i * stride + static_cast<std::size_t>(k) * size;
  const auto read = [at](auto value) {
    std::memcpy(&value, at, sizeof value);
    return value;
  };
  switch (a.componentType) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return read(float{});
    case TINYGLTF_COMPONENT_TYPE_BYTE:
      return a.normalized ? std::max(read(std::int8_t{}) / 127.0, -1.0) : read(std::int8_t{});
    case TINYGLTF_COMPONENT_TYPE_SHORT:
      return a.normalized ? std::max(read(std::int16_t{}) / 32767.0, -1.0) : read(std::int16_t{});
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return read(std::uint16_t{}) / (a.normalized ? 65535.0 : 1.0);
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
      return read(std::uint32_t{});
    default:
      ADD_FAILURE() << "component type " << a.componentType;
      return 0.0;
  }
}

/// A vertex read back: x, y, z (times the node's `scale`), normal x, y, z, u, v (0 when absent).
using ReadVertex = std::array<double, 8>;
/// A triangle's vertices in its order, rotated to start at the least (winding kept).
using ReadTriangle = std::array<ReadVertex, 3>;

inline ReadTriangle canonical(ReadTriangle t) {
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

/// The primitive's vertices in the file's order; positions times `scale` (the node's).
inline std::vector<ReadVertex> read_vertices(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                             double scale = 1.0) {
  const auto attribute = [&p](const char* name) { return p.attributes.count(name) ? p.attributes.at(name) : -1; };
  const int position = attribute("POSITION"), normal = attribute("NORMAL"), uv = attribute("TEXCOORD_0");
  std::vector<ReadVertex> out(model.accessors.at(static_cast<std::size_t>(position)).count);
  for (std::size_t i = 0; i < out.size(); ++i) {
    for (std::size_t k = 0; k < 3; ++k) out[i][k] = scale * accessor_number(model, position, i, static_cast<int>(k));
    for (std::size_t k = 0; k < 3 && normal >= 0; ++k)
      out[i][3 + k] = accessor_number(model, normal, i, static_cast<int>(k));
    for (std::size_t k = 0; k < 2 && uv >= 0; ++k) out[i][6 + k] = accessor_number(model, uv, i, static_cast<int>(k));
  }
  return out;
}

/// The primitive's indices.
inline std::vector<std::uint32_t> read_indices(const tinygltf::Model& model, const tinygltf::Primitive& p) {
  std::vector<std::uint32_t> out(model.accessors.at(static_cast<std::size_t>(p.indices)).count);
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = static_cast<std::uint32_t>(accessor_number(model, p.indices, i, 0));
  return out;
}

/// The primitive's triangles, each rotated to start at its least vertex, sorted; positions times
/// `scale`.
inline std::vector<ReadTriangle> read_triangles(const tinygltf::Model& model, const tinygltf::Primitive& p,
                                                double scale = 1.0) {
  const std::vector<ReadVertex> vertices = read_vertices(model, p, scale);
  const std::vector<std::uint32_t> indices = read_indices(model, p);
  std::vector<ReadTriangle> out;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    out.push_back(canonical({vertices.at(indices[t]), vertices.at(indices[t + 1]), vertices.at(indices[t + 2])}));
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// The triangles a glb of `mesh` should hold (v flipped, as glTF has it), sorted.
inline std::vector<ReadTriangle> mesh_triangles(const Mesh& mesh) {
  const bool normals = mesh.normals.size() == mesh.positions.size();
  const bool uvs = !mesh.uvs.empty() && mesh.uvs.size() == mesh.positions.size();
  std::vector<ReadTriangle> out;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    ReadTriangle triangle;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t i = mesh.indices[t + k];
      const glm::vec3& q = mesh.positions[i];
      const glm::vec3 n = normals ? mesh.normals[i] : glm::vec3(0.0f);
      const glm::vec2 uv = uvs ? glm::vec2(mesh.uvs[i].x, 1.0f - mesh.uvs[i].y) : glm::vec2(0.0f);
      triangle[k] = {q.x, q.y, q.z, n.x, n.y, n.z, uv.x, uv.y};
    }
    out.push_back(canonical(triangle));
  }
  std::sort(out.begin(), out.end());
  return out;
}

/// True when the index buffer uses vertices in order: index i's first use before index i + 1's
/// (what meshopt_optimizeVertexFetch leaves).
inline bool in_fetch_order(const std::vector<std::uint32_t>& indices) {
  std::uint32_t next = 0;
  for (const std::uint32_t i : indices) {
    if (i > next) return false;
    if (i == next) ++next;
  }
  return true;
}

}  // namespace sweep::test
