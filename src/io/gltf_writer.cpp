#include "io/gltf_writer.hpp"

#include "geometry/precondition.hpp"
#include "io/atomic_file.hpp"
#include "io/obj_writer.hpp"

#include <tiny_gltf.h>
#include <glm/common.hpp>
#include <glm/vec4.hpp>

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

/// An empty model: asset, one buffer with room for `bytes`.
tinygltf::Model empty_model(const std::string& generator, std::size_t bytes) {
  tinygltf::Model model;
  model.asset.version = "2.0";
  model.asset.generator = generator;
  model.buffers.emplace_back();
  model.buffers[0].data.reserve(bytes);
  return model;
}

/// The buffer bytes a mesh and its texture take, give or take alignment.
std::size_t mesh_bytes(const Mesh& mesh, const MaterialImages& images) {
  return mesh.positions.size() * 24 + mesh.uvs.size() * 8 + mesh.indices.size() * 4 + images.texture.size() + 16;
}

/// Adds `mesh` named `name` with its material as a glTF mesh of one triangle primitive; returns
/// its index, or -1 (nothing added) when it has no triangles.
int add_mesh(tinygltf::Model& model, const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
             const MaterialImages& images) {
  if (mesh.triangle_count() == 0) return -1;
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
  return static_cast<int>(model.meshes.size() - 1);
}

/// Adds a node named `name` showing glTF mesh `mesh` (-1: none) to the model's one scene.
int add_node(tinygltf::Model& model, const std::string& name, int mesh) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh;
  model.nodes.push_back(std::move(node));
  const int index = static_cast<int>(model.nodes.size() - 1);
  if (model.scenes.empty()) model.scenes.emplace_back();
  model.scenes[0].nodes.push_back(index);
  model.defaultScene = 0;
  return index;
}

/// Closes the model: a buffer holds at least one byte, so an empty one goes.
void finish_model(tinygltf::Model& model) {
  if (model.buffers[0].data.empty()) model.buffers.clear();
}

tinygltf::Model gltf_model(const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                           const MaterialImages& images, const std::string& generator) {
  tinygltf::Model model = empty_model(generator, mesh_bytes(mesh, images));
  add_node(model, name, add_mesh(model, mesh, name, material, images));
  finish_model(model);
  return model;
}

/// The key times as floats: the input accessor of an animation (with its min and max, as glTF asks).
int add_key_times(tinygltf::Model& model, const std::vector<double>& times) {
  std::vector<float> values(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    values[k] = static_cast<float>(times[k]);
  }
  const int view = add_view(model, values.data(), values.size() * sizeof(float), 0);
  const int accessor = add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, TINYGLTF_TYPE_SCALAR, values.size());
  model.accessors[static_cast<std::size_t>(accessor)].minValues = {values.front()};
  model.accessors[static_cast<std::size_t>(accessor)].maxValues = {values.back()};
  return accessor;
}

/// A LINEAR sampler from `input` to `output` with a channel driving `path` of `node`.
void add_channel(tinygltf::Animation& animation, int input, int output, int node, const char* path) {
  tinygltf::AnimationSampler sampler;
  sampler.input = input;
  sampler.output = output;
  sampler.interpolation = "LINEAR";
  animation.samplers.push_back(std::move(sampler));
  tinygltf::AnimationChannel channel;
  channel.sampler = static_cast<int>(animation.samplers.size() - 1);
  channel.target_node = node;
  channel.target_path = path;
  animation.channels.push_back(std::move(channel));
}

/// The animation `name` moving `node` through `keys`: translation and rotation channels sharing
/// one input of key times. The node rests at the first key (for readers that do not animate).
void add_animation(tinygltf::Model& model, const std::string& name, int node, const RiderKeys& keys) {
  std::vector<glm::vec3> translations(keys.translations.begin(), keys.translations.end());
  std::vector<glm::vec4> rotations;  // glTF's order: x, y, z, w
  rotations.reserve(keys.rotations.size());
  for (const glm::dquat& q : keys.rotations) rotations.emplace_back(q.x, q.y, q.z, q.w);
  const int input = add_key_times(model, keys.times);
  const int moves = add_vertex_attribute(model, translations, TINYGLTF_TYPE_VEC3);
  const int turns = add_vertex_attribute(model, rotations, TINYGLTF_TYPE_VEC4);
  model.bufferViews[model.accessors[static_cast<std::size_t>(moves)].bufferView].target = 0;
  model.bufferViews[model.accessors[static_cast<std::size_t>(turns)].bufferView].target = 0;
  tinygltf::Animation animation;
  animation.name = name;
  add_channel(animation, input, moves, node, "translation");
  add_channel(animation, input, turns, node, "rotation");
  model.animations.push_back(std::move(animation));
  tinygltf::Node& rest = model.nodes[static_cast<std::size_t>(node)];
  rest.translation = {keys.translations[0].x, keys.translations[0].y, keys.translations[0].z};
  rest.rotation = {rotations[0].x, rotations[0].y, rotations[0].z, rotations[0].w};
}

tinygltf::Model gltf_scene_model(const GlbScene& scene, const std::string& generator) {
  std::size_t bytes = 0;
  for (const GlbSurface& surface : scene.surfaces) bytes += mesh_bytes(*surface.mesh, *surface.images);
  tinygltf::Model model = empty_model(generator, bytes);
  std::vector<int> meshes;
  for (const GlbSurface& surface : scene.surfaces) {
    meshes.push_back(add_mesh(model, *surface.mesh, surface.name, *surface.material, *surface.images));
  }
  for (const GlbNode& node : scene.nodes) {
    const int mesh = node.surface < 0 ? -1 : meshes[static_cast<std::size_t>(node.surface)];
    const int index = add_node(model, node.name, mesh);
    if (node.keys) add_animation(model, node.name, index, *node.keys);
  }
  finish_model(model);
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

/// Writes the model's .glb to `path` atomically.
void write_model(const std::filesystem::path& path, const tinygltf::Model& model) {
  write_file_atomically(path, [&model](std::FILE* file) {
    FileStreamBuffer buffer(file);
    std::ostream out(&buffer);
    return write_glb(out, model);
  });
}

/// The scene's preconditions: surfaces complete, nodes naming one of them, keys whole.
void check_scene(const GlbScene& scene) {
  for (const GlbSurface& surface : scene.surfaces) {
    SWEEP_EXPECTS(surface.mesh && surface.material && surface.images, "every surface has its mesh and look");
  }
  for (const GlbNode& node : scene.nodes) {
    SWEEP_EXPECTS(node.surface >= -1 && node.surface < static_cast<int>(scene.surfaces.size()),
                  "a node shows one of the scene's surfaces or none");
    SWEEP_EXPECTS(
        !node.keys || (!node.keys->times.empty() && node.keys->translations.size() == node.keys->times.size() &&
                       node.keys->rotations.size() == node.keys->times.size()),
        "keys: as many translations and rotations as times, at least one");
    if (!node.keys) continue;
    const std::vector<double>& times = node.keys->times;
    SWEEP_EXPECTS(std::adjacent_find(times.begin(), times.end(),
                                     [](double a, double b) {
                                       return !(static_cast<float>(a) < static_cast<float>(b));
                                     }) == times.end(),
                  "key times strictly increasing as floats");
  }
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
  write_model(path, gltf_model(mesh, name, material, images, generator));
}

void save_glb_scene_file(const std::filesystem::path& path, const GlbScene& scene, const std::string& generator) {
  check_scene(scene);
  for (const GlbSurface& surface : scene.surfaces) {
    if (mesh_is_finite(*surface.mesh)) continue;
    throw std::runtime_error("cannot write " + path.string() + ": surface '" + surface.name +
                             "' has a NaN or infinite coordinate");
  }
  write_model(path, gltf_scene_model(scene, generator));
}

}  // namespace sweep
