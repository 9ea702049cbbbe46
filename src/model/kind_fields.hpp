#pragma once
// What every kind type (kind_*.hpp, gathered in object.hpp) is built from: its parts and traits
// (parts.hpp), its clauses (clause.hpp), the range checks its fields use (curve_parameters.hpp),
// and the list of fixed fields it declares, read and written from that one list.
#include "model/clause.hpp"
#include "model/curve_parameters.hpp"
#include "model/parts.hpp"

#include <cmath>
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

/// Where a surface's vertex count is reported: at its STEPS or at its keyword.
enum class VerticesAt : std::uint8_t { Steps, Keyword };

/// "expected at least 2 Catmull-Rom control points" for too few points of a kind through them.
std::string interpolating_count_problem(std::int64_t count, const char* family);

}  // namespace sweep
