// A long session (issue 29), as a measurement rather than a CI test: 10 000 random edit steps
// (point moves, STEPS, radius, undo, redo) on a starter file in one EditSession, printing the
// resident memory every 1 000 steps; the history's caps (model/edit/history.hpp) keep its growth under
// 64 MiB. Runs only with SWEEP_LONG_SESSION=1 (scripts/measure-long-session.sh), since resident
// memory depends on the allocator and the sanitizers; the caps themselves are tested in
// History.TheDefaultCapsKeepTheNewest1000Steps and EditSession.TellsOnceWhenTheHistoryStartsForgetting.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>
#include <string>

namespace sweep::editor {
namespace {

/// Resident memory of this process in MiB (VmRSS).
double resident_mib() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) return std::strtod(line.c_str() + 6, nullptr) / 1024.0;
  }
  return -1.0;
}

TEST(LongSession, TenThousandEditStepsKeepMemoryBounded) {
  if (std::getenv("SWEEP_LONG_SESSION") == nullptr) GTEST_SKIP() << "a measurement: SWEEP_LONG_SESSION=1";
  EditSession session;
  session.load(io::load_swp_file(std::string(SWEEP_SWP_DIR) + "/wineglass.swp"), "wineglass.swp");
  std::mt19937 random(29);
  const auto pick = [&random](int n) { return std::uniform_int_distribution<int>(0, n - 1)(random); };
  const double start = resident_mib();
  double peak = start;
  int undos = 0, redos = 0, edits = 0;
  for (int step = 1; step <= 10'000; ++step) {
    const int what = pick(10);
    if (what < 2) {
      undos += session.undo();
    } else if (what < 3) {
      redos += session.redo();
    } else {
      const int object = pick(static_cast<int>(session.document().objects.size()));
      const glm::dvec3 to{pick(200) / 50.0, pick(200) / 50.0, 0.0};
      const int point = pick(30), steps = 1 + pick(16);
      edits += session.edit("random", [&](Document& doc) {
        if (what < 8) return move_point(doc, object, point, to);
        return set_steps_or_levels(doc, object, steps);
      });
    }
    if (step % 1000 == 0) {
      const double now = resident_mib();
      peak = std::max(peak, now);
      std::printf("step %5d: resident %7.1f MiB (+%6.1f), undo steps kept %zu, forgotten %zu\n", step, now, now - start,
                  session.undo_count(), session.forgotten_steps());
    }
  }
  std::printf("edits %d, undos %d, redos %d; resident memory grew by %.1f MiB at most (goal: under 64)\n", edits, undos,
              redos, peak - start);
  EXPECT_LT(peak - start, 64.0);
}

}  // namespace
}  // namespace sweep::editor
