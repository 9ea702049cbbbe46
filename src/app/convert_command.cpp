// `sweep convert FILE CURVE --to KIND [-o OUT] [--tolerance D]`: one curve of FILE converted to
// another kind (issue 61, item 3; model/edit/edit_convert.cpp), the rest of the file written back
// byte for byte (write_swp_preserving), the surfaces that use the curve keeping their references.
#include "app/commands.hpp"
#include "base/number_text.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace sweep::app {
namespace {

struct ConvertChoice {
  std::string file;
  std::string curve;
  std::string to;
  std::string out;
  double tolerance = 0.0;
};

/// The kind `name` means for a curve of `planar`ity: a keyword (bez2), or a family without its
/// dimension (bez), which takes the curve's.
std::optional<ObjectKind> target_kind(const std::string& name, bool planar) {
  for (const KindInfo& info : kinds()) {
    if (!is_curve(info.kind) || !has_editable_points(info.kind)) continue;
    const std::string keyword(info.keyword);
    if (name == keyword) return info.kind;
    if (is_planar_curve(info.kind) == planar && keyword.size() == name.size() + 1 && keyword.starts_with(name)) {
      return info.kind;
    }
  }
  return std::nullopt;
}

int convert_file(const ConvertChoice& choice) {
  Document doc;
  Scene scene;
  if (!load_and_evaluate(choice.file, {}, doc, scene)) return 1;
  const int index = doc.find(choice.curve);
  if (index < 0) {
    std::fprintf(stderr, "sweep: %s has no object named '%s'\n", choice.file.c_str(), choice.curve.c_str());
    return 1;
  }
  const Object& curve = doc.objects[std::size_t(index)];
  const std::optional<ObjectKind> to = target_kind(choice.to, is_planar_curve(curve.kind()));
  if (!to) {
    std::fprintf(stderr, "sweep: --to: expected bez, herm, bsp or cr (or bez2, bez3, ...), found '%s'\n",
                 choice.to.c_str());
    return 1;
  }
  const std::string from(keyword(curve.kind()));
  const double tolerance = choice.tolerance > 0.0 ? choice.tolerance : 1e-3 * curve_extent(curve);
  Conversion result;
  try {
    convert_curve(doc, index, *to, tolerance, &result);
  } catch (const EditError& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
  const std::string out = choice.out.empty() ? choice.file : choice.out;
  io::save_swp_file(out, doc);
  const std::string how = result.exact ? "exactly"
                                       : "by a fit of " + std::to_string(points_of(result.curve).size()) +
                                             " points, largest deviation " + number_text(result.deviation) +
                                             " (tolerance " + number_text(tolerance) + ")";
  std::printf("converted '%s' from %s to %s %s: wrote %s\n", choice.curve.c_str(), from.c_str(),
              std::string(keyword(*to)).c_str(), how.c_str(), out.c_str());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace

void add_convert_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<ConvertChoice>();
  CLI::App* command = app.add_subcommand(
      "convert",
      "Convert curve CURVE of FILE to another kind, writing FILE back (or OUT) with every other line as it was: "
      "exactly to Bezier (bez) from any curve with control points, and to Hermite (herm) from one without corners; "
      "to B-spline (bsp) or Catmull-Rom (cr) by a fit within the tolerance, its largest deviation printed");
  command->add_option("file", choice->file, "SWP file to read")->required()->check(CLI::ExistingFile);
  command->add_option("curve", choice->curve, "Name of the curve to convert")->required();
  command->add_option("--to", choice->to, "The kind: bez, herm, bsp or cr (the curve's dimension), or bez2, bez3, ...")
      ->required();
  command->add_option("-o,--output", choice->out, "SWP file to write instead of FILE (replaced)");
  command
      ->add_option("--tolerance", choice->tolerance,
                   "A fit's largest deviation (model units; default a thousandth of the curve's size)")
      ->check(CLI::PositiveNumber);
  command->callback([choice, &action] { action = [choice] { return convert_file(*choice); }; });
}

}  // namespace sweep::app
