#include "snapshot/suite.hpp"

#include "base/fnv1a.hpp"
#include "base/precondition.hpp"
#include "model/document.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <system_error>
#include <utility>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kSwpExtension = ".swp";
constexpr std::string_view kReferencesFolder = "__snapshots__";
constexpr std::array<Mode, 3> kEveryMode{Mode::Smooth, Mode::Wire, Mode::Frames};
/// Bytes of a found token shown in a message (printable_excerpt adds "..." when cut).
constexpr std::size_t kShownBytes = 100;

bool is_hidden(std::string_view name) {
  return !name.empty() && name.front() == '.';
}

bool ends_with_swp(std::string_view name) {
  return name.size() >= kSwpExtension.size() && name.substr(name.size() - kSwpExtension.size()) == kSwpExtension;
}

/// "'text'", cut and with control bytes escaped (the SWP reader's `describe`).
std::string in_quotes(std::string_view text) {
  std::string out(1, '\'');
  out += printable_excerpt(text, kShownBytes);
  out += '\'';
  return out;
}

// ---- Folders ---------------------------------------------------------------------------------

/// One visible entry of a folder: hidden entries and __snapshots__ folders are left out, symlinks
/// are followed (a dangling one is left out).
struct Entry {
  std::string name;
  bool folder = false;
  bool file = false;
};

/// The visible entries of `folder` sorted by name; none when it cannot be read.
std::vector<Entry> visible_entries(const fs::path& folder) {
  std::vector<Entry> entries;
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  for (const fs::directory_iterator end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (is_hidden(name)) continue;
    std::error_code status_ec;
    const fs::file_status status = it->status(status_ec);
    if (status_ec) continue;
    const bool is_folder = fs::is_directory(status);
    if (is_folder && name == kReferencesFolder) continue;
    entries.push_back({std::move(name), is_folder, fs::is_regular_file(status)});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return entries;
}

/// Whether `folder` is entered for the first time: the walks enter each real folder once (by its
/// canonical path), so a symlinked folder never leads into a loop and the work stays bounded.
template <typename Key>
bool first_visit(std::set<std::pair<Key, fs::path>>& seen, const Key& key, const fs::path& folder) {
  std::error_code ec;
  fs::path real = fs::canonical(folder, ec);
  if (ec) return false;
  return seen.insert({key, std::move(real)}).second;
}

/// Every .swp file below `folder` (relative paths with '/', prefixed by `prefix`) into `out`.
void collect_swp_files(const fs::path& folder, const std::string& prefix, std::set<std::pair<int, fs::path>>& seen,
                       std::set<std::string>& out) {
  for (const Entry& entry : visible_entries(folder)) {
    if (entry.folder) {
      if (first_visit(seen, 0, folder / entry.name)) {
        collect_swp_files(folder / entry.name, prefix + entry.name + "/", seen, out);
      }
    } else if (entry.file && ends_with_swp(entry.name)) {
      out.insert(prefix + entry.name);
    }
  }
}

// ---- Globs -----------------------------------------------------------------------------------

bool has_wildcard(std::string_view segment) {
  return segment.find_first_of("*?") != std::string_view::npos;
}

/// Whether `name` matches `pattern`, where '*' is any run of bytes and '?' any one byte (the
/// greedy match with one backtrack point: O(size of name × size of pattern) at worst).
bool wildcard_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0;
  std::size_t star = std::string_view::npos, star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_n;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

/// The files a path pattern matches below the suite's folder: the segments of the pattern ('/'
/// between them), each literal, a wildcard segment ('*' and '?' within it, never matching a
/// hidden name or __snapshots__) or "**" (any number of visible folders).
class GlobWalk {
 public:
  GlobWalk(std::vector<std::string> segments, std::size_t limit) : segments_(std::move(segments)), limit_(limit) {}

  /// The matches below `root`, sorted; stops once more than the limit are found.
  const std::set<std::string>& run(const fs::path& root) {
    walk(root, "", 0);
    return matches_;
  }
  bool over_limit() const { return matches_.size() > limit_; }

 private:
  void walk(const fs::path& folder, const std::string& prefix, std::size_t i) {
    if (over_limit() || !first_visit(seen_, i, folder)) return;
    const std::string& segment = segments_[i];
    const bool last = i + 1 == segments_.size();
    if (segment == "**") {
      walk(folder, prefix, i + 1);  // no folder
      for (const Entry& entry : visible_entries(folder)) {
        if (entry.folder) walk(folder / entry.name, prefix + entry.name + "/", i);
      }
    } else if (!has_wildcard(segment)) {
      std::error_code ec;
      const fs::file_status status = fs::status(folder / segment, ec);
      if (ec) return;
      if (last && fs::is_regular_file(status)) add(prefix + segment);
      if (!last && fs::is_directory(status)) walk(folder / segment, prefix + segment + "/", i + 1);
    } else {
      for (const Entry& entry : visible_entries(folder)) {
        if (!wildcard_match(segment, entry.name)) continue;
        if (last && entry.file) add(prefix + entry.name);
        if (!last && entry.folder) walk(folder / entry.name, prefix + entry.name + "/", i + 1);
      }
    }
  }
  void add(std::string relative) {
    if (!over_limit()) matches_.insert(std::move(relative));
  }

  std::vector<std::string> segments_;
  std::size_t limit_;
  std::set<std::string> matches_;
  std::set<std::pair<std::size_t, fs::path>> seen_;  // (segment, real folder) pairs walked
};

// ---- Names -----------------------------------------------------------------------------------

/// A number as a name shows it: the shortest text that reads back as the value ("10", "2.5").
std::string shortest(double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value == 0.0 ? 0.0 : value);
  return {buffer, result.ptr};
}

/// "-iso", "-yaw10-pitch30", "-front-distance12", or "" for the default view.
std::string view_part(const ViewSpec& view) {
  std::string part;
  if (view.name != "default") part += "-" + view.name;
  if (view.yaw) part += "-yaw" + shortest(*view.yaw);
  if (view.pitch) part += "-pitch" + shortest(*view.pitch);
  if (view.distance) part += "-distance" + shortest(*view.distance);
  return part;
}

std::string without_extension(const std::string& relative) {
  return relative.substr(0, relative.size() - kSwpExtension.size());
}

bool is_name_byte(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '/';
}

bool is_valid_case_name(std::string_view name) {
  if (name.empty() || name.size() > kMaxSuiteNameBytes || name.front() == '/' || name.back() == '/') return false;
  if (name.find("//") != std::string_view::npos) return false;
  return std::all_of(name.begin(), name.end(), is_name_byte);
}

// ---- Values ----------------------------------------------------------------------------------

/// Everything a suite line sets but its name; the defaults lines change the suite's copy.
struct Settings {
  std::vector<Mode> modes{kEveryMode.begin(), kEveryMode.end()};
  ViewSpec view;
  std::string color = "material";
  glm::ivec2 size{320, 240};
  double tolerance = 0.0;
  std::string frames = "rmf";
  std::string seam = "full";
  double time = 0.0;
  DiffOptions diff;
  DiffLimits limits;
};

Settings settings_from(const CaseDefaults& defaults) {
  Settings s;
  s.size = defaults.size;
  s.tolerance = defaults.tolerance;
  s.frames = defaults.frames;
  s.seam = defaults.seam;
  s.time = defaults.time;
  s.diff = defaults.diff;
  s.limits = defaults.limits;
  return s;
}

/// What is wrong with a value: the message and where in the value it starts (a list's item).
struct ValueProblem {
  std::string message;
  std::size_t offset = 0;
};
using ValueResult = std::optional<ValueProblem>;

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

/// Whether `text` is one of `words`.
template <std::size_t N>
bool is_one_of(std::string_view text, const std::array<std::string_view, N>& words) {
  return std::find(words.begin(), words.end(), text) != words.end();
}

constexpr std::array<std::string_view, 5> kViews{"default", "front", "top", "side", "iso"};
constexpr std::array<std::string_view, 5> kColors{"material", "gaussian", "mean", "normals", "uv"};
constexpr std::array<std::string_view, 2> kFrames{"rmf", "projection"};
constexpr std::array<std::string_view, 4> kSeams{"full", "symmetric", "index", "none"};

ValueResult set_modes(Settings& s, std::string_view value) {
  std::vector<Mode> modes;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = std::min(value.find(',', start), value.size());
    const std::string_view item = value.substr(start, comma - start);
    const auto mode = std::find_if(kEveryMode.begin(), kEveryMode.end(), [&](Mode m) { return item == name_of(m); });
    if (mode == kEveryMode.end()) return expected("a mode (smooth, wire or frames; a list with ',')", item, start);
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
  if (!is_one_of(value, kViews)) return expected("a view (default, front, top, side or iso)", value);
  s.view.name = std::string(value);
  return std::nullopt;
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
  if (!is_one_of(value, kColors)) return expected("a color (material, gaussian, mean, normals or uv)", value);
  s.color = std::string(value);
  return std::nullopt;
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
  if (!is_one_of(value, kFrames)) return expected("frames rmf or projection", value);
  s.frames = std::string(value);
  return std::nullopt;
}

ValueResult set_seam(Settings& s, std::string_view value) {
  if (!is_one_of(value, kSeams)) return expected("a seam (full, symmetric, index or none)", value);
  s.seam = std::string(value);
  return std::nullopt;
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

struct Key {
  std::string_view name;
  ValueResult (*set)(Settings&, std::string_view);  // null for name=, which a line keeps itself
};

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

/// "modes, view, ..., name" (without name on a defaults line).
std::string key_list(bool with_name) {
  std::string list;
  for (const Key& key : kKeys) {
    if (key.set == nullptr && !with_name) continue;
    if (!list.empty()) list += ", ";
    list += key.name;
  }
  return list;
}

// ---- Lines -----------------------------------------------------------------------------------

struct Token {
  std::string_view text;  // a quoted path without its quotes
  int column = 0;         // of its first byte (a quoted path's opening quote)
  bool quoted = false;
};

/// A line's name= value and its column.
struct LineName {
  std::string_view text;
  int column = 0;
};

class SuiteParser {
 public:
  SuiteParser(const fs::path& suite, const fs::path& dir, const CaseDefaults& defaults)
      : suite_(suite.string()), dir_(dir), defaults_(settings_from(defaults)) {}

  std::vector<CaseSpec> parse(std::string_view text) {
    if (text.size() > kMaxSuiteBytes) fail(1, 1, too_big(text.size()));
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);  // a UTF-8 byte order mark
    int line_number = 0;
    while (!text.empty()) {
      ++line_number;
      const std::size_t newline = std::min(text.find('\n'), text.size());
      std::string_view line = text.substr(0, newline);
      text.remove_prefix(std::min(newline + 1, text.size()));
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      if (line.size() > kMaxSuiteLineBytes) {
        fail(line_number, static_cast<int>(kMaxSuiteLineBytes) + 1,
             "expected a line of at most " + std::to_string(kMaxSuiteLineBytes) + " bytes, found " +
                 std::to_string(line.size()) + " bytes");
      }
      read_line(line, line_number);
    }
    return std::move(cases_);
  }

  static std::string too_big(std::uintmax_t bytes) {
    return "expected a suite of at most 1 MiB (" + std::to_string(kMaxSuiteBytes) + " bytes), found " +
           std::to_string(bytes) + " bytes";
  }

 private:
  [[noreturn]] void fail(int line, int column, const std::string& message) const {
    throw SuiteError(suite_ + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message);
  }

  /// The line's tokens: the first may be a double-quoted path, the rest end at a space, a tab
  /// or '#' (a comment to the end of the line).
  std::vector<Token> tokens_of(std::string_view line, int line_number) const {
    std::vector<Token> tokens;
    std::size_t i = 0;
    const auto column = [](std::size_t at) { return static_cast<int>(at) + 1; };
    while (i < line.size()) {
      const char c = line[i];
      if (c == ' ' || c == '\t') {
        ++i;
      } else if (c == '#') {
        break;
      } else if (c == '"' && tokens.empty()) {
        const std::size_t close = line.find('"', i + 1);
        if (close == std::string_view::npos) {
          check_printable(line.substr(i + 1), i + 1, line_number);
          fail(line_number, column(line.size()), "expected '\"' to end the quoted path, found the end of the line");
        }
        check_printable(line.substr(i + 1, close - i - 1), i + 1, line_number);
        if (close + 1 < line.size() && line[close + 1] != ' ' && line[close + 1] != '\t' && line[close + 1] != '#') {
          const std::size_t end = std::min(line.find_first_of(" \t#", close + 1), line.size());
          fail(line_number, column(close + 1),
               "expected a space after the quoted path, found " + in_quotes(line.substr(close + 1, end - close - 1)));
        }
        tokens.push_back({line.substr(i + 1, close - i - 1), column(i), true});
        i = close + 1;
      } else {
        const std::size_t end = std::min(line.find_first_of(" \t#", i), line.size());
        check_printable(line.substr(i, end - i), i, line_number);
        tokens.push_back({line.substr(i, end - i), column(i), false});
        i = end;
      }
    }
    return tokens;
  }

  /// Control bytes (but tab) are refused: a path with a NUL or a newline in it would name
  /// another file than the one shown.
  void check_printable(std::string_view text, std::size_t start, int line_number) const {
    for (std::size_t i = 0; i < text.size(); ++i) {
      const auto c = static_cast<unsigned char>(text[i]);
      if (c < 0x20 || c == 0x7f) {
        fail(line_number, static_cast<int>(start + i) + 1,
             "expected printable text, found " + in_quotes(text.substr(i, 1)));
      }
    }
  }

  void read_line(std::string_view line, int line_number) {
    const std::vector<Token> tokens = tokens_of(line, line_number);
    if (tokens.empty()) return;
    if (tokens.front().text == "defaults" && !tokens.front().quoted) {
      std::optional<LineName> name;
      read_keys(tokens, line_number, defaults_, name, false);
      return;
    }
    const Token& path = tokens.front();
    const std::vector<std::string> segments = path_segments(path, line_number);
    // The files first (the path is the line's first token), then the keys in order.
    const std::size_t room = kMaxSuiteCases - cases_.size();
    GlobWalk walk(segments, room);
    const std::set<std::string>& files = walk.run(dir_);
    if (walk.over_limit()) fail(line_number, path.column, too_many_cases());
    if (files.empty()) fail(line_number, path.column, "no .swp file matches " + in_quotes(path.text));

    Settings settings = defaults_;
    std::optional<LineName> name;
    read_keys(tokens, line_number, settings, name, true);
    if (name && files.size() > 1) {
      fail(line_number, name->column,
           "name= needs a path of one file, but " + in_quotes(path.text) + " matches " + std::to_string(files.size()));
    }
    if (files.size() * settings.modes.size() > room) fail(line_number, path.column, too_many_cases());

    const std::string location = suite_ + ":" + std::to_string(line_number);
    for (const std::string& relative : files) {
      const std::string stem = name ? std::string(name->text) : without_extension(relative) + view_part(settings.view);
      for (const Mode mode : settings.modes) {
        std::string case_name = stem + "-" + name_of(mode);
        const auto [made, inserted] = made_by_.emplace(case_name, line_number);
        if (!inserted) {
          fail(line_number, path.column,
               "case " + in_quotes(case_name) + " is already made by line " + std::to_string(made->second) +
                   (name ? "; give this line another name=" : "; give this line a name="));
        }
        cases_.push_back(make_case(settings, std::move(case_name), relative, mode, location));
      }
    }
  }

  std::string too_many_cases() const {
    return "expected a suite of at most " + std::to_string(kMaxSuiteCases) + " cases, found more by this line";
  }

  /// The path's segments ("." and empty ones dropped, runs of "**" made one), or the error.
  std::vector<std::string> path_segments(const Token& path, int line_number) const {
    if (!ends_with_swp(path.text)) {
      fail(line_number, path.column,
           "expected a .swp file, a glob of .swp files or 'defaults', found " + in_quotes(path.text));
    }
    if (path.text.front() == '/') {
      fail(line_number, path.column, "expected a path relative to the suite's folder, found " + in_quotes(path.text));
    }
    std::vector<std::string> segments;
    std::size_t start = 0;
    while (start <= path.text.size()) {
      const std::size_t slash = std::min(path.text.find('/', start), path.text.size());
      const std::string_view segment = path.text.substr(start, slash - start);
      start = slash + 1;
      if (segment.empty() || segment == ".") continue;
      if (segment == "..") {
        fail(line_number, path.column,
             "expected a path below the suite's folder (no '..'), found " + in_quotes(path.text));
      }
      if (segment == "**" && !segments.empty() && segments.back() == "**") continue;
      segments.emplace_back(segment);
    }
    return segments;
  }

  /// Reads the key=value tokens after the first into `settings` (and name= into `name`).
  void read_keys(const std::vector<Token>& tokens, int line_number, Settings& settings, std::optional<LineName>& name,
                 bool case_line) const {
    std::map<std::string_view, int> given;  // key: its column
    for (std::size_t t = 1; t < tokens.size(); ++t) {
      const Token& token = tokens[t];
      const std::size_t equals = token.text.find('=');
      if (equals == std::string_view::npos || equals == 0) {
        fail(line_number, token.column, "expected key=value (no spaces around '='), found " + in_quotes(token.text));
      }
      const std::string_view key_name = token.text.substr(0, equals);
      const std::string_view value = token.text.substr(equals + 1);
      const int value_column = token.column + static_cast<int>(equals) + 1;
      const auto key = std::find_if(kKeys.begin(), kKeys.end(), [&](const Key& k) { return k.name == key_name; });
      if (key == kKeys.end()) {
        fail(line_number, token.column, "unknown key " + in_quotes(key_name) + " (keys: " + key_list(case_line) + ")");
      }
      if (key->set == nullptr && !case_line) {
        fail(line_number, token.column, "'name' cannot be a default (keys: " + key_list(false) + ")");
      }
      if (const auto [before, inserted] = given.emplace(key->name, token.column); !inserted) {
        fail(line_number, token.column,
             "key " + in_quotes(key->name) + " is already given at column " + std::to_string(before->second));
      }
      if (key->set == nullptr) {
        if (!is_valid_case_name(value)) {
          fail(line_number, value_column,
               "expected a name of letters, digits, '-', '_' and '/' (at most " + std::to_string(kMaxSuiteNameBytes) +
                   " bytes, no '/' first, last or twice), found " + in_quotes(value));
        }
        name = LineName{value, token.column};
      } else if (const ValueResult problem = key->set(settings, value)) {
        fail(line_number, value_column + static_cast<int>(problem->offset), problem->message);
      }
    }
  }

  CaseSpec make_case(const Settings& s, std::string name, const std::string& relative, Mode mode,
                     const std::string& location) const {
    CaseSpec c;
    c.name = std::move(name);
    c.relative = fs::path(relative);
    c.file = dir_ / c.relative;
    c.mode = mode;
    c.view = s.view;
    c.color = s.color;
    c.size = s.size;
    c.tolerance = s.tolerance;
    c.frames = s.frames;
    c.seam = s.seam;
    c.time = s.time;
    c.diff = s.diff;
    c.limits = s.limits;
    c.suite_location = location;
    return c;
  }

  std::string suite_;
  fs::path dir_;
  Settings defaults_;
  std::vector<CaseSpec> cases_;
  std::map<std::string, int> made_by_;  // case name: the line that made it
};

}  // namespace

std::vector<CaseSpec> cases_in_folder(const fs::path& dir, const CaseDefaults& defaults) {
  std::set<std::string> files;
  std::set<std::pair<int, fs::path>> seen;
  if (first_visit(seen, 0, dir)) collect_swp_files(dir, "", seen, files);
  const Settings settings = settings_from(defaults);
  std::vector<CaseSpec> cases;
  cases.reserve(files.size() * kEveryMode.size());
  for (const std::string& relative : files) {
    for (const Mode mode : kEveryMode) {
      CaseSpec c;
      c.name = without_extension(relative) + "-" + name_of(mode);
      c.relative = fs::path(relative);
      c.file = dir / c.relative;
      c.mode = mode;
      c.size = settings.size;
      c.tolerance = settings.tolerance;
      c.frames = settings.frames;
      c.seam = settings.seam;
      c.time = settings.time;
      c.diff = settings.diff;
      c.limits = settings.limits;
      cases.push_back(std::move(c));
    }
  }
  return cases;
}

std::vector<CaseSpec> read_suite(const fs::path& suite, const fs::path& dir, const CaseDefaults& defaults) {
  std::error_code ec;
  if (fs::is_directory(suite, ec)) throw SuiteError(suite.string() + ": cannot read: it is a folder");
  // A regular file over the cap is refused before it is read.
  if (const std::uintmax_t size = fs::file_size(suite, ec); !ec && size > kMaxSuiteBytes) {
    throw SuiteError(suite.string() + ":1:1: " + SuiteParser::too_big(size));
  }
  std::FILE* file = std::fopen(suite.c_str(), "rb");
  if (file == nullptr) {
    throw SuiteError(suite.string() + ": cannot read: " + std::generic_category().message(errno));
  }
  std::string text(kMaxSuiteBytes + 1, '\0');  // one byte over, so a longer stream is refused too
  const std::size_t read = std::fread(text.data(), 1, text.size(), file);
  const int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error != 0) throw SuiteError(suite.string() + ": cannot read: " + std::generic_category().message(error));
  text.resize(read);
  return parse_suite(text, suite, dir, defaults);
}

std::vector<CaseSpec> parse_suite(const std::string& text, const fs::path& suite, const fs::path& dir,
                                  const CaseDefaults& defaults) {
  return SuiteParser(suite, dir, defaults).parse(text);
}

std::uint64_t case_name_hash(std::string_view name) {
  return fnv1a(name);
}

std::vector<CaseSpec> shard(const std::vector<CaseSpec>& cases, int k, int n) {
  SWEEP_EXPECTS(1 <= k && k <= n, "1 <= k <= n");
  std::vector<CaseSpec> part;
  for (const CaseSpec& c : cases) {
    if (case_name_hash(c.name) % static_cast<std::uint64_t>(n) == static_cast<std::uint64_t>(k - 1)) part.push_back(c);
  }
  return part;
}

}  // namespace sweep::snapshot
