// Output safety: OBJ export and SWP save go through a temporary file and a rename, so a failure
// (missing folder, unwritable folder, full disk, target is a folder) gives a clear error, leaves
// the existing target as it was and leaves no temporary file behind. The tests run as root in CI,
// where permission bits do not stop writes, so each failure is made in a way root cannot bypass.
#include "io/files/atomic_file.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

using sweep::test::read_file;

using sweep::test::ScratchFolder;
using sweep::test::write_text;

/// Scratch folders are named after this test file, so a leftover says where it came from.
const char* const kScratchPrefix = "sweep-output";

/// A mesh whose OBJ text is far larger than any stdio or ObjBuffer buffer (about 2.5 MB).
sweep::Mesh large_mesh() {
  sweep::Mesh mesh;
  for (int i = 0; i < 50'000; ++i) {
    const float x = static_cast<float>(i) * 0.001f;
    mesh.positions.push_back({x, -x, 0.5f + x});
    mesh.normals.push_back({0.0f, 0.0f, 1.0f});
  }
  for (std::uint32_t i = 0; i + 2 < 50'000; i += 3) mesh.indices.insert(mesh.indices.end(), {i, i + 1, i + 2});
  return mesh;
}

sweep::Document small_document() {
  return sweep::io::parse_swp("circ c 8 1\nsrev s 4 c\n", "small.swp");
}

/// The message of the std::runtime_error `action` throws, or "no error".
std::string error_of(const std::function<void()>& action) {
  try {
    action();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "no error";
}

TEST(OutputSafety, SuccessfulSavesReplaceTheTargetAndLeaveOnlyIt) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path obj = folder.path() / "out.obj";
  const fs::path swp = folder.path() / "out.swp";
  write_text(obj, "old");
  write_text(swp, "old");
  const sweep::Mesh mesh = large_mesh();
  sweep::io::save_obj_file(obj, mesh, "large");
  sweep::io::save_swp_file(swp, small_document());
  EXPECT_EQ(read_file(obj), sweep::io::obj_text(mesh, "large"));
  EXPECT_EQ(sweep::io::load_swp_file(swp), small_document());
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out.obj", "out.swp"}));
}

TEST(OutputSafety, MissingFolder) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path obj = folder.path() / "missing" / "out.obj";
  EXPECT_EQ(error_of([&] { sweep::io::save_obj_file(obj, large_mesh()); }),
            "cannot write " + obj.string() + ": cannot create a temporary file beside it: No such file or directory");
  const fs::path swp = folder.path() / "missing" / "out.swp";
  EXPECT_EQ(error_of([&] { sweep::io::save_swp_file(swp, small_document()); }),
            "cannot write " + swp.string() + ": cannot create a temporary file beside it: No such file or directory");
  EXPECT_TRUE(folder.entries().empty());
}

TEST(OutputSafety, ParentIsARegularFile) {
  // Holds for root too: no permission lets a file be created inside a regular file.
  ScratchFolder folder(kScratchPrefix);
  write_text(folder.path() / "file", "keep");
  const fs::path obj = folder.path() / "file" / "out.obj";
  EXPECT_EQ(error_of([&] { sweep::io::save_obj_file(obj, large_mesh()); }),
            "cannot write " + obj.string() + ": cannot create a temporary file beside it: Not a directory");
  EXPECT_EQ(read_file(folder.path() / "file"), "keep");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"file"});
}

TEST(OutputSafety, ReadOnlyFolder) {
  fs::path target;
  std::optional<ScratchFolder> folder;
  if (::geteuid() != 0) {
    folder.emplace(kScratchPrefix);
    fs::permissions(folder->path(), fs::perms::owner_read | fs::perms::owner_exec);
    target = folder->path() / "out.obj";
  } else {
    // Root writes through permission bits; sysfs refuses to create files even for root.
    if (!fs::is_directory("/sys/kernel")) GTEST_SKIP() << "no /sys to stand in for a read-only folder as root";
    target = "/sys/kernel/sweep-hardening-test.obj";
  }
  EXPECT_EQ(error_of([&] { sweep::io::save_obj_file(target, large_mesh()); }),
            "cannot write " + target.string() + ": cannot create a temporary file beside it: Permission denied");
  EXPECT_FALSE(fs::exists(target));
  for (const auto& e : fs::directory_iterator(target.parent_path())) {
    EXPECT_EQ(e.path().filename().string().find("sweep-hardening-test"), std::string::npos);
  }
  if (folder) {
    EXPECT_TRUE(folder->entries().empty());
  }
}

/// Lowers the largest file size this process may write (RLIMIT_FSIZE, which binds root too) so a
/// write fails part way as on a full disk, and restores it on destruction.
class FileSizeLimit {
 public:
  explicit FileSizeLimit(rlim_t bytes) {
    ::getrlimit(RLIMIT_FSIZE, &saved_);
    // Over the limit the kernel sends SIGXFSZ, which would kill the process; ignored, the write
    // fails with EFBIG instead.
    previous_handler_ = std::signal(SIGXFSZ, SIG_IGN);
    rlimit lowered = saved_;
    lowered.rlim_cur = bytes;
    ::setrlimit(RLIMIT_FSIZE, &lowered);
  }
  ~FileSizeLimit() {
    ::setrlimit(RLIMIT_FSIZE, &saved_);
    std::signal(SIGXFSZ, previous_handler_);
  }
  FileSizeLimit(const FileSizeLimit&) = delete;
  FileSizeLimit& operator=(const FileSizeLimit&) = delete;

 private:
  rlimit saved_{};
  void (*previous_handler_)(int) = nullptr;
};

TEST(OutputSafety, WriteFailingPartWayLeavesTheTargetUntouched) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path obj = folder.path() / "out.obj";
  const fs::path swp = folder.path() / "out.swp";
  write_text(obj, "previous export");
  write_text(swp, "circ previous 4 1\n");
  std::string obj_error, swp_error;
  {
    const FileSizeLimit limit(100'000);  // part of the 2.5 MB OBJ text fits
    obj_error = error_of([&] { sweep::io::save_obj_file(obj, large_mesh()); });
    const FileSizeLimit tiny(10);
    swp_error = error_of([&] { sweep::io::save_swp_file(swp, small_document()); });
  }
  EXPECT_EQ(obj_error, "cannot write " + obj.string() + ": writing failed: File too large");
  EXPECT_EQ(swp_error, "cannot write " + swp.string() + ": writing failed: File too large");
  EXPECT_EQ(read_file(obj), "previous export");
  EXPECT_EQ(read_file(swp), "circ previous 4 1\n");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out.obj", "out.swp"}));
}

TEST(OutputSafety, FullDiskIsReportedByTheObjWriter) {
  // /dev/full fails every write with ENOSPC. Unbuffered, the failure reaches write_obj's own
  // writes; buffered, it must surface at the latest when the stream is flushed.
  std::FILE* full = std::fopen("/dev/full", "wb");
  if (!full) GTEST_SKIP() << "no /dev/full";
  std::setvbuf(full, nullptr, _IONBF, 0);
  EXPECT_FALSE(sweep::io::write_obj(full, large_mesh()));
  EXPECT_TRUE(std::ferror(full));
  std::fclose(full);

  full = std::fopen("/dev/full", "wb");
  const bool wrote = sweep::io::write_obj(full, large_mesh());
  const bool flushed = std::fflush(full) == 0;
  EXPECT_FALSE(wrote && flushed);
  std::fclose(full);
}

TEST(OutputSafety, WriterThatGivesUpLeavesNothing) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path target = folder.path() / "out.txt";
  write_text(target, "before");
  EXPECT_EQ(error_of([&] {
              sweep::io::write_file_atomically(target, [](std::FILE* f) {
                std::fputs("half", f);
                errno = ENOSPC;
                return false;
              });
            }),
            "cannot write " + target.string() + ": writing failed: No space left on device");
  EXPECT_THROW(sweep::io::write_file_atomically(target,
                                                [](std::FILE* f) -> bool {
                                                  std::fputs("half", f);
                                                  throw std::runtime_error("generator failed");
                                                }),
               std::runtime_error);
  EXPECT_EQ(read_file(target), "before");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.txt"});
}

TEST(OutputSafety, TargetThatIsAFolder) {
  ScratchFolder folder(kScratchPrefix);
  fs::create_directory(folder.path() / "out.obj");
  const fs::path target = folder.path() / "out.obj";
  EXPECT_EQ(error_of([&] { sweep::io::save_obj_file(target, large_mesh()); }),
            "cannot write " + target.string() + ": cannot rename the temporary file over it: Is a directory");
  EXPECT_TRUE(fs::is_directory(target));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out.obj"});
}

}  // namespace
