#pragma once
// Export of a document's surfaces as OBJ (with its MTL and images), STL or binary glTF: the one
// export used by `sweep export` (and the original two-argument form) and by the viewer's Export
// button.
#include "io/mesh/gltf_writer.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "model/print/printability.hpp"

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::io {

/// A surface that cannot be exported (its message is SOURCE:LINE:COLUMN: ...).
class ExportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A file written for a surface besides its mesh: the OBJ's material library and its images.
struct CompanionFile {
  std::string path;
  std::string what;  // "material NAME", "texture", "N x N checker", "bump map"
};

struct ExportedFile {
  std::string path;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
  std::vector<CompanionFile> companions;  // in the order written; none for STL and glb
  bool quantized = false;                 // a glb written with GlbEncoding::Quantized
};

struct ExportReport {
  std::vector<ExportedFile> files;     // in document order; empty: the document has no named surface
  std::vector<std::string> warnings;   // one line per surface that folds over itself, per finding
  std::vector<std::string> notes;      // what else a user wants to know: a 3MF model's size
  std::vector<PrintFinding> findings;  // 3MF and STL: the printability checks' (printability.hpp)
};

enum class ExportFormat { Obj, Stl, Glb, ThreeMf };

/// How a print export (3MF, STL) sizes and checks the model.
struct PrintOptions {
  double height_mm = 0.0;    // > 0: scale the model to this height; 0: 1 model unit = 1 mm
  bool merge = false;        // STL: one PREFIX.stl of the whole model, placed as 3MF places it
  double min_wall_mm = 0.8;  // the thinnest wall the checks accept, in millimetres as printed
};

/// Writes PREFIX_NAME.obj for every named surface of `doc` (anonymous surfaces have no file
/// name and are skipped), with the comment "sweep: NAME from SOURCE". All or nothing: every
/// mesh is checked first (a NaN or infinity throws ExportError
/// "SOURCE:LINE:COLUMN: surface 'NAME' has a NaN or infinite coordinate; nothing written"), and
/// every image the materials need is read (a missing or unreadable one throws ExportError
/// "SOURCE:LINE:COLUMN: material 'M': cannot read texture PATH: REASON; nothing written", at the
/// material, or "bump image PATH"); then every file is written beside its target, and only once
/// all are written are they renamed into place, the old files set aside and put back if a rename
/// fails: a failure (std::runtime_error naming the path) leaves no new file and every old one
/// intact. Image paths are relative to the folder of SOURCE (image_base). Precondition: `scene`
/// is evaluated from `doc`.
///
/// OBJ: a mesh with texture coordinates gets vt lines and v/vt/vn faces. A surface with a
/// `material` clause also gets PREFIX_NAME.mtl (mtllib and usemtl in the OBJ, mesh/mtl_writer.hpp)
/// and its images beside it: the texture copied as PREFIX_NAME_FILE (FILE: the texture's file
/// name, blanks made '_'), `checker N` made as PREFIX_NAME_checkerN.png, the bump copied as
/// PREFIX_NAME_FILE (one file when the bump is the texture's file; PREFIX_NAME_bump_FILE when
/// another file has its name). A surface without a `material` clause gets no MTL.
///
/// `format` Stl writes binary STL (io/mesh/stl_writer.hpp) of every printable surface
/// (print_model.hpp: not a subdivision surface's cage), welded into shells (no duplicate
/// vertex along a seam or at a pole, no triangle of zero area): PREFIX_NAME.stl each in model
/// coordinates, or, with print.height_mm > 0 or print.merge, placed as 3MF places them (one
/// PREFIX.stl of the whole model with merge), with a note of the model's size.
///
/// `format` Glb writes binary glTF 2.0 (PREFIX_NAME.glb, io/mesh/gltf_writer.hpp): the mesh, its
/// material (the default look without a `material` clause) and its texture or checker embedded.
/// When the document has riders it also writes the scene PREFIX.glb (reported after the surfaces'
/// files, with the vertices and triangles of the meshes it holds): every named surface that no
/// rider carries as a still node, and every rider as a node named after it showing its model's
/// mesh and material, animated by the animation of the same name through rider_keys
/// (model/evaluation/rider_keys.hpp): translation and rotation, LINEAR, one loop of its `seconds`.
/// `encoding` Quantized writes every .glb's vertices quantized (KHR_mesh_quantization,
/// mesh/gltf_writer.hpp); it is ignored for Obj and Stl.
///
/// Precondition: for Obj and Glb, `scene` was evaluated with export_evaluation's options, so every
/// surface has texture coordinates (both formats write them for every surface).
///
/// `format` ThreeMf writes one file, PREFIX.3mf (io/mesh/threemf_writer.hpp), of every printable
/// surface, welded as for STL, in millimetres, z up, standing on the plate and centred over it;
/// print.height_mm > 0 scales the model to that height (else 1 model unit = 1 mm), and a note
/// gives the size (model_size_text: "model size 38.1 x 38.1 x 80.0 mm (scaled to the height
/// asked: 1 model unit = 22.3 mm)").
///
/// Both print formats run the printability checks (check_print, at print.min_wall_mm) on what
/// they write: report.findings, and each finding's message among the warnings. `print` is
/// ignored for Obj and Glb.
ExportReport export_surfaces(const Document& doc, const Scene& scene, const std::string& source,
                             const std::string& prefix, ExportFormat format = ExportFormat::Obj,
                             GlbEncoding encoding = GlbEncoding::Float, const PrintOptions& print = {});

/// `options` as an export in `format` needs them: every surface's texture coordinates for Obj and
/// Glb (TextureCoordinates::Everywhere), only the textured ones' for Stl (it writes none).
EvaluationOptions export_evaluation(EvaluationOptions options, ExportFormat format);

/// "SOURCE has no named surfaces; nothing written": what to say when the report has no files.
std::string no_surfaces_message(const std::string& source);

/// Every file `report` says was written, in the order written: each surface's file, then its
/// companions (the OBJ's MTL and images). The paths are as export_surfaces made them from PREFIX
/// (absolute when PREFIX is).
std::vector<std::string> written_files(const ExportReport& report);

/// One line per file written, as `sweep export` prints them and the viewer shows them:
/// "wrote PATH (N vertices, M triangles)" for a surface's file (", quantized" before the ")" for a
/// quantized glb), "wrote PATH (WHAT)" for a companion; in written_files' order.
std::vector<std::string> written_lines(const ExportReport& report);

/// The format `sweep export --format NAME` means: "obj", "stl", "glb" or "3mf"; nullopt for any other.
std::optional<ExportFormat> export_format_named(std::string_view name);

/// What messages and buttons call `format`: "OBJ", "STL", "glb", "3MF".
const char* export_format_label(ExportFormat format);

}  // namespace sweep::io
