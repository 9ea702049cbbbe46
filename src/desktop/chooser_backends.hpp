#pragma once
// The two ways file_chooser.cpp runs a desktop dialog, on FileChoice's thread: a dialog program
// (zenity, kdialog) and the XDG desktop portal (libportal). Internal to the desktop layer.
#include "desktop/file_chooser.hpp"

#include <sys/types.h>
#include <atomic>
#include <mutex>
#include <string>
#include <vector>

namespace sweep::editor {

/// How FileChoice's destructor stops a dialog still open: the program is killed, the portal
/// request cancelled. Either may start after the stop was asked; each looks at `requested`.
struct FileChoice::Cancel {
  std::atomic<bool> requested{false};
  std::mutex mutex;
  pid_t child = 0;              // the running dialog program, under `mutex`
  void* cancellable = nullptr;  // the portal request's GCancellable*, under `mutex`

  /// Asks the dialog to stop (any thread).
  void request();
};

/// Runs `argv` (argv[0] a path), waits for it and reads what it prints. Never throws.
ChooserResult run_command_chooser(const std::vector<std::string>& argv, FileChoice::Cancel& cancel);

/// Asks the portal's FileChooser and waits for the answer. Never throws.
ChooserResult run_portal_chooser(const ChooserRequest& request, FileChoice::Cancel& cancel);

/// Cancels a running portal request (a GCancellable*; null: none). Any thread.
void cancel_portal_request(void* cancellable);

/// Whether org.freedesktop.portal.Desktop is on the bus at `address` (the session bus's) or can
/// be started there; a connection of its own, closed again.
bool portal_on_session_bus(const char* address);

}  // namespace sweep::editor
