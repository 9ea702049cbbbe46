#include "io/svg/writer.hpp"

#include "base/number_text.hpp"
#include "base/precondition.hpp"
#include "geometry/curves/bezier.hpp"
#include "io/files/xml_text.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace sweep::io {
namespace {

/// The box of the outlines' exact shapes, in SWP coordinates.
struct Box {
  glm::dvec2 lo{INFINITY};
  glm::dvec2 hi{-INFINITY};
  void add(glm::dvec2 p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
};

/// The parameters in (0, 1) where the cubic's coordinate `axis` turns: the roots of its
/// derivative, a quadratic in t with coefficients from the differences of the control points.
std::vector<double> turning_parameters(const BezierPiece& p, int axis) {
  const double a = p[1][axis] - p[0][axis], b = p[2][axis] - p[1][axis], c = p[3][axis] - p[2][axis];
  const double qa = a - 2.0 * b + c, qb = 2.0 * (b - a), qc = a;  // qa t^2 + qb t + qc
  std::vector<double> roots;
  if (qa == 0.0) {
    if (qb != 0.0) roots.push_back(-qc / qb);
  } else {
    const double discriminant = qb * qb - 4.0 * qa * qc;
    if (discriminant >= 0.0) {
      const double root = std::sqrt(discriminant);
      roots = {(-qb - root) / (2.0 * qa), (-qb + root) / (2.0 * qa)};
    }
  }
  std::erase_if(roots, [](double t) { return !(t > 0.0 && t < 1.0); });
  return roots;
}

void add_piece(Box& box, const BezierPiece& p) {
  box.add(glm::dvec2(p[0]));
  box.add(glm::dvec2(p[3]));
  for (int axis = 0; axis < 2; ++axis) {
    for (const double t : turning_parameters(p, axis)) box.add(glm::dvec2(evaluate_bezier_piece(p, t).position));
  }
}

Box box_of(const std::vector<SvgOutline>& outlines) {
  Box box;
  for (const SvgOutline& outline : outlines) {
    if (const auto* circle = std::get_if<SvgCircle>(&outline.shape)) {
      box.add(circle->center - circle->radius);
      box.add(circle->center + circle->radius);
    } else {
      for (const BezierPiece& p : std::get<SvgPath>(outline.shape).pieces) add_piece(box, p);
    }
  }
  return box;
}

/// A number as SVG reads it: the shortest round-trip text, never "-0".
std::string num(double value) {
  return number_text(value + 0.0);
}

/// x and -y: SVG's y points down.
std::string point_text(const glm::dvec3& p) {
  return num(p.x) + " " + num(-p.y);
}

std::string path_data(const SvgPath& path) {
  std::string d = "M " + point_text(path.pieces.front()[0]);
  for (const BezierPiece& p : path.pieces) {
    if (path.straight) {
      d += " L " + point_text(p[3]);
    } else {
      d += " C " + point_text(p[1]) + " " + point_text(p[2]) + " " + point_text(p[3]);
    }
  }
  if (path.closed) d += " Z";
  return d;
}

std::string element(const SvgOutline& outline, const std::string& style) {
  std::string out = "  <";
  out += std::holds_alternative<SvgCircle>(outline.shape) ? "circle" : "path";
  if (!outline.id.empty()) out += " id=\"" + xml_escaped(outline.id) + "\"";
  if (const auto* circle = std::get_if<SvgCircle>(&outline.shape)) {
    out +=
        " cx=\"" + num(circle->center.x) + "\" cy=\"" + num(-circle->center.y) + "\" r=\"" + num(circle->radius) + "\"";
  } else {
    out += " d=\"" + path_data(std::get<SvgPath>(outline.shape)) + "\"";
  }
  return out + style + "/>\n";
}

}  // namespace

std::string svg_text(const std::vector<SvgOutline>& outlines, const std::string& title) {
  SWEEP_EXPECTS(!outlines.empty(), "at least one outline");
  SWEEP_EXPECTS(std::all_of(outlines.begin(), outlines.end(),
                            [](const SvgOutline& o) {
                              const auto* path = std::get_if<SvgPath>(&o.shape);
                              return !path || !path->pieces.empty();
                            }),
                "every path has a piece");
  const Box box = box_of(outlines);
  const glm::dvec2 size = box.hi - box.lo;
  // A margin of 5% of the larger side; a drawing of one point gets one unit.
  const double margin = std::max(size.x, size.y) > 0.0 ? 0.05 * std::max(size.x, size.y) : 1.0;
  const double x = box.lo.x - margin, y = -box.hi.y - margin;
  const double width = size.x + 2.0 * margin, height = size.y + 2.0 * margin;
  const std::string style =
      " fill=\"none\" stroke=\"black\" stroke-width=\"" + num(std::max(width, height) / 500.0) + "\"";
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" + num(width) + "mm\" height=\"" +
         num(height) + "mm\" viewBox=\"" + num(x) + " " + num(y) + " " + num(width) + " " + num(height) + "\">\n";
  out += "  <title>" + xml_escaped(title) + "</title>\n";
  for (const SvgOutline& outline : outlines) out += element(outline, style);
  out += "</svg>\n";
  return out;
}

}  // namespace sweep::io
