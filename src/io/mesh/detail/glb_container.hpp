#pragma once
// The GLB container (glTF 2.0, "GLB File Format Specification") around a glTF document: a
// 12-byte header, the JSON chunk and the BIN chunk. Internal to io/mesh: gltf_writer.cpp builds
// the document, this writes it out. Its bytes go out from where the model put them, not copied
// by tinygltf (as its binary writer does) or through a stream.
#include <cstdio>
#include <string>
#include <vector>

namespace tinygltf {
class Model;
}

namespace sweep::io::mesh_detail {

/// A .glb's two chunks: the JSON text, padded with spaces to a multiple of 4 bytes, and the one
/// buffer's bytes (the BIN chunk).
struct GlbChunks {
  std::string json;
  std::vector<unsigned char> bin;
};

/// Takes the bytes out of `model` and serializes the rest (tinygltf writes the JSON); the buffer
/// the bytes make is declared in the JSON by its length, as the object's last member (none when
/// there are no bytes: a buffer holds at least one). Throws std::runtime_error when tinygltf
/// writes no JSON object.
GlbChunks glb_chunks(tinygltf::Model model);

/// Writes the .glb of `chunks` to `file`; false when a write fails.
bool write_chunks(std::FILE* file, const GlbChunks& chunks);

}  // namespace sweep::io::mesh_detail
