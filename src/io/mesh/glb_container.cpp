#include "io/mesh/detail/glb_container.hpp"

#include <tiny_gltf.h>

#include <sstream>
#include <stdexcept>
#include <utility>

namespace sweep::io::mesh_detail {
namespace {

/// Appends `value` as 4 little-endian bytes.
void append_u32(std::string& out, std::size_t value) {
  for (int shift = 0; shift < 32; shift += 8) out.push_back(static_cast<char>((value >> shift) & 0xFF));
}

/// The bytes before the BIN chunk's data: the header, the JSON chunk and the BIN chunk's header.
std::string glb_head(const GlbChunks& chunks) {
  const std::size_t bin = (chunks.bin.size() + 3) / 4 * 4;
  std::string head = "glTF";
  append_u32(head, 2);
  append_u32(head, 12 + 8 + chunks.json.size() + (bin > 0 ? 8 + bin : 0));
  append_u32(head, chunks.json.size());
  append_u32(head, 0x4E4F534A);  // "JSON"
  head += chunks.json;
  if (bin == 0) return head;
  append_u32(head, bin);
  append_u32(head, 0x004E4942);  // "BIN\0"
  return head;
}

/// The BIN chunk's padding: zeros up to a multiple of 4 bytes.
std::size_t bin_padding(const GlbChunks& chunks) {
  return (4 - chunks.bin.size() % 4) % 4;
}

}  // namespace

GlbChunks glb_chunks(tinygltf::Model model) {
  GlbChunks chunks;
  if (!model.buffers.empty()) chunks.bin = std::move(model.buffers[0].data);
  model.buffers.clear();
  std::ostringstream text;
  tinygltf::TinyGLTF writer;
  if (!writer.WriteGltfSceneToStream(&model, text, false, false)) throw std::runtime_error("tinygltf wrote no JSON");
  chunks.json = std::move(text).str();
  while (!chunks.json.empty() && chunks.json.back() != '}') chunks.json.pop_back();  // its newline
  if (chunks.json.empty()) throw std::runtime_error("tinygltf wrote no JSON object");
  if (!chunks.bin.empty()) {
    chunks.json.pop_back();
    chunks.json += ",\"buffers\":[{\"byteLength\":" + std::to_string(chunks.bin.size()) + "}]}";
  }
  chunks.json.resize((chunks.json.size() + 3) / 4 * 4, ' ');
  return chunks;
}

bool write_chunks(std::FILE* file, const GlbChunks& chunks) {
  const std::string head = glb_head(chunks);
  const char zeros[4] = {};
  const std::size_t padding = bin_padding(chunks);
  // No BIN chunk when the model has no bytes (its data() may then be null, which fwrite refuses).
  return std::fwrite(head.data(), 1, head.size(), file) == head.size() &&
         (chunks.bin.empty() || std::fwrite(chunks.bin.data(), 1, chunks.bin.size(), file) == chunks.bin.size()) &&
         std::fwrite(zeros, 1, padding, file) == padding;
}

}  // namespace sweep::io::mesh_detail
