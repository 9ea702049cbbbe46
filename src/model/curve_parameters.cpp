#include "model/curve_parameters.hpp"

#include "model/document.hpp"

#include "model/file_limits.hpp"

#include <numeric>

namespace sweep {

std::string check_alpha(double alpha) {
  return alpha >= 0.0 && alpha <= 1.0 ? "" : "expected alpha from 0 to 1 (0 uniform, 0.5 centripetal, 1 chordal)";
}

std::string check_tension(ObjectKind kind, double tension) {
  if (kind == ObjectKind::KochanekBartels2 || kind == ObjectKind::KochanekBartels3) {
    return tension >= -1.0 && tension <= 1.0 ? "" : "expected tension from -1 to 1";
  }
  return tension >= 0.0 && tension < 1.0 ? "" : "expected tension from 0 up to (not including) 1";
}

std::string check_kb_parameter(const char* what, double value) {
  return value >= -1.0 && value <= 1.0 ? "" : std::string("expected ") + what + " from -1 to 1";
}

std::string check_radius(double radius) {
  if (!(radius > 0.0)) return "expected a positive radius";
  if (radius < limits::kMinRadius) return "expected a radius of at least 1e-12";
  return "";
}

std::string check_circle_radius(double radius) {
  if (radius == 0.0) return "";  // a point with the circle's turning frames (curve.hpp)
  if (!(radius > 0.0)) return "expected a radius of 0 or more";
  if (radius < limits::kMinRadius) return "expected a radius of 0 or of at least 1e-12";
  return "";
}

std::string check_turns(double turns) {
  return turns > 0.0 ? "" : "expected a positive number of turns";
}

std::string check_knot_pq(int p, int q) {
  if (p < 1 || q < 1) return "expected positive P and Q";
  const int common = std::gcd(p, q);
  if (common == 1) return "";
  return "expected P and Q without a common factor (P = " + std::to_string(p) + " and Q = " + std::to_string(q) +
         " share " + std::to_string(common) + ": that is a link of " + std::to_string(common) + " loops, not a knot)";
}

std::string check_knot_radii(double major_radius, double minor_radius) {
  if (!(minor_radius > 0.0)) return "expected a positive tube radius r";
  if (minor_radius < limits::kMinRadius) return "expected a tube radius r of at least 1e-12";
  if (!(minor_radius < major_radius)) return "expected r less than R (the torus would cross its own axis)";
  return "";
}

}  // namespace sweep
