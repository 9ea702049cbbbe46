#pragma once
// The marks the editor draws over the scene, as plain data (OverlayBatch) for the renderer:
// the selected curve highlighted with its handles, the samples where a tube folds, the
// profile view's grid, and the 3D view's ground grid with the axes.
#include "base/nice_step.hpp"
#include "geometry/mesh/overlay.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/vec3.hpp>

#include <optional>
#include <vector>

namespace sweep::editor {

inline const glm::vec3 kHighlightColor{1.0f, 0.55f, 0.1f};  // the selected curve
inline const glm::vec3 kHandleColor{1.0f, 0.9f, 0.1f};      // its control points
inline const glm::vec3 kHandleHoveredColor{1.0f, 1.0f, 1.0f};
inline const glm::vec3 kHandleSelectedColor{0.2f, 0.9f, 1.0f};  // the selected point and its seam partners
inline const glm::vec3 kFoldColor{1.0f, 0.2f, 1.0f};            // sweep samples where a tube folds over itself
inline const glm::vec3 kGridColor{0.24f, 0.26f, 0.30f};         // grid lines, a little lighter than the background
inline const glm::vec3 kXAxisColor{0.62f, 0.24f, 0.24f};        // the axes: x red, y green, z blue
inline const glm::vec3 kYAxisColor{0.30f, 0.56f, 0.24f};
inline const glm::vec3 kZAxisColor{0.26f, 0.38f, 0.70f};
inline constexpr float kHandleSize = 9.0f;
inline constexpr float kHandleBigSize = 13.0f;
inline constexpr float kJointSize = 10.0f;       // a Bezier or Hermite joint's square
inline constexpr float kHandleSmallSize = 7.0f;  // and its handles' discs

/// The xy-grid of the profile view around what the camera looks at.
struct GridView {
  glm::dvec3 centre{0.0};    // the camera's target
  double half_height = 1.0;  // half the view's height at the target
  double snap = 0.0;         // the snapping step when snapping is on (used when not too dense), else 0
};

/// The 3D view's ground grid: a square in the xz-plane (y is up: surfaces of revolution turn
/// about the y axis) around the y axis, at y = 0 or, when the scene reaches below, at its lowest
/// point, so the grid never cuts through what it shows (the starter files are centred on the
/// origin: a wineglass stands on it); spaced and sized from the box of what is shown. The box
/// may be empty (low above high on an axis, as render::Bounds is before anything is added) or
/// not finite: the grid then covers the unit square at y = 0.
struct GroundGrid {
  glm::dvec3 low{0.0};  // the visible scene's box (render::scene_bounds)
  glm::dvec3 high{0.0};
};

struct OverlayInput {
  const Document* doc = nullptr;  // required, with its evaluated scene
  const Scene* scene = nullptr;
  std::vector<bool> visible;  // per object; past the end: visible
  int selected = -1;          // object index
  int selected_point = -1;
  std::vector<int> selected_points;  // several selected together (with selected_point among them)
  int hovered_point = -1;
  bool curves_shown = true;          // fold marks go with the curves
  std::optional<GridView> grid;      // the profile view's grid
  std::optional<GroundGrid> ground;  // the 3D view's ground grid and axes
  std::vector<OverlayBatch> extra;   // the selected curve's curvature comb (curvature_comb.hpp)
};

/// Every batch to draw over the scene, in drawing order; `extra` (a curvature comb) after the
/// selected curve's highlight and before its handles.
std::vector<OverlayBatch> build_overlay(const OverlayInput& input);

/// The selected object's index when it is a visible surface (the view highlights it), else -1.
/// Precondition: input.doc is set.
int highlighted_surface(const OverlayInput& input);

/// The ground grid's height: min(0, the box's lowest y), 0 for an empty box.
double ground_height(const GroundGrid& ground);

/// The ground grid's spacing: a nice step near a fifth of the box's radius (0.2 for an empty box).
double ground_step(const GroundGrid& ground);

}  // namespace sweep::editor
