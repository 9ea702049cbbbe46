#pragma once
// The SWP reader's internals (src/io only): the Parser class, whose readers live in
// swp/read.cpp (objects, names, references, clauses, caps), swp/reader_fields.cpp (the fixed
// fields every kind lists in model/object.hpp, and points) and swp/reader_surfaces.cpp (the kinds
// with a syntax of their own: patches, cages, subdivision, materials), and the helpers their
// messages share.
#include "io/swp/detail/lexer.hpp"
#include "model/caps.hpp"
#include "model/clauses.hpp"
#include "model/document.hpp"
#include "model/file_limits.hpp"
#include "model/surface_validation.hpp"

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace sweep::io::swp_detail {

/// "a keyword (bez2, bez3, ...)".
const std::string& expected_keyword();
/// True if `word` is `key` (lower case) up to case: keys and keywords are case-insensitive.
bool equal_key(std::string_view word, std::string_view key);
/// The clause with key `word` (case-insensitively), or nullptr.
const SwpClause* find_clause(std::span<const SwpClause> clauses, std::string_view word);
/// "a clause (alpha, tension)".
std::string clause_list(std::span<const SwpClause> clauses);

class Parser : private TokenReader {
 public:
  Parser(std::string_view text, std::string_view file) : TokenReader(text, file) {}

  Document parse();

 private:
  /// Reads the fields a kind lists (its `fields`, object.hpp): swp/reader_fields.cpp.
  struct FieldReader;
  /// The fields after the name, then the optional clauses (for point curves: before the points).
  void read_fields(Object& object, const Document& doc);
  /// What the referenced curves' samples must satisfy (sweep_controls.hpp), reported at the
  /// reference or clause it is about.
  void check_curves(const Object& object, const Document& doc);
  /// Reads the optional `key value` clauses of `object`, each at most once, in any order. They
  /// end at the first token that cannot start one: a bracket, the end, or (where no points
  /// follow) a keyword. `instead` says what else may come there, for the message.
  void read_clauses(Object& object, const Document& doc, const std::string& instead);
  /// `material` is both a keyword and a surface's clause key: it is the clause when the name after
  /// it is taken already (a new material needs a new name); the clause then says if it is not a
  /// material.
  bool material_clause_follows(std::span<const SwpClause> clauses);
  /// A clause value that is a number rather than a name: names start with a letter or '_'.
  static bool starts_number(const Token& token);
  void read_name(Object& object, const Document& doc);
  /// The index of the earlier object `token` names, or a failure saying `expected` and why not.
  int find_named(const Token& token, const std::string& expected);
  int read_reference(const Document& doc, const char* role, bool planar_only);
  // Only on the error path: does a later object take this name?
  bool defined_later(std::string_view name);
  void check_mesh(const Token& at, std::int64_t vertices);
  /// A count of points of `what` ("this curve") that adds to the document's total (an error at
  /// `count_token` beyond it).
  void count_points(std::int64_t count, const Token& count_token, const char* what = "this object");
  /// Checks a curve's sample count against the caps. The error is at STEPS, or for the
  /// document's total at `at` if given (a helix's TURNS).
  void check_samples(std::int64_t samples, const Token* at = nullptr);

  void read_points(Object& object, std::int64_t count);

  void read_bezier_patch(Object& object, const Document& doc);
  void read_bspline_patch(Object& object, const Document& doc);
  /// `mesh NAME NV NF`, NV points, NF faces `[i j k ...]` of 0-based vertex indices.
  void read_polygon_mesh(Object& object, const Document& doc);
  /// One face: '[', at least 3 vertex indices, ']'. Returns its '['.
  Token read_face(Object& object, std::int64_t face, std::int64_t faces, std::int64_t vertices);
  /// `subd NAME LEVELS SOURCE`: SOURCE is an earlier mesh or grid surface.
  void read_subdivision(Object& object, const Document& doc);
  /// Loop needs triangles; the refined mesh must fit the caps (checked before refining).
  void check_subdivision(const Object& object, const Document& doc);
  int read_material_reference(const Document& doc);
  /// A rider's MODEL: the name of a surface defined above.
  int read_model_reference(const Document& doc);
  /// A clause of three numbers (`up X Y Z`), checked as a whole at its first number.
  void read_vector_clause(Object& object, const SwpClause& clause);
  /// `material NAME [color R G B] [shininess S] [texture FILE.png | checker N] [bump FILE.png H]`,
  /// each clause at most once, in any order; image files are checked here (material.hpp): one
  /// that is not there is a warning, not an error (Document::missing_images).
  void read_material(Object& object);
  void read_material_clause(Object& object, std::string_view key);
  /// An image file name, checked to be a PNG that stb_image reads, relative to the SWP file.
  /// `role` names it in an error ("texture"), `image` in the warning for a missing one
  /// ("texture", "bump image"), which goes to missing_images_ while the file reads on.
  std::string read_image_path(const char* role, const char* image);
  /// A missing image's name is quoted whole in its warning up to this length.
  static constexpr std::size_t kMaxWarnedPathBytes = 256;

  int read_steps() { return static_cast<int>(read_integer("STEPS", 1, limits::kMaxSteps, &steps_token_)); }

  std::unordered_map<std::string, int> names_;
  Token steps_token_;
  Token tolerance_token_;  // where the current object's tolerance clause gave its value
  // Where the current surface named its profile, second rail, scale and twist.
  Token profile_token_;
  Token rail2_token_;
  Token scale_token_;
  Token twist_token_;
  Token loop_token_;    // the current subd's `loop`
  Token levels_token_;  // and its LEVELS
  std::int64_t source_vertices_ = 0;
  // Vertices the current surface will have (0 for curves), and those of every object read.
  std::int64_t estimated_vertices_ = 0;
  std::vector<std::int64_t> vertex_estimates_;
  CapTally caps_;
  std::vector<MissingImage> missing_images_;  // Document::missing_images, in file order
};

}  // namespace sweep::io::swp_detail
