// `sweep snapshot DIR`: screenshot regression of a folder of models (issue 43). Options are read
// and checked here; the run (OSMesa, comparison, references, reports) is src/snapshot's, reached
// through the sweep_gui module like `sweep render`.
#include "app/commands.hpp"

#include "app/gui_module.hpp"
#include "snapshot/run_snapshots.hpp"

#include <charconv>
#include <cstdio>
#include <memory>
#include <string>

namespace sweep::app {
namespace {

struct SnapshotChoice {
  snapshot::RunOptions run;
  std::string dir;
  std::string update;  // "", "all" or "missing"
  std::string shard = "1/1";
  std::string size = "320x240";
};

/// "K/N" with 1 <= K <= N <= 10000.
bool parse_shard(const std::string& text, int& k, int& n) {
  const std::size_t slash = text.find('/');
  if (slash == std::string::npos) return false;
  const char* begin = text.data();
  const auto a = std::from_chars(begin, begin + slash, k);
  const auto b = std::from_chars(begin + slash + 1, begin + text.size(), n);
  return a.ec == std::errc{} && a.ptr == begin + slash && b.ec == std::errc{} && b.ptr == begin + text.size() &&
         k >= 1 && n >= 1 && k <= n && n <= 10000;
}

const CLI::Validator kShardValidator(
    [](std::string& value) {
      int k = 0, n = 0;
      return parse_shard(value, k, n) ? std::string() : "expected K/N with 1 <= K <= N <= 10000, found " + value;
    },
    "K/N", "shard");

int snapshot(SnapshotChoice& choice) {
  snapshot::RunOptions& run = choice.run;
  run.dir = choice.dir;
  run.update = choice.update == "missing" ? snapshot::UpdateMode::Missing
               : choice.update.empty()    ? snapshot::UpdateMode::None
                                          : snapshot::UpdateMode::All;
  parse_shard(choice.shard, run.shard_k, run.shard_n);
  run.defaults.size = parse_size(choice.size).value_or(glm::ivec2(320, 240));
  const GuiEntryPoints* gui = load_gui_module();
  return gui ? gui->run_snapshots(run) : 2;
}

void add_comparison_options(CLI::App* command, snapshot::CaseDefaults& defaults) {
  command
      ->add_option("--threshold", defaults.diff.threshold,
                   "Colour distance (YIQ, 0 same .. 1 black against white) above which a pixel differs")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
  command
      ->add_option("--max-diff-pixels", defaults.limits.max_diff_pixels,
                   "A case fails when more pixels than this differ (after anti-aliased edges and one-pixel "
                   "shifts are forgiven)")
      ->capture_default_str();
  command
      ->add_option("--max-diff-ratio", defaults.limits.max_diff_ratio,
                   "... or when a larger share of its pixels (0..1) differs")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

void add_evaluation_choice(CLI::App* command, snapshot::CaseDefaults& defaults) {
  command->add_option("--tolerance", defaults.tolerance, kToleranceHelp)->check(CLI::PositiveNumber);
  command->add_option("--frames", defaults.frames, kFramesHelp)
      ->check(CLI::IsMember({"rmf", "projection"}))
      ->capture_default_str();
  command->add_option("--seam", defaults.seam, kSeamHelp)
      ->check(CLI::IsMember({"full", "symmetric", "index", "none"}))
      ->capture_default_str();
  command->add_option("--time", defaults.time, "Draw the riders where they are at T seconds")
      ->check(CLI::Range(-1e9, 1e9))
      ->capture_default_str();
}

}  // namespace

void add_snapshot_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<SnapshotChoice>();
  CLI::App* cmd = app.add_subcommand(
      "snapshot",
      "Screenshot regression: render every SWP file under DIR (or the cases of DIR/snapshots.txt) headless, compare "
      "each picture with its reference in DIR/__snapshots__, and say which named object changed. Exit 0 when all "
      "pass, 1 when any fails or is new, 2 for usage or input errors");
  cmd->add_option("dir", choice->dir, "Folder of SWP models")->required()->check(CLI::ExistingDirectory);
  cmd->add_option("--suite", choice->run.suite, "Suite file (default: DIR/snapshots.txt when it exists)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--references", choice->run.references, "Folder of the references (default: DIR/__snapshots__)");
  cmd->add_flag("--update{all}", choice->update,
                "Accept the pictures: rewrite the references whose comparison failed and write the new ones "
                "(--update=missing: only write the new ones)")
      ->check(CLI::IsMember({"all", "missing"}));
  cmd->add_flag("--prune", choice->run.prune, "Delete references that belong to no case of the suite");
  cmd->add_option("--report", choice->run.report, "Write an HTML report (DIR/index.html and its images)");
  cmd->add_option("--junit", choice->run.junit, "Write JUnit XML for CI systems");
  add_threads_option(cmd);  // each worker's geometry (subdivision); --jobs: the pictures at once
  cmd->add_option("-j,--jobs", choice->run.jobs, "Workers, each with its own OSMesa context (default: the cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--shard", choice->shard, "Run the K-th of N stable shares of the cases (CI matrices)")
      ->check(kShardValidator)
      ->capture_default_str();
  cmd->add_option("--size", choice->size, "Picture size WxH of cases that do not give one")
      ->check(kSizeValidator)
      ->capture_default_str();
  add_evaluation_choice(cmd, choice->run.defaults);
  add_comparison_options(cmd, choice->run.defaults);
  cmd->add_flag("--strict-geometry", choice->run.strict_geometry,
                "Fail (not only warn) when an object's geometry changed but its pixels did not");
  cmd->add_flag("-q,--quiet", choice->run.quiet, "No progress count before each case's line");
  cmd->callback([choice, &action] { action = [choice] { return snapshot(*choice); }; });
}

}  // namespace sweep::app
