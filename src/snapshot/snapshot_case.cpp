#include "snapshot/snapshot_case.hpp"

namespace sweep::snapshot {

const char* name_of(Mode mode) {
  switch (mode) {
    case Mode::Smooth:
      return "smooth";
    case Mode::Wire:
      return "wire";
    case Mode::Frames:
      return "frames";
  }
  return "?";
}

const char* name_of(Status status) {
  switch (status) {
    case Status::Pass:
      return "pass";
    case Status::Warning:
      return "warning";
    case Status::Fail:
      return "FAIL";
    case Status::New:
      return "new";
    case Status::Updated:
      return "updated";
    case Status::Error:
      return "error";
  }
  return "?";
}

}  // namespace sweep::snapshot
