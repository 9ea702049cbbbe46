#pragma once
// The valid ranges of the curve kinds' numbers (cr/kb clauses, helix, knot), in one place for
// the SWP reader (which reports file:line:column) and the editor (which refuses the edit). Each
// check returns "" for a valid value, else the message's "expected ..." text.
#include <cstdint>
#include <string>

namespace sweep {

enum class ObjectKind : std::uint8_t;  // object.hpp, which names these checks in its kinds

/// alpha of cr2/cr3: 0 uniform, 0.5 centripetal (default), 1 chordal.
std::string check_alpha(double alpha);
/// tension: cr in [0, 1) (the tangents are scaled by 1 - T), kb in [-1, 1].
std::string check_tension(ObjectKind kind, double tension);
/// continuity and bias of kb2/kb3, in [-1, 1]; `what` is "continuity" or "bias".
std::string check_kb_parameter(const char* what, double value);
/// A helix radius (positive, at least limits::kMinRadius).
std::string check_radius(double radius);
/// A circle radius: 0 (a point whose frames still turn: sweeps along it turn the profile about
/// z, as the course tool does) or as a helix radius.
std::string check_circle_radius(double radius);
/// Helix turns: positive (the sample count is checked against the caps apart).
std::string check_turns(double turns);
/// Knot P and Q: positive and coprime (else the curve is a link of gcd(P, Q) components).
std::string check_knot_pq(int p, int q);
/// Knot radii: 0 < r < R.
std::string check_knot_radii(double major_radius, double minor_radius);

/// The number of control points a cr/kb curve needs at least (2), and a closed one (4: three
/// distinct points and the first repeated).
inline constexpr int kMinInterpolatingPoints = 2;

/// The largest knot P and Q (the SWP reader reads whole numbers from 1 to this). A thousand
/// windings is far past any knot worth sweeping, and keeps STEPS+1 samples meaningful.
inline constexpr int kMaxKnotWinding = 1000;

}  // namespace sweep
