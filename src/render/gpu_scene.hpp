#pragma once
// The GPU copies of a scene's objects (internal to render: renderer.cpp draws from it). Each copy
// follows its EvaluatedObject by revision: a new revision replaces it, and what is drawn only in
// some modes (frames, normal segments, control polygons, nets, curvature colours) is uploaded on
// first use and kept until the revision changes. Needs the GL context current.
#include "render/display_settings.hpp"
#include "render/draw_list.hpp"
#include "render/gpu_buffers.hpp"

#include "geometry/mesh/curvature.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace sweep::render {

/// The GPU copy of one scene object. `revision` is the EvaluatedObject revision it mirrors;
/// decorations are built on first use and remember the revision they were built from.
struct GpuObject {
  std::uint64_t revision = 0;
  GpuArray mesh;         // surfaces
  GpuArray strip;        // curves
  GpuArray decorations;  // frames (curves) or normal segments (surfaces)
  std::uint64_t decorations_revision = 0;
  GpuArray control;  // control points and polygon
  std::uint64_t control_revision = 0;
  GpuArray net;  // a control net or a subd's cage (EvaluatedObject::net)
  std::uint64_t net_revision = 0;
  // Curvature colours: the values (per revision) and the colours uploaded (per mode and range).
  Curvatures curvatures;
  std::uint64_t curvature_revision = 0;
  GLuint colors = 0;
  ColorMode colors_mode = ColorMode::Material;
  float colors_range = 0.0f;

  void release();
};

class GpuScene {
 public:
  /// Brings the copies in line with `scene`: new revisions replace the old copies, and the
  /// scene's radius is measured again when anything changed.
  void sync(const Scene& scene);
  /// Releases every copy.
  void clear();

  std::size_t size() const { return objects_.size(); }
  const GpuObject& operator[](std::size_t i) const { return objects_[i]; }
  /// The scene's bounding radius at the last sync (1 for an empty or a one-point scene).
  double radius() const { return radius_; }
  /// Buffers uploaded since the renderer was made (a test's measure of work not repeated).
  std::uint64_t uploads() const { return uploads_; }

  /// Object i's normal segments (a surface) or frames (a curve), from `source`.
  const GpuArray& decorations(std::size_t i, const EvaluatedObject& source);
  /// Object i's control polygon through `points`.
  const GpuArray& control(std::size_t i, std::span<const glm::dvec3> points);
  /// Object i's control net or cage, from `source`.
  const GpuArray& net(std::size_t i, const EvaluatedObject& source);
  /// The curvature colours (Gaussian or Mean `mode`) of the surfaces `list` shades or rides: one
  /// symmetric range over them all, then each surface's colours, uploaded again only when its
  /// revision, the mode or the range changed. Returns the range.
  float prepare_curvature_colors(const DrawList& list, ColorMode mode);

 private:
  GpuArray counted(GpuArray array);
  const std::vector<float>& curvature(GpuObject& gpu, const EvaluatedObject& source, ColorMode mode);

  std::vector<GpuObject> objects_;
  std::uint64_t uploads_ = 0;
  double radius_ = 1.0;
};

}  // namespace sweep::render
