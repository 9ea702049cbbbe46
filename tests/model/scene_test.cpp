// Scene bookkeeping: a change to one curve re-evaluates exactly that curve and the surfaces that
// use it, bumping exactly their revisions.
#include "model/evaluation/scene.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

// 0 profile, 1 sweep, 2 other (unused), 3 srev of profile, 4 gcyl profile x sweep,
// 5 gcyl other x sweep, 6 lone (unused 3D curve).
const char* const kText =
    "bez2 profile 4 4 [-1 1] [-2 0.5] [-2 -0.5] [-1 -1]\n"
    "circ sweep 12 3\n"
    "circ other 8 0.5\n"
    "srev turned 10 profile\n"
    "gcyl tube profile sweep\n"
    "gcyl ring other sweep\n"
    "bsp3 lone 3 4 [0 0 0] [1 0 0] [1 1 0] [1 1 1]\n";

TEST(Scene, DependentsAreTheObjectAndTheSurfacesUsingIt) {
  const sweep::Document doc = sweep::io::parse_swp(kText);
  EXPECT_EQ(sweep::dependents_of(doc, 0), (std::vector<int>{0, 3, 4}));
  EXPECT_EQ(sweep::dependents_of(doc, 1), (std::vector<int>{1, 4, 5}));
  EXPECT_EQ(sweep::dependents_of(doc, 2), (std::vector<int>{2, 5}));
  EXPECT_EQ(sweep::dependents_of(doc, 3), (std::vector<int>{3}));
  EXPECT_EQ(sweep::dependents_of(doc, 4), (std::vector<int>{4}));
  EXPECT_EQ(sweep::dependents_of(doc, 6), (std::vector<int>{6}));
  EXPECT_TRUE(sweep::dependents_of(doc, -1).empty());
  EXPECT_TRUE(sweep::dependents_of(doc, 7).empty());
}

TEST(Scene, EveryObjectGetsADistinctRevision) {
  const sweep::Document doc = sweep::io::parse_swp(kText);
  const sweep::Scene scene = sweep::evaluate_document(doc);
  ASSERT_EQ(scene.objects.size(), doc.objects.size());
  std::vector<std::uint64_t> revisions;
  for (const auto& o : scene.objects) revisions.push_back(o.revision);
  std::sort(revisions.begin(), revisions.end());
  EXPECT_EQ(std::adjacent_find(revisions.begin(), revisions.end()), revisions.end());
  EXPECT_GT(revisions.front(), 0u);
  // Curves carry samples, surfaces carry meshes.
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const bool surface = sweep::is_surface(doc.objects[i].kind());
    EXPECT_EQ(scene.objects[i].curve.frames.empty(), surface) << i;
    EXPECT_EQ(scene.objects[i].mesh.positions.empty(), !surface) << i;
  }
}

TEST(Scene, ReevaluateTouchesOnlyTheChangedCurveAndItsSurfaces) {
  sweep::Document doc = sweep::io::parse_swp(kText);
  sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Scene before = scene;

  // Move a control point of the profile, as the editor would.
  doc.objects[0].as<sweep::PointsPart>().points[1].x = -3.0;
  const std::vector<int> changed = sweep::reevaluate(scene, doc, 0);
  EXPECT_EQ(changed, (std::vector<int>{0, 3, 4}));

  const sweep::Scene fresh = sweep::evaluate_document(doc);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const bool touched = std::find(changed.begin(), changed.end(), static_cast<int>(i)) != changed.end();
    if (touched) {
      EXPECT_GT(scene.objects[i].revision, before.objects[i].revision) << i;
    } else {
      EXPECT_EQ(scene.objects[i].revision, before.objects[i].revision) << i;
    }
    // Whatever was re-evaluated now matches the edited document; nothing else moved.
    const auto& now = scene.objects[i];
    EXPECT_EQ(now.mesh.positions, fresh.objects[i].mesh.positions) << i;
    EXPECT_EQ(now.mesh.indices, fresh.objects[i].mesh.indices) << i;
    ASSERT_EQ(now.curve.frames.size(), fresh.objects[i].curve.frames.size()) << i;
    for (std::size_t s = 0; s < now.curve.frames.size(); ++s)
      EXPECT_EQ(now.curve.frames[s].V, fresh.objects[i].curve.frames[s].V);
    if (!touched) {
      EXPECT_EQ(now.mesh.positions, before.objects[i].mesh.positions) << i;
    }
  }
  // The edit really changed the surfaces that use the profile.
  EXPECT_NE(scene.objects[3].mesh.positions, before.objects[3].mesh.positions);
  EXPECT_NE(scene.objects[4].mesh.positions, before.objects[4].mesh.positions);
}

TEST(Scene, ReevaluatingTheSweepLeavesTheProfileAndItsRevolutionAlone) {
  sweep::Document doc = sweep::io::parse_swp(kText);
  sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Scene before = scene;
  doc.objects[1].as<sweep::RadiusPart>().radius = 4.0;
  EXPECT_EQ(sweep::reevaluate(scene, doc, 1), (std::vector<int>{1, 4, 5}));
  for (int i : {0, 2, 3, 6})
    EXPECT_EQ(scene.objects[static_cast<std::size_t>(i)].revision, before.objects[static_cast<std::size_t>(i)].revision)
        << i;
  for (int i : {1, 4, 5})
    EXPECT_GT(scene.objects[static_cast<std::size_t>(i)].revision, before.objects[static_cast<std::size_t>(i)].revision)
        << i;
}

TEST(Scene, ReevaluatingASurfaceTouchesOnlyIt) {
  sweep::Document doc = sweep::io::parse_swp(kText);
  sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Scene before = scene;
  doc.objects[3].as<sweep::CopiesPart>().copies = 5;
  EXPECT_EQ(sweep::reevaluate(scene, doc, 3), (std::vector<int>{3}));
  EXPECT_EQ(scene.objects[3].mesh.vertex_count(), 5u * 5u);  // 4 * 1 + 1 profile samples, 5 copies
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (i == 3) {
      EXPECT_GT(scene.objects[i].revision, before.objects[i].revision);
    } else {
      EXPECT_EQ(scene.objects[i].revision, before.objects[i].revision) << i;
    }
  }
}

}  // namespace
