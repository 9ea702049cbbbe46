#pragma once
// Pictures: what Document::render makes, PNG files, and the comparison `sweep snapshot` uses.
#include <sweep/version.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

SWEEP_BEGIN_NAMESPACE

/// An RGBA picture, 8 bits a channel, rows top to bottom.
struct SWEEP_API Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes

  /// The PNG file's bytes, RGB: the alpha channel is dropped, since every picture Sweep makes is
  /// opaque. Throws Error for an empty image.
  std::string png() const;
  /// Writes png() to a file (through a temporary file and a rename). Throws Error.
  void save_png(const std::filesystem::path& file) const;
  /// Reads a PNG file (any PNG, as RGBA). Throws Error naming the file and why.
  static Image load_png(const std::filesystem::path& file);
};

/// How two pictures are compared: a pixel differs when its colour distance (pixelmatch's YIQ
/// measure, 0 equal .. 1 farthest) is above `threshold`, unless it is an anti-aliased edge or
/// found one pixel away in the other picture both ways; the pictures match when at most
/// `max_diff_pixels` pixels differ. The rules are docs/screenshot-regression.md's.
struct CompareOptions {
  double threshold = 0.1;
  std::size_t max_diff_pixels = 8;
};

struct Comparison {
  bool same_size = false;
  bool matches = false;
  std::size_t differing_pixels = 0;  // over the threshold, not forgiven: what the limit counts
  std::size_t changed_pixels = 0;    // whose colour changed at all
  double max_distance = 0.0;
  std::string summary;  // "1,204 pixels differ (1.57%), largest distance 0.82, mean 0.41", "identical", ...
};

/// Compares `actual` with `reference` (alpha ignored). Throws Error when either's rgba does not
/// hold width * height * 4 bytes.
SWEEP_API Comparison compare_images(const Image& actual, const Image& reference, const CompareOptions& options = {});

SWEEP_END_NAMESPACE
