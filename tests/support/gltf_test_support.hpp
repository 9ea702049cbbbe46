#pragma once
// Reading back what sweep's glb writer wrote, with tinygltf: an accessor's elements.
#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cstddef>
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

}  // namespace sweep::test
