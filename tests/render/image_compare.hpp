#pragma once
// Tolerant image comparison for the golden tests: rasterizer noise passes, a flipped normal, a
// missing draw mode or a moved object does not.
#include "render/image.hpp"

#include <cstddef>
#include <string>

namespace sweep::test {

struct Tolerance {
  /// A pixel differs when one of its channels differs by more than this (0..255).
  int channel_threshold = 40;
  /// The comparison passes when at most this share of all pixels differs.
  double max_differing_share = 0.003;
};

struct Comparison {
  bool same_size = false;
  int max_channel_difference = 0;  // largest |actual - expected| over all channels
  std::size_t differing_pixels = 0;
  double differing_share = 0.0;  // differing_pixels / pixel count

  bool passes(const Tolerance& tolerance) const {
    return same_size && differing_share <= tolerance.max_differing_share;
  }
  /// "max channel difference 12, 0.041% of pixels differ (32 of 76800)".
  std::string summary() const;
};

/// Compares two images pixel by pixel (RGB; alpha is ignored).
Comparison compare_images(const render::Image& actual, const render::Image& expected, const Tolerance& tolerance);

/// A picture of the differences: the expected image dimmed to grey, differing pixels in red
/// (brighter for larger differences). Precondition: same size.
render::Image difference_image(const render::Image& actual, const render::Image& expected, const Tolerance& tolerance);

}  // namespace sweep::test
