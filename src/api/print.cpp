#include "api/document_state.hpp"

#include "io/surface_export.hpp"
#include "model/print/printability.hpp"

#include <cmath>

// The public Document's printability checks (since 0.2): `sweep check` through the library.

namespace sweep::v0 {
namespace {

void check_options(const PrintOptions& print) {
  if (!(std::isfinite(print.height_mm) && print.height_mm >= 0.0)) {
    throw Error("a print height is 0 (1 model unit = 1 mm) or a positive number of millimetres");
  }
  if (!(std::isfinite(print.min_wall_mm) && print.min_wall_mm > 0.0)) {
    throw Error("the thinnest wall is a positive number of millimetres");
  }
}

PrintFinding public_finding(const ::sweep::Document& doc, const ::sweep::PrintFinding& f) {
  PrintFinding out;
  out.check = ::sweep::print_check_name(f.check);
  out.object = doc.objects[f.object].name;
  if (f.other) out.other = doc.objects[*f.other].name;
  out.line = f.line;
  out.message = f.message;
  out.where = {f.where.x, f.where.y, f.where.z};
  out.fails = f.fails;
  return out;
}

}  // namespace

std::vector<PrintFinding> Document::check_print(const PrintOptions& print) const {
  check_options(print);
  try {
    const ::sweep::PrintModel model = ::sweep::print_model(state_->doc, *state_->scene, print.height_mm);
    std::vector<PrintFinding> out;
    for (const ::sweep::PrintFinding& f : ::sweep::check_print(state_->doc, model, state_->name, {print.min_wall_mm})) {
      out.push_back(public_finding(state_->doc, f));
    }
    return out;
  } catch (...) {
    detail::throw_public_error();
  }
}

std::vector<std::filesystem::path> Document::export_surfaces(const std::filesystem::path& prefix,
                                                             ExportFormat format) const {
  return export_surfaces(prefix, format, PrintOptions{});
}

std::vector<std::filesystem::path> Document::export_surfaces(const std::filesystem::path& prefix, ExportFormat format,
                                                             const PrintOptions& print) const {
  using ::sweep::io::ExportFormat;
  check_options(print);
  constexpr ExportFormat kInternal[] = {ExportFormat::Obj, ExportFormat::Stl, ExportFormat::Glb, ExportFormat::ThreeMf};
  const ExportFormat internal_format = kInternal[static_cast<int>(format)];
  try {
    const ::sweep::EvaluationOptions options = ::sweep::io::export_evaluation(state_->options, internal_format);
    const ::sweep::Scene scene = ::sweep::evaluate_document(state_->doc, options);
    const ::sweep::io::ExportReport report =
        ::sweep::io::export_surfaces(state_->doc, scene, state_->name, prefix.string(), internal_format, {},
                                     {print.height_mm, print.merge, print.min_wall_mm});
    std::vector<std::filesystem::path> out;
    for (const std::string& file : ::sweep::io::written_files(report)) out.emplace_back(file);
    return out;
  } catch (...) {
    detail::throw_public_error();
  }
}

}  // namespace sweep::v0
