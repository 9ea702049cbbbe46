#pragma once
// The object-id pass of a snapshot: which scene object each pixel shows, rasterized on the CPU
// from the same draw list and camera as the picture (no GL, so it is the same on every machine
// and for every renderer). Surfaces are filled triangles with a depth test; curves, control
// polygons and riders' models are drawn as they are in the picture's mode. Attribution counts a
// differing pixel against the objects it shows in the reference and now.
#include "render/camera.hpp"
#include "render/draw_list.hpp"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweep::snapshot {

/// 0: background; i + 1: scene object i. Rows top to bottom, like render::Image.
struct IdMap {
  int width = 0;
  int height = 0;
  std::vector<std::uint16_t> ids;

  std::uint16_t at(int x, int y) const {
    return ids[static_cast<std::size_t>(y) * std::size_t(width) + std::size_t(x)];
  }
  /// Pixels showing scene object `index`.
  std::size_t coverage(int index) const;
};

/// What the id pass draws, as the picture's mode does.
struct IdPassContent {
  bool surfaces = true;         // smooth and wire modes
  bool curves = true;           // every mode
  bool control_points = false;  // frames mode
};

/// Rasterizes `list` seen by `camera` into a `size` map.
/// Preconditions: list.scene set; size.x, size.y in [1, 16384]; at most 65,534 scene objects.
IdMap object_ids(const render::DrawList& list, const render::Camera& camera, glm::ivec2 size,
                 const IdPassContent& content);

}  // namespace sweep::snapshot
