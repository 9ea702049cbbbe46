#pragma once
// Helpers shared by the document-driven tests: the starter files, edits that must fail, error
// messages; and the geometry helpers (geometry_test_support.hpp).
#include "io/swp/read.hpp"
#include "model/document.hpp"
#include "model/edit/edit.hpp"
#include "support/geometry_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sweep::test {

/// Runs an edit that must fail; checks that the document did not change and returns the message.
inline std::string edit_error(Document& doc, const std::function<void()>& edit) {
  const Document before = doc;
  try {
    edit();
  } catch (const EditError& e) {
    EXPECT_EQ(doc, before) << "the failed edit changed the document";
    return e.what();
  }
  ADD_FAILURE() << "no EditError";
  return {};
}

/// Every *.swp file in `folder` (not below it), sorted.
inline std::vector<std::filesystem::path> swp_files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().extension() == ".swp") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

/// Every *.swp file in swp/, sorted, so a new starter file is covered without touching the tests.
inline std::vector<std::filesystem::path> starter_files() {
  return swp_files_in(SWEEP_SWP_DIR);
}

/// Every *.swp file in swp/artifacts/ (the README's showcase models), sorted.
inline std::vector<std::filesystem::path> artifact_files() {
  return swp_files_in(std::filesystem::path(SWEEP_SWP_DIR) / "artifacts");
}

/// The message parsing `text` as `file` throws; "no error" if it parses.
inline std::string error_of(const std::string& text, const std::string& file = "bad.swp") {
  try {
    (void)io::parse_swp(text, file);
  } catch (const io::ParseError& e) {
    return e.what();
  }
  return "no error";
}

/// Expects parsing `text` as `file` to throw a ParseError at LINE:COLUMN whose message is exactly
/// "FILE:LINE:COLUMN: " + detail, and whose file(), line(), column() and detail() say the same.
inline void expect_error(const std::string& text, int line, int column, const std::string& detail,
                         const std::string& file = "bad.swp") {
  try {
    (void)io::parse_swp(text, file);
  } catch (const io::ParseError& e) {
    EXPECT_EQ(std::string(e.what()), file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + detail)
        << text;
    EXPECT_EQ(e.line(), line) << text;
    EXPECT_EQ(e.column(), column) << text;
    EXPECT_EQ(e.file(), file) << text;
    EXPECT_EQ(e.detail(), detail) << text;
    return;
  }
  ADD_FAILURE() << "no ParseError for: " << text;
}

/// The starter file swp/NAME, parsed.
inline Document load_starter(const char* name) {
  return io::load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / name);
}

}  // namespace sweep::test
