#include "app/viewer/command_bindings.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/curve_actions.hpp"
#include "app/viewer/dialog_actions.hpp"
#include "app/viewer/pen_actions.hpp"
#include "model/evaluation/riders.hpp"

#include <utility>

namespace sweep::viewer {
namespace {

using editor::CommandId;

void bind_files(editor::CommandTable& t, ViewerState& s) {
  t.bind(CommandId::Open, [&s] { request_open(s, s.fields.open.get()); });
  t.bind(CommandId::OpenBrowser, [&s] { open_browser(s, BrowserPurpose::Open); });
  t.bind(CommandId::New, [&s] { request_new(s); });
  t.bind(CommandId::Save, [&s] { save_current(s); });
  t.bind(CommandId::SaveAs, [&s] { ask_save_path(s); });
  t.bind(CommandId::DesktopFileDialogs, [&s] { toggle_desktop_dialogs(s); });
  const std::pair<CommandId, io::ExportFormat> exports[] = {{CommandId::ExportObj, io::ExportFormat::Obj},
                                                            {CommandId::ExportStl, io::ExportFormat::Stl},
                                                            {CommandId::ExportGlb, io::ExportFormat::Glb},
                                                            {CommandId::Export3mf, io::ExportFormat::ThreeMf}};
  for (const auto& [id, format] : exports) {
    t.bind(id, [&s, format = format] { export_document(s, s.fields.export_prefix.get(), format); });
  }
  t.bind(CommandId::ExportGlbQuantized,
         [&s] { export_document(s, s.fields.export_prefix.get(), io::ExportFormat::Glb, io::GlbEncoding::Quantized); });
  t.bind(CommandId::ExportSvg, [&s] { export_planar_curves(s, s.fields.export_prefix.get()); });
  t.bind(CommandId::SavePng, [&s] { open_png_dialog(s); });
  t.bind(CommandId::SaveWindowPng, [&s] { request_screenshot(s, s.fields.screenshot.get(), true); });
  t.bind(CommandId::Quit, [&s] { request_quit(s); });
}

void bind_edits(editor::CommandTable& t, ViewerState& s) {
  t.bind(
      CommandId::Undo, [&s] { undo(s); }, [&s] { return s.session.can_undo(); });
  t.bind(
      CommandId::Redo, [&s] { redo(s); }, [&s] { return s.session.can_redo(); });
  const auto has_point = [&s] { return selected_control_curve(s) != nullptr && s.selection.point >= 0; };
  t.bind(
      CommandId::InsertPoint, [&s] { insert_after_selected_point(s); }, has_point);
  t.bind(
      CommandId::DeletePoint, [&s] { delete_selected_point(s); }, has_point);
  t.bind(CommandId::Pen, [&s] { toggle_pen(s); });
}

void bind_view(editor::CommandTable& t, ViewerState& s) {
  t.bind(CommandId::CycleSurfaces, [&s] { s.display.surface = render::next(s.display.surface); });
  t.bind(CommandId::CycleCurves, [&s] { s.display.curves = render::next(s.display.curves); });
  t.bind(CommandId::TogglePoints, [&s] { s.display.control_points = !s.display.control_points; });
  t.bind(CommandId::ToggleNormals, [&s] { s.display.normals = !s.display.normals; });
  t.bind(CommandId::ToggleGrid, [&s] { s.display.grid = !s.display.grid; });
  t.bind(CommandId::ProfileView, [&s] { set_profile_view(s, !s.profile_view); });
  t.bind(CommandId::ResetCamera, [&s] { reset_camera(s); });
  t.bind(CommandId::FrameSelection, [&s] { frame_selection(s); });
  t.bind(CommandId::FrameAll, [&s] { frame_all(s); });
  t.bind(CommandId::Help, [&s] { s.show_help = !s.show_help; });
  t.bind(
      CommandId::PlayPause, [&s] { toggle_playback(s); }, [&s] { return longest_loop(s.doc()) > 0.0; });
  const auto free_view = [&s] { return !s.profile_view; };
  t.bind(
      CommandId::ViewFront, [&s] { set_view(s, render::ViewPreset::Front); }, free_view);
  t.bind(
      CommandId::ViewTop, [&s] { set_view(s, render::ViewPreset::Top); }, free_view);
  t.bind(
      CommandId::ViewSide, [&s] { set_view(s, render::ViewPreset::Side); }, free_view);
}

void bind_curve_editing(editor::CommandTable& t, ViewerState& s) {
  const auto has_joint = [&s] { return selected_joint(s) >= 0; };
  const std::pair<CommandId, editor::JointType> joints[] = {{CommandId::JointCorner, editor::JointType::Corner},
                                                            {CommandId::JointSmooth, editor::JointType::Smooth},
                                                            {CommandId::JointSymmetric, editor::JointType::Symmetric}};
  for (const auto& [id, type] : joints) {
    t.bind(
        id, [&s, type = type] { convert_selected_joint(s, type); }, has_joint);
  }
  t.bind(CommandId::ToggleComb, [&s] { s.curve_editing.comb = !s.curve_editing.comb; });
  const auto has_points = [&s] { return selected_control_curve(s) != nullptr; };
  t.bind(
      CommandId::SelectAllPoints, [&s] { select_all_points(s); }, has_points);
  const auto has_selection = [&s] { return selected_control_curve(s) != nullptr && !s.selection.points().empty(); };
  const std::pair<CommandId, editor::TransformMode> transforms[] = {{CommandId::Grab, editor::TransformMode::Grab},
                                                                    {CommandId::Rotate, editor::TransformMode::Rotate},
                                                                    {CommandId::Scale, editor::TransformMode::Scale}};
  for (const auto& [id, mode] : transforms) {
    t.bind(
        id, [&s, mode = mode] { request_transform(s, mode); }, has_selection);
  }
  const auto has_several = [&s] { return selected_control_curve(s) != nullptr && s.selection.points().size() >= 2; };
  for (int axis = 0; axis < 3; ++axis) {
    t.bind(
        CommandId(int(CommandId::MirrorX) + axis), [&s, axis] { mirror_selected_points(s, axis); }, has_several);
  }
  t.bind(
      CommandId::SnapSelectionToGrid, [&s] { snap_selected_points(s); }, has_selection);
  const auto has_curve = [&s] { return selected_control_curve(s) != nullptr; };
  static constexpr std::pair<CommandId, std::pair<ObjectKind, ObjectKind>> kConversions[] = {
      {CommandId::ConvertToBezier, {ObjectKind::Bezier2, ObjectKind::Bezier3}},
      {CommandId::ConvertToHermite, {ObjectKind::Hermite2, ObjectKind::Hermite3}},
      {CommandId::ConvertToBSpline, {ObjectKind::BSpline2, ObjectKind::BSpline3}},
      {CommandId::ConvertToCatmullRom, {ObjectKind::CatmullRom2, ObjectKind::CatmullRom3}}};
  for (const auto& [id, to] : kConversions) {
    t.bind(
        id,
        [&s, to = to] {
          const Object* curve = selected_control_curve(s);
          if (curve != nullptr) convert_selected_curve(s, is_planar_curve(curve->kind()) ? to.first : to.second);
        },
        has_curve);
  }
  editor::SnapOptions& snap = s.curve_editing.snap;
  t.bind(CommandId::SnapToPoints, [&snap] { snap.points = !snap.points; });
  t.bind(CommandId::SnapToCurves, [&snap] { snap.curves = !snap.curves; });
  t.bind(CommandId::SnapToAxis, [&snap] { snap.axis = !snap.axis; });
}

}  // namespace

void bind_commands(editor::CommandTable& table, ViewerState& state) {
  bind_files(table, state);
  bind_edits(table, state);
  bind_view(table, state);
  bind_curve_editing(table, state);
}

}  // namespace sweep::viewer
