#pragma once
// The format-preserving writer's clause order (swp/preserving_write.cpp): a changed object's
// new text (write_swp's) with its clauses in the order the file wrote them, so that only the
// values the edit changed differ from the file's text.
#include "model/object.hpp"

#include <string>
#include <string_view>

namespace sweep::io {

/// `written` (write_swp's text of an object of `kind`) with its clauses (the keys of
/// swp_clauses(kind), or kMaterialKeys, and their values, before the first point) in the order `original` (the
/// file's text of the same object) gives their keys, in any case; the clauses the file lacks
/// follow in the writer's order. `written` as it is when the two orders agree. The result must be
/// read back to be trusted: a value spelled like a key would be taken for one.
std::string in_clause_order_of(std::string_view original, std::string_view written, ObjectKind kind);

}  // namespace sweep::io
