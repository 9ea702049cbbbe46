// Opening a large file and exporting a large document off the drawing thread, without a window:
// open_file and export_document start a background task, poll_task applies what it found on the
// calling thread, Cancel drops it; a file with an error keeps the document and reports the
// error; small ones are done at once.
#include "app/viewer/actions.hpp"
#include "app/viewer/viewer_state.hpp"
#include "io/swp/read.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>
#include <string>

namespace sweep::viewer {
namespace {

namespace fs = std::filesystem;

/// A polyline of `points` points (about 25 bytes each: 350 000 make a file past the 8 MiB from
/// which files are read in the background), then `tail`.
std::string long_polyline(int points, const std::string& tail = "") {
  std::ostringstream text;
  text << "poly3 long " << points << '\n';
  for (int i = 0; i < points; ++i) text << '[' << i * 0.001 << ' ' << (i % 7) * 0.25 << " 1.234567890]\n";
  text << tail;
  return text.str();
}

/// Polls until the task in flight is applied.
void finish_task(ViewerState& s) {
  ASSERT_TRUE(s.task);
  s.task->wait();
  ASSERT_TRUE(poll_task(s));
  EXPECT_FALSE(s.task);
}

TEST(BackgroundOpen, ALargeFileIsReadInTheBackgroundAndShownWhenRead) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "big.swp";
  test::write_text(file, long_polyline(350'000));
  ASSERT_GE(fs::file_size(file), 8u << 20);
  ViewerState s;
  ASSERT_TRUE(open_file(s, file.string()));
  ASSERT_TRUE(s.task) << "read in the background";
  EXPECT_EQ(s.task->label(), "Opening big.swp");
  EXPECT_EQ(s.session.file(), "") << "the document stays until the new one is read";
  finish_task(s);
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(s.session.file(), file.string());
  ASSERT_EQ(s.doc().objects.size(), 1u);
  EXPECT_EQ(points_of(s.doc().objects[0]).size(), 350'000u);
  s.session.finish_evaluation();  // 350 000 samples: evaluated in the background too
  EXPECT_EQ(s.session.scene().objects[0].curve.frames.size(), 350'000u);
}

TEST(BackgroundOpen, ALargeFileWithAnErrorKeepsTheDocumentAndSaysWhere) {
  const test::ScratchFolder folder;
  const fs::path small = folder.path() / "small.swp";
  test::write_text(small, "circ ring 8 1\n");
  const fs::path file = folder.path() / "big.swp";
  test::write_text(file, long_polyline(350'000, "circ broken 8\n"));
  ViewerState s;
  ASSERT_TRUE(open_file(s, small.string()));
  EXPECT_FALSE(s.task) << "a small file is read at once";
  ASSERT_TRUE(open_file(s, file.string()));
  finish_task(s);
  EXPECT_EQ(s.error, file.string() + ":350003:1: expected a number (radius), found end of file");
  EXPECT_EQ(s.session.file(), small.string());
}

TEST(BackgroundOpen, CancelDropsTheFileBeingRead) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "big.swp";
  test::write_text(file, long_polyline(350'000));
  ViewerState s;
  ASSERT_TRUE(open_file(s, file.string()));
  cancel_task(s);
  EXPECT_FALSE(s.task);
  EXPECT_EQ(s.status, "cancelled: Opening big.swp");
  ASSERT_EQ(s.retired_tasks.size(), 1u);
  s.retired_tasks.front()->wait();
  EXPECT_FALSE(poll_task(s));  // nothing to apply; the finished thread is let go
  EXPECT_TRUE(s.retired_tasks.empty());
  EXPECT_EQ(s.session.file(), "");
  EXPECT_TRUE(s.doc().objects.empty());
}

TEST(BackgroundExport, ALargeDocumentIsExportedInTheBackground) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "model.swp";
  // 20 000 samples turned 16 times: 320 000 vertices, past the viewer's background work.
  test::write_text(file, "circ profile 20000 0.5\nsrev vase 16 profile\n");
  ViewerState s;
  ASSERT_TRUE(open_file(s, file.string()));
  s.session.finish_evaluation();
  export_document(s, "out", io::ExportFormat::Stl);
  ASSERT_TRUE(s.task) << "exported in the background";
  finish_task(s);
  EXPECT_EQ(s.error, "");
  const fs::path stl = folder.path() / "out_vase.stl";
  EXPECT_EQ(s.status.rfind("wrote " + fs::canonical(stl).string() + " (", 0), 0u) << s.status;
  // Binary STL: an 80-byte header, a count, 50 bytes a triangle.
  EXPECT_GT(fs::file_size(stl), 84u + 50u * 300'000u);
}

}  // namespace
}  // namespace sweep::viewer
