#pragma once
// A reference's sidecar (NAME.json beside NAME.png): what Sweep knew when it rendered it. The
// renderer, the case's options, the camera the picture was taken with (later runs render with
// it, not with a new fit, so a changed model does not re-frame the picture), and per named
// object its fingerprint and coverage, with the object-id map (run-length coded) that says which
// object each pixel showed.
#include "render/camera.hpp"
#include "snapshot/fingerprint.hpp"
#include "snapshot/object_ids.hpp"
#include "snapshot/snapshot_case.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::snapshot {

struct Sidecar {
  std::string sweep_version;
  std::string renderer;  // the GL renderer string ("llvmpipe (LLVM 15.0.6, 256 bits)", ...)
  Mode mode = Mode::Smooth;
  CaseSetup setup;  // the case's size, view, colour, tolerance, frames, seam and time
  render::Camera camera;
  std::vector<Fingerprint> objects;
  IdMap ids;  // 0: background; k + 1: objects[k]
};

/// The sidecar of `spec` rendered by `renderer` with `camera`.
Sidecar make_sidecar(const CaseSpec& spec, const std::string& renderer, const render::Camera& camera,
                     std::vector<Fingerprint> objects, IdMap ids);

/// Whether both pictures were set up alike: the mode, the case's setup and the camera (sidecars
/// keep numbers exactly).
bool same_setup(const Sidecar& a, const Sidecar& b);

/// Pretty JSON (numbers printed so they read back exactly).
std::string sidecar_json(const Sidecar& sidecar);

class SidecarError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Reads sidecar JSON; throws SidecarError ("not JSON: ..." or "expected FIELD ...").
Sidecar parse_sidecar(const std::string& text);
/// Reads FILE; throws SidecarError naming it.
Sidecar read_sidecar(const std::filesystem::path& file);

}  // namespace sweep::snapshot
