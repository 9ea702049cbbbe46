// Format-preserving SWP writing (write_swp_preserving, swp/write.hpp): each object read from the
// file is its original text with only the tokens the edit changed rewritten, found by comparing
// the original tokens with those write_swp writes for the object now.
#include "io/swp/clause_order.hpp"
#include "io/swp/detail/lexer.hpp"
#include "io/swp/detail/patch_tokens.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "base/precondition.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sweep::io {
namespace {

using namespace swp_detail;  // the lexer, and the pieces and numbers of swp/detail/patch_tokens.hpp

/// True unless `o` also lists integers in brackets (a cage's faces), which stay integers.
bool has_only_points_in_brackets(const Object& o) {
  return o.find<PolygonMeshSurface>() == nullptr;
}

/// Rewrites `original` (one object's text) into the text of `written` (write_swp's for it now),
/// keeping every token the two share and the bytes between them.
class ObjectPatch {
 public:
  /// `o`: the object both texts are of.
  ObjectPatch(std::string_view original, std::string_view written, const Style& style, const Document& doc,
              const Object& o)
      : original_(original),
        written_(written),
        old_(pieces_of(original)),
        new_(pieces_of(written)),
        style_(style),
        coordinates_in_brackets_(has_only_points_in_brackets(o)) {
    for (Piece& p : new_) {
      p.format_word = p.type == TokenType::Word && std::isalpha(static_cast<unsigned char>(p.text.front())) &&
                      doc.find(p.text) < 0 && std::none_of(p.text.begin(), p.text.end(), [](char c) {
                        return std::isupper(static_cast<unsigned char>(c));
                      });
    }
  }

  /// True if every token says the same as before (the object is unchanged, clauses in order).
  bool unchanged() const {
    return old_.size() == new_.size() && std::equal(old_.begin(), old_.end(), new_.begin(), same);
  }

  std::string text() {
    // Tokens equal at both ends; in a short middle the longest run of equal tokens in order
    // stays too (a clause kept between changed ones); between those, tokens paired while their
    // kinds agree (a changed number or name), from the front and from the back; what is left
    // was deleted or inserted.
    const std::size_t n = old_.size(), m = new_.size();
    std::size_t front = 0;
    while (front < n && front < m && same(old_[front], new_[front])) ++front;
    std::size_t back = 0;
    while (back < n - front && back < m - front && same(old_[n - 1 - back], new_[m - 1 - back])) ++back;
    out_ = std::string(original_.substr(0, front > 0 ? old_[front - 1].end() : 0));
    copied_ = out_.size();
    std::size_t a = front, b = front;
    for (const auto& [kept_a, kept_b] : equal_in_middle(front, n - back, front, m - back)) {
      gap(a, kept_a, b, kept_b);
      pair(kept_a, kept_b);
      a = kept_a + 1;
      b = kept_b + 1;
    }
    gap(a, n - back, b, m - back);
    out_ += original_.substr(copied_);  // the equal end, as it was
    return std::move(out_);
  }

 private:
  /// Old token a written as new token b (its text kept when the two say the same).
  void pair(std::size_t a, std::size_t b) {
    out_ += original_.substr(copied_, old_[a].begin - copied_);
    out_ += same(old_[a], new_[b]) ? std::string(old_[a].text) : replacement(a, b);
    copied_ = old_[a].end();
  }

  /// Old tokens [a0, a1) written as new tokens [b0, b1), none of which say the same in order.
  void gap(std::size_t a0, std::size_t a1, std::size_t b0, std::size_t b1) {
    std::size_t i = a0, j = b0;
    while (i < a1 && j < b1 && old_[i].type == new_[j].type) ++i, ++j;
    std::size_t old_tail = a1, new_tail = b1;
    while (old_tail > i && new_tail > j && old_[old_tail - 1].type == new_[new_tail - 1].type) --old_tail, --new_tail;
    for (std::size_t x = a0, y = b0; x < i; ++x, ++y) pair(x, y);
    if (old_tail > i) copied_ = old_[old_tail - 1].end();  // deleted, with the spaces before each
    for (std::size_t y = j; y < new_tail; ++y) {
      const std::size_t gap_begin = y > 0 ? new_[y - 1].end() : 0;
      out_ += with_eol(written_.substr(gap_begin, new_[y].begin - gap_begin), style_);
      out_ += replacement(kNone, y);
    }
    for (std::size_t x = old_tail, y = new_tail; x < a1; ++x, ++y) pair(x, y);
  }

  /// The pairs (a, b) of a longest sequence of old tokens in [a0, a1) that say the same as new
  /// tokens in [b0, b1), in order; none when either side is longer than kShortMiddle (a quadratic
  /// table: an object's line of clauses, not its million points).
  std::vector<std::pair<std::size_t, std::size_t>> equal_in_middle(std::size_t a0, std::size_t a1, std::size_t b0,
                                                                   std::size_t b1) const {
    constexpr std::size_t kShortMiddle = 64;
    const std::size_t na = a1 - a0, nb = b1 - b0;
    if (na == 0 || nb == 0 || na > kShortMiddle || nb > kShortMiddle) return {};
    // longest[i][j]: the longest such sequence in old [a0 + i, a1) and new [b0 + j, b1).
    std::vector<std::vector<std::size_t>> longest(na + 1, std::vector<std::size_t>(nb + 1, 0));
    for (std::size_t i = na; i-- > 0;) {
      for (std::size_t j = nb; j-- > 0;) {
        longest[i][j] = same(old_[a0 + i], new_[b0 + j]) ? longest[i + 1][j + 1] + 1
                                                         : std::max(longest[i + 1][j], longest[i][j + 1]);
      }
    }
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0, j = 0; i < na && j < nb;) {
      if (same(old_[a0 + i], new_[b0 + j])) {
        pairs.emplace_back(a0 + i++, b0 + j++);
      } else if (longest[i + 1][j] >= longest[i][j + 1]) {
        ++i;
      } else {
        ++j;
      }
    }
    return pairs;
  }

  /// The most decimals of any number of the object in the file.
  int most_decimals() const {
    int d = 0;
    for (const Piece& p : old_) d = std::max(d, decimals_of(p.text));
    return d;
  }

  /// The text of new token b where it replaces old token a (or is inserted: a = kNone).
  std::string replacement(std::size_t a, std::size_t b) {
    if (a == kNone) {
      if (object_decimals_ < 0) object_decimals_ = most_decimals();
      return number_text_like(new_[b].text, object_decimals_, style_, coordinate(b));
    }
    // The old token's line: the tokens next to it (a point is one line; no scan of the object).
    int d = decimals_of(old_[a].text);
    for (std::size_t k = a; k-- > 0 && old_[k].line == old_[a].line;) d = std::max(d, decimals_of(old_[k].text));
    for (std::size_t k = a + 1; k < old_.size() && old_[k].line == old_[a].line; ++k)
      d = std::max(d, decimals_of(old_[k].text));
    return number_text_like(new_[b].text, d, style_, coordinate(b));
  }

  bool coordinate(std::size_t b) const { return coordinates_in_brackets_ && new_[b].in_point; }

  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::string_view original_;
  std::string_view written_;
  std::vector<Piece> old_;
  std::vector<Piece> new_;
  const Style& style_;
  int object_decimals_ = -1;  // not yet known
  bool coordinates_in_brackets_;
  std::string out_;         // text() being written
  std::size_t copied_ = 0;  // bytes of the original taken or skipped so far
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

/// The decimals most of the numbers inside the file's points have ("[ 0.000000 2.503360 ]": 6),
/// from its first 4096 such numbers; 0 when none is written with a point (a new point then gets
/// as few as the tolerance needs, as in a new document: write_swp_rounded).
int point_decimals_of(std::string_view source) {
  constexpr int kSampled = 4096;
  std::array<int, 18> counts{};
  int sampled = 0, depth = 0;
  Lexer lexer(source);
  for (auto t = lexer.next(); t.type != TokenType::End && sampled < kSampled; t = lexer.next()) {
    depth += t.type == TokenType::Open ? 1 : t.type == TokenType::Close ? -1 : 0;
    if (t.type != TokenType::Word || depth <= 0 || t.text.find('.') == std::string_view::npos) continue;
    const int d = decimals_of(t.text);
    if (d > 0 && d < int(counts.size())) ++counts[std::size_t(d)], ++sampled;
  }
  if (sampled == 0) return 0;
  return int(std::max_element(counts.begin(), counts.end()) - counts.begin());
}

/// A new object's text (write_swp's) in the file's style: its line ends, and the numbers of its
/// points at the decimals the file's points use (more where the tolerance needs them). The one
/// rule for points placed in the editor, in a file read or a new document (write_swp_rounded).
std::string new_object_text(std::string_view written, const Object& o, const Style& style) {
  if (!has_only_points_in_brackets(o)) return with_eol(written, style);
  std::string out;
  std::size_t copied = 0;
  for (const Piece& piece : pieces_of(written)) {
    if (!piece.in_point || style.point_decimals < 0) continue;
    out.append(written.substr(copied, piece.begin - copied));
    out += number_text_like(piece.text, style.point_decimals, style, true);
    copied = piece.end();
  }
  out.append(written.substr(copied));
  return with_eol(out, style);
}

/// The objects as the file had them, by the byte where each starts: what tells an object that
/// says the same as before in other words (its clauses in another order, a clause at its default
/// value written out, a keyword in capitals), which only reading it can. Read once per save,
/// when first needed; empty if the file no longer reads (an image gone since).
class OriginalObjects {
 public:
  explicit OriginalObjects(const SourceText& source) : source_(source) {}

  enum class Same { Whole, AllButPoints, AllButPointsAndCounts, Neither };

  /// Whether `o`, in `doc`, is as it was read: wholly, or but for its points (and a cage's faces),
  /// of the same number or not; the objects it refers to (by index) must have the names they had.
  Same compare(const Object& o, const Document& doc) {
    const Object* was = original_of(o);
    if (!was || !same_names(o, doc)) return Same::Neither;
    if (*was == o) return Same::Whole;
    const auto* points = o.find<PointsPart>();
    if (!points) return Same::Neither;
    Object header = *was;
    header.as<PointsPart>().points = points->points;
    const auto* cage = o.find<PolygonMeshSurface>();
    if (cage) {
      header.as<PolygonMeshSurface>().face_sizes = cage->face_sizes;
      header.as<PolygonMeshSurface>().face_vertices = cage->face_vertices;
    }
    if (!(header == o)) return Same::Neither;
    // The same number of points (and faces): the counts on the line of fields stay right.
    const bool same_counts = points->points.size() == was->as<PointsPart>().points.size() &&
                             (!cage || cage->face_sizes.size() == was->as<PolygonMeshSurface>().face_sizes.size());
    return same_counts ? Same::AllButPoints : Same::AllButPointsAndCounts;
  }

  /// The object as the file had it. Precondition: compare(o, ...) said it is one of the file's.
  const Object& original(const Object& o) {
    const Object* was = original_of(o);
    SWEEP_EXPECTS(was != nullptr, "o was read from the file");
    return *was;
  }

 private:
  const Object* original_of(const Object& o) {
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
    return it != doc_.objects.end() && it->location.begin == o.location.begin ? &*it : nullptr;
  }

  bool same_names(const Object& o, const Document& doc) const {
    for (const int r : references(o)) {
      const auto k = static_cast<std::size_t>(r);
      if (r >= 0 &&
          (k >= doc_.objects.size() || k >= doc.objects.size() || doc_.objects[k].name != doc.objects[k].name))
        return false;
    }
    return true;
  }

  const SourceText& source_;
  bool read_ = false;
  Document doc_;
};

/// The line of fields and clauses as the file has it (`original`), with only its counts changed:
/// the tokens in which write_swp's text of the object as it was (`was`) and as it is (`now`)
/// differ, each found at the same place in `original`; nullopt when one is not there (the
/// fields are written in another way), and the whole object is then patched instead.
std::optional<std::string> fields_with_new_counts(std::string_view original, std::string_view was,
                                                  std::string_view now) {
  const std::vector<Piece> in_file = pieces_of(original), before = pieces_of(was), after = pieces_of(now);
  if (before.size() != after.size()) return std::nullopt;
  std::string out;
  std::size_t copied = 0;
  for (std::size_t k = 0; k < after.size(); ++k) {
    if (same(before[k], after[k])) continue;
    if (k >= in_file.size() || !same(in_file[k], before[k])) return std::nullopt;
    out += original.substr(copied, in_file[k].begin - copied);
    out += after[k].text;
    copied = in_file[k].end();
  }
  return out + std::string(original.substr(copied));
}

/// The text of object `o` read from `original`, now written as `written`.
std::string object_text_preserved(std::string_view original, const std::string& written, const Object& o,
                                  const Document& doc, const Style& style, OriginalObjects& originals) {
  ObjectPatch patch(original, written, style, doc, o);
  if (patch.unchanged()) return std::string(original);
  const OriginalObjects::Same same = originals.compare(o, doc);
  if (same == OriginalObjects::Same::Whole) return std::string(original);
  const std::size_t points_in_original = original.find('['), points_in_written = written.find('[');
  if (same == OriginalObjects::Same::Neither || points_in_original == std::string_view::npos ||
      points_in_written == std::string::npos) {
    // Clauses the file orders otherwise are patched in its order: only changed values differ.
    const std::string reordered = in_clause_order_of(original, written, o.kind());
    return reordered == written ? patch.text() : ObjectPatch(original, reordered, style, doc, o).text();
  }
  const std::string_view fields = original.substr(0, points_in_original);
  const std::string_view written_fields = std::string_view(written).substr(0, points_in_written);
  std::optional<std::string> kept(fields);
  if (same == OriginalObjects::Same::AllButPointsAndCounts) {
    const std::string was = object_text(doc, originals.original(o));
    kept = fields_with_new_counts(fields, std::string_view(was).substr(0, was.find('[')), written_fields);
    if (!kept) return patch.text();
  }
  // The line of fields and clauses as the file has it (its counts updated); only the points patched.
  return *kept + ObjectPatch(original.substr(points_in_original), std::string_view(written).substr(points_in_written),
                             style, doc, o)
                     .text();
}

/// True if `text` reads back as the document whose write_swp text is `expected`, numbers within
/// the tolerance: write_swp of both, token by token. What makes the format-preserving text safe
/// to save whatever the patch did.
bool reads_back_as(const std::string& text, const std::string& expected, const Document& doc, const Style& style) {
  Document back;
  try {
    back = parse_swp(text, doc.source.file_name);
  } catch (const ParseError&) {
    return false;
  }
  const std::string got = write_swp(back);
  const std::vector<Piece> a = pieces_of(expected), b = pieces_of(got);
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k].type != b[k].type) return false;
    if (a[k].text == b[k].text) continue;
    const std::optional<double> x = number_in(a[k].text), y = number_in(b[k].text);
    if (!x || !y || !(std::abs(*x - *y) <= style.tolerance * (1.0 + 1e-9))) return false;
  }
  return true;
}

}  // namespace

std::string write_swp_rounded(const Document& doc) {
  Style style;  // a new file's: '\n' line ends, a blank line between objects
  style.tolerance = 1e-6 * document_extent(doc);
  style.point_decimals = 0;  // every object new, in a file whose points have no decimals
  std::string out;
  std::string canonical;  // write_swp(doc)
  for (const Object& o : doc.objects) {
    const std::string written = object_text(doc, o);
    (canonical += written) += '\n';
    (out += new_object_text(written, o, style)) += '\n';
  }
  return reads_back_as(out, canonical, doc, style) ? out : canonical;
}

std::string write_swp_preserving(const Document& doc) {
  SWEEP_EXPECTS(doc.source.text != nullptr, "doc.source.text is set");
  const std::string_view source = *doc.source.text;
  if (doc.objects.empty()) {  // a file of blanks stays as it was; one whose objects all went is empty
    return source.find_first_not_of(" \t\n\r\f\v") == std::string_view::npos ? std::string(source) : std::string();
  }
  Style style = style_of(doc, source);
  if (!std::all_of(doc.objects.begin(), doc.objects.end(), read_from_source)) {
    style.point_decimals = point_decimals_of(source);
  }
  OriginalObjects originals(doc.source);
  const std::size_t content_begin = std::min(source.find_first_not_of(" \t\n\r\f\v"), source.size());
  std::string out;
  std::string canonical;  // what write_swp(doc) writes: each object's lines and a blank line
  for (const Object& o : doc.objects) {
    const std::string written = object_text(doc, o);
    (canonical += written) += '\n';
    const bool first = &o == &doc.objects.front();
    if (!read_from_source(o)) {
      out += first ? std::string() : style.between;
      std::string_view lines(written);
      while (!lines.empty() && lines.back() == '\n') lines.remove_suffix(1);
      out += new_object_text(lines, o, style);
      continue;
    }
    SWEEP_EXPECTS(o.location.end <= source.size(), "every object's span is in doc.source");
    const std::string_view original = source.substr(o.location.begin, o.location.end - o.location.begin);
    out += spaces_before(source, first ? content_begin : o.location.begin);
    out += object_text_preserved(original, written, o, doc, style, originals);
  }
  // The file's end as it was: its last line end, or none, or trailing blanks.
  const std::size_t content_end = source.find_last_not_of(" \t\n\r\f\v");
  out += source.substr(content_end == std::string_view::npos ? 0 : content_end + 1);
  // Saving never loses data: should the patched text read back as anything else, the canonical one.
  return reads_back_as(out, canonical, doc, style) ? out : write_swp(doc);
}

}  // namespace sweep::io
