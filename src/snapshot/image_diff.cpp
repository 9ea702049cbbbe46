#include "snapshot/image_diff.hpp"

#include "base/precondition.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace sweep::snapshot {
namespace {

/// The largest YIQ delta of two 8-bit colours (red against cyan): pixelmatch's maxDelta.
constexpr double kMaxYiqDelta = 35215.0;

/// Kotsarenko & Ramos, "Measuring perceived color difference using YIQ NTSC transmission color
/// space in mobile applications" (2010), with pixelmatch's coefficients: the weighted squared
/// difference in YIQ of two RGB pixels.
double yiq_delta(const std::uint8_t* a, const std::uint8_t* b) {
  const double dr = double(a[0]) - double(b[0]);
  const double dg = double(a[1]) - double(b[1]);
  const double db = double(a[2]) - double(b[2]);
  const double y = dr * 0.29889531 + dg * 0.58662247 + db * 0.11448223;
  const double i = dr * 0.59597799 - dg * 0.27417610 - db * 0.32180189;
  const double q = dr * 0.21147017 - dg * 0.52261711 + db * 0.31114694;
  return 0.5053 * y * y + 0.299 * i * i + 0.1957 * q * q;
}

/// luma(a) - luma(b), the Y of YIQ: the anti-aliasing detector's brightness step.
double luma_difference(const std::uint8_t* a, const std::uint8_t* b) {
  if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) return 0.0;
  return (double(a[0]) - double(b[0])) * 0.29889531 + (double(a[1]) - double(b[1])) * 0.58662247 +
         (double(a[2]) - double(b[2])) * 0.11448223;
}

bool same_rgb(const std::uint8_t* a, const std::uint8_t* b) {
  return a[0] == b[0] && a[1] == b[1] && a[2] == b[2];
}

// Only the preconditions call it, which Release builds compile out.
[[maybe_unused]] bool holds_its_pixels(const render::Image& image) {
  return image.width >= 0 && image.height >= 0 &&
         image.rgba.size() == static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4;
}

/// The pixels within `radius` of (x, y) (Chebyshev distance), clipped to the image.
struct Window {
  int x0, y0, x1, y1;
};

Window window_around(int x, int y, int width, int height, int radius) {
  return {std::max(x - radius, 0), std::max(y - radius, 0), std::min(x + radius, width - 1),
          std::min(y + radius, height - 1)};
}

bool on_border(int x, int y, int width, int height) {
  return x == 0 || y == 0 || x == width - 1 || y == height - 1;
}

/// pixelmatch's hasManySiblings: at least 3 of the 8 neighbours have exactly this pixel's RGB, a
/// pixel on the border counting one more.
bool has_many_siblings(const render::Image& image, int x, int y) {
  const Window w = window_around(x, y, image.width, image.height, 1);
  const std::uint8_t* centre = image.pixel(x, y);
  int equal = on_border(x, y, image.width, image.height) ? 1 : 0;
  for (int nx = w.x0; nx <= w.x1; ++nx) {
    for (int ny = w.y0; ny <= w.y1; ++ny) {
      if (nx == x && ny == y) continue;
      if (same_rgb(centre, image.pixel(nx, ny)) && ++equal > 2) return true;
    }
  }
  return false;
}

/// pixelmatch's antialiased(), after Vysniauskas, "Anti-aliased pixel and intensity slope
/// detector" (2009): (x, y) of `image` is a blend between two flat areas, which `a` and `b`
/// (both images) must agree are flat. The scan order (columns, then rows) decides ties as
/// pixelmatch does.
bool antialiased(const render::Image& image, int x, int y, const render::Image& a, const render::Image& b) {
  const Window w = window_around(x, y, image.width, image.height, 1);
  const std::uint8_t* centre = image.pixel(x, y);
  int equal = on_border(x, y, image.width, image.height) ? 1 : 0;
  double darkest = 0.0;  // most negative luma(centre) - luma(neighbour)
  double brightest = 0.0;
  int darkest_x = 0, darkest_y = 0, brightest_x = 0, brightest_y = 0;
  for (int nx = w.x0; nx <= w.x1; ++nx) {
    for (int ny = w.y0; ny <= w.y1; ++ny) {
      if (nx == x && ny == y) continue;
      const double step = luma_difference(centre, image.pixel(nx, ny));
      if (step == 0.0) {
        if (++equal > 2) return false;  // a flat area, not an edge
      } else if (step < darkest) {
        darkest = step;
        darkest_x = nx;
        darkest_y = ny;
      } else if (step > brightest) {
        brightest = step;
        brightest_x = nx;
        brightest_y = ny;
      }
    }
  }
  if (darkest == 0.0 || brightest == 0.0) return false;  // not between a darker and a brighter side
  return (has_many_siblings(a, darkest_x, darkest_y) && has_many_siblings(b, darkest_x, darkest_y)) ||
         (has_many_siblings(a, brightest_x, brightest_y) && has_many_siblings(b, brightest_x, brightest_y));
}

/// Whether `image` has a pixel within the threshold of `colour` within `radius` of (x, y).
bool found_near(const std::uint8_t* colour, const render::Image& image, int x, int y, int radius, double max_delta) {
  const Window w = window_around(x, y, image.width, image.height, radius);
  for (int ny = w.y0; ny <= w.y1; ++ny) {
    for (int nx = w.x0; nx <= w.x1; ++nx) {
      const std::uint8_t* other = image.pixel(nx, ny);
      if (same_rgb(colour, other) || yiq_delta(colour, other) <= max_delta) return true;
    }
  }
  return false;
}

std::string two_decimals(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", value);
  return text;
}

/// "37 anti-aliased and 12 shifted pixels forgiven", leaving out a kind with none.
std::string forgiven_text(std::size_t antialiased_pixels, std::size_t shifted_pixels) {
  std::string text;
  if (antialiased_pixels > 0) text = grouped_count(antialiased_pixels) + " anti-aliased";
  if (shifted_pixels > 0) {
    if (!text.empty()) text += " and ";
    text += grouped_count(shifted_pixels) + " shifted";
  }
  return text + (antialiased_pixels + shifted_pixels == 1 ? " pixel forgiven" : " pixels forgiven");
}

std::string size_text(int width, int height) {
  return std::to_string(width) + "x" + std::to_string(height);
}

}  // namespace

std::string percent(double share, PercentSpelling spelling) {
  if (share > 0.0 && 100.0 * share < 0.005) return std::string(spelling.below) + "0.01" + spelling.space + "%";
  return two_decimals(100.0 * share) + spelling.space + "%";
}

std::string grouped_count(std::size_t count) {
  const std::string digits = std::to_string(count);
  std::string text;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

std::string pixels_differ(std::size_t count) {
  return grouped_count(count) + (count == 1 ? " pixel differs" : " pixels differ");
}

double pixel_distance(const std::uint8_t* a, const std::uint8_t* b) {
  SWEEP_EXPECTS(a != nullptr && b != nullptr, "a and b point at 3 readable bytes each");
  return std::min(1.0, std::sqrt(yiq_delta(a, b) / kMaxYiqDelta));
}

std::string ImageDiff::summary() const {
  if (!same_size) {
    return "the images differ in size (" + size_text(width, height) + " against " +
           size_text(reference_width, reference_height) + ")";
  }
  if (differing_pixels == 0 && antialiased_pixels == 0 && shifted_pixels == 0) {
    return changed_pixels > 0 ? "0 pixels differ (none over the threshold)" : "identical";
  }
  if (differing_pixels == 0) return "0 pixels differ (" + forgiven_text(antialiased_pixels, shifted_pixels) + ")";
  std::string text = pixels_differ(differing_pixels) + " (" + percent(differing_share) + "), largest distance " +
                     two_decimals(max_distance) + ", mean " + two_decimals(mean_distance);
  if (antialiased_pixels + shifted_pixels > 0) text += "; " + forgiven_text(antialiased_pixels, shifted_pixels);
  return text;
}

ImageDiff diff_images(const render::Image& actual, const render::Image& reference, const DiffOptions& options) {
  SWEEP_EXPECTS(holds_its_pixels(actual), "actual's rgba holds width * height * 4 bytes, width and height >= 0");
  SWEEP_EXPECTS(holds_its_pixels(reference), "reference's rgba holds width * height * 4 bytes, width and height >= 0");
  SWEEP_EXPECTS(options.threshold >= 0.0 && options.threshold <= 1.0, "0 <= options.threshold <= 1");
  SWEEP_EXPECTS(options.shift >= 0, "options.shift >= 0");
  ImageDiff diff;
  diff.width = actual.width;
  diff.height = actual.height;
  diff.reference_width = reference.width;
  diff.reference_height = reference.height;
  diff.threshold = options.threshold;
  diff.same_size = actual.width == reference.width && actual.height == reference.height;
  if (!diff.same_size) return diff;

  const std::size_t count = static_cast<std::size_t>(actual.width) * static_cast<std::size_t>(actual.height);
  diff.distance.assign(count, 0.0f);
  diff.classes.assign(count, PixelClass::Same);
  if (count == 0 || std::memcmp(actual.rgba.data(), reference.rgba.data(), count * 4) == 0) return diff;

  // One pass over the pixels: distances, and the few over the threshold to look at closer.
  const double max_delta = kMaxYiqDelta * options.threshold * options.threshold;
  std::vector<std::size_t> over;
  const std::uint8_t* a = actual.rgba.data();
  const std::uint8_t* r = reference.rgba.data();
  for (std::size_t i = 0; i < count; ++i, a += 4, r += 4) {
    if (same_rgb(a, r)) continue;
    ++diff.changed_pixels;
    const double delta = yiq_delta(a, r);
    diff.distance[i] = static_cast<float>(std::min(1.0, std::sqrt(delta / kMaxYiqDelta)));
    if (delta > max_delta) over.push_back(i);
  }

  double distance_sum = 0.0;
  for (const std::size_t i : over) {
    const int x = static_cast<int>(i % static_cast<std::size_t>(actual.width));
    const int y = static_cast<int>(i / static_cast<std::size_t>(actual.width));
    if (options.forgive_antialiasing &&
        (antialiased(actual, x, y, actual, reference) || antialiased(reference, x, y, reference, actual))) {
      diff.classes[i] = PixelClass::AntiAliased;
      ++diff.antialiased_pixels;
    } else if (options.shift > 0 && found_near(actual.pixel(x, y), reference, x, y, options.shift, max_delta) &&
               found_near(reference.pixel(x, y), actual, x, y, options.shift, max_delta)) {
      diff.classes[i] = PixelClass::Shifted;
      ++diff.shifted_pixels;
    } else {
      diff.classes[i] = PixelClass::Differs;
      ++diff.differing_pixels;
      diff.max_distance = std::max(diff.max_distance, double(diff.distance[i]));
      distance_sum += double(diff.distance[i]);
    }
  }
  diff.differing_share = double(diff.differing_pixels) / double(count);
  if (diff.differing_pixels > 0) diff.mean_distance = distance_sum / double(diff.differing_pixels);
  return diff;
}

render::Image heat_map(const ImageDiff& diff, const render::Image& reference) {
  SWEEP_EXPECTS(diff.same_size, "diff.same_size");
  SWEEP_EXPECTS(reference.width == diff.width && reference.height == diff.height && holds_its_pixels(reference),
                "reference is diff.width x diff.height with width * height * 4 bytes");
  const std::size_t count = static_cast<std::size_t>(diff.width) * static_cast<std::size_t>(diff.height);
  SWEEP_EXPECTS(diff.distance.size() == count && diff.classes.size() == count,
                "diff.distance and diff.classes hold one entry per pixel");
  render::Image out;
  out.width = diff.width;
  out.height = diff.height;
  out.rgba.resize(count * 4);
  const double span = 1.0 - diff.threshold;
  for (std::size_t i = 0; i < count; ++i) {
    const std::uint8_t* ref = &reference.rgba[i * 4];
    std::uint8_t* o = &out.rgba[i * 4];
    const int luma = (299 * int(ref[0]) + 587 * int(ref[1]) + 114 * int(ref[2])) / 1000;
    const auto v = static_cast<std::uint8_t>(40 + luma / 4);
    const auto half = static_cast<std::uint8_t>(v / 2);
    switch (diff.classes[i]) {
      case PixelClass::Same:
        if (diff.distance[i] > 0.0f) {  // changed, under the threshold
          o[0] = static_cast<std::uint8_t>(half + 70);
          o[1] = half;
          o[2] = static_cast<std::uint8_t>(half + 110);
        } else {
          o[0] = o[1] = o[2] = v;
        }
        break;
      case PixelClass::Differs: {
        const double t = span > 0.0 ? std::clamp((double(diff.distance[i]) - diff.threshold) / span, 0.0, 1.0) : 1.0;
        o[0] = 255;
        o[1] = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - t)));
        o[2] = 0;
        break;
      }
      case PixelClass::AntiAliased:
        o[0] = o[1] = half;
        o[2] = 160;
        break;
      case PixelClass::Shifted:
        o[0] = o[2] = half;
        o[1] = 160;
        break;
    }
    o[3] = 255;
  }
  return out;
}

}  // namespace sweep::snapshot
