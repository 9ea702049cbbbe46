// The main panel's menus: File, Edit, View, Help. Every item is a command.
#include "app/viewer/actions.hpp"
#include "app/viewer/dialog_actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <string>
#include <string_view>

namespace sweep::viewer::panels {

void menu_bar(ViewerState& s, editor::CommandTable& commands) {
  using editor::CommandId;
  if (!ImGui::BeginMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    command_menu_item(commands, CommandId::New);
    command_menu_item(commands, CommandId::OpenBrowser);
    command_menu_item(commands, CommandId::Save);
    command_menu_item(commands, CommandId::SaveAs);
    command_menu_item(commands, CommandId::DesktopFileDialogs, {}, desktop_dialogs_on(s));
    ImGui::Separator();
    for (CommandId id :
         {CommandId::ExportObj, CommandId::ExportStl, CommandId::ExportGlb, CommandId::ExportGlbQuantized,
          CommandId::Export3mf, CommandId::ExportSvg, CommandId::SavePng, CommandId::SaveWindowPng}) {
      command_menu_item(commands, id);
    }
    ImGui::Separator();
    command_menu_item(commands, CommandId::Quit);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Edit")) {
    command_menu_item(commands, CommandId::Undo, "Undo " + s.session.undo_label());
    command_menu_item(commands, CommandId::Redo, "Redo " + s.session.redo_label());
    ImGui::Separator();
    command_menu_item(commands, CommandId::Pen, {}, s.pen.on);
    command_menu_item(commands, CommandId::InsertPoint, insert_label(s));
    if (ImGui::BeginMenu("Convert the curve to", commands.enabled(CommandId::ConvertToBezier))) {
      // The submenu names the kind; the command's label (Help) says the whole of it.
      constexpr std::string_view kPrefix = "Convert the curve to ";
      for (CommandId id : {CommandId::ConvertToBezier, CommandId::ConvertToHermite, CommandId::ConvertToBSpline,
                           CommandId::ConvertToCatmullRom}) {
        command_menu_item(commands, id, std::string(commands.get(id).label.substr(kPrefix.size())));
      }
      ImGui::EndMenu();
    }
    command_menu_item(commands, CommandId::DeletePoint);
    ImGui::Separator();
    for (CommandId id : {CommandId::SelectAllPoints, CommandId::Grab, CommandId::Rotate, CommandId::Scale,
                         CommandId::MirrorX, CommandId::MirrorY, CommandId::MirrorZ, CommandId::SnapSelectionToGrid}) {
      command_menu_item(commands, id);
    }
    ImGui::Separator();
    for (CommandId id : {CommandId::JointCorner, CommandId::JointSmooth, CommandId::JointSymmetric}) {
      command_menu_item(commands, id);
    }
    ImGui::Separator();
    for (CommandId id : {CommandId::SnapToPoints, CommandId::SnapToCurves, CommandId::SnapToAxis}) {
      command_menu_item(commands, id);
    }
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("View")) {
    for (CommandId id :
         {CommandId::CycleSurfaces, CommandId::ToggleNormals, CommandId::CycleCurves, CommandId::TogglePoints,
          CommandId::ToggleGrid, CommandId::ToggleComb, CommandId::ProfileView}) {
      command_menu_item(commands, id);
    }
    ImGui::Separator();
    for (CommandId id : {CommandId::FrameSelection, CommandId::FrameAll, CommandId::ResetCamera, CommandId::ViewFront,
                         CommandId::ViewTop, CommandId::ViewSide}) {
      command_menu_item(commands, id);
    }
    ImGui::Separator();
    command_menu_item(commands, CommandId::PlayPause);  // greyed out without riders
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Help")) {
    command_menu_item(commands, CommandId::Help);
    ImGui::EndMenu();
  }
  ImGui::EndMenuBar();
}

}  // namespace sweep::viewer::panels
