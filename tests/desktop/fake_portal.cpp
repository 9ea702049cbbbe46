// A stand-in for xdg-desktop-portal's FileChooser on a private session bus, for the tests of the
// portal dialog (file_chooser_portal_test.cpp, the viewer's dialog GUI test):
//
//   sweep_fake_portal ANSWER LOG
//
// owns org.freedesktop.portal.Desktop, prints "ready" once it does, and answers every OpenFile
// and SaveFile as the portal does (a Request handle, then its Response signal): with the path
// on ANSWER's first line as a file:// URI, or cancelled when that line is "cancel" (ANSWER is
// read at each call, so a test may change it between calls). Each call is appended to LOG:
// "OpenFile TITLE" or "SaveFile TITLE NAME FOLDER" (the current_name and current_folder).
#include <gio/gio.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

constexpr const char* kIntrospection = R"(<node>
  <interface name='org.freedesktop.portal.FileChooser'>
    <method name='OpenFile'>
      <arg type='s' direction='in'/><arg type='s' direction='in'/><arg type='a{sv}' direction='in'/>
      <arg type='o' direction='out'/>
    </method>
    <method name='SaveFile'>
      <arg type='s' direction='in'/><arg type='s' direction='in'/><arg type='a{sv}' direction='in'/>
      <arg type='o' direction='out'/>
    </method>
    <property name='version' type='u' access='read'/>
  </interface>
</node>)";

std::string g_answer_file;
std::string g_log_file;

std::string option_text(GVariant* options, const char* key) {
  GVariant* value = g_variant_lookup_value(options, key, nullptr);
  if (value == nullptr) return "-";
  std::string text = g_variant_is_of_type(value, G_VARIANT_TYPE_STRING) ? g_variant_get_string(value, nullptr)
                                                                        : g_variant_get_bytestring(value);
  g_variant_unref(value);
  return text;
}

/// The Request object path the caller waits on: /org/freedesktop/portal/desktop/request/SENDER/TOKEN.
std::string request_path(const char* sender, GVariant* options) {
  std::string who = sender + 1;  // ":1.5" -> "1_5"
  for (char& c : who)
    if (c == '.') c = '_';
  return "/org/freedesktop/portal/desktop/request/" + who + "/" + option_text(options, "handle_token");
}

struct Response {
  GDBusConnection* bus;
  std::string sender;
  std::string path;
};

gboolean respond(gpointer data) {
  auto* r = static_cast<Response*>(data);
  std::ifstream in(g_answer_file);
  std::string answer;
  std::getline(in, answer);
  GVariantBuilder results;
  g_variant_builder_init(&results, G_VARIANT_TYPE_VARDICT);
  const bool cancel = answer == "cancel";
  if (!cancel) {
    gchar* uri = g_filename_to_uri(answer.c_str(), nullptr, nullptr);
    const gchar* uris[] = {uri, nullptr};
    g_variant_builder_add(&results, "{sv}", "uris", g_variant_new_strv(uris, -1));
    g_free(uri);
  }
  g_dbus_connection_emit_signal(r->bus, r->sender.c_str(), r->path.c_str(), "org.freedesktop.portal.Request",
                                "Response", g_variant_new("(ua{sv})", cancel ? 1u : 0u, &results), nullptr);
  delete r;
  return G_SOURCE_REMOVE;
}

void on_call(GDBusConnection* bus, const gchar* sender, const gchar*, const gchar*, const gchar* method,
             GVariant* parameters, GDBusMethodInvocation* invocation, gpointer) {
  const gchar* parent = nullptr;
  const gchar* title = nullptr;
  GVariant* options = nullptr;
  g_variant_get(parameters, "(&s&s@a{sv})", &parent, &title, &options);
  std::string line = std::string(method) + " " + title;
  if (g_str_equal(method, "SaveFile")) {
    line += " " + option_text(options, "current_name") + " " + option_text(options, "current_folder");
  }
  std::ofstream(g_log_file, std::ios::app) << line << "\n";
  const std::string path = request_path(sender, options);
  g_variant_unref(options);
  g_dbus_method_invocation_return_value(invocation, g_variant_new("(o)", path.c_str()));
  g_idle_add(respond, new Response{bus, sender, path});
}

GVariant* on_get(GDBusConnection*, const gchar*, const gchar*, const gchar*, const gchar*, GError**, gpointer) {
  return g_variant_new_uint32(3);
}

void on_bus(GDBusConnection* bus, const gchar*, gpointer) {
  static const GDBusInterfaceVTable vtable = {on_call, on_get, nullptr, {}};
  GDBusNodeInfo* info = g_dbus_node_info_new_for_xml(kIntrospection, nullptr);
  g_dbus_connection_register_object(bus, "/org/freedesktop/portal/desktop", info->interfaces[0], &vtable, nullptr,
                                    nullptr, nullptr);
  g_dbus_node_info_unref(info);
}

void on_name(GDBusConnection*, const gchar*, gpointer) {
  std::printf("ready\n");
  std::fflush(stdout);
}

void on_lost(GDBusConnection*, const gchar* name, gpointer loop) {
  std::fprintf(stderr, "sweep_fake_portal: cannot own %s\n", name);
  g_main_loop_quit(static_cast<GMainLoop*>(loop));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: sweep_fake_portal ANSWER LOG\n");
    return 2;
  }
  g_answer_file = argv[1];
  g_log_file = argv[2];
  GMainLoop* loop = g_main_loop_new(nullptr, FALSE);
  g_bus_own_name(G_BUS_TYPE_SESSION, "org.freedesktop.portal.Desktop", G_BUS_NAME_OWNER_FLAGS_NONE, on_bus, on_name,
                 on_lost, loop, nullptr);
  g_main_loop_run(loop);
  return 1;
}
