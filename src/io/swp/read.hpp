#pragma once
// Reading SWP text into a Document. Every problem is one ParseError naming file:line:column,
// what was expected and what was found; nothing is half-built.
#include "model/document.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sweep::io {

class ParseError : public std::runtime_error {
 public:
  ParseError(std::string file, int line, int column, std::string detail);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  int column() const { return column_; }
  /// The message without the "file:line:column: " prefix.
  const std::string& detail() const { return detail_; }

 private:
  std::string file_;
  int line_;
  int column_;
  std::string detail_;
};

/// Parses SWP text. `file_name` is used in messages and to find the images materials name (in
/// its folder). Throws ParseError. Checks counts, references and the caps in core/limits.hpp
/// (including the mesh size of every surface) so that evaluating the result never exceeds them.
/// An image that is not there is no error: it is listed, with its warning, in
/// Document::missing_images.
Document parse_swp(std::string_view text, std::string_view file_name = "<input>");

/// parse_swp, keeping `text` in the document (Document::source) so that saving it writes back
/// every token an edit did not change as it was (save_swp_file).
Document parse_swp_keeping_source(std::string text, std::string_view file_name = "<input>");

/// Reads and parses a file, keeping its text (parse_swp_keeping_source). Throws ParseError (an
/// unreadable file is reported at line 0).
Document load_swp_file(const std::filesystem::path& path);

/// Checks a document built or edited in memory against the same rules as the parser
/// (references backwards, counts, caps). Throws ParseError naming the object's location.
void validate_document(const Document& doc, std::string_view file_name = "<document>");

}  // namespace sweep::io
