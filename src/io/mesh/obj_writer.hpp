#pragma once
// Wavefront OBJ output: v, vt (when the mesh has texture coordinates), vn and faces with 1-based
// indices, f a//a b//b c//c, or f a/a/a b/b/b c/c/c with texture coordinates (a polygon mesh's
// polygons as they are, Mesh::polygon_sizes); optionally `mtllib` and `usemtl` (mesh/mtl_writer.hpp).
#include "geometry/mesh/mesh.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

namespace sweep::io {

/// The material statements of an OBJ file: `mtllib LIBRARY` before the vertices and `usemtl
/// MATERIAL` before the faces. Both empty: none (the file has no material).
struct ObjMaterialLink {
  std::string library;   // the .mtl file name, relative to the OBJ file
  std::string material;  // a `newmtl` name of that library
};

/// True if the mesh has one texture coordinate per position (and at least one): OBJ writes
/// them as vt and references them in its faces.
bool has_texture_coordinates(const Mesh& mesh);

/// Writes the mesh as OBJ to a stdio stream. Numbers are formatted with std::to_chars into a
/// buffer. Returns false on a write error.
bool write_obj(std::FILE* out, const Mesh& mesh, const std::string& comment = {}, const ObjMaterialLink& material = {});

/// OBJ text of the mesh (tests and small meshes).
std::string obj_text(const Mesh& mesh, const std::string& comment = {}, const ObjMaterialLink& material = {});

/// Writes the mesh to `path` atomically. Throws std::runtime_error if the mesh holds a NaN or
/// an infinity (nothing is written) or the file cannot be written.
void save_obj_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment = {},
                   const ObjMaterialLink& material = {});

/// True if every position, normal and texture coordinate is finite.
bool mesh_is_finite(const Mesh& mesh);

}  // namespace sweep::io
