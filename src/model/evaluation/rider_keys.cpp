#include "model/evaluation/rider_keys.hpp"

#include "base/precondition.hpp"
#include "model/evaluation/riders.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace sweep {
namespace {

struct Key {
  double time = 0.0;
  Frame frame;
  bool added = false;  // a key at 0, at `seconds` or at a jump: kept over a sample's key
};

double fract(double x) {
  return x - std::floor(x);
}

/// One key per sample of the path, at the time rider `index` reaches it. An open path's first
/// and last samples are left to the added keys (its jump back to the start).
void add_sample_keys(const Document& doc, const Scene& scene, int index, std::vector<Key>& keys) {
  const auto i = static_cast<std::size_t>(index);
  const RiderObject& rider = doc.objects[i].as<RiderObject>();
  const RiderTrack& track = scene.objects[i].track;
  const double length = track.length();
  if (!(length > 0.0)) return;
  for (const double at : track.lengths) {
    if (!track.closed && (at <= 0.0 || at >= length)) continue;
    const double time = std::min(rider.seconds * fract(at / length - rider.start), rider.seconds);
    keys.push_back({time, rider_frame(doc, scene, index, time), false});
  }
}

/// The keys at 0 and at `seconds`, and an open path's jump keys.
void add_loop_keys(const Document& doc, const Scene& scene, int index, std::vector<Key>& keys) {
  const auto i = static_cast<std::size_t>(index);
  const RiderObject& rider = doc.objects[i].as<RiderObject>();
  const RiderTrack& track = scene.objects[i].track;
  const double length = track.length();
  const bool jumps = !track.closed && length > 0.0;
  keys.push_back({0.0, rider_frame(doc, scene, index, 0.0), true});
  if (jumps && rider.start == 0.0) {  // the loop's wrap is the jump
    keys.push_back({rider.seconds, track_frame_at(track, length), true});
    return;
  }
  keys.push_back({rider.seconds, rider_frame(doc, scene, index, rider.seconds), true});
  if (!jumps) return;
  const double jump = rider.seconds * (1.0 - rider.start);
  keys.push_back({std::max(jump - rider_jump_gap(rider.seconds), 0.0), track_frame_at(track, length), true});
  keys.push_back({jump, track_frame_at(track, 0.0), true});
}

/// `keys` sorted by time without keys at equal float times (an added key is kept over a sample's).
std::vector<Key> distinct_times(const std::vector<Key>& keys) {
  // By (time, place in `keys`) with std::sort: std::stable_sort's temporary buffer in GCC 12's
  // libstdc++ is reported by AddressSanitizer as an alloc-dealloc mismatch.
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&keys](std::size_t a, std::size_t b) {
    return keys[a].time < keys[b].time || (keys[a].time == keys[b].time && a < b);
  });
  std::vector<Key> out;
  for (const std::size_t k : order) {
    const Key& key = keys[k];
    if (out.empty() || static_cast<float>(key.time) > static_cast<float>(out.back().time)) {
      out.push_back(key);
    } else if (key.added && !out.back().added) {
      out.back() = key;
    }
  }
  return out;
}

}  // namespace

glm::dquat frame_rotation(const Frame& frame) {
  return glm::normalize(glm::quat_cast(glm::dmat3(frame.N, frame.B, frame.T)));
}

double rider_jump_gap(double seconds) {
  SWEEP_EXPECTS(seconds > 0.0, "seconds > 0");
  const auto s = static_cast<float>(seconds);
  const double step = static_cast<double>(std::nextafter(s, INFINITY)) - static_cast<double>(s);
  return std::max(std::min(kRiderJumpSeconds, 1e-3 * seconds), 2.0 * step);
}

RiderKeys rider_keys(const Document& doc, const Scene& scene, int index) {
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    is_rider(doc.objects[static_cast<std::size_t>(index)].kind()),
                "doc.objects[index] is a rider");
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  std::vector<Key> keys;
  add_sample_keys(doc, scene, index, keys);
  add_loop_keys(doc, scene, index, keys);
  RiderKeys out;
  for (const Key& key : distinct_times(keys)) {
    glm::dquat q = frame_rotation(key.frame);
    if (!out.rotations.empty() && glm::dot(out.rotations.back(), q) < 0.0) q = -q;
    out.times.push_back(key.time);
    out.translations.push_back(key.frame.V);
    out.rotations.push_back(q);
  }
  return out;
}

}  // namespace sweep
