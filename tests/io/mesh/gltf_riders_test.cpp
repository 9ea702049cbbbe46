// The riders' scene glb (`sweep export --format glb` with riders) read back by tinygltf: one
// animation per rider driving its node's translation and rotation from one input of key times
// (0 to seconds, strictly increasing); the still nodes are the surfaces no rider carries; every
// key where rider_frame puts the rider at its time, its quaternion unit, sign-continuous and
// turning +z into T and +x into N; a closed path's loop ends where it began; an open path jumps
// back to its start between two keys; the rider's mesh is its model's. Also rider_keys alone for
// an open path ridden from its start.
#include "io/surface_export.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/rider_keys.hpp"
#include "model/evaluation/riders.hpp"

#include "support/gltf_test_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <tiny_gltf.h>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <vector>

namespace sweep {
namespace {

using io::export_evaluation;
using io::export_surfaces;
using io::ExportFormat;
using test::accessor_data;

// A closed path (a circle of radius 2) and an open one (a cubic Bezier about 6 long); the car
// rides both, `pole` is still. `spine` is a curve, so not in the scene.
const char* const kText =
    "circ track 40 2\n"
    "circ body 12 0.2\n"
    "bez3 spine 4 4\n[0 0 0]\n[0 0 0.3]\n[0 0 0.6]\n[0 0 1]\n"
    "gcyl car body spine\n"
    "bez3 road 16 4\n[0 0 0]\n[2 1 0]\n[4 -1 1]\n[6 0 0]\n"
    "circ hoop 16 1\n"
    "srev pole 16 hoop\n"
    "rider loop track car seconds 4 start 0.2137\n"
    "rider drive road car seconds 3 start 0.37 up 0 1 0\n";

constexpr double kSize = 6.0;  // about the largest extent of the paths
constexpr double kTolerance = 1e-6 * kSize;

struct Exported {
  Document doc;
  Scene scene;
  tinygltf::Model model;
};

/// kText exported as glb into `folder`, its PREFIX.glb read back.
Exported export_riders(const test::ScratchFolder& folder) {
  Exported out;
  out.doc = io::parse_swp(kText, "riders.swp");
  out.scene = evaluate_document(out.doc, io::export_evaluation({}, io::ExportFormat::Glb));
  const std::string prefix = (folder.path() / "r").string();
  const io::ExportReport report = io::export_surfaces(out.doc, out.scene, "riders.swp", prefix, io::ExportFormat::Glb);
  EXPECT_EQ(report.files.back().path, prefix + ".glb");
  tinygltf::TinyGLTF reader;
  std::string error;
  std::string warning;
  EXPECT_TRUE(reader.LoadBinaryFromFile(&out.model, &error, &warning, prefix + ".glb")) << error;
  EXPECT_EQ(error, "");
  EXPECT_EQ(warning, "");
  return out;
}

int node_named(const tinygltf::Model& model, const std::string& name) {
  for (std::size_t n = 0; n < model.nodes.size(); ++n) {
    if (model.nodes[n].name == name) return static_cast<int>(n);
  }
  return -1;
}

/// One rider's keys as the file has them.
struct FileKeys {
  std::vector<float> times;
  std::vector<glm::vec3> translations;
  std::vector<glm::vec4> rotations;  // x, y, z, w
};

/// The animation named after rider `name`, checked for its shape, and its keys.
FileKeys animation_of(const tinygltf::Model& model, const std::string& name) {
  FileKeys out;
  const int node = node_named(model, name);
  EXPECT_GE(node, 0) << name;
  for (const tinygltf::Animation& animation : model.animations) {
    if (animation.name != name) continue;
    EXPECT_EQ(animation.channels.size(), 2u);
    EXPECT_EQ(animation.samplers.size(), 2u);
    if (animation.channels.size() != 2 || animation.samplers.size() != 2) return out;
    std::set<std::string> paths;
    for (const tinygltf::AnimationChannel& channel : animation.channels) {
      EXPECT_EQ(channel.target_node, node);
      paths.insert(channel.target_path);
      const tinygltf::AnimationSampler& sampler = animation.samplers.at(static_cast<std::size_t>(channel.sampler));
      EXPECT_EQ(sampler.interpolation, "LINEAR");
      EXPECT_EQ(sampler.input, animation.samplers[0].input);
      out.times = accessor_data<float>(model, sampler.input);
      if (channel.target_path == "translation") out.translations = accessor_data<glm::vec3>(model, sampler.output);
      if (channel.target_path == "rotation") out.rotations = accessor_data<glm::vec4>(model, sampler.output);
    }
    EXPECT_EQ(paths, (std::set<std::string>{"translation", "rotation"}));
    EXPECT_EQ(out.translations.size(), out.times.size());
    EXPECT_EQ(out.rotations.size(), out.times.size());
    return out;
  }
  ADD_FAILURE() << "no animation named " << name;
  return out;
}

glm::dquat quaternion(const glm::vec4& q) {
  return glm::dquat(q.w, q.x, q.y, q.z);
}

/// The key is the frame: V, and +z turned into T, +x into N.
void expect_key_is(const FileKeys& keys, std::size_t k, const Frame& frame, const std::string& what) {
  EXPECT_LE(glm::length(glm::dvec3(keys.translations[k]) - frame.V), kTolerance) << what << " key " << k;
  const glm::dquat q = quaternion(keys.rotations[k]);
  EXPECT_LE(glm::length(q * glm::dvec3(0, 0, 1) - frame.T), 1e-6) << what << " key " << k;
  EXPECT_LE(glm::length(q * glm::dvec3(1, 0, 0) - frame.N), 1e-6) << what << " key " << k;
}

void expect_keys_whole(const FileKeys& keys, double seconds) {
  ASSERT_GE(keys.times.size(), 3u);
  EXPECT_EQ(keys.times.front(), 0.0f);
  EXPECT_EQ(keys.times.back(), static_cast<float>(seconds));
  for (std::size_t k = 1; k < keys.times.size(); ++k) EXPECT_LT(keys.times[k - 1], keys.times[k]) << k;
  for (std::size_t k = 0; k < keys.rotations.size(); ++k) {
    EXPECT_NEAR(glm::length(keys.rotations[k]), 1.0, 1e-6) << k;
    if (k > 0) {
      EXPECT_GE(glm::dot(keys.rotations[k - 1], keys.rotations[k]), 0.0f) << k;
    }
  }
}

/// Every sample of the path is a key, at the time its arc length is reached:
/// seconds * fract(lengths[i] / L - start) (an open path's ends: at its jump or the loop's end).
void expect_sample_times(const FileKeys& keys, const RiderTrack& track, double seconds, double start) {
  for (std::size_t i = 0; i < track.lengths.size(); ++i) {
    const double share = track.lengths[i] / track.length() - start;
    const double time = seconds * (share - std::floor(share));
    const auto near = [time](float t) { return std::abs(t - time) <= 1e-6 * (1.0 + time); };
    const bool end = !track.closed && i + 1 == track.lengths.size();
    EXPECT_TRUE(std::any_of(keys.times.begin(), keys.times.end(), near) ||
                (end && std::any_of(keys.times.begin(), keys.times.end(),
                                    [time](float t) { return std::abs(t - (time - kRiderJumpSeconds)) <= 2e-7; })))
        << "sample " << i << " at " << time << " s";
  }
}

TEST(GlbRiders, EachRiderHasItsAnimationAndTheStillNodesAreTheFreeSurfaces) {
  const test::ScratchFolder folder("sweep-glb-riders");
  const Exported e = export_riders(folder);
  ASSERT_EQ(e.model.animations.size(), 2u);
  std::set<std::string> animated;
  std::set<std::string> still;
  for (const tinygltf::Animation& animation : e.model.animations) animated.insert(animation.name);
  for (const tinygltf::Node& node : e.model.nodes) {
    if (!animated.count(node.name)) still.insert(node.name);
  }
  EXPECT_EQ(animated, (std::set<std::string>{"loop", "drive"}));
  EXPECT_EQ(still, (std::set<std::string>{"pole"}));  // car rides; curves are not surfaces
  ASSERT_EQ(e.model.scenes.size(), 1u);
  EXPECT_EQ(e.model.scenes[0].nodes.size(), 3u);
  const std::size_t car_triangles = e.scene.objects[static_cast<std::size_t>(e.doc.find("car"))].mesh.triangle_count();
  ASSERT_GT(car_triangles, 0u);
  for (const char* rider : {"loop", "drive"}) {
    const tinygltf::Node& node = e.model.nodes.at(static_cast<std::size_t>(node_named(e.model, rider)));
    ASSERT_GE(node.mesh, 0) << rider;
    const tinygltf::Primitive& primitive = e.model.meshes.at(static_cast<std::size_t>(node.mesh)).primitives.at(0);
    EXPECT_EQ(e.model.accessors.at(static_cast<std::size_t>(primitive.indices)).count, 3 * car_triangles) << rider;
  }
}

TEST(GlbRiders, ClosedPathKeysFollowTheRiderAndCloseTheLoop) {
  const test::ScratchFolder folder("sweep-glb-riders");
  const Exported e = export_riders(folder);
  const int rider = e.doc.find("loop");
  const FileKeys keys = animation_of(e.model, "loop");
  expect_keys_whole(keys, 4.0);
  ASSERT_GT(keys.times.size(), 40u);  // every sample of the circle
  expect_sample_times(keys, e.scene.objects[static_cast<std::size_t>(rider)].track, 4.0, 0.2137);
  for (std::size_t k = 0; k < keys.times.size(); ++k) {
    expect_key_is(keys, k, rider_frame(e.doc, e.scene, rider, keys.times[k]), "loop");
  }
  EXPECT_LE(glm::length(keys.translations.front() - keys.translations.back()), kTolerance);
  // the same rotation; after a whole turn about the circle's axis, sign continuity gives -q
  const glm::vec4 first = keys.rotations.front();
  const glm::vec4 last = keys.rotations.back();
  EXPECT_LE(std::min(glm::length(first - last), glm::length(first + last)), 1e-6);
}

TEST(GlbRiders, OpenPathKeysFollowTheRiderAndJumpBackToTheStart) {
  const test::ScratchFolder folder("sweep-glb-riders");
  const Exported e = export_riders(folder);
  const int rider = e.doc.find("drive");
  const RiderTrack& track = e.scene.objects[static_cast<std::size_t>(rider)].track;
  const FileKeys keys = animation_of(e.model, "drive");
  expect_keys_whole(keys, 3.0);
  expect_sample_times(keys, track, 3.0, 0.37);
  const double jump = 3.0 * (1.0 - 0.37);
  std::size_t end_key = keys.times.size();
  for (std::size_t k = 0; k + 1 < keys.times.size(); ++k) {
    if (keys.times[k + 1] == static_cast<float>(jump)) end_key = k;
  }
  ASSERT_LT(end_key, keys.times.size()) << "no key at the jump";
  EXPECT_NEAR(keys.times[end_key + 1] - keys.times[end_key], kRiderJumpSeconds, 1e-7);
  expect_key_is(keys, end_key, track_frame_at(track, track.length()), "the path's end");
  expect_key_is(keys, end_key + 1, track_frame_at(track, 0.0), "the path's start");
  for (std::size_t k = 0; k < keys.times.size(); ++k) {
    if (k == end_key || k == end_key + 1) continue;
    expect_key_is(keys, k, rider_frame(e.doc, e.scene, rider, keys.times[k]), "drive");
  }
  for (std::size_t k = 0; k < keys.times.size(); ++k) {  // up 0 1 0: B as high as it goes, N level
    const glm::dquat q = quaternion(keys.rotations[k]);
    EXPECT_NEAR((q * glm::dvec3(1, 0, 0)).y, 0.0, 1e-6) << k;
  }
}

TEST(RiderKeys, OpenPathFromItsStartEndsTheLoopAtItsEnd) {
  Document doc = io::parse_swp(std::string(kText) + "rider plain road car seconds 2\n", "riders.swp");
  const Scene scene = evaluate_document(doc);
  const int rider = doc.find("plain");
  const RiderTrack& track = scene.objects[static_cast<std::size_t>(rider)].track;
  const RiderKeys keys = rider_keys(doc, scene, rider);
  ASSERT_EQ(keys.times.size(), track.lengths.size());  // every sample once, no jump keys inside
  EXPECT_EQ(keys.times.front(), 0.0);
  EXPECT_EQ(keys.times.back(), 2.0);
  EXPECT_LE(glm::length(keys.translations.front() - track.frames.front().V), kTolerance);
  EXPECT_LE(glm::length(keys.translations.back() - track.frames.back().V), kTolerance);
  for (std::size_t k = 0; k < keys.times.size(); ++k) {
    EXPECT_NEAR(keys.times[k], 2.0 * track.lengths[k] / track.length(), 1e-12) << k;
    EXPECT_LE(glm::length(keys.translations[k] - track.frames[k].V), kTolerance) << k;
  }
}

}  // namespace
}  // namespace sweep
