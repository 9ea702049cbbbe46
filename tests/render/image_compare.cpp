#include "image_compare.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>

namespace sweep::test {
namespace {

int pixel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  int largest = 0;
  for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
  return largest;
}

}  // namespace

std::string Comparison::summary() const {
  if (!same_size) return "the images differ in size";
  char text[160];
  std::snprintf(text, sizeof text, "max channel difference %d, %.3f%% of pixels differ (%zu)", max_channel_difference,
                100.0 * differing_share, differing_pixels);
  return text;
}

Comparison compare_images(const render::Image& actual, const render::Image& expected, const Tolerance& tolerance) {
  Comparison result;
  result.same_size = actual.width == expected.width && actual.height == expected.height && !actual.empty();
  if (!result.same_size) return result;
  for (int y = 0; y < actual.height; ++y) {
    for (int x = 0; x < actual.width; ++x) {
      const int difference = pixel_difference(actual.pixel(x, y), expected.pixel(x, y));
      result.max_channel_difference = std::max(result.max_channel_difference, difference);
      if (difference > tolerance.channel_threshold) ++result.differing_pixels;
    }
  }
  result.differing_share = double(result.differing_pixels) / (double(actual.width) * double(actual.height));
  return result;
}

render::Image difference_image(const render::Image& actual, const render::Image& expected, const Tolerance& tolerance) {
  render::Image out = expected;
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      const std::uint8_t* e = expected.pixel(x, y);
      const int difference = pixel_difference(actual.pixel(x, y), e);
      std::uint8_t* o = out.pixel(x, y);
      const auto grey = static_cast<std::uint8_t>((int(e[0]) + int(e[1]) + int(e[2])) / 9);
      if (difference > tolerance.channel_threshold) {
        o[0] = static_cast<std::uint8_t>(std::min(255, 128 + difference));
        o[1] = o[2] = 0;
      } else {
        o[0] = o[1] = o[2] = grey;
      }
      o[3] = 255;
    }
  }
  return out;
}

}  // namespace sweep::test
