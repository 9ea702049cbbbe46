#pragma once
// Wavefront OBJ output: v, vn and f a//a b//b c//c with 1-based indices (a polygon mesh's
// polygons as they are, Mesh::polygon_sizes).
#include "core/mesh.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

namespace sweep {

/// Writes the mesh as OBJ to a stdio stream. Numbers are formatted with std::to_chars into a
/// buffer. Returns false on a write error.
bool write_obj(std::FILE* out, const Mesh& mesh, const std::string& comment = {});

/// OBJ text of the mesh (tests and small meshes).
std::string obj_text(const Mesh& mesh, const std::string& comment = {});

/// Writes the mesh to `path` atomically. Throws std::runtime_error if the mesh holds a NaN or
/// an infinity (nothing is written) or the file cannot be written.
void save_obj_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment = {});

/// True if every position and normal is finite.
bool mesh_is_finite(const Mesh& mesh);

}  // namespace sweep
