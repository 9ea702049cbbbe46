#pragma once
// Where a model goes on a printer's plate: millimetres, z up, standing on the plate (its lowest
// point at z = 0) and centred over it. The 3MF and placed STL exports and the printability
// checks place every surface of a model with one placement.
#include "geometry/mesh/mesh.hpp"

#include <glm/vec3.hpp>

#include <span>

namespace sweep {

/// A model position p (y up) becomes the millimetres scale * (p.x, -p.z, p.y) + offset (z up; a
/// rotation, so triangles keep their orientation).
struct PrintPlacement {
  double scale = 1.0;      // millimetres per model unit
  glm::dvec3 offset{0.0};  // millimetres
  glm::dvec3 size{0.0};    // the placed model's extent in x, y, z (millimetres)
};

/// The placement of `meshes` together: scale 1 (1 model unit = 1 mm) when `height_mm` is 0, else
/// the scale that makes the model `height_mm` tall; the lowest point at z = 0 and the bounding
/// box centred over x = y = 0. Preconditions: height_mm >= 0, every mesh finite. A model with no
/// vertex gets scale 1 and no offset. Linear in the vertices.
PrintPlacement place_on_plate(std::span<const Mesh* const> meshes, double height_mm);

/// `p` placed: scale * (p.x, -p.z, p.y) + offset.
glm::dvec3 placed(const PrintPlacement& placement, const glm::vec3& p);

/// The model position that `placed` puts at the millimetres `q` (its inverse).
glm::dvec3 unplaced(const PrintPlacement& placement, const glm::dvec3& q);

}  // namespace sweep
