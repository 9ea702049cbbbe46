#pragma once
// The clauses of each kind by ObjectKind, from the declarations beside the kinds (clause.hpp,
// object.hpp), and the values of an object's clauses for the writer. Header-only.
#include "geometry/curves/adaptive.hpp"
#include "model/curve_parameters.hpp"
#include "model/document.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace sweep {

/// A clause's value in `object` (which has it), for the writer.
inline double clause_number(const SwpClause& clause, const Object& object) {
  return *clause.field(const_cast<Object&>(object));
}
inline int clause_reference(const SwpClause& clause, const Object& object) {
  return *clause.reference(const_cast<Object&>(object));
}
inline bool clause_flag(const SwpClause& clause, const Object& object) {
  return *clause.flag(const_cast<Object&>(object));
}

namespace swp_clause_checks {
template <std::size_t... I>
constexpr std::array<std::span<const SwpClause>, sizeof...(I)> clauses_by_kind(std::index_sequence<I...>) {
  return {kind_clauses<std::variant_alternative_t<I, Payload>>...};
}
inline constexpr auto kByKind = clauses_by_kind(std::make_index_sequence<std::variant_size_v<Payload>>());
}  // namespace swp_clause_checks

/// The clauses `kind` accepts, in the order the writer writes them; empty for kinds without any.
inline std::span<const SwpClause> swp_clauses(ObjectKind kind) {
  return swp_clause_checks::kByKind[static_cast<std::size_t>(kind)];
}

}  // namespace sweep
