#pragma once
// Shared by the golden tests: the three picture modes, the fixed camera, and the comparison of
// a rendered picture with tests/golden/NAME.png by `sweep snapshot`'s comparison
// (snapshot/image_diff.hpp: one implementation of one rule).
#include "headless/headless_renderer.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "snapshot/image_diff.hpp"
#include "snapshot/run_render.hpp"
#include "snapshot/snapshot_case.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sweep::test {

/// The picture size of every golden: small enough to keep the repository and the run light.
inline constexpr int kGoldenWidth = 320;
inline constexpr int kGoldenHeight = 240;

/// The three modes of `sweep snapshot` (snapshot/snapshot_case.hpp), drawn as it draws them.
using GoldenMode = snapshot::Mode;

/// The golden file suffix is snapshot::name_of(mode): "smooth", "wire", "frames" (found by ADL).
/// A mode's display settings are snapshot::settings_for(mode) (found by ADL): one rule for both.

struct LoadedScene {
  Document doc;
  Scene scene;
  std::filesystem::path folder;  // where the file's material images are
};
/// Loads and evaluates swp/STEM.swp (with `options`, e.g. a tolerance).
LoadedScene load_starter(const std::string& stem, const EvaluationOptions& options = {});

/// The fixed camera of the goldens: `sweep render`'s default (framed, default yaw and pitch).
render::Camera golden_camera(const Scene& scene);

/// One renderer for the whole test process (creating OSMesa contexts is not free).
headless::HeadlessRenderer& shared_renderer();

render::Image render_golden_picture(const LoadedScene& loaded, GoldenMode mode);
/// The same picture with `settings` instead of a mode's.
render::Image render_golden_picture(const LoadedScene& loaded, const render::DisplaySettings& settings);

/// The comparison options of every golden: snapshot's defaults (threshold 0.1, anti-aliased edge
/// pixels and one-pixel shifts forgiven).
snapshot::DiffOptions golden_options();
/// What may still differ after that, in pixels of the 76,800: smooth 150, wire 400 (a dense
/// wireframe scatters a small change over many pixels), frames 150. The shaded pictures that are
/// not one of the modes (colour modes, artifacts, riders) use smooth's.
snapshot::DiffLimits limits_for(GoldenMode mode);

/// Compares `actual` with tests/golden/NAME.png (golden_options) and checks it against `limits`.
/// With SWEEP_UPDATE_GOLDEN=1 in the environment it writes the golden instead. On failure it
/// keeps NAME-actual.png and NAME-diff.png (the heat map) in the build tree and names them in the
/// message.
::testing::AssertionResult matches_golden(const render::Image& actual, const std::string& name,
                                          const snapshot::DiffLimits& limits);

/// The golden picture NAME (tests/golden/NAME.png). Throws if missing.
render::Image load_golden(const std::string& name);

}  // namespace sweep::test
