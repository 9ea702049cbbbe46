// `sweep snapshot` across two renderers (issue 56): references made by llvmpipe, then runs under
// Mesa's softpipe (GALLIUM_DRIVER=softpipe, standing in for another machine's driver). Unchanged
// models pass as renderer differences with a warning; a moved control point still fails and
// names its object; --update adds NAME_1.png and leaves llvmpipe's references byte-identical;
// then both renderers pass with no change.
#include "snapshot/snapshot_cli_support.hpp"

#include <gtest/gtest.h>

#include <map>

namespace sweep::test {
namespace {

const std::string kSoftpipe = "GALLIUM_DRIVER=softpipe";

/// Every file under the references folder and its bytes.
std::map<std::string, std::string> references_of(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& entry : fs::recursive_directory_iterator(dir / "models" / "__snapshots__")) {
    if (entry.is_regular_file()) out[entry.path().lexically_relative(dir).generic_string()] = read_file(entry.path());
  }
  return out;
}

/// A folder whose references llvmpipe made.
fs::path llvmpipe_references(const std::string& test) {
  const fs::path dir = fresh_models(test);
  const Outcome first = snapshot(dir, "models -q --update");
  EXPECT_EQ(first.status, 0) << first.out << first.err;
  EXPECT_NE(read_file(dir / "models" / "__snapshots__" / "wineglass-smooth.json").find("llvmpipe"), std::string::npos);
  return dir;
}

TEST(SnapshotRenderers, AnotherRendererWarnsThenItsUpdateAddsReferencesBesideTheFirst) {
  const fs::path dir = llvmpipe_references("renderers");
  const std::map<std::string, std::string> llvmpipe = references_of(dir);

  const Outcome other = snapshot(dir, "models -q --report report --junit report/junit.xml", kSoftpipe);
  EXPECT_EQ(other.status, 0) << other.out << other.err;
  const std::vector<std::string> warnings = lines_starting(other.out, "warning  ");
  EXPECT_GE(warnings.size(), 6u) << other.out;  // pictures with shading or lines differ between the two
  for (const std::string& line : warnings) {
    EXPECT_NE(line.find(": renderer difference: "), std::string::npos) << line;
    EXPECT_NE(line.find(" made by llvmpipe"), std::string::npos) << line;
    EXPECT_NE(line.find("; this machine renders with softpipe"), std::string::npos) << line;
    EXPECT_NE(line.find("every object, material, the camera and the options are unchanged"), std::string::npos);
    EXPECT_TRUE(line.ends_with("to add this renderer's reference: sweep snapshot models --update=renderer")) << line;
  }
  EXPECT_EQ(lines_starting(other.out, "FAIL").size(), 0u) << other.out;
  const std::string junit = read_file(dir / "report" / "junit.xml");
  EXPECT_NE(junit.find("failures=\"0\" errors=\"0\""), std::string::npos) << junit;
  EXPECT_NE(junit.find("warning: renderer difference: "), std::string::npos);
  expect_report_works_in_a_browser(dir / "report");
  EXPECT_NE(read_file(dir / "report" / "index.html").find("none from this run's renderer, softpipe"),
            std::string::npos);

  const Outcome strict = snapshot(dir, "models -q --strict-renderer", kSoftpipe);
  EXPECT_EQ(strict.status, 1) << strict.out;

  const Outcome update = snapshot(dir, "models -q --update", kSoftpipe);
  EXPECT_EQ(update.status, 0) << update.out << update.err;
  EXPECT_EQ(lines_starting(update.out, "updated  ").size(), warnings.size()) << update.out;
  EXPECT_NE(update.out.find("added models/__snapshots__/wineglass-smooth_1.png for softpipe"), std::string::npos)
      << update.out;
  for (const auto& [file, bytes] : llvmpipe) EXPECT_EQ(read_file(dir / file), bytes) << file << " was rewritten";
  EXPECT_NE(read_file(dir / "models" / "__snapshots__" / "wineglass-smooth_1.json").find("softpipe"),
            std::string::npos);

  for (const std::string& env : {std::string(), kSoftpipe}) {
    const Outcome again = snapshot(dir, "models -q", env);
    EXPECT_EQ(again.status, 0) << env << again.out << again.err;
    EXPECT_NE(again.out.find("9 passed, 0 failed (0 new, 0 updated, 0 warnings, 0 errors)"), std::string::npos)
        << env << again.out;
  }
  const Outcome update_again = snapshot(dir, "models -q --update", kSoftpipe);
  EXPECT_EQ(lines_starting(update_again.out, "updated ").size(), 0u) << update_again.out;
}

TEST(SnapshotRenderers, AMovedControlPointFailsUnderAnotherRendererAndNamesItsObject) {
  const fs::path dir = llvmpipe_references("renderers-moved");
  move_outer_wall_point(dir / "models" / "wineglass.swp");
  const Outcome run = snapshot(dir, "models -q --update=renderer", kSoftpipe);
  EXPECT_EQ(run.status, 1) << run.out << run.err;
  const std::vector<std::string> failed = lines_starting(run.out, "FAIL     ");
  ASSERT_EQ(failed.size(), 3u) << run.out;
  for (const std::string& line : failed) EXPECT_NE(line.find(" wineglass-"), std::string::npos) << line;
  EXPECT_NE(run.out.find("wineglass: "), std::string::npos);
  EXPECT_NE(run.out.find("its mesh moved up to 0.03"), std::string::npos) << run.out;
  // --update=renderer accepts renderer differences only, never a model change.
  EXPECT_FALSE(fs::exists(dir / "models" / "__snapshots__" / "wineglass-smooth_1.png"));
}

}  // namespace
}  // namespace sweep::test
