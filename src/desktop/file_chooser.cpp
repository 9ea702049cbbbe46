#include "desktop/file_chooser.hpp"

#include "base/precondition.hpp"
#include "desktop/chooser_backends.hpp"

#include <unistd.h>
#include <csignal>
#include <sstream>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;

constexpr const char* kOpenTitle = "Open a file";
constexpr const char* kSaveTitle = "Save the document as";

/// The first line of `text`, without its line end.
std::string first_line(const std::string& text) {
  std::string line = text.substr(0, text.find('\n'));
  if (!line.empty() && line.back() == '\r') line.pop_back();
  return line;
}

/// `name` found in one of PATH's folders as an executable file, or "".
std::string find_program(const char* name, const Environment& env) {
  const char* path = env("PATH");
  if (path == nullptr) return {};
  std::stringstream folders(path);
  std::string folder;
  while (std::getline(folders, folder, ':')) {
    if (folder.empty()) continue;
    const fs::path candidate = fs::path(folder) / name;
    if (::access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate.string();
  }
  return {};
}

bool names_kde(const char* desktop) {
  return desktop != nullptr && std::string_view(desktop).find("KDE") != std::string_view::npos;
}

/// The folder to start in, with the trailing '/' zenity needs to show a folder's contents.
std::string folder_text(const fs::path& folder) {
  std::string text = folder.empty() ? std::string(".") : folder.string();
  if (text.back() != '/') text += '/';
  return text;
}

/// The file a Save dialog starts with: the one being saved, or a name in the folder.
std::string save_target(const ChooserRequest& request) {
  if (request.file.empty()) return folder_text(request.folder) + "untitled.swp";
  if (request.file.is_absolute() || request.folder.empty()) return request.file.string();
  return (request.folder / request.file).string();
}

std::vector<std::string> zenity_command(const std::string& program, const ChooserRequest& request) {
  const bool save = request.purpose == ChooserRequest::Purpose::Save;
  std::vector<std::string> argv{program, "--file-selection"};
  if (save) {
    argv.insert(argv.end(), {"--save", "--confirm-overwrite"});
  }
  argv.push_back(std::string("--title=") + (save ? kSaveTitle : kOpenTitle));
  argv.push_back("--filename=" + (save ? save_target(request) : folder_text(request.folder)));
  argv.insert(argv.end(), {"--file-filter=SWP files | *.swp *.SWP", "--file-filter=All files | *"});
  return argv;
}

std::vector<std::string> kdialog_command(const std::string& program, const ChooserRequest& request) {
  const bool save = request.purpose == ChooserRequest::Purpose::Save;
  return {program,
          "--title",
          save ? kSaveTitle : kOpenTitle,
          save ? "--getsavefilename" : "--getopenfilename",
          save ? save_target(request) : folder_text(request.folder),
          "SWP files (*.swp *.SWP)"};
}

}  // namespace

std::optional<ChooserPreference> chooser_preference_named(std::string_view name) {
  if (name == "auto") return ChooserPreference::Auto;
  if (name == "in-app") return ChooserPreference::InApp;
  return std::nullopt;
}

const char* chooser_preference_name(ChooserPreference preference) {
  return preference == ChooserPreference::InApp ? "in-app" : "auto";
}

const char* chooser_kind_label(ChooserKind kind) {
  switch (kind) {
    case ChooserKind::InApp:
      return "Sweep's own browser";
    case ChooserKind::Portal:
      return "the desktop portal";
    case ChooserKind::Zenity:
      return "zenity";
    case ChooserKind::Kdialog:
      return "kdialog";
  }
  return "?";
}

ChooserSystem probe_chooser_system(const Environment& env) {
  ChooserSystem system;
  system.zenity = find_program("zenity", env);
  system.kdialog = find_program("kdialog", env);
  system.kde = names_kde(env("XDG_CURRENT_DESKTOP"));
  const char* bus = env("DBUS_SESSION_BUS_ADDRESS");
  system.portal = bus != nullptr && *bus != '\0' && portal_on_session_bus(bus);
  return system;
}

ChooserKind choose_chooser(ChooserPreference preference, const ChooserSystem& system) {
  if (preference == ChooserPreference::InApp) return ChooserKind::InApp;
  if (system.portal) return ChooserKind::Portal;
  if (system.kde && !system.kdialog.empty()) return ChooserKind::Kdialog;
  if (!system.zenity.empty()) return ChooserKind::Zenity;
  if (!system.kdialog.empty()) return ChooserKind::Kdialog;
  return ChooserKind::InApp;
}

std::vector<std::string> chooser_command(ChooserKind kind, const std::string& program, const ChooserRequest& request) {
  SWEEP_EXPECTS(kind == ChooserKind::Zenity || kind == ChooserKind::Kdialog, "kind is Zenity or Kdialog");
  return kind == ChooserKind::Zenity ? zenity_command(program, request) : kdialog_command(program, request);
}

ChooserResult command_result(const std::string& program, int exit_status, const std::string& output,
                             const std::string& errors) {
  ChooserResult result;
  const std::string path = first_line(output);
  if (exit_status == 0 && !path.empty()) {
    result.outcome = ChooserResult::Outcome::Chosen;
    result.path = fs::absolute(path).lexically_normal().string();
  } else if (exit_status == 0 || exit_status == 1) {
    result.outcome = ChooserResult::Outcome::Cancelled;
  } else {
    result.outcome = ChooserResult::Outcome::Failed;
    const std::string name = fs::path(program).filename().string();
    result.problem =
        exit_status < 0 ? name + " did not run" : name + " exited with status " + std::to_string(exit_status);
    const std::string why = first_line(errors);
    if (!why.empty()) result.problem += ": " + why;
  }
  return result;
}

void FileChoice::Cancel::request() {
  requested = true;
  std::lock_guard<std::mutex> lock(mutex);
  if (child > 0) ::kill(child, SIGTERM);
  cancel_portal_request(cancellable);
}

FileChoice::FileChoice(ChooserKind kind, std::string program, ChooserRequest request, std::function<void()> wake)
    : kind_(kind),
      purpose_(request.purpose),
      cancel_(std::make_shared<Cancel>()),
      done_(std::make_shared<std::atomic<bool>>(false)),
      result_(std::make_shared<ChooserResult>()) {
  SWEEP_EXPECTS(kind != ChooserKind::InApp, "kind is not InApp");
  thread_ = std::thread([kind, program = std::move(program), request = std::move(request), wake = std::move(wake),
                         cancel = cancel_, done = done_, result = result_] {
    *result = kind == ChooserKind::Portal ? run_portal_chooser(request, *cancel)
                                          : run_command_chooser(chooser_command(kind, program, request), *cancel);
    done->store(true);
    if (wake) wake();
  });
}

FileChoice::~FileChoice() {
  if (!done_->load()) cancel_->request();
  thread_.join();
}

bool FileChoice::finished() const {
  return done_->load();
}

ChooserResult FileChoice::take() {
  SWEEP_EXPECTS(finished(), "the dialog has finished");
  return std::move(*result_);
}

}  // namespace sweep::editor
