#pragma once
// Turning every planar curve of a document into a surface of revolution: what `sweep import
// DRAWING.svg OUT.swp --revolve` does with the curves it read, so a profile drawn in a drawing
// program becomes a model in one step.
#include "model/document.hpp"

namespace sweep {

/// The suffix a revolved curve's name gets: curve "vase" becomes "vase_profile".
inline constexpr std::string_view kProfileSuffix = "_profile";

/// `doc` with each curve NAME renamed NAME_profile and followed by `srev NAME steps NAME_profile`
/// (no caps), in the curves' order. The surface takes the curve's name, so the name the user gave
/// (an SVG id) is the model's. A profile name already taken by another object, or made by the
/// rule for an earlier curve, gets "_2", "_3", ... (NAME_profile_2); NAME is cut so that the
/// whole stays at most limits::kMaxNameLength bytes. Which way the profile runs and which side of the axis it is on
/// do not matter: srev's normals point out of the region the profile bounds with the axis
/// (geometry/surfaces/surface.hpp), so the triangles are counterclockwise seen from outside either way.
/// Preconditions: every object is a named planar curve (is_planar_curve), the names are valid and
/// unique; 1 <= steps <= limits::kMaxSteps.
Document revolve_curves(Document doc, int steps);

}  // namespace sweep
