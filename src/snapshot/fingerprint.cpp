#include "snapshot/fingerprint.hpp"

#include "base/fnv1a.hpp"
#include "model/material.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace sweep::snapshot {
namespace {

/// The positions an object shows: its mesh, else its curve's samples, else its rider track.
std::vector<glm::dvec3> positions_of(const EvaluatedObject& object) {
  std::vector<glm::dvec3> out;
  if (!object.mesh.positions.empty()) {
    out.assign(object.mesh.positions.begin(), object.mesh.positions.end());
  } else if (!object.curve.frames.empty()) {
    for (const Frame& frame : object.curve.frames) out.push_back(frame.V);
  } else {
    for (const Frame& frame : object.track.frames) out.push_back(frame.V);
  }
  return out;
}

void measure(Fingerprint& f, const std::vector<glm::dvec3>& points, const std::vector<std::uint32_t>& indices,
             double quantum) {
  f.vertices = points.size();
  f.triangles = indices.size() / 3;
  Fnv1a hash(kShortFnvOffsetBasis);  // the basis stored fingerprints were made with (base/fnv1a.hpp)
  f.hash = hash.value();
  if (points.empty()) return;
  f.box_min = glm::dvec3(std::numeric_limits<double>::infinity());
  f.box_max = -f.box_min;
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : points) {
    f.box_min = glm::min(f.box_min, p);
    f.box_max = glm::max(f.box_max, p);
    sum += p;
    for (int c = 0; c < 3; ++c) {
      const auto q = static_cast<std::int64_t>(std::llround(p[c] / quantum));
      hash.add_bytes(&q, sizeof q);
    }
  }
  f.hash = hash.add_bytes(indices.data(), indices.size() * sizeof(std::uint32_t)).value();
  f.centroid = sum / double(points.size());
  const std::size_t n = std::min(kFingerprintSamples, points.size());
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t index = n == 1 ? 0 : k * (points.size() - 1) / (n - 1);
    f.samples.push_back(points[index]);
  }
}

std::string material_text(const SurfaceMaterial& m) {
  if (m.name.empty()) return "default";
  char text[160];
  std::snprintf(text, sizeof text, " rgb(%.4g, %.4g, %.4g) shininess %.4g checker %d bump %.4g", double(m.color.r),
                double(m.color.g), double(m.color.b), double(m.shininess), m.checker, double(m.bump_height));
  std::string out = m.name + text;
  if (!m.texture.empty()) out += " texture " + m.texture.filename().string();
  if (!m.bump.empty()) out += " bump " + m.bump.filename().string();
  return out;
}

}  // namespace

std::vector<Fingerprint> fingerprints(const Document& doc, const Scene& scene, const IdMap& ids,
                                      const std::filesystem::path& image_folder) {
  // Absolute, so an object's hash does not change when another one grows the scene.
  constexpr double quantum = 1e-6;
  std::vector<Fingerprint> out;
  const std::size_t count = std::min(doc.objects.size(), scene.objects.size());
  for (std::size_t i = 0; i < count; ++i) {
    const Object& object = doc.objects[i];
    if (object.kind() == ObjectKind::Material) continue;  // a surface's material is in its fingerprint
    Fingerprint f;
    f.name = display_name(doc, int(i));
    f.kind = std::string(keyword(object.kind()));
    f.surface = is_surface(object.kind());
    measure(f, positions_of(scene.objects[i]), scene.objects[i].mesh.indices, quantum);
    if (f.surface) f.material = material_text(surface_material(doc, int(i), image_folder));
    f.coverage = ids.ids.empty() ? 0 : ids.coverage(int(i));
    f.scene_index = int(i);
    out.push_back(std::move(f));
  }
  return out;
}

IdMap relabel(const IdMap& ids, const std::vector<Fingerprint>& objects) {
  std::vector<std::uint16_t> label(65536, 0);
  for (std::size_t k = 0; k < objects.size() && k < 65534; ++k) {
    const int scene = objects[k].scene_index;
    if (scene >= 0 && scene < 65534) label[std::size_t(scene) + 1] = static_cast<std::uint16_t>(k + 1);
  }
  IdMap out = ids;
  for (std::uint16_t& id : out.ids) id = label[id];
  return out;
}

}  // namespace sweep::snapshot
