#pragma once
// The pen (B): curves drawn by clicking in the view, as in a drawing program. A stroke is one
// undo step from its first node to its end; once it has the nodes its kind needs it is a curve of
// the document (selected, drawn and evaluated as any other) that each further node reshapes. What
// a node and its drag become is editor/pen.hpp's. pen_input.cpp feeds the pointer; the Pen panel
// the typed coordinates and its buttons. No GL.
#include "app/viewer/viewer_state.hpp"

#include <glm/vec3.hpp>

namespace sweep::viewer {

/// B: the pen on, or off (ending the stroke being drawn, as pen_finish).
void toggle_pen(ViewerState& s);
/// The plane a stroke of the pen's kind is drawn on now: the xy-plane (z = 0) for a 2D kind or in
/// the profile view, else the 3D view's ground grid (y = its height).
PenPlane pen_plane(const ViewerState& s);
/// Puts down a node at `at` (the first one starts a stroke on pen_plane).
void pen_place(ViewerState& s, const glm::dvec3& at);
/// The last node dragged to `to` (its handles, where the kind has them).
void pen_drag(ViewerState& s, const glm::dvec3& to);
/// Backspace while drawing: the last node taken back (the curve goes when it has too few).
void pen_take_back(ViewerState& s);
/// A click on the stroke's first node: the curve closed and ended. False, with a status saying
/// how many nodes a closed curve of the kind needs, when it has too few (the stroke goes on).
bool pen_close(ViewerState& s);
/// Enter or Esc: the stroke ends open; with too few nodes for a curve nothing is drawn.
void pen_finish(ViewerState& s);

}  // namespace sweep::viewer
