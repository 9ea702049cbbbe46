#pragma once
// The suite's values (internal to src/snapshot: suite.cpp): what a suite line sets besides its
// name, each key's reading of its value with the message of what it expected, and the names cases
// are given.
#include "snapshot/suite.hpp"

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::snapshot {

/// Everything a suite line sets but its name; the defaults lines change the suite's copy.
struct Settings : CaseOptions {
  std::vector<Mode> modes{kEveryMode.begin(), kEveryMode.end()};
};

/// The settings of a suite without defaults lines: the command line's `defaults`.
Settings settings_from(const CaseDefaults& defaults);

/// What is wrong with a value: the message and where in the value it starts (a list's item).
struct ValueProblem {
  std::string message;
  std::size_t offset = 0;
};
using ValueResult = std::optional<ValueProblem>;

/// A suite key: its name and how it sets its value (null for name=, which a line keeps itself).
struct Key {
  std::string_view name;
  ValueResult (*set)(Settings&, std::string_view);  // null for name=, which a line keeps itself
};

/// The key named `name`, or null.
const Key* find_key(std::string_view name);
/// "modes, view, ..., name" (without name on a defaults line).
std::string key_list(bool with_name);

/// "'text'", cut and with control bytes escaped (the SWP reader's `describe`).
std::string in_quotes(std::string_view text);
/// "-iso", "-yaw10-pitch30", "-front-distance12", or "" for the default view.
std::string view_part(const ViewSpec& view);
/// A relative .swp path without ".swp".
std::string without_extension(const std::string& relative);
/// Letters, digits, '-', '_' and '/' (not first, last or twice), at most kMaxSuiteNameBytes.
bool is_valid_case_name(std::string_view name);

}  // namespace sweep::snapshot
