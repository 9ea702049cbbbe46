#pragma once
// Building strings in tests without "literal" + string (which trips GCC 12's false -Wrestrict).
#include <filesystem>
#include <initializer_list>
#include <string>
#include <string_view>

namespace sweep::test {

/// The parts one after another.
inline std::string joined(std::initializer_list<std::string_view> parts) {
  std::string text;
  for (const std::string_view part : parts) text += part;
  return text;
}

/// A path in single quotes, for a shell command line.
inline std::string quoted(const std::filesystem::path& path) {
  std::string text(1, '\'');
  text.append(path.string());
  text.push_back('\'');
  return text;
}

}  // namespace sweep::test
