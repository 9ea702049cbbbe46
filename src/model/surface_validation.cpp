// The checks of the curves a surface refers to, shared by the reader (which locates the message
// at the reference or clause) and the editor (which shows the same words).
#include "model/surface_validation.hpp"

#include "base/number_text.hpp"
#include "base/precondition.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/sweep_controls.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace sweep {
namespace {

CurveSamples evaluated(const Document& doc, int index) {
  return evaluate_curve(doc.objects[static_cast<std::size_t>(index)]);
}

std::optional<CurveProblem> check_graph_reference(const Document& doc, int index, GraphRole role) {
  if (index < 0) return std::nullopt;
  std::optional<CurveProblem> problem = check_graph(evaluated(doc, index), role);
  if (problem) problem->at = role == GraphRole::Scale ? CurveProblem::At::Scale : CurveProblem::At::Twist;
  return problem;
}

/// A twist on a closed sweep must bring the profile back onto itself at the seam.
std::optional<CurveProblem> check_closed_twist(const Document& doc, const CylinderSurface& surface) {
  if (surface.twist_curve < 0 && surface.twist == 0.0) return std::nullopt;
  const Object& sweep = doc.objects[static_cast<std::size_t>(surface.sweep)];
  if (!evaluate_curve(sweep).closed) return std::nullopt;
  const CurveSamples twist_curve = surface.twist_curve >= 0 ? evaluated(doc, surface.twist_curve) : CurveSamples{};
  SweepControls controls;
  controls.twist_degrees = surface.twist;
  if (surface.twist_curve >= 0) controls.twist_curve = &twist_curve;
  const double total = total_twist_degrees(controls);
  const int order = profile_symmetry(evaluated(doc, surface.profile)).order;
  const double unit = 360.0 / order;
  const double turns = total / unit;
  if (std::abs(turns - std::round(turns)) <= 1e-9 * std::max(1.0, std::abs(turns))) return std::nullopt;
  CurveProblem problem;
  problem.at = CurveProblem::At::Twist;
  const std::string sweep_name = "'" + sweep.name + "'";
  problem.expected =
      order == 1 ? "expected a twist ending at a multiple of 360 degrees, since the sweep " + sweep_name + " is closed"
                 : "expected a twist ending at a multiple of " + number_text(unit) + " degrees (360 / " +
                       std::to_string(order) + " for the profile's " + std::to_string(order) +
                       "-fold symmetry), since the sweep " + sweep_name + " is closed";
  if (surface.twist_curve >= 0) problem.note = "it ends " + number_text(total) + " degrees from where it starts";
  return problem;
}

/// The curves a surface names: profile, path, second rail, scale, twist.
[[maybe_unused]] std::vector<int> curve_references(const Object& surface) {
  const SweptCurves curves = swept_curves(surface);
  std::vector<int> out{curves.profile, curves.path, curves.rail2};
  if (const auto* cylinder = surface.find<CylinderSurface>())
    out.insert(out.end(), {cylinder->scale, cylinder->twist_curve});
  return out;
}

std::optional<CurveProblem> check_birail(const Document& doc, const BirailSurface& surface) {
  const CurveSamples profile = evaluated(doc, surface.profile);
  const glm::dvec3 chord = profile.frames.back().V - profile.frames.front().V;
  double size = 0.0;
  for (const Frame& f : profile.frames) size = std::max(size, std::abs(f.V.x) + std::abs(f.V.y));
  if (profile.closed || glm::length(chord) <= 1e-9 * size) {
    return CurveProblem{CurveProblem::At::Profile,
                        "expected a profile whose ends are apart (its first sample rides RAIL1, its last RAIL2)",
                        "its first and last samples meet"};
  }
  const bool first_closed = evaluated(doc, surface.rail1).closed;
  if (evaluated(doc, surface.rail2).closed != first_closed) {
    const std::string first = "'" + doc.objects[static_cast<std::size_t>(surface.rail1)].name + "'";
    return CurveProblem{CurveProblem::At::Rail2,
                        first_closed ? "expected a closed second rail, like the first rail " + first
                                     : "expected an open second rail, like the first rail " + first,
                        std::string("it is ") + (first_closed ? "open" : "closed")};
  }
  return std::nullopt;
}

}  // namespace

std::optional<CurveProblem> check_surface_curves(const Document& doc, const Object& surface) {
  SWEEP_EXPECTS(std::ranges::all_of(curve_references(surface),
                                    [&](int i) {
                                      return i < 0 || (static_cast<std::size_t>(i) < doc.objects.size() &&
                                                       is_curve(doc.objects[static_cast<std::size_t>(i)].kind()));
                                    }),
                "the references are valid indices of curves in doc");
  if (const auto* birail = surface.find<BirailSurface>()) return check_birail(doc, *birail);
  const auto* cylinder = surface.find<CylinderSurface>();
  if (!cylinder) return std::nullopt;
  if (auto problem = check_graph_reference(doc, cylinder->scale, GraphRole::Scale)) return problem;
  if (auto problem = check_graph_reference(doc, cylinder->twist_curve, GraphRole::Twist)) return problem;
  return check_closed_twist(doc, *cylinder);
}

std::optional<CurveProblem> check_subdivision_scheme(const SubdivisionSurface& subd, const Object& source,
                                                     const std::string& source_name) {
  if (!subd.loop) return std::nullopt;
  const std::string expected = "expected a triangle cage for loop";
  if (const auto* cage = source.find<PolygonMeshSurface>()) {
    const auto it = std::find_if(cage->face_sizes.begin(), cage->face_sizes.end(), [](int n) { return n != 3; });
    if (it == cage->face_sizes.end()) return std::nullopt;
    return CurveProblem{CurveProblem::At::Profile, expected,
                        "face " + std::to_string(it - cage->face_sizes.begin() + 1) + " of " + source_name + " has " +
                            std::to_string(*it) + " vertices; Catmull-Clark, the default, takes any polygons"};
  }
  if (source.kind() == ObjectKind::Subdivision) return std::nullopt;
  return CurveProblem{CurveProblem::At::Profile, expected,
                      source_name + " is a grid of quads (" + std::string(keyword(source.kind())) +
                          "); Catmull-Clark, the default, takes them"};
}

std::string expected_reference(const char* role, bool planar_only) {
  static const std::string planar = "expected the name of a 2D curve (" + keyword_list(is_planar_curve) + ")";
  return (planar_only ? planar : std::string("expected the name of a curve")) + " defined above as " + role;
}

std::string kind_description(ObjectKind kind) {
  const char* what = is_surface(kind) ? "a surface (" : is_material(kind) ? "a material (" : "a curve (";
  return std::string(what) + std::string(keyword(kind)) + ")";
}

std::optional<CurveProblem> check_reference_kind(const Object& target, const char* role, bool planar_only) {
  const CurveProblem::At at = CurveProblem::At::Profile;
  if (!is_curve(target.kind())) {
    return CurveProblem{at, expected_reference(role, planar_only), "it is " + kind_description(target.kind())};
  }
  if (planar_only && !is_planar_curve(target.kind())) {
    return CurveProblem{at, expected_reference(role, planar_only),
                        "it is a 3D curve (" + std::string(keyword(target.kind())) + ")"};
  }
  return std::nullopt;
}

}  // namespace sweep
