#pragma once
// The one offscreen context of each thread that renders through the public API: render() and
// check_snapshot() share it (making one costs about 60 ms).
#include "snapshot/run_render.hpp"

namespace sweep::v0::detail {

/// The mode a picture is drawn in: "smooth", "wire" or "frames"; Error for another name.
::sweep::snapshot::Mode mode_named(const std::string& mode);
/// The colouring of a picture: "material", "gaussian", "mean", "normals" or "uv"; Error for another name.
::sweep::render::ColorMode color_named(const std::string& color);

/// This thread's worker, made on its first use. Throws std::runtime_error when no context can be made.
::sweep::snapshot::Worker& thread_worker();

}  // namespace sweep::v0::detail
