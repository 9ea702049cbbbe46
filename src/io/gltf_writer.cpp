#include "io/gltf_writer.hpp"

#include "io/atomic_file.hpp"
#include "io/obj_writer.hpp"

#include <tiny_gltf.h>
#include <glm/common.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <streambuf>

namespace sweep {
namespace {

/// Appends `size` bytes to the buffer as a new buffer view (offsets stay 4-byte aligned) and
/// returns the view's index.
int add_view(tinygltf::Model& model, const void* data, std::size_t size, int target) {
  std::vector<unsigned char>& bytes = model.buffers[0].data;
  while (bytes.size() % 4 != 0) bytes.push_back(0);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = bytes.size();
  view.byteLength = size;
  view.target = target;
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes.insert(bytes.end(), begin, begin + size);
  model.bufferViews.push_back(std::move(view));
  return static_cast<int>(model.bufferViews.size() - 1);
}

int add_accessor(tinygltf::Model& model, int view, int component_type, int type, std::size_t count) {
  tinygltf::Accessor accessor;
  accessor.bufferView = view;
  accessor.byteOffset = 0;
  accessor.componentType = component_type;
  accessor.type = type;
  accessor.count = count;
  model.accessors.push_back(std::move(accessor));
  return static_cast<int>(model.accessors.size() - 1);
}

template <typename T>
int add_vertex_attribute(tinygltf::Model& model, const std::vector<T>& values, int type) {
  const int view = add_view(model, values.data(), values.size() * sizeof(T), TINYGLTF_TARGET_ARRAY_BUFFER);
  return add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size());
}

/// The double nearest the float's shortest decimal form (0.8f -> 0.8, not 0.800000011920929), so
/// that the JSON says what the SWP file said.
double shortest(float value) {
  char buffer[32];
  const char* end = std::to_chars(buffer, buffer + sizeof buffer, value).ptr;
  double out = 0.0;
  std::from_chars(buffer, end, out);
  return out;
}

int add_material(tinygltf::Model& model, const SurfaceMaterial& material, const MaterialImages& images) {
  tinygltf::Material out;
  out.name = mtl_material_name(material);
  const glm::vec3& c = material.color;
  out.pbrMetallicRoughness.baseColorFactor = {shortest(c.r), shortest(c.g), shortest(c.b), 1.0};
  out.pbrMetallicRoughness.metallicFactor = 0.0;
  out.pbrMetallicRoughness.roughnessFactor = shortest(roughness_from_shininess(material.shininess));
  out.doubleSided = true;
  if (!images.texture.empty()) {
    tinygltf::Image image;
    image.name = material.texture.empty() ? std::filesystem::path(checker_file_name(material.checker)).stem().string()
                                          : material.texture.stem().string();
    image.mimeType = "image/png";
    image.bufferView = add_view(model, images.texture.data(), images.texture.size(), 0);
    model.images.push_back(std::move(image));
    tinygltf::Sampler sampler;
    sampler.magFilter = TINYGLTF_TEXTURE_FILTER_LINEAR;
    sampler.minFilter = TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR;
    sampler.wrapS = TINYGLTF_TEXTURE_WRAP_REPEAT;
    sampler.wrapT = TINYGLTF_TEXTURE_WRAP_REPEAT;
    model.samplers.push_back(std::move(sampler));
    tinygltf::Texture texture;
    texture.source = static_cast<int>(model.images.size() - 1);
    texture.sampler = static_cast<int>(model.samplers.size() - 1);
    model.textures.push_back(std::move(texture));
    out.pbrMetallicRoughness.baseColorTexture.index = static_cast<int>(model.textures.size() - 1);
  }
  model.materials.push_back(std::move(out));
  return static_cast<int>(model.materials.size() - 1);
}

tinygltf::Model gltf_model(const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                           const MaterialImages& images, const std::string& generator) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = generator;
  model.buffers.emplace_back();
  std::size_t bytes = mesh.positions.size() * 24 + mesh.uvs.size() * 8 + mesh.indices.size() * 4;
  bytes += images.texture.size() + 16;
  model.buffers[0].data.reserve(bytes);

  tinygltf::Node node;
  node.name = name;
  if (mesh.triangle_count() > 0) {
    tinygltf::Primitive primitive;
    primitive.mode = TINYGLTF_MODE_TRIANGLES;
    const int position = add_vertex_attribute(model, mesh.positions, TINYGLTF_TYPE_VEC3);
    glm::vec3 low(std::numeric_limits<float>::max());
    glm::vec3 high(std::numeric_limits<float>::lowest());
    for (const glm::vec3& p : mesh.positions) {
      low = glm::min(low, p);
      high = glm::max(high, p);
    }
    model.accessors[static_cast<std::size_t>(position)].minValues = {low.x, low.y, low.z};
    model.accessors[static_cast<std::size_t>(position)].maxValues = {high.x, high.y, high.z};
    primitive.attributes["POSITION"] = position;
    if (mesh.normals.size() == mesh.positions.size()) {
      primitive.attributes["NORMAL"] = add_vertex_attribute(model, mesh.normals, TINYGLTF_TYPE_VEC3);
    }
    if (has_texture_coordinates(mesh)) {
      std::vector<glm::vec2> flipped(mesh.uvs.size());
      std::transform(mesh.uvs.begin(), mesh.uvs.end(), flipped.begin(),
                     [](const glm::vec2& uv) { return glm::vec2(uv.x, 1.0f - uv.y); });
      primitive.attributes["TEXCOORD_0"] = add_vertex_attribute(model, flipped, TINYGLTF_TYPE_VEC2);
    }
    const int indices = add_view(model, mesh.indices.data(), mesh.indices.size() * sizeof(std::uint32_t),
                                 TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
    primitive.indices =
        add_accessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, mesh.indices.size());
    primitive.material = add_material(model, material, images);
    tinygltf::Mesh out;
    out.name = name;
    out.primitives.push_back(std::move(primitive));
    model.meshes.push_back(std::move(out));
    node.mesh = 0;
  }
  model.nodes.push_back(std::move(node));
  if (model.buffers[0].data.empty()) model.buffers.clear();  // a buffer holds at least one byte
  tinygltf::Scene scene;
  scene.nodes.push_back(0);
  model.scenes.push_back(std::move(scene));
  model.defaultScene = 0;
  return model;
}

/// An output stream buffer writing straight to a stdio stream: the .glb goes to the file without
/// a copy of it in memory.
class FileStreamBuffer : public std::streambuf {
 public:
  explicit FileStreamBuffer(std::FILE* file) : file_(file) {}

 protected:
  std::streamsize xsputn(const char* data, std::streamsize size) override {
    return static_cast<std::streamsize>(std::fwrite(data, 1, static_cast<std::size_t>(size), file_));
  }
  int_type overflow(int_type c) override {
    if (traits_type::eq_int_type(c, traits_type::eof())) return traits_type::not_eof(c);
    return std::fputc(traits_type::to_char_type(c), file_) == EOF ? traits_type::eof() : c;
  }

 private:
  std::FILE* file_;
};

bool write_glb(std::ostream& out, const tinygltf::Model& model) {
  tinygltf::TinyGLTF writer;
  return writer.WriteGltfSceneToStream(&model, out, false, true) && out.flush();
}

}  // namespace

float roughness_from_shininess(float shininess) {
  return std::sqrt(2.0f / (shininess + 2.0f));
}

std::string glb_bytes(const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                      const MaterialImages& images, const std::string& generator) {
  const tinygltf::Model model = gltf_model(mesh, name, material, images, generator);
  std::ostringstream out;
  if (!write_glb(out, model)) {
    std::string message = "tinygltf could not write the glTF of ";
    message += name;
    throw std::runtime_error(message);
  }
  return std::move(out).str();
}

void save_glb_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& name,
                   const SurfaceMaterial& material, const MaterialImages& images, const std::string& generator) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  const tinygltf::Model model = gltf_model(mesh, name, material, images, generator);
  write_file_atomically(path, [&model](std::FILE* file) {
    FileStreamBuffer buffer(file);
    std::ostream out(&buffer);
    return write_glb(out, model);
  });
}

}  // namespace sweep
