// `sweep snapshot` end to end through the real binary (issue 43): a folder of starter files; the
// first run writes the references and exits 1 (new); the second passes; a control point moved in
// one file fails that file's cases only, names the object and writes the report; --update passes
// again; a corrupt reference, an SWP with a syntax error, an unwritable reference folder; shards
// that partition the cases; --prune; the same build renders bit-identical pictures.
#include "snapshot/snapshot_cli_support.hpp"
#include "support/file_support.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <string>

namespace sweep::test {
namespace {

namespace fs = std::filesystem;

TEST(SnapshotCli, FirstRunWritesReferencesThenPassesThenNamesTheChangedObjectThenUpdates) {
  const fs::path dir = fresh_models("lifecycle");
  Outcome first = snapshot(dir, "models -q");
  EXPECT_EQ(first.status, 1) << first.out << first.err;
  EXPECT_EQ(lines_starting(first.out, "new ").size(), 9u) << first.out;
  EXPECT_NE(first.out.find("0 passed, 9 failed (9 new, 0 updated, 0 warnings, 0 errors)"), std::string::npos)
      << first.out;
  for (const char* name : {"wineglass-smooth", "wineglass-wire", "wineglass-frames", "more/tor-smooth"}) {
    EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / (std::string(name) + ".png"))) << name;
    EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / (std::string(name) + ".json"))) << name;
  }

  const Outcome second = snapshot(dir, "models -q");
  EXPECT_EQ(second.status, 0) << second.out << second.err;
  EXPECT_EQ(lines_starting(second.out, "pass ").size(), 9u) << second.out;
  EXPECT_NE(second.out.find("9 passed, 0 failed"), std::string::npos) << second.out;

  move_outer_wall_point(dir / "models" / "wineglass.swp");
  const Outcome third = snapshot(dir, "models -q --report report --junit report/junit.xml");
  EXPECT_EQ(third.status, 1) << third.out << third.err;
  const std::vector<std::string> failed = lines_starting(third.out, "FAIL ");
  ASSERT_EQ(failed.size(), 3u) << third.out;
  for (const std::string& line : failed) EXPECT_NE(line.find(" wineglass-"), std::string::npos) << line;
  EXPECT_NE(third.out.find("wineglass: "), std::string::npos) << third.out;
  EXPECT_NE(third.out.find("its mesh moved up to 0.03"), std::string::npos) << third.out;
  EXPECT_NE(third.out.find("profile: "), std::string::npos) << third.out;
  EXPECT_NE(third.out.find("6 passed, 3 failed"), std::string::npos) << third.out;
  EXPECT_TRUE(fs::exists(dir / "report" / "index.html"));
  EXPECT_TRUE(fs::exists(dir / "report" / "images" / "wineglass-smooth-diff.png"));
  EXPECT_NE(read_file(dir / "report" / "junit.xml").find("wineglass-smooth"), std::string::npos);
  expect_report_works_in_a_browser(dir / "report");

  const Outcome update = snapshot(dir, "models -q --update");
  EXPECT_EQ(update.status, 0) << update.out << update.err;
  EXPECT_EQ(lines_starting(update.out, "updated ").size(), 3u) << update.out;
  const Outcome after = snapshot(dir, "models -q");
  EXPECT_EQ(after.status, 0) << after.out << after.err;
}

TEST(SnapshotCli, TheCameraHoldsStillSoOnlyTheChangedPartDiffers) {
  const fs::path dir = fresh_models("camera");
  snapshot(dir, "models -q");
  move_outer_wall_point(dir / "models" / "wineglass.swp");
  const Outcome run = snapshot(dir, "models -q");
  // The reference's camera is reused: the foot and stem, unchanged, do not differ, so far fewer
  // pixels differ than the glass covers.
  const std::string json = read_file(dir / "models" / "__snapshots__" / "wineglass-smooth.json");
  EXPECT_NE(json.find("\"camera\""), std::string::npos);
  const std::size_t at = run.out.find("FAIL     wineglass-smooth: ");
  ASSERT_NE(at, std::string::npos) << run.out;
  const std::size_t pixels = std::stoul(run.out.substr(at + 27));
  EXPECT_GT(pixels, 8u);
  EXPECT_LT(pixels, 3000u) << run.out;
}

TEST(SnapshotCli, ReferencesFromTheSameBuildAreBitIdentical) {
  const fs::path dir = fresh_models("determinism");
  snapshot(dir, "models -q --references first");
  snapshot(dir, "models -q --references second -j 1");
  for (const char* name : {"wineglass-smooth", "wineglass-wire", "circles-frames", "more/tor-smooth"}) {
    const std::string a = read_file(dir / "first" / (std::string(name) + ".png"));
    const std::string b = read_file(dir / "second" / (std::string(name) + ".png"));
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_EQ(a, b) << name << " differs between runs";
  }
}

TEST(SnapshotCli, BadInputIsReportedPerCaseAndNothingIsLost) {
  const fs::path dir = fresh_models("bad-input");
  snapshot(dir, "models -q");
  write_text(dir / "models" / "__snapshots__" / "circles-smooth.png", "not a png");
  write_text(dir / "models" / "broken.swp", "bez2 a 4 4\n[0 0] [1 1] [2 oops]\n");
  const std::string tor_before = read_file(dir / "models" / "__snapshots__" / "more" / "tor-smooth.png");
  const Outcome run = snapshot(dir, "models -q");
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  EXPECT_NE(run.out.find("FAIL     circles-smooth: reference circles-smooth.png cannot be read"), std::string::npos)
      << run.out;
  const std::vector<std::string> errors = lines_starting(run.out, "error ");
  ASSERT_EQ(errors.size(), 3u) << run.out;
  EXPECT_NE(errors[0].find("broken.swp:2:"), std::string::npos) << errors[0];
  EXPECT_EQ(lines_starting(run.out, "pass ").size(), 8u) << run.out;
  EXPECT_EQ(read_file(dir / "models" / "__snapshots__" / "more" / "tor-smooth.png"), tor_before);

  write_text(dir / "file", "");
  const Outcome unwritable = snapshot(dir, "models -q --references file/refs");
  EXPECT_EQ(unwritable.status, 2) << unwritable.out;
  EXPECT_NE(unwritable.out.find("error    wineglass-smooth: cannot create file/refs"), std::string::npos)
      << unwritable.out;
}

TEST(SnapshotCli, AnyAcceptedReferencePassesAndTheMessageSaysWhichAndWhoseRenderer) {
  const fs::path dir = fresh_models("accepted");
  snapshot(dir, "models -q");
  const fs::path refs = dir / "models" / "__snapshots__";
  // A second accepted picture of the wineglass (here: its wire picture, another "driver's" look),
  // then the first replaced by a picture that does not match: the second one passes the case.
  fs::copy_file(refs / "wineglass-smooth.png", refs / "wineglass-smooth_1.png");
  fs::copy_file(refs / "wineglass-smooth.json", refs / "wineglass-smooth_1.json");
  fs::copy_file(refs / "wineglass-wire.png", refs / "wineglass-smooth.png", fs::copy_options::overwrite_existing);
  std::string sidecar = read_file(refs / "wineglass-smooth_1.json");
  const std::size_t at = sidecar.find("\"renderer\": \"");
  ASSERT_NE(at, std::string::npos);
  sidecar.insert(at + 13, "A GPU driver, ");
  write_text(refs / "wineglass-smooth_1.json", sidecar);
  const Outcome run = snapshot(dir, "models -q");
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  const std::vector<std::string> lines = lines_starting(run.out, "pass     wineglass-smooth");
  ASSERT_EQ(lines.size(), 1u) << run.out;
  EXPECT_NE(lines[0].find("compared with wineglass-smooth_1.png of 2 accepted references"), std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("the reference is from another renderer (A GPU driver, "), std::string::npos) << lines[0];
}

TEST(SnapshotCli, ASuiteFileChoosesTheCasesAndABadLineIsOneMessage) {
  const fs::path dir = fresh_models("suite");
  write_text(dir / "models" / "snapshots.txt",
             "# two cases of the glass, one of the torus from the front\n"
             "wineglass.swp modes=smooth,wire size=160x120\n"
             "more/tor.swp modes=smooth view=front color=normals name=tor-normals\n");
  const Outcome run = snapshot(dir, "models -q --update=missing");
  EXPECT_EQ(run.status, 0) << run.out << run.err;
  EXPECT_EQ(lines_starting(run.out, "new ").size(), 3u) << run.out;
  EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / "tor-normals-smooth.png"));
  EXPECT_NE(read_file(dir / "models" / "__snapshots__" / "wineglass-wire.json").find("160"), std::string::npos);

  write_text(dir / "models" / "snapshots.txt", "wineglass.swp colour=normals\n");
  const Outcome bad = snapshot(dir, "models -q");
  EXPECT_EQ(bad.status, 2) << bad.out << bad.err;
  EXPECT_EQ(bad.err.rfind("sweep: models/snapshots.txt:1:15: unknown key 'colour'", 0), 0u) << bad.err;
  EXPECT_EQ(bad.out, "");
}

TEST(SnapshotCli, ShardsPartitionTheCases) {
  const fs::path dir = fresh_models("shards");
  std::multiset<std::string> seen;
  for (int k = 1; k <= 3; ++k) {
    const Outcome run =
        snapshot(dir, "models -q --references refs --update=missing --shard " + std::to_string(k) + "/3");
    EXPECT_EQ(run.status, 0) << run.out << run.err;
    for (const std::string& line : lines_starting(run.out, "new ")) seen.insert(line.substr(9, line.find(':') - 9));
  }
  EXPECT_EQ(seen.size(), 9u);
  EXPECT_EQ(std::set<std::string>(seen.begin(), seen.end()).size(), 9u);
  const Outcome bad = snapshot(dir, "models --shard 4/3");
  EXPECT_EQ(bad.status, 2) << bad.out << bad.err;
}

TEST(SnapshotCli, UpdateKeepsReferencesOfRemovedCasesUnlessPruned) {
  const fs::path dir = fresh_models("prune");
  snapshot(dir, "models -q");
  fs::remove(dir / "models" / "circles.swp");
  const Outcome kept = snapshot(dir, "models -q --update");
  EXPECT_EQ(kept.status, 0) << kept.out;
  // The first five named, then a count, and the commands that list and delete them all.
  EXPECT_NE(kept.out.find("6 reference files belong to no case: circles-frames.json, circles-frames.png, "
                          "circles-smooth.json, circles-smooth.png, circles-wire.json (and 1 more); kept (`sweep "
                          "snapshot models --prune --dry-run` lists them all, --prune deletes them)"),
            std::string::npos)
      << kept.out;
  EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / "circles-smooth.png"));
  const Outcome listed = snapshot(dir, "models -q --prune --dry-run");
  EXPECT_EQ(listed.status, 0) << listed.out << listed.err;
  EXPECT_EQ(lines_starting(listed.out, "would prune ").size(), 6u) << listed.out;
  EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / "circles-smooth.png"));
  const Outcome pruned = snapshot(dir, "models -q --prune");
  EXPECT_EQ(lines_starting(pruned.out, "pruned ").size(), 6u) << pruned.out;
  EXPECT_FALSE(fs::exists(dir / "models" / "__snapshots__" / "circles-smooth.png"));
  EXPECT_TRUE(fs::exists(dir / "models" / "__snapshots__" / "wineglass-smooth.png"));
}

}  // namespace
}  // namespace sweep::test
