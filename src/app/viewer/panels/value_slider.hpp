#pragma once
// A slider whose value stays readable (issue 47, item 9): ImGui centres a slider's value over the
// frame and draws its grab under it, so near the middle the grab covers the number. Every slider
// of the panels goes through value_slider, which puts the text where the grab leaves it clear.
#include <imgui.h>

namespace sweep::viewer::panels {

/// A horizontal span [min, max] in screen units.
struct Span {
  float min = 0.0f;
  float max = 0.0f;
};

/// The left edge of a slider's value text `width` wide in `frame`, kept off `grab` (at least
/// `gap` from it): centred in the frame, as ImGui puts it, while the grab is clear of it, else
/// against the frame's inner edge (`padding` in) on the side of the grab with more room, so the
/// text stays put while the grab moves. Preconditions: frame.min <= frame.max, grab.min <=
/// grab.max, width, gap and padding >= 0.
float value_text_left(Span frame, Span grab, float width, float gap, float padding);

/// Where ImGui 1.86 draws the grab of a horizontal slider over `frame` for `value` of `type`
/// between `low` and `high` (its SliderBehavior's geometry: 2 units of padding, GrabMinSize, an
/// integer slider's grab a step wide; ImGuiSliderFlags_Logarithmic as its log scale, with the
/// format's precision deciding how close to 0 a bound of 0 counts). Preconditions: an ImGui
/// context, frame.min <= frame.max, low <= high.
Span slider_grab(Span frame, ImGuiDataType type, const void* value, const void* low, const void* high,
                 const char* format, ImGuiSliderFlags flags);

/// ImGui::SliderScalar(label, type, value, low, high, format, flags), with the value's text placed
/// by value_text_left (while Ctrl+click types into it, as ImGui draws it). Returns whether the
/// value changed.
bool value_slider(const char* label, ImGuiDataType type, void* value, const void* low, const void* high,
                  const char* format, ImGuiSliderFlags flags = 0);

/// value_slider for a float, as ImGui::SliderFloat.
bool value_slider_float(const char* label, float* value, float low, float high, const char* format,
                        ImGuiSliderFlags flags = 0);

}  // namespace sweep::viewer::panels
