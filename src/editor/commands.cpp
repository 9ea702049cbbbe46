#include "editor/commands.hpp"

#include <stdexcept>
#include <string_view>
#include <utility>

namespace sweep::editor {
namespace {

constexpr Shortcut key(Key k) {
  return {k, false, false};
}
constexpr Shortcut ctrl(Key k, bool shift = false) {
  return {k, true, shift};
}
constexpr Shortcut shift(Key k) {
  return {k, false, true};
}

/// The commands in CommandId order: the one list of what the viewer can do.
std::vector<Command> all_commands() {
  using enum CommandId;
  return {
      {Open, "Open the path typed in the File panel", {}, {}, {}},
      {Save, "Save", {ctrl(Key::S)}, {}, {}},
      {SaveAs, "Save As...", {ctrl(Key::S, true)}, {}, {}},
      {ExportObj, "Export OBJ", {}, {}, {}},
      {SavePng, "Save PNG of the view...", {}, {}, {}},
      {Quit, "Quit", {key(Key::Escape), ctrl(Key::Q)}, {}, {}},
      {Undo, "Undo", {ctrl(Key::Z)}, {}, {}},
      {Redo, "Redo", {ctrl(Key::Z, true), ctrl(Key::Y)}, {}, {}},
      {InsertPoint,
       "Insert point after the selected one; at an open curve's end, extend it (Bezier: a piece)",
       {key(Key::I), key(Key::Insert)},
       {},
       {}},
      {DeletePoint, "Delete the selected point", {key(Key::Delete), key(Key::Backspace)}, {}, {}},
      {CycleSurfaces, "Surfaces: smooth, wireframe, off", {key(Key::S)}, {}, {}},
      {CycleCurves, "Curves: plain, with frames (N red, B green, T blue), off", {key(Key::C)}, {}, {}},
      {TogglePoints, "Control points and polygons on/off", {key(Key::P)}, {}, {}},
      {ProfileView, "Profile view (xy)", {key(Key::V)}, {}, {}},
      {ResetCamera, "Reset the camera", {key(Key::Space)}, {}, {}},
      {ViewFront, "Front view", {key(Key::Digit1), key(Key::Keypad1)}, {}, {}},
      {ViewTop, "Top view", {key(Key::Digit7), key(Key::Keypad7)}, {}, {}},
      {ViewSide, "Side view", {key(Key::Digit3), key(Key::Keypad3)}, {}, {}},
      {OpenBrowser, "Open...", {ctrl(Key::O)}, {}, {}},
      {New, "New", {ctrl(Key::N)}, {}, {}},
      {ExportStl, "Export STL", {}, {}, {}},
      {ExportGlb, "Export glb", {}, {}, {}},
      {SaveWindowPng, "Save PNG of the window (with panels)", {}, {}, {}},
      {ToggleGrid, "Grid and axes on/off", {shift(Key::G)}, {}, {}},
      {FrameSelection, "Frame the selection (the selected points, else the selected object)", {key(Key::F)}, {}, {}},
      {FrameAll, "Frame everything", {key(Key::Home)}, {}, {}},
      {Help, "Help: every command and key", {key(Key::F1)}, {}, {}},
      {SelectAllPoints, "Select every point of the selected curve", {key(Key::A)}, {}, {}},
      {Grab, "Grab the selected points (X/Y/Z, a number, Enter)", {key(Key::G)}, {}, {}},
      {Rotate, "Rotate the selected points about their centre", {key(Key::R)}, {}, {}},
      {Scale, "Scale the selected points about their centre", {key(Key::E)}, {}, {}},
      {JointCorner, "Make the selected joint a corner", {shift(Key::C)}, {}, {}},
      {JointSmooth, "Make the selected joint smooth", {shift(Key::S)}, {}, {}},
      {JointSymmetric, "Make the selected joint symmetric", {shift(Key::Y)}, {}, {}},
      {ToggleComb, "Curvature comb of the selected curve on/off", {key(Key::K)}, {}, {}},
      {MirrorX, "Mirror the selected points in x", {}, {}, {}},
      {MirrorY, "Mirror the selected points in y", {}, {}, {}},
      {MirrorZ, "Mirror the selected points in z", {}, {}, {}},
      {SnapToPoints, "Snap to control points", {}, {}, {}},
      {SnapToCurves, "Snap to curves", {}, {}, {}},
      {SnapToAxis, "Snap to the axis (x = 0)", {}, {}, {}},
      {PlayPause, "Play / pause the riders", {shift(Key::Space)}, {}, {}},
      {DesktopFileDialogs, "Use the desktop's file dialog", {}, {}, {}},
      {ExportGlbQuantized, "Export glb, quantized (smaller, for the web)", {}, {}, {}},
      {ExportSvg, "Export SVG of the planar curves", {}, {}, {}},
      {Export3mf, "Export 3MF for 3D printing (checked for printability)", {}, {}, {}},
      {ToggleNormals, "Normals on/off (violet segments on the surfaces)", {key(Key::N)}, {}, {}},
      {SnapSelectionToGrid, "Snap the selected points to the grid", {}, {}, {}},
      {ConvertToBezier, "Convert the curve to Bezier (exact)", {}, {}, {}},
      {ConvertToHermite, "Convert the curve to Hermite (exact, for a curve without corners)", {}, {}, {}},
      {ConvertToBSpline, "Convert the curve to B-spline (a fit within a thousandth of its size)", {}, {}, {}},
      {ConvertToCatmullRom, "Convert the curve to Catmull-Rom (a fit within a thousandth of its size)", {}, {}, {}},
      {Pen, "Pen: draw a curve by clicking (drag: handles; Enter or Esc ends)", {key(Key::B)}, {}, {}},
  };
}

}  // namespace

std::string label(const Shortcut& shortcut) {
  std::string text;
  if (shortcut.ctrl) text += "Ctrl+";
  if (shortcut.shift) text += "Shift+";
  // The keys without a letter of their own; the letters are named by their upper-case ASCII code.
  static constexpr std::pair<Key, std::string_view> kNamed[] = {{Key::Space, "Space"},
                                                                {Key::Escape, "Esc"},
                                                                {Key::Backspace, "Backspace"},
                                                                {Key::Insert, "Insert"},
                                                                {Key::Delete, "Del"},
                                                                {Key::Home, "Home"},
                                                                {Key::F1, "F1"},
                                                                {Key::Keypad1, "Numpad 1"},
                                                                {Key::Keypad3, "Numpad 3"},
                                                                {Key::Keypad7, "Numpad 7"},
                                                                {Key::Enter, "Enter"},
                                                                {Key::KeypadEnter, "Numpad Enter"}};
  for (const auto& [named, name] : kNamed) {
    if (shortcut.key == named) return text + std::string(name);
  }
  return text + char(static_cast<int>(shortcut.key));
}

CommandTable::CommandTable() : commands_(all_commands()) {
  for (std::size_t i = 0; i < commands_.size(); ++i) {
    if (static_cast<std::size_t>(commands_[i].id) != i) throw std::logic_error("commands out of CommandId order");
  }
}

void CommandTable::bind(CommandId id, std::function<void()> run, std::function<bool()> enabled) {
  Command& command = commands_[static_cast<std::size_t>(id)];
  command.run = std::move(run);
  command.enabled = std::move(enabled);
}

const Command& CommandTable::get(CommandId id) const {
  return commands_[static_cast<std::size_t>(id)];
}

bool CommandTable::enabled(CommandId id) const {
  const Command& command = get(id);
  return command.run && (!command.enabled || command.enabled());
}

bool CommandTable::run(CommandId id) {
  if (!enabled(id)) return false;
  get(id).run();
  return true;
}

std::optional<CommandId> CommandTable::find(const Shortcut& pressed) const {
  for (const Command& command : commands_) {
    for (const Shortcut& s : command.shortcuts) {
      if (s == pressed) return command.id;
    }
  }
  if (pressed.ctrl || !pressed.shift) return std::nullopt;
  return find(Shortcut{pressed.key, false, false});
}

bool CommandTable::press(const Shortcut& pressed) {
  const std::optional<CommandId> id = find(pressed);
  return id && run(*id);
}

bool CommandTable::press(const Shortcut& pressed, bool interface_open) {
  if (interface_open && pressed.key == Key::Escape && !pressed.ctrl && !pressed.shift) return false;
  return press(pressed);
}

std::string CommandTable::shortcut_label(CommandId id) const {
  const Command& command = get(id);
  return command.shortcuts.empty() ? std::string() : label(command.shortcuts.front());
}

std::string CommandTable::all_shortcuts_label(CommandId id) const {
  std::string text;
  for (const Shortcut& s : get(id).shortcuts) text += (text.empty() ? "" : " / ") + label(s);
  return text;
}

std::string CommandTable::button_label(CommandId id) const {
  const std::string shortcut = shortcut_label(id);
  std::string text(get(id).label);
  return shortcut.empty() ? text : text + " [" + shortcut + "]";
}

}  // namespace sweep::editor
