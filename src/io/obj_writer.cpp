#include "io/obj_writer.hpp"

#include "geometry/thread_pool.hpp"
#include "io/atomic_file.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep {
namespace {

/// Collects OBJ text in a fixed buffer and hands it to a sink (a file, or a string for one chunk
/// of a section formatted on another thread) when full: no per-line allocation.
class ObjBuffer {
 public:
  explicit ObjBuffer(std::FILE* out) : out_(out) {}
  explicit ObjBuffer(std::string* text) : text_(text) {}

  void text(std::string_view s) {
    reserve(s.size());
    std::copy(s.begin(), s.end(), buf_ + used_);
    used_ += s.size();
  }
  void number(float v) {
    reserve(32);
    used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + sizeof buf_, v).ptr - buf_);
  }
  void number(std::uint32_t v) {
    reserve(16);
    used_ = static_cast<std::size_t>(std::to_chars(buf_ + used_, buf_ + sizeof buf_, v).ptr - buf_);
  }
  void ch(char c) {
    reserve(1);
    buf_[used_++] = c;
  }
  bool flush() {
    if (used_ > 0 && ok_) {
      if (text_) {
        text_->append(buf_, used_);
      } else {
        ok_ = std::fwrite(buf_, 1, used_, out_) == used_;
      }
    }
    used_ = 0;
    return ok_;
  }
  /// Text of any length, after what is buffered (a chunk formatted on another thread).
  void block(std::string_view s) {
    flush();
    if (s.empty() || !ok_) return;
    if (text_) {
      text_->append(s);
    } else {
      ok_ = std::fwrite(s.data(), 1, s.size(), out_) == s.size();
    }
  }

 private:
  void reserve(std::size_t n) {
    if (used_ + n > sizeof buf_) flush();
  }
  std::FILE* out_ = nullptr;
  std::string* text_ = nullptr;
  char buf_[1 << 16];
  std::size_t used_ = 0;
  bool ok_ = true;
};

/// Items of a section formatted on one thread at a time; a round is a few of these per thread.
constexpr std::size_t kChunkItems = 1 << 15;

/// Writes the lines of items [0, count) through `format(buffer, begin, end)`: on one thread into
/// `b`, or, with more threads and more than one chunk, in rounds of chunks formatted in parallel
/// into strings and written in order, so the bytes are the same whatever the thread count.
template <typename Format>
void write_section(ObjBuffer& b, std::size_t count, int threads, const Format& format) {
  if (threads <= 1 || count <= kChunkItems) {
    format(b, 0, count);
    return;
  }
  const std::size_t round = kChunkItems * 2 * static_cast<std::size_t>(threads);
  std::vector<std::string> texts(2 * static_cast<std::size_t>(threads));
  for (std::size_t start = 0; start < count; start += round) {
    const std::size_t items = std::min(round, count - start);
    parallel_chunks(items, kChunkItems, threads, [&](std::size_t begin, std::size_t end, int) {
      std::string& text = texts[begin / kChunkItems];
      text.clear();
      ObjBuffer chunk(&text);
      format(chunk, start + begin, start + end);
      chunk.flush();
    });
    for (std::size_t i = 0; i * kChunkItems < items; ++i) b.block(texts[i]);
  }
}

void write_vectors(ObjBuffer& b, std::string_view tag, const std::vector<glm::vec3>& vs, int threads) {
  write_section(b, vs.size(), threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      out.text(tag);
      out.number(vs[i].x);
      out.ch(' ');
      out.number(vs[i].y);
      out.ch(' ');
      out.number(vs[i].z);
      out.ch('\n');
    }
  });
}

void write_uvs(ObjBuffer& b, const std::vector<glm::vec2>& uvs, int threads) {
  write_section(b, uvs.size(), threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      out.text("vt ");
      out.number(uvs[i].x);
      out.ch(' ');
      out.number(uvs[i].y);
      out.ch('\n');
    }
  });
}

/// One face's corners [corner, corner + size): " v//vn" each, or " v/vt/vn" with texture
/// coordinates (position, texture coordinate and normal share their index).
void write_face(ObjBuffer& out, const std::vector<std::uint32_t>& indices, std::size_t corner, std::size_t size,
                bool uvs) {
  const std::string_view separator = uvs ? "/" : "//";
  out.ch('f');
  for (std::size_t k = 0; k < size && corner + k < indices.size(); ++k) {
    const std::uint32_t index = indices[corner + k] + 1;  // OBJ counts from 1
    out.ch(' ');
    out.number(index);
    out.text(separator);
    if (uvs) {
      out.number(index);
      out.text(separator);
    }
    out.number(index);
  }
  out.ch('\n');
}

/// A polygon mesh keeps its polygons (written on one thread: their corners are a running sum);
/// otherwise every triangle is a face.
void write_faces(ObjBuffer& b, const Mesh& mesh, bool uvs, int threads) {
  if (!mesh.polygon_sizes.empty()) {
    std::size_t corner = 0;
    for (const std::uint32_t size : mesh.polygon_sizes) {
      write_face(b, mesh.polygon_indices, corner, size, uvs);
      corner += size;
    }
    return;
  }
  write_section(b, mesh.indices.size() / 3, threads, [&](ObjBuffer& out, std::size_t begin, std::size_t end) {
    for (std::size_t f = begin; f < end; ++f) write_face(out, mesh.indices, 3 * f, 3, uvs);
  });
}

}  // namespace

bool has_texture_coordinates(const Mesh& mesh) {
  return !mesh.uvs.empty() && mesh.uvs.size() == mesh.positions.size();
}

bool write_obj(std::FILE* out, const Mesh& mesh, const std::string& comment, const ObjMaterialLink& material) {
  ObjBuffer b(out);
  if (!comment.empty()) {
    b.text("# ");
    b.text(comment);
    b.ch('\n');
  }
  if (!material.library.empty()) {
    b.text("mtllib ");
    b.text(material.library);
    b.ch('\n');
  }
  const int threads = worker_count();
  write_vectors(b, "v ", mesh.positions, threads);
  const bool uvs = has_texture_coordinates(mesh);
  if (uvs) write_uvs(b, mesh.uvs, threads);
  write_vectors(b, "vn ", mesh.normals, threads);
  if (!material.material.empty()) {
    b.text("usemtl ");
    b.text(material.material);
    b.ch('\n');
  }
  write_faces(b, mesh, uvs, threads);
  return b.flush();
}

std::string obj_text(const Mesh& mesh, const std::string& comment, const ObjMaterialLink& material) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&data, &size);
  if (!memory) throw std::runtime_error("cannot allocate OBJ text");
  write_obj(memory, mesh, comment, material);
  std::fclose(memory);
  std::string text(data, size);
  std::free(data);
  return text;
}

bool mesh_is_finite(const Mesh& mesh) {
  auto finite = [](const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
  for (const auto& p : mesh.positions) {
    if (!finite(p)) return false;
  }
  for (const auto& n : mesh.normals) {
    if (!finite(n)) return false;
  }
  for (const auto& uv : mesh.uvs) {
    if (!std::isfinite(uv.x) || !std::isfinite(uv.y)) return false;
  }
  return true;
}

void save_obj_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment,
                   const ObjMaterialLink& material) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  write_file_atomically(path, [&](std::FILE* f) { return write_obj(f, mesh, comment, material); });
}

}  // namespace sweep
