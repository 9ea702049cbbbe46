#pragma once
// Shared by the golden tests: the three picture modes, the fixed camera, and the comparison of
// a rendered picture with tests/golden/NAME.png.
#include "headless/headless_renderer.hpp"
#include "image_compare.hpp"
#include "model/document.hpp"
#include "model/scene.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sweep::test {

/// The picture size of every golden: small enough to keep the repository and the run light.
inline constexpr int kGoldenWidth = 320;
inline constexpr int kGoldenHeight = 240;

enum class GoldenMode { Smooth, Wire, Frames };

/// "smooth", "wire", "frames": the golden file suffix.
std::string name_of(GoldenMode mode);
/// smooth: shaded surfaces + curves; wire: wireframe with normals + curves;
/// frames: curves with frames and control points, surfaces off.
render::DisplaySettings settings_for(GoldenMode mode);

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

/// Compares `actual` with tests/golden/NAME.png. With SWEEP_UPDATE_GOLDEN=1 in the environment
/// it writes the golden instead. On failure it keeps NAME-actual.png and NAME-diff.png in the
/// build tree and names them in the message.
::testing::AssertionResult matches_golden(const render::Image& actual, const std::string& name,
                                          const Tolerance& tolerance);

/// The golden picture NAME (tests/golden/NAME.png). Throws if missing.
render::Image load_golden(const std::string& name);

}  // namespace sweep::test
