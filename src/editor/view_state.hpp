#pragma once
// What the viewer remembers per object and which object is selected, keyed by the object's
// stable id (never by its position, which deletions and undo change).
#include "editor/edit_session.hpp"
#include "editor/point_selection.hpp"

#include <unordered_map>
#include <vector>

namespace sweep::editor {

/// How one object is shown. Later display options per object go here.
struct ObjectViewState {
  bool visible = true;
};

/// View state per object id. Objects never mentioned have the default state; the state of a
/// deleted object is kept, so undoing the deletion brings it back as it was.
class ViewStates {
 public:
  const ObjectViewState& get(ObjectId id) const;
  ObjectViewState& at(ObjectId id) { return states_[id]; }
  bool visible(ObjectId id) const { return get(id).visible; }
  void set_visible(ObjectId id, bool visible) { states_[id].visible = visible; }
  /// visible(id) of every object of `doc` in document order (what the renderer takes).
  std::vector<bool> visibility(const Document& doc) const;
  /// Forgets everything (a file was opened).
  void clear() { states_.clear(); }

 private:
  std::unordered_map<ObjectId, ObjectViewState> states_;
};

/// The selected object, its selected control point and the point under the pointer.
struct Selection {
  ObjectId object = kNoObject;
  int point = -1;          // control point of the selected curve (the active one), or -1
  int hovered_point = -1;  // handle under the pointer, or -1
  /// The points selected together (Shift+click, the rubber band, A). They count only while they
  /// hold `point`: whoever sets `point` alone (the point table, an insert) selects it alone.
  PointSelection group;

  /// The selected points, ascending: the group when it holds `point`, else `point` alone (or
  /// none).
  std::vector<int> points() const;

  /// Selects `id`; the point selection goes unless the object stays the same.
  void select(ObjectId id);
  void clear() { *this = {}; }
  /// The selected object's index in `session`'s document, or -1.
  int index(const EditSession& session) const { return session.index_of(object); }
  /// After an edit, undo or redo: drops a selection whose object is gone and keeps the point
  /// indices within the object's points.
  void fix(const EditSession& session);
};

}  // namespace sweep::editor
