#include "svg_fuzz_check.hpp"

#include "io/mesh/obj_import.hpp"
#include "io/svg/import.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include <cmath>
#include <set>

namespace sweep::fuzz {
namespace {

/// The curve rules of an imported document, or a description of the first one broken.
std::string check_curves(const Document& doc) {
  if (doc.objects.empty()) return "an import without curves did not throw";
  std::set<std::string> names;
  for (const Object& o : doc.objects) {
    if (o.kind() != ObjectKind::Bezier2) return "'" + o.name + "' is not a bez2";
    if (!names.insert(o.name).second) return "two curves named '" + o.name + "'";
    const std::vector<glm::dvec3>& points = o.as<PointsPart>().points;
    if (points.size() < 4 || points.size() % 3 != 1)
      return "'" + o.name + "' has " + std::to_string(points.size()) + " points";
    for (const glm::dvec3& p : points) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y) || p.z != 0.0) return "'" + o.name + "' has a point off the plane";
    }
  }
  return {};
}

}  // namespace

std::string check_svg_input(std::string_view bytes) {
  Document doc;
  try {
    doc = io::parse_svg_drawing(std::string(bytes), "fuzz.svg", "shape", 1.0);
  } catch (const io::ImportError& e) {
    const std::string message = e.what();
    if (message.rfind("fuzz.svg:", 0) != 0) return "an import error not starting with the file: " + message;
    if (message.find('\n') != std::string::npos) return "an import error of more than one line: " + message;
    return {};
  } catch (const std::exception& e) {
    return std::string("parse_svg_drawing threw something other than ImportError: ") + e.what();
  }
  if (std::string problem = check_curves(doc); !problem.empty()) return problem;
  const std::string written = io::write_swp(doc);
  try {
    if (!(io::parse_swp(written, "written.swp") == doc)) return "parse_swp(write_swp(import)) != import";
  } catch (const std::exception& e) {
    return std::string("the imported document does not read back: ") + e.what() + "\n" + written;
  }
  return {};
}

}  // namespace sweep::fuzz
