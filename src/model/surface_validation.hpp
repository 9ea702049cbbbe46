#pragma once
// What the curves a surface refers to must satisfy (its scale and twist graphs, a closed sweep's
// twist, a birail's rails and profile), for the reader and the editor alike.
#include "geometry/sweep_controls.hpp"
#include "model/document.hpp"

#include <optional>

namespace sweep {

/// The problem with the curves `surface` refers to, evaluated by their STEPS or clauses: its
/// scale and twist graphs (check_graph); a twist on a closed sweep must end at a multiple of 360
/// degrees, or of 360 / k for a profile with k-fold symmetry (ProfileSymmetry); a birail's rails
/// must be both open or both closed and its profile's ends apart. nullopt if none, and for kinds
/// without such references. Precondition: the references are valid indices of curves in `doc`.
std::optional<CurveProblem> check_surface_curves(const Document& doc, const Object& surface);

/// The problem with a subd's scheme for its cage `source` (called `source_name` in the note):
/// Loop takes triangles only, so a mesh with another face or a grid of quads cannot take it.
/// nullopt if none (the size of the refined mesh is a cap: caps.hpp).
std::optional<CurveProblem> check_subdivision_scheme(const SubdivisionSurface& subd, const Object& source,
                                                     const std::string& source_name);

}  // namespace sweep
