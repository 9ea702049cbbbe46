#pragma once
// One snapshot case (a file, a mode, a view, a size and the evaluation options it is rendered
// with, and the limits its comparison uses) and what running it gave. Plain data, no GL: the
// suite reader makes cases, the runner fills results, the reports read them.
#include "snapshot/image_diff.hpp"

#include <glm/vec2.hpp>

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sweep::snapshot {

/// The three display modes of a snapshot: smooth (shaded surfaces and curves), wire (wireframe
/// with normals and curves), frames (curves with their frames and control points, no surfaces).
enum class Mode { Smooth, Wire, Frames };
/// "smooth", "wire", "frames".
const char* name_of(Mode mode);

/// Where the camera looks from. Named views: "default" (sweep render's yaw 30, pitch 20),
/// "front", "top", "side", "iso" (yaw 45, pitch 35.264); yaw/pitch/distance override a named
/// view's angles and the fitted distance.
struct ViewSpec {
  std::string name = "default";
  std::optional<double> yaw;       // degrees
  std::optional<double> pitch;     // degrees
  std::optional<double> distance;  // model units; none: fitted to the scene
  bool operator==(const ViewSpec&) const = default;
};

/// How a case is rendered and compared, besides its file, mode, view and colour: one type for the
/// command line's defaults (CaseDefaults), a suite line's settings (suite_values.hpp) and the case.
/// The values are checked once, by the suite's reading of each key (case_value_problem,
/// suite.hpp), which the command line's options call too.
struct CaseOptions {
  glm::ivec2 size{320, 240};
  double tolerance = 0.0;      // > 0: adaptive sampling (sweep render --tolerance)
  std::string frames = "rmf";  // rmf | projection
  std::string seam = "full";   // full | symmetric | index | none
  double time = 0.0;           // riders drawn where they are at T seconds
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
  ViewSpec view;
  std::string color = "material";  // material | gaussian | mean | normals | uv
  std::string suite_location;      // "snapshots.txt:12" for cases from a suite line, else ""
  std::size_t order = 0;           // its place in the whole suite, before sharding (merged shards keep it)
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
