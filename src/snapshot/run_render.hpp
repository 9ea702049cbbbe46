#pragma once
// One worker's pictures: a scene loaded and evaluated once for all the cases that share its file
// and evaluation options, each case rendered through the worker's own OSMesa context, with its
// object-id pass and fingerprints (the sidecar a reference would keep).
#include "headless/headless_renderer.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/image.hpp"
#include "snapshot/sidecar.hpp"
#include "snapshot/snapshot_case.hpp"

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

namespace sweep::snapshot {

/// The display settings of a case's mode and colour: smooth (shaded surfaces and curves), wire
/// (wireframe with normals and curves), frames (curves with frames and control points, no
/// surfaces). The golden tests draw with the same.
render::DisplaySettings settings_for(Mode mode, render::ColorMode color = render::ColorMode::Material);

/// The camera a case gets when it has no reference yet: fitted to the scene as `sweep render`
/// does, then turned to the case's view (named, yaw, pitch) and moved to its distance if given.
render::Camera fitted_camera(const Scene& scene, const CaseSpec& spec);

/// Cases that can share one evaluation: same file, tolerance, frames, seam and texture coordinates.
bool same_scene(const CaseSpec& a, const CaseSpec& b);

/// A file read and evaluated for a case's options, or why not ("FILE:LINE:COLUMN: ...").
struct LoadedScene {
  Document doc;
  Scene scene;
  std::filesystem::path image_folder;
  std::string error;
};
LoadedScene load_scene(const CaseSpec& spec);

struct Rendered {
  render::Image image;
  Sidecar sidecar;
  double render_seconds = 0.0;  // the picture alone (OSMesa), without the id pass and fingerprints
};

/// A worker's OSMesa context and renderer (created under a lock: GL function loading is global).
class Worker {
 public:
  Worker();
  const std::string& renderer_name() const { return renderer_name_; }
  /// The largest picture side the context can render (HeadlessRenderer::max_picture_side).
  int max_picture_side() const { return renderer_->max_picture_side(); }
  /// The worker's renderer, for pictures without a case (the public API's renders).
  headless::HeadlessRenderer& renderer() { return *renderer_; }
  /// The case's picture seen by `camera`, and its sidecar. Precondition: scene loaded without error.
  Rendered render(const LoadedScene& scene, const CaseSpec& spec, const render::Camera& camera);

 private:
  std::unique_ptr<headless::HeadlessRenderer> renderer_;
  std::string renderer_name_;
};

}  // namespace sweep::snapshot
