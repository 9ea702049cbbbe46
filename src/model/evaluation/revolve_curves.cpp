// Every curve of a document turned into a surface of revolution (revolve_curves.hpp).
#include "model/evaluation/revolve_curves.hpp"

#include "base/precondition.hpp"
#include "model/file_limits.hpp"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sweep {
namespace {

/// NAME_profile, or NAME_profile_2, _3, ... when taken; NAME is cut so that the whole fits.
std::string profile_name(const std::string& name, std::set<std::string>& used) {
  std::string candidate;
  for (int n = 1; candidate.empty() || used.contains(candidate); ++n) {
    std::string suffix(kProfileSuffix);
    if (n > 1) suffix.append("_").append(std::to_string(n));
    candidate.assign(name, 0, limits::kMaxNameLength - suffix.size());
    candidate.append(suffix);
  }
  used.insert(candidate);
  return candidate;
}

}  // namespace

Document revolve_curves(Document doc, int steps) {
  SWEEP_EXPECTS(steps >= 1 && steps <= limits::kMaxSteps, "1 <= steps <= kMaxSteps");
  std::set<std::string> used;
  for (const Object& curve : doc.objects) {
    SWEEP_EXPECTS(is_planar_curve(curve.kind()), "every object is a planar curve");
    SWEEP_EXPECTS(is_valid_object_name(curve.name), "every object has a valid name");
    const bool unique = used.insert(curve.name).second;  // outside the check: it must run without it
    SWEEP_EXPECTS(unique, "the names are unique");
  }
  std::vector<Object> objects;
  objects.reserve(2 * doc.objects.size());
  for (Object& curve : doc.objects) {
    Object surface;
    surface.set_kind(ObjectKind::SurfaceOfRevolution);
    surface.name = curve.name;
    surface.as<CopiesPart>().copies = steps;
    surface.as<ProfilePart>().profile = static_cast<int>(objects.size());
    curve.name = profile_name(curve.name, used);
    objects.push_back(std::move(curve));
    objects.push_back(std::move(surface));
  }
  doc.objects = std::move(objects);
  return doc;
}

}  // namespace sweep
