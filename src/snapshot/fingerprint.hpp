#pragma once
// What Sweep knows of each named object at render time, kept in a reference's sidecar so a later
// run can say which object changed and how: its evaluated geometry's counts, bounding box,
// centroid, a hash of every position and a few sample points, its material, and how many pixels
// it covers in the case's picture (the object-id pass).
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "snapshot/object_ids.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::snapshot {

/// Sample points per object: evenly spaced by vertex (or curve sample) index.
inline constexpr std::size_t kFingerprintSamples = 32;

struct Fingerprint {
  std::string name;  // display_name: the object's name, or e.g. "bez2#0"
  std::string kind;  // its keyword ("srev", "bez2", ...)
  bool surface = false;
  std::size_t vertices = 0;   // mesh vertices, or curve samples
  std::size_t triangles = 0;  // surfaces only
  glm::dvec3 box_min{0.0};
  glm::dvec3 box_max{0.0};
  glm::dvec3 centroid{0.0};  // mean of the positions
  /// FNV-1a of every position rounded to 1e-6 model units, and of the indices: equal hashes mean
  /// the geometry did not move by more than that.
  std::uint64_t hash = 0;
  std::vector<glm::dvec3> samples;
  std::string material;      // "" for curves; "default" or "NAME rgb(...) shininess ..." for surfaces
  std::size_t coverage = 0;  // pixels in the case's picture
  int scene_index = -1;      // its index in the scene (not kept in sidecars)

  bool same_geometry(const Fingerprint& other) const { return hash == other.hash && vertices == other.vertices; }
};

/// Every curve, surface and rider of `doc` (drawn or not; materials are in their surfaces'), in document order, with
/// its coverage in `ids`. `image_folder` resolves the materials' images (their names, not their pixels, are
/// fingerprinted). Precondition: scene evaluated from doc.
std::vector<Fingerprint> fingerprints(const Document& doc, const Scene& scene, const IdMap& ids,
                                      const std::filesystem::path& image_folder);

/// `ids` (scene indices + 1) relabelled to indices into `objects` + 1 (0 for anything else), as
/// sidecars keep them.
IdMap relabel(const IdMap& ids, const std::vector<Fingerprint>& objects);

}  // namespace sweep::snapshot
