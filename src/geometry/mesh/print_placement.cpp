#include "geometry/mesh/print_placement.hpp"

#include "base/precondition.hpp"

#include <glm/common.hpp>

#include <limits>

namespace sweep {

PrintPlacement place_on_plate(std::span<const Mesh* const> meshes, double height_mm) {
  SWEEP_EXPECTS(height_mm >= 0.0, "height_mm >= 0");
  PrintPlacement placement;
  glm::dvec3 low(std::numeric_limits<double>::max());
  glm::dvec3 high(std::numeric_limits<double>::lowest());
  for (const Mesh* mesh : meshes) {
    for (const glm::vec3& p : mesh->positions) {
      const glm::dvec3 q = placed(placement, p);  // scale 1, no offset: z up
      low = glm::min(low, q);
      high = glm::max(high, q);
    }
  }
  if (low.x > high.x) return placement;
  if (height_mm > 0.0 && high.z > low.z) placement.scale = height_mm / (high.z - low.z);
  const glm::dvec3 centre = 0.5 * (low + high) * placement.scale;
  placement.offset = {-centre.x, -centre.y, -low.z * placement.scale};
  placement.size = (high - low) * placement.scale;
  return placement;
}

glm::dvec3 placed(const PrintPlacement& placement, const glm::vec3& p) {
  return placement.scale * glm::dvec3(p.x, -p.z, p.y) + placement.offset;
}

glm::dvec3 unplaced(const PrintPlacement& placement, const glm::dvec3& q) {
  const glm::dvec3 r = (q - placement.offset) / placement.scale;
  return {r.x, r.z, -r.y};
}

}  // namespace sweep
