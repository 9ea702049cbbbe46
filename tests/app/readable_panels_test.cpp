// Issue 47, item 9, drawn by the real panel code in a headless ImGui context: a slider's grab does
// not cover its number (ImGui centres the number over the frame, where the grab passes), and no
// label of the Edit panel is cut off at its edge, for every object of every starter file.
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"
#include "editor/viewport_layout.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>
#include <imgui_internal.h>  // SliderBehavior, ImRect, the current window's extent

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

using sweep::test::HeadlessImGui;
using sweep::viewer::ViewerState;
using sweep::viewer::panels::Span;
using sweep::viewer::panels::value_text_left;

TEST(ValueSlider, TheNumberStaysCentredWhileTheGrabIsClearOfIt) {
  const Span frame{100.0f, 300.0f};
  EXPECT_FLOAT_EQ(value_text_left(frame, {102.0f, 112.0f}, 40.0f, 2.0f, 4.0f), 180.0f);
  EXPECT_FLOAT_EQ(value_text_left(frame, {288.0f, 298.0f}, 40.0f, 2.0f, 4.0f), 180.0f);
}

TEST(ValueSlider, AGrabUnderTheNumberSendsItToTheFarEndWhereItStays) {
  const Span frame{100.0f, 300.0f};
  const float width = 40.0f;
  const float gap = 2.0f;
  const float padding = 4.0f;
  EXPECT_FLOAT_EQ(value_text_left(frame, {190.0f, 200.0f}, width, gap, padding), 300.0f - padding - width);
  EXPECT_FLOAT_EQ(value_text_left(frame, {205.0f, 215.0f}, width, gap, padding), 100.0f + padding);
  for (float grab = 102.0f; grab <= 288.0f; grab += 0.5f) {
    const float x = value_text_left(frame, {grab, grab + 10.0f}, width, gap, padding);
    EXPECT_TRUE(x + width <= grab - gap || x >= grab + 10.0f + gap) << "the grab at " << grab << " covers it";
    EXPECT_GE(x, frame.min + padding - 1e-3f);
    EXPECT_LE(x + width, frame.max - padding + 1e-3f);
  }
}

// slider_grab repeats ImGui 1.86's geometry: checked against ImGui's own SliderBehavior.
TEST(ValueSlider, ItsGrabIsWhereImGuiPutsIt) {
  HeadlessImGui imgui;
  ViewerState s;
  imgui.frame(s, [](ViewerState&) {
    const ImRect bb(100.0f, 60.0f, 320.0f, 79.0f);
    const Span frame{bb.Min.x, bb.Max.x};
    const auto check = [&](ImGuiDataType type, auto value, auto low, auto high, const char* format, int flags) {
      ImRect grab;
      auto v = value;
      ImGui::SliderBehavior(bb, ImGui::GetID("slider"), type, &v, &low, &high, format, flags, &grab);
      const Span mine = sweep::viewer::panels::slider_grab(frame, type, &value, &low, &high, format, flags);
      EXPECT_NEAR(mine.min, grab.Min.x, 0.05f) << format << " " << double(value);
      EXPECT_NEAR(mine.max, grab.Max.x, 0.05f) << format << " " << double(value);
    };
    for (float v : {1.0f, 1.5f, 4.0f, 7.25f, 10.0f}) check(ImGuiDataType_Float, v, 1.0f, 10.0f, "%.2f", 0);
    for (float v : {0.0f, 0.0001f, 0.05f, 0.5f, 1.0f}) {
      check(ImGuiDataType_Float, v, 0.0f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic);  // a bound of 0
    }
    for (float v : {0.1f, 0.7f, 1.0f, 3.0f})
      check(ImGuiDataType_Float, v, 0.1f, 4.0f, "%.2fx", ImGuiSliderFlags_Logarithmic);
    for (int v : {0, 2, 3, 6}) check(ImGuiDataType_S32, v, 0, 6, "%d", 0);  // a grab a step wide
    for (int v : {1, 8, 32, 240, 1000}) check(ImGuiDataType_S32, v, 1, 1000, "%d", ImGuiSliderFlags_Logarithmic);
    for (double v : {0.0, 0.3, 0.5, 1.0}) check(ImGuiDataType_Double, v, 0.0, 1.0, "5.12e-03", 0);
  });
}

/// The x range of the vertices of `colour` in the current frame's draw data between `top` and
/// `bottom` and left of `right` ({+inf, -inf} when there are none).
Span extent_of(ImU32 colour, float top, float bottom, float right) {
  Span span{1e9f, -1e9f};
  const ImDrawData* data = ImGui::GetDrawData();
  for (int l = 0; l < data->CmdListsCount; ++l) {
    for (const ImDrawVert& v : data->CmdLists[l]->VtxBuffer) {
      if (v.col != colour || v.pos.y < top || v.pos.y > bottom || v.pos.x > right) continue;
      span.min = std::min(span.min, v.pos.x);
      span.max = std::max(span.max, v.pos.x);
    }
  }
  return span;
}

// What the panels draw: every value of a slider from one end to the other, its number's glyphs
// never overlap its grab (ImGui's own slider covers it near the middle).
TEST(ValueSlider, TheDrawnNumberIsNeverUnderTheDrawnGrab) {
  HeadlessImGui imgui;
  ViewerState s;
  for (int k = 0; k <= 40; ++k) {
    float value = float(k) / 40.0f;
    ImVec2 frame_min;
    ImVec2 frame_max;
    ImU32 text = 0;
    ImU32 grab = 0;
    imgui.frame(s, [&](ViewerState&) {
      ImGui::SetNextItemWidth(200.0f);
      sweep::viewer::panels::value_slider_float("mitre", &value, 0.0f, 1.0f, "%.3f");
      frame_min = ImGui::GetItemRectMin();
      frame_max = ImVec2(frame_min.x + 200.0f, ImGui::GetItemRectMax().y);
      text = ImGui::GetColorU32(ImGuiCol_Text);
      grab = ImGui::GetColorU32(ImGuiCol_SliderGrab);
    });
    const Span glyphs = extent_of(text, frame_min.y, frame_max.y, frame_max.x);
    const Span handle = extent_of(grab, frame_min.y, frame_max.y, frame_max.x);
    ASSERT_LT(glyphs.min, glyphs.max) << "no number drawn at " << value;
    ASSERT_LT(handle.min, handle.max) << "no grab drawn at " << value;
    EXPECT_TRUE(glyphs.max <= handle.min || glyphs.min >= handle.max)
        << value << ": number " << glyphs.min << ".." << glyphs.max << ", grab " << handle.min << ".." << handle.max;
    EXPECT_GE(glyphs.min, frame_min.x);
    EXPECT_LE(glyphs.max, frame_max.x);
  }
}

/// Every SWP file of the starter folder and its artifacts.
std::vector<std::filesystem::path> starter_files() {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SWEEP_SWP_DIR)) {
    if (entry.path().extension() == ".swp") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// Issue 47, item 9: "continuity" and "tolerance" ran past the Edit panel's right edge.
TEST(EditPanel, NoLabelRunsPastItsEdgeForAnyObjectOfTheStarterFiles) {
  HeadlessImGui imgui;
  ViewerState s;
  sweep::editor::CommandTable commands;
  s.layout = sweep::editor::compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  // The Edit window's inner width: the layout's, less its padding on both sides.
  const float inner = s.layout.edit_width - 2.0f * ImGui::GetStyle().WindowPadding.x;
  float widest = 0.0f;
  float edge = 0.0f;
  const HeadlessImGui::Draw draw = [&](ViewerState& state) {
    ImGui::BeginChild("edit", ImVec2(inner, 3000.0f));  // taller than any: no scroll bar takes width
    sweep::viewer::panels::edit_panel(state, commands);
    const ImGuiWindow* window = ImGui::GetCurrentWindow();
    widest = window->DC.CursorMaxPos.x;
    edge = window->Pos.x + ImGui::GetWindowContentRegionMax().x;
    ImGui::EndChild();
  };
  int objects = 0;
  for (const std::filesystem::path& file : starter_files()) {
    s.session.load(sweep::io::load_swp_file(file), file.string());
    for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
      s.selection.select(s.session.id_of(int(i)));
      imgui.frame(s, draw);
      imgui.frame(s, draw);
      EXPECT_LE(widest, edge + 0.5f) << file.filename().string() << ": " << sweep::display_name(s.doc(), int(i)) << " ("
                                     << sweep::keyword(s.doc().objects[i].kind()) << ")";
      ++objects;
    }
  }
  EXPECT_GT(objects, 100) << "every kind is among them";
}

}  // namespace
