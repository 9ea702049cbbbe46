// The one image comparison (snapshot/image_diff.hpp) on constructed pictures: what differs, what
// is forgiven as an anti-aliased edge or a one-pixel shift and what never is (a thin line that
// vanished), the summary's texts and the heat map's colours; and, as properties, what holds for
// any picture (an image against itself, swapping the two, translations, forgiving never adds).
#include "snapshot/image_diff.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

namespace sweep::snapshot {
namespace {

#if defined(SWEEP_CHECK_PRECONDITIONS) && SWEEP_CHECK_PRECONDITIONS
constexpr bool kChecked = true;
#else
constexpr bool kChecked = false;
#endif

using Rgb = std::array<std::uint8_t, 3>;

constexpr Rgb kGrey{128, 128, 128};
constexpr Rgb kWhite{255, 255, 255};
constexpr Rgb kNavy{20, 30, 90};
constexpr Rgb kRed{255, 0, 0};
constexpr Rgb kCyan{0, 255, 255};

render::Image filled(int width, int height, Rgb colour) {
  render::Image image;
  image.width = width;
  image.height = height;
  image.rgba.resize(std::size_t(width) * std::size_t(height) * 4);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    image.rgba[i] = colour[0];
    image.rgba[i + 1] = colour[1];
    image.rgba[i + 2] = colour[2];
    image.rgba[i + 3] = 255;
  }
  return image;
}

void set(render::Image& image, int x, int y, Rgb colour) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = colour[0];
  p[1] = colour[1];
  p[2] = colour[2];
}

Rgb rgb_at(const render::Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2]};
}

/// Fills the columns [x0, x1) of the rows [y0, y1).
void fill_rect(render::Image& image, int x0, int y0, int x1, int y1, Rgb colour) {
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) set(image, x, y, colour);
  }
}

/// A disc drawn as a rasterizer with coverage blending draws it: each pixel is the background
/// blended with `colour` by the share of its 16 x 16 sample points inside the disc.
render::Image soft_disc(int width, int height, double cx, double cy, double radius, Rgb background, Rgb colour) {
  render::Image image = filled(width, height, background);
  constexpr int kSamples = 16;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      int inside = 0;
      for (int sy = 0; sy < kSamples; ++sy) {
        for (int sx = 0; sx < kSamples; ++sx) {
          const double px = x + (sx + 0.5) / kSamples - cx;
          const double py = y + (sy + 0.5) / kSamples - cy;
          if (px * px + py * py <= radius * radius) ++inside;
        }
      }
      const double coverage = double(inside) / (kSamples * kSamples);
      Rgb blended;
      for (int c = 0; c < 3; ++c) {
        blended[std::size_t(c)] = static_cast<std::uint8_t>(
            std::lround(background[std::size_t(c)] + coverage * (colour[std::size_t(c)] - background[std::size_t(c)])));
      }
      set(image, x, y, blended);
    }
  }
  return image;
}

std::size_t count_class(const ImageDiff& diff, PixelClass which) {
  return std::size_t(std::count(diff.classes.begin(), diff.classes.end(), which));
}

std::size_t index_of(const ImageDiff& diff, int x, int y) {
  return std::size_t(y) * std::size_t(diff.width) + std::size_t(x);
}

TEST(ImageDiff, IdenticalImages) {
  const render::Image image = soft_disc(40, 30, 20.0, 15.0, 9.0, kWhite, kNavy);
  const ImageDiff diff = diff_images(image, image, {});
  EXPECT_TRUE(diff.same_size);
  EXPECT_EQ(diff.differing_pixels, 0u);
  EXPECT_EQ(diff.antialiased_pixels, 0u);
  EXPECT_EQ(diff.shifted_pixels, 0u);
  EXPECT_EQ(diff.max_distance, 0.0);
  ASSERT_EQ(diff.distance.size(), 40u * 30u);
  ASSERT_EQ(diff.classes.size(), 40u * 30u);
  EXPECT_EQ(count_class(diff, PixelClass::Same), 40u * 30u);
  EXPECT_TRUE(diff.passes({0, 0.0}));
  EXPECT_EQ(diff.summary(), "identical");
}

TEST(ImageDiff, AlphaIsIgnored) {
  const render::Image image = soft_disc(20, 20, 10.0, 10.0, 5.0, kWhite, kNavy);
  render::Image translucent = image;
  for (std::size_t i = 3; i < translucent.rgba.size(); i += 4) translucent.rgba[i] = 17;
  const ImageDiff diff = diff_images(translucent, image, {});
  EXPECT_EQ(diff.summary(), "identical");
}

TEST(ImageDiff, DistanceIsPixelmatchsYiqScale) {
  const Rgb black{0, 0, 0};
  EXPECT_EQ(pixel_distance(kGrey.data(), kGrey.data()), 0.0);
  EXPECT_NEAR(pixel_distance(kRed.data(), kCyan.data()), 1.0, 1e-5);  // the largest there is
  EXPECT_NEAR(pixel_distance(black.data(), kWhite.data()), 0.9659, 1e-4);
  EXPECT_EQ(pixel_distance(black.data(), kWhite.data()), pixel_distance(kWhite.data(), black.data()));
  // pixelmatch: delta = 0.5053 Y^2 for a grey step of 10, against 35215 threshold^2.
  const Rgb lighter{138, 138, 138};
  EXPECT_NEAR(pixel_distance(kGrey.data(), lighter.data()), std::sqrt(0.5053 * 100.0 / 35215.0), 1e-6);
}

TEST(ImageDiff, NoiseBelowTheThresholdPasses) {
  render::Image reference = soft_disc(64, 48, 30.0, 22.0, 15.0, kWhite, kNavy);
  render::Image noisy = reference;
  std::uint32_t state = 7;
  for (std::size_t i = 0; i < noisy.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    state = state * 1664525u + 1013904223u;
    const int delta = int((state >> 8) % 13) - 6;  // +-6 per channel: distance at most 0.041
    noisy.rgba[i] = static_cast<std::uint8_t>(std::clamp(int(noisy.rgba[i]) + delta, 0, 255));
  }
  const ImageDiff diff = diff_images(noisy, reference, {});
  EXPECT_EQ(diff.differing_pixels, 0u);
  EXPECT_EQ(diff.antialiased_pixels + diff.shifted_pixels, 0u);
  const float largest = *std::max_element(diff.distance.begin(), diff.distance.end());
  EXPECT_GT(largest, 0.0f);
  EXPECT_LE(largest, 0.1f);
  EXPECT_EQ(diff.summary(), "0 pixels differ (none over the threshold)");
  EXPECT_TRUE(diff.passes({0, 0.0}));
}

TEST(ImageDiff, AFilledSquareOfAnotherColourFailsWithItsExactCount) {
  const render::Image reference = filled(64, 48, kGrey);
  render::Image actual = reference;
  fill_rect(actual, 20, 10, 30, 20, kRed);  // 10 x 10
  const ImageDiff diff = diff_images(actual, reference, {});
  EXPECT_EQ(diff.differing_pixels, 100u);
  EXPECT_EQ(diff.antialiased_pixels, 0u);
  EXPECT_EQ(diff.shifted_pixels, 0u);
  EXPECT_DOUBLE_EQ(diff.differing_share, 100.0 / (64.0 * 48.0));
  const double expected = pixel_distance(kRed.data(), kGrey.data());
  EXPECT_NEAR(diff.max_distance, expected, 1e-6);
  EXPECT_NEAR(diff.mean_distance, expected, 1e-6);
  EXPECT_EQ(diff.classes[index_of(diff, 20, 10)], PixelClass::Differs);
  EXPECT_EQ(diff.classes[index_of(diff, 19, 10)], PixelClass::Same);
  EXPECT_FALSE(diff.passes({99, 1.0}));
  EXPECT_TRUE(diff.passes({100, 1.0}));
  EXPECT_FALSE(diff.passes({100, 0.03}));  // 3.26% of the pixels
  EXPECT_EQ(diff.summary(), "100 pixels differ (3.26%), largest distance 0.50, mean 0.50");
}

TEST(ImageDiff, AnAntiAliasedEdgeMovedByAFractionOfAPixelIsForgiven) {
  // The same soft disc, its centre 0.35 pixels apart: only the blended edge pixels change.
  const render::Image reference = soft_disc(80, 60, 40.0, 30.0, 20.0, kWhite, kNavy);
  const render::Image actual = soft_disc(80, 60, 40.35, 30.2, 20.0, kWhite, kNavy);
  DiffOptions no_shift;
  no_shift.shift = 0;  // the anti-aliasing rule alone
  const ImageDiff diff = diff_images(actual, reference, no_shift);
  EXPECT_GT(diff.antialiased_pixels, 20u) << diff.summary();
  EXPECT_EQ(diff.differing_pixels, 0u) << diff.summary();
  EXPECT_EQ(diff.shifted_pixels, 0u);
  // Without the rule the same edge fails.
  DiffOptions strict = no_shift;
  strict.forgive_antialiasing = false;
  const ImageDiff unforgiven = diff_images(actual, reference, strict);
  EXPECT_EQ(unforgiven.differing_pixels, diff.antialiased_pixels);
  EXPECT_EQ(unforgiven.antialiased_pixels, 0u);
}

TEST(ImageDiff, AShapeShiftedByOnePixelPasses) {
  const render::Image reference = [] {
    render::Image image = filled(48, 40, kWhite);
    fill_rect(image, 10, 8, 30, 20, kNavy);  // 20 x 12
    return image;
  }();
  render::Image right = filled(48, 40, kWhite);
  fill_rect(right, 11, 8, 31, 20, kNavy);
  const ImageDiff diff = diff_images(right, reference, {});
  EXPECT_EQ(diff.differing_pixels, 0u);
  EXPECT_EQ(diff.shifted_pixels, 24u);  // a column of 12 at either side
  EXPECT_EQ(diff.antialiased_pixels, 0u);
  EXPECT_EQ(diff.classes[index_of(diff, 30, 12)], PixelClass::Shifted);
  EXPECT_EQ(diff.summary(), "0 pixels differ (24 shifted pixels forgiven)");

  render::Image diagonal = filled(48, 40, kWhite);
  fill_rect(diagonal, 9, 9, 29, 21, kNavy);  // one left, one down
  const ImageDiff diagonal_diff = diff_images(diagonal, reference, {});
  EXPECT_EQ(diagonal_diff.differing_pixels, 0u) << diagonal_diff.summary();
  EXPECT_GT(diagonal_diff.shifted_pixels, 0u);

  DiffOptions no_shift;
  no_shift.shift = 0;
  EXPECT_EQ(diff_images(right, reference, no_shift).differing_pixels, 24u);
}

TEST(ImageDiff, AShapeShiftedByTwoPixelsFails) {
  render::Image reference = filled(48, 40, kWhite);
  fill_rect(reference, 10, 8, 30, 20, kNavy);  // columns 10..29, rows 8..19
  render::Image actual = filled(48, 40, kWhite);
  fill_rect(actual, 12, 8, 32, 20, kNavy);
  const ImageDiff diff = diff_images(actual, reference, {});
  // Columns 10, 11, 30 and 31 change in all 12 rows. Only the top and bottom pixels of columns
  // 11 and 30 see both colours within one pixel in the other image.
  EXPECT_EQ(diff.differing_pixels + diff.shifted_pixels, 48u);
  EXPECT_EQ(diff.shifted_pixels, 4u);
  EXPECT_EQ(diff.differing_pixels, 44u);
  EXPECT_EQ(diff.classes[index_of(diff, 11, 8)], PixelClass::Shifted);
  EXPECT_EQ(diff.classes[index_of(diff, 11, 12)], PixelClass::Differs);
  EXPECT_EQ(diff.classes[index_of(diff, 31, 12)], PixelClass::Differs);
  EXPECT_FALSE(diff.passes({8, 1.0}));
  // A shift of two is forgiven when two pixels are.
  DiffOptions two;
  two.shift = 2;
  EXPECT_EQ(diff_images(actual, reference, two).differing_pixels, 0u);
}

TEST(ImageDiff, AOnePixelLineThatVanishesIsNeverForgiven) {
  render::Image with_line = filled(40, 30, kWhite);
  fill_rect(with_line, 15, 5, 16, 25, kNavy);  // a vertical line, 20 pixels long
  const render::Image without = filled(40, 30, kWhite);
  const ImageDiff vanished = diff_images(without, with_line, {});
  EXPECT_EQ(vanished.differing_pixels, 20u);
  EXPECT_EQ(vanished.antialiased_pixels, 0u);
  EXPECT_EQ(vanished.shifted_pixels, 0u);
  const ImageDiff appeared = diff_images(with_line, without, {});
  EXPECT_EQ(appeared.differing_pixels, 20u);
  // A horizontal line of grey on grey-blue: the same.
  render::Image horizontal = filled(40, 30, kGrey);
  fill_rect(horizontal, 3, 12, 37, 13, kNavy);
  EXPECT_EQ(diff_images(filled(40, 30, kGrey), horizontal, {}).differing_pixels, 34u);
  // An anti-aliased line, one pixel wide across two rows (a fifth and four fifths covered): its
  // faint row may pass for an edge between the background and the strong row, the strong row is
  // still counted, every pixel of it.
  render::Image soft_line = filled(40, 30, kWhite);
  const Rgb faint{208, 210, 222};  // a fifth of navy on white
  const Rgb strong{67, 75, 123};   // four fifths
  fill_rect(soft_line, 5, 9, 35, 10, faint);
  fill_rect(soft_line, 5, 10, 35, 11, strong);
  const ImageDiff soft_vanished = diff_images(filled(40, 30, kWhite), soft_line, {});
  EXPECT_GE(soft_vanished.differing_pixels, 30u) << soft_vanished.summary();
  for (int x = 5; x < 35; ++x) EXPECT_EQ(soft_vanished.classes[index_of(soft_vanished, x, 10)], PixelClass::Differs);
  // The same line moved by one pixel is a shift.
  render::Image moved = filled(40, 30, kWhite);
  fill_rect(moved, 16, 5, 17, 25, kNavy);
  const ImageDiff shifted = diff_images(moved, with_line, {});
  EXPECT_EQ(shifted.differing_pixels, 0u);
  EXPECT_EQ(shifted.shifted_pixels, 40u);
}

TEST(ImageDiff, SizeMismatch) {
  const ImageDiff diff = diff_images(filled(320, 240, kGrey), filled(640, 480, kGrey), {});
  EXPECT_FALSE(diff.same_size);
  EXPECT_FALSE(diff.passes({1000000, 1.0}));
  EXPECT_TRUE(diff.distance.empty());
  EXPECT_TRUE(diff.classes.empty());
  EXPECT_EQ(diff.summary(), "the images differ in size (320x240 against 640x480)");
  EXPECT_EQ(diff_images(filled(3, 2, kGrey), filled(2, 3, kGrey), {}).summary(),
            "the images differ in size (3x2 against 2x3)");
}

TEST(ImageDiff, SummaryTexts) {
  ImageDiff diff;
  diff.same_size = true;
  diff.width = 320;
  diff.height = 240;
  diff.differing_pixels = 1204;
  diff.differing_share = 0.0157;
  diff.max_distance = 0.82;
  diff.mean_distance = 0.41;
  EXPECT_EQ(diff.summary(), "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41");
  diff.antialiased_pixels = 37;
  diff.shifted_pixels = 12;
  EXPECT_EQ(diff.summary(),
            "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41; 37 anti-aliased and 12 shifted pixels "
            "forgiven");
  diff.shifted_pixels = 0;
  EXPECT_EQ(diff.summary(),
            "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41; 37 anti-aliased pixels forgiven");
  diff.differing_pixels = 1;
  diff.differing_share = 1.0 / 76800.0;
  diff.antialiased_pixels = 1;
  EXPECT_EQ(diff.summary(),
            "1 pixel differs (<0.01%), largest distance 0.82, mean 0.41; 1 anti-aliased pixel forgiven");
  diff.differing_pixels = 0;
  diff.differing_share = 0.0;
  diff.max_distance = diff.mean_distance = 0.0;
  diff.antialiased_pixels = 37;
  diff.shifted_pixels = 12;
  EXPECT_EQ(diff.summary(), "0 pixels differ (37 anti-aliased and 12 shifted pixels forgiven)");
  diff.antialiased_pixels = 0;
  diff.shifted_pixels = 1;
  EXPECT_EQ(diff.summary(), "0 pixels differ (1 shifted pixel forgiven)");
}

TEST(ImageDiff, GroupedCounts) {
  EXPECT_EQ(grouped_count(0), "0");
  EXPECT_EQ(grouped_count(999), "999");
  EXPECT_EQ(grouped_count(1000), "1,000");
  EXPECT_EQ(grouped_count(76800), "76,800");
  EXPECT_EQ(grouped_count(1234567), "1,234,567");
}

TEST(ImageDiff, HeatMapColours) {
  // Grey reference; a red-against-cyan pixel (distance 1), a pixel just over the threshold, a
  // shifted line and an anti-aliased edge.
  render::Image reference = soft_disc(80, 60, 50.0, 30.0, 12.0, kGrey, kWhite);
  fill_rect(reference, 5, 5, 6, 6, kCyan);
  fill_rect(reference, 10, 10, 11, 40, kNavy);  // a line at column 10
  render::Image actual = soft_disc(80, 60, 50.4, 30.0, 12.0, kGrey, kWhite);
  fill_rect(actual, 5, 5, 6, 6, kRed);
  fill_rect(actual, 11, 10, 12, 40, kNavy);  // moved to column 11
  const Rgb slightly{158, 158, 158};         // a grey step of 30: distance 0.114, just over 0.1
  fill_rect(actual, 20, 50, 21, 51, slightly);
  const Rgb faintly{130, 130, 130};  // a grey step of 2: changed, far under the threshold
  fill_rect(actual, 30, 50, 31, 51, faintly);
  const ImageDiff diff = diff_images(actual, reference, {});
  ASSERT_TRUE(diff.same_size);
  const render::Image map = heat_map(diff, reference);
  ASSERT_EQ(map.width, 80);
  ASSERT_EQ(map.height, 60);

  // Same: v = 40 + luma / 4 = 40 + 128 / 4.
  EXPECT_EQ(rgb_at(map, 0, 0), (Rgb{72, 72, 72}));
  EXPECT_EQ(map.pixel(0, 0)[3], 255);
  // Differs at distance 1: red.
  EXPECT_EQ(diff.classes[index_of(diff, 5, 5)], PixelClass::Differs);
  EXPECT_EQ(rgb_at(map, 5, 5), (Rgb{255, 0, 0}));
  // Differs just over the threshold: nearly yellow.
  ASSERT_EQ(diff.classes[index_of(diff, 20, 50)], PixelClass::Differs);
  const double t = (pixel_distance(kGrey.data(), slightly.data()) - 0.1) / 0.9;
  EXPECT_EQ(rgb_at(map, 20, 50), (Rgb{255, static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - t))), 0}));
  EXPECT_GT(rgb_at(map, 20, 50)[1], 245);
  // Changed under the threshold: violet, so the place shows.
  ASSERT_EQ(diff.classes[index_of(diff, 30, 50)], PixelClass::Same);
  EXPECT_EQ(rgb_at(map, 30, 50), (Rgb{36 + 70, 36, 36 + 110}));
  // Shifted: faint green over the reference's v (the line's old column: navy, luma 33, v 48).
  ASSERT_EQ(diff.classes[index_of(diff, 10, 20)], PixelClass::Shifted);
  EXPECT_EQ(rgb_at(map, 10, 20), (Rgb{24, 160, 24}));
  // Anti-aliased: faint blue; some edge pixel of the disc is one.
  bool found_antialiased = false;
  for (int y = 0; y < 60; ++y) {
    for (int x = 30; x < 80; ++x) {
      if (diff.classes[index_of(diff, x, y)] != PixelClass::AntiAliased) continue;
      found_antialiased = true;
      const std::uint8_t* r = reference.pixel(x, y);
      const int v = 40 + (299 * r[0] + 587 * r[1] + 114 * r[2]) / 1000 / 4;
      EXPECT_EQ(rgb_at(map, x, y), (Rgb{std::uint8_t(v / 2), std::uint8_t(v / 2), 160}));
    }
  }
  EXPECT_TRUE(found_antialiased) << diff.summary();
  // Deterministic.
  EXPECT_EQ(heat_map(diff, reference).rgba, map.rgba);
}

TEST(ImageDiff, BrokenInputIsAPreconditionFailure) {
  if (!kChecked) GTEST_SKIP() << "built without SWEEP_CHECK_PRECONDITIONS (CMake option SWEEP_PRECONDITIONS=OFF)";
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  const render::Image image = filled(4, 3, kGrey);
  render::Image short_of_bytes = image;
  short_of_bytes.rgba.pop_back();
  EXPECT_DEATH(diff_images(short_of_bytes, image, {}),
               "precondition failed: actual's rgba holds width \\* height .* in diff_images");
  EXPECT_DEATH(diff_images(image, short_of_bytes, {}), "precondition failed: reference's rgba holds .* in diff_images");
  DiffOptions options;
  options.threshold = 1.5;
  EXPECT_DEATH(diff_images(image, image, options),
               "precondition failed: 0 <= options.threshold <= 1 .* in diff_images");
  options.threshold = 0.1;
  options.shift = -1;
  EXPECT_DEATH(diff_images(image, image, options), "precondition failed: options.shift >= 0 .* in diff_images");
  const ImageDiff mismatch = diff_images(image, filled(3, 4, kGrey), {});
  EXPECT_DEATH(heat_map(mismatch, image), "precondition failed: diff.same_size .* in heat_map");
  const ImageDiff diff = diff_images(image, image, {});
  EXPECT_DEATH(heat_map(diff, filled(3, 4, kGrey)),
               "precondition failed: reference is diff.width x diff.height .* in heat_map");
}

// Properties. Small random pictures of a few colours with flat areas (so edges, siblings and
// shifts all occur), and a changed copy.

/// A colour drawn evenly from all of them (arbitrary<std::uint8_t> stays near 0 at small sizes).
Rgb random_colour() {
  const auto channel = [] { return static_cast<std::uint8_t>(*rc::gen::inRange(0, 256)); };
  return {channel(), channel(), channel()};
}

/// A w x h picture of up to four colours in random rectangles on a background.
render::Image random_picture(int width, int height) {
  const Rgb palette[] = {random_colour(), random_colour(), random_colour(), random_colour()};
  render::Image image = filled(width, height, palette[0]);
  const int rects = *rc::gen::inRange(0, 6);
  for (int k = 0; k < rects; ++k) {
    const int x0 = *rc::gen::inRange(0, width);
    const int y0 = *rc::gen::inRange(0, height);
    const int x1 = *rc::gen::inRange(x0, width + 1);
    const int y1 = *rc::gen::inRange(y0, height + 1);
    fill_rect(image, x0, y0, x1, y1, palette[*rc::gen::inRange(1, 4)]);
  }
  return image;
}

/// `image` with a few pixels changed at random, and a random rectangle either painted over or
/// copied one pixel over (so shifts and changed edges occur too).
render::Image changed_copy(const render::Image& image) {
  render::Image copy = image;
  const int pixels = *rc::gen::inRange(0, 12);
  for (int k = 0; k < pixels; ++k) {
    set(copy, *rc::gen::inRange(0, image.width), *rc::gen::inRange(0, image.height), random_colour());
  }
  const int x0 = *rc::gen::inRange(0, image.width);
  const int y0 = *rc::gen::inRange(0, image.height);
  const int x1 = *rc::gen::inRange(x0, image.width + 1);
  const int y1 = *rc::gen::inRange(y0, image.height + 1);
  if (*rc::gen::arbitrary<bool>()) {
    fill_rect(copy, x0, y0, x1, y1, random_colour());
  } else {
    const int dx = *rc::gen::inRange(-1, 2);
    const int dy = *rc::gen::inRange(-1, 2);
    for (int y = y0; y < y1; ++y) {
      for (int x = x0; x < x1; ++x) {
        if (x + dx >= 0 && x + dx < image.width && y + dy >= 0 && y + dy < image.height) {
          set(copy, x + dx, y + dy, rgb_at(image, x, y));
        }
      }
    }
  }
  return copy;
}

DiffOptions random_options() {
  DiffOptions options;
  options.threshold = *rc::gen::inRange(0, 31) / 100.0;
  options.forgive_antialiasing = *rc::gen::arbitrary<bool>();
  options.shift = *rc::gen::inRange(0, 3);
  return options;
}

RC_GTEST_PROP(ImageDiffProperty, AnImageAgainstItselfIsIdentical, ()) {
  const render::Image image = random_picture(*rc::gen::inRange(1, 24), *rc::gen::inRange(1, 24));
  const ImageDiff diff = diff_images(image, image, random_options());
  RC_ASSERT(diff.same_size);
  RC_ASSERT(diff.differing_pixels == 0u);
  RC_ASSERT(diff.antialiased_pixels + diff.shifted_pixels == 0u);
  RC_ASSERT(std::all_of(diff.classes.begin(), diff.classes.end(), [](PixelClass c) { return c == PixelClass::Same; }));
  RC_ASSERT(diff.summary() == std::string("identical"));
}

RC_GTEST_PROP(ImageDiffProperty, SwappingTheImagesChangesNoPixelsClass, ()) {
  // The distance, the anti-aliasing rule (either image, siblings in both) and the shift rule
  // (both ways) are each symmetric in the two images.
  const render::Image a = random_picture(*rc::gen::inRange(1, 24), *rc::gen::inRange(1, 24));
  const render::Image b = changed_copy(a);
  const DiffOptions options = random_options();
  const ImageDiff ab = diff_images(a, b, options);
  const ImageDiff ba = diff_images(b, a, options);
  RC_ASSERT(ab.differing_pixels == ba.differing_pixels);
  RC_ASSERT(ab.antialiased_pixels == ba.antialiased_pixels);
  RC_ASSERT(ab.shifted_pixels == ba.shifted_pixels);
  RC_ASSERT(ab.classes == ba.classes);
  RC_ASSERT(ab.distance == ba.distance);
}

RC_GTEST_PROP(ImageDiffProperty, EveryPixelOverTheThresholdIsCountedOnce, ()) {
  const render::Image a = random_picture(*rc::gen::inRange(1, 24), *rc::gen::inRange(1, 24));
  const render::Image b = changed_copy(a);
  const DiffOptions options = random_options();
  const ImageDiff diff = diff_images(b, a, options);
  const auto over = std::size_t(std::count_if(diff.distance.begin(), diff.distance.end(),
                                              [&](float d) { return double(d) > options.threshold + 1e-6; }));
  const std::size_t classified = diff.differing_pixels + diff.antialiased_pixels + diff.shifted_pixels;
  RC_ASSERT(classified >= over);  // a float distance may round down onto the threshold
  RC_ASSERT(count_class(diff, PixelClass::Differs) == diff.differing_pixels);
  RC_ASSERT(count_class(diff, PixelClass::AntiAliased) == diff.antialiased_pixels);
  RC_ASSERT(count_class(diff, PixelClass::Shifted) == diff.shifted_pixels);
  if (!options.forgive_antialiasing) RC_ASSERT(diff.antialiased_pixels == 0u);
  if (options.shift == 0) RC_ASSERT(diff.shifted_pixels == 0u);
}

RC_GTEST_PROP(ImageDiffProperty, ForgivingMoreNeverCountsMore, ()) {
  // A wider shift, the anti-aliasing rule and a higher threshold each only forgive more.
  const render::Image a = random_picture(*rc::gen::inRange(1, 24), *rc::gen::inRange(1, 24));
  const render::Image b = changed_copy(a);
  DiffOptions strict;
  strict.threshold = *rc::gen::inRange(0, 21) / 100.0;
  strict.forgive_antialiasing = false;
  strict.shift = 0;
  DiffOptions looser = strict;
  looser.forgive_antialiasing = true;
  DiffOptions loosest = looser;
  loosest.shift = *rc::gen::inRange(1, 3);
  DiffOptions widest = loosest;
  widest.shift += 1;
  widest.threshold += 0.05;
  const std::size_t counts[] = {diff_images(b, a, strict).differing_pixels, diff_images(b, a, looser).differing_pixels,
                                diff_images(b, a, loosest).differing_pixels,
                                diff_images(b, a, widest).differing_pixels};
  RC_ASSERT(counts[0] >= counts[1]);
  RC_ASSERT(counts[1] >= counts[2]);
  RC_ASSERT(counts[2] >= counts[3]);
}

RC_GTEST_PROP(ImageDiffProperty, ATranslationByOnePixelIsForgiven, ()) {
  // Content inside a flat two-pixel margin, moved by at most one pixel each way: every pixel's
  // colour is one pixel away in the other image, both ways.
  const int width = *rc::gen::inRange(5, 24);
  const int height = *rc::gen::inRange(5, 24);
  const render::Image content = random_picture(width - 4, height - 4);
  const Rgb margin = random_colour();
  const int dx = *rc::gen::inRange(-1, 2);
  const int dy = *rc::gen::inRange(-1, 2);
  render::Image reference = filled(width, height, margin);
  render::Image actual = filled(width, height, margin);
  for (int y = 0; y < content.height; ++y) {
    for (int x = 0; x < content.width; ++x) {
      set(reference, x + 2, y + 2, rgb_at(content, x, y));
      set(actual, x + 2 + dx, y + 2 + dy, rgb_at(content, x, y));
    }
  }
  DiffOptions options;
  options.forgive_antialiasing = *rc::gen::arbitrary<bool>();
  const ImageDiff diff = diff_images(actual, reference, options);
  RC_ASSERT(diff.differing_pixels == 0u);
}

}  // namespace
}  // namespace sweep::snapshot
