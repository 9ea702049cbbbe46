#pragma once
// Where a dragged control point goes: in the xy-plane for 2D curves, in the plane facing the
// camera for 3D ones, or along one axis while X, Y or Z is held; optionally snapped to a grid.
#include "editor/picking.hpp"

#include <glm/vec3.hpp>

#include <optional>

namespace sweep::editor {

struct PointDragInput {
  glm::dvec3 start{0.0};                    // where the point was when the drag began
  bool planar = false;                      // the point of a 2D curve: stays in the xy-plane
  int axis = -1;                            // 0, 1, 2: move along x, y or z only; -1: free
  glm::dvec3 view_forward{0.0, 0.0, -1.0};  // the camera's viewing direction
  double snap = 0.0;                        // grid step to round to; 0: no snapping
};

/// A handle held with the pointer, in window units: where the pointer was pressed, and the
/// handle's centre minus that (so the handle keeps its place under the pointer, not jumping to it).
struct HandleGrip {
  glm::dvec2 pressed{0.0};
  glm::dvec2 offset{0.0};
};

/// The new position of the dragged point with the pointer at `pointer`: exactly `input.start`
/// while the pointer is where it was pressed (a click moves nothing, and a drag back there puts
/// the point back as it was, to the bit), else drag_target of the ray through the handle's
/// centre. Nullopt as drag_target says.
std::optional<glm::dvec3> grip_target(const ScreenMapping& mapping, const HandleGrip& grip, const glm::dvec2& pointer,
                                      const PointDragInput& input);

/// The new position of the dragged point for the pointer ray `ray`, or nullopt when there is
/// none (the ray runs along the plane or axis, or a 2D point is asked to move along z).
std::optional<glm::dvec3> drag_target(const Ray& ray, const PointDragInput& input);

}  // namespace sweep::editor
