#pragma once
// What the curves a surface refers to must satisfy (its scale and twist graphs, a closed sweep's
// twist, a birail's rails and profile), for the reader and the editor alike.
#include "geometry/surfaces/sweep_controls.hpp"
#include "model/document.hpp"

#include <optional>

namespace sweep {

/// The problem with the curves `surface` refers to, evaluated by their STEPS or clauses: its
/// scale and twist graphs (check_graph); a twist on a closed sweep must end at a multiple of 360
/// degrees, or of 360 / k for a profile with k-fold symmetry (ProfileSymmetry); a birail's rails
/// must be both open or both closed and its profile's ends apart. nullopt if none, and for kinds
/// without such references. Precondition: the references are valid indices of curves in `doc`.
std::optional<CurveProblem> check_surface_curves(const Document& doc, const Object& surface);

/// What a surface's reference as `role` ("profile", "a scale curve") must name: "expected the
/// name of a curve defined above as sweep", or of a 2D curve (listing them) when `planar_only`.
std::string expected_reference(const char* role, bool planar_only);
/// The problem with `target` as a surface's reference (a curve; a 2D one when `planar_only`), in
/// the reader's words (expected_reference, and the note "it is a 3D curve (bsp3)"); nullopt if
/// none.
std::optional<CurveProblem> check_reference_kind(const Object& target, const char* role, bool planar_only);
/// "a surface (gcyl)", "a material (material)", "a curve (circ)".
std::string kind_description(ObjectKind kind);

/// The problem with a subd's scheme for its cage `source` (called `source_name` in the note):
/// Loop takes triangles only, so a mesh with another face or a grid of quads cannot take it.
/// nullopt if none (the size of the refined mesh is a cap: caps.hpp).
std::optional<CurveProblem> check_subdivision_scheme(const SubdivisionSurface& subd, const Object& source,
                                                     const std::string& source_name);

}  // namespace sweep
