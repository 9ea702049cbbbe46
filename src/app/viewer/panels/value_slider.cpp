#include "app/viewer/panels/value_slider.hpp"

#include "base/precondition.hpp"

#include <imgui_internal.h>  // TempInputIsActive, DataTypeFormatString, ImParseFormatPrecision, FindRenderedTextEnd

#include <algorithm>
#include <cmath>

namespace sweep::viewer::panels {
namespace {

/// The number at `p`, of ImGui data type `type`.
double as_double(ImGuiDataType type, const void* p) {
  switch (type) {
    case ImGuiDataType_S8:
      return static_cast<double>(*static_cast<const ImS8*>(p));
    case ImGuiDataType_U8:
      return static_cast<double>(*static_cast<const ImU8*>(p));
    case ImGuiDataType_S16:
      return static_cast<double>(*static_cast<const ImS16*>(p));
    case ImGuiDataType_U16:
      return static_cast<double>(*static_cast<const ImU16*>(p));
    case ImGuiDataType_S32:
      return static_cast<double>(*static_cast<const ImS32*>(p));
    case ImGuiDataType_U32:
      return static_cast<double>(*static_cast<const ImU32*>(p));
    case ImGuiDataType_S64:
      return static_cast<double>(*static_cast<const ImS64*>(p));
    case ImGuiDataType_U64:
      return static_cast<double>(*static_cast<const ImU64*>(p));
    case ImGuiDataType_Float:
      return static_cast<double>(*static_cast<const float*>(p));
    case ImGuiDataType_Double:
      return *static_cast<const double*>(p);
    default:
      return 0.0;
  }
}

/// Where `value` lies between `low` and `high`, 0 to 1, as ImGui's ScaleRatioFromValueT puts it:
/// linear, or logarithmic with a bound nearer 0 than `epsilon` moved out to epsilon. A log range
/// across 0 (ImGui's dead zone) is taken as linear: no panel has one.
double slider_ratio(double value, double low, double high, bool logarithmic, double epsilon) {
  if (low == high) return 0.0;
  const double v = std::clamp(value, low, high);
  if (!logarithmic || (low < 0.0 && high > 0.0)) return (v - low) / (high - low);
  const double from = std::abs(low) < epsilon ? (high < 0.0 ? -epsilon : epsilon) : low;
  const double to = std::abs(high) < epsilon ? (low < 0.0 ? -epsilon : epsilon) : high;
  if (v <= from) return 0.0;
  if (v >= to) return 1.0;
  return std::log(v / from) / std::log(to / from);
}

}  // namespace

float value_text_left(Span frame, Span grab, float width, float gap, float padding) {
  SWEEP_EXPECTS(frame.min <= frame.max && grab.min <= grab.max, "spans run left to right");
  SWEEP_EXPECTS(width >= 0.0f && gap >= 0.0f && padding >= 0.0f, "width, gap and padding >= 0");
  const float centred = 0.5f * (frame.min + frame.max - width);
  if (centred + width <= grab.min - gap || centred >= grab.max + gap) return centred;
  const float left_room = grab.min - gap - (frame.min + padding);
  const float right_room = frame.max - padding - (grab.max + gap);
  return right_room >= left_room ? frame.max - padding - width : frame.min + padding;
}

Span slider_grab(Span frame, ImGuiDataType type, const void* value, const void* low, const void* high,
                 const char* format, ImGuiSliderFlags flags) {
  SWEEP_EXPECTS(frame.min <= frame.max, "the frame runs left to right");
  SWEEP_EXPECTS(as_double(type, low) <= as_double(type, high), "low <= high");
  constexpr float kGrabPadding = 2.0f;  // SliderBehaviorT's
  const bool floating = type == ImGuiDataType_Float || type == ImGuiDataType_Double;
  const double from = as_double(type, low);
  const double to = as_double(type, high);
  const float slider = std::max(0.0f, frame.max - frame.min - 2.0f * kGrabPadding);
  float grab = ImGui::GetStyle().GrabMinSize;
  if (!floating) grab = std::max(static_cast<float>(double(slider) / (to - from + 1.0)), grab);  // a step wide
  grab = std::min(grab, slider);
  const int precision = floating ? ImParseFormatPrecision(format, 3) : 1;
  const double t = slider_ratio(as_double(type, value), from, to, (flags & ImGuiSliderFlags_Logarithmic) != 0,
                                std::pow(0.1, precision));
  const float centre = frame.min + kGrabPadding + 0.5f * grab + static_cast<float>(t) * (slider - grab);
  return {centre - 0.5f * grab, centre + 0.5f * grab};
}

bool value_slider(const char* label, ImGuiDataType type, void* value, const void* low, const void* high,
                  const char* format, ImGuiSliderFlags flags) {
  // Typed into (Ctrl+click), or not drawn at all: ImGui's own.
  if (ImGui::GetCurrentWindowRead()->SkipItems || ImGui::TempInputIsActive(ImGui::GetID(label))) {
    return ImGui::SliderScalar(label, type, value, low, high, format, flags);
  }
  // ImGui draws the frame and the grab; its value and label are drawn invisible and then here.
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(0.0f, 0.0f, 0.0f, 0.0f));
  const bool changed = ImGui::SliderScalar(label, type, value, low, high, format, flags);
  ImGui::PopStyleColor();
  if (!ImGui::IsItemVisible()) return changed;
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 item_min = ImGui::GetItemRectMin();
  const ImVec2 item_max = ImGui::GetItemRectMax();
  const char* label_end = ImGui::FindRenderedTextEnd(label);
  const float label_width = ImGui::CalcTextSize(label, label_end).x;
  const Span frame{item_min.x, item_max.x - (label_width > 0.0f ? style.ItemInnerSpacing.x + label_width : 0.0f)};
  char text[64];
  const int length = ImGui::DataTypeFormatString(text, int(sizeof text), type, value, format);
  const float width = ImGui::CalcTextSize(text, text + length).x;
  const Span grab = slider_grab(frame, type, value, low, high, format, flags);
  const float x = value_text_left(frame, grab, width, 2.0f, style.FramePadding.x);
  const float y = item_min.y + style.FramePadding.y;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImU32 colour = ImGui::GetColorU32(ImGuiCol_Text);
  const ImVec4 clip(frame.min, item_min.y, frame.max, item_max.y);
  draw->AddText(nullptr, 0.0f, ImVec2(x, y), colour, text, text + length, 0.0f, &clip);
  if (label_width > 0.0f) draw->AddText(ImVec2(frame.max + style.ItemInnerSpacing.x, y), colour, label, label_end);
  return changed;
}

bool value_slider_float(const char* label, float* value, float low, float high, const char* format,
                        ImGuiSliderFlags flags) {
  return value_slider(label, ImGuiDataType_Float, value, &low, &high, format, flags);
}

}  // namespace sweep::viewer::panels
