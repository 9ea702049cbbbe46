#pragma once
// The desktop's own file dialog for Open and Save As: the XDG desktop portal (libportal), or
// zenity or kdialog when one is on the PATH; the in-app browser (file_browser.hpp) otherwise.
// Which one is decided here, once (choose_chooser); the dialog runs on a thread of its own
// (FileChoice) so the window keeps drawing, and says when it is done through a wake function.
// No GL; the viewer (app/viewer/dialog_actions.cpp) shows the result.
#include "desktop/user_folders.hpp"

#include <atomic>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace sweep::editor {

/// The user's setting: the desktop's dialog where there is one, or always the in-app browser.
enum class ChooserPreference { Auto, InApp };

/// "auto" or "in-app"; nullopt for anything else.
std::optional<ChooserPreference> chooser_preference_named(std::string_view name);
const char* chooser_preference_name(ChooserPreference preference);

/// Which dialog asks for a file.
enum class ChooserKind { InApp, Portal, Zenity, Kdialog };

/// "Sweep's own browser", "the desktop portal", "zenity", "kdialog": for messages.
const char* chooser_kind_label(ChooserKind kind);

/// What the desktop offers, as probe_chooser_system found it.
struct ChooserSystem {
  bool portal = false;  // org.freedesktop.portal.Desktop is on (or activatable on) the session bus
  std::string zenity;   // its path on the PATH, or ""
  std::string kdialog;  // the same
  bool kde = false;     // XDG_CURRENT_DESKTOP names KDE: kdialog before zenity
};

/// Looks at the environment: PATH for zenity and kdialog, XDG_CURRENT_DESKTOP, and, only when
/// DBUS_SESSION_BUS_ADDRESS is set, the session bus for the portal (two calls of at most 0.5 s
/// each). Never throws.
ChooserSystem probe_chooser_system(const Environment& env);

/// The one rule: InApp when the preference says so; else the portal, else kdialog on KDE, else
/// zenity, else kdialog, else InApp.
ChooserKind choose_chooser(ChooserPreference preference, const ChooserSystem& system);

/// What to ask for. `folder`: where the dialog starts; `file`: for Save, the file being saved
/// (or just a suggested name in `folder`).
struct ChooserRequest {
  enum class Purpose { Open, Save } purpose = Purpose::Open;
  std::filesystem::path folder;
  std::filesystem::path file;
};

/// The command line that asks zenity or kdialog (`program`: its path) for `request`: SWP files
/// listed first, all files on request, overwriting confirmed by the dialog when saving.
/// Precondition: `kind` is Zenity or Kdialog.
std::vector<std::string> chooser_command(ChooserKind kind, const std::string& program, const ChooserRequest& request);

/// How a dialog ended.
struct ChooserResult {
  enum class Outcome { Chosen, Cancelled, Failed } outcome = Outcome::Cancelled;
  std::string path;     // Chosen: the file, absolute
  std::string problem;  // Failed: why, naming the dialog ("zenity exited with status 5: ...")
};

/// A dialog program's exit as a result: status 0 with a path on the first line of `output` is
/// Chosen, 0 without one or 1 is Cancelled, anything else (or `exit_status` < 0: it did not run
/// or was killed) is Failed, with `errors` (its stderr, first line) in the problem.
ChooserResult command_result(const std::string& program, int exit_status, const std::string& output,
                             const std::string& errors);

/// One dialog on its own thread. `wake` is called on that thread once it is done (the viewer
/// posts an empty event so its loop looks again). Destroying it while the dialog is open closes
/// the dialog (the program is killed, the portal request cancelled) and waits for the thread.
class FileChoice {
 public:
  /// Precondition: `kind` is not InApp; `program` is zenity's or kdialog's path for those.
  FileChoice(ChooserKind kind, std::string program, ChooserRequest request, std::function<void()> wake);
  ~FileChoice();
  FileChoice(const FileChoice&) = delete;
  FileChoice& operator=(const FileChoice&) = delete;

  ChooserKind kind() const { return kind_; }
  ChooserRequest::Purpose purpose() const { return purpose_; }
  bool finished() const;
  /// The result. Precondition: finished().
  ChooserResult take();

  /// What a dialog does on the thread: runs until the user answers or `cancel` says stop.
  struct Cancel;

 private:
  ChooserKind kind_;
  ChooserRequest::Purpose purpose_;
  std::shared_ptr<Cancel> cancel_;
  std::shared_ptr<std::atomic<bool>> done_;
  std::shared_ptr<ChooserResult> result_;
  std::thread thread_;
};

}  // namespace sweep::editor
