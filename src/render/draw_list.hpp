#pragma once
// What the renderer is given to draw, and where: plain data without GL, built by the window,
// `sweep render` and the tests. The renderer reads nothing else (no Document, no editor state).
#include "geometry/mesh/overlay.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "model/material.hpp"
#include "render/display_settings.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace sweep::render {

/// The texture coordinates a scene needs to be drawn in colour mode `mode`: every surface's for
/// ColorMode::Uv, else only those of the surfaces whose material shows an image.
TextureCoordinates texture_coordinates_drawn(ColorMode mode);

/// A rider's model drawn where it rides: the surface `model`'s mesh placed by `matrix` (its +x,
/// +y, +z along the frame's N, B, T, its origin on the path: model/evaluation/riders.hpp).
struct RiderPlacement {
  int model = -1;
  glm::mat4 matrix{1.0f};
};

/// What one draw shows: the evaluated scene, which of its objects are visible, the control
/// polygons to show, and marks drawn over everything.
struct DrawList {
  const Scene* scene = nullptr;  // required
  std::vector<bool> visible;     // visible[i] false hides scene object i; objects past the end are visible
  /// Per scene object; empty (or past the end): none. Valid during draw(). The renderer keeps its
  /// GPU copy per object revision, so a polygon may change only when its object's revision does.
  std::vector<std::span<const glm::dvec3>> control_polygons;
  /// The polygons that are not the document's points as they are (a Hermite curve's, with its
  /// tangents' handles: model/edit/shown_points.hpp): control_polygons' spans of them point here.
  std::vector<std::vector<glm::dvec3>> drawn_polygons;
  std::vector<OverlayBatch> overlay;  // drawn last
  /// Per scene object: true for a surface that a subd refines (its cage), not shaded over the
  /// smooth surface inside it: a mesh or patch shows its net with the control points, and every
  /// cage shows with the subd's wireframe. Past the end: false.
  std::vector<bool> cage_only;
  /// Per scene object: true for a surface a rider carries, drawn only where it rides (`riders`),
  /// not at its own place. Past the end: false.
  std::vector<bool> carried;
  /// The riders' models at the time shown (add_riders), drawn with the surfaces.
  std::vector<RiderPlacement> riders;
  /// Per scene object: for a carried surface, the curves it is made of (carried_curves). They are
  /// not drawn: at their own place they would be wire clutter where no model is, and at the
  /// rider's they would stick out of the model (profiles and scale graphs live in planes of their
  /// own); the model itself shows where it rides.
  std::vector<std::vector<int>> carried_curves;
  /// Per scene object: true for a curve of carried_curves. Past the end: false.
  std::vector<bool> riding_curves;
  /// Per scene object: its surface's material (material.hpp); past the end or unnamed: the
  /// default look, which DisplaySettings::material gives.
  std::vector<SurfaceMaterial> materials;
  /// The scene object whose surface is shown highlighted (the selected one), or -1: its shading
  /// turns towards `highlight_color` at the silhouette and a little everywhere (a wireframe
  /// takes the colour), so it stands out without hiding its shape. Costs a uniform, no upload.
  int highlighted = -1;
  glm::vec3 highlight_color{1.0f, 0.55f, 0.1f};

  /// False only for objects hidden by `visible`.
  bool is_visible(std::size_t index) const;
  /// Visible, not cage_only and not carried: its mesh is drawn at its own place.
  bool is_shaded(std::size_t index) const;
  /// A rider of `riders` carries it: its mesh is drawn where it rides.
  bool rides(std::size_t index) const;
  /// A curve of carried_curves: not drawn (nor its control polygon).
  bool curve_rides(std::size_t index) const;
};

/// Every object of `scene` visible, with the control polygons of `doc`'s control-point curves
/// (has_control_points(kind)), the surfaces that subds refine marked cage_only, and no overlay. The list points into
/// `doc` and `scene`, which must outlive it. Precondition: scene evaluated from doc.
/// `image_folder` is where the materials' image paths start (the SWP file's folder).
DrawList draw_list(const Document& doc, const Scene& scene, const std::filesystem::path& image_folder = {});

/// Sets `list.riders` to every visible rider of `doc` at `time` seconds (and `list.carried` to the
/// surfaces they carry). Precondition: scene evaluated from doc.
void add_riders(DrawList& list, const Document& doc, const Scene& scene, double time);

/// Where a draw goes: the bound draw framebuffer's size in pixels and its pixels per screen unit (HiDPI).
struct RenderTarget {
  glm::ivec2 size{1, 1};
  float pixel_ratio = 1.0f;
};

}  // namespace sweep::render
