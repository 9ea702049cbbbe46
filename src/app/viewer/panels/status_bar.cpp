// The status bar: the last thing done (ViewerState::status) along the bottom of the window, and
// the first line of an error in its colour, where no panel scrolls them out of sight. A warning
// among the status's lines (an STL export of a surface that is not closed) is the line shown, in
// amber, rather than one of the lines hidden behind "(and N more)".
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::viewer::panels {
namespace {

bool is_warning(std::string_view line) {
  return line.starts_with("warning:") || line.find(": warning: ") != std::string_view::npos;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

ImVec4 colour(StatusLine::Tone tone) {
  switch (tone) {
    case StatusLine::Tone::Error:
      return ImVec4(1.0f, 0.45f, 0.4f, 1.0f);  // as the Error panel
    case StatusLine::Tone::Warning:
      return kWarningText;
    case StatusLine::Tone::Plain:
      break;
  }
  return ImGui::GetStyle().Colors[ImGuiCol_Text];
}

}  // namespace

StatusLine status_line(const StatusParts& s) {
  const bool error = !s.error.empty();
  const std::vector<std::string> lines = lines_of(error ? s.error : s.status);
  if (lines.empty()) return {};
  // An error's first line is its file:line:column message; the status's first warning, if any.
  const auto shown = error ? lines.begin() : std::find_if(lines.begin(), lines.end(), is_warning);
  const std::string& line = shown == lines.end() ? lines.front() : *shown;
  const StatusLine::Tone tone = is_warning(line) ? StatusLine::Tone::Warning
                                : error          ? StatusLine::Tone::Error
                                                 : StatusLine::Tone::Plain;
  const std::size_t more = lines.size() - 1;
  if (more == 0) return {line, {}, tone};
  if (error) return {line, "(more in the Error panel)", tone};
  return {line, "(and " + std::to_string(more) + " more: point here to see them)", tone};
}

std::string elide_middle(const std::string& text, float width, const std::function<float(std::string_view)>& measure) {
  if (measure(text) <= width) return text;
  const auto starts_character = [&text](std::size_t i) {
    return i >= text.size() || (static_cast<unsigned char>(text[i]) & 0xC0u) != 0x80u;  // not a continuation byte
  };
  // `text` less about `cut` bytes from its middle, "..." in their place.
  const auto elided = [&](std::size_t cut) {
    std::size_t head = (text.size() - cut) / 2;
    std::size_t tail = head + cut;
    while (head > 0 && !starts_character(head)) --head;
    while (!starts_character(tail)) ++tail;
    return text.substr(0, head) + "..." + text.substr(tail);
  };
  // The smallest cut that fits: the widths shrink as the cut grows (all of it: "...").
  std::size_t low = 1;
  std::size_t high = text.size();
  while (low < high) {
    const std::size_t middle = low + (high - low) / 2;
    if (measure(elided(middle)) <= width) {
      high = middle;
    } else {
      low = middle + 1;
    }
  }
  return elided(low);
}

void status_bar(const StatusParts& s) {
  if (s.layout.status_height <= 0.0f) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x, viewport->WorkPos.y + viewport->WorkSize.y), ImGuiCond_Always,
                          ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x, s.layout.status_height), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##status", nullptr, flags)) {
    const StatusLine line = status_line(s);
    // Nothing said yet (an empty start): where to begin.
    const std::string text =
        line.text.empty() ? "Ready: open a file, or add a curve in Create; F1 lists every key" : line.text;
    const std::string more = line.more.empty() ? "" : "  " + line.more;
    // One line that fits the bar: a long one loses its middle, not its end or the pointer to the rest.
    const auto measure = [](std::string_view part) {
      return ImGui::CalcTextSize(part.data(), part.data() + part.size()).x;
    };
    // The pointer's coordinates in the profile view, at the right end.
    char where[64] = "";
    if (s.cursor) std::snprintf(where, sizeof where, "x %.4g  y %.4g", s.cursor->x, s.cursor->y);
    const float where_width = where[0] != '\0' ? measure(where) + 24.0f : 0.0f;
    const std::string shown =
        elide_middle(text, ImGui::GetContentRegionAvail().x - measure(more) - where_width, measure) + more;
    ImGui::PushStyleColor(ImGuiCol_Text, colour(line.tone));
    ImGui::TextUnformatted(shown.c_str());
    ImGui::PopStyleColor();
    if (where[0] != '\0') {
      ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - measure(where));
      ImGui::TextDisabled("%s", where);
    }
    // For scripted tests: how the line is shown (printed again when that changes).
    static constexpr const char* kToneMarks[] = {"status-bar-plain", "status-bar-warning", "status-bar-error"};
    mark_item(s.item_positions, kToneMarks[static_cast<int>(line.tone)]);
    const std::string& all = s.error.empty() ? s.status : s.error;
    if (ImGui::IsWindowHovered() && !all.empty()) ImGui::SetTooltip("%s", all.c_str());
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

}  // namespace sweep::viewer::panels
