// Property (rapidcheck): the drag rules keep a smooth joint smooth. A random two-piece bez2 with a
// smooth or symmetric joint 3 goes through a few random drags of the joint and its handles, each
// a few frames long with the type decided when it began (as the viewer drags), applied to a
// Document through move_points. Afterwards the joint still classifies smooth or symmetric, the
// pieces' tangents at the joint agree to 1e-9, the evaluated profile has no corner there, and the
// surface of revolution of it has vertex normals across the joint's ring that are normal to the
// arriving tangent too (no crease).
#include "editor/bezier_joints.hpp"
#include "geometry/curves/bezier.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/scene.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <numbers>
#include <vector>

namespace sweep::editor {
namespace {

using glm::dvec3;

constexpr int kSteps = 8;    // samples per piece: the joint is sample kSteps
constexpr int kCopies = 12;  // the srev's copies

/// A point of the box [1, 3] x [-1, 1] on a grid of 1/8.
dvec3 box_point() {
  return {1.0 + *rc::gen::inRange(0, 17) / 8.0, -1.0 + *rc::gen::inRange(0, 17) / 8.0, 0.0};
}

/// A handle's offset from its joint: 1/8 to 7/8 long (so the profile stays off the axis), at a
/// whole number of degrees.
dvec3 handle_offset() {
  const double length = *rc::gen::inRange(1, 8) / 8.0;
  const double angle = *rc::gen::inRange(0, 360) * std::numbers::pi / 180.0;
  return length * dvec3(std::cos(angle), std::sin(angle), 0.0);
}

/// Profile `profile` (a random open bez2 of two pieces whose joint 3 is smooth, or symmetric) and
/// its surface of revolution.
Document random_document() {
  Document doc = io::parse_swp(
      "bez2 profile 8 7\n[1 0]\n[1 1]\n[1 2]\n[1 3]\n[1 4]\n[1 5]\n[1 6]\n"
      "srev lathe 12 profile\n");
  const dvec3 joint = box_point();
  const double angle = *rc::gen::inRange(0, 360) * std::numbers::pi / 180.0;
  const dvec3 direction(std::cos(angle), std::sin(angle), 0.0);
  const double in = *rc::gen::inRange(1, 8) / 8.0;
  const double out = *rc::gen::arbitrary<bool>() ? in : *rc::gen::inRange(1, 8) / 8.0;
  doc.objects[0].as<PointsPart>().points = {box_point(),
                                            box_point(),
                                            joint - in * direction,
                                            joint,
                                            joint + out * direction,
                                            box_point(),
                                            box_point() + dvec3(0.0, 3.0, 0.0)};
  return doc;
}

/// One drag of point 2, 3 or 4 to a random target in 1 to 3 frames, by the rule of the joint's
/// type when it began.
void random_drag(Document& doc) {
  const int point = *rc::gen::inRange(2, 5);
  const dvec3 start = doc.objects[0].as<PointsPart>().points[static_cast<std::size_t>(point)];
  const dvec3 joint = doc.objects[0].as<PointsPart>().points[3];
  const dvec3 target = point == 3 ? box_point() : joint + handle_offset();
  const JointType type = classify_joint(doc.objects[0], 3);
  RC_ASSERT(type != JointType::Corner);
  const int frames = *rc::gen::inRange(1, 4);
  for (int frame = 1; frame <= frames; ++frame) {
    const dvec3 to = frame == frames ? target : start + (target - start) * (double(frame) / frames);
    move_points(doc, 0, drag_moves(doc.objects[0], point, to, type, false));
  }
}

/// |sin| of the angle between the pieces' tangents at joint 3 (from the pieces' derivatives).
double tangent_jump(const std::vector<dvec3>& p) {
  const dvec3 arriving = evaluate_bezier_piece({p[0], p[1], p[2], p[3]}, 1.0).d1;
  const dvec3 leaving = evaluate_bezier_piece({p[3], p[4], p[5], p[6]}, 0.0).d1;
  RC_ASSERT(glm::dot(arriving, leaving) > 0.0);
  return glm::length(glm::cross(arriving, leaving)) / (glm::length(arriving) * glm::length(leaving));
}

RC_GTEST_PROP(BezierJointProperty, DragsKeepASmoothJointSmoothOnTheCurveAndItsSurface, ()) {
  Document doc = random_document();
  const int drags = *rc::gen::inRange(1, 6);
  for (int k = 0; k < drags; ++k) {
    random_drag(doc);
    RC_ASSERT(classify_joint(doc.objects[0], 3) != JointType::Corner);
    RC_ASSERT(tangent_jump(doc.objects[0].as<PointsPart>().points) <= 1e-9);
  }
  const std::vector<dvec3>& p = doc.objects[0].as<PointsPart>().points;
  const dvec3 arriving = glm::normalize(evaluate_bezier_piece({p[0], p[1], p[2], p[3]}, 1.0).d1);

  const Scene scene = evaluate_document(doc);
  const CurveSamples& profile = scene.objects[0].curve;
  RC_ASSERT(profile.frames.size() == std::size_t{2 * kSteps + 1});
  RC_ASSERT(profile.parameters[kSteps] == 1.0);
  for (const Corner& corner : profile.corners) RC_ASSERT(corner.sample != std::size_t{kSteps});
  // Each copy's vertex on the joint's ring: a unit normal across both pieces' tangents (the
  // tangent turned with the copy: the dot product is the same for every turn about y).
  const Mesh& mesh = scene.objects[1].mesh;
  RC_ASSERT(mesh.normals.size() == profile.frames.size() * kCopies);
  for (std::size_t copy = 0; copy < kCopies; ++copy) {
    const glm::vec3 n = mesh.normals[copy * profile.frames.size() + kSteps];
    const dvec3 normal(n.x, n.y, n.z);
    RC_ASSERT(std::abs(glm::length(normal) - 1.0) <= 1e-6);
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(copy) / kCopies;
    const dvec3 turned(arriving.x * std::cos(angle), arriving.y, -arriving.x * std::sin(angle));
    RC_ASSERT(std::abs(glm::dot(normal, turned)) <= 1e-6);
  }
}

}  // namespace
}  // namespace sweep::editor
