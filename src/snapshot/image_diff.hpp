#pragma once
// The one image comparison of Sweep: `sweep snapshot` and the project's own golden tests both
// call it (issue 43). A pixel differs when its perceptual colour distance (YIQ, as pixelmatch
// measures it, 0 = same, 1 = the largest distance two colours can have) is above `threshold`; a
// differing pixel is forgiven when it is an anti-aliased edge pixel or when its colour is found
// one pixel away in the other image both ways (a one-pixel shift). What is left is counted
// against the limits.
//
// The rule, step by step (diff_images):
//
// 1. Distance. For the RGB of a pixel in the two images (alpha ignored), with the differences
//    dr, dg, db of the channels (0..255):
//      Y = 0.29889531 dr + 0.58662247 dg + 0.11448223 db
//      I = 0.59597799 dr - 0.27417610 dg - 0.32180189 db
//      Q = 0.21147017 dr - 0.52261711 dg + 0.31114694 db
//      delta = 0.5053 Y^2 + 0.299 I^2 + 0.1957 Q^2
//    (Kotsarenko & Ramos, "Measuring perceived color difference using YIQ NTSC transmission
//    color space in mobile applications", 2010, as pixelmatch computed it up to 7.x), and
//      distance = sqrt(delta / 35215),
//    35215 being the largest delta of two 8-bit colours (red against cyan), pixelmatch's
//    maxDelta. So the distance is 0 exactly when the RGB are equal, 1 for red against cyan,
//    0.966 for black against white, and `threshold` means what pixelmatch's threshold means.
// 2. Differs. A pixel is over the threshold when distance > threshold (delta > 35215 threshold^2).
//    Pixels at or under it are Same.
// 3. Anti-aliased (when forgive_antialiasing). A pixel over the threshold is forgiven as an
//    anti-aliased edge when it looks like one in either image (pixelmatch's antialiased(), after
//    Vysniauskas, "Anti-aliased pixel and intensity slope detector", 2009). In image A, with B the
//    other image, the pixel P is anti-aliased when:
//    - at most 2 of its neighbours (8, fewer on the border) are equal to P in A, equal meaning a
//      luma difference of exactly 0 (below); a pixel on the image's border counts as having one
//      equal neighbour more, so it may have only 1;
//    - among its neighbours in A there is one darker and one brighter than P, by the luma
//      difference 0.29889531 dr + 0.58662247 dg + 0.11448223 db;
//    - the darkest or the brightest of them (on a tie the first found, columns left to right,
//      each top to bottom) has at least 3 neighbours of exactly its own RGB in A and also in B
//      (a pixel on the border counts one more): it lies in a flat area in both images, so P is
//      a blend of the flat colours on the two sides of an edge.
// 4. Shifted (when shift > 0). A pixel P over the threshold that is not anti-aliased is forgiven
//    as shifted when, within `shift` pixels of P (Chebyshev distance, P included, clipped at the
//    border), the reference has a pixel within the threshold of actual[P] AND the actual has a
//    pixel within the threshold of reference[P]. Both ways: a thin line that vanished or
//    appeared has no partner on one side, so it is never forgiven.
// 5. What is left Differs and is counted: differing_pixels, differing_share (of all pixels), the
//    largest and the mean distance of these pixels.
//
// The summary (ImageDiff::summary), counts with commas between thousands and shares in percent
// with two decimals ("<0.01%" for a share above 0 that rounds to 0.00):
//   "the images differ in size (320x240 against 640x480)"   actual first, then reference
//   "identical"                                              every pixel has the same RGB
//   "0 pixels differ (none over the threshold)"              some RGB differ, none over it
//   "0 pixels differ (37 anti-aliased and 12 shifted pixels forgiven)"   all forgiven
//   "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41"      none forgiven
//   "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41; 37 anti-aliased and 12
//    shifted pixels forgiven"                                            (one line)
// A forgiven kind of which there is none is left out ("12 shifted pixels forgiven"); one pixel
// reads "1 pixel differs (<0.01%), ..." and "1 anti-aliased pixel forgiven".
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
  /// The run's two counts of pixels (docs/screenshot-regression.md, "Two counts of pixels"):
  /// differing pixels are over the threshold and not forgiven, the count the limits apply to;
  /// changed pixels are every pixel whose colour changed at all (any distance above 0).
  std::size_t differing_pixels = 0;    // after forgiving
  std::size_t changed_pixels = 0;      // RGB not equal
  double differing_share = 0.0;        // differing_pixels / pixel count
  double max_distance = 0.0;           // largest distance of a differing pixel, in [0, 1]
  double mean_distance = 0.0;          // mean distance of the differing pixels (0 when none)
  std::size_t antialiased_pixels = 0;  // forgiven as anti-aliased edges
  std::size_t shifted_pixels = 0;      // forgiven as a one-pixel shift
  std::vector<float> distance;         // per pixel, rows top to bottom (empty when sizes differ)
  std::vector<PixelClass> classes;     // per pixel
  /// The reference's size, for the size message (the actual's is width x height).
  int reference_width = 0;
  int reference_height = 0;
  double threshold = 0.1;  // DiffOptions::threshold of the comparison (the heat map's scale)

  bool passes(const DiffLimits& limits) const {
    return same_size && differing_pixels <= limits.max_diff_pixels && differing_share <= limits.max_diff_ratio;
  }
  /// "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41" or "the images differ in size
  /// (320x240 against 640x480)" or "identical"; every form is listed at the top of this header.
  std::string summary() const;
};

/// The distance of step 1 above between two RGB pixels (3 bytes each; a fourth is ignored), in
/// [0, 1]. Precondition: a and b point at 3 readable bytes each.
double pixel_distance(const std::uint8_t* a, const std::uint8_t* b);

/// Compares `actual` with `reference` (RGB; alpha ignored) by the rule at the top of this header.
/// Images of different sizes give same_size = false and nothing else. Identical bytes take a
/// fast path; otherwise only the neighbourhoods of pixels over the threshold are examined.
/// Preconditions: each image's rgba holds width * height * 4 bytes, width >= 0, height >= 0;
/// 0 <= options.threshold <= 1; options.shift >= 0.
ImageDiff diff_images(const render::Image& actual, const render::Image& reference, const DiffOptions& options);

/// The heat map, width x height, opaque: each pixel by its class, with v = 40 + L / 4 (L = the
/// reference's luma 0.299 r + 0.587 g + 0.114 b, rounded down; v in 40..103):
///   Same: the reference dimmed to grey (v, v, v), or violet (v / 2 + 70, v / 2, v / 2 + 110)
///     when its colour changed at all but not past the threshold (distance > 0), so a change
///     too faint to count still shows where it is (sweep snapshot fails such changes on objects
///     whose geometry changed);
///   Differs: yellow (255, 255, 0) just over the threshold to red (255, 0, 0) at distance 1, the
///     green channel round(255 (1 - t)) with t = (distance - threshold) / (1 - threshold) clamped
///     to [0, 1] (diff.threshold; t = 1 when the threshold is 1);
///   AntiAliased: faint blue (v / 2, v / 2, 160); Shifted: faint green (v / 2, 160, v / 2).
/// Deterministic: the same diff and reference give the same bytes.
/// Preconditions: diff.same_size; reference is diff.width x diff.height with width * height * 4
/// bytes (the image diff was made against); diff.distance and diff.classes hold one entry per pixel.
render::Image heat_map(const ImageDiff& diff, const render::Image& reference);

/// "1 pixel differs", "1,204 pixels differ": the differing pixels' words everywhere.
std::string pixels_differ(std::size_t count);

/// "1,204": a count with commas between thousands (the summary's and the reports' form).
std::string grouped_count(std::size_t count);

/// How a percentage is spelled: the terminal's "<0.01%" (the default) or, for HTML,
/// {"&lt; ", "&#8201;"} giving "&lt; 0.01&#8201;%".
struct PercentSpelling {
  const char* below = "<";  // before "0.01" when a share above zero rounds to 0.00
  const char* space = "";   // between the number and "%"
};

/// A share from 0 to 1 as a percentage with two decimals ("12.50%"); a share above zero that
/// rounds to 0.00 is "<0.01%", so a difference never reads as none. The one percentage of the
/// summary, the terminal and the reports.
std::string percent(double share, PercentSpelling spelling = {});

}  // namespace sweep::snapshot
