// Format-preserving SWP writing (write_swp_preserving, swp_writer.hpp): each object read from the
// file is its original text with only the tokens the edit changed rewritten, found by comparing
// the original tokens with those write_swp writes for the object now.
#include "io/swp_lexer.hpp"
#include "io/swp_parser.hpp"
#include "io/swp_writer.hpp"

#include "geometry/precondition.hpp"
#include "model/curve_evaluation.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace sweep {
namespace {

using swp_detail::Lexer;
using swp_detail::TokenType;

struct Piece {  // a token of an object's text
  TokenType type = TokenType::End;
  std::string_view text;
  std::size_t begin = 0;  // in that text
  int line = 0;
  std::size_t end() const { return begin + text.size(); }
};

std::vector<Piece> pieces_of(std::string_view text) {
  Lexer lexer(text);
  std::vector<Piece> out;
  for (auto t = lexer.next(); t.type != TokenType::End; t = lexer.next()) {
    out.push_back({t.type, t.text, lexer.offset_of(t), t.line});
  }
  return out;
}

std::optional<double> number_in(std::string_view word) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
  if (error != std::errc() || end != word.data() + word.size()) return std::nullopt;
  return value;
}

/// Digits after the point of a plain decimal number ("2.503360": 6, "3": 0); 0 for others.
int decimals_of(std::string_view word) {
  if (!number_in(word) || word.find_first_of("eEnNiI") != std::string_view::npos) return 0;
  const std::size_t point = word.find('.');
  return point == std::string_view::npos ? 0 : static_cast<int>(word.size() - point - 1);
}

/// True if the two tokens say the same: equal text, or numbers of equal value ("0.000000", "0").
bool same(const Piece& a, const Piece& b) {
  if (a.type != b.type) return false;
  if (a.text == b.text) return true;
  const std::optional<double> x = number_in(a.text), y = number_in(b.text);
  return x && y && *x == *y;
}

/// How the file writes: its line end, what it puts between objects, its size for the precision.
struct Style {
  std::string eol = "\n";
  std::string between = "\n\n";  // before a new object
  double tolerance = 0.0;        // a rewritten number may move by this much
};

/// `text` with its '\n's as the file's line ends.
std::string with_eol(std::string_view text, const Style& style) {
  std::string out;
  for (const char c : text) {
    if (c == '\n') {
      out += style.eol;
    } else {
      out += c;
    }
  }
  return out;
}

/// A changed number: with `decimals` (its line's in the file), more while that moves it by more
/// than the tolerance, the shortest exact text past 17. An integer as written (STEPS, counts).
std::string number_text_like(std::string_view written, int decimals, const Style& style) {
  const std::optional<double> value = number_in(written);
  if (!value || written.find_first_of(".eEnNiI") == std::string_view::npos) return std::string(written);
  for (int d = decimals; d <= 17; ++d) {
    char buffer[400];
    const int n = std::snprintf(buffer, sizeof buffer, "%.*f", d, *value);
    if (n <= 0 || n >= static_cast<int>(sizeof buffer)) break;
    std::string text(buffer, static_cast<std::size_t>(n));
    const double back = number_in(text).value_or(*value);
    if (std::abs(back - *value) > style.tolerance) continue;
    if (back == 0.0 && text.front() == '-') text.erase(0, 1);  // no "-0.000000"
    return text;
  }
  return std::string(written);  // write_swp's shortest exact text
}

/// Rewrites `original` (one object's text) into the text of `written` (write_swp's for it now),
/// keeping every token the two share and the bytes between them.
class ObjectPatch {
 public:
  ObjectPatch(std::string_view original, std::string_view written, const Style& style)
      : original_(original), written_(written), old_(pieces_of(original)), new_(pieces_of(written)), style_(style) {
    for (const Piece& p : old_) {
      if (p.line >= static_cast<int>(line_decimals_.size()))
        line_decimals_.resize(static_cast<std::size_t>(p.line) + 1);
      int& d = line_decimals_[static_cast<std::size_t>(p.line)];
      d = std::max(d, decimals_of(p.text));
      object_decimals_ = std::max(object_decimals_, d);
    }
  }

  /// True if every token says the same as before (the object is unchanged, clauses in order).
  bool unchanged() const {
    return old_.size() == new_.size() && std::equal(old_.begin(), old_.end(), new_.begin(), same);
  }

  std::string text() {
    // Tokens equal at both ends, then the middle paired while the kinds agree (a changed number
    // or name), from the front and from the back; what is left was deleted or inserted.
    std::size_t front = 0;
    while (front < old_.size() && front < new_.size() && same(old_[front], new_[front])) ++front;
    std::size_t back = 0;
    while (back < old_.size() - front && back < new_.size() - front &&
           same(old_[old_.size() - 1 - back], new_[new_.size() - 1 - back]))
      ++back;
    std::size_t i = front, j = front;
    for (; i < old_.size() - back && j < new_.size() - back && old_[i].type == new_[j].type; ++i, ++j) keep(i, j);
    std::size_t old_tail = old_.size() - back, new_tail = new_.size() - back;
    while (old_tail > i && new_tail > j && old_[old_tail - 1].type == new_[new_tail - 1].type) {
      --old_tail;
      --new_tail;
    }
    for (std::size_t k = 0; k < front; ++k) keep(k, k);
    // Old tokens in [i, old_tail) have no pair: deleted.
    for (std::size_t k = j; k < new_tail; ++k) inserted_after_.push_back({old_tail, k});
    for (std::size_t k = old_tail, m = new_tail; k < old_.size(); ++k, ++m) keep(k, m);
    return assemble();
  }

 private:
  void keep(std::size_t i, std::size_t j) { pairs_.push_back({i, j}); }

  /// The text of new token j where it replaces old token i (or is inserted: i = npos).
  std::string replacement(std::size_t i, std::size_t j) const {
    const int decimals = i < old_.size() ? line_decimals_[static_cast<std::size_t>(old_[i].line)] : object_decimals_;
    return number_text_like(new_[j].text, decimals, style_);
  }

  std::string assemble() {
    std::sort(pairs_.begin(), pairs_.end());
    std::vector<std::size_t> new_for(old_.size(), kNone);
    for (const auto& [i, j] : pairs_) new_for[i] = j;
    std::string out;
    std::size_t copied = 0;  // bytes of the original taken or skipped
    const auto insert_before = [&](std::size_t old_index) {
      for (const auto& [at, j] : inserted_after_) {
        if (at != old_index) continue;
        const std::size_t gap_begin = j > 0 ? new_[j - 1].end() : 0;
        out += with_eol(written_.substr(gap_begin, new_[j].begin - gap_begin), style_);
        out += replacement(kNone, j);
      }
    };
    for (std::size_t i = 0; i < old_.size(); ++i) {
      insert_before(i);
      if (new_for[i] == kNone) {  // deleted, with the spaces before it
        copied = old_[i].end();
        continue;
      }
      out += original_.substr(copied, old_[i].begin - copied);
      const Piece& replaced = new_[new_for[i]];
      out += same(old_[i], replaced) ? std::string(old_[i].text) : replacement(i, new_for[i]);
      copied = old_[i].end();
    }
    insert_before(old_.size());
    out += original_.substr(copied);
    return out;
  }

  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::string_view original_;
  std::string_view written_;
  std::vector<Piece> old_;
  std::vector<Piece> new_;
  const Style& style_;
  std::vector<int> line_decimals_;
  int object_decimals_ = 0;
  std::vector<std::pair<std::size_t, std::size_t>> pairs_;           // (old, new) kept or replaced
  std::vector<std::pair<std::size_t, std::size_t>> inserted_after_;  // (before old index, new)
};

bool read_from_source(const Object& o) {
  return o.location.end > o.location.begin;
}

/// The spaces just before byte `at`: the blank lines and line ends in front of an object.
std::string_view spaces_before(std::string_view text, std::size_t at) {
  std::size_t from = at;
  while (from > 0 && swp_detail::is_space(text[from - 1])) --from;
  return text.substr(from, at - from);
}

Style style_of(const Document& doc, std::string_view source) {
  Style style;
  if (source.find("\r\n") != std::string_view::npos) style.eol = "\r\n";
  for (std::size_t k = 1; k < doc.objects.size(); ++k) {  // the first gap between two read objects
    if (read_from_source(doc.objects[k]) && read_from_source(doc.objects[k - 1])) {
      style.between = std::string(spaces_before(source, doc.objects[k].location.begin));
      break;
    }
  }
  if (style.between.empty()) style.between = style.eol + style.eol;
  style.tolerance = 1e-6 * document_extent(doc);
  return style;
}

/// The objects as the file had them, by the byte where each starts: what tells an unchanged
/// object whose clauses the file gives in another order than write_swp. Read once, when first
/// needed; empty if the file no longer reads (an image gone since).
class OriginalObjects {
 public:
  explicit OriginalObjects(const SourceText& source) : source_(source) {}

  /// True if `o`, in `doc`, is as it was read: the same name and data, and the objects it
  /// refers to (by index) have the names they had.
  bool unchanged(const Object& o, const Document& doc) {
    if (!read_) {
      read_ = true;
      try {
        doc_ = parse_swp(*source_.text, source_.file_name);
      } catch (const ParseError&) {
        doc_.objects.clear();
      }
    }
    const auto it = std::lower_bound(doc_.objects.begin(), doc_.objects.end(), o.location.begin,
                                     [](const Object& a, std::size_t at) { return a.location.begin < at; });
    if (it == doc_.objects.end() || it->location.begin != o.location.begin || !(*it == o)) return false;
    for (const int r : references(o)) {
      const auto k = static_cast<std::size_t>(r);
      if (r >= 0 &&
          (k >= doc_.objects.size() || k >= doc.objects.size() || doc_.objects[k].name != doc.objects[k].name))
        return false;
    }
    return true;
  }

 private:
  const SourceText& source_;
  bool read_ = false;
  Document doc_;
};

}  // namespace

std::string write_swp_preserving(const Document& doc) {
  SWEEP_EXPECTS(doc.source.text != nullptr, "doc.source.text is set");
  const std::string_view source = *doc.source.text;
  const Style style = style_of(doc, source);
  OriginalObjects originals(doc.source);
  const std::size_t content_begin = std::min(source.find_first_not_of(" \t\n\r\f\v"), source.size());
  std::string out;
  for (const Object& o : doc.objects) {
    const std::string written = object_text(doc, o);
    const bool first = &o == &doc.objects.front();
    if (!read_from_source(o)) {
      out += first ? std::string() : style.between;
      std::string_view lines(written);
      while (!lines.empty() && lines.back() == '\n') lines.remove_suffix(1);
      out += with_eol(lines, style);
      continue;
    }
    SWEEP_EXPECTS(o.location.end <= source.size(), "every object's span is in doc.source");
    const std::string_view original = source.substr(o.location.begin, o.location.end - o.location.begin);
    out += spaces_before(source, first ? content_begin : o.location.begin);
    ObjectPatch patch(original, written, style);
    if (patch.unchanged() || originals.unchanged(o, doc)) {
      out += original;
    } else {
      out += patch.text();
    }
  }
  // The file's end as it was: its last line end, or none, or trailing blanks.
  const std::size_t content_end = source.find_last_not_of(" \t\n\r\f\v");
  if (!doc.objects.empty()) out += source.substr(content_end == std::string_view::npos ? 0 : content_end + 1);
  return out;
}

}  // namespace sweep
