#include "snapshot/run_render.hpp"

#include "base/number_text.hpp"
#include "geometry/curves/adaptive.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/material.hpp"
#include "render/draw_list.hpp"
#include "snapshot/object_ids.hpp"

#include <chrono>
#include <mutex>

namespace sweep::snapshot {
namespace {

/// Yaw and pitch (degrees) of the named views.
glm::dvec2 view_angles(NamedView view) {
  switch (view) {
    case NamedView::Front:
      return {0.0, 0.0};
    case NamedView::Top:
      return {0.0, 90.0};
    case NamedView::Side:
      return {90.0, 0.0};
    case NamedView::Iso:
      return {45.0, 35.264};
    case NamedView::Default:
      break;
  }
  return {render::Camera::kDefaultYaw, render::Camera::kDefaultPitch};
}

IdPassContent content_of(Mode mode) {
  IdPassContent content;
  content.surfaces = mode != Mode::Frames;
  content.control_points = mode == Mode::Frames;
  return content;
}

std::mutex& context_creation() {
  static std::mutex lock;
  return lock;
}

}  // namespace

render::DisplaySettings settings_for(Mode mode, render::ColorMode color) {
  render::DisplaySettings settings;
  settings.color = color;
  switch (mode) {
    case Mode::Smooth:
      render::show_surface(settings, render::SurfaceMode::Smooth);
      settings.curves = render::CurveMode::Curves;
      break;
    case Mode::Wire:
      render::show_surface(settings, render::SurfaceMode::Wireframe);
      settings.curves = render::CurveMode::Curves;
      break;
    case Mode::Frames:
      render::show_surface(settings, render::SurfaceMode::Off);
      settings.curves = render::CurveMode::Frames;
      settings.control_points = true;
      break;
  }
  return settings;
}

render::Camera fitted_camera(const Scene& scene, const CaseSpec& spec) {
  render::Camera camera;
  camera.reset(render::scene_bounds(scene), double(spec.size.x) / double(spec.size.y));
  const glm::dvec2 angles = view_angles(spec.view.name);
  camera.set_yaw_pitch(spec.view.yaw.value_or(angles.x), spec.view.pitch.value_or(angles.y));
  if (spec.view.distance) camera.distance = *spec.view.distance;
  return camera;
}

bool same_scene(const CaseSpec& a, const CaseSpec& b) {
  return a.file == b.file && a.tolerance == b.tolerance && a.frames == b.frames && a.seam == b.seam &&
         (a.color == render::ColorMode::Uv) == (b.color == render::ColorMode::Uv);
}

LoadedScene load_scene(const CaseSpec& spec) {
  LoadedScene loaded;
  try {
    loaded.doc = io::load_swp_file(spec.file);
  } catch (const std::exception& e) {  // ParseError: "FILE:LINE:COLUMN: ..."; or a file that cannot be read
    loaded.error = e.what();
    return loaded;
  }
  if (spec.tolerance > 0.0) {
    const std::string problem = check_tolerance(spec.tolerance, document_extent(loaded.doc), "the scene");
    if (!problem.empty()) {
      loaded.error = spec.file.string() + ": " + problem + ", found " + number_text(spec.tolerance);
      return loaded;
    }
  }
  EvaluationOptions options = evaluation_options(name_of(spec.frames), name_of(spec.seam), spec.tolerance);
  options.texture_coordinates =
      spec.color == render::ColorMode::Uv ? TextureCoordinates::Everywhere : TextureCoordinates::WhereTextured;
  loaded.scene = evaluate_document(loaded.doc, options);
  loaded.image_folder = image_base(spec.file);
  return loaded;
}

Worker::Worker() {
  const std::lock_guard<std::mutex> hold(context_creation());
  renderer_ = std::make_unique<headless::HeadlessRenderer>("osmesa");
  renderer_name_ = renderer_->description();
}

Rendered Worker::render(const LoadedScene& loaded, const CaseSpec& spec, const render::Camera& camera) {
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene, loaded.image_folder);
  render::add_riders(list, loaded.doc, loaded.scene, spec.time);
  Rendered out;
  const auto start = std::chrono::steady_clock::now();
  out.image = renderer_->render(list, camera, spec.size, settings_for(spec.mode, spec.color));
  out.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const IdMap ids = object_ids(list, camera, spec.size, content_of(spec.mode));
  std::vector<Fingerprint> objects = fingerprints(loaded.doc, loaded.scene, ids, loaded.image_folder);
  IdMap labels = relabel(ids, objects);
  out.sidecar = make_sidecar(spec, renderer_name_, camera, std::move(objects), std::move(labels));
  return out;
}

}  // namespace sweep::snapshot
