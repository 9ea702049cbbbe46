#pragma once
// sweep::Error: what every function of the public API throws for bad input or a failed write.
#include <sweep/version.hpp>

#include <stdexcept>
#include <string>

SWEEP_BEGIN_NAMESPACE

/// A problem the user can act on. what() is one line, "FILE:LINE:COLUMN: message" when it is
/// about a place in an SWP file (file(), line() and column() then say where; both counted from
/// 1), otherwise the message alone (line() and column() are 0; file() names the file when the
/// problem is one, such as "FILE: cannot open: REASON").
class SWEEP_API Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message, std::string file = {}, int line = 0, int column = 0);
  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  int column() const noexcept { return column_; }

 private:
  std::string file_;
  int line_ = 0;
  int column_ = 0;
};

SWEEP_END_NAMESPACE
