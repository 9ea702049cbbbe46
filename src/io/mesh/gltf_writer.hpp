#pragma once
// Binary glTF 2.0 (.glb) output of one mesh, written with tinygltf: one scene of one node whose
// mesh has one triangle primitive:
//  - POSITION (float3, with min and max), NORMAL (float3), TEXCOORD_0 (float2, when the mesh has
//    texture coordinates; v flipped, since glTF puts v = 0 at the image's top row and the mesh, as
//    OBJ, at its bottom row) and uint32 indices, each in its own buffer view of the one buffer;
//    triangles and vertices in GPU order (gpu_order, mesh/gltf_vertices.hpp: vertex cache, then
//    vertex fetch; unused vertices left out);
//  - quantized (GlbEncoding::Quantized, KHR_mesh_quantization, required): POSITION as int16 x 4
//    on a grid whose step is the node's uniform scale, NORMAL as normalized int8 x 4, TEXCOORD_0 as
//    normalized uint16 x 2 when it lies in [0, 1] (float otherwise); quantize_* in mesh/gltf_vertices.hpp
//    states each error;
//  - one metallic-roughness material: baseColorFactor the colour (alpha 1), metallic 0, roughness
//    sqrt(2 / (shininess + 2)) (the Blinn-Phong exponent's usual match), double-sided (sweeps are
//    open surfaces seen from both sides, as in the viewer); baseColorTexture the texture or the
//    generated checker, its PNG embedded in the buffer, sampled with repeat. The bump is not
//    exported (glTF has height maps only as normal maps).
// A mesh without triangles gives a node without a mesh.
//
// A scene .glb (save_glb_scene_file) holds several surfaces as above, one glTF mesh each, and
// nodes showing them, in order; a node with keys also gets one animation named after it: LINEAR
// translation and rotation channels sharing one input accessor of the key times (floats).
#include "geometry/mesh/mesh.hpp"
#include "io/mesh/mtl_writer.hpp"
#include "model/evaluation/rider_keys.hpp"
#include "model/material.hpp"

#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::io {

/// How a .glb stores vertex attributes: 32-bit floats, or the smaller quantized integers.
enum class GlbEncoding { Float, Quantized };

/// What a .glb says besides its meshes: asset.generator, and how its vertices are stored.
struct GlbOptions {
  std::string generator = "sweep";
  GlbEncoding encoding = GlbEncoding::Float;
};

/// The roughness matching a Blinn-Phong shininess: sqrt(2 / (shininess + 2)).
float roughness_from_shininess(float shininess);

/// The .glb bytes of `mesh` named `name` with `material` (the texture's PNG bytes from
/// `images.texture`; images.bump is ignored).
std::string glb_bytes(const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
                      const MaterialImages& images, const GlbOptions& options = {});

/// Writes glb_bytes to `out` (what save_glb_file writes, without a copy of the buffer in memory);
/// false when a write fails. Precondition: out is open for writing.
bool write_glb(std::FILE* out, const Mesh& mesh, const std::string& name, const SurfaceMaterial& material,
               const MaterialImages& images, const GlbOptions& options = {});

/// Writes glb_bytes to `path` atomically. Throws std::runtime_error if the mesh holds a NaN or
/// an infinity (nothing is written) or the file cannot be written.
void save_glb_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& name,
                   const SurfaceMaterial& material, const MaterialImages& images, const GlbOptions& options = {});

/// A surface of a scene .glb: its mesh, named `name`, and its look (borrowed).
struct GlbSurface {
  std::string name;
  const Mesh* mesh = nullptr;
  const SurfaceMaterial* material = nullptr;
  const MaterialImages* images = nullptr;  // the texture's PNG bytes; the bump is ignored
};

/// A node of a scene .glb: `surface` indexes GlbScene::surfaces (-1: no mesh); with `keys`
/// (borrowed) the node is animated through them, resting at the first.
struct GlbNode {
  std::string name;
  int surface = -1;
  const RiderKeys* keys = nullptr;
};

struct GlbScene {
  std::vector<GlbSurface> surfaces;  // each written once, however many nodes show it
  std::vector<GlbNode> nodes;
};

/// Writes the scene as one .glb to `path` atomically. Throws std::runtime_error if a mesh holds a
/// NaN or an infinity (nothing is written) or the file cannot be written. Preconditions: every
/// surface has its mesh, material and images; every node's surface is -1 or one of them; every
/// node's keys have as many translations and rotations as times, their times strictly increasing
/// as floats (rider_keys makes them so).
void save_glb_scene_file(const std::filesystem::path& path, const GlbScene& scene, const GlbOptions& options = {});

}  // namespace sweep::io
