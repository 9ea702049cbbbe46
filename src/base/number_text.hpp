#pragma once
// Numbers in messages: the shortest text that reads back as the same double.
#include <charconv>
#include <cmath>
#include <string>

namespace sweep {

/// Shortest text that reads back as `value` ("0.5", "1e+12", "nan"), for messages.
inline std::string number_text(double value) {
  if (std::isnan(value)) return "nan";
  if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buf[32];
  const auto result = std::to_chars(buf, buf + sizeof buf, value);
  return std::string(buf, result.ptr);
}

}  // namespace sweep
