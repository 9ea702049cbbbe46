#pragma once
// Binary STL output, what 3D printers' slicers read: an 80-byte header, the triangle count, then
// per triangle its unit facet normal, three vertices and a zero attribute word, little-endian.
#include "geometry/mesh/mesh.hpp"

#include <cstdio>
#include <filesystem>
#include <string>

namespace sweep::io {

/// The STL bytes of the mesh. The header is "sweep binary STL: " and `comment`, cut to 80 bytes
/// and padded with zeros (never starting with "solid", which readers take for ASCII STL). Facet
/// normals are the triangles' geometric ones ((b - a) x (c - a), unit), 0 0 0 if degenerate.
std::string stl_bytes(const Mesh& mesh, const std::string& comment = {});

/// Writes stl_bytes(mesh, comment) to `out`, a whole triangle at a time in 64 KB chunks. Returns
/// false if a write fails.
bool write_stl(std::FILE* out, const Mesh& mesh, const std::string& comment = {});

/// Writes the mesh to `path` atomically (write_stl). Throws std::runtime_error if the mesh holds a NaN or
/// an infinity (nothing is written) or the file cannot be written.
void save_stl_file(const std::filesystem::path& path, const Mesh& mesh, const std::string& comment = {});

}  // namespace sweep::io
