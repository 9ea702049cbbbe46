#include "app/viewer/dialog_actions.hpp"

#include "app/viewer/actions.hpp"

#include <cstdio>

namespace sweep::viewer {
namespace {

using editor::ChooserKind;
using editor::ChooserRequest;
using editor::ChooserResult;
using SavePath = DesktopDialogs::SavePath;

/// Scripted runs (the GUI tests) follow what the dialogs did on stdout.
void report(const ViewerState& s, const std::string& line) {
  if (!s.report_saves) return;
  std::printf("%s\n", line.c_str());
  std::fflush(stdout);
}

constexpr const char* kNoDesktopDialog =
    "no desktop file dialog here (no desktop portal, zenity or kdialog): Sweep's own file browser opened";

/// The dialog this run uses, the desktop probed at the first call.
ChooserKind dialog_kind(ViewerState& s) {
  DesktopDialogs& d = s.dialogs;
  if (d.preference == editor::ChooserPreference::InApp) return ChooserKind::InApp;
  if (!d.system) d.system = editor::probe_chooser_system(editor::process_environment());
  return editor::choose_chooser(d.preference, *d.system);
}

const std::string& program_of(const editor::ChooserSystem& system, ChooserKind kind) {
  static const std::string kNone;
  if (kind == ChooserKind::Zenity) return system.zenity;
  if (kind == ChooserKind::Kdialog) return system.kdialog;
  return kNone;
}

/// Starts the desktop's dialog for `request`; false when the in-app one is to be used.
bool start_dialog(ViewerState& s, ChooserRequest request) {
  const ChooserKind kind = dialog_kind(s);
  DesktopDialogs& d = s.dialogs;
  if (kind == ChooserKind::InApp) {
    // Asked for and not there: said once, so a user who ticked the setting knows why.
    if (d.preference == editor::ChooserPreference::Auto && !d.fallback_said) {
      s.status = kNoDesktopDialog;
      d.fallback_said = true;
    }
    return false;
  }
  d.open = std::make_unique<editor::FileChoice>(kind, program_of(*d.system, kind), std::move(request), d.wake);
  s.status = std::string("choosing a file in ") + editor::chooser_kind_label(kind);
  report(s, std::string("dialog ") + editor::chooser_kind_label(kind));
  return true;
}

/// The desktop's dialog failed: say why, and let the in-app browser ask instead.
void fall_back(ViewerState& s, ChooserRequest::Purpose purpose, const std::string& problem) {
  s.error = problem + "; using Sweep's own file browser";
  report(s, "dialog failed: " + problem);
  s.browser.open_at(output_folder(s));
  if (purpose == ChooserRequest::Purpose::Open) {
    s.browser_for = BrowserPurpose::Open;
  } else {
    s.dialogs.save_path = SavePath::InApp;
  }
}

void answer_open(ViewerState& s, const ChooserResult& result) {
  if (result.outcome == ChooserResult::Outcome::Chosen) {
    report(s, "dialog chose " + result.path);
    request_open(s, result.path);
  } else if (result.outcome == ChooserResult::Outcome::Cancelled) {
    s.status = "nothing opened";
    report(s, "dialog cancelled");
  } else {
    fall_back(s, ChooserRequest::Purpose::Open, result.problem);
  }
}

void answer_save(ViewerState& s, const ChooserResult& result) {
  using Stage = editor::UnsavedChangesFlow::Stage;
  if (s.unsaved.stage() != Stage::AskPath) return;  // the question went away meanwhile
  if (result.outcome == ChooserResult::Outcome::Chosen) {
    report(s, "dialog chose " + result.path);
    const bool saved = save_to(s, result.path);
    s.unsaved.saved(saved, s.session.error());
    if (!saved) {  // the in-app question shows the error, with the path chosen
      s.fields.save_as.set(result.path);
      s.browser.open_at(output_folder(s));
      s.dialogs.save_path = SavePath::InApp;
    }
  } else if (result.outcome == ChooserResult::Outcome::Cancelled) {
    report(s, "dialog cancelled");
    s.unsaved.cancel();
  } else {
    fall_back(s, ChooserRequest::Purpose::Save, result.problem);
  }
}

}  // namespace

void init_dialogs(ViewerState& s, const editor::Environment& env, const std::filesystem::path& settings_file) {
  DesktopDialogs& d = s.dialogs;
  d.settings_file = settings_file;
  if (!settings_file.empty()) d.preference = editor::load_settings(settings_file).file_chooser;
  if (const auto forced = editor::chooser_preference_override(env)) d.preference = *forced;
}

bool start_open_dialog(ViewerState& s) {
  if (s.dialogs.open) {
    s.status = "a file dialog is open already";
    return true;
  }
  ChooserRequest request;
  request.purpose = ChooserRequest::Purpose::Open;
  request.folder = output_folder(s);
  return start_dialog(s, std::move(request));
}

bool save_path_in_desktop_dialog(ViewerState& s) {
  DesktopDialogs& d = s.dialogs;
  if (s.unsaved.stage() != editor::UnsavedChangesFlow::Stage::AskPath) {
    d.save_path = SavePath::None;
    return false;
  }
  if (d.save_path == SavePath::None) {
    ChooserRequest request;
    request.purpose = ChooserRequest::Purpose::Save;
    request.folder = output_folder(s);
    request.file = s.session.file().empty() ? std::string("untitled.swp") : s.session.file();
    d.save_path = !d.open && start_dialog(s, std::move(request)) ? SavePath::Desktop : SavePath::InApp;
  }
  return d.save_path == SavePath::Desktop;
}

bool poll_dialogs(ViewerState& s) {
  DesktopDialogs& d = s.dialogs;
  if (!d.open || !d.open->finished()) return false;
  const ChooserResult result = d.open->take();
  const ChooserRequest::Purpose purpose = d.open->purpose();
  d.open.reset();
  if (purpose == ChooserRequest::Purpose::Open) {
    answer_open(s, result);
  } else {
    answer_save(s, result);
  }
  return true;
}

void toggle_desktop_dialogs(ViewerState& s) {
  DesktopDialogs& d = s.dialogs;
  d.preference = desktop_dialogs_on(s) ? editor::ChooserPreference::InApp : editor::ChooserPreference::Auto;
  s.status = desktop_dialogs_on(s) ? "Open and Save As use the desktop's file dialog where there is one"
                                   : "Open and Save As use Sweep's own file browser";
  if (d.settings_file.empty()) return;
  editor::Settings settings = editor::load_settings(d.settings_file);
  settings.file_chooser = d.preference;
  if (const std::string problem = editor::save_settings(d.settings_file, settings); !problem.empty()) s.error = problem;
}

bool desktop_dialogs_on(const ViewerState& s) {
  return s.dialogs.preference == editor::ChooserPreference::Auto;
}

}  // namespace sweep::viewer
