#include "render/display_settings.hpp"

namespace sweep::render {

std::string_view name_of(SurfaceMode mode) {
  switch (mode) {
    case SurfaceMode::Smooth:
      return "smooth";
    case SurfaceMode::Wireframe:
      return "wire";
    case SurfaceMode::Off:
      return "off";
  }
  return "?";
}

void show_surface(DisplaySettings& settings, SurfaceMode mode) {
  settings.surface = mode;
  settings.normals = mode == SurfaceMode::Wireframe;
}

std::string_view name_of(CurveMode mode) {
  switch (mode) {
    case CurveMode::Curves:
      return "on";
    case CurveMode::Frames:
      return "frames";
    case CurveMode::Off:
      return "off";
  }
  return "?";
}

std::optional<SurfaceMode> surface_mode_from_name(std::string_view name) {
  for (SurfaceMode mode : {SurfaceMode::Smooth, SurfaceMode::Wireframe, SurfaceMode::Off}) {
    if (name_of(mode) == name) return mode;
  }
  return std::nullopt;
}

std::optional<CurveMode> curve_mode_from_name(std::string_view name) {
  for (CurveMode mode : {CurveMode::Curves, CurveMode::Frames, CurveMode::Off}) {
    if (name_of(mode) == name) return mode;
  }
  return std::nullopt;
}

std::optional<ColorMode> color_mode_from_name(std::string_view name) {
  for (const ColorMode mode : kColorModes) {
    if (name_of(mode) == name) return mode;
  }
  return std::nullopt;
}

SurfaceMode next(SurfaceMode mode) {
  switch (mode) {
    case SurfaceMode::Smooth:
      return SurfaceMode::Wireframe;
    case SurfaceMode::Wireframe:
      return SurfaceMode::Off;
    case SurfaceMode::Off:
      return SurfaceMode::Smooth;
  }
  return SurfaceMode::Smooth;
}

CurveMode next(CurveMode mode) {
  switch (mode) {
    case CurveMode::Curves:
      return CurveMode::Frames;
    case CurveMode::Frames:
      return CurveMode::Off;
    case CurveMode::Off:
      return CurveMode::Curves;
  }
  return CurveMode::Curves;
}

}  // namespace sweep::render
