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

const char* name_of(NamedView view) {
  switch (view) {
    case NamedView::Default:
      return "default";
    case NamedView::Front:
      return "front";
    case NamedView::Top:
      return "top";
    case NamedView::Side:
      return "side";
    case NamedView::Iso:
      return "iso";
  }
  return "?";
}

const char* name_of(SweepFrames frames) {
  return frames == SweepFrames::Projection ? "projection" : "rmf";
}

const char* name_of(SeamClosing seam) {
  switch (seam) {
    case SeamClosing::Full:
      return "full";
    case SeamClosing::Symmetric:
      return "symmetric";
    case SeamClosing::Index:
      return "index";
    case SeamClosing::None:
      return "none";
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
