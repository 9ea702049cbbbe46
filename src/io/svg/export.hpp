#pragma once
// Export of a document's planar curves as one SVG file (`sweep export FILE PREFIX --format svg`).
// Not an ExportFormat (surface_export.hpp): those write a document's surfaces, one file each, from
// an evaluated scene; this writes its curves, exactly, into one file, and evaluates nothing.
#include "io/svg/writer.hpp"
#include "model/document.hpp"

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::io {

/// The name `sweep export --format NAME` gives this export.
inline constexpr std::string_view kSvgFormatName = "svg";

/// The outlines of the planar curves of `doc` (bez2, bsp2, cr2, kb2, poly2, circ), in document
/// order: each control-point curve as its Bezier pieces (bezier_pieces, geometry/curves/curve.hpp;
/// straight for a polyline), closed when is_closed says so; a circle as a circle about the
/// origin. 3D curves, surfaces, materials and riders have none. Precondition: `doc` is one the
/// SWP reader accepts.
std::vector<SvgOutline> planar_outlines(const Document& doc);

/// What export_curves_svg wrote: PREFIX.svg and its number of curves (0: nothing written).
struct SvgExport {
  std::string path;
  std::size_t curves = 0;
};

/// Writes PREFIX.svg atomically (io/files/atomic_file.hpp): svg_text of planar_outlines(doc), titled
/// "sweep: planar curves of SOURCE". Writes nothing and returns 0 curves when `doc` has no planar
/// curve. A failed write throws std::runtime_error naming the path and leaves no file.
/// Precondition: as planar_outlines.
SvgExport export_curves_svg(const Document& doc, const std::string& source, const std::string& prefix);

/// "wrote PATH (N curves)" ("1 curve"): what `sweep export` prints.
std::string written_line(const SvgExport& written);

/// "SOURCE has no planar curves; nothing written".
std::string no_planar_curves_message(const std::string& source);

}  // namespace sweep::io
