#include <sweep/error.hpp>
#include <sweep/version.hpp>

// The small parts of the public API: its error type and the version the library was built as.

namespace sweep::v0 {

Error::Error(const std::string& message, std::string file, int line, int column)
    : std::runtime_error(message), file_(std::move(file)), line_(line), column_(column) {}

Version version() {
  return {SWEEP_VERSION_MAJOR, SWEEP_VERSION_MINOR, SWEEP_VERSION_PATCH};
}

}  // namespace sweep::v0
