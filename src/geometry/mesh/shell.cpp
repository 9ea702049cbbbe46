#include "geometry/mesh/shell.hpp"

#include "geometry/mesh/weld.hpp"

#include <glm/geometric.hpp>

namespace sweep {

Shell welded_shell(const Mesh& mesh, const PrintPlacement& placement) {
  std::vector<glm::dvec3> points;
  points.reserve(mesh.positions.size());
  for (const glm::vec3& p : mesh.positions) points.push_back(placed(placement, p));
  const std::vector<std::uint32_t> first = weld_points(points, kPrintWeldMillimetres);
  Shell shell;
  std::vector<std::uint32_t> number(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (first[i] != i) {
      number[i] = number[first[i]];
      continue;
    }
    number[i] = static_cast<std::uint32_t>(shell.positions.size());
    shell.positions.push_back(points[i]);
  }
  shell.indices.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = number[mesh.indices[t]];
    const std::uint32_t b = number[mesh.indices[t + 1]];
    const std::uint32_t c = number[mesh.indices[t + 2]];
    if (a == b || b == c || c == a) continue;
    shell.indices.insert(shell.indices.end(), {a, b, c});
  }
  return shell;
}

std::size_t zero_area_triangles(const Shell& shell) {
  const auto stored = [&shell](std::uint32_t i) { return glm::dvec3(glm::vec3(shell.positions[i])); };
  std::size_t count = 0;
  for (std::size_t t = 0; t + 2 < shell.indices.size(); t += 3) {
    const glm::dvec3 a = stored(shell.indices[t]);
    const glm::dvec3 n = glm::cross(stored(shell.indices[t + 1]) - a, stored(shell.indices[t + 2]) - a);
    if (n == glm::dvec3(0.0)) ++count;
  }
  return count;
}

}  // namespace sweep
