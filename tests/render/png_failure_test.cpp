// A PNG (a render, a screenshot) with every write failing in turn (issue 29): the old picture
// stays or the new one is whole, no temporary is left, and the message names the path and the
// cause.
#include "render/image.hpp"
#include "render/png_file.hpp"
#include "support/scratch_folder.hpp"
#include "support/write_failure_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep {
namespace {

using test::WriteOutcome;

TEST(PngFailure, APictureIsTheOldOneOrTheNewOneWhole) {
  const test::ScratchFolder folder;
  const std::filesystem::path path = folder.path() / "render.png";
  test::restore_folder(folder.path(), {{"render.png", "an older picture"}});
  // Noise compresses badly: a file of several writes.
  render::Image image{256, 256, std::vector<std::uint8_t>(256 * 256 * 4)};
  std::uint32_t state = 12345;
  for (std::uint8_t& byte : image.rgba) {
    state = state * 1664525u + 1013904223u;
    byte = static_cast<std::uint8_t>(state >> 24);
  }
  const int injected = test::expect_every_failure_leaves_old_or_new(
      folder.path(),
      [&] {
        try {
          render::save_png_file(path, image);
          return WriteOutcome{};
        } catch (const std::exception& e) {
          return WriteOutcome{false, e.what()};
        }
      },
      [&](const WriteOutcome& failed) {
        EXPECT_EQ(failed.message.rfind("cannot write " + path.string() + ": ", 0), 0u) << failed.message;
      });
  EXPECT_GE(injected, 6);
}

}  // namespace
}  // namespace sweep
