#pragma once
// Reading a Wavefront OBJ polygon mesh as one `mesh` object (a subdivision cage). Every problem is
// one ImportError, a single line that starts with the file's name; nothing is half-built.
#include "io/files/import_file.hpp"
#include "model/document.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace sweep::io {

/// Largest number of vertices of one OBJ face (tinyobjloader keeps face sizes in a byte).
inline constexpr int kMaxObjFaceVertices = 255;

/// The polygons of OBJ text as a `mesh` object named `name`: every vertex ('v' line) in file order,
/// every face ('f' line) of every group and object in file order, its indices copied in order
/// (OBJ and SWP faces both run counterclockwise seen from outside) and made 0-based; normals,
/// texture coordinates, lines, points and materials are ignored. The result passes check_cage and
/// the parser's caps, so its SWP text reads back. `file_name` is only used in messages
/// ("FILE:LINE: ..." or "FILE: ..."; faces and vertices are named 1-based, as in the file).
/// Precondition: is_valid_object_name(name) (else std::invalid_argument). Throws ImportError.
Object parse_obj_cage(const std::string& text, std::string_view file_name, const std::string& name);

/// Reads the OBJ file at `path` (at most limits::kMaxFileBytes) and parses it with
/// parse_obj_cage, named in messages as `path` is spelled. Throws ImportError.
Object import_obj_cage(const std::filesystem::path& path, const std::string& name);

/// A valid object name made from the file name's stem: characters a name may not have become '_',
/// and a '_' goes in front unless it starts with a letter or '_' ("2 cubes.obj" gives "_2_cubes");
/// cut to limits::kMaxNameLength bytes.
std::string object_name_from_path(const std::filesystem::path& path);

}  // namespace sweep::io
