#pragma once
// 3MF output for 3D printing (issue 58), through lib3mf: one file of every printable surface,
// in millimetres, z up, the whole model standing on the plate as one object.
#include "geometry/mesh/mesh.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <span>
#include <string>

namespace sweep {

/// One object of a print: a surface's mesh, its name and its base colour (0..1 RGB).
struct PrintObject {
  std::string name;
  const Mesh* mesh = nullptr;
  glm::vec3 color{0.8f};
};

/// Where a model goes on the plate. A model position p (y up) becomes the millimetres
/// scale * (p.x, -p.z, p.y) + offset (z up; a rotation, so triangles keep their orientation),
/// with the lowest point at z = 0 and the bounding box centred over x = y = 0.
struct PrintPlacement {
  double scale = 1.0;      // millimetres per model unit
  glm::dvec3 offset{0.0};  // millimetres
  glm::dvec3 size{0.0};    // the placed model's extent in x, y, z (millimetres)
};

/// The placement of `objects` together: scale 1 (1 model unit = 1 mm) when `height_mm` is 0,
/// else the scale that makes the model `height_mm` tall. Precondition: height_mm >= 0, every mesh
/// finite; a model with no vertex gets scale 1 and no offset.
PrintPlacement place_on_plate(std::span<const PrintObject> objects, double height_mm);

/// `p` placed: scale * (p.x, -p.z, p.y) + offset.
glm::dvec3 placed(const PrintPlacement& placement, const glm::vec3& p);

/// Writes the 3MF file: unit millimetre, one mesh object named `name` holding every entry's
/// placed vertices and triangles (one model on the plate, its parts where they belong: a slicer
/// would drop separate objects to the plate or leave them floating), one build item with the
/// identity transform, and per entry a base material named after it in its colour, which its
/// triangles carry. Throws std::runtime_error naming the path when lib3mf cannot.
void save_3mf_file(const std::filesystem::path& path, std::span<const PrintObject> objects,
                   const PrintPlacement& placement, const std::string& name);

}  // namespace sweep
