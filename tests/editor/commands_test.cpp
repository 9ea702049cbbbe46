// The command table: labels, binding and enabling, what each key press means, shortcut labels,
// and docs/viewer.md's key table, which must list exactly the commands that have shortcuts.
#include "editor/commands.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sweep::editor {
namespace {

constexpr std::size_t kCommandCount = static_cast<std::size_t>(CommandId::Pen) + 1;

Shortcut key(Key k) {
  return {k, false, false};
}
Shortcut shift(Key k) {
  return {k, false, true};
}
Shortcut ctrl(Key k) {
  return {k, true, false};
}
Shortcut ctrl_shift(Key k) {
  return {k, true, true};
}

TEST(Commands, EveryCommandHasAnEntryWithALabelInIdOrder) {
  const CommandTable table;
  ASSERT_EQ(table.commands().size(), kCommandCount);
  for (std::size_t i = 0; i < kCommandCount; ++i) {
    const CommandId id = static_cast<CommandId>(i);
    EXPECT_EQ(table.commands()[i].id, id);
    EXPECT_EQ(&table.get(id), &table.commands()[i]);
    EXPECT_FALSE(table.get(id).label.empty()) << "command " << i;
  }
}

TEST(Commands, UnboundCommandsAreDisabled) {
  CommandTable table;
  for (const Command& command : table.commands()) {
    EXPECT_FALSE(table.enabled(command.id)) << command.label;
    EXPECT_FALSE(table.run(command.id)) << command.label;
  }
  EXPECT_FALSE(table.press(ctrl(Key::S))) << "a shortcut of an unbound command does nothing";
}

TEST(Commands, ABoundCommandRunsAndItsPredicateCanBlockIt) {
  CommandTable table;
  int saves = 0;
  bool can_save = true;
  table.bind(
      CommandId::Save, [&] { ++saves; }, [&] { return can_save; });
  EXPECT_TRUE(table.enabled(CommandId::Save));
  EXPECT_TRUE(table.run(CommandId::Save));
  EXPECT_TRUE(table.press(ctrl(Key::S)));
  EXPECT_EQ(saves, 2);

  can_save = false;
  EXPECT_FALSE(table.enabled(CommandId::Save));
  EXPECT_FALSE(table.run(CommandId::Save));
  EXPECT_FALSE(table.press(ctrl(Key::S)));
  EXPECT_EQ(saves, 2);

  int other = 0;
  table.bind(CommandId::Save, [&] { ++other; });  // replaces the action and the predicate
  EXPECT_TRUE(table.run(CommandId::Save));
  EXPECT_EQ(other, 1);
  EXPECT_EQ(saves, 2);
  EXPECT_FALSE(table.enabled(CommandId::Open)) << "binding one command leaves the others unbound";
}

TEST(Commands, KeyPressesFindTheirCommands) {
  const CommandTable table;
  const std::vector<std::pair<Shortcut, CommandId>> expected = {
      {ctrl(Key::S), CommandId::Save},
      {ctrl_shift(Key::S), CommandId::SaveAs},
      {key(Key::S), CommandId::CycleSurfaces},
      {shift(Key::S), CommandId::JointSmooth},
      {shift(Key::P), CommandId::TogglePoints},
      {ctrl(Key::Z), CommandId::Undo},
      {ctrl_shift(Key::Z), CommandId::Redo},
      {ctrl(Key::Y), CommandId::Redo},
      {key(Key::Escape), CommandId::Quit},
      {ctrl(Key::Q), CommandId::Quit},
      {ctrl(Key::N), CommandId::New},
      {ctrl(Key::O), CommandId::OpenBrowser},
      {key(Key::Delete), CommandId::DeletePoint},
      {key(Key::Backspace), CommandId::DeletePoint},
      {key(Key::I), CommandId::InsertPoint},
      {key(Key::Insert), CommandId::InsertPoint},
      {key(Key::C), CommandId::CycleCurves},
      {key(Key::P), CommandId::TogglePoints},
      {key(Key::V), CommandId::ProfileView},
      {key(Key::Space), CommandId::ResetCamera},
      {shift(Key::Space), CommandId::PlayPause},
      {key(Key::Keypad1), CommandId::ViewFront},
      {key(Key::Digit1), CommandId::ViewFront},
      {key(Key::Keypad3), CommandId::ViewSide},
      {key(Key::Digit7), CommandId::ViewTop},
      {shift(Key::G), CommandId::ToggleGrid},
      {key(Key::G), CommandId::Grab},
      {key(Key::R), CommandId::Rotate},
      {key(Key::E), CommandId::Scale},
      {key(Key::A), CommandId::SelectAllPoints},
      {shift(Key::C), CommandId::JointCorner},
      {shift(Key::Y), CommandId::JointSymmetric},
      {key(Key::K), CommandId::ToggleComb},
      {key(Key::F), CommandId::FrameSelection},
      {key(Key::Home), CommandId::FrameAll},
      {key(Key::F1), CommandId::Help},
  };
  for (const auto& [pressed, id] : expected) {
    EXPECT_EQ(table.find(pressed), std::optional<CommandId>(id)) << label(pressed);
  }
  EXPECT_EQ(table.find(ctrl(Key::P)), std::nullopt) << "Ctrl does not fall back to the plain key";
  EXPECT_EQ(table.find(ctrl(Key::C)), std::nullopt);
  EXPECT_EQ(table.find(ctrl_shift(Key::Y)), std::nullopt);
  EXPECT_EQ(table.find(key(Key::Z)), std::nullopt);
  EXPECT_EQ(table.find(key(Key::X)), std::nullopt) << "X, Y and Z belong to drags and transforms";
  EXPECT_EQ(table.find(key(Key::Y)), std::nullopt);
}

TEST(Commands, EscClosesAnOpenMenuOrPopupFirstAndCtrlQAlwaysQuits) {
  CommandTable table;
  int quits = 0;
  table.bind(CommandId::Quit, [&quits] { ++quits; });
  EXPECT_FALSE(table.press(key(Key::Escape), true)) << "a menu, popup or field was open: Esc is theirs";
  EXPECT_EQ(quits, 0);
  EXPECT_TRUE(table.press(key(Key::Escape), false));
  EXPECT_TRUE(table.press(ctrl(Key::Q), true));
  EXPECT_TRUE(table.press(ctrl(Key::Q), false));
  EXPECT_EQ(quits, 3);
}

TEST(Commands, NoTwoCommandsShareAShortcut) {
  const CommandTable table;
  std::vector<std::pair<Shortcut, CommandId>> seen;
  for (const Command& command : table.commands()) {
    for (const Shortcut& s : command.shortcuts) {
      for (const auto& [other, owner] : seen) {
        EXPECT_FALSE(other == s) << label(s) << " belongs to " << table.get(owner).label << " and " << command.label;
      }
      seen.emplace_back(s, command.id);
      EXPECT_EQ(table.find(s), std::optional<CommandId>(command.id)) << label(s);
    }
  }
}

TEST(Commands, ShortcutLabels) {
  EXPECT_EQ(label(ctrl_shift(Key::Z)), "Ctrl+Shift+Z");
  EXPECT_EQ(label(ctrl(Key::S)), "Ctrl+S");
  EXPECT_EQ(label(key(Key::Escape)), "Esc");
  EXPECT_EQ(label(key(Key::Delete)), "Del");
  EXPECT_EQ(label(key(Key::Space)), "Space");
  EXPECT_EQ(label(key(Key::S)), "S");
  EXPECT_EQ(label(key(Key::Backspace)), "Backspace");
  EXPECT_EQ(label(key(Key::Insert)), "Insert");
  EXPECT_EQ(label(shift(Key::A)), "Shift+A");

  const CommandTable table;
  EXPECT_EQ(table.shortcut_label(CommandId::Redo), "Ctrl+Shift+Z");
  EXPECT_EQ(table.all_shortcuts_label(CommandId::Redo), "Ctrl+Shift+Z / Ctrl+Y");
  EXPECT_EQ(table.all_shortcuts_label(CommandId::DeletePoint), "Del / Backspace");
  EXPECT_EQ(table.shortcut_label(CommandId::Open), "");
  EXPECT_EQ(table.all_shortcuts_label(CommandId::Open), "");
  EXPECT_EQ(table.button_label(CommandId::Save), "Save [Ctrl+S]");
  EXPECT_EQ(table.button_label(CommandId::Redo), "Redo [Ctrl+Shift+Z]");
  EXPECT_EQ(table.button_label(CommandId::ExportObj), "Export OBJ");
}

// docs/viewer.md's key table ---------------------------------------------------------------------

std::string trim(const std::string& text) {
  const std::size_t begin = text.find_first_not_of(" \t\r");
  if (begin == std::string::npos) return "";
  return text.substr(begin, text.find_last_not_of(" \t\r") - begin + 1);
}

/// The cells of a markdown table row "| a | b |", trimmed.
std::vector<std::string> cells(const std::string& row) {
  std::vector<std::string> out;
  std::string body = trim(row);
  if (body.size() < 2 || body.front() != '|' || body.back() != '|') return out;
  body = body.substr(1, body.size() - 2);
  std::stringstream stream(body);
  for (std::string cell; std::getline(stream, cell, '|');) out.push_back(trim(cell));
  return out;
}

bool is_delimiter_row(const std::vector<std::string>& row) {
  for (const std::string& cell : row) {
    if (cell.empty() || cell.find_first_not_of("-:") != std::string::npos) return false;
  }
  return !row.empty();
}

/// The rows of the "| keys | command |" table in docs/viewer.md's "## The viewer" section.
std::vector<std::vector<std::string>> readme_key_table() {
  std::ifstream in(SWEEP_VIEWER_GUIDE);
  EXPECT_TRUE(in) << "cannot read " << SWEEP_VIEWER_GUIDE;
  std::vector<std::vector<std::string>> rows;
  bool in_section = false;
  bool in_table = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("## ", 0) == 0) {
      if (in_section) break;
      in_section = trim(line) == "## The viewer";
      continue;
    }
    if (!in_section) continue;
    if (!in_table) {
      in_table = trim(line) == "| keys | command |";
      continue;
    }
    if (line.empty() || line.front() != '|') break;
    std::vector<std::string> row = cells(line);
    if (rows.empty() && is_delimiter_row(row)) continue;  // | --- | --- |
    rows.push_back(std::move(row));
  }
  EXPECT_TRUE(in_table) << "docs/viewer.md's \"## The viewer\" section has no \"| keys | command |\" table";
  return rows;
}

TEST(Commands, TheReadmeKeyTableListsEveryShortcutOfTheTable) {
  const CommandTable table;
  std::vector<std::vector<std::string>> expected;
  for (const Command& command : table.commands()) {
    if (command.shortcuts.empty()) continue;
    std::string keys;
    for (const Shortcut& s : command.shortcuts) keys += (keys.empty() ? "`" : " / `") + label(s) + "`";
    expected.push_back({keys, std::string(command.label)});
  }
  ASSERT_EQ(expected.size(), 32u);
  EXPECT_EQ(expected[4][0], "`Ctrl+Shift+Z` / `Ctrl+Y`") << "the keys cell is all_shortcuts_label with backticks";

  const std::vector<std::vector<std::string>> rows = readme_key_table();
  for (std::size_t i = 0; i < std::max(rows.size(), expected.size()); ++i) {
    if (i >= rows.size()) {
      ADD_FAILURE() << "docs/viewer.md lacks the row | " << expected[i][0] << " | " << expected[i][1] << " |";
    } else if (i >= expected.size()) {
      ADD_FAILURE() << "docs/viewer.md has an extra row: " << ::testing::PrintToString(rows[i]);
    } else {
      EXPECT_EQ(rows[i], expected[i]) << "row " << i + 1 << " of docs/viewer.md's key table";
    }
  }
}

}  // namespace
}  // namespace sweep::editor
