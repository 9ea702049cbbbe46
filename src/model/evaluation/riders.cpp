#include "model/evaluation/riders.hpp"

#include "base/precondition.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep {

Frame rider_frame(const Document& doc, const Scene& scene, int index, double time) {
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    is_rider(doc.objects[static_cast<std::size_t>(index)].kind()),
                "doc.objects[index] is a rider");
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  const auto i = static_cast<std::size_t>(index);
  const RiderObject& rider = doc.objects[i].as<RiderObject>();
  const RiderTrack& track = scene.objects[i].track;
  return track_frame_at(track, ride_distance(track, time, rider.seconds, rider.start));
}

glm::dmat4 rider_matrix(const Document& doc, const Scene& scene, int index, double time) {
  return frame_matrix(rider_frame(doc, scene, index, time));
}

double rider_model_radius(const Document& doc, const Scene& scene, int index) {
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    is_rider(doc.objects[static_cast<std::size_t>(index)].kind()),
                "doc.objects[index] is a rider");
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  const int model = doc.objects[static_cast<std::size_t>(index)].as<RiderObject>().model;
  if (model < 0 || static_cast<std::size_t>(model) >= scene.objects.size()) return 1.0;
  double radius = 0.0;
  for (const glm::vec3& p : scene.objects[static_cast<std::size_t>(model)].mesh.positions) {
    const double d = glm::length(glm::dvec3(p));
    if (std::isfinite(d)) radius = std::max(radius, d);
  }
  return radius > 0.0 ? radius : 1.0;
}

namespace {

/// The largest +y of the model rider `index` carries (0 without vertices).
double model_top(const Document& doc, const Scene& scene, int index) {
  const int model = doc.objects[static_cast<std::size_t>(index)].as<RiderObject>().model;
  if (model < 0 || static_cast<std::size_t>(model) >= scene.objects.size()) return 0.0;
  double top = 0.0;
  for (const glm::vec3& p : scene.objects[static_cast<std::size_t>(model)].mesh.positions) {
    if (std::isfinite(p.y)) top = std::max(top, double(p.y));
  }
  return top;
}

/// True when riders `a` and `b` ride the same path at the same pace and place (one car's parts).
bool ride_together(const RiderObject& a, const RiderObject& b) {
  return a.path == b.path && a.seconds == b.seconds && a.start == b.start;
}

/// The top of everything riding with rider `index` (a car's body, seats and wheels).
double riding_top(const Document& doc, const Scene& scene, int index) {
  const RiderObject& self = doc.objects[static_cast<std::size_t>(index)].as<RiderObject>();
  double top = model_top(doc, scene, index);
  for (const int other : riders_of(doc)) {
    if (ride_together(self, doc.objects[static_cast<std::size_t>(other)].as<RiderObject>())) {
      top = std::max(top, model_top(doc, scene, other));
    }
  }
  return top;
}

/// True when another rider of the same path and pace rides behind rider `index` within `reach`.
bool followed_within(const Document& doc, const Scene& scene, int index, double reach) {
  const RiderObject& self = doc.objects[static_cast<std::size_t>(index)].as<RiderObject>();
  const double length = scene.objects[static_cast<std::size_t>(index)].track.length();
  if (!(length > 0.0)) return false;
  for (const int other : riders_of(doc)) {
    const RiderObject& r = doc.objects[static_cast<std::size_t>(other)].as<RiderObject>();
    if (other == index || r.path != self.path || r.seconds != self.seconds) continue;
    const double behind = std::fmod(self.start - r.start + 1.0, 1.0) * length;  // along the loop
    if (behind > 1e-9 * length && behind < reach) return true;
  }
  return false;
}

}  // namespace

RiderSize rider_size(const Document& doc, const Scene& scene, int index) {
  RiderSize size;
  size.radius = rider_model_radius(doc, scene, index);
  size.top = riding_top(doc, scene, index);
  size.followed = followed_within(doc, scene, index, 4.0 * size.radius);
  return size;
}

std::vector<bool> carried_models(const Document& doc) {
  std::vector<bool> carried(doc.objects.size(), false);
  for (const Object& object : doc.objects) {
    const auto* rider = object.find<RiderObject>();
    if (rider && rider->model >= 0 && static_cast<std::size_t>(rider->model) < carried.size()) {
      carried[static_cast<std::size_t>(rider->model)] = true;
    }
  }
  return carried;
}

std::vector<std::vector<int>> carried_curves(const Document& doc) {
  const std::vector<bool> carried = carried_models(doc);
  // Which curves something other than a carried surface refers to (a rider its path, a surface
  // at its own place its profile).
  std::vector<bool> used_elsewhere(doc.objects.size(), false);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (carried[i]) continue;
    for (const int r : references(doc.objects[i])) {
      if (r >= 0 && static_cast<std::size_t>(r) < used_elsewhere.size()) used_elsewhere[std::size_t(r)] = true;
    }
  }
  std::vector<std::vector<int>> out(doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (!carried[i]) continue;
    for (const int r : references(doc.objects[i])) {
      if (r < 0 || static_cast<std::size_t>(r) >= doc.objects.size() || used_elsewhere[std::size_t(r)]) continue;
      if (is_curve(doc.objects[std::size_t(r)].kind())) out[i].push_back(r);
    }
  }
  return out;
}

std::vector<int> riders_of(const Document& doc) {
  std::vector<int> out;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (is_rider(doc.objects[i].kind())) out.push_back(static_cast<int>(i));
  }
  return out;
}

double longest_loop(const Document& doc) {
  double longest = 0.0;
  for (const Object& object : doc.objects) {
    if (const auto* rider = object.find<RiderObject>()) longest = std::max(longest, rider->seconds);
  }
  return longest;
}

}  // namespace sweep
