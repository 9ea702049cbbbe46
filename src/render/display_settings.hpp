#pragma once
// How the renderer draws: modes, material, lights, colours. Plain appearance data shared by the
// window, `sweep render` and the tests; what is drawn (and which objects) is a DrawList.
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

namespace sweep::render {

enum class SurfaceMode : std::uint8_t { Smooth, Wireframe, Off };
enum class CurveMode : std::uint8_t { Curves, Frames, Off };
/// What colours the surfaces: their materials, Gaussian or mean curvature (a diverging map
/// symmetric about 0), their normals, or their texture coordinates.
enum class ColorMode : std::uint8_t { Material, Gaussian, Mean, Normals, Uv };

struct Material {
  glm::vec3 color{0.62f, 0.68f, 0.80f};
  glm::vec3 specular{0.45f, 0.45f, 0.45f};
  float shininess = 48.0f;
  bool two_sided = true;  // light back faces too (open surfaces show their inside)
};

/// A key light and a weaker fill light, both fixed to the camera; directions point towards
/// the light in view space (x right, y up, z towards the viewer) and need not be unit.
struct Lighting {
  glm::vec3 key_direction{-0.45f, 0.6f, 0.65f};
  glm::vec3 key_color{0.80f, 0.80f, 0.78f};
  glm::vec3 fill_direction{0.6f, -0.25f, 0.5f};
  glm::vec3 fill_color{0.30f, 0.32f, 0.38f};
  glm::vec3 ambient{0.16f, 0.16f, 0.18f};
};

struct DisplaySettings {
  SurfaceMode surface = SurfaceMode::Smooth;
  /// Each shown surface's vertex normals as short segments in normal_color, with either surface
  /// mode: a toggle of its own (the viewer's N). `--surface wire` and a snapshot's wire mode turn
  /// it on with the wireframe (show_surface).
  bool normals = false;
  CurveMode curves = CurveMode::Curves;
  bool control_points = false;
  /// The ground grid and axes (the editor's overlay builds them): on in the viewer, off in
  /// `sweep render` unless --grid, so its pictures stay as they were.
  bool grid = false;
  ColorMode color = ColorMode::Material;
  Material material;
  Lighting lighting;
  glm::vec3 background{0.11f, 0.12f, 0.14f};
  glm::vec3 curve_color{1.0f, 1.0f, 1.0f};
  glm::vec3 wire_color{0.55f, 0.62f, 0.75f};
  /// Violet: apart from the selection's orange, the control points' yellow, the selected point's
  /// cyan, the frames' N red, B green and T blue, the comb's green, the fold markers' magenta and
  /// the wireframe's grey blue (the viewer's legend lists them all).
  glm::vec3 normal_color{0.62f, 0.45f, 1.0f};
  glm::vec3 control_color{1.0f, 0.9f, 0.1f};
  /// Frame axes and normal segments, as a fraction of the scene's bounding radius.
  float frame_length = 0.08f;
  float normal_length = 0.02f;
  float point_size = 6.0f;  // control points, in screen units (times the target's pixel ratio)
};

/// Shows surfaces in `mode` as `--surface NAME` and a snapshot case's mode mean it: the
/// wireframe with its normals, smooth shading and off without.
void show_surface(DisplaySettings& settings, SurfaceMode mode);

/// Mode names as on the command line and in the UI: "smooth", "wire", "off"; "on", "frames", "off".
std::string_view name_of(SurfaceMode mode);
std::string_view name_of(CurveMode mode);
std::optional<SurfaceMode> surface_mode_from_name(std::string_view name);
std::optional<CurveMode> curve_mode_from_name(std::string_view name);
/// Every colouring, in the order the command line and the UI list them.
inline constexpr std::array<ColorMode, 5> kColorModes{ColorMode::Material, ColorMode::Gaussian, ColorMode::Mean,
                                                      ColorMode::Normals, ColorMode::Uv};
/// "material", "gaussian", "mean", "normals", "uv". Inline: the GL-free snapshot core (a suite's
/// color=, a sidecar's) reads the same names without the render library.
inline std::string_view name_of(ColorMode mode) {
  switch (mode) {
    case ColorMode::Material:
      return "material";
    case ColorMode::Gaussian:
      return "gaussian";
    case ColorMode::Mean:
      return "mean";
    case ColorMode::Normals:
      return "normals";
    case ColorMode::Uv:
      return "uv";
  }
  return "?";
}
std::optional<ColorMode> color_mode_from_name(std::string_view name);
/// The next mode in the viewer's cycle: smooth -> wire -> off -> smooth; curves -> frames -> off.
SurfaceMode next(SurfaceMode mode);
CurveMode next(CurveMode mode);

}  // namespace sweep::render
