#include "editor/view_state.hpp"

namespace sweep::editor {

const ObjectViewState& ViewStates::get(ObjectId id) const {
  static const ObjectViewState kDefault;
  const auto found = states_.find(id);
  return found == states_.end() ? kDefault : found->second;
}

std::vector<bool> ViewStates::visibility(const Document& doc) const {
  std::vector<bool> visible;
  visible.reserve(doc.objects.size());
  for (const Object& object : doc.objects) visible.push_back(get(object.id).visible);
  return visible;
}

void Selection::select(ObjectId id) {
  if (id != object) {
    point = -1;
    group.clear();
  }
  object = id;
}

std::vector<int> Selection::points() const {
  if (point >= 0 && group.contains(point)) return group.points();
  return point >= 0 ? std::vector<int>{point} : std::vector<int>{};
}

void Selection::fix(const EditSession& session) {
  const int i = index(session);
  if (i < 0) {
    clear();
    return;
  }
  const int count = static_cast<int>(points_of(session.document().objects[std::size_t(i)]).size());
  if (point >= count) point = count - 1;
  if (hovered_point >= count) hovered_point = -1;
  group.fix(count);
}

}  // namespace sweep::editor
