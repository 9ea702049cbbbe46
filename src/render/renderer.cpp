#include "render/renderer.hpp"

#include "render/gpu_scene.hpp"
#include "render/shader_program.hpp"
#include "render/textures.hpp"

#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <cstring>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::render {
namespace {

/// The camera as every pass of one draw sees it.
struct ViewMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  bool orthographic = false;
};

ViewMatrices view_matrices(const Camera& camera, glm::ivec2 size) {
  const double aspect = size.y > 0 ? double(size.x) / double(size.y) : 1.0;
  return {glm::mat4(camera.view_matrix()), glm::mat4(camera.projection_matrix(aspect)),
          camera.projection == Projection::Orthographic};
}

GLenum gl_primitive(OverlayBatch::Primitive primitive) {
  switch (primitive) {
    case OverlayBatch::Primitive::Points:
      return GL_POINTS;
    case OverlayBatch::Primitive::Lines:
      return GL_LINES;
    case OverlayBatch::Primitive::LineStrip:
      return GL_LINE_STRIP;
  }
  return GL_POINTS;
}

}  // namespace

// -----------------------------------------------------------------------------------------------

struct Renderer::Impl {
  Program mesh_program{"mesh"};
  Program wire_program{"mesh.vert", "wire.geom", "wire.frag"};  // the wireframe: filled triangles
  Program lines_program{"lines"};
  GpuScene objects;  // the GPU copies the passes draw
  RenderStats stats;

  GpuArray overlay_stream;  // one stream buffer reused by every overlay batch
  MaterialBinder looks;

  // The passes of Renderer::draw, in order. Those after use_lines draw with the lines program.

  void clear_and_reset_state(const RenderTarget& target, const DisplaySettings& settings) {
    glViewport(0, 0, target.size.x, target.size.y);
    glClearColor(settings.background.r, settings.background.g, settings.background.b, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);
    glDisable(GL_BLEND);
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_PROGRAM_POINT_SIZE);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
  }

  /// The camera's matrices in `p` (u_view, u_projection), which every program draws with.
  static void set_view(const Program& p, const ViewMatrices& matrices) {
    p.set("u_view", matrices.view);
    p.set("u_projection", matrices.projection);
  }

  /// The program surfaces are drawn with: the wireframe's or the shaded one.
  const Program& surface_program(const DisplaySettings& settings) const {
    return settings.surface == SurfaceMode::Wireframe ? wire_program : mesh_program;
  }

  /// The wireframe: one draw of each mesh's triangles, their edges kept in the fragment shader
  /// (shaders/wire.geom), about a pixel wide (times the target's pixel ratio).
  void use_wire_program(const ViewMatrices& matrices, const DisplaySettings& settings, const RenderTarget& target) {
    const Program& p = wire_program;
    p.use();
    p.set("u_model", glm::mat4(1.0f));
    set_view(p, matrices);
    p.set("u_color", settings.wire_color);
    p.set("u_viewport", glm::vec2(target.size));
    p.set("u_half_width", 0.5f * target.pixel_ratio);
  }

  void use_mesh_program(const ViewMatrices& matrices, const DisplaySettings& settings) const {
    const Program& p = mesh_program;
    p.use();
    p.set("u_model", glm::mat4(1.0f));
    set_view(p, matrices);
    const Material& m = settings.material;
    const Lighting& l = settings.lighting;
    p.set("u_color", m.color);
    p.set("u_specular_color", m.specular);
    p.set("u_shininess", std::max(m.shininess, 1.0f));
    p.set("u_two_sided", m.two_sided);
    p.set("u_key_direction", glm::normalize(l.key_direction));
    p.set("u_key_color", l.key_color);
    p.set("u_fill_direction", glm::normalize(l.fill_direction));
    p.set("u_fill_color", l.fill_color);
    p.set("u_ambient_color", l.ambient);
    p.set("u_orthographic", matrices.orthographic);
    p.set("u_texture", 0);
    p.set("u_bump", 1);
    p.set("u_textured", false);
    p.set("u_bumped", false);
    p.set("u_highlighted", false);
  }

  /// Surface `i` highlighted or not (DrawList::highlighted): a wireframe takes the colour, shading
  /// is tinted in the shader.
  void use_highlight(const DrawList& list, std::size_t i, const DisplaySettings& settings) const {
    const bool on = list.highlighted >= 0 && static_cast<std::size_t>(list.highlighted) == i;
    if (settings.surface == SurfaceMode::Wireframe) {
      wire_program.set("u_color", on ? list.highlight_color : settings.wire_color);
      return;
    }
    mesh_program.set("u_highlighted", on);
    if (on) mesh_program.set("u_highlight_color", list.highlight_color);
  }

  /// What colours shaded surfaces (ColorMode): the curvature colours made ready, and the mode set.
  void use_colors(const DrawList& list, ColorMode mode) {
    const bool by_vertex = mode == ColorMode::Gaussian || mode == ColorMode::Mean;
    if (by_vertex) stats.color_range = objects.prepare_curvature_colors(list, mode);
    mesh_program.set("u_color_mode", mode == ColorMode::Material  ? 0
                                     : by_vertex                  ? 1
                                     : mode == ColorMode::Normals ? 2
                                                                  : 3);
  }

  /// Binds surface `i`'s material (MaterialBinder); the wireframe keeps its flat colour.
  void use_material(const DrawList& list, std::size_t i, const DisplaySettings& settings) {
    if (settings.surface == SurfaceMode::Wireframe) return;
    const bool named = i < list.materials.size() && !list.materials[i].name.empty();
    looks.bind(mesh_program, named ? &list.materials[i] : nullptr, settings.material);
  }

  void draw_surfaces(const DrawList& list, const ViewMatrices& matrices, const DisplaySettings& settings,
                     const RenderTarget& target) {
    if (settings.surface == SurfaceMode::Off) return;
    if (settings.surface == SurfaceMode::Wireframe) {
      use_wire_program(matrices, settings, target);
      glEnable(GL_SAMPLE_ALPHA_TO_COVERAGE);
    } else {
      use_mesh_program(matrices, settings);
      use_colors(list, settings.color);
    }
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const GpuObject& gpu = objects[i];
      if (gpu.mesh.empty() || !list.is_shaded(i)) continue;
      use_material(list, i, settings);
      use_highlight(list, i, settings);
      glBindVertexArray(gpu.mesh.vao);
      glDrawElements(GL_TRIANGLES, gpu.mesh.count, GL_UNSIGNED_INT, nullptr);
      stats.vertices += list.scene->objects[i].mesh.vertex_count();
      stats.triangles += list.scene->objects[i].mesh.triangle_count();
    }
    draw_riders(list, settings);
    glDisable(GL_SAMPLE_ALPHA_TO_COVERAGE);
  }

  /// Each rider's model mesh where it rides (its material, and the highlight of the model).
  void draw_riders(const DrawList& list, const DisplaySettings& settings) {
    for (const RiderPlacement& rider : list.riders) {
      const auto i = static_cast<std::size_t>(rider.model);
      if (rider.model < 0 || i >= objects.size() || objects[i].mesh.empty()) continue;
      use_material(list, i, settings);
      use_highlight(list, i, settings);
      surface_program(settings).set("u_model", rider.matrix);
      glBindVertexArray(objects[i].mesh.vao);
      glDrawElements(GL_TRIANGLES, objects[i].mesh.count, GL_UNSIGNED_INT, nullptr);
      stats.vertices += list.scene->objects[i].mesh.vertex_count();
      stats.triangles += list.scene->objects[i].mesh.triangle_count();
    }
    surface_program(settings).set("u_model", glm::mat4(1.0f));
  }

  void use_lines(const ViewMatrices& matrices) const {
    const Program& lines = lines_program;
    lines.use();
    set_view(lines, matrices);
    lines.set("u_round_points", false);
    lines.set("u_point_size", 1.0f);
  }

  /// Normal segments of the shown surfaces (DisplaySettings::normals).
  void draw_normal_segments(const DrawList& list, const DisplaySettings& settings) {
    if (!settings.normals || settings.surface == SurfaceMode::Off) return;
    lines_program.set("u_tint", settings.normal_color);
    lines_program.set("u_direction_length", settings.normal_length * static_cast<float>(objects.radius()));
    for (std::size_t i = 0; i < objects.size(); ++i) {
      if (objects[i].mesh.empty() || !list.is_shaded(i)) continue;
      const GpuArray& segments = objects.decorations(i, list.scene->objects[i]);
      glBindVertexArray(segments.vao);
      glDrawArrays(GL_LINES, 0, segments.count);
    }
  }

  /// Curves, and their frames; not the curves riders' models are made of (DrawList::curve_rides).
  void draw_curves(const DrawList& list, const DisplaySettings& settings) {
    if (settings.curves == CurveMode::Off) return;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      if (!list.curve_rides(i)) draw_curve(list, i, settings);
    }
  }

  /// Curve `i`: its strip, and its frames in frames mode.
  void draw_curve(const DrawList& list, std::size_t i, const DisplaySettings& settings) {
    if (i >= objects.size()) return;
    const GpuObject& gpu = objects[i];
    if (gpu.strip.empty() || !list.is_visible(i)) return;
    const Program& lines = lines_program;
    lines.set("u_tint", settings.curve_color);
    lines.set("u_direction_length", 0.0f);
    glBindVertexArray(gpu.strip.vao);
    glDrawArrays(GL_LINE_STRIP, 0, gpu.strip.count);
    stats.curve_samples += list.scene->objects[i].curve.frames.size();
    if (settings.curves != CurveMode::Frames) return;
    const GpuArray& frames = objects.decorations(i, list.scene->objects[i]);
    lines.set("u_tint", kWhite);
    lines.set("u_direction_length", settings.frame_length * static_cast<float>(objects.radius()));
    glBindVertexArray(frames.vao);
    glDrawArrays(GL_LINES, 0, frames.count);
  }

  /// Control points joined by their control polygon.
  void draw_control_polygons(const DrawList& list, const DisplaySettings& settings, float pixel_ratio) {
    if (!settings.control_points) return;
    const Program& lines = lines_program;
    lines.set("u_direction_length", 0.0f);
    const std::size_t count = std::min(objects.size(), list.control_polygons.size());
    for (std::size_t i = 0; i < count; ++i) {
      if (list.control_polygons[i].empty() || !list.is_visible(i) || list.curve_rides(i)) continue;
      const GpuArray& polygon = objects.control(i, list.control_polygons[i]);
      glBindVertexArray(polygon.vao);
      lines.set("u_tint", settings.control_color * 0.75f);
      lines.set("u_round_points", false);
      glDrawArrays(GL_LINE_STRIP, 0, polygon.count);
      lines.set("u_tint", settings.control_color);
      lines.set("u_round_points", true);
      lines.set("u_point_size", settings.point_size * pixel_ratio);
      glDrawArrays(GL_POINTS, 0, polygon.count);
      lines.set("u_round_points", false);
    }
  }

  /// Control nets of patches and cages with the control points (their lines and points), and
  /// the cages of subds with the wireframe (lines).
  void draw_nets(const DrawList& list, const DisplaySettings& settings, float pixel_ratio) {
    using Role = EvaluatedObject::NetRole;
    const Program& lines = lines_program;
    lines.set("u_direction_length", 0.0f);
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const EvaluatedObject& source = list.scene->objects[i];
      const bool control = source.net_role == Role::ControlNet && settings.control_points;
      const bool cage = source.net_role == Role::Cage && settings.surface == SurfaceMode::Wireframe;
      if ((!control && !cage) || source.net.empty() || !list.is_visible(i)) continue;
      const GpuArray& net = objects.net(i, source);
      glBindVertexArray(net.vao);
      lines.set("u_tint", control ? settings.control_color * 0.75f : settings.control_color * 0.6f);
      lines.set("u_round_points", false);
      glDrawArrays(GL_LINES, 0, net.count);
      if (!control) continue;
      lines.set("u_tint", settings.control_color);
      lines.set("u_round_points", true);
      lines.set("u_point_size", settings.point_size * pixel_ratio);
      glDrawArrays(GL_POINTS, 0, net.count);
      lines.set("u_round_points", false);
    }
  }

  /// Overlay batches over everything drawn so far, streamed through one buffer.
  void draw_overlay(const std::vector<OverlayBatch>& overlay, float pixel_ratio) {
    if (overlay.empty()) return;
    if (overlay_stream.vao == 0) overlay_stream = upload_lines({});  // attributes set up once
    const Program& lines = lines_program;
    lines.set("u_direction_length", 0.0f);
    glBindVertexArray(overlay_stream.vao);
    glBindBuffer(GL_ARRAY_BUFFER, overlay_stream.vbo);
    std::vector<LineVertex> vertices;
    for (const OverlayBatch& batch : overlay) {
      if (batch.positions.empty()) continue;
      vertices.clear();
      for (const glm::vec3& p : batch.positions) vertices.push_back({p, glm::vec3(0.0f), kWhite});
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(LineVertex)), vertices.data(),
                   GL_STREAM_DRAW);
      if (batch.on_top) {
        glDisable(GL_DEPTH_TEST);
      } else {
        glEnable(GL_DEPTH_TEST);
      }
      const bool points = batch.primitive == OverlayBatch::Primitive::Points;
      lines.set("u_tint", batch.color);
      lines.set("u_round_points", points && batch.round);
      lines.set("u_point_size", points ? batch.point_size * pixel_ratio : 1.0f);
      glDrawArrays(gl_primitive(batch.primitive), 0, static_cast<GLsizei>(vertices.size()));
    }
    lines.set("u_round_points", false);
    glEnable(GL_DEPTH_TEST);
  }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {}

Renderer::~Renderer() {
  clear();
}

void Renderer::clear() {
  impl_->objects.clear();
  impl_->overlay_stream.release();
  impl_->looks.clear();
}

const RenderStats& Renderer::stats() const {
  return impl_->stats;
}
std::uint64_t Renderer::upload_count() const {
  return impl_->objects.uploads();
}

void Renderer::draw(const DrawList& list, const Camera& camera, const RenderTarget& target,
                    const DisplaySettings& settings) {
  if (list.scene == nullptr) throw std::invalid_argument("Renderer::draw: the draw list has no scene");
  Impl& r = *impl_;
  r.objects.sync(*list.scene);
  r.stats = {};
  const ViewMatrices matrices = view_matrices(camera, target.size);
  r.clear_and_reset_state(target, settings);
  r.draw_surfaces(list, matrices, settings, target);
  r.use_lines(matrices);
  r.draw_normal_segments(list, settings);
  r.draw_curves(list, settings);
  r.draw_control_polygons(list, settings, target.pixel_ratio);
  r.draw_nets(list, settings, target.pixel_ratio);
  r.draw_overlay(list.overlay, target.pixel_ratio);
  r.stats.warnings = r.looks.warnings();
  glBindVertexArray(0);
  glUseProgram(0);
}

}  // namespace sweep::render
