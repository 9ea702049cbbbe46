#pragma once
// The one image comparison of Sweep: `sweep snapshot` and the project's own golden tests both
// call it (issue 43). A pixel differs when its perceptual colour distance (YIQ, as pixelmatch
// measures it, 0 = same, 1 = black against white) is above `threshold`; a differing pixel is
// forgiven when it is an anti-aliased edge pixel or when its colour is found one pixel away in
// the other image both ways (a one-pixel shift). What is left is counted against the limits.
#include "render/image.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace sweep::snapshot {

struct DiffOptions {
  /// Per-pixel colour distance above which a pixel differs, in [0, 1] (pixelmatch's threshold).
  double threshold = 0.1;
  /// Forgive anti-aliased edge pixels (see diff_images for the rule).
  bool forgive_antialiasing = true;
  /// Forgive a pixel whose colour is found this many pixels away in the other image, both ways
  /// (0: no shift is forgiven).
  int shift = 1;
};

/// How much may differ after the forgiving: a case passes when both hold.
struct DiffLimits {
  std::size_t max_diff_pixels = 8;
  /// Share of all pixels, in [0, 1].
  double max_diff_ratio = 1.0;
};

/// What each pixel turned out to be, for the heat map and the report.
enum class PixelClass : std::uint8_t { Same, Differs, AntiAliased, Shifted };

struct ImageDiff {
  bool same_size = false;
  int width = 0;
  int height = 0;
  std::size_t differing_pixels = 0;  // after forgiving
  double differing_share = 0.0;      // differing_pixels / pixel count
  double max_distance = 0.0;         // largest distance of a differing pixel, in [0, 1]
  double mean_distance = 0.0;        // mean distance of the differing pixels (0 when none)
  std::size_t antialiased_pixels = 0;  // forgiven as anti-aliased edges
  std::size_t shifted_pixels = 0;      // forgiven as a one-pixel shift
  std::vector<float> distance;         // per pixel, rows top to bottom (empty when sizes differ)
  std::vector<PixelClass> classes;     // per pixel

  bool passes(const DiffLimits& limits) const {
    return same_size && differing_pixels <= limits.max_diff_pixels && differing_share <= limits.max_diff_ratio;
  }
  /// "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41" or "the images differ in size
  /// (320x240 against 640x480)" or "identical".
  std::string summary() const;
};

/// Compares `actual` with `reference` (RGB; alpha ignored).
ImageDiff diff_images(const render::Image& actual, const render::Image& reference, const DiffOptions& options);

/// The heat map: the reference dimmed to grey, differing pixels from yellow (just over the
/// threshold) to red (most different), forgiven pixels faint (anti-aliased blue, shifted green).
/// Precondition: diff.same_size and reference is the image diff was made against.
render::Image heat_map(const ImageDiff& diff, const render::Image& reference);

}  // namespace sweep::snapshot
