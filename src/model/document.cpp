#include "model/document.hpp"

#include "model/file_limits.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <utility>

namespace sweep {
namespace {

/// One row per kind, in the order messages list them, from the kinds' own traits (object.hpp).
template <std::size_t... I>
constexpr std::array<KindInfo, sizeof...(I)> make_kinds(std::index_sequence<I...>) {
  return {KindInfo{std::variant_alternative_t<I, Payload>::traits, static_cast<ObjectKind>(I)}...};
}
constexpr auto kKinds = make_kinds(std::make_index_sequence<std::variant_size_v<Payload>>());

template <std::size_t... I>
Payload make_payload_at(std::size_t index, std::index_sequence<I...>) {
  static constexpr Payload (*kMake[])() = {[] { return Payload(std::in_place_index<I>); }...};
  return kMake[index]();
}

/// Cubic pieces of `count` points for the kinds with pieces, 0 for the others.
template <std::size_t... I>
std::int64_t pieces_at(std::size_t index, std::int64_t count, std::index_sequence<I...>) {
  static constexpr std::int64_t (*kPieces[])(std::int64_t) = {[](std::int64_t n) -> std::int64_t {
    using Kind = std::variant_alternative_t<I, Payload>;
    if constexpr (requires { Kind::pieces(n); }) {
      return Kind::pieces(n);
    } else {
      return 0;
    }
  }...};
  return kPieces[index](count);
}

}  // namespace

bool equal_ignoring_case(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) {
      return false;
    }
  }
  return true;
}

std::span<const KindInfo> kinds() {
  return kKinds;
}

const KindInfo& kind_info(ObjectKind kind) {
  return kKinds[static_cast<std::size_t>(kind)];
}

std::string_view keyword(ObjectKind kind) {
  return kind_info(kind).keyword;
}

std::string_view phrase(ObjectKind kind) {
  return kind_info(kind).phrase;
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

bool is_rider(ObjectKind kind) {
  return kind_info(kind).family == KindFamily::Rider;
}

bool is_planar_curve(ObjectKind kind) {
  return kind_info(kind).planar;
}

bool has_control_points(ObjectKind kind) {
  return kind_info(kind).points.role == PointRole::ControlPoints;
}

bool has_control_net(ObjectKind kind) {
  return kind_info(kind).points.role == PointRole::Net;
}

bool has_editable_points(ObjectKind kind) {
  return kind_info(kind).points.role != PointRole::None;
}

std::string count_problem(const Object& object) {
  return std::visit(
      [](const auto& data) -> std::string {
        using Kind = std::decay_t<decltype(data)>;
        if constexpr (requires { Kind::count_problem(std::int64_t{}); }) {
          return Kind::count_problem(static_cast<std::int64_t>(data.points.size()));
        } else {
          return {};
        }
      },
      object.data);
}

const PointLayout& point_layout(ObjectKind kind) {
  return kind_info(kind).points;
}

bool is_interpolating(ObjectKind kind) {
  return kind_info(kind).interpolating;
}

Payload make_payload(ObjectKind kind) {
  return make_payload_at(static_cast<std::size_t>(kind), std::make_index_sequence<std::variant_size_v<Payload>>());
}

std::string interpolating_count_problem(std::int64_t count, const char* family) {
  if (count >= kMinInterpolatingPoints) return {};
  return "expected at least " + std::to_string(kMinInterpolatingPoints) + " " + family + " control points";
}

namespace detail {
void wrong_part(ObjectKind kind, const char* file, int line) {
  std::fprintf(stderr, "sweep: a %s has no such data (asked at %s:%d)\n", std::string(keyword(kind)).c_str(), file,
               line);
  std::fflush(stderr);
  std::abort();
}
}  // namespace detail

std::vector<int*> reference_slots(Object& object) {
  std::vector<int*> slots;
  if (auto* p = object.find<ProfilePart>()) slots.push_back(&p->profile);
  if (auto* c = object.find<CylinderSurface>()) slots.insert(slots.end(), {&c->sweep, &c->scale, &c->twist_curve});
  if (auto* b = object.find<BirailSurface>()) slots.insert(slots.end(), {&b->rail1, &b->rail2});
  if (auto* s = object.find<SubdivisionSurface>()) slots.push_back(&s->source);
  if (auto* m = object.find<MaterialPart>()) slots.push_back(&m->material);
  if (auto* r = object.find<RiderObject>()) slots.insert(slots.end(), {&r->path, &r->model});
  return slots;
}

SweptCurves swept_curves(const Object& object) {
  SweptCurves curves;
  if (const auto* p = object.find<ProfilePart>()) curves.profile = p->profile;
  if (const auto* c = object.find<CylinderSurface>()) curves.path = c->sweep;
  if (const auto* b = object.find<BirailSurface>()) {
    curves.path = b->rail1;
    curves.rail2 = b->rail2;
  }
  return curves;
}

double own_tolerance(const Object& object) {
  const auto* part = object.find<TolerancePart>();
  return part ? part->tolerance : 0.0;
}

std::span<const glm::dvec3> points_of(const Object& object) {
  const auto* part = object.find<PointsPart>();
  return part ? std::span<const glm::dvec3>(part->points) : std::span<const glm::dvec3>();
}

std::vector<int> references(const Object& object) {
  // Read through the one list of slots; nothing is written.
  std::vector<int> out;
  for (const int* slot : reference_slots(const_cast<Object&>(object))) out.push_back(*slot);
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
  return std::string(keyword(object.kind())) + "#" + std::to_string(index);
}

std::int64_t piece_count(ObjectKind kind, std::int64_t count) {
  return pieces_at(static_cast<std::size_t>(kind), count, std::make_index_sequence<std::variant_size_v<Payload>>());
}

int* steps_field(Object& object) {
  if (auto* steps = object.find<StepsPart>()) return &steps->steps;
  if (auto* copies = object.find<CopiesPart>()) return &copies->copies;
  return nullptr;
}

const int* steps_field(const Object& object) {
  return steps_field(const_cast<Object&>(object));
}

std::int64_t curve_sample_count(const Object& curve) {
  return std::visit(
      [&](const auto& data) -> std::int64_t {
        using Kind = std::decay_t<decltype(data)>;
        if constexpr (requires { data.sample_count(); }) {
          return data.sample_count();
        } else if constexpr (std::is_base_of_v<StepsPart, Kind> && std::is_base_of_v<PointsPart, Kind>) {
          return piece_count(curve.kind(), static_cast<std::int64_t>(data.points.size())) * data.steps + 1;
        } else {
          return 1;  // no samples of its own
        }
      },
      curve.data);
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
