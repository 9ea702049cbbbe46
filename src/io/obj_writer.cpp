#include "io/obj_writer.hpp"

#include "io/atomic_file.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>

namespace sweep {
namespace {

/// Collects OBJ text in a fixed buffer and hands it to a sink when full: no per-line allocation.
class ObjBuffer {
 public:
  explicit ObjBuffer(std::FILE* out) : out_(out) {}
  ~ObjBuffer() = default;

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
    if (used_ > 0 && ok_) ok_ = std::fwrite(buf_, 1, used_, out_) == used_;
    used_ = 0;
    return ok_;
  }

 private:
  void reserve(std::size_t n) {
    if (used_ + n > sizeof buf_) flush();
  }
  std::FILE* out_;
  char buf_[1 << 16];
  std::size_t used_ = 0;
  bool ok_ = true;
};

void write_vectors(ObjBuffer& b, std::string_view tag, const std::vector<glm::vec3>& vs) {
  for (const auto& v : vs) {
    b.text(tag);
    b.number(v.x);
    b.ch(' ');
    b.number(v.y);
    b.ch(' ');
    b.number(v.z);
    b.ch('\n');
  }
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
  write_vectors(b, "v ", mesh.positions);
  const bool uvs = has_texture_coordinates(mesh);
  if (uvs) {
    for (const glm::vec2& uv : mesh.uvs) {
      b.text("vt ");
      b.number(uv.x);
      b.ch(' ');
      b.number(uv.y);
      b.ch('\n');
    }
  }
  write_vectors(b, "vn ", mesh.normals);
  if (!material.material.empty()) {
    b.text("usemtl ");
    b.text(material.material);
    b.ch('\n');
  }
  // A polygon mesh keeps its polygons; otherwise every triangle is a face. Position, texture
  // coordinate and normal share their index: v//vn, or v/vt/vn with texture coordinates.
  const std::string_view separator = uvs ? "/" : "//";
  const bool polygons = !mesh.polygon_sizes.empty();
  const std::vector<std::uint32_t>& indices = polygons ? mesh.polygon_indices : mesh.indices;
  const std::size_t faces = polygons ? mesh.polygon_sizes.size() : mesh.indices.size() / 3;
  std::size_t corner = 0;
  for (std::size_t f = 0; f < faces; ++f) {
    b.ch('f');
    const std::size_t size = polygons ? mesh.polygon_sizes[f] : 3;
    for (std::size_t k = 0; k < size && corner < indices.size(); ++k, ++corner) {
      const std::uint32_t index = indices[corner] + 1;  // OBJ counts from 1
      b.ch(' ');
      b.number(index);
      b.text(separator);
      if (uvs) {
        b.number(index);
        b.text(separator);
      }
      b.number(index);
    }
    b.ch('\n');
  }
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
