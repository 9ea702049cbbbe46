// Closed sweep curves: the end frame equals the start frame, the closure rotation is spread in
// proportion to arc length, tubes along closed sweeps are watertight after welding with no kink at
// the seam, open curves are untouched, and the symmetric seam mode twists less and stays watertight.
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace {

using sweep::test::distance;

/// Merges vertices closer than `tolerance` (relative to the mesh size) and rewrites the indices;
/// independent of how the builder shares vertices.
sweep::Mesh welded(const sweep::Mesh& mesh) {
  glm::dvec3 lo(mesh.positions.front()), hi = lo;
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  const double tolerance = 1e-5 * glm::length(hi - lo);
  std::vector<std::uint32_t> order(mesh.positions.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return mesh.positions[a].x < mesh.positions[b].x; });
  std::vector<std::uint32_t> representative(mesh.positions.size());
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::uint32_t v = order[k];
    representative[v] = v;
    for (std::size_t m = k; m-- > 0;) {
      const std::uint32_t w = order[m];
      if (mesh.positions[v].x - mesh.positions[w].x > tolerance) break;
      if (distance(glm::dvec3(mesh.positions[v]), glm::dvec3(mesh.positions[w])) <= tolerance) {
        representative[v] = representative[w];
        break;
      }
    }
  }
  // Triangles whose corners weld together (where a folding tube pinches) vanish.
  sweep::Mesh out = mesh;
  out.indices.clear();
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = representative[mesh.indices[t]], b = representative[mesh.indices[t + 1]],
                        c = representative[mesh.indices[t + 2]];
    if (a != b && b != c && a != c) out.indices.insert(out.indices.end(), {a, b, c});
  }
  return out;
}

/// Edges used by a number of triangles other than two, after welding.
int bad_edges_after_welding(const sweep::Mesh& mesh) {
  int bad = 0;
  for (const auto& [edge, uses] : sweep::test::edge_uses(welded(mesh))) bad += uses != 2 ? 1 : 0;
  return bad;
}

/// Edges used by one triangle only, after welding.
int boundary_edges_after_welding(const sweep::Mesh& mesh) {
  int boundary = 0;
  for (const auto& [edge, uses] : sweep::test::edge_uses(welded(mesh))) boundary += uses == 1 ? 1 : 0;
  return boundary;
}

double angle_between(const glm::vec3& a, const glm::vec3& b) {
  return std::acos(std::clamp(static_cast<double>(glm::dot(a, b)), -1.0, 1.0));
}

/// Largest change of vertex normal along the mesh edges joining sweep ring j to ring j + 1
/// (result[j]; rings of `ring` vertices laid out ring after ring, `rings` of them) and, in
/// result[rings - 1], across the seam from the last ring to ring 0.
std::vector<double> normal_jumps(const sweep::Mesh& mesh, std::size_t ring, std::size_t rings) {
  std::vector<double> jumps(rings, 0.0);
  for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) {
    const std::size_t ra = edge.first / ring, rb = edge.second / ring;
    std::size_t slot = rings;
    if (rb == ra + 1) slot = ra;
    if (ra == 0 && rb == rings - 1) slot = rings - 1;
    if (slot == rings) continue;
    jumps[slot] = std::max(jumps[slot], angle_between(mesh.normals[edge.first], mesh.normals[edge.second]));
  }
  return jumps;
}

/// Expects the seam ring of a tube along a closed sweep to turn its normals no more than the
/// sweep's ordinary rings do: the largest normal change across the seam is at most 1.5 times the
/// largest between any other two consecutive rings.
void expect_no_seam_kink(const sweep::Mesh& mesh, const sweep::CurveSamples& profile,
                         const sweep::CurveSamples& sweep_curve, const std::string& what) {
  const std::size_t ring = profile.closed ? profile.frames.size() - 1 : profile.frames.size();
  const std::size_t rings = sweep_curve.frames.size() - 1;
  const std::vector<double> jumps = normal_jumps(mesh, ring, rings);
  const double ordinary = *std::max_element(jumps.begin(), jumps.end() - 1);
  const double seam = jumps.back();
  EXPECT_GT(seam, 0.0) << what << ": no edges across the seam";
  EXPECT_LE(seam, 1.5 * ordinary + 1e-6) << what << ": seam turns normals by " << seam
                                         << " rad, other rings by at most " << ordinary;
}

TEST(ClosedSweeps, StarterTubesAreWatertightAfterWeldingWithoutASeamKink) {
  int checked = 0;
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
      for (const auto seam : {sweep::SeamMode::Full, sweep::SeamMode::Symmetric}) {
        sweep::EvaluationOptions options;
        options.frames.method = method;
        options.seam = seam;
        const sweep::Scene scene = sweep::evaluate_document(doc, options);
        for (std::size_t i = 0; i < doc.objects.size(); ++i) {
          const sweep::Object& object = doc.objects[i];
          if (object.kind() != sweep::ObjectKind::GeneralizedCylinder) continue;
          const auto& profile = scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve;
          const auto& sweep_curve =
              scene.objects[static_cast<std::size_t>(object.as<sweep::CylinderSurface>().sweep)].curve;
          if (!profile.closed || !sweep_curve.closed) continue;
          const std::string what = file.filename().string() + " " + object.name +
                                   (method == sweep::FrameMethod::Projection ? " projection" : " rmf") +
                                   (seam == sweep::SeamMode::Symmetric ? " symmetric" : " full");
          // No boundary edge; and every edge shared by exactly two triangles unless the tube
          // folds (flircle), where welding also joins vertices the fold brings together.
          EXPECT_EQ(boundary_edges_after_welding(scene.objects[i].mesh), 0) << what;
          if (scene.objects[i].diagnostics.folds.empty()) {
            EXPECT_EQ(bad_edges_after_welding(scene.objects[i].mesh), 0) << what;
          }
          EXPECT_TRUE(scene.objects[i].diagnostics.closed) << what;
          if (seam == sweep::SeamMode::Full) expect_no_seam_kink(scene.objects[i].mesh, profile, sweep_curve, what);
          ++checked;
        }
      }
    }
  }
  // weird, weirder, flircle, florus, gentorus, tor and the corner frames.
  EXPECT_GE(checked, 4 * 6);
}

TEST(ClosedSweeps, WithoutTheCorrectionWeirderHasASeamKink) {
  // The check above can fail: the original tool's seam (no correction) kinks.
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weirder.swp");
  sweep::EvaluationOptions options;
  options.frames.close_seam = false;
  const sweep::Scene scene = sweep::evaluate_document(doc, options);
  const int surface = doc.find("weirder");
  const auto& object = doc.objects[static_cast<std::size_t>(surface)];
  const auto& profile = scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve;
  const auto& sweep_curve = scene.objects[static_cast<std::size_t>(object.as<sweep::CylinderSurface>().sweep)].curve;
  const sweep::Mesh& mesh = scene.objects[static_cast<std::size_t>(surface)].mesh;
  const std::size_t ring = profile.frames.size() - 1;
  const std::size_t rings = sweep_curve.frames.size() - 1;
  const std::vector<double> jumps = normal_jumps(mesh, ring, rings);
  EXPECT_GT(jumps.back(), 1.5 * *std::max_element(jumps.begin(), jumps.end() - 1));
}

/// Largest change of vertex normal from vertex i of sweep ring j to vertex i of ring j + 1
/// (result[j]) and, in result[rings - 1], from the last ring across the seam to ring 0: how the
/// surface bends along the sweep, without the turn around the profile that normal_jumps also sees
/// on the quads' diagonals (up to 11.5 degrees on trefoil-braid's rounded square: it hid the kink).
std::vector<double> normal_turns_along_sweep(const sweep::Mesh& mesh, std::size_t ring, std::size_t rings) {
  std::vector<double> turns(rings, 0.0);
  for (std::size_t j = 0; j < rings; ++j) {
    for (std::size_t i = 0; i < ring; ++i) {
      const std::size_t next = (j + 1) % rings * ring + i;
      turns[j] = std::max(turns[j], angle_between(mesh.normals[j * ring + i], mesh.normals[next]));
    }
  }
  return turns;
}

TEST(ClosedSweeps, ArtifactTubesBendAlongTheSweepNoMoreAtTheSeam) {
  // The showcase models' closed tubes: a scale or twist graph must join its ends as smoothly as
  // the rest of the tube does. trefoil-braid's pulse once started at a peak, where an open
  // Catmull-Rom's reflected end neighbours make a corner (scale slope -7.2 after the seam, +7.2
  // before it, 0 at the other peaks): its normals turned 10.0 degrees across the seam and at most
  // 5.0 between any other two rings.
  int checked = 0;
  for (const auto& file : sweep::test::artifact_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const sweep::Object& object = doc.objects[i];
      if (object.kind() != sweep::ObjectKind::GeneralizedCylinder) continue;
      const auto& profile = scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve;
      const auto& sweep_curve =
          scene.objects[static_cast<std::size_t>(object.as<sweep::CylinderSurface>().sweep)].curve;
      if (!profile.closed || !sweep_curve.closed) continue;
      const std::vector<double> turns =
          normal_turns_along_sweep(scene.objects[i].mesh, profile.frames.size() - 1, sweep_curve.frames.size() - 1);
      const double ordinary = *std::max_element(turns.begin(), turns.end() - 1);
      const double seam = turns.back();
      EXPECT_LE(seam, 1.5 * ordinary) << file.filename().string() << " " << object.name
                                      << ": the seam turns normals by " << seam << " rad, other rings by at most "
                                      << ordinary;
      ++checked;
    }
  }
  // chess-queen's crown and necklace, trefoil-braid's braid.
  EXPECT_GE(checked, 3);
}

/// The sweep curve of weirder.swp.
sweep::Object weirder_sweep() {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weirder.swp");
  return doc.objects[static_cast<std::size_t>(doc.find("sweep"))];
}

TEST(ClosedSweeps, ClosureRotationIsSpreadInProportionToArcLength) {
  const sweep::Object object = weirder_sweep();
  for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
    const sweep::CurveSamples raw = sweep::evaluate_curve(object, {method, false});
    const sweep::CurveSamples closed = sweep::evaluate_curve(object, {method, true});
    ASSERT_TRUE(closed.closed);
    ASSERT_EQ(raw.frames.size(), closed.frames.size());
    const auto& a = raw.frames;
    const auto& b = closed.frames;
    // The measured angle: from the start normal to the propagated end normal, about T.
    const glm::dvec3 t0 = a.front().T;
    const glm::dvec3 end = a.back().N - glm::dot(a.back().N, t0) * t0;
    const double gap = std::atan2(glm::dot(glm::cross(a.front().N, end), t0), glm::dot(a.front().N, end));
    EXPECT_NEAR(closed.seam_angle, gap, 1e-12);
    EXPECT_GT(std::abs(gap), 0.01) << "weirder's sweep should not close by itself";
    EXPECT_EQ(raw.seam_angle, 0.0);
    double total = 0.0;
    for (std::size_t i = 1; i < a.size(); ++i) total += distance(a[i].V, a[i - 1].V);
    double travelled = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i > 0) travelled += distance(a[i].V, a[i - 1].V);
      EXPECT_EQ(a[i].V, b[i].V) << i;
      if (i + 1 < a.size()) {
        EXPECT_EQ(a[i].T, b[i].T) << i;
      }
      const double turned = std::atan2(glm::dot(glm::cross(a[i].N, b[i].N), a[i].T), glm::dot(a[i].N, b[i].N));
      EXPECT_NEAR(turned, -gap * travelled / total, 1e-9) << i;
    }
    // The end frame is the start frame.
    EXPECT_EQ(b.back().T, b.front().T);
    EXPECT_EQ(b.back().N, b.front().N);
    EXPECT_EQ(b.back().B, b.front().B);
  }
}

// --seam index, the course tool's rule: frame i turns back by gap * i / (n - 1), whatever the
// spacing of the samples (weirder's sweep is sampled unevenly in arc length).
TEST(ClosedSweeps, TheIndexSeamSpreadsTheClosureRotationEvenlyBySample) {
  const sweep::Object object = weirder_sweep();
  for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
    const sweep::CurveSamples raw = sweep::evaluate_curve(object, {method, false});
    const sweep::CurveSamples by_index = sweep::evaluate_curve(object, {method, true, sweep::SeamSpread::SampleIndex});
    const sweep::CurveSamples by_length = sweep::evaluate_curve(object, {method, true});
    ASSERT_TRUE(by_index.closed);
    const auto& a = raw.frames;
    const auto& b = by_index.frames;
    const double gap = by_index.seam_angle;
    EXPECT_NEAR(gap, by_length.seam_angle, 1e-12) << "the same angle, spread another way";
    const double last = static_cast<double>(a.size() - 1);
    double largest_difference = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(a[i].V, b[i].V) << i;
      const double turned = std::atan2(glm::dot(glm::cross(a[i].N, b[i].N), a[i].T), glm::dot(a[i].N, b[i].N));
      EXPECT_NEAR(turned, -gap * static_cast<double>(i) / last, 1e-9) << i;
      EXPECT_NEAR(glm::dot(b[i].N, b[i].T), 0.0, 1e-12) << i;
      largest_difference = std::max(largest_difference, distance(b[i].N, by_length.frames[i].N));
    }
    EXPECT_GT(largest_difference, 1e-3) << "weirder's uneven samples make the two rules differ";
    EXPECT_EQ(b.back().N, b.front().N);
  }
}

TEST(ClosedSweeps, DetectionToleratesFloatNoiseButNotAnOpening) {
  sweep::Object object = weirder_sweep();
  const std::size_t n = object.as<sweep::PointsPart>().points.size();
  sweep::Object noisy = object;
  for (std::size_t k = n - 3; k < n; ++k) noisy.as<sweep::PointsPart>().points[k] += glm::dvec3(1e-9, -1e-9, 1e-9);
  const sweep::CurveSamples noisy_curve = sweep::evaluate_curve(noisy);
  EXPECT_TRUE(noisy_curve.closed);
  EXPECT_EQ(noisy_curve.frames.back().N, noisy_curve.frames.front().N);
  sweep::Object opened = object;
  for (std::size_t k = n - 3; k < n; ++k) opened.as<sweep::PointsPart>().points[k] += glm::dvec3(1e-2, 0, 0);
  const sweep::CurveSamples opened_curve = sweep::evaluate_curve(opened);
  EXPECT_FALSE(opened_curve.closed);
  EXPECT_EQ(opened_curve.seam_angle, 0.0);
}

TEST(OpenSweeps, FramesAreExactlyThePropagatedOnes) {
  // An open 3D curve comes out as the plain propagation, whatever the seam option.
  const std::vector<glm::dvec3> points{{0, 0, 0}, {1, 2, 1}, {3, -1, 2}, {4, 1, 3}, {2, 2, 2}, {0, 1, 0}};
  for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
    const sweep::CurveSamples with = sweep::evaluate_bspline(points, 9, false, {method, true});
    const sweep::CurveSamples without = sweep::evaluate_bspline(points, 9, false, {method, false});
    ASSERT_FALSE(with.closed);
    std::vector<sweep::Frame> propagated = with.frames;
    sweep::compute_frames(propagated, false, {method, false});
    for (std::size_t i = 0; i < with.frames.size(); ++i) {
      EXPECT_EQ(with.frames[i].N, without.frames[i].N) << i;
      EXPECT_EQ(with.frames[i].N, propagated[i].N) << i;
      EXPECT_EQ(with.frames[i].B, propagated[i].B) << i;
    }
  }
}

TEST(ClosedSweeps, PlanarClosedSweepsKeepBinormalZ) {
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (const sweep::Object& object : doc.objects) {
      if (!sweep::is_planar_curve(object.kind())) continue;
      const sweep::CurveSamples curve = sweep::evaluate_curve(object);
      EXPECT_EQ(curve.seam_angle, 0.0) << file;
      for (const sweep::Frame& f : curve.frames) EXPECT_EQ(f.B, glm::dvec3(0, 0, 1)) << file;
    }
  }
}

/// A circle profile (`steps` samples) along weirder's closed 3D sweep.
struct CircleAlongWeirder {
  sweep::CurveSamples profile;
  sweep::CurveSamples sweep_curve;
};
CircleAlongWeirder circle_along_weirder(int steps, sweep::FrameMethod method = sweep::FrameMethod::RotationMinimizing) {
  return {sweep::evaluate_circle(0.2, steps), sweep::evaluate_curve(weirder_sweep(), {method})};
}

TEST(SymmetricSeam, ProfileSymmetryOfCirclesSquaresAndIrregularProfiles) {
  for (int steps : {3, 8, 50}) {
    const sweep::ProfileSymmetry s = sweep::profile_symmetry(sweep::evaluate_circle(1.0, steps));
    EXPECT_EQ(s.order, steps);
    EXPECT_EQ(s.shift, 1);
  }
  // A B-spline square, counterclockwise and clockwise: 4-fold, moving by one piece's samples.
  const std::vector<glm::dvec3> ccw{{1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  const std::vector<glm::dvec3> cw(ccw.rbegin(), ccw.rend());
  const sweep::ProfileSymmetry a = sweep::profile_symmetry(sweep::evaluate_bspline(ccw, 5, true));
  EXPECT_EQ(a.order, 4);
  EXPECT_EQ(a.shift, 5);
  const sweep::ProfileSymmetry b = sweep::profile_symmetry(sweep::evaluate_bspline(cw, 5, true));
  EXPECT_EQ(b.order, 4);
  EXPECT_EQ(b.shift, -5);
  // The same square moved off the origin turns about the origin onto something else.
  std::vector<glm::dvec3> moved = ccw;
  for (auto& p : moved) p.x += 0.5;
  EXPECT_EQ(sweep::profile_symmetry(sweep::evaluate_bspline(moved, 5, true)).order, 1);
  // weirder's own profile has no symmetry; an open curve has none either.
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weirder.swp");
  EXPECT_EQ(
      sweep::profile_symmetry(sweep::evaluate_curve(doc.objects[static_cast<std::size_t>(doc.find("profile"))])).order,
      1);
  EXPECT_EQ(sweep::profile_symmetry(
                sweep::evaluate_bezier(std::vector<glm::dvec3>{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}}, 4, true))
                .order,
            1);
}

TEST(SymmetricSeam, CircleTubeTwistsLessAndStaysWatertight) {
  for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
    for (int steps : {6, 24, 50}) {
      const CircleAlongWeirder c = circle_along_weirder(steps, method);
      sweep::SweepDiagnostics full, symmetric;
      const sweep::Mesh full_mesh =
          sweep::build_generalized_cylinder(c.profile, c.sweep_curve, sweep::SeamMode::Full, &full);
      const sweep::Mesh symmetric_mesh =
          sweep::build_generalized_cylinder(c.profile, c.sweep_curve, sweep::SeamMode::Symmetric, &symmetric);
      const std::string what = std::to_string(steps) + " steps";
      EXPECT_NEAR(full.seam_angle, c.sweep_curve.seam_angle, 1e-15) << what;
      EXPECT_LE(std::abs(symmetric.seam_angle), std::numbers::pi / steps + 1e-12) << what;
      // Less twist whenever the closure angle exceeds half a symmetry turn; otherwise the same.
      if (std::abs(full.seam_angle) > std::numbers::pi / steps) {
        EXPECT_LT(symmetric.total_twist, full.total_twist - 1e-3) << what;
      } else {
        EXPECT_NEAR(symmetric.total_twist, full.total_twist, 1e-12) << what;
      }
      EXPECT_EQ(bad_edges_after_welding(symmetric_mesh), 0) << what;
      EXPECT_EQ(bad_edges_after_welding(full_mesh), 0) << what;
      ASSERT_EQ(symmetric_mesh.vertex_count(), full_mesh.vertex_count());
      // The end ring lands on the start ring turned by whole symmetry steps: every seam edge
      // joins vertices no farther apart than ordinary edges along the sweep.
      const std::size_t ring = static_cast<std::size_t>(steps);
      const std::size_t rings = c.sweep_curve.frames.size() - 1;
      double longest_seam = 0.0, longest_ordinary = 0.0;
      for (const auto& [edge, uses] : sweep::test::edge_uses(symmetric_mesh)) {
        const double length = distance(glm::dvec3(symmetric_mesh.positions[edge.first]),
                                       glm::dvec3(symmetric_mesh.positions[edge.second]));
        const std::size_t ra = edge.first / ring, rb = edge.second / ring;
        if ((ra == 0 && rb == rings - 1) || (rb == 0 && ra == rings - 1)) {
          longest_seam = std::max(longest_seam, length);
        } else if (ra != rb) {
          longest_ordinary = std::max(longest_ordinary, length);
        }
      }
      EXPECT_LE(longest_seam, 1.5 * longest_ordinary) << what;
    }
  }
}

TEST(SymmetricSeam, AsymmetricProfileGetsTheFullCorrection) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weirder.swp");
  sweep::EvaluationOptions full_options, symmetric_options;
  symmetric_options.seam = sweep::SeamMode::Symmetric;
  const sweep::Scene full = sweep::evaluate_document(doc, full_options);
  const sweep::Scene symmetric = sweep::evaluate_document(doc, symmetric_options);
  const auto surface = static_cast<std::size_t>(doc.find("weirder"));
  EXPECT_EQ(full.objects[surface].mesh.positions, symmetric.objects[surface].mesh.positions);
  EXPECT_EQ(full.objects[surface].mesh.indices, symmetric.objects[surface].mesh.indices);
  EXPECT_EQ(full.objects[surface].diagnostics.seam_angle, symmetric.objects[surface].diagnostics.seam_angle);
}

}  // namespace
