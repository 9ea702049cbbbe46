// The real `sweep` binary: the window under Xvfb (--screenshot), the no-display message, and
// `sweep render` writing a PNG or, for a bad file, nothing.
#include "render/png_file.hpp"
#include "support/file_support.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;
using test::quoted;
using test::read_file;
using test::write_text;

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs a shell command line with stdout and stderr captured in files of `dir`.
CommandResult run_command(const std::string& command, const fs::path& dir) {
  const fs::path out = dir / "stdout.txt";
  const fs::path err = dir / "stderr.txt";
  const std::string line = command + " >" + out.string() + " 2>" + err.string();
  const int status = std::system(line.c_str());
  CommandResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.out = read_file(out);
  result.err = read_file(err);
  return result;
}

class SweepBinary : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(SWEEP_TEST_OUTPUT_DIR) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  fs::path dir_;
  const std::string sweep_ = quoted(SWEEP_EXECUTABLE);
  const fs::path swp_ = SWEEP_SWP_DIR;
};

/// Distinct colours and the share of pixels unlike the top-right corner (the background).
struct Busyness {
  std::size_t colours = 0;
  double foreground_share = 0.0;
};

Busyness busyness(const render::Image& image) {
  std::set<std::uint32_t> colours;
  const std::uint8_t* corner = image.pixel(image.width - 1, 0);
  std::size_t foreground = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      colours.insert(std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | p[2]);
      if (p[0] != corner[0] || p[1] != corner[1] || p[2] != corner[2]) ++foreground;
    }
  }
  return {colours.size(), double(foreground) / (double(image.width) * double(image.height))};
}

TEST_F(SweepBinary, WindowScreenshotUnderXvfbIsNotBlank) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const fs::path shot = dir_ / "viewer.png";
  const CommandResult r =
      run_command("xvfb-run -a -s '-screen 0 1280x800x24' " + sweep_ + " view " + quoted(swp_ / "weird.swp") +
                      " --size 800x600 --screenshot " + quoted(shot) + " --frame-count 4",
                  dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  ASSERT_TRUE(fs::exists(shot)) << r.err;
  const render::Image image = render::load_png_file(shot);
  EXPECT_EQ(image.width, 800);
  EXPECT_EQ(image.height, 600);
  const Busyness b = busyness(image);
  EXPECT_GT(b.colours, 50u) << "a shaded surface and the panels have many colours";
  EXPECT_GT(b.foreground_share, 0.10);
}

TEST_F(SweepBinary, TheViewerWorksWithoutUsableUserFolders) {
  // No HOME, and XDG folders where nothing can be created (under a regular file): the viewer
  // says so once in its Error panel and works on; nothing crashes.
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  write_text(dir_ / "file", "x");
  const fs::path shot = dir_ / "viewer.png";
  const CommandResult r = run_command(
      "env -u HOME XDG_STATE_HOME=" + quoted(dir_ / "file" / "state") +
          " XDG_CONFIG_HOME=" + quoted(dir_ / "file" / "config") + " xvfb-run -a -s '-screen 0 1280x800x24' " + sweep_ +
          " view " + quoted(swp_ / "tor.swp") + " --size 640x480 --screenshot " + quoted(shot) + " --frame-count 3",
      dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_TRUE(fs::exists(shot));
  EXPECT_FALSE(fs::exists(dir_ / "file" / "config"));
}

/// Pixels in the colour of control points (yellow: DisplaySettings::control_color).
std::size_t yellow_pixels(const render::Image& image) {
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > 200 && p[1] > 170 && p[2] < 90) ++count;
    }
  }
  return count;
}

TEST_F(SweepBinary, TheViewerShowsTheControlPointsFromTheStart) {
  if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) GTEST_SKIP() << "xvfb-run is not installed";
  const auto shot = [&](const std::string& name, const std::string& extra) {
    const fs::path png = dir_ / name;
    const CommandResult r =
        run_command("xvfb-run -a -s '-screen 0 1280x800x24' " + sweep_ + " view " + quoted(swp_ / "core.swp") +
                        " --no-ui --size 400x300 --screenshot " + quoted(png) + extra,
                    dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return render::load_png_file(png);
  };
  // The original tool's users look for the yellow points: the viewer starts with them on.
  EXPECT_GT(yellow_pixels(shot("default.png", "")), 100u);
  EXPECT_EQ(yellow_pixels(shot("off.png", " --points off")), 0u);
}

TEST_F(SweepBinary, ViewWithoutDisplaySaysSoInOneLine) {
  const CommandResult r =
      run_command("env -u DISPLAY -u WAYLAND_DISPLAY " + sweep_ + " view " + quoted(swp_ / "tor.swp"), dir_);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("no display"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("sweep render"), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
}

TEST_F(SweepBinary, RenderWritesThePicture) {
  const fs::path png = dir_ / "tor.png";
  const CommandResult r =
      run_command(sweep_ + " render " + quoted(swp_ / "tor.swp") + " -o " + quoted(png) +
                      " --size 200x150 --surface wire --curves frames --points on --yaw 10 --pitch 50 --ortho",
                  dir_);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const render::Image image = render::load_png_file(png);
  EXPECT_EQ(image.width, 200);
  EXPECT_EQ(image.height, 150);
  EXPECT_GT(busyness(image).foreground_share, 0.05);
  // No temporary files left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator{}), 3);  // png + 2 logs
}

TEST_F(SweepBinary, RenderDrawsTheGroundGridOnlyWhenAsked) {
  const auto render_to = [&](const std::string& name, const std::string& extra) {
    const fs::path png = dir_ / name;
    const CommandResult r = run_command(
        sweep_ + " render " + quoted(swp_ / "wineglass.swp") + " -o " + quoted(png) + " --size 200x150" + extra, dir_);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return render::load_png_file(png);
  };
  const render::Image plain = render_to("plain.png", "");
  const render::Image grid = render_to("grid.png", " --grid");
  // The x axis: red well above green and blue, which the blue-grey glass and background never are.
  const auto red = [](const render::Image& image) {
    std::size_t n = 0;
    for (int y = 0; y < image.height; ++y) {
      for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* p = image.pixel(x, y);
        if (p[0] > p[1] + 30 && p[0] > p[2] + 30) ++n;
      }
    }
    return n;
  };
  EXPECT_EQ(red(plain), 0u) << "sweep render keeps its pictures (the goldens) without --grid";
  EXPECT_GT(red(grid), 20u);
  EXPECT_GT(busyness(grid).foreground_share, busyness(plain).foreground_share + 0.02) << "the grid's lines";
}

TEST_F(SweepBinary, RenderOfABadFilePrintsWhereAndWritesNothing) {
  const fs::path bad = dir_ / "bad.swp";
  write_text(bad, "circ c 20 1\nsrev s 10 nowhere\n");
  const fs::path png = dir_ / "bad.png";
  const CommandResult r = run_command(sweep_ + " render " + quoted(bad) + " -o " + quoted(png), dir_);
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.err.find("bad.swp:2:"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(png));
}

/// Pixels clearly magenta: red and blue alike and well above green (no starter colour is).
std::size_t magenta_pixels(const render::Image& image) {
  std::size_t n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > p[1] + 60 && p[2] > p[1] + 60 && std::abs(int(p[0]) - int(p[2])) < 40) ++n;
    }
  }
  return n;
}

TEST_F(SweepBinary, RenderOfAFileWithoutItsTextureWarnsAndDrawsAMagentaChecker) {
  // An SWP file copied without its PNG: drawn, with the placeholder where the surface is, and one
  // warning naming the file, line and column; exit status 0.
  const fs::path file = dir_ / "lost.swp";
  write_text(file,
             "material wood color 0.8 0.5 0.25 texture wood.png\ncirc c 24 1\ncirc s 48 3\ngcyl t c s material wood\n");
  const fs::path png = dir_ / "lost.png";
  const CommandResult r =
      run_command(sweep_ + " render " + quoted(file) + " -o " + quoted(png) + " --size 200x150", dir_);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(r.err, file.string() + ":1:42: warning: texture 'wood.png' not found; drawn as a magenta checker\n");
  const render::Image lost = render::load_png_file(png);
  EXPECT_GT(magenta_pixels(lost), 2000u) << "the torus covers about a third of the picture";
  // With the image beside it the same file has no magenta and no warning.
  fs::copy_file(swp_ / "artifacts" / "wood.png", dir_ / "wood.png");
  const fs::path found = dir_ / "found.png";
  const CommandResult again =
      run_command(sweep_ + " render " + quoted(file) + " -o " + quoted(found) + " --size 200x150", dir_);
  EXPECT_EQ(again.exit_code, 0) << again.err;
  EXPECT_EQ(again.err, "");
  EXPECT_EQ(magenta_pixels(render::load_png_file(found)), 0u);
}

TEST_F(SweepBinary, RenderRejectsABadSize) {
  const CommandResult r = run_command(
      sweep_ + " render " + quoted(swp_ / "tor.swp") + " -o " + quoted(dir_ / "x.png") + " --size 12", dir_);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_FALSE(fs::exists(dir_ / "x.png"));
}

}  // namespace
}  // namespace sweep
