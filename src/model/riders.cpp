#include "model/riders.hpp"

#include "geometry/precondition.hpp"

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
