// Used when Sweep is built without the GL parts (SWEEP_GUI=OFF).
#include "app/commands.hpp"

#include <cstdio>

namespace sweep::app {

void add_view_commands(CLI::App&, Action&) {}
void add_snapshot_command(CLI::App&, Action&) {}

int open_viewer(const std::string&, const EvaluationOptions&) {
  std::fprintf(stderr, "sweep: this build has no viewer (configured with SWEEP_GUI=OFF)\n");
  return 1;
}

}  // namespace sweep::app
