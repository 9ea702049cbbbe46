// The suite file's reader (its lines: paths, globs, defaults and keys), the cases of a folder
// without a suite, and sharding. The files it finds are suite_files' and the values its keys set
// suite_values'.
#include "snapshot/suite.hpp"

#include "base/fnv1a.hpp"
#include "base/precondition.hpp"
#include "model/document.hpp"
#include "snapshot/suite_files.hpp"
#include "snapshot/suite_values.hpp"

#include <algorithm>
#include <array>
#include <cerrno>
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
      const Key* key = find_key(key_name);
      if (key == nullptr) {
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
    static_cast<CaseOptions&>(c) = s;
    c.name = std::move(name);
    c.relative = fs::path(relative);
    c.file = dir_ / c.relative;
    c.mode = mode;
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
  const std::set<std::string> files = swp_files_below(dir);
  std::vector<CaseSpec> cases;
  cases.reserve(files.size() * kEveryMode.size());
  for (const std::string& relative : files) {
    for (const Mode mode : kEveryMode) {
      CaseSpec c;
      static_cast<CaseOptions&>(c) = defaults;
      c.name = without_extension(relative) + "-" + name_of(mode);
      c.relative = fs::path(relative);
      c.file = dir / c.relative;
      c.mode = mode;
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
