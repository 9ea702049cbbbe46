// Finds and opens the sweep_gui module on demand, so commands that draw nothing never map GL,
// OSMesa, LLVM, GLFW or ImGui (all of which sweep_gui links).
#include "app/gui_module.hpp"

#include "geometry/thread_pool.hpp"

#include <dlfcn.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <system_error>
#include <vector>

namespace sweep::app {
namespace {

namespace fs = std::filesystem;

/// The module's file name (e.g. libsweep_gui.so), from the build.
constexpr const char* kGuiModuleName = SWEEP_GUI_MODULE_NAME;

/// Where `cmake --install` puts the module, relative to the executable's folder (e.g.
/// ../lib/x86_64-linux-gnu/sweep): cmake/install.cmake, from the same GNUInstallDirs variables.
constexpr const char* kGuiModuleInstallDir = SWEEP_GUI_MODULE_INSTALL_DIR;

/// Next to the executable (the build directory), then the install layout.
std::vector<fs::path> module_candidates() {
  std::error_code error;
  const fs::path exe = fs::read_symlink("/proc/self/exe", error);
  const fs::path dir = error ? fs::path(".") : exe.parent_path();
  return {dir / kGuiModuleName, (dir / kGuiModuleInstallDir / kGuiModuleName).lexically_normal()};
}

/// The first candidate that exists; the first one when none does (for the message).
fs::path module_path() {
  const std::vector<fs::path> candidates = module_candidates();
  for (const fs::path& candidate : candidates) {
    std::error_code error;
    if (fs::exists(candidate, error)) return candidate;
  }
  return candidates.front();
}

const GuiEntryPoints* fail(const fs::path& path, const std::string& why) {
  std::fprintf(stderr, "sweep: cannot load the viewer (%s): %s\n", path.c_str(), why.c_str());
  return nullptr;
}

const GuiEntryPoints* open_module() {
  const fs::path path = module_path();
  // RTLD_NOW: a missing symbol fails here with one message, not in the middle of a command.
  void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) return fail(path, dlerror());
  auto entry = reinterpret_cast<GuiEntryFunction>(dlsym(handle, kGuiEntrySymbol));
  if (!entry) return fail(path, dlerror());
  const GuiEntryPoints* points = entry();
  if (!points || points->version != kGuiInterfaceVersion) {
    return fail(path, "interface version does not match this sweep executable");
  }
  return points;  // the handle stays open for the rest of the process
}

}  // namespace

const GuiEntryPoints* load_gui_module() {
  static const GuiEntryPoints* const points = open_module();
  if (points) points->set_workers(worker_count());  // --threads, SWEEP_THREADS or the cores
  return points;
}

}  // namespace sweep::app
