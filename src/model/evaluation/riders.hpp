#pragma once
// Riders in an evaluated scene: where each is at a time, which surfaces ride, how long a loop is.
// Shared by the viewer, `sweep render` and the glb export, so all three place a model alike.
#include "geometry/curves/frames.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/mat4x4.hpp>

#include <vector>

namespace sweep {

/// Where rider `index` is at `time` seconds: the frame of its path at the arc length it has
/// covered (ride_distance, track_frame_at). Preconditions: doc.objects[index] is a rider and
/// `scene` is evaluated from `doc`.
Frame rider_frame(const Document& doc, const Scene& scene, int index, double time);

/// The model matrix of rider `index` at `time` (frame_matrix of rider_frame): the model's +x, +y,
/// +z along N, B, T, its origin on the path. Same preconditions.
glm::dmat4 rider_matrix(const Document& doc, const Scene& scene, int index, double time);

/// The bounding radius about its own origin of the model rider `index` carries: the largest
/// distance of a vertex of its mesh from (0, 0, 0), where the rider's frame puts it (1 when the
/// mesh has no vertices). What a camera riding along keeps its distance by. Same preconditions.
double rider_model_radius(const Document& doc, const Scene& scene, int index);

/// How big a rider is, for a camera riding along with it: its model's bounding radius (above),
/// the height of the top above its origin along B (the largest +y of its model's mesh and of the
/// models riding with it at the same place and pace: a car's seats and wheels), and whether
/// another rider follows close behind on the same path at the same pace (a train: within 4 radii),
/// which a chase camera must look over.
struct RiderSize {
  double radius = 1.0;
  double top = 0.5;
  bool followed = false;
};
/// Same preconditions as rider_model_radius.
RiderSize rider_size(const Document& doc, const Scene& scene, int index);

/// Per object of `doc`: true for a surface that a rider carries, drawn only where it rides.
std::vector<bool> carried_models(const Document& doc);

/// Per object of `doc`: the curves a carried surface is made of (those that only carried surfaces
/// refer to, directly), listed at that surface's index; empty elsewhere. They are drawn where the
/// model rides, not at their own place.
std::vector<std::vector<int>> carried_curves(const Document& doc);

/// The indices of the riders of `doc`, in document order.
std::vector<int> riders_of(const Document& doc);

/// The time after which every rider has made a whole loop at least once: the longest `seconds`
/// of the riders (0 without riders).
double longest_loop(const Document& doc);

}  // namespace sweep
