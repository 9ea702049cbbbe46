#pragma once
// What every kind type (kind_*.hpp, gathered in object.hpp) is built from: its parts and traits
// (parts.hpp), its clauses (clause.hpp), the range checks its fields use (curve_parameters.hpp),
// and the list of fixed fields it declares, read and written from that one list.
#include "model/curve_parameters.hpp"
#include "model/kinds/clause.hpp"
#include "model/kinds/parts.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sweep {

// Each kind's `fields(self, f)` lists its fixed fields after the name, in file order, to a
// visitor: the SWP reader reads them and the writer writes them from this one list, so a kind's
// syntax is written once. A visitor has:
//   f.steps(steps)                      STEPS, a whole number from 1 to limits::kMaxSteps
//   f.points(self, what)                a point count (`what`: "a control point count") checked by
//                                       Kind::count_problem and the caps, then the clauses and the
//                                       points (the last field)
//   f.samples(n)                        the curve's sample count against the caps, reported at STEPS
//   f.samples_by(n, field)              the same, given by STEPS and the field just read (TURNS)
//   f.number(name, value[, check])      a number; check() is "" or the "expected ..." text; the
//                                       editor's parameter of that name (FieldName, parts.hpp)
//   f.integer(name, value, low, high[, check])
//   f.reference(role, index, planar)    the name of a curve defined above
//   f.vertices(at)                      the surface's vertices (caps.hpp) against the caps
//   f.custom(self)                      a syntax of its own (patches, cages, subd, material, a rider's model)
// and `kind_clauses<Kind>` beside each kind lists its optional clauses (clause.hpp).
//
// Each curve kind's `templates(t)` lists its Create-panel templates (none: an empty body; a
// curve kind without it does not compile), each as
//   t.add(label, base_name, order, fill)  the panel's label ("open B-spline (2D)"), the stem of a
//                                         new curve's name, its place in the panel's list (lowest
//                                         first), and fill(Kind&), which gives the new curve its
//                                         data (STEPS left 0 means 16)

/// `distinct` with its first `repeats` points repeated at the end: a closed control polygon of a
/// kind whose layout repeats that many (PointLayout::seam_repeats).
inline std::vector<glm::dvec3> closed_points(std::vector<glm::dvec3> distinct, std::size_t repeats) {
  for (std::size_t k = 0; k < repeats; ++k) distinct.push_back(distinct[k]);
  return distinct;
}

/// The open 2D templates' wave through 5 points (cr2, kb2). Open 2D templates are profiles: left of
/// the y axis, top to bottom, as the course's are, so a surface of revolution of one is a solid's
/// side rather than a flat dome.
inline std::vector<glm::dvec3> wave_profile() {
  using P = glm::dvec3;
  return {P(-0.3, 0.6, 0), P(-0.45, 0.3, 0), P(-0.3, 0, 0), P(-0.45, -0.3, 0), P(-0.3, -0.6, 0)};
}

/// Where a surface's vertex count is reported: at its STEPS or at its keyword.
enum class VerticesAt : std::uint8_t { Steps, Keyword };

/// "expected at least 2 Catmull-Rom control points" for too few points of a kind through them.
std::string interpolating_count_problem(std::int64_t count, const char* family);

}  // namespace sweep
