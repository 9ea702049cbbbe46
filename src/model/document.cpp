#include "model/document.hpp"

#include "geometry/helix.hpp"
#include "geometry/limits.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace sweep {
namespace {

using enum KindFamily;
using enum PointRole;

/// One row per kind, in the order messages list them. A new kind is one row here (and its own
/// reader, writer and evaluation: docs/architecture.md, "Adding a kind").
constexpr KindInfo kKinds[] = {
    {ObjectKind::Bezier2, "bez2", Curve, true, ControlPoints, false, true, "Bezier (2D)"},
    {ObjectKind::Bezier3, "bez3", Curve, false, ControlPoints, false, true, "Bezier (3D)"},
    {ObjectKind::BSpline2, "bsp2", Curve, true, ControlPoints, false, true, "B-spline (2D)"},
    {ObjectKind::BSpline3, "bsp3", Curve, false, ControlPoints, false, true, "B-spline (3D)"},
    {ObjectKind::Circle, "circ", Curve, true, None, false, true, "circle"},
    {ObjectKind::CatmullRom2, "cr2", Curve, true, ControlPoints, true, true, "Catmull-Rom (2D)"},
    {ObjectKind::CatmullRom3, "cr3", Curve, false, ControlPoints, true, true, "Catmull-Rom (3D)"},
    {ObjectKind::KochanekBartels2, "kb2", Curve, true, ControlPoints, true, true, "Kochanek-Bartels (2D)"},
    {ObjectKind::KochanekBartels3, "kb3", Curve, false, ControlPoints, true, true, "Kochanek-Bartels (3D)"},
    {ObjectKind::Helix, "helix", Curve, false, None, false, true, "helix"},
    {ObjectKind::TorusKnot, "knot", Curve, false, None, false, true, "torus knot"},
    {ObjectKind::Polyline2, "poly2", Curve, true, ControlPoints, true, false, "polyline (2D)"},
    {ObjectKind::Polyline3, "poly3", Curve, false, ControlPoints, true, false, "polyline (3D)"},
    {ObjectKind::SurfaceOfRevolution, "srev", Surface, false, None, false, true, "surface of revolution"},
    {ObjectKind::GeneralizedCylinder, "gcyl", Surface, false, None, false, false, "generalized cylinder"},
    {ObjectKind::Birail, "birail", Surface, false, None, false, false, "birail surface"},
    {ObjectKind::BezierPatch, "bezpatch", Surface, false, Net, false, true, "Bezier patches"},
    {ObjectKind::BSplinePatch, "bsppatch", Surface, false, Net, false, true, "B-spline patch"},
    {ObjectKind::PolygonMesh, "mesh", Surface, false, Net, false, false, "polygon mesh"},
    {ObjectKind::Subdivision, "subd", Surface, false, None, false, false, "subdivision surface"},
    {ObjectKind::Material, "material", Material, false, None, false, false, "material"},
};

/// Each kind has exactly one row, at the index of its enumerator.
constexpr bool rows_in_enum_order() {
  for (std::size_t i = 0; i < std::size(kKinds); ++i) {
    if (static_cast<std::size_t>(kKinds[i].kind) != i) return false;
  }
  return true;
}
static_assert(rows_in_enum_order(), "kKinds has one row per ObjectKind, in the enumerators' order");

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

}  // namespace

std::span<const KindInfo> kinds() {
  return kKinds;
}

const KindInfo& kind_info(ObjectKind kind) {
  return kKinds[static_cast<std::size_t>(kind)];
}

std::string_view keyword(ObjectKind kind) {
  return kind_info(kind).keyword;
}

std::optional<ObjectKind> kind_from_keyword(std::string_view word) {
  for (const KindInfo& k : kKinds) {
    if (equal_ignoring_case(word, k.keyword)) return k.kind;
  }
  return std::nullopt;
}

bool is_curve(ObjectKind kind) {
  return kind_info(kind).family == KindFamily::Curve;
}

bool is_surface(ObjectKind kind) {
  return kind_info(kind).family == KindFamily::Surface;
}

bool is_material(ObjectKind kind) {
  return kind_info(kind).family == KindFamily::Material;
}

bool is_planar_curve(ObjectKind kind) {
  return kind_info(kind).planar;
}

bool has_control_points(ObjectKind kind) {
  return kind_info(kind).points == PointRole::ControlPoints;
}

bool has_control_net(ObjectKind kind) {
  return kind_info(kind).points == PointRole::Net;
}

bool has_editable_points(ObjectKind kind) {
  return kind_info(kind).points != PointRole::None;
}

bool is_interpolating(ObjectKind kind) {
  return kind_info(kind).interpolating;
}

std::array<int*, 7> reference_slots(Object& object) {
  return {&object.profile,     &object.sweep,  &object.rail2,   &object.scale,
          &object.twist_curve, &object.source, &object.material};
}

std::array<int, 7> references(const Object& object) {
  // Read through the one list of slots; nothing is written.
  std::array<int, 7> out{};
  const std::array<int*, 7> slots = reference_slots(const_cast<Object&>(object));
  for (std::size_t k = 0; k < slots.size(); ++k) out[k] = *slots[k];
  return out;
}

int Document::find(std::string_view name) const {
  if (name.empty()) return -1;
  for (std::size_t i = 0; i < objects.size(); ++i) {
    if (objects[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

std::string display_name(const Document& doc, int index) {
  const Object& object = doc.objects.at(static_cast<std::size_t>(index));
  if (!object.name.empty()) return object.name;
  return std::string(keyword(object.kind)) + "#" + std::to_string(index);
}

std::int64_t piece_count(ObjectKind kind, std::int64_t count) {
  switch (kind) {
    case ObjectKind::Bezier2:
    case ObjectKind::Bezier3:
      return count >= 4 && (count - 1) % 3 == 0 ? (count - 1) / 3 : 0;
    case ObjectKind::BSpline2:
    case ObjectKind::BSpline3:
      return count >= 4 ? count - 3 : 0;
    case ObjectKind::CatmullRom2:
    case ObjectKind::CatmullRom3:
    case ObjectKind::KochanekBartels2:
    case ObjectKind::KochanekBartels3:
    case ObjectKind::Polyline2:
    case ObjectKind::Polyline3:
      return count >= 2 ? count - 1 : 0;
    default:
      return 0;
  }
}

std::int64_t curve_sample_count(const Object& curve) {
  switch (curve.kind) {
    case ObjectKind::Circle:
    case ObjectKind::TorusKnot:
      return std::int64_t{curve.steps} + 1;
    case ObjectKind::Helix:
      return helix_sample_count(curve.steps, curve.turns);
    case ObjectKind::Polyline2:
    case ObjectKind::Polyline3:
      return static_cast<std::int64_t>(curve.points.size());  // one sample per point
    default:
      return piece_count(curve.kind, static_cast<std::int64_t>(curve.points.size())) * curve.steps + 1;
  }
}

bool is_valid_object_name(std::string_view name) {
  if (name.empty() || name.size() > limits::kMaxNameLength) return false;
  const auto first = static_cast<unsigned char>(name[0]);
  if (!std::isalpha(first) && first != '_') return false;
  for (char ch : name) {
    const auto c = static_cast<unsigned char>(ch);
    if (!std::isalnum(c) && c != '_' && c != '-' && c != '.') return false;
  }
  return true;
}

std::string printable_excerpt(std::string_view text, std::size_t max_bytes) {
  std::string out;
  const std::size_t shown = std::min(text.size(), max_bytes);
  for (std::size_t i = 0; i < shown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02X", c);
      out += buf;
    }
  }
  if (shown < text.size()) out += "...";
  return out;
}

}  // namespace sweep
