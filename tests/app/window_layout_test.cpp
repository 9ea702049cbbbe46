// The window layout (imgui.ini) is written by the viewer, atomically, not by ImGui in place: with
// every write failing in turn the old layout stays or the new one is whole, no temporary is left,
// and the problem is reported once, naming the path and the cause (issue 29).
#include "app/viewer/file_safety.hpp"
#include "headless_imgui.hpp"
#include "support/scratch_folder.hpp"
#include "support/write_failure_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::viewer {
namespace {

using test::WriteOutcome;

TEST(WindowLayout, IsTheOldFileOrTheNewOneWhole) {
  const test::ScratchFolder folder;
  test::HeadlessImGui imgui;
  ViewerState s;
  s.safety.ini_file = (folder.path() / "imgui.ini").string();
  test::restore_folder(folder.path(), {{"imgui.ini", "[Window][old]\nPos=1,2\n"}});
  imgui.frame(s, [](ViewerState&) {});  // a window: something to keep
  const int injected = test::expect_every_failure_leaves_old_or_new(
      folder.path(),
      [&] {
        save_window_layout(s, true);
        return WriteOutcome{s.safety.layout_problem.empty(), s.safety.layout_problem};
      },
      [&](const WriteOutcome& failed) {
        EXPECT_EQ(failed.message.rfind("cannot write " + s.safety.ini_file + ": ", 0), 0u) << failed.message;
        EXPECT_NE(s.error.find("window layout not kept: " + failed.message), std::string::npos) << s.error;
      });
  EXPECT_GE(injected, 5);
  const test::FolderContents written = test::folder_contents(folder.path());
  EXPECT_NE(written.at("imgui.ini").find("[Window][panel]"), std::string::npos) << "the layout ImGui keeps";
}

TEST(WindowLayout, AProblemIsReportedOnce) {
  const test::ScratchFolder folder;
  test::HeadlessImGui imgui;
  ViewerState s;
  s.safety.ini_file = (folder.path() / "missing" / "imgui.ini").string();
  imgui.frame(s, [](ViewerState&) {});
  save_window_layout(s, true);
  const std::string once = s.error;
  EXPECT_EQ(once.rfind("window layout not kept: cannot write " + s.safety.ini_file + ": ", 0), 0u) << once;
  save_window_layout(s, true);
  EXPECT_EQ(s.error, once) << "the same problem again is not repeated";
}

}  // namespace
}  // namespace sweep::viewer
