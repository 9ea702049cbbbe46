// `sweep snapshot DIR`: screenshot regression of a folder of models (issue 43). Options are read
// and checked here; the run (OSMesa, comparison, references, reports) is src/snapshot's, reached
// through the sweep_gui module like `sweep render`.
#include "app/commands.hpp"

#include "app/gui_module.hpp"
#include "snapshot/merge.hpp"
#include "snapshot/run_snapshots.hpp"
#include "snapshot/suite.hpp"

#include <charconv>
#include <cstdio>
#include <memory>
#include <string>

namespace sweep::app {
namespace {

struct SnapshotChoice {
  snapshot::RunOptions run;
  std::string dir;
  std::string update;  // "", "all", "missing" or "renderer"
  std::string shard = "1/1";
  std::string size = "320x240";
  std::string frames = "rmf";  // the names, checked by suite_check; run.defaults has their values
  std::string seam = "full";
  std::vector<std::string> rename;  // OLD NEW
  snapshot::MergeOptions merge;
};

/// The suite's own check of its key `key` (snapshot/suite.hpp): an option and the suite's key take
/// the same values and say the same of a wrong one.
CLI::Validator suite_check(const std::string& key) {
  return CLI::Validator([key](std::string& value) { return snapshot::case_value_problem(key, value); }, "", key);
}

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
  run.update = choice.update == "missing"    ? snapshot::UpdateMode::Missing
               : choice.update == "renderer" ? snapshot::UpdateMode::Renderer
               : choice.update.empty()       ? snapshot::UpdateMode::None
                                             : snapshot::UpdateMode::All;
  parse_shard(choice.shard, run.shard_k, run.shard_n);
  // Checked by suite_check("size"), ("frames") and ("seam"):
  run.defaults.size = parse_size(choice.size).value_or(glm::ivec2(320, 240));
  run.defaults.frames = snapshot::named(snapshot::kEveryFrames, choice.frames).value_or(snapshot::SweepFrames::Rmf);
  run.defaults.seam = snapshot::named(snapshot::kEverySeam, choice.seam).value_or(snapshot::SeamClosing::Full);
  if (choice.rename.size() == 2) {
    run.rename_from = choice.rename[0];
    run.rename_to = choice.rename[1];
  }
  const GuiEntryPoints* gui = load_gui_module();
  return gui ? gui->run_snapshots(run) : 2;
}

void add_comparison_options(CLI::App* command, snapshot::CaseDefaults& defaults) {
  command
      ->add_option("--threshold", defaults.diff.threshold,
                   "Colour distance (YIQ, 0 same .. 1 black against white) above which a pixel differs")
      ->check(suite_check("threshold"))
      ->capture_default_str();
  command
      ->add_option("--max-diff-pixels", defaults.limits.max_diff_pixels,
                   "A case fails when more pixels than this differ (after anti-aliased edges and one-pixel "
                   "shifts are forgiven)")
      ->check(suite_check("max-diff-pixels"))
      ->capture_default_str();
  command
      ->add_option("--max-diff-ratio", defaults.limits.max_diff_ratio,
                   "... or when a larger share of its pixels (0..1) differs")
      ->check(suite_check("max-diff-ratio"))
      ->capture_default_str();
}

void add_evaluation_choice(CLI::App* command, SnapshotChoice& choice) {
  snapshot::CaseDefaults& defaults = choice.run.defaults;
  command->add_option("--tolerance", defaults.tolerance, kToleranceHelp)->check(suite_check("tolerance"));
  command->add_option("--frames", choice.frames, kFramesHelp)->check(suite_check("frames"))->capture_default_str();
  command->add_option("--seam", choice.seam, kSeamHelp)->check(suite_check("seam"))->capture_default_str();
  command->add_option("--time", defaults.time, "Draw the riders where they are at T seconds (0 to 1e9)")
      ->check(suite_check("T"))
      ->capture_default_str();
}

/// `sweep snapshot merge DIR... --report OUT [--junit FILE]` (no GL).
CLI::App* add_merge_command(CLI::App* snapshot_command, const std::shared_ptr<SnapshotChoice>& choice, Action& action) {
  CLI::App* merge = snapshot_command->add_subcommand(
      "merge",
      "Put the reports of shards (each run with --shard K/N --report DIRk) back together: one HTML report, results "
      "file and JUnit XML, equal to what one unsharded run writes, and its exit status");
  merge->add_option("shards", choice->merge.shards, "The shards' report folders (or their results.json)")
      ->required()
      ->check(CLI::ExistingPath);
  merge->add_option("--report", choice->merge.report, "Where the merged report goes")->required();
  merge->add_option("--junit", choice->merge.junit, "Also write the merged JUnit XML");
  merge->callback([choice, &action] { action = [choice] { return snapshot::merge_reports(choice->merge); }; });
  return merge;
}

}  // namespace

void add_snapshot_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<SnapshotChoice>();
  CLI::App* cmd = app.add_subcommand(
      "snapshot",
      "Screenshot regression: render every SWP file under DIR (or the cases of DIR/snapshots.txt) headless, compare "
      "each picture with its reference in DIR/__snapshots__, and say which named object changed");
  cmd->footer(std::string("Exit status: ") + kSnapshotExitStatus);
  CLI::App* merge = add_merge_command(cmd, choice, action);
  CLI::Option* dir = cmd->add_option("dir", choice->dir, "Folder of SWP models")->check(CLI::ExistingDirectory);
  cmd->add_option("--suite", choice->run.suite, "Suite file (default: DIR/snapshots.txt when it exists)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--references", choice->run.references, "Folder of the references (default: DIR/__snapshots__)");
  cmd->add_flag("--update{all}", choice->update,
                "Accept the pictures: rewrite the references whose comparison failed (this renderer's; where "
                "another renderer made every one, add NAME_K.png beside them) and write the new ones "
                "(--update=missing: only write the new ones; --update=renderer: only add this renderer's references "
                "where a case is a renderer difference)")
      ->check(CLI::IsMember({"all", "missing", "renderer"}));
  CLI::Option* prune =
      cmd->add_flag("--prune", choice->run.prune, "Delete references that belong to no case of the suite");
  cmd->add_flag("--dry-run", choice->run.dry_run, "With --prune: list what it would delete, delete nothing")
      ->needs(prune);
  cmd->add_option("--rename", choice->rename,
                  "Move the references of case OLD to case NEW (a renamed model), render nothing")
      ->expected(2)
      ->type_name("OLD NEW");
  cmd->add_option("--report", choice->run.report, "Write an HTML report (DIR/index.html and its images)");
  cmd->add_option("--junit", choice->run.junit, "Write JUnit XML for CI systems");
  add_threads_option(cmd);  // each worker's geometry (subdivision); --jobs: the pictures at once
  cmd->add_option("-j,--jobs", choice->run.jobs, "Workers, each with its own OSMesa context (default: the cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--shard", choice->shard, "Run the K-th of N stable shares of the cases (CI matrices)")
      ->check(kShardValidator)
      ->capture_default_str();
  cmd->add_option("--size", choice->size, "Picture size WxH of cases that do not give one")
      ->check(suite_check("size"))
      ->capture_default_str();
  add_evaluation_choice(cmd, *choice);
  add_comparison_options(cmd, choice->run.defaults);
  cmd->add_flag("--strict-geometry", choice->run.strict_geometry,
                "Fail (not only warn) when an object's geometry changed but its pixels did not");
  cmd->add_flag("--strict-renderer", choice->run.strict_renderer,
                "Fail (not only warn) a renderer difference: pictures that differ where the model, camera and "
                "options did not, against references from other renderers only");
  cmd->add_flag("-q,--quiet", choice->run.quiet, "No progress count before each case's line");
  cmd->callback([choice, dir, merge, &action] {
    if (merge->parsed()) return;
    if (dir->count() == 0) throw CLI::RequiredError("dir");
    action = [choice] { return snapshot(*choice); };
  });
}

}  // namespace sweep::app
