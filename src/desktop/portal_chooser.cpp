// The XDG desktop portal's FileChooser through libportal: the request and its answer run in a
// GLib main context of this thread's own, so nothing else of Sweep needs a GLib main loop.
#include "desktop/chooser_backends.hpp"

#include <gio/gio.h>
#include <libportal/portal.h>

#include <memory>

namespace sweep::editor {
namespace {

constexpr const char* kPortalName = "org.freedesktop.portal.Desktop";
constexpr int kBusTimeoutMs = 500;

template <typename T>
struct GObjectDeleter {
  void operator()(T* p) const {
    if (p != nullptr) g_object_unref(p);
  }
};
template <typename T>
using GObjectPtr = std::unique_ptr<T, GObjectDeleter<T>>;

/// What the portal's callback hands back to the waiting loop.
struct PortalAnswer {
  GMainLoop* loop = nullptr;
  bool save = false;
  ChooserResult result;
};

/// The first URI of the portal's answer as a local path.
ChooserResult chosen_from(GVariant* answer) {
  ChooserResult result;
  const gchar** uris = nullptr;
  if (answer == nullptr || !g_variant_lookup(answer, "uris", "^a&s", &uris) || uris == nullptr || uris[0] == nullptr) {
    g_free(uris);
    return result;  // nothing chosen
  }
  GError* error = nullptr;
  gchar* path = g_filename_from_uri(uris[0], nullptr, &error);
  if (path != nullptr) {
    result.outcome = ChooserResult::Outcome::Chosen;
    result.path = path;
  } else {
    result.outcome = ChooserResult::Outcome::Failed;
    result.problem = std::string("the desktop portal chose ") + uris[0] + ", which is not a local file";
    g_error_free(error);
  }
  g_free(path);
  g_free(uris);
  return result;
}

void on_answer(GObject* source, GAsyncResult* async, gpointer data) {
  auto* answer = static_cast<PortalAnswer*>(data);
  auto* portal = XDP_PORTAL(source);
  GError* error = nullptr;
  GVariant* value = answer->save ? xdp_portal_save_file_finish(portal, async, &error)
                                 : xdp_portal_open_file_finish(portal, async, &error);
  if (value != nullptr) {
    answer->result = chosen_from(value);
    g_variant_unref(value);
  } else {
    if (!g_error_matches(error, G_IO_ERROR, G_IO_ERROR_CANCELLED)) {
      answer->result.outcome = ChooserResult::Outcome::Failed;
      answer->result.problem = std::string("the desktop portal failed: ") + (error ? error->message : "no answer");
    }
    if (error != nullptr) g_error_free(error);
  }
  g_main_loop_quit(answer->loop);
}

GVariant* swp_filters() {
  return g_variant_new_parsed(
      "[('SWP files', [(uint32 0, '*.swp'), (uint32 0, '*.SWP')]), ('All files', [(uint32 0, '*')])]");
}

void ask(XdpPortal* portal, const ChooserRequest& request, GCancellable* cancellable, PortalAnswer& answer) {
  if (!answer.save) {
    xdp_portal_open_file(portal, nullptr, "Open a file", swp_filters(), nullptr, nullptr, XDP_OPEN_FILE_FLAG_NONE,
                         cancellable, on_answer, &answer);
    return;
  }
  const std::filesystem::path file = request.file.is_absolute() ? request.file : request.folder / request.file;
  const bool exists = !request.file.empty() && std::filesystem::exists(file);
  const std::string name = request.file.empty() ? std::string("untitled.swp") : file.filename().string();
  const std::string folder = request.file.empty() ? request.folder.string() : file.parent_path().string();
  xdp_portal_save_file(portal, nullptr, "Save the document as", name.c_str(), folder.c_str(),
                       exists ? file.c_str() : nullptr, swp_filters(), nullptr, nullptr, XDP_SAVE_FILE_FLAG_NONE,
                       cancellable, on_answer, &answer);
}

bool bus_call_true(GDBusConnection* bus, const char* method, GVariant* args, const char* reply_type) {
  GVariant* reply = g_dbus_connection_call_sync(bus, "org.freedesktop.DBus", "/org/freedesktop/DBus",
                                                "org.freedesktop.DBus", method, args, G_VARIANT_TYPE(reply_type),
                                                G_DBUS_CALL_FLAGS_NONE, kBusTimeoutMs, nullptr, nullptr);
  if (reply == nullptr) return false;
  bool found = false;
  if (g_variant_is_of_type(reply, G_VARIANT_TYPE("(b)"))) {
    gboolean owned = FALSE;
    g_variant_get(reply, "(b)", &owned);
    found = owned != FALSE;
  } else {
    const gchar** names = nullptr;
    g_variant_get(reply, "(^a&s)", &names);
    for (const gchar** n = names; n != nullptr && *n != nullptr; ++n) found = found || g_str_equal(*n, kPortalName);
    g_free(names);
  }
  g_variant_unref(reply);
  return found;
}

}  // namespace

void cancel_portal_request(void* cancellable) {
  if (cancellable != nullptr) g_cancellable_cancel(static_cast<GCancellable*>(cancellable));
}

bool portal_on_session_bus(const char* address) {
  const auto flags = static_cast<GDBusConnectionFlags>(G_DBUS_CONNECTION_FLAGS_AUTHENTICATION_CLIENT |
                                                       G_DBUS_CONNECTION_FLAGS_MESSAGE_BUS_CONNECTION);
  GDBusConnection* bus = g_dbus_connection_new_for_address_sync(address, flags, nullptr, nullptr, nullptr);
  if (bus == nullptr) return false;
  GObjectPtr<GDBusConnection> owned(bus);
  const bool found = bus_call_true(bus, "NameHasOwner", g_variant_new("(s)", kPortalName), "(b)") ||
                     bus_call_true(bus, "ListActivatableNames", nullptr, "(as)");
  g_dbus_connection_close_sync(bus, nullptr, nullptr);
  return found;
}

ChooserResult run_portal_chooser(const ChooserRequest& request, FileChoice::Cancel& cancel) {
  GMainContext* context = g_main_context_new();
  g_main_context_push_thread_default(context);
  GObjectPtr<GCancellable> cancellable(g_cancellable_new());
  PortalAnswer answer;
  answer.loop = g_main_loop_new(context, FALSE);
  answer.save = request.purpose == ChooserRequest::Purpose::Save;
  {
    std::lock_guard<std::mutex> lock(cancel.mutex);
    cancel.cancellable = cancellable.get();
  }
  if (!cancel.requested) {
    GObjectPtr<XdpPortal> portal(xdp_portal_new());
    ask(portal.get(), request, cancellable.get(), answer);
    g_main_loop_run(answer.loop);
  }
  {
    std::lock_guard<std::mutex> lock(cancel.mutex);
    cancel.cancellable = nullptr;
  }
  g_main_loop_unref(answer.loop);
  g_main_context_pop_thread_default(context);
  g_main_context_unref(context);
  if (cancel.requested) return {};
  return answer.result;
}

}  // namespace sweep::editor
