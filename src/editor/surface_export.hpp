#pragma once
// OBJ export of a document's surfaces: the one export used by `sweep export` (and the original
// two-argument form) and by the viewer's Export button.
#include "core/document.hpp"
#include "core/scene.hpp"

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::editor {

/// A surface that cannot be exported (its message is SOURCE:LINE:COLUMN: ...).
class ExportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct ExportedFile {
  std::string path;
  std::size_t vertices = 0;
  std::size_t triangles = 0;
};

struct ExportReport {
  std::vector<ExportedFile> files;    // in document order; empty: the document has no named surface
  std::vector<std::string> warnings;  // one line per surface that folds over itself
};

/// Writes PREFIX_NAME.obj for every named surface of `doc` (anonymous surfaces have no file
/// name and are skipped), with the comment "sweep: NAME from SOURCE". All or nothing: every
/// mesh is checked first (a NaN or infinity throws ExportError
/// "SOURCE:LINE:COLUMN: surface 'NAME' has a NaN or infinite coordinate; nothing written"), then
/// every file is written beside its target, and only once all are written are they renamed
/// into place, the old files set aside and put back if a rename fails: a failure
/// (std::runtime_error naming the path) leaves no new file and every old one intact.
/// Precondition: `scene` is evaluated from `doc`.
enum class ExportFormat { Obj, Stl };

/// `format` Stl writes binary STL (PREFIX_NAME.stl, core/stl_writer.hpp) the same way, and warns
/// for every surface that is not a closed manifold once equal positions are welded
/// ("warning: surface 'NAME' is not a closed manifold (B boundary edges, M non-manifold edges); a
/// printer may reject PATH").
ExportReport export_surfaces(const Document& doc, const Scene& scene, const std::string& source,
                             const std::string& prefix, ExportFormat format = ExportFormat::Obj);

/// "SOURCE has no named surfaces; nothing written": what to say when the report has no files.
std::string no_surfaces_message(const std::string& source);

}  // namespace sweep::editor
