// `sweep snapshot` at CI scale (issue 56): JUnit XML that agrees with the exit status and passes
// the JUnit schema CI dashboards read; shards merged into the report one unsharded run writes;
// case lines in the suite's order at any -j; stale and renamed references named; one size limit
// refused before any rendering.
#include "snapshot/snapshot_cli_support.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <regex>

namespace sweep::test {
namespace {

/// xmllint's verdict on `xml` against tests/data/junit.xsd: "" when it validates, else its output.
std::string junit_schema_errors(const fs::path& xml) {
  const fs::path log = xml.parent_path() / "xmllint.log";
  const std::string command = "xmllint --noout --schema " + quoted(fs::path(SWEEP_TEST_DATA_DIR) / "junit.xsd") + " " +
                              quoted(xml) + " >" + quoted(log) + " 2>&1";
  return std::system(command.c_str()) == 0 ? "" : read_file(log) + " ";
}

/// The JUnit XML without its times and worker count (what the shards' machines spent, the only
/// part a merge and one run of the same cases differ in).
std::string without_times(const std::string& xml) {
  const std::string untimed = std::regex_replace(xml, std::regex(" time=\"[0-9.]+\""), "");
  return std::regex_replace(untimed, std::regex("<property name=\"workers\" value=\"[0-9]+\"/>"), "");
}

/// The HTML report without what the shards' machines spent: the run's line of facts (renderer,
/// time, workers, date) and each case's time.
std::string without_run_facts(const std::string& html) {
  std::string out = std::regex_replace(html, std::regex("<p class=\"meta\">.*?</p>"), "");
  return std::regex_replace(out, std::regex("<span class=\"(case-time|ptime)\">[^<]*</span>"), "");
}

/// The results file's cases without their times.
nlohmann::json untimed_cases(const fs::path& report) {
  nlohmann::json cases = nlohmann::json::parse(read_file(report / "results.json")).at("cases");
  for (nlohmann::json& c : cases) {
    c.erase("seconds");
    c.erase("render_seconds");
  }
  return cases;
}

TEST(SnapshotCi, JunitFailsANewReferenceLikeTheExitStatusAndPassesTheSchema) {
  const fs::path dir = fresh_models("junit-new");
  const Outcome first = snapshot(dir, "models -q --junit first.xml");
  EXPECT_EQ(first.status, 1) << first.out << first.err;
  const std::string xml = read_file(dir / "first.xml");
  EXPECT_NE(xml.find("tests=\"9\" failures=\"9\" errors=\"0\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("type=\"new-reference\""), std::string::npos);
  EXPECT_EQ(junit_schema_errors(dir / "first.xml"), "");

  move_outer_wall_point(dir / "models" / "wineglass.swp");
  const Outcome changed = snapshot(dir, "models -q --junit changed.xml");
  EXPECT_EQ(changed.status, 1);
  EXPECT_NE(read_file(dir / "changed.xml").find("tests=\"9\" failures=\"3\" errors=\"0\""), std::string::npos);
  EXPECT_EQ(junit_schema_errors(dir / "changed.xml"), "");

  const Outcome accepted = snapshot(dir, "models -q --update --junit accepted.xml");
  EXPECT_EQ(accepted.status, 0);
  EXPECT_NE(read_file(dir / "accepted.xml").find("failures=\"0\" errors=\"0\""), std::string::npos);
  EXPECT_EQ(junit_schema_errors(dir / "accepted.xml"), "");

  // The schema is a real judge: a failure before a skip is not JUnit as Jenkins reads it.
  write_text(dir / "wrong.xml",
             "<testsuite name=\"s\" tests=\"1\"><testcase name=\"c\"><failure/><skipped/>"
             "</testcase></testsuite>");
  EXPECT_NE(junit_schema_errors(dir / "wrong.xml"), "");
}

TEST(SnapshotCi, ThreeShardsMergeIntoWhatOneRunWrites) {
  const fs::path dir = fresh_models("merge");
  snapshot(dir, "models -q --update");
  move_outer_wall_point(dir / "models" / "wineglass.swp");
  const Outcome whole = snapshot(dir, "models -q --report whole --junit whole/junit.xml");
  EXPECT_EQ(whole.status, 1) << whole.out << whole.err;
  for (int k = 1; k <= 3; ++k) {
    const std::string shard = "shard" + std::to_string(k);
    snapshot(dir, "models -q --shard " + std::to_string(k) + "/3 --report " + shard + " --junit " + shard + "/j.xml");
  }
  const Outcome merged = snapshot(dir, "merge shard1 shard2 shard3 --report merged --junit merged/junit.xml");
  EXPECT_EQ(merged.status, whole.status) << merged.out << merged.err;
  EXPECT_NE(merged.out.find("merged 3 shards: 6 passed, 3 failed (0 new, 0 updated, 0 warnings, 0 errors)"),
            std::string::npos)
      << merged.out;
  EXPECT_EQ(untimed_cases(dir / "merged"), untimed_cases(dir / "whole"));
  EXPECT_EQ(without_times(read_file(dir / "merged" / "junit.xml")),
            without_times(read_file(dir / "whole" / "junit.xml")));
  EXPECT_EQ(junit_schema_errors(dir / "merged" / "junit.xml"), "");
  EXPECT_EQ(without_run_facts(read_file(dir / "merged" / "index.html")),
            without_run_facts(read_file(dir / "whole" / "index.html")));
  for (const char* image : {"wineglass-smooth-diff.png", "wineglass-wire-reference.png", "circles-frames-actual.png"}) {
    EXPECT_EQ(read_file(dir / "merged" / "images" / image), read_file(dir / "whole" / "images" / image)) << image;
  }
  expect_report_works_in_a_browser(dir / "merged");

  const Outcome missing = snapshot(dir, "merge shard1 shard3 --report partial");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("sweep: the reports hold "), std::string::npos) << missing.err;
  EXPECT_NE(missing.err.find("missing shard 2/3"), std::string::npos) << missing.err;
  const Outcome twice = snapshot(dir, "merge shard1 shard1 shard2 shard3 --report twice");
  EXPECT_EQ(twice.status, 2);
  EXPECT_NE(twice.err.find("shard 1/3 is given twice"), std::string::npos) << twice.err;
}

TEST(SnapshotCi, CaseLinesComeInTheSuitesOrderAtAnyJobs) {
  const fs::path dir = fresh_models("order");
  snapshot(dir, "models -q --update");
  const Outcome one = snapshot(dir, "models -j 1");
  const Outcome two = snapshot(dir, "models -j 2");
  const std::vector<std::string> lines = lines_starting(one.out, "[");
  ASSERT_EQ(lines.size(), 9u) << one.out;
  EXPECT_EQ(lines, lines_starting(two.out, "["));
  EXPECT_EQ(lines.front(), "[1/9] pass     circles-smooth");
  EXPECT_EQ(lines.back(), "[9/9] pass     wineglass-frames");
}

TEST(SnapshotCi, ARenamedModelSaysItsOldNameAndRenameMovesTheReferences) {
  const fs::path dir = fresh_models("rename");
  snapshot(dir, "models -q --update");
  fs::rename(dir / "models" / "circles.swp", dir / "models" / "rings.swp");
  const Outcome renamed = snapshot(dir, "models -q");
  EXPECT_NE(renamed.out.find("new      rings-smooth: new reference models/__snapshots__/rings-smooth.png; looks "
                             "like circles-smooth (renamed?): move its references with `sweep snapshot models "
                             "--rename circles-smooth rings-smooth`"),
            std::string::npos)
      << renamed.out;
  const std::string old_bytes = read_file(dir / "models" / "__snapshots__" / "circles-smooth.png");
  const Outcome moved = snapshot(dir, "models --rename circles-smooth rings-smooth");
  EXPECT_EQ(moved.status, 0) << moved.out << moved.err;
  EXPECT_EQ(read_file(dir / "models" / "__snapshots__" / "rings-smooth.png"), old_bytes);
  EXPECT_FALSE(fs::exists(dir / "models" / "__snapshots__" / "circles-smooth.png"));
  const Outcome refused = snapshot(dir, "models --rename wineglass-smooth rings-smooth");
  EXPECT_EQ(refused.status, 2);
  EXPECT_EQ(refused.err,
            "sweep: case 'rings-smooth' already has references in models/__snapshots__ that show "
            "another model; nothing moved\n");
}

TEST(SnapshotCi, OneSizeLimitIsRefusedBeforeAnyRendering) {
  const fs::path dir = fresh_models("sizes");
  const Outcome huge = snapshot(dir, "models --size 16384x16384");
  EXPECT_EQ(huge.status, 2);
  // The command line and the suite check a size with one rule and say the same (issue 60).
  EXPECT_NE(huge.err.find("--size: expected a size WxH with sides 1..8192, found '16384x16384'"), std::string::npos)
      << huge.err;
  write_text(dir / "models" / "snapshots.txt", "wineglass.swp size=8193x8\n");
  const Outcome suite = snapshot(dir, "models");
  EXPECT_EQ(suite.status, 2);
  EXPECT_NE(suite.err.find("snapshots.txt:1:20: expected a size WxH with sides 1..8192, found '8193x8'"),
            std::string::npos)
      << suite.err;
  EXPECT_FALSE(fs::exists(dir / "models" / "__snapshots__"));
}

// Each option the suite has a key for is checked by the suite's own reading of it: the same range
// (the command line once took --time -5, the suite only 0..1e9; --max-diff-pixels had no bound)
// and the same words.
TEST(SnapshotCi, TheCommandLineChecksItsOptionsAsTheSuiteChecksItsKeys) {
  const fs::path dir = fresh_models("same-checks");
  struct Check {
    const char* option;
    const char* key;
    const char* message;
  };
  const Check checks[] = {
      {"--time -5", "T=-5", "expected a rider time T in seconds from 0 to 1e9, found '-5'"},
      {"--max-diff-pixels 99999999999", "max-diff-pixels=99999999999",
       "expected a whole number of pixels from 0 to 67108864, found '99999999999'"},
      {"--frames bogus", "frames=bogus", "expected frames rmf or projection, found 'bogus'"},
      {"--threshold 2", "threshold=2", "expected a threshold from 0 to 1, found '2'"},
  };
  for (const Check& check : checks) {
    fs::remove(dir / "models" / "snapshots.txt");
    const Outcome option = snapshot(dir, std::string("models ") + check.option);
    EXPECT_EQ(option.status, 2) << check.option;
    const std::string name = std::string(check.option).substr(0, std::string(check.option).find(' '));
    EXPECT_NE(option.err.find(name + ": " + check.message), std::string::npos) << option.err;
    write_text(dir / "models" / "snapshots.txt", std::string("wineglass.swp ") + check.key + "\n");
    const Outcome suite = snapshot(dir, "models");
    EXPECT_EQ(suite.status, 2) << check.key;
    EXPECT_NE(suite.err.find("snapshots.txt:1:" + std::to_string(16 + std::string(check.key).find('=')) + ": " +
                             check.message),
              std::string::npos)
        << suite.err;
  }
  EXPECT_FALSE(fs::exists(dir / "models" / "__snapshots__"));
}

}  // namespace
}  // namespace sweep::test
