#include "io/swp/clause_order.hpp"

#include "io/swp/detail/lexer.hpp"
#include "model/clauses.hpp"

#include <algorithm>
#include <vector>

namespace sweep::io {
namespace {

using swp_detail::Lexer;
using swp_detail::TokenType;

/// One clause of a text: its key and its bytes, from the key to the end of its last value.
struct ClauseSpan {
  std::string_view key;
  std::size_t begin = 0;
  std::size_t end = 0;
};

/// The clause key `word` is, or "" (the kind's keys are lower case; the reader takes any case).
std::string_view key_named(std::string_view word, ObjectKind kind) {
  if (kind == ObjectKind::Material) {
    for (const std::string_view key : kMaterialKeys) {
      if (equal_ignoring_case(word, key)) return key;
    }
  }
  for (const SwpClause& clause : swp_clauses(kind)) {
    if (equal_ignoring_case(word, clause.key)) return clause.key;
  }
  return {};
}

/// The clauses of `text` before its first point, in the text's order.
std::vector<ClauseSpan> clauses_of(std::string_view text, ObjectKind kind) {
  std::vector<ClauseSpan> clauses;
  Lexer lexer(text);
  for (auto t = lexer.next(); t.type == TokenType::Word; t = lexer.next()) {
    const std::size_t begin = lexer.offset_of(t);
    if (const std::string_view key = key_named(t.text, kind); !key.empty()) {
      clauses.push_back({key, begin, begin + t.text.size()});
    } else if (!clauses.empty()) {
      clauses.back().end = begin + t.text.size();  // a value of the clause before
    }
  }
  return clauses;
}

std::vector<std::string_view> keys_of(const std::vector<ClauseSpan>& clauses) {
  std::vector<std::string_view> keys;
  for (const ClauseSpan& c : clauses) keys.push_back(c.key);
  return keys;
}

/// Where `key` stands in the file's order; past the end for a key the file lacks.
std::size_t rank(const std::vector<std::string_view>& file_keys, std::string_view key) {
  return std::size_t(std::find(file_keys.begin(), file_keys.end(), key) - file_keys.begin());
}

}  // namespace

std::string in_clause_order_of(std::string_view original, std::string_view written, ObjectKind kind) {
  const std::vector<std::string_view> file_keys = keys_of(clauses_of(original, kind));
  std::vector<ClauseSpan> clauses = clauses_of(written, kind);
  if (clauses.size() < 2) return std::string(written);
  std::vector<ClauseSpan> ordered = clauses;
  // By the file's order, clauses it lacks after them in the written order (the span's start):
  // a stable sort by rank, without std::stable_sort, whose temporary buffer GCC 12's libstdc++
  // frees in a way AddressSanitizer reports as an alloc-dealloc mismatch.
  std::sort(ordered.begin(), ordered.end(), [&file_keys](const ClauseSpan& a, const ClauseSpan& b) {
    const std::size_t rank_a = rank(file_keys, a.key), rank_b = rank(file_keys, b.key);
    return rank_a != rank_b ? rank_a < rank_b : a.begin < b.begin;
  });
  if (keys_of(ordered) == keys_of(clauses)) return std::string(written);
  std::string out(written.substr(0, clauses.front().begin));
  for (const ClauseSpan& c : ordered) {
    if (&c != &ordered.front()) out += ' ';
    out += written.substr(c.begin, c.end - c.begin);
  }
  return out + std::string(written.substr(clauses.back().end));
}

}  // namespace sweep::io
