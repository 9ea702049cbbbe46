// `sweep snapshot`'s cases (issue 43 items 1 and 7): every .swp under a folder in three modes
// (zero configuration), the suite file (docs/snapshot-suite.md: every key, defaults lines, globs,
// comments, names, every error message exactly) and shards (FNV-1a of the name).
#include "snapshot/suite.hpp"

#include "../../fuzz/suite_fuzz_check.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace {

namespace fs = std::filesystem;
using sweep::render::ColorMode;
using sweep::snapshot::CaseDefaults;
using sweep::snapshot::CaseSpec;
using sweep::snapshot::Mode;
using sweep::snapshot::NamedView;
using sweep::snapshot::SeamClosing;
using sweep::snapshot::SuiteError;
using sweep::snapshot::SweepFrames;

#if SWEEP_CHECK_PRECONDITIONS
constexpr bool kChecked = true;
#else
constexpr bool kChecked = false;
#endif

void touch(const fs::path& file) {
  fs::create_directories(file.parent_path());
  sweep::test::write_text(file, "bsp3 . 4 [0 0] [1 0] [1 1] [0 1]\n");
}

std::vector<std::string> names_of(const std::vector<CaseSpec>& cases) {
  std::vector<std::string> names;
  for (const CaseSpec& c : cases) names.push_back(c.name);
  return names;
}

std::vector<std::string> relatives_of(const std::vector<CaseSpec>& cases) {
  std::vector<std::string> relatives;
  for (const CaseSpec& c : cases) relatives.push_back(c.relative.generic_string());
  return relatives;
}

// ---- Zero configuration ----------------------------------------------------------------------

TEST(CasesInFolder, EverySwpBelowTheFolderInThreeModesSortedByRelativePath) {
  const sweep::test::ScratchFolder folder("sweep-suite");
  const fs::path& dir = folder.path();
  for (const char* file : {"wineglass.swp", "sub/bowl.swp", "sub/deep/cup.swp", "sub.swp", "a.b/c.swp", "Z.swp",
                           ".hidden.swp", ".git/x.swp", "sub/.cache/y.swp", "__snapshots__/old.swp",
                           "sub/__snapshots__/z.swp", "notes.txt", "upper.SWP", "swp"}) {
    touch(dir / file);
  }
  fs::create_directories(dir / "empty");
  fs::create_directories(dir / "folder.swp");  // a folder, not a file

  CaseDefaults defaults;
  defaults.size = {640, 480};
  defaults.tolerance = 0.25;
  defaults.frames = SweepFrames::Projection;
  defaults.seam = SeamClosing::None;
  defaults.time = 1.5;
  defaults.diff.threshold = 0.3;
  defaults.limits.max_diff_pixels = 17;
  const std::vector<CaseSpec> cases = sweep::snapshot::cases_in_folder(dir, defaults);

  // Byte order of the paths with '/': "Z" < "a.b/" < "sub.swp" < "sub/" ('.' < '/') < "wineglass".
  const std::vector<std::string> expected{"Z-smooth",
                                          "Z-wire",
                                          "Z-frames",
                                          "a.b/c-smooth",
                                          "a.b/c-wire",
                                          "a.b/c-frames",
                                          "sub-smooth",
                                          "sub-wire",
                                          "sub-frames",
                                          "sub/bowl-smooth",
                                          "sub/bowl-wire",
                                          "sub/bowl-frames",
                                          "sub/deep/cup-smooth",
                                          "sub/deep/cup-wire",
                                          "sub/deep/cup-frames",
                                          "wineglass-smooth",
                                          "wineglass-wire",
                                          "wineglass-frames"};
  EXPECT_EQ(names_of(cases), expected);
  ASSERT_EQ(cases.size(), 18u);
  const CaseSpec& bowl = cases[10];
  EXPECT_EQ(bowl.name, "sub/bowl-wire");
  EXPECT_EQ(bowl.relative, fs::path("sub/bowl.swp"));
  EXPECT_EQ(bowl.file, dir / "sub/bowl.swp");
  EXPECT_EQ(bowl.mode, Mode::Wire);
  EXPECT_EQ(bowl.view, sweep::snapshot::ViewSpec{});
  EXPECT_EQ(bowl.color, ColorMode::Material);
  EXPECT_EQ(bowl.size, glm::ivec2(640, 480));
  EXPECT_EQ(bowl.tolerance, 0.25);
  EXPECT_EQ(bowl.frames, SweepFrames::Projection);
  EXPECT_EQ(bowl.seam, SeamClosing::None);
  EXPECT_EQ(bowl.time, 1.5);
  EXPECT_EQ(bowl.diff.threshold, 0.3);
  EXPECT_EQ(bowl.limits.max_diff_pixels, 17u);
  EXPECT_EQ(bowl.suite_location, "");
  EXPECT_EQ(cases[9].mode, Mode::Smooth);
  EXPECT_EQ(cases[11].mode, Mode::Frames);
}

TEST(CasesInFolder, FollowsSymlinksButWalksEachFolderOnce) {
  const sweep::test::ScratchFolder folder("sweep-suite");
  const fs::path& dir = folder.path();
  touch(dir / "a/model.swp");
  touch(dir / "elsewhere.swp");
  fs::create_directory_symlink("..", dir / "a/up");             // a loop: a/up/a/up/...
  fs::create_directory_symlink(dir / "a", dir / "b");           // a second name of a/
  fs::create_symlink(dir / "elsewhere.swp", dir / "link.swp");  // a linked file is a file
  fs::create_symlink(dir / "missing.swp", dir / "dangling.swp");
  const std::vector<std::string> expected{"a/model-smooth",   "a/model-wire",   "a/model-frames",
                                          "elsewhere-smooth", "elsewhere-wire", "elsewhere-frames",
                                          "link-smooth",      "link-wire",      "link-frames"};
  EXPECT_EQ(names_of(sweep::snapshot::cases_in_folder(dir, {})), expected);
}

TEST(CasesInFolder, NoFolderNoCases) {
  const sweep::test::ScratchFolder folder("sweep-suite");
  EXPECT_TRUE(sweep::snapshot::cases_in_folder(folder.path() / "missing", {}).empty());
  EXPECT_TRUE(sweep::snapshot::cases_in_folder(folder.path(), {}).empty());
}

// ---- The suite file --------------------------------------------------------------------------

class Suite : public ::testing::Test {
 protected:
  Suite() {
    for (const char* file : {"wineglass.swp", "tor.swp", "taper.swp", "roller-coaster.swp", "bowls/deep.swp",
                             "bowls/flat.swp", "bowls/.draft.swp", "bowls/notes.txt", "bowls/__snapshots__/old.swp",
                             "my models/cup one.swp", "hash#tag.swp", "deep/a/b/c.swp"}) {
      touch(dir() / file);
    }
  }
  const fs::path& dir() const { return folder_.path(); }
  std::vector<CaseSpec> parse(const std::string& text, const CaseDefaults& defaults = {}) const {
    return sweep::snapshot::parse_suite(text, "snapshots.txt", dir(), defaults);
  }
  /// The one message of a bad suite.
  std::string error(const std::string& text) const {
    try {
      parse(text);
    } catch (const SuiteError& e) {
      return e.what();
    }
    return "(no error)";
  }

 private:
  sweep::test::ScratchFolder folder_{"sweep-suite"};
};

TEST_F(Suite, APathAloneIsItsThreeModesFromTheDefaultView) {
  const std::vector<CaseSpec> cases = parse("wineglass.swp\n");
  EXPECT_EQ(names_of(cases), (std::vector<std::string>{"wineglass-smooth", "wineglass-wire", "wineglass-frames"}));
  ASSERT_EQ(cases.size(), 3u);
  EXPECT_EQ(cases[0].mode, Mode::Smooth);
  EXPECT_EQ(cases[1].mode, Mode::Wire);
  EXPECT_EQ(cases[2].mode, Mode::Frames);
  for (const CaseSpec& c : cases) {
    EXPECT_EQ(c.file, dir() / "wineglass.swp");
    EXPECT_EQ(c.relative, fs::path("wineglass.swp"));
    EXPECT_EQ(c.view, sweep::snapshot::ViewSpec{});
    EXPECT_EQ(c.suite_location, "snapshots.txt:1");
  }
}

TEST_F(Suite, TheDocumentedExamplesMakeTheDocumentedCases) {
  // docs/snapshot-suite.md
  EXPECT_EQ(
      names_of(parse("# snapshots.txt: paths relative to the suite's DIR\n"
                     "defaults size=640x480 threshold=0.1          # applies to the lines after it\n"
                     "wineglass.swp                                # the three modes, default view\n"
                     "bowls/*.swp modes=smooth view=iso            # a glob (* and ? within a path segment, ** for any "
                     "folders)\n"
                     "tor.swp modes=smooth,wire color=normals view=front size=320x240 name=tor-normals\n"
                     "roller-coaster.swp modes=smooth T=2.5 yaw=10 pitch=30 distance=12 max-diff-pixels=40 "
                     "max-diff-ratio=0.001\n"
                     "taper.swp tolerance=0.001 frames=projection seam=symmetric\n"
                     "\"my models/cup one.swp\" modes=frames         # a path with spaces, in double quotes\n")),
      (std::vector<std::string>{"wineglass-smooth", "wineglass-wire", "wineglass-frames", "bowls/deep-iso-smooth",
                                "bowls/flat-iso-smooth", "tor-normals-smooth", "tor-normals-wire",
                                "roller-coaster-yaw10-pitch30-distance12-smooth", "taper-smooth", "taper-wire",
                                "taper-frames", "my models/cup one-frames"}));
  EXPECT_EQ(names_of(parse("defaults size=640x480 threshold=0.2\n"
                           "taper.swp\n"
                           "defaults modes=smooth view=top\n"
                           "tor.swp\n"
                           "tor.swp view=default\n")),
            (std::vector<std::string>{"taper-smooth", "taper-wire", "taper-frames", "tor-top-smooth", "tor-smooth"}));
}

TEST_F(Suite, EveryKeyIsReadIntoTheCase) {
  const std::vector<CaseSpec> cases = parse(
      "tor.swp modes=wire,smooth view=front yaw=10 pitch=-30.5 distance=12 color=normals size=640x480 "
      "tolerance=0.001 frames=projection seam=symmetric T=2.5 threshold=0.2 max-diff-pixels=40 max-diff-ratio=0.001 "
      "shift=2 antialiasing=off name=tor/front_1\n");
  ASSERT_EQ(cases.size(), 2u);
  EXPECT_EQ(cases[0].name, "tor/front_1-wire");  // modes in the order given
  EXPECT_EQ(cases[1].name, "tor/front_1-smooth");
  const CaseSpec& c = cases[0];
  EXPECT_EQ(c.mode, Mode::Wire);
  EXPECT_EQ(cases[1].mode, Mode::Smooth);
  EXPECT_EQ(c.view.name, NamedView::Front);
  EXPECT_EQ(c.view.yaw, 10.0);
  EXPECT_EQ(c.view.pitch, -30.5);
  EXPECT_EQ(c.view.distance, 12.0);
  EXPECT_EQ(c.color, ColorMode::Normals);
  EXPECT_EQ(c.size, glm::ivec2(640, 480));
  EXPECT_EQ(c.tolerance, 0.001);
  EXPECT_EQ(c.frames, SweepFrames::Projection);
  EXPECT_EQ(c.seam, SeamClosing::Symmetric);
  EXPECT_EQ(c.time, 2.5);
  EXPECT_EQ(c.diff.threshold, 0.2);
  EXPECT_EQ(c.limits.max_diff_pixels, 40u);
  EXPECT_EQ(c.limits.max_diff_ratio, 0.001);
  EXPECT_EQ(c.diff.shift, 2);
  EXPECT_FALSE(c.diff.forgive_antialiasing);
  EXPECT_EQ(c.file, dir() / "tor.swp");

  const CaseSpec on = parse("tor.swp modes=frames antialiasing=on shift=0 color=uv seam=index frames=rmf\n").at(0);
  EXPECT_TRUE(on.diff.forgive_antialiasing);
  EXPECT_EQ(on.diff.shift, 0);
  EXPECT_EQ(on.color, ColorMode::Uv);
  EXPECT_EQ(on.seam, SeamClosing::Index);
  EXPECT_EQ(on.frames, SweepFrames::Rmf);
  EXPECT_FALSE(on.view.yaw.has_value());
  const std::pair<const char*, ColorMode> colors[] = {{"material", ColorMode::Material},
                                                      {"gaussian", ColorMode::Gaussian},
                                                      {"mean", ColorMode::Mean},
                                                      {"normals", ColorMode::Normals},
                                                      {"uv", ColorMode::Uv}};
  for (const auto& [name, color] : colors) {
    EXPECT_EQ(parse(std::string("tor.swp modes=smooth color=") + name).at(0).color, color) << name;
  }
  const std::pair<const char*, SeamClosing> seams[] = {{"full", SeamClosing::Full},
                                                       {"symmetric", SeamClosing::Symmetric},
                                                       {"index", SeamClosing::Index},
                                                       {"none", SeamClosing::None}};
  for (const auto& [name, seam] : seams) {
    EXPECT_EQ(parse(std::string("tor.swp modes=smooth seam=") + name).at(0).seam, seam) << name;
  }
  const std::pair<const char*, NamedView> views[] = {{"default", NamedView::Default},
                                                     {"front", NamedView::Front},
                                                     {"top", NamedView::Top},
                                                     {"side", NamedView::Side},
                                                     {"iso", NamedView::Iso}};
  for (const auto& [name, view] : views) {
    EXPECT_EQ(parse(std::string("tor.swp modes=smooth view=") + name).at(0).view.name, view) << name;
  }
  // The ends of the ranges are in them.
  const CaseSpec ends = parse(
                            "tor.swp modes=smooth yaw=-360 pitch=90 distance=1e12 size=1x4096 threshold=1 "
                            "max-diff-ratio=0 max-diff-pixels=16777216 shift=3 tolerance=0 T=0\n")
                            .at(0);
  EXPECT_EQ(ends.view.yaw, -360.0);
  EXPECT_EQ(ends.view.pitch, 90.0);
  EXPECT_EQ(ends.size, glm::ivec2(1, 4096));
  EXPECT_EQ(ends.limits.max_diff_pixels, 16777216u);
}

TEST_F(Suite, DefaultsLinesSetTheKeysOfTheLinesAfterThem) {
  CaseDefaults defaults;
  defaults.size = {100, 50};
  defaults.tolerance = 0.5;
  defaults.frames = SweepFrames::Projection;
  defaults.seam = SeamClosing::None;
  defaults.time = 3.0;
  defaults.diff.threshold = 0.3;
  defaults.diff.shift = 0;
  defaults.diff.forgive_antialiasing = false;
  defaults.limits.max_diff_pixels = 5;
  defaults.limits.max_diff_ratio = 0.5;
  const std::vector<CaseSpec> cases = parse(
      "tor.swp modes=smooth                 # the command line's defaults\n"
      "defaults size=640x480 threshold=0.2\n"
      "taper.swp modes=smooth\n"
      "defaults modes=wire color=uv view=top  # adds to the defaults before it\n"
      "wineglass.swp\n"
      "roller-coaster.swp size=10x10 modes=frames view=default\n"
      "defaults\n",
      defaults);
  ASSERT_EQ(names_of(cases),
            (std::vector<std::string>{"tor-smooth", "taper-smooth", "wineglass-top-wire", "roller-coaster-frames"}));
  const CaseSpec& tor = cases[0];
  EXPECT_EQ(tor.size, glm::ivec2(100, 50));
  EXPECT_EQ(tor.tolerance, 0.5);
  EXPECT_EQ(tor.frames, SweepFrames::Projection);
  EXPECT_EQ(tor.seam, SeamClosing::None);
  EXPECT_EQ(tor.time, 3.0);
  EXPECT_EQ(tor.diff.threshold, 0.3);
  EXPECT_EQ(tor.diff.shift, 0);
  EXPECT_FALSE(tor.diff.forgive_antialiasing);
  EXPECT_EQ(tor.limits.max_diff_pixels, 5u);
  EXPECT_EQ(tor.limits.max_diff_ratio, 0.5);
  EXPECT_EQ(tor.color, ColorMode::Material);

  const CaseSpec& taper = cases[1];
  EXPECT_EQ(taper.size, glm::ivec2(640, 480));
  EXPECT_EQ(taper.diff.threshold, 0.2);
  EXPECT_EQ(taper.tolerance, 0.5);  // the keys a defaults line does not give stay
  EXPECT_EQ(taper.suite_location, "snapshots.txt:3");

  const CaseSpec& wineglass = cases[2];
  EXPECT_EQ(wineglass.size, glm::ivec2(640, 480));
  EXPECT_EQ(wineglass.diff.threshold, 0.2);
  EXPECT_EQ(wineglass.color, ColorMode::Uv);
  EXPECT_EQ(wineglass.view.name, NamedView::Top);
  EXPECT_EQ(wineglass.mode, Mode::Wire);

  const CaseSpec& coaster = cases[3];  // a line's own keys win, for it alone
  EXPECT_EQ(coaster.size, glm::ivec2(10, 10));
  EXPECT_EQ(coaster.view.name, NamedView::Default);
  EXPECT_EQ(coaster.color, ColorMode::Uv);
}

TEST_F(Suite, CaseNamesShowTheViewWhenItIsNotTheDefault) {
  const std::vector<CaseSpec> cases = parse(
      "bowls/*.swp modes=smooth view=iso\n"
      "roller-coaster.swp modes=smooth T=2.5 yaw=10 pitch=30 distance=12\n"
      "tor.swp modes=frames view=front yaw=-15.50\n"
      "tor.swp modes=wire view=default\n"
      "tor.swp modes=wire pitch=0 distance=2.5e-3\n"
      "tor.swp modes=smooth,wire color=normals view=front size=320x240 name=tor-normals\n"
      "taper.swp modes=smooth view=iso name=taper\n");
  const std::vector<std::string> expected{"bowls/deep-iso-smooth",
                                          "bowls/flat-iso-smooth",
                                          "roller-coaster-yaw10-pitch30-distance12-smooth",
                                          "tor-front-yaw-15.5-frames",
                                          "tor-wire",
                                          "tor-pitch0-distance0.0025-wire",
                                          "tor-normals-smooth",
                                          "tor-normals-wire",
                                          "taper-smooth"};
  EXPECT_EQ(names_of(cases), expected);
}

TEST_F(Suite, GlobsMatchVisibleSwpFilesInPathOrder) {
  EXPECT_EQ(relatives_of(parse("**/*.swp modes=smooth\n")),
            (std::vector<std::string>{"bowls/deep.swp", "bowls/flat.swp", "deep/a/b/c.swp", "hash#tag.swp",
                                      "my models/cup one.swp", "roller-coaster.swp", "taper.swp", "tor.swp",
                                      "wineglass.swp"}));
  EXPECT_EQ(relatives_of(parse("*/*.swp modes=smooth\n")),
            (std::vector<std::string>{"bowls/deep.swp", "bowls/flat.swp", "my models/cup one.swp"}));
  EXPECT_EQ(relatives_of(parse("deep/**/c.swp modes=smooth\n")), (std::vector<std::string>{"deep/a/b/c.swp"}));
  EXPECT_EQ(relatives_of(parse("**/**/b/**/*.swp modes=smooth\n")), (std::vector<std::string>{"deep/a/b/c.swp"}));
  EXPECT_EQ(relatives_of(parse("t?r.swp modes=smooth\n")), (std::vector<std::string>{"tor.swp"}));
  EXPECT_EQ(relatives_of(parse("t*.swp modes=smooth\n")), (std::vector<std::string>{"taper.swp", "tor.swp"}));
  EXPECT_EQ(relatives_of(parse("*a*e*.swp modes=smooth\n")),
            (std::vector<std::string>{"roller-coaster.swp", "taper.swp"}));
  EXPECT_EQ(relatives_of(parse("b*/*f*.swp modes=smooth\n")), (std::vector<std::string>{"bowls/flat.swp"}));
  // Hidden files and __snapshots__ are matched only by name.
  EXPECT_EQ(names_of(parse("bowls/.draft.swp modes=smooth\nbowls/__snapshots__/old.swp modes=smooth\n")),
            (std::vector<std::string>{"bowls/.draft-smooth", "bowls/__snapshots__/old-smooth"}));
  // "." and empty segments are dropped.
  const CaseSpec deep = parse("./bowls//deep.swp modes=smooth\n").at(0);
  EXPECT_EQ(deep.relative, fs::path("bowls/deep.swp"));
  EXPECT_EQ(deep.name, "bowls/deep-smooth");
  // A folder loop is walked once.
  fs::create_directory_symlink("..", dir() / "deep/a/up");
  EXPECT_EQ(relatives_of(parse("**/c.swp modes=smooth\n")), (std::vector<std::string>{"deep/a/b/c.swp"}));
}

TEST_F(Suite, CommentsBlankLinesQuotesAndLineEnds) {
  const std::vector<CaseSpec> cases = parse(
      "\xEF\xBB\xBF# snapshots.txt\n"
      "\n"
      "   \t \n"
      "  tor.swp modes=smooth   # the torus\r\n"
      "\ttaper.swp\tmodes=wire#glued to the value\n"
      "\"my models/cup one.swp\" modes=frames\n"
      "\"hash#tag.swp\" modes=smooth # a '#' in quotes is the name's\n"
      "\"my models/*.swp\" modes=wire view=side\n"
      "wineglass.swp modes=smooth");  // no newline at the end
  EXPECT_EQ(names_of(cases),
            (std::vector<std::string>{"tor-smooth", "taper-wire", "my models/cup one-frames", "hash#tag-smooth",
                                      "my models/cup one-side-wire", "wineglass-smooth"}));
  EXPECT_EQ(cases[0].suite_location, "snapshots.txt:4");
  EXPECT_EQ(cases[2].file, dir() / "my models/cup one.swp");
  EXPECT_TRUE(parse("").empty());
  EXPECT_TRUE(parse("# nothing\n\n").empty());
}

TEST_F(Suite, ReadSuiteReadsTheFileAndNamesItInMessages) {
  const fs::path suite = dir() / "snapshots.txt";
  sweep::test::write_text(suite, "tor.swp modes=smooth\nwineglass.swp colour=red\n");
  try {
    sweep::snapshot::read_suite(suite, dir(), {});
    ADD_FAILURE() << "no SuiteError";
  } catch (const SuiteError& e) {
    EXPECT_EQ(std::string(e.what()), suite.string() +
                                         ":2:15: unknown key 'colour' (keys: modes, view, yaw, pitch, distance, "
                                         "color, size, tolerance, frames, seam, T, threshold, max-diff-pixels, "
                                         "max-diff-ratio, shift, antialiasing, name)");
  }
  sweep::test::write_text(suite, "tor.swp modes=smooth\n");
  const std::vector<CaseSpec> cases = sweep::snapshot::read_suite(suite, dir(), {});
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0].suite_location, suite.string() + ":1");
}

TEST_F(Suite, ReadSuiteReportsWhyItCannotRead) {
  const auto message = [&](const fs::path& suite) -> std::string {
    try {
      sweep::snapshot::read_suite(suite, dir(), {});
    } catch (const SuiteError& e) {
      return e.what();
    }
    return "(no error)";
  };
  EXPECT_EQ(message(dir() / "missing.txt"),
            (dir() / "missing.txt").string() + ": cannot read: No such file or directory");
  EXPECT_EQ(message(dir() / "bowls"), (dir() / "bowls").string() + ": cannot read: it is a folder");
  const fs::path big = dir() / "big.txt";
  sweep::test::write_text(big, std::string(sweep::snapshot::kMaxSuiteBytes + 10, '\n'));
  EXPECT_EQ(message(big),
            big.string() + ":1:1: expected a suite of at most 1 MiB (1048576 bytes), found 1048586 bytes");
}

TEST_F(Suite, EveryErrorMessageNamesTheSuiteLineAndColumn) {
  const std::string keys =
      "modes, view, yaw, pitch, distance, color, size, tolerance, frames, seam, T, threshold, max-diff-pixels, "
      "max-diff-ratio, shift, antialiasing";
  const std::string name_rule =
      "expected a name of letters, digits, '-', '_' and '/' (at most 200 bytes, no '/' first, last or twice), found ";
  const std::vector<std::pair<std::string, std::string>> cases{
      // The path.
      {"# c\n\n\n\nbowls/*.swp\nnone/*.swp\n", "snapshots.txt:6:1: no .swp file matches 'none/*.swp'"},
      {"missing.swp modes=smooth", "snapshots.txt:1:1: no .swp file matches 'missing.swp'"},
      {"  bowls/notes.swp", "snapshots.txt:1:3: no .swp file matches 'bowls/notes.swp'"},
      {"folder/**/*.swp", "snapshots.txt:1:1: no .swp file matches 'folder/**/*.swp'"},
      {"bowls/*.txt",
       "snapshots.txt:1:1: expected a .swp file, a glob of .swp files or 'defaults', found 'bowls/*.txt'"},
      {"Defaults size=1x1",
       "snapshots.txt:1:1: expected a .swp file, a glob of .swp files or 'defaults', found 'Defaults'"},
      {"\"defaults\"", "snapshots.txt:1:1: expected a .swp file, a glob of .swp files or 'defaults', found 'defaults'"},
      {"/tmp/tor.swp", "snapshots.txt:1:1: expected a path relative to the suite's folder, found '/tmp/tor.swp'"},
      {"bowls/../tor.swp",
       "snapshots.txt:1:1: expected a path below the suite's folder (no '..'), found 'bowls/../tor.swp'"},
      {"\"my models/cup one.swp modes=smooth",
       "snapshots.txt:1:36: expected '\"' to end the quoted path, found the end of the line"},
      {"\"tor.swp\"x modes=smooth", "snapshots.txt:1:10: expected a space after the quoted path, found 'x'"},
      {"tor.swp\x01", "snapshots.txt:1:8: expected printable text, found '\\x01'"},
      {"tor.swp name=a\x7f", "snapshots.txt:1:15: expected printable text, found '\\x7F'"},
      {std::string("\"to\0r.swp\"", 10), "snapshots.txt:1:4: expected printable text, found '\\x00'"},
      {"tor.swp\rmodes=smooth", "snapshots.txt:1:8: expected printable text, found '\\x0D'"},
      // Keys.
      {"tor.swp colour=red", "snapshots.txt:1:9: unknown key 'colour' (keys: " + keys + ", name)"},
      {"tor.swp t=1", "snapshots.txt:1:9: unknown key 't' (keys: " + keys + ", name)"},
      {"defaults colour=red", "snapshots.txt:1:10: unknown key 'colour' (keys: " + keys + ")"},
      {"defaults name=x", "snapshots.txt:1:10: 'name' cannot be a default (keys: " + keys + ")"},
      {"tor.swp size 640x480", "snapshots.txt:1:9: expected key=value (no spaces around '='), found 'size'"},
      {"tor.swp =3", "snapshots.txt:1:9: expected key=value (no spaces around '='), found '=3'"},
      {"tor.swp size=1x1 size=2x2", "snapshots.txt:1:18: key 'size' is already given at column 9"},
      // Values.
      {"tor.swp modes=smooth,shaded",
       "snapshots.txt:1:22: expected a mode (smooth, wire or frames; a list with ','), found 'shaded'"},
      {"tor.swp modes=", "snapshots.txt:1:15: expected a mode (smooth, wire or frames; a list with ','), found ''"},
      {"tor.swp modes=wire,",
       "snapshots.txt:1:20: expected a mode (smooth, wire or frames; a list with ','), found ''"},
      {"tor.swp modes=wire,wire", "snapshots.txt:1:20: mode 'wire' is given twice"},
      {"tor.swp view=back", "snapshots.txt:1:14: expected a view (default, front, top, side or iso), found 'back'"},
      {"tor.swp yaw=400", "snapshots.txt:1:13: expected a yaw in degrees from -360 to 360, found '400'"},
      {"tor.swp yaw=+5", "snapshots.txt:1:13: expected a yaw in degrees from -360 to 360, found '+5'"},
      {"tor.swp yaw=nan", "snapshots.txt:1:13: expected a yaw in degrees from -360 to 360, found 'nan'"},
      {"tor.swp yaw=10deg", "snapshots.txt:1:13: expected a yaw in degrees from -360 to 360, found '10deg'"},
      {"tor.swp pitch=95", "snapshots.txt:1:15: expected a pitch in degrees from -90 to 90, found '95'"},
      {"tor.swp distance=0", "snapshots.txt:1:18: expected a distance > 0 and at most 1e12, found '0'"},
      {"tor.swp distance=1e999", "snapshots.txt:1:18: expected a distance > 0 and at most 1e12, found '1e999'"},
      {"tor.swp color=red",
       "snapshots.txt:1:15: expected a color (material, gaussian, mean, normals or uv), found 'red'"},
      {"defaults size=0x10", "snapshots.txt:1:15: expected a size WxH with sides 1..8192, found '0x10'"},
      {"tor.swp size=8193x10", "snapshots.txt:1:14: expected a size WxH with sides 1..8192, found '8193x10'"},
      {"tor.swp size=640x", "snapshots.txt:1:14: expected a size WxH with sides 1..8192, found '640x'"},
      {"tor.swp size=640X480", "snapshots.txt:1:14: expected a size WxH with sides 1..8192, found '640X480'"},
      {"tor.swp size=-1x5", "snapshots.txt:1:14: expected a size WxH with sides 1..8192, found '-1x5'"},
      {"tor.swp tolerance=-1", "snapshots.txt:1:19: expected a tolerance >= 0 (0: uniform sampling), found '-1'"},
      {"tor.swp frames=frenet", "snapshots.txt:1:16: expected frames rmf or projection, found 'frenet'"},
      {"tor.swp seam=half", "snapshots.txt:1:14: expected a seam (full, symmetric, index or none), found 'half'"},
      {"tor.swp T=-1", "snapshots.txt:1:11: expected a rider time T in seconds from 0 to 1e9, found '-1'"},
      {"tor.swp threshold=1.5", "snapshots.txt:1:19: expected a threshold from 0 to 1, found '1.5'"},
      {"tor.swp max-diff-pixels=1.5",
       "snapshots.txt:1:25: expected a whole number of pixels from 0 to 67108864, found '1.5'"},
      {"tor.swp max-diff-pixels=-3",
       "snapshots.txt:1:25: expected a whole number of pixels from 0 to 67108864, found '-3'"},
      {"tor.swp max-diff-pixels=67108865",
       "snapshots.txt:1:25: expected a whole number of pixels from 0 to 67108864, found '67108865'"},
      {"tor.swp max-diff-pixels=99999999999999999999999",
       "snapshots.txt:1:25: expected a whole number of pixels from 0 to 67108864, found '99999999999999999999999'"},
      {"tor.swp max-diff-ratio=2", "snapshots.txt:1:24: expected a share of the pixels from 0 to 1, found '2'"},
      {"tor.swp shift=4", "snapshots.txt:1:15: expected a shift of 0 to 3 pixels, found '4'"},
      {"tor.swp antialiasing=yes", "snapshots.txt:1:22: expected antialiasing on or off, found 'yes'"},
      {"tor.swp name=a.b", "snapshots.txt:1:14: " + name_rule + "'a.b'"},
      {"tor.swp name=", "snapshots.txt:1:14: " + name_rule + "''"},
      {"tor.swp name=/abs", "snapshots.txt:1:14: " + name_rule + "'/abs'"},
      {"tor.swp name=a//b", "snapshots.txt:1:14: " + name_rule + "'a//b'"},
      {"tor.swp name=a/", "snapshots.txt:1:14: " + name_rule + "'a/'"},
      {"tor.swp name=" + std::string(201, 'n'),
       "snapshots.txt:1:14: " + name_rule + "'" + std::string(100, 'n') + "...'"},
      {"bowls/*.swp name=bowl", "snapshots.txt:1:13: name= needs a path of one file, but 'bowls/*.swp' matches 2"},
      // The first problem: in line order, then in column order.
      {"tor.swp colour=red size=0", "snapshots.txt:1:9: unknown key 'colour' (keys: " + keys + ", name)"},
      {"missing.swp colour=red", "snapshots.txt:1:1: no .swp file matches 'missing.swp'"},
      {"tor.swp\ntor.swp size=0\nwineglass.swp view=x\n",
       "snapshots.txt:2:14: expected a size WxH with sides 1..8192, found '0'"},
  };
  for (const auto& [text, message] : cases) EXPECT_EQ(error(text), message) << text;
}

TEST_F(Suite, ADuplicateCaseNameIsAnErrorNamingTheFirstLine) {
  EXPECT_EQ(error("tor.swp\nwineglass.swp\n# a comment\ntor.swp modes=wire color=uv\n"),
            "snapshots.txt:4:1: case 'tor-wire' is already made by line 1; give this line a name=");
  EXPECT_EQ(error("tor.swp name=x\ntaper.swp modes=frames name=x\n"),
            "snapshots.txt:2:1: case 'x-frames' is already made by line 1; give this line another name=");
  EXPECT_EQ(error("bowls/*.swp view=iso\n  bowls/flat.swp modes=smooth view=iso\n"),
            "snapshots.txt:2:3: case 'bowls/flat-iso-smooth' is already made by line 1; give this line a name=");
  // The same file twice is fine when the names differ.
  EXPECT_EQ(names_of(parse("tor.swp modes=smooth\ntor.swp modes=smooth view=top\ntor.swp modes=smooth name=t\n")),
            (std::vector<std::string>{"tor-smooth", "tor-top-smooth", "t-smooth"}));
}

TEST_F(Suite, BoundsKeepBadInputSmall) {
  const std::string longest = "tor.swp modes=smooth" + std::string(sweep::snapshot::kMaxSuiteLineBytes - 20, ' ');
  EXPECT_EQ(parse(longest).size(), 1u);
  EXPECT_EQ(parse(longest + "\r\n").size(), 1u);  // the line end is not counted
  EXPECT_EQ(error("tor.swp\n" + longest + " "),
            "snapshots.txt:2:4097: expected a line of at most 4096 bytes, found 4097 bytes");
  EXPECT_EQ(error(std::string(sweep::snapshot::kMaxSuiteBytes + 1, '\n')),
            "snapshots.txt:1:1: expected a suite of at most 1 MiB (1048576 bytes), found 1048577 bytes");
  // 33 334 lines of three cases each: the last one passes 100 000.
  std::string many;
  for (int i = 1; i <= 33'334; ++i) many += "tor.swp name=n" + std::to_string(i) + "\n";
  EXPECT_EQ(error(many), "snapshots.txt:33334:1: expected a suite of at most 100000 cases, found more by this line");
  many.resize(many.rfind("tor.swp"));
  EXPECT_EQ(parse(many).size(), 100'000u - 1u);
}

TEST_F(Suite, TheFuzzerSeedsKeepItsProperties) {
  const fs::path seeds = fs::path(SWEEP_SWP_DIR) / ".." / "fuzz" / "suite-corpus";
  const sweep::test::ScratchFolder models("sweep-suite-fuzz");
  sweep::fuzz::make_suite_fuzz_models(models.path());
  int count = 0;
  for (const fs::directory_entry& seed : fs::directory_iterator(seeds)) {
    const std::string text = sweep::test::read_file(seed.path());
    EXPECT_EQ(sweep::fuzz::check_suite_input(text, models.path()), "") << seed.path();
    // Seeds named error-* are bad suites; the others make cases.
    const bool bad = seed.path().filename().string().rfind("error-", 0) == 0;
    bool made_cases = false;
    try {
      made_cases = !sweep::snapshot::parse_suite(text, "seed.txt", models.path(), {}).empty();
    } catch (const SuiteError&) {
      // a bad suite: made_cases stays false
    }
    EXPECT_EQ(made_cases, !bad) << seed.path();
    ++count;
  }
  EXPECT_GE(count, 4);
  // The property holds for bad input too: a bad suite is one located message.
  EXPECT_EQ(sweep::fuzz::check_suite_input("a.swp colour=red", models.path()), "");
  EXPECT_EQ(sweep::fuzz::check_suite_input("**/*.swp\nsub/loop/**/*.swp name=x", models.path()), "");
}

// ---- Shards ----------------------------------------------------------------------------------

TEST(Shard, HashIsFnv1a64OfTheName) {
  EXPECT_EQ(sweep::snapshot::case_name_hash(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(sweep::snapshot::case_name_hash("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(sweep::snapshot::case_name_hash("foobar"), 0x85944171f73967e8ull);
}

TEST(Shard, OneShardIsEveryCaseAndEachShardKeepsTheOrder) {
  std::vector<CaseSpec> cases(40);
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].name = "case" + std::to_string(i) + "-smooth";
  EXPECT_EQ(names_of(sweep::snapshot::shard(cases, 1, 1)), names_of(cases));
  for (int k = 1; k <= 4; ++k) {
    const std::vector<std::string> part = names_of(sweep::snapshot::shard(cases, k, 4));
    EXPECT_FALSE(part.empty()) << "shard " << k << " of 4 of 40 cases";
    std::vector<std::string> in_order;
    for (const CaseSpec& c : cases) {
      if (std::find(part.begin(), part.end(), c.name) != part.end()) in_order.push_back(c.name);
    }
    EXPECT_EQ(part, in_order);
  }
}

TEST(Shard, KOutsideOneToNIsAPreconditionFailure) {
  if (!kChecked) GTEST_SKIP() << "built without SWEEP_CHECK_PRECONDITIONS (CMake option SWEEP_PRECONDITIONS=OFF)";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const std::vector<CaseSpec> cases(2);
  EXPECT_DEATH(sweep::snapshot::shard(cases, 0, 2), "precondition failed: 1 <= k <= n .* in shard");
  EXPECT_DEATH(sweep::snapshot::shard(cases, 3, 2), "precondition failed: 1 <= k <= n .* in shard");
}

std::vector<CaseSpec> cases_named(const std::vector<std::string>& names) {
  std::vector<CaseSpec> cases(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) cases[i].name = names[i];
  return cases;
}

/// The shard (1..n) of each case, by name.
std::map<std::string, int> shard_of_each(const std::vector<CaseSpec>& cases, int n) {
  std::map<std::string, int> shard_of;
  for (int k = 1; k <= n; ++k) {
    for (const CaseSpec& c : sweep::snapshot::shard(cases, k, n)) {
      RC_ASSERT(shard_of.emplace(c.name, k).second);  // in one shard only
    }
  }
  return shard_of;
}

RC_GTEST_PROP(Shard, ShardsPartitionTheCasesAndAddingACaseMovesNoOther, ()) {
  const int n = *rc::gen::inRange(1, 17);
  const auto unique = *rc::gen::container<std::set<std::string>>(rc::gen::nonEmpty(rc::gen::string<std::string>()));
  const auto added = *rc::gen::nonEmpty(rc::gen::string<std::string>());
  RC_PRE(unique.count(added) == 0u);
  std::vector<std::string> names(unique.begin(), unique.end());
  const std::map<std::string, int> before = shard_of_each(cases_named(names), n);
  RC_ASSERT(before.size() == names.size());  // every case in a shard

  const auto at = *rc::gen::inRange<std::size_t>(0, names.size() + 1);
  names.insert(names.begin() + static_cast<std::ptrdiff_t>(at), added);
  std::map<std::string, int> after = shard_of_each(cases_named(names), n);
  RC_ASSERT(after.size() == names.size());
  after.erase(added);
  RC_ASSERT(after == before);
}

}  // namespace
