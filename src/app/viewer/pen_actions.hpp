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
/// The plane the pen's next node goes on: the xy-plane (z = 0) for a 2D kind or curve or in the
/// profile view; else, continuing a 3D curve from its selected end, the level plane through that
/// end; else the 3D view's ground grid (y = its height).
PenPlane pen_plane(const ViewerState& s);
/// The curve the pen's next node continues: the one being continued, else the selected point's
/// when it is an open curve's first or last point; -1 for none (the next node starts a stroke).
int pen_continues(const ViewerState& s);
/// Puts down a node at `at`. The first one starts a stroke on pen_plane, or, when the selected
/// point is an open curve's first or last point, continues that curve there (extend_curve: every
/// node an undo step, "extend curve").
void pen_place(ViewerState& s, const glm::dvec3& at);
/// The last node dragged to `to` (its handles, where the kind has them; pen_shape_end for an end).
void pen_drag(ViewerState& s, const glm::dvec3& to);
/// The button let go: a node put down at a continued end is one undo step.
void pen_release(ViewerState& s);
/// Backspace while drawing: the last node taken back (the curve goes when it has too few; at a
/// continued end, its step undone).
void pen_take_back(ViewerState& s);
/// A click on the stroke's first node: the curve closed and ended. False, with a status saying
/// how many nodes a closed curve of the kind needs, when it has too few (the stroke goes on).
bool pen_close(ViewerState& s);
/// Enter or Esc: the stroke ends open; with too few nodes for a curve nothing is drawn.
void pen_finish(ViewerState& s);

}  // namespace sweep::viewer
