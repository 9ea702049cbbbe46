#pragma once
// The command table: every user action of the viewer has one entry with its id, label,
// shortcuts, enabled-predicate and action. Keys, menus and buttons all look commands up here,
// and the shortcut labels the UI shows are made from it (README's key table is checked against
// it by a test). The editor defines the commands; the viewer binds what they do.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::editor {

/// Keys that shortcuts use. The values are GLFW's key codes (the platform layer checks this at
/// compile time), so the window layer passes its codes through unchanged.
enum class Key : int {
  Space = 32,
  Digit1 = 49,
  Digit3 = 51,
  Digit7 = 55,
  A = 65,
  B = 66,
  C = 67,
  E = 69,
  F = 70,
  G = 71,
  I = 73,
  K = 75,
  N = 78,
  Q = 81,
  O = 79,
  P = 80,
  R = 82,
  S = 83,
  V = 86,
  X = 88,
  Y = 89,
  Z = 90,
  Escape = 256,
  Enter = 257,
  Backspace = 259,
  Insert = 260,
  Delete = 261,
  Home = 268,
  F1 = 290,
  Keypad1 = 321,
  Keypad3 = 323,
  Keypad7 = 327,
  KeypadEnter = 335,
};

struct Shortcut {
  Key key = Key::Space;
  bool ctrl = false;  // Ctrl, or Cmd on macOS
  bool shift = false;
  bool operator==(const Shortcut&) const = default;
};

/// "Ctrl+Shift+Z", "S", "Space", "Esc", "Del".
std::string label(const Shortcut& shortcut);

enum class CommandId : std::uint8_t {
  Open,
  Save,
  SaveAs,
  ExportObj,
  SavePng,
  Quit,
  Undo,
  Redo,
  InsertPoint,
  DeletePoint,
  CycleSurfaces,
  CycleCurves,
  TogglePoints,
  ProfileView,
  ResetCamera,
  ViewFront,
  ViewTop,
  ViewSide,
  OpenBrowser,  // the file browser for Open
  New,          // an untitled, empty document
  ExportStl,
  ExportGlb,
  SaveWindowPng,    // the whole window, panels included (SavePng: the 3D view alone)
  ToggleGrid,       // the ground grid and the axes
  FrameSelection,   // fit the selected object (or everything) into the uncovered view
  FrameAll,         // fit everything
  Help,             // the Help window: every command and its keys
  SelectAllPoints,  // every control point of the selected curve
  Grab,             // modal transforms of the selected points (point_transform.hpp)
  Rotate,
  Scale,
  JointCorner,  // the selected Bezier joint's type (bezier_joints.hpp)
  JointSmooth,
  JointSymmetric,
  ToggleComb,  // the selected curve's curvature comb
  MirrorX,     // the selected points mirrored about their centre's plane
  MirrorY,
  MirrorZ,
  SnapToPoints,  // what a dragged point snaps to (snapping.hpp)
  SnapToCurves,
  SnapToAxis,
  PlayPause,            // the riders' clock (playback.hpp)
  DesktopFileDialogs,   // Open and Save As in the desktop's dialog, or in Sweep's own browser
  ExportGlbQuantized,   // glb with quantized vertices (KHR_mesh_quantization)
  ExportSvg,            // the planar curves as PREFIX.svg
  Export3mf,            // PREFIX.3mf for 3D printing, at the File panel's print height, checked
  ToggleNormals,        // the surfaces' normals, with either surface mode
  SnapSelectionToGrid,  // the selected points moved to the nearest grid points
  ConvertToBezier,      // the selected curve converted, keeping its dimension (edit_convert.cpp)
  ConvertToHermite,
  ConvertToBSpline,
  ConvertToCatmullRom,
  Pen,  // drawing a curve by clicking (editor/pen.hpp)
};

struct Command {
  CommandId id = CommandId::Open;
  std::string_view label;           // as menus and the README show it
  std::vector<Shortcut> shortcuts;  // the first is the one labels show
  std::function<bool()> enabled;    // unset: enabled when bound
  std::function<void()> run;        // unset: not bound (disabled)
};

class CommandTable {
 public:
  /// Every command, unbound.
  CommandTable();

  /// Says what `id` does and when it can. Replaces an earlier binding.
  void bind(CommandId id, std::function<void()> run, std::function<bool()> enabled = {});

  const Command& get(CommandId id) const;
  const std::vector<Command>& commands() const { return commands_; }
  /// Bound, and its predicate (if any) says yes.
  bool enabled(CommandId id) const;
  /// Runs `id` if it is enabled. Returns whether it ran.
  bool run(CommandId id);

  /// The command a key press means: the exact shortcut, else (without Ctrl) the same key
  /// ignoring Shift. nullopt if none.
  std::optional<CommandId> find(const Shortcut& pressed) const;
  /// Runs the command of a key press, if any is enabled. Returns whether one ran.
  bool press(const Shortcut& pressed);
  /// press(), unless the key belongs to the interface: Esc while a menu, popup or typed field
  /// is open (`interface_open`) closes that, and only Esc with nothing open quits.
  bool press(const Shortcut& pressed, bool interface_open);

  /// The first shortcut's label ("Ctrl+S"), or "" for a command without one.
  std::string shortcut_label(CommandId id) const;
  /// Every shortcut, joined with " / " ("Ctrl+Shift+Z / Ctrl+Y").
  std::string all_shortcuts_label(CommandId id) const;
  /// "LABEL [SHORTCUT]" for buttons, or the label alone.
  std::string button_label(CommandId id) const;

 private:
  std::vector<Command> commands_;  // indexed by CommandId
};

}  // namespace sweep::editor
