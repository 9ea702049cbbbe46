#pragma once
// The circular helix, evaluated exactly (helix.cpp).
#include "geometry/curves/curve.hpp"

#include <cstdint>

namespace sweep {

/// The helix basis (helix.cpp): closed when helix_closes.
extern const CurveBasis kHelixBasis;

/// A helix closes only when flat (pitch 0) and of whole turns: then it is a circle.
bool helix_closes(double pitch, double turns);

/// A helix about +z starting at (radius, 0, 0), counterclockwise seen from +z, rising `pitch`
/// per turn (negative descends) over `turns` turns: helix_sample_count(steps, turns) samples,
/// sample i at angle 2 pi turns i / (count - 1). Tangents and curvature a / (a^2 + c^2),
/// c = pitch / (2 pi), are exact; frames are the 3D frames of compute_frames. A flat helix
/// (pitch 0) of whole turns is a closed circle and closes its seam like any closed 3D curve.
/// Preconditions: radius >= limits::kMinRadius, turns > 0, steps >= 1, |pitch| and radius at
/// most limits::kMaxCoordinate, the sample count within limits::kMaxCurveSamples.
/// Samples of a helix of `steps` per turn and `turns` > 0 turns: ceil(steps * turns) + 1 (4e18,
/// beyond every cap, when that would be more). The one statement of the count: the reader's and
/// editor's caps (model/caps.hpp) and the evaluation use it.
std::int64_t helix_sample_count(int steps, double turns);

CurveSamples evaluate_helix(double radius, double pitch, double turns, int steps, const FrameOptions& options = {});

}  // namespace sweep
