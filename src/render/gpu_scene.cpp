#include "render/gpu_scene.hpp"

#include "geometry/mesh/colormap.hpp"
#include "render/camera.hpp"

namespace sweep::render {

void GpuObject::release() {
  if (colors) glDeleteBuffers(1, &colors);
  colors = 0;
  colors_range = 0.0f;
  curvatures = {};
  curvature_revision = 0;
  mesh.release();
  strip.release();
  decorations.release();
  control.release();
  net.release();
  revision = decorations_revision = control_revision = net_revision = 0;
}

GpuArray GpuScene::counted(GpuArray array) {
  ++uploads_;
  return array;
}

void GpuScene::sync(const Scene& scene) {
  bool changed = objects_.size() != scene.objects.size();
  for (std::size_t i = scene.objects.size(); i < objects_.size(); ++i) objects_[i].release();
  objects_.resize(scene.objects.size());
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const EvaluatedObject& source = scene.objects[i];
    GpuObject& gpu = objects_[i];
    if (gpu.revision == source.revision && source.revision != 0) continue;
    gpu.release();
    changed = true;
    if (!source.mesh.indices.empty()) gpu.mesh = counted(upload_mesh(source.mesh));
    if (source.curve.frames.size() >= 2) gpu.strip = counted(upload_lines(curve_strip(source.curve)));
    gpu.revision = source.revision;
  }
  if (changed) {
    const double radius = scene_bounds(scene).radius();
    radius_ = radius > 0.0 ? radius : 1.0;
  }
}

void GpuScene::clear() {
  for (GpuObject& gpu : objects_) gpu.release();
  objects_.clear();
}

const GpuArray& GpuScene::decorations(std::size_t i, const EvaluatedObject& source) {
  GpuObject& gpu = objects_[i];
  if (gpu.decorations_revision == gpu.revision) return gpu.decorations;
  gpu.decorations.release();
  if (!source.mesh.positions.empty()) {
    gpu.decorations = counted(upload_lines(normal_segments(source.mesh)));
  } else if (!source.curve.frames.empty()) {
    gpu.decorations = counted(upload_lines(frame_segments(source.curve)));
  }
  gpu.decorations_revision = gpu.revision;
  return gpu.decorations;
}

// The control polygon changes only with its object's revision (edits re-evaluate the object).
const GpuArray& GpuScene::control(std::size_t i, std::span<const glm::dvec3> points) {
  GpuObject& gpu = objects_[i];
  if (gpu.control_revision == gpu.revision) return gpu.control;
  gpu.control.release();
  gpu.control = counted(upload_lines(control_polygon(points)));
  gpu.control_revision = gpu.revision;
  return gpu.control;
}

const GpuArray& GpuScene::net(std::size_t i, const EvaluatedObject& source) {
  GpuObject& gpu = objects_[i];
  if (gpu.net_revision == gpu.revision) return gpu.net;
  gpu.net.release();
  gpu.net = counted(upload_lines(net_segments(source.net)));
  gpu.net_revision = gpu.revision;
  return gpu.net;
}

const std::vector<float>& GpuScene::curvature(GpuObject& gpu, const EvaluatedObject& source, ColorMode mode) {
  if (gpu.curvature_revision != gpu.revision) {
    gpu.curvatures = vertex_curvatures(source.mesh);
    gpu.curvature_revision = gpu.revision;
  }
  return mode == ColorMode::Gaussian ? gpu.curvatures.gaussian : gpu.curvatures.mean;
}

float GpuScene::prepare_curvature_colors(const DrawList& list, ColorMode mode) {
  std::vector<float> all;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    if (objects_[i].mesh.empty() || !(list.is_shaded(i) || list.rides(i))) continue;
    const std::vector<float>& values = curvature(objects_[i], list.scene->objects[i], mode);
    all.insert(all.end(), values.begin(), values.end());
  }
  const float range = symmetric_range(all);
  std::vector<glm::vec3> colors;
  for (std::size_t i = 0; i < objects_.size(); ++i) {
    GpuObject& gpu = objects_[i];
    if (gpu.mesh.empty() || !(list.is_shaded(i) || list.rides(i))) continue;
    if (gpu.colors != 0 && gpu.colors_mode == mode && gpu.colors_range == range) continue;
    const std::vector<float>& values = curvature(gpu, list.scene->objects[i], mode);
    colors.resize(values.size());
    for (std::size_t k = 0; k < values.size(); ++k) colors[k] = cool_warm(values[k] / range);
    upload_vertex_colors(gpu.mesh, gpu.colors, colors);
    gpu.colors_mode = mode;
    gpu.colors_range = range;
  }
  return range;
}

}  // namespace sweep::render
