#pragma once
// One snapshot case (a file, a mode, a view, a size and the evaluation options it is rendered
// with, and the limits its comparison uses) and what running it gave. Plain data, no GL: the
// suite reader makes cases, the runner fills results, the reports read them.
#include "render/display_settings.hpp"
#include "snapshot/image_diff.hpp"

#include <glm/vec2.hpp>

#include <array>
#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::snapshot {

/// The three display modes of a snapshot: smooth (shaded surfaces and curves), wire (wireframe
/// with normals and curves), frames (curves with their frames and control points, no surfaces).
enum class Mode { Smooth, Wire, Frames };
/// "smooth", "wire", "frames".
const char* name_of(Mode mode);

/// Frames along 3D sweep curves (--frames, frames=): rotation-minimizing or projection.
enum class SweepFrames { Rmf, Projection };
/// "rmf", "projection" (the names evaluation_options reads).
const char* name_of(SweepFrames frames);

/// How a closed sweep's seam is closed (--seam, seam=; evaluation_options says what each does).
enum class SeamClosing { Full, Symmetric, Index, None };
/// "full", "symmetric", "index", "none".
const char* name_of(SeamClosing seam);

/// The named views: "default" (sweep render's yaw 30, pitch 20), "front", "top", "side", "iso"
/// (yaw 45, pitch 35.264).
enum class NamedView { Default, Front, Top, Side, Iso };
/// "default", "front", "top", "side", "iso".
const char* name_of(NamedView view);

inline constexpr std::array<Mode, 3> kEveryMode{Mode::Smooth, Mode::Wire, Mode::Frames};
inline constexpr std::array<NamedView, 5> kEveryView{NamedView::Default, NamedView::Front, NamedView::Top,
                                                     NamedView::Side, NamedView::Iso};
inline constexpr std::array<SweepFrames, 2> kEveryFrames{SweepFrames::Rmf, SweepFrames::Projection};
inline constexpr std::array<SeamClosing, 4> kEverySeam{SeamClosing::Full, SeamClosing::Symmetric, SeamClosing::Index,
                                                       SeamClosing::None};

/// The value among `values` whose name_of is `name` (the suite's, the sidecar's and the results
/// file's one reading of a name), or none.
template <typename Enum, std::size_t N>
std::optional<Enum> named(const std::array<Enum, N>& values, std::string_view name) {
  for (const Enum value : values) {
    if (std::string_view(name_of(value)) == name) return value;
  }
  return std::nullopt;
}

/// Where the camera looks from: a named view, whose angles and fitted distance yaw, pitch and
/// distance override.
struct ViewSpec {
  NamedView name = NamedView::Default;
  std::optional<double> yaw;       // degrees
  std::optional<double> pitch;     // degrees
  std::optional<double> distance;  // model units; none: fitted to the scene
  bool operator==(const ViewSpec&) const = default;
};

/// How a case's picture is made, besides its file and mode: what its sidecar records, and what
/// two sidecars must agree on for their pictures to be compared (same_setup).
struct CaseSetup {
  glm::ivec2 size{320, 240};
  ViewSpec view;
  render::ColorMode color = render::ColorMode::Material;
  double tolerance = 0.0;  // > 0: adaptive sampling (sweep render --tolerance)
  SweepFrames frames = SweepFrames::Rmf;
  SeamClosing seam = SeamClosing::Full;
  double time = 0.0;  // riders drawn where they are at T seconds
  bool operator==(const CaseSetup&) const = default;
};

/// How a case is made and compared: the one type of the command line's defaults (CaseDefaults),
/// a suite line's settings (suite_values.hpp), the case, and (its CaseSetup) the sidecar. Each
/// value is checked once, by the suite's reading of its key (case_value_problem, suite.hpp), which
/// the command line's options call too.
struct CaseOptions : CaseSetup {
  DiffOptions diff;
  DiffLimits limits;
};

struct CaseSpec : CaseOptions {
  /// The reference's stem relative to the references folder, unique in a run:
  /// "sub/bowl-smooth" (the file's path below DIR without .swp, then the view when it is not
  /// the default, then the mode; or the suite line's name= followed by the mode).
  std::string name;
  std::filesystem::path file;      // the SWP file
  std::filesystem::path relative;  // the file's path below DIR (for messages and names)
  Mode mode = Mode::Smooth;
  std::string suite_location;  // "snapshots.txt:12" for cases from a suite line, else ""
  std::size_t order = 0;       // its place in the whole suite, before sharding (merged shards keep it)
};

/// The largest side of a snapshot, for the command line and the suite file alike (a renderer
/// that allocates less is asked before any case renders: run_snapshots).
inline constexpr int kMaxSnapshotSide = 8192;

enum class Status { Pass, Warning, Fail, New, Updated, Error };
inline constexpr std::size_t kStatusCount = 6;
/// "pass", "warning", "FAIL", "new", "updated", "error".
const char* name_of(Status status);

/// What one named object did between the reference and now (attribution.hpp).
struct ObjectChange {
  std::string object;
  std::string text;  // "bowl: 1,204 px differ; its mesh moved up to 0.031 (bounding box +0.03 in y)"
  bool changed = false;
};

/// One accepted reference of a case and the renderer its sidecar names ("" when unknown).
struct AcceptedReference {
  std::string file;  // "bowl-smooth_1.png"
  std::string renderer;
  bool operator==(const AcceptedReference&) const = default;
};

struct CaseResult {
  CaseSpec spec;
  Status status = Status::Error;
  /// One line: why it failed or errored, what was written, or which reference matched.
  std::string message;
  /// The comparison with the reference that matched (or came closest); absent for new and error.
  std::optional<ImageDiff> diff;
  std::string matched_reference;            // file name of the accepted reference compared ("bowl-smooth_1.png")
  std::vector<AcceptedReference> accepted;  // the case's accepted references, NAME.png first
  bool other_renderer = false;              // the reference came from another renderer: thresholds, never bit-exact
  /// The pictures differ by more than the limits, but only as two renderers do: the reference is
  /// from another renderer (none from this one), and every object's fingerprint and material,
  /// the camera and the case's options are those of the reference (a warning; --strict-renderer
  /// fails it).
  bool renderer_difference = false;
  std::string renderer;               // the renderer of this run's picture
  std::vector<ObjectChange> changes;  // attribution, failures and warnings only
  /// Images for the HTML report, relative to the report folder; empty when not written.
  std::string reference_image;
  std::string actual_image;
  std::string diff_image;
  double seconds = 0.0;         // render and compare time of this case
  double render_seconds = 0.0;  // of which the picture alone (OSMesa)
};

}  // namespace sweep::snapshot
