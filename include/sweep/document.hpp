#pragma once
// sweep::Document: an SWP document, evaluated. Load it from a file or a string, read its objects
// and their geometry as views (geometry.hpp), evaluate a curve where you like, edit it as the
// viewer does (every edit undoable), save it keeping the file's own text, export its surfaces,
// render it headless.
//
// Lifetimes: a Document owns its state and is movable, not copyable. The views it hands out
// (SurfaceMesh, CurveView) keep the evaluated geometry they show alive on their own.
// Threads: one Document is used by one thread at a time; different Documents may be used on
// different threads at once. render() makes one offscreen OpenGL context per thread (OSMesa,
// software) on its first call there and keeps it for that thread's later calls.
#include <sweep/error.hpp>
#include <sweep/geometry.hpp>
#include <sweep/image.hpp>
#include <sweep/version.hpp>

#include <array>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

SWEEP_BEGIN_NAMESPACE

namespace detail {
struct DocumentState;
}

/// What an object is: "curve" (bez2, bsp3, circ, ...), "surface" (srev, gcyl, subd, ...),
/// "material" or "rider".
struct ObjectInfo {
  std::string name;      // its name, or "KIND#INDEX" when unnamed
  std::string kind;      // its SWP keyword
  std::string category;  // "curve", "surface", "material" or "rider"
  int points = 0;        // editable control points (0 for kinds without)
};

/// How a document is evaluated: the options `sweep render` and `sweep export` take.
struct EvaluationOptions {
  std::string frames = "rmf";  // 3D curves' frames: "rmf" (rotation-minimizing) or "projection"
  std::string seam = "full";   // how tubes along closed curves close: full, symmetric, index, none
  double tolerance = 0.0;      // > 0: sample adaptively within this distance; 0: by STEPS
  bool uvs = false;            // texture coordinates on every surface (else only textured ones)
};

/// What a picture shows: "smooth" (shaded surfaces and curves), "wire" (wireframe with normals
/// and curves) or "frames" (curves with their frames and control points), the colouring
/// ("material", "gaussian", "mean", "normals", "uv"), and the view: yaw and pitch in degrees
/// about the scene, fitted to it, as `sweep render` does.
struct RenderOptions {
  std::string mode = "smooth";
  std::string color = "material";
  double yaw = 30.0;
  double pitch = 20.0;
};

/// The formats of export_surfaces. ThreeMf (since 0.2): one PREFIX.3mf of the whole model for
/// a slicer, in millimetres, z up, standing on the plate (docs/printing.md).
enum class ExportFormat { Obj, Stl, Glb, ThreeMf };

/// How a print export (ThreeMf, Stl) sizes the model and what its checks accept, as `sweep
/// export --height MM [--merge] [--min-wall MM]` (since 0.2).
struct PrintOptions {
  double height_mm = 0.0;    // > 0: the model scaled to this height; 0: 1 model unit = 1 mm
  bool merge = false;        // Stl: one PREFIX.stl of the whole model, placed as 3MF places it
  double min_wall_mm = 0.8;  // walls thinner than this as printed are warned of (> 0)
};

/// One finding of the printability checks (check_print, since 0.2), as `sweep check` prints it.
struct PrintFinding {
  /// "open", "non-manifold", "orientation", "self-intersection", "intersection" (crossing an
  /// open surface), "overlap" (two closed ones: a note), "thin-wall" or "floating".
  std::string check;
  std::string object;             // the surface it names
  std::string other;              // the other surface of an intersection or overlap, else ""
  int line = 0;                   // the surface's line in the file
  std::string message;            // "FILE:LINE:COLUMN: warning: surface 'NAME' is open: ..."
  std::array<double, 3> where{};  // where it is, in model coordinates
  bool fails = true;              // false for an overlap's note
};

class SWEEP_API Document {
 public:
  /// Reads and evaluates an SWP file. Throws Error: "FILE:LINE:COLUMN: message" for bad input
  /// (line() and column() say where), "FILE: cannot open: REASON" when it cannot be read (file()
  /// names it, line() and column() are 0).
  static Document load(const std::filesystem::path& file, const EvaluationOptions& options = {});
  /// The same from text; `name` stands for the file in messages, and relative image paths of
  /// materials are found beside it.
  static Document parse(std::string_view text, std::string_view name = "<string>",
                        const EvaluationOptions& options = {});

  Document(Document&&) noexcept;
  Document& operator=(Document&&) noexcept;
  ~Document();

  /// Every object in file order.
  std::vector<ObjectInfo> objects() const;
  /// Every surface's mesh, in file order. Constant time per surface: no array is copied.
  std::vector<SurfaceMesh> surfaces() const;
  /// Every curve's samples, in file order.
  std::vector<CurveView> curves() const;
  /// The surface or curve named `name`. Throws Error when there is none of that name.
  SurfaceMesh surface(std::string_view name) const;
  CurveView curve(std::string_view name) const;

  /// The range of curve `name`'s parameter: 0..pieces for control-point curves (piece i spans
  /// i..i+1), 0..1 for a circle or a torus knot, 0..turns for a helix.
  std::pair<double, double> curve_range(std::string_view name) const;
  /// Curve `name` evaluated at `parameters` (ascending, each within curve_range: Error if not;
  /// one beyond an end by rounding, within 1e-9 of the range's size, counts as the end),
  /// with its frames carried from one parameter to the next as the document's evaluation does.
  CurveFrames evaluate_curve(std::string_view name, std::span<const double> parameters) const;

  /// Only the positions of curve `name` at `parameters` (any order, each within curve_range as
  /// evaluate_curve takes them):
  /// x, y, z per parameter. Faster than evaluate_curve (no frames), on every core.
  std::vector<double> curve_points(std::string_view name, std::span<const double> parameters) const;

  /// Control point `point` of `object` (x, y, z; z = 0 for planar curves).
  std::array<double, 3> point(std::string_view object, int point) const;
  /// Moves control point `point` of `object` (z is ignored for planar curves); a closed curve's
  /// seam point moves with its partner. One undoable step. Throws Error and changes nothing for a
  /// bad name or index, or a position the surfaces using the curve would refuse.
  void move_point(std::string_view object, int point, const std::array<double, 3>& position);
  /// Sets a number of `object`: "steps" (or "levels" of a subd), "radius", and the curve
  /// parameters as the file spells them ("alpha", "tension", "continuity", "bias", "pitch",
  /// "turns", "R", "P", "Q", "tolerance"). One undoable step; Error for an unknown field or a value
  /// out of range, and nothing changes.
  void set_field(std::string_view object, std::string_view field, double value);
  /// Undoes or redoes one step; false when there is none.
  bool undo();
  bool redo();
  bool can_undo() const;
  bool can_redo() const;
  /// True when an edit since loading or saving is not saved.
  bool modified() const;

  /// The SWP text of the document: for a document read from a file, the file's text with only
  /// the edited numbers changed (spacing, comments and the numbers' decimals kept).
  std::string text() const;
  /// Writes text() to `file` through a temporary file and a rename (a failed write leaves the
  /// old file). Throws Error.
  void save(const std::filesystem::path& file);

  /// Writes every named surface as PREFIX_NAME.obj (with its .mtl), .stl or .glb, or the whole
  /// model as PREFIX.3mf, as `sweep export` does; returns the files written. Throws Error.
  std::vector<std::filesystem::path> export_surfaces(const std::filesystem::path& prefix,
                                                     ExportFormat format = ExportFormat::Obj) const;
  /// The same with the print options of a ThreeMf or Stl export (ignored for the others); the
  /// printability findings are what check_print(print) returns (since 0.2).
  std::vector<std::filesystem::path> export_surfaces(const std::filesystem::path& prefix, ExportFormat format,
                                                     const PrintOptions& print) const;

  /// The printability checks of a 3MF export at `print`'s size, writing nothing, as `sweep
  /// check` runs them: open surfaces, non-manifold edges, orientation, surfaces through
  /// themselves or crossing each other, thin walls, floating parts; in document order, then
  /// pairs, then floating parts. Empty: printable. Throws Error when height_mm is negative or
  /// not finite, or min_wall_mm is not a positive number (since 0.2).
  std::vector<PrintFinding> check_print(const PrintOptions& print = {}) const;

  /// A picture of the document, headless (OSMesa), `width` x `height` (1..8192 each). Throws
  /// Error when no offscreen context can be made, or for a mode or colour that is not one of
  /// RenderOptions' names (a colour since 0.2; 0.1 drew an unknown one as "material").
  Image render(int width, int height, const RenderOptions& options = {}) const;

  /// The file it was loaded from (empty for parse()).
  const std::filesystem::path& file() const;

 private:
  explicit Document(std::unique_ptr<detail::DocumentState> state);
  std::unique_ptr<detail::DocumentState> state_;
  friend struct detail::DocumentState;
};

SWEEP_END_NAMESPACE
