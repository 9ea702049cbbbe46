#pragma once
// Where named widgets ended up on screen, for scripted GUI tests that click them with xdotool
// (--select prints them). ScriptHooks owns it and hands the panels a pointer only when a script
// asked; the panels fill it through panels::mark_item and mark_window. Header-only, so the
// panels library does not link the one with the main loop. No GL and no GLFW.
#include <glm/vec2.hpp>

#include <map>
#include <string>
#include <string_view>

namespace sweep::viewer {

class ItemPositions {
 public:
  void mark(std::string_view name, glm::vec2 position) { positions_.insert_or_assign(std::string(name), position); }
  /// Where `name` was marked, or `fallback` when no panel marked it (e.g. the widget is not shown).
  glm::vec2 position(std::string_view name, glm::vec2 fallback) const {
    const auto found = positions_.find(name);
    return found == positions_.end() ? fallback : found->second;
  }
  /// Every mark, by name.
  const std::map<std::string, glm::vec2, std::less<>>& all() const { return positions_; }
  /// Forgets every mark, so a widget gone since shows as unmarked, not where it last was.
  void clear() { positions_.clear(); }

 private:
  std::map<std::string, glm::vec2, std::less<>> positions_;
};

}  // namespace sweep::viewer
