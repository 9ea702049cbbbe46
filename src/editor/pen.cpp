#include "editor/pen.hpp"

#include "model/document.hpp"

#include <algorithm>
#include <stdexcept>

namespace sweep::editor {
namespace {

/// The nodes seen by one curve: node i's neighbours, wrapping when closed.
struct NodeRing {
  std::span<const PenNode> nodes;
  bool closed;

  std::size_t size() const { return nodes.size(); }
  const PenNode& next(std::size_t i) const { return nodes[(i + 1) % size()]; }
  const PenNode& previous(std::size_t i) const { return nodes[(i + size() - 1) % size()]; }
  bool is_first_open(std::size_t i) const { return !closed && i == 0; }
  bool is_last_open(std::size_t i) const { return !closed && i + 1 == size(); }
};

bool dragged(const PenNode& node) {
  return node.drag != glm::dvec3(0.0);
}

/// Handle `which` (0: outgoing, 1: the next node's incoming) of the piece from node i.
glm::dvec3 handle(const NodeRing& ring, std::size_t i, int which) {
  const PenNode& from = which == 0 ? ring.nodes[i] : ring.next(i);
  const PenNode& to = which == 0 ? ring.next(i) : ring.nodes[i];
  if (dragged(from)) return which == 0 ? from.at + from.drag : from.at - from.drag;
  return from.at + (to.at - from.at) / 3.0;
}

/// Node i's tangent: 3 × its drag, else the Catmull-Rom tangent.
glm::dvec3 tangent(const NodeRing& ring, std::size_t i) {
  const PenNode& node = ring.nodes[i];
  if (dragged(node)) return 3.0 * node.drag;
  if (ring.is_first_open(i)) return ring.next(i).at - node.at;
  if (ring.is_last_open(i)) return node.at - ring.previous(i).at;
  return (ring.next(i).at - ring.previous(i).at) / 2.0;
}

}  // namespace

bool pen_draws(ObjectKind kind) {
  return is_curve(kind) && point_layout(kind).role == PointRole::ControlPoints;
}

std::size_t pen_least_nodes(ObjectKind kind, bool closed) {
  const PointLayout& layout = point_layout(kind);
  const std::size_t least = closed ? layout.least_closed : layout.least_open + (layout.has_joints() ? 1 : 0);
  return std::max<std::size_t>(least, 2);
}

std::vector<glm::dvec3> pen_points(ObjectKind kind, std::span<const PenNode> nodes, bool closed) {
  if (!pen_draws(kind) || nodes.size() < pen_least_nodes(kind, closed)) {
    throw std::invalid_argument("pen_points: too few nodes for the kind");
  }
  const PointLayout& layout = point_layout(kind);
  const NodeRing ring{nodes, closed};
  std::vector<glm::dvec3> points;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    int handles = 0;  // handles of this node's group so far
    for (std::size_t e = 0; e < layout.stride; ++e) {
      switch (layout.entry(e)) {
        case EntryRole::Position:
          points.push_back(nodes[i].at);
          break;
        case EntryRole::Tangent:
          points.push_back(tangent(ring, i));
          break;
        case EntryRole::Handle:
          if (!ring.is_last_open(i)) points.push_back(handle(ring, i, handles++));
          break;
      }
    }
  }
  if (closed) {
    const std::vector<glm::dvec3> first(points.begin(), points.begin() + layout.seam_repeats);
    points.insert(points.end(), first.begin(), first.end());
  }
  return points;
}

std::vector<glm::dvec3> pen_shape_end(ObjectKind kind, std::vector<glm::dvec3> points, CurveEnd end,
                                      const glm::dvec3& drag) {
  const PointLayout& layout = point_layout(kind);
  const std::size_t n = points.size();
  const bool at_start = end == CurveEnd::Start;
  if (layout.has_joints() && n >= 4) {
    const std::size_t joint = at_start ? 0 : n - 1;
    points[at_start ? 1 : n - 2] = points[joint] - drag;
  } else if (layout.stride >= 2) {
    const std::size_t group = at_start ? 0 : n - layout.stride;
    for (std::size_t e = 0; e < layout.stride; ++e) {
      if (layout.entry(e) == EntryRole::Tangent) points[group + e] = (at_start ? -3.0 : 3.0) * drag;
    }
  }
  return points;
}

}  // namespace sweep::editor
