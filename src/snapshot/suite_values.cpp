// The suite's values: the names cases are given, the settings a line sets, and each key's
// reading and checking of its value, with the message of what was expected.
#include "snapshot/suite_values.hpp"

#include "base/precondition.hpp"
#include "model/document.hpp"
#include "snapshot/suite_files.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace sweep::snapshot {
namespace {

/// Bytes of a found token shown in a message (printable_excerpt adds "..." when cut).
constexpr std::size_t kShownBytes = 100;

}  // namespace

std::string in_quotes(std::string_view text) {
  std::string out(1, '\'');
  out += printable_excerpt(text, kShownBytes);
  out += '\'';
  return out;
}

namespace {

/// A number as a name shows it: the shortest text that reads back as the value ("10", "2.5").
std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value == 0.0 ? 0.0 : value);
  return {buffer, result.ptr};
}

bool is_name_byte(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '/';
}

}  // namespace

std::string view_part(const ViewSpec& view) {
  std::string part;
  if (view.name != NamedView::Default) part += std::string("-") + name_of(view.name);
  if (view.yaw) part += "-yaw" + shortest(*view.yaw);
  if (view.pitch) part += "-pitch" + shortest(*view.pitch);
  if (view.distance) part += "-distance" + shortest(*view.distance);
  return part;
}

std::string without_extension(const std::string& relative) {
  return relative.substr(0, relative.size() - kSwpExtension.size());
}

bool is_valid_case_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxSuiteNameBytes || name.front() == '/' || name.back() == '/') return false;
  if (name.find("//") != std::string_view::npos) return false;
  return std::all_of(name.begin(), name.end(), is_name_byte);
}

Settings settings_from(const CaseDefaults& defaults) {
  Settings s;
  static_cast<CaseOptions&>(s) = defaults;
  return s;
}

namespace {

ValueResult expected(const std::string& what, std::string_view found, std::size_t offset = 0) {
  return ValueProblem{"expected " + what + ", found " + in_quotes(found), offset};
}

/// A finite decimal number using all of `text` ("2.5", "-10", "1e-3"; no '+', no "inf").
std::optional<double> read_number(std::string_view text) {
  double value = 0.0;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (text.empty() || ec != std::errc() || ptr != end || !std::isfinite(value)) return std::nullopt;
  return value;
}

/// A whole number of decimal digits using all of `text` (no sign).
template <typename Integer>
std::optional<Integer> read_whole(std::string_view text) {
  Integer value{};
  const char* end = text.data() + text.size();
  if (text.empty() || text.front() < '0' || text.front() > '9') return std::nullopt;
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  if (ec != std::errc() || ptr != end) return std::nullopt;
  return value;
}

/// A number in [low, high] (or (low, high] when `open_low`), or none.
std::optional<double> read_in_range(std::string_view text, double low, double high, bool open_low = false) {
  const std::optional<double> value = read_number(text);
  if (!value || *value > high || *value < low || (open_low && *value == low)) return std::nullopt;
  return value;
}

/// Sets `field` to the value named `text` among `values`, or says what was expected.
template <typename Enum, std::size_t N>
ValueResult set_named(Enum& field, const std::array<Enum, N>& values, std::string_view text, const char* what) {
  const std::optional<Enum> value = named(values, text);
  if (!value) return expected(what, text);
  field = *value;
  return std::nullopt;
}

ValueResult set_modes(Settings& s, std::string_view value) {
  std::vector<Mode> modes;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = std::min(value.find(',', start), value.size());
    const std::string_view item = value.substr(start, comma - start);
    const std::optional<Mode> mode = named(kEveryMode, item);
    if (!mode) return expected("a mode (smooth, wire or frames; a list with ',')", item, start);
    if (std::find(modes.begin(), modes.end(), *mode) != modes.end()) {
      return ValueProblem{"mode " + in_quotes(item) + " is given twice", start};
    }
    modes.push_back(*mode);
    if (comma == value.size()) break;
    start = comma + 1;
  }
  s.modes = std::move(modes);
  return std::nullopt;
}

ValueResult set_view(Settings& s, std::string_view value) {
  return set_named(s.view.name, kEveryView, value, "a view (default, front, top, side or iso)");
}

ValueResult set_yaw(Settings& s, std::string_view value) {
  s.view.yaw = read_in_range(value, -360.0, 360.0);
  if (!s.view.yaw) return expected("a yaw in degrees from -360 to 360", value);
  return std::nullopt;
}

ValueResult set_pitch(Settings& s, std::string_view value) {
  s.view.pitch = read_in_range(value, -90.0, 90.0);
  if (!s.view.pitch) return expected("a pitch in degrees from -90 to 90", value);
  return std::nullopt;
}

ValueResult set_distance(Settings& s, std::string_view value) {
  s.view.distance = read_in_range(value, 0.0, 1e12, true);
  if (!s.view.distance) return expected("a distance > 0 and at most 1e12", value);
  return std::nullopt;
}

ValueResult set_color(Settings& s, std::string_view value) {
  return set_named(s.color, render::kColorModes, value, "a color (material, gaussian, mean, normals or uv)");
}

ValueResult set_size(Settings& s, std::string_view value) {
  const std::size_t x = value.find('x');
  const std::optional<int> w = x == std::string_view::npos ? std::nullopt : read_whole<int>(value.substr(0, x));
  const std::optional<int> h = x == std::string_view::npos ? std::nullopt : read_whole<int>(value.substr(x + 1));
  const auto side = [](const std::optional<int>& v) { return v && *v >= 1 && *v <= kMaxSuiteImageSide; };
  if (!side(w) || !side(h)) return expected("a size WxH with sides 1.." + std::to_string(kMaxSuiteImageSide), value);
  s.size = {*w, *h};
  return std::nullopt;
}

ValueResult set_tolerance(Settings& s, std::string_view value) {
  const std::optional<double> tolerance = read_in_range(value, 0.0, 1e12);
  if (!tolerance) return expected("a tolerance >= 0 (0: uniform sampling)", value);
  s.tolerance = *tolerance;
  return std::nullopt;
}

ValueResult set_frames(Settings& s, std::string_view value) {
  return set_named(s.frames, kEveryFrames, value, "frames rmf or projection");
}

ValueResult set_seam(Settings& s, std::string_view value) {
  return set_named(s.seam, kEverySeam, value, "a seam (full, symmetric, index or none)");
}

ValueResult set_time(Settings& s, std::string_view value) {
  const std::optional<double> time = read_in_range(value, 0.0, 1e9);
  if (!time) return expected("a rider time T in seconds from 0 to 1e9", value);
  s.time = *time;
  return std::nullopt;
}

ValueResult set_threshold(Settings& s, std::string_view value) {
  const std::optional<double> threshold = read_in_range(value, 0.0, 1.0);
  if (!threshold) return expected("a threshold from 0 to 1", value);
  s.diff.threshold = *threshold;
  return std::nullopt;
}

ValueResult set_max_diff_pixels(Settings& s, std::string_view value) {
  const std::optional<std::uint64_t> pixels = read_whole<std::uint64_t>(value);
  if (!pixels || *pixels > kMaxSuiteDiffPixels) {
    return expected("a whole number of pixels from 0 to " + std::to_string(kMaxSuiteDiffPixels), value);
  }
  s.limits.max_diff_pixels = static_cast<std::size_t>(*pixels);
  return std::nullopt;
}

ValueResult set_max_diff_ratio(Settings& s, std::string_view value) {
  const std::optional<double> ratio = read_in_range(value, 0.0, 1.0);
  if (!ratio) return expected("a share of the pixels from 0 to 1", value);
  s.limits.max_diff_ratio = *ratio;
  return std::nullopt;
}

ValueResult set_shift(Settings& s, std::string_view value) {
  const std::optional<int> shift = read_whole<int>(value);
  if (!shift || *shift > 3) return expected("a shift of 0 to 3 pixels", value);
  s.diff.shift = *shift;
  return std::nullopt;
}

ValueResult set_antialiasing(Settings& s, std::string_view value) {
  if (value != "on" && value != "off") return expected("antialiasing on or off", value);
  s.diff.forgive_antialiasing = value == "on";
  return std::nullopt;
}

constexpr std::array<Key, 17> kKeys{{{"modes", set_modes},
                                     {"view", set_view},
                                     {"yaw", set_yaw},
                                     {"pitch", set_pitch},
                                     {"distance", set_distance},
                                     {"color", set_color},
                                     {"size", set_size},
                                     {"tolerance", set_tolerance},
                                     {"frames", set_frames},
                                     {"seam", set_seam},
                                     {"T", set_time},
                                     {"threshold", set_threshold},
                                     {"max-diff-pixels", set_max_diff_pixels},
                                     {"max-diff-ratio", set_max_diff_ratio},
                                     {"shift", set_shift},
                                     {"antialiasing", set_antialiasing},
                                     {"name", nullptr}}};

}  // namespace

std::string case_value_problem(std::string_view key, std::string_view value) {
  const Key* found = find_key(key);
  SWEEP_EXPECTS(found != nullptr && found->set != nullptr, "a suite key other than name");
  Settings scratch;
  const ValueResult problem = found->set(scratch, value);
  return problem ? problem->message : std::string();
}

const Key* find_key(std::string_view name) {
  const auto key = std::find_if(kKeys.begin(), kKeys.end(), [&](const Key& k) { return k.name == name; });
  return key == kKeys.end() ? nullptr : &*key;
}

std::string key_list(bool with_name) {
  std::string list;
  for (const Key& key : kKeys) {
    if (key.set == nullptr && !with_name) continue;
    if (!list.empty()) list += ", ";
    list += key.name;
  }
  return list;
}

}  // namespace sweep::snapshot
