#include "io/svg/export.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/circle.hpp"
#include "io/files/atomic_file.hpp"
#include "model/evaluation/curve_evaluation.hpp"

namespace sweep::io {
namespace {

SvgOutline outline_of(const Object& curve) {
  const CurveDescriptor c = describe_curve(curve);
  if (c.basis->pieces) return {curve.name, SvgPath{bezier_pieces(c), c.basis->straight, is_closed(c)}};
  // The circle is the one planar basis without pieces.
  SWEEP_EXPECTS(c.basis == &kCircleBasis, "a planar curve without pieces is a circle");
  return {curve.name, SvgCircle{glm::dvec2(0.0), c.radius}};
}

}  // namespace

std::vector<SvgOutline> planar_outlines(const Document& doc) {
  std::vector<SvgOutline> outlines;
  for (const Object& o : doc.objects) {
    if (is_curve(o.kind()) && is_planar_curve(o.kind())) outlines.push_back(outline_of(o));
  }
  return outlines;
}

SvgExport export_curves_svg(const Document& doc, const std::string& source, const std::string& prefix) {
  const std::vector<SvgOutline> outlines = planar_outlines(doc);
  if (outlines.empty()) return {};
  SvgExport written{prefix + ".svg", outlines.size()};
  write_file_atomically(written.path, svg_text(outlines, "sweep: planar curves of " + source));
  return written;
}

std::string written_line(const SvgExport& written) {
  return "wrote " + written.path + " (" + std::to_string(written.curves) +
         (written.curves == 1 ? " curve)" : " curves)");
}

std::string no_planar_curves_message(const std::string& source) {
  return source + " has no planar curves; nothing written";
}

}  // namespace sweep::io
