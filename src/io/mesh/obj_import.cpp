// Importing a Wavefront OBJ polygon mesh as a `mesh` object.
//
// tinyobjloader reads the faces: the index forms v, v/vt, v//vn and v/vt/vn, negative (relative)
// indices, groups and objects. A scan of our own over the same lines comes first, because
//  - the caps must hold before tinyobjloader allocates anything;
//  - tinyobjloader's number parser is not correctly rounded (about half of all shortest round-trip
//    numbers come back an ulp off) and reads "nan" or "abc" as 0, so positions are read here, with
//    std::from_chars;
//  - tinyobjloader drops a face of fewer than 3 vertices with only a warning, keeps the size of one
//    of more than 255 in a byte, and messages need each face's line.
#include "io/mesh/obj_import.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "model/file_limits.hpp"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace sweep::io {
namespace {

bool is_blank(char c) {
  return c == ' ' || c == '\t';
}

/// The lines of OBJ text as tinyobjloader sees them (its safeGetline): ended by "\n", "\r\n" or
/// "\r", each cut at its first NUL byte (it reads a line as a C string), numbered from 1.
class ObjLines {
 public:
  explicit ObjLines(std::string_view text) : text_(text) {}

  /// The next line, without its end; false after the last.
  bool next(std::string_view& line) {
    if (at_ >= text_.size()) return false;
    const std::size_t end = std::min(text_.find_first_of("\r\n", at_), text_.size());
    line = text_.substr(at_, end - at_);
    line = line.substr(0, line.find('\0'));
    at_ = end;
    if (at_ < text_.size()) at_ += text_.compare(at_, 2, "\r\n") == 0 ? 2 : 1;
    ++number_;
    return true;
  }
  /// The 1-based number of the line `next` returned last.
  int number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t at_ = 0;
  int number_ = 0;
};

/// What follows `keyword` on a line that starts with it and a blank (after leading blanks), which
/// is how tinyobjloader tells 'v' and 'f' lines; nullopt for other lines.
std::optional<std::string_view> after_keyword(std::string_view line, char keyword) {
  const std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string_view::npos || line.size() - start < 2 || line[start] != keyword ||
      !is_blank(line[start + 1])) {
    return std::nullopt;
  }
  return line.substr(start + 2);
}

/// Cuts the next blank-separated word off the front of `text`; empty when none is left.
std::string_view next_word(std::string_view& text) {
  const std::size_t start = std::min(text.find_first_not_of(" \t"), text.size());
  const std::size_t end = std::min(text.find_first_of(" \t", start), text.size());
  const std::string_view word = text.substr(start, end - start);
  text.remove_prefix(end);
  return word;
}

/// Drops one leading '+' from a number (tinyobjloader allows it, std::from_chars does not).
std::string_view without_plus(std::string_view word) {
  if (word.size() > 1 && word[0] == '+' && word[1] != '+' && word[1] != '-') word.remove_prefix(1);
  return word;
}

/// A coordinate: a decimal number from -kMaxCoordinate to kMaxCoordinate; nullopt for anything
/// else ("nan" and "inf" included).
std::optional<double> coordinate(std::string_view word) {
  word = without_plus(word);
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value) ||
      std::abs(value) > limits::kMaxCoordinate) {
    return std::nullopt;
  }
  return value;
}

/// The vertex part of a face corner ("-3" of "-3/1/2").
std::string_view vertex_part(std::string_view corner) {
  return corner.substr(0, corner.find('/'));
}

std::string in_quotes(std::string_view text) {
  // Appended to rather than "'" + ...: for that, GCC 12 warns of an overlapping copy that is not there.
  std::string quoted(1, '\'');
  quoted += printable_excerpt(text, 40);
  quoted += '\'';
  return quoted;
}

/// "face 3" for the 0-based face 2, as check_cage names faces.
std::string face_name(std::size_t face) {
  return "face " + std::to_string(face + 1);
}

/// What the scan reads: the positions, and the line of every face.
struct ObjScan {
  std::vector<glm::dvec3> points;
  std::vector<int> face_lines;
  std::int64_t corners = 0;
};

ObjScan scan_obj(std::string_view text, std::string_view file) {
  ObjScan scan;
  ObjLines lines(text);
  // What the SWP parser allows a document: points and face corners count alike.
  const auto check_total = [&] {
    const std::int64_t total = static_cast<std::int64_t>(scan.points.size()) + scan.corners;
    if (total > limits::kMaxControlPoints) {
      import_failure(file, lines.number(),
                     "expected at most " + std::to_string(limits::kMaxControlPoints) +
                         " vertices and face corners in all, found " + std::to_string(total) + " by this line");
    }
  };
  std::string_view line;
  while (lines.next(line)) {
    if (std::optional<std::string_view> rest = after_keyword(line, 'v')) {
      const std::string vertex = "vertex " + std::to_string(scan.points.size() + 1);
      glm::dvec3 point(0.0);
      for (int axis = 0; axis < 3; ++axis) {
        const std::string_view word = next_word(*rest);
        if (word.empty()) {
          import_failure(file, lines.number(),
                         "expected 3 coordinates (x y z) of " + vertex + ", found " + std::to_string(axis));
        }
        const std::optional<double> value = coordinate(word);
        if (!value) {
          import_failure(file, lines.number(),
                         "expected a number from -1e12 to 1e12 as " + std::string(1, "xyz"[axis]) + " of " + vertex +
                             ", found " + in_quotes(word));
        }
        point[axis] = *value;
      }
      scan.points.push_back(point);
      check_total();
    } else if (std::optional<std::string_view> corners = after_keyword(line, 'f')) {
      const std::size_t face = scan.face_lines.size();
      std::int64_t size = 0;
      for (std::string_view word = next_word(*corners); !word.empty(); word = next_word(*corners)) {
        // tinyobjloader reads an index with atoi, which wraps one that does not fit.
        const std::string_view index = without_plus(vertex_part(word));
        int value = 0;
        if (std::from_chars(index.data(), index.data() + index.size(), value).ec == std::errc::result_out_of_range) {
          import_failure(
              file, lines.number(),
              std::string("expected a vertex index in ") + face_name(face) + ", found " + in_quotes(vertex_part(word)));
        }
        ++size;
      }
      if (size < 3) {
        import_failure(file, lines.number(),
                       "expected at least 3 vertices in " + face_name(face) + ", found " + std::to_string(size));
      }
      if (size > kMaxObjFaceVertices) {
        import_failure(file, lines.number(),
                       "expected at most " + std::to_string(kMaxObjFaceVertices) + " vertices in " + face_name(face) +
                           " (tinyobjloader's limit), found " + std::to_string(size));
      }
      scan.face_lines.push_back(lines.number());
      scan.corners += size;
      check_total();
    }
  }
  return scan;
}

/// Why corner `corner` of face `face` (0-based), on line `line_number`, names no vertex: tinyobjloader
/// resolved its index to the 0-based `resolved`, and the file has `count` vertices.
std::string index_problem(std::string_view text, int line_number, std::size_t face, int corner, int resolved,
                          int count) {
  ObjLines lines(text);
  std::string_view line;
  while (lines.next(line) && lines.number() < line_number) {
  }
  std::string_view rest = after_keyword(line, 'f').value_or(std::string_view());
  std::string_view word;
  for (int k = 0; k <= corner; ++k) word = next_word(rest);
  const std::string_view index = vertex_part(word);
  const std::string found = ", found " + in_quotes(index);
  std::int64_t value = 0;
  (void)std::from_chars(index.data(), index.data() + index.size(), value);
  if (value >= 0) {
    return "expected a vertex index from 1 to " + std::to_string(count) + " in " + face_name(face) + found;
  }
  // tinyobjloader resolves a relative index against the vertices read before its line.
  const std::int64_t before = resolved - value;
  if (before <= 0) return "expected a vertex ('v' line) before the relative vertex index in " + face_name(face) + found;
  return "expected a relative vertex index from -1 to -" + std::to_string(before) + " in " + face_name(face) + found;
}

/// One line of tinyobjloader's message.
std::string one_line(std::string message) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  std::replace(message.begin(), message.end(), '\r', ' ');
  const std::size_t end = message.find_last_not_of(' ');
  message.erase(end == std::string::npos ? 0 : end + 1);
  return message.empty() ? "tinyobjloader cannot read it" : message;
}

}  // namespace

Object parse_obj_cage(const std::string& text, std::string_view file, const std::string& name) {
  if (!is_valid_object_name(name)) {
    throw std::invalid_argument("expected a valid object name, found " + in_quotes(name));
  }
  ObjScan scan = scan_obj(text, file);

  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From a string with empty MTL text, so `mtllib` never opens a file. Its warnings are dropped:
  // they are about materials, which are ignored, or about indices, which are checked below.
  if (!reader.ParseFromString(text, "", config)) import_failure(file, 0, one_line(reader.Error()));
  if (reader.GetAttrib().vertices.size() != 3 * scan.points.size()) {  // as for the faces below
    import_failure(file, 0,
                   "tinyobjloader reads " + std::to_string(reader.GetAttrib().vertices.size() / 3) +
                       " vertices where the file has " + std::to_string(scan.points.size()) + " 'v' lines");
  }
  if (scan.points.empty()) import_failure(file, 0, "expected at least one vertex ('v' line)");
  if (scan.face_lines.empty()) import_failure(file, 0, "expected at least one face ('f' line)");

  // Every shape's faces, in file order. The indices go in 1-based, as OBJ numbers vertices, behind
  // a placeholder point 0, so that check_cage's messages name vertices as the file does.
  Cage cage;
  cage.face_sizes.reserve(scan.face_lines.size());
  cage.face_vertices.reserve(static_cast<std::size_t>(scan.corners));
  const auto count = static_cast<int>(scan.points.size());
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    const std::vector<tinyobj::index_t>& indices = shape.mesh.indices;
    std::size_t at = 0;
    for (const unsigned char size : shape.mesh.num_face_vertices) {
      const std::size_t face = cage.face_sizes.size();
      if (face >= scan.face_lines.size() || at + size > indices.size()) break;
      for (int k = 0; k < size; ++k) {
        const int vertex = indices[at + static_cast<std::size_t>(k)].vertex_index;
        if (vertex < 0 || vertex >= count) {
          import_failure(file, scan.face_lines[face],
                         index_problem(text, scan.face_lines[face], face, k, vertex, count));
        }
        cage.face_vertices.push_back(vertex + 1);
      }
      cage.face_sizes.push_back(size);
      at += size;
    }
  }
  if (cage.face_sizes.size() != scan.face_lines.size() ||
      static_cast<std::int64_t>(cage.face_vertices.size()) != scan.corners) {
    // Not expected to happen: the scan reads 'f' lines as tinyobjloader does.
    import_failure(file, 0,
                   "tinyobjloader reads " + std::to_string(cage.face_sizes.size()) + " faces with " +
                       std::to_string(cage.face_vertices.size()) + " corners where the file has " +
                       std::to_string(scan.face_lines.size()) + " 'f' lines with " + std::to_string(scan.corners));
  }
  cage.points = std::move(scan.points);
  cage.points.insert(cage.points.begin(), glm::dvec3(0.0));
  if (const std::optional<CageProblem> problem = check_cage(cage)) {
    const auto face = static_cast<std::size_t>(problem->face);
    import_failure(file, scan.face_lines[face], problem->expected);
  }

  Object mesh;
  mesh.set_kind(ObjectKind::PolygonMesh);
  mesh.name = name;
  cage.points.erase(cage.points.begin());
  mesh.as<PointsPart>().points = std::move(cage.points);
  for (int& vertex : cage.face_vertices) --vertex;
  mesh.as<PolygonMeshSurface>().face_sizes = std::move(cage.face_sizes);
  mesh.as<PolygonMeshSurface>().face_vertices = std::move(cage.face_vertices);
  return mesh;
}

Object import_obj_cage(const std::filesystem::path& path, const std::string& name) {
  return parse_obj_cage(read_import_file(path, "an OBJ file"), path.string(), name);
}

std::string object_name_from_path(const std::filesystem::path& path) {
  const std::string stem = path.stem().string();
  std::string name;
  if (stem.empty() || (!std::isalpha(static_cast<unsigned char>(stem[0])) && stem[0] != '_')) name += '_';
  for (const char c : stem) {
    const bool allowed = std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
    name += allowed ? c : '_';
  }
  if (name.size() > limits::kMaxNameLength) name.resize(limits::kMaxNameLength);
  return name;
}

}  // namespace sweep::io
