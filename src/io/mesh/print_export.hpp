#pragma once
// The print exports' part of export_surfaces (surface_export.hpp): 3MF and STL, written from the
// print model (model/print/print_model.hpp) and reported with its printability findings.
// Internal to io: surface_export.cpp is its one user.
#include "io/files/file_set.hpp"
#include "io/surface_export.hpp"
#include "model/print/print_model.hpp"

#include <functional>
#include <string>
#include <vector>

namespace sweep::io {

/// One file to write: its target and how to write it (to the staged path given).
using ExportOutput = FileSetMember;

/// What the planned outputs of a print export read while they are written: it must outlive
/// the writing.
struct PrintPlan {
  PrintModel model;
  std::vector<Mesh> meshes;  // STL: each file's triangles as written
};

/// Plans the files of a 3MF or STL export of `doc` into `outputs` and reports them, the model's
/// size (3MF, and STL placed) and every printability finding (check_print at `options`' scale
/// and wall) in `report`. 3MF: PREFIX.3mf of the whole model. STL: PREFIX_NAME.stl per printable
/// surface, welded; in model coordinates unless options.height_mm > 0 or options.merge, which
/// place them as 3MF does (millimetres, z up, on the plate); with merge one PREFIX.stl of the
/// whole model. Precondition: format is ThreeMf or Stl; scene evaluated from doc, finite.
void plan_print_export(const Document& doc, const Scene& scene, const std::string& source, const std::string& prefix,
                       ExportFormat format, const PrintOptions& options, PrintPlan& plan,
                       std::vector<ExportOutput>& outputs, ExportReport& report);

}  // namespace sweep::io
