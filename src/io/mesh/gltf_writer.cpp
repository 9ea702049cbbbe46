#include "io/mesh/gltf_writer.hpp"

#include "base/precondition.hpp"
#include "io/files/atomic_file.hpp"
#include "io/mesh/detail/glb_container.hpp"
#include "io/mesh/gltf_vertices.hpp"
#include "io/mesh/obj_writer.hpp"

#include <tiny_gltf.h>
#include <glm/common.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <stdexcept>

namespace sweep::io {
namespace {

using mesh_detail::glb_chunks;
using mesh_detail::GlbChunks;
using mesh_detail::write_chunks;

/// Appends a buffer view of `bytes` bytes (offsets stay 4-byte aligned) and returns its index and
/// where its bytes go; the pointer is valid until the buffer grows again.
std::pair<int, unsigned char*> append_view(tinygltf::Model& model, std::size_t bytes, int target) {
  std::vector<unsigned char>& data = model.buffers[0].data;
  const std::size_t offset = (data.size() + 3) / 4 * 4;
  data.resize(offset + bytes);
  tinygltf::BufferView view;
  view.buffer = 0;
  view.byteOffset = offset;
  view.byteLength = bytes;
  view.target = target;
  model.bufferViews.push_back(std::move(view));
  return {static_cast<int>(model.bufferViews.size() - 1), data.data() + offset};
}

/// Appends `size` bytes from `data` as a new buffer view and returns the view's index.
int add_view(tinygltf::Model& model, const void* data, std::size_t size, int target) {
  const auto [view, bytes] = append_view(model, size, target);
  if (size > 0) std::memcpy(bytes, data, size);
  return view;
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

/// An animation's input or output (a float, or a float VECn, per key), tightly packed.
template <typename T>
int add_key_values(tinygltf::Model& model, const std::vector<T>& values, int type) {
  const int view = add_view(model, values.data(), values.size() * sizeof(T), 0);
  return add_accessor(model, view, TINYGLTF_COMPONENT_TYPE_FLOAT, type, values.size());
}

/// A vertex attribute: `values`, one per vertex of the mesh, written in `order` (mesh/gltf_vertices.hpp)
/// as `type` elements of `component_type` (normalized or not). An element padded to a multiple of
/// 4 bytes (a VEC3 of int16 takes 8) gets its stride in the view.
template <typename T>
int add_vertex_attribute(tinygltf::Model& model, const GpuOrder& order, const std::vector<T>& values, int type,
                         int component_type = TINYGLTF_COMPONENT_TYPE_FLOAT, bool normalized = false) {
  const auto [view, bytes] = append_view(model, order.vertex_count * sizeof(T), TINYGLTF_TARGET_ARRAY_BUFFER);
  reorder_into(order, values.data(), values.size(), sizeof(T), bytes);
  const std::size_t packed = static_cast<std::size_t>(tinygltf::GetComponentSizeInBytes(component_type) *
                                                      tinygltf::GetNumComponentsInType(type));
  if (packed != sizeof(T)) model.bufferViews.back().byteStride = sizeof(T);
  const int accessor = add_accessor(model, view, component_type, type, order.vertex_count);
  model.accessors.back().normalized = normalized;
  return accessor;
}

/// The least and greatest of each of the first three components of the attribute `accessor`
/// wrote (of type T), as its min and max.
template <typename T>
void set_bounds(tinygltf::Model& model, int accessor) {
  tinygltf::Accessor& a = model.accessors[static_cast<std::size_t>(accessor)];
  const tinygltf::BufferView& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
  const unsigned char* bytes = model.buffers[0].data.data() + view.byteOffset;
  glm::dvec3 low(std::numeric_limits<double>::max());
  glm::dvec3 high(std::numeric_limits<double>::lowest());
  for (std::size_t i = 0; i < a.count; ++i) {
    T value;
    std::memcpy(&value, bytes + i * sizeof(T), sizeof(T));
    const glm::dvec3 p(value[0], value[1], value[2]);
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  a.minValues = {low.x, low.y, low.z};
  a.maxValues = {high.x, high.y, high.z};
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

/// Declares KHR_mesh_quantization used and required (readers without it cannot read the vertices).
void require_quantization(tinygltf::Model& model) {
  const std::string name = "KHR_mesh_quantization";
  if (std::find(model.extensionsUsed.begin(), model.extensionsUsed.end(), name) != model.extensionsUsed.end()) return;
  model.extensionsUsed.push_back(name);
  model.extensionsRequired.push_back(name);
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

/// A glTF mesh added to the model: its index (-1: none) and the uniform scale its nodes need (the
/// quantization step of its positions; 1 for floats).
struct AddedMesh {
  int index = -1;
  double scale = 1.0;
};

/// Adds POSITION with its bounds (in the accessor's own numbers); returns the scale its nodes need.
double add_positions(tinygltf::Model& model, tinygltf::Primitive& primitive, const GpuOrder& order, const Mesh& mesh,
                     GlbEncoding encoding) {
  if (encoding == GlbEncoding::Float) {
    const int accessor = add_vertex_attribute(model, order, mesh.positions, TINYGLTF_TYPE_VEC3);
    set_bounds<glm::vec3>(model, accessor);
    primitive.attributes["POSITION"] = accessor;
    return 1.0;
  }
  const QuantizedPositions q = quantize_positions(mesh.positions);
  const int accessor = add_vertex_attribute(model, order, q.values, TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_SHORT);
  set_bounds<std::array<std::int16_t, 4>>(model, accessor);
  primitive.attributes["POSITION"] = accessor;
  return q.step;
}

/// Adds NORMAL and TEXCOORD_0 (v flipped: glTF's v = 0 is the image's top row) when the mesh has
/// one per position.
void add_normals_and_uvs(tinygltf::Model& model, tinygltf::Primitive& primitive, const GpuOrder& order,
                         const Mesh& mesh, GlbEncoding encoding) {
  const bool quantized = encoding == GlbEncoding::Quantized;
  if (mesh.normals.size() == mesh.positions.size()) {
    primitive.attributes["NORMAL"] = quantized
                                         ? add_vertex_attribute(model, order, quantize_normals(mesh.normals),
                                                                TINYGLTF_TYPE_VEC3, TINYGLTF_COMPONENT_TYPE_BYTE, true)
                                         : add_vertex_attribute(model, order, mesh.normals, TINYGLTF_TYPE_VEC3);
  }
  if (!has_texture_coordinates(mesh)) return;
  std::vector<glm::vec2> flipped(mesh.uvs.size());
  std::transform(mesh.uvs.begin(), mesh.uvs.end(), flipped.begin(),
                 [](const glm::vec2& uv) { return glm::vec2(uv.x, 1.0f - uv.y); });
  const auto uvs = quantized ? quantize_uvs(flipped) : std::nullopt;
  primitive.attributes["TEXCOORD_0"] =
      uvs ? add_vertex_attribute(model, order, *uvs, TINYGLTF_TYPE_VEC2, TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT, true)
          : add_vertex_attribute(model, order, flipped, TINYGLTF_TYPE_VEC2);
}

/// Adds `mesh` named `name` with its material as a glTF mesh of one triangle primitive, its
/// triangles and vertices in GPU order; nothing when it has no triangles.
AddedMesh add_mesh(tinygltf::Model& model, const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                   const MaterialImages& images, GlbEncoding encoding) {
  if (mesh.triangle_count() == 0) return {};
  const GpuOrder order = gpu_order(mesh);
  tinygltf::Primitive primitive;
  primitive.mode = TINYGLTF_MODE_TRIANGLES;
  const double scale = add_positions(model, primitive, order, mesh, encoding);
  add_normals_and_uvs(model, primitive, order, mesh, encoding);
  const int indices = add_view(model, order.indices.data(), order.indices.size() * sizeof(std::uint32_t),
                               TINYGLTF_TARGET_ELEMENT_ARRAY_BUFFER);
  primitive.indices =
      add_accessor(model, indices, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, TINYGLTF_TYPE_SCALAR, order.indices.size());
  primitive.material = add_material(model, material, images);
  if (encoding == GlbEncoding::Quantized) require_quantization(model);
  tinygltf::Mesh out;
  out.name = name;
  out.primitives.push_back(std::move(primitive));
  model.meshes.push_back(std::move(out));
  return {static_cast<int>(model.meshes.size() - 1), scale};
}

/// Adds a node named `name` showing `mesh` (index -1: none) to the model's one scene, scaled as
/// the mesh needs.
int add_node(tinygltf::Model& model, const std::string& name, const AddedMesh& mesh) {
  tinygltf::Node node;
  node.name = name;
  node.mesh = mesh.index;
  if (mesh.scale != 1.0) node.scale = {mesh.scale, mesh.scale, mesh.scale};
  model.nodes.push_back(std::move(node));
  const int index = static_cast<int>(model.nodes.size() - 1);
  if (model.scenes.empty()) model.scenes.emplace_back();
  model.scenes[0].nodes.push_back(index);
  model.defaultScene = 0;
  return index;
}

tinygltf::Model gltf_model(const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                           const MaterialImages& images, const GlbOptions& options) {
  tinygltf::Model model = empty_model(options.generator, mesh_bytes(mesh, images));
  add_node(model, name, add_mesh(model, mesh, name, material, images, options.encoding));
  return model;
}

/// The key times as floats: the input accessor of an animation (with its min and max, as glTF asks).
int add_key_times(tinygltf::Model& model, const std::vector<double>& times) {
  std::vector<float> values(times.size());
  for (std::size_t k = 0; k < times.size(); ++k) {
    values[k] = static_cast<float>(times[k]);
  }
  const int accessor = add_key_values(model, values, TINYGLTF_TYPE_SCALAR);
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
  const int moves = add_key_values(model, translations, TINYGLTF_TYPE_VEC3);
  const int turns = add_key_values(model, rotations, TINYGLTF_TYPE_VEC4);
  tinygltf::Animation animation;
  animation.name = name;
  add_channel(animation, input, moves, node, "translation");
  add_channel(animation, input, turns, node, "rotation");
  model.animations.push_back(std::move(animation));
  tinygltf::Node& rest = model.nodes[static_cast<std::size_t>(node)];
  rest.translation = {keys.translations[0].x, keys.translations[0].y, keys.translations[0].z};
  rest.rotation = {rotations[0].x, rotations[0].y, rotations[0].z, rotations[0].w};
}

tinygltf::Model gltf_scene_model(const GlbScene& scene, const GlbOptions& options) {
  std::size_t bytes = 0;
  for (const GlbSurface& surface : scene.surfaces) bytes += mesh_bytes(*surface.mesh, *surface.images);
  tinygltf::Model model = empty_model(options.generator, bytes);
  std::vector<AddedMesh> meshes;
  for (const GlbSurface& surface : scene.surfaces) {
    meshes.push_back(
        add_mesh(model, *surface.mesh, surface.name, *surface.material, *surface.images, options.encoding));
  }
  for (const GlbNode& node : scene.nodes) {
    const AddedMesh mesh = node.surface < 0 ? AddedMesh{} : meshes[static_cast<std::size_t>(node.surface)];
    const int index = add_node(model, node.name, mesh);
    if (node.keys) add_animation(model, node.name, index, *node.keys);
  }
  return model;
}

/// Writes the model's .glb to `path` atomically.
void write_model(const std::filesystem::path& path, tinygltf::Model model) {
  const GlbChunks chunks = glb_chunks(std::move(model));
  write_file_atomically(path, [&chunks](std::FILE* file) { return write_chunks(file, chunks); });
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
                      const MaterialImages& images, const GlbOptions& options) {
  char* data = nullptr;
  std::size_t size = 0;
  std::FILE* memory = ::open_memstream(&data, &size);
  if (!memory) throw std::runtime_error("cannot allocate the glb bytes of " + name);
  const bool written = write_glb(memory, mesh, name, material, images, options);
  std::fclose(memory);
  std::string bytes(data, size);
  std::free(data);
  if (!written) throw std::runtime_error("cannot write the glb bytes of " + name);
  return bytes;
}

bool write_glb(std::FILE* out, const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
               const MaterialImages& images, const GlbOptions& options) {
  SWEEP_EXPECTS(out != nullptr, "out is open for writing");
  return write_chunks(out, glb_chunks(gltf_model(mesh, name, material, images, options)));
}

void save_glb_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& name,
                   const SurfaceMaterial& material, const MaterialImages& images, const GlbOptions& options) {
  if (!mesh_is_finite(mesh)) {
    throw std::runtime_error("cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  write_model(path, gltf_model(mesh, name, material, images, options));
}

void save_glb_scene_file(const std::filesystem::path& path, const GlbScene& scene, const GlbOptions& options) {
  check_scene(scene);
  for (const GlbSurface& surface : scene.surfaces) {
    if (mesh_is_finite(*surface.mesh)) continue;
    throw std::runtime_error("cannot write " + path.string() + ": surface '" + surface.name +
                             "' has a NaN or infinite coordinate");
  }
  write_model(path, gltf_scene_model(scene, options));
}

}  // namespace sweep::io
