#pragma once
// The SWP document: the objects of a file in file order, as the editor changes and saves them.
#include "base/number_text.hpp"
#include "model/object.hpp"

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sweep {

/// Everything that describes a kind as a whole: its type's traits (object.hpp) and its
/// enumerator. The reader, writer, messages, editor and panels read it instead of listing kinds.
struct KindInfo : KindTraits {
  ObjectKind kind;
};

/// Every kind, in the order messages list them (curves, surfaces, materials, then riders).
std::span<const KindInfo> kinds();
/// The row of `kind`.
const KindInfo& kind_info(ObjectKind kind);

/// "bez2, bez3, ..." for the kinds `wanted` accepts.
template <typename Predicate>
inline std::string keyword_list(Predicate wanted) {
  std::string out;
  for (const KindInfo& kind : kinds()) {  // in the order messages list them
    if (!wanted(kind.kind)) continue;
    if (!out.empty()) out += ", ";
    out += kind.keyword;
  }
  return out;
}

/// The SWP keyword of a kind, lower case ("bez2", "srev", ...).
std::string_view keyword(ObjectKind kind);
/// A kind in a sentence: "a B-spline", "a polyline", "a surface of revolution".
std::string_view phrase(ObjectKind kind);
/// The kind of a keyword, case-insensitively; nullopt if it is none.
std::optional<ObjectKind> kind_from_keyword(std::string_view word);

/// Curves, surfaces, materials and riders: every object is exactly one of them.
bool is_curve(ObjectKind kind);
bool is_surface(ObjectKind kind);
bool is_material(ObjectKind kind);
bool is_rider(ObjectKind kind);
/// True for the 2D curves (bez2, circ, ...: KindTraits::planar), which lie in the xy-plane.
bool is_planar_curve(ObjectKind kind);
/// True for curves defined by control points (KindTraits::points is ControlPoints).
bool has_control_points(ObjectKind kind);
/// True for bezpatch, bsppatch and mesh: surfaces defined by a net of 3D control points.
bool has_control_net(ObjectKind kind);
/// Curves with control points and surfaces with a control net: objects whose points one edits.
bool has_editable_points(ObjectKind kind);
/// What the reader says of `object`'s point count ("expected ..."), or "" when it is one the reader
/// takes or the kind has no count rule (its `count_problem`).
std::string count_problem(const Object& object);
/// How the points of `kind` are laid out and edited (its traits' `points`, point_layout.hpp).
const PointLayout& point_layout(ObjectKind kind);
/// True for curves through their points (cr, kb, poly: KindTraits::interpolating), one segment
/// between consecutive points; closed when the last point equals the first.
bool is_interpolating(ObjectKind kind);

/// The objects `object` refers to (profile, sweep or rails, scale, twist curve, subd source,
/// material, a rider's path and model), in that order; -1 where one is optional and not given. References always point
/// to earlier objects.
std::vector<int> references(const Object& object);
/// The same references as fields to change (an object inserted or erased before them moves
/// them); one list, so no edit can forget one.
std::vector<int*> reference_slots(Object& object);

/// The curves a swept surface (srev, gcyl, birail) is built from: its profile, the path it is
/// swept along (gcyl: the sweep; birail: the first rail; srev: none) and a birail's second rail;
/// -1 where it has none. All -1 for other objects.
struct SweptCurves {
  int profile = -1;
  int path = -1;
  int rail2 = -1;
};
SweptCurves swept_curves(const Object& object);
/// An object's own tolerance clause (TolerancePart), 0 for kinds without one.
double own_tolerance(const Object& object);
/// The points of an object with points (PointsPart), empty for the others.
std::span<const glm::dvec3> points_of(const Object& object);

/// The text a document was read from, shared by its copies (the history's snapshots); saving
/// writes back every token an edit did not change as it was there (swp/write.hpp). Ignored by ==.
struct SourceText {
  std::shared_ptr<const std::string> text;  // null: the document was not read from a file
  std::string file_name;                    // as it was read (images are found beside it)
  bool operator==(const SourceText&) const { return true; }
};

/// An image a material names that was not there when the file was read (an SWP file copied
/// without its PNGs). The reader accepts the file with this warning; renderers draw a magenta and
/// black checker in the image's place (SurfaceMaterial::placeholder); the exports, which copy or
/// embed the image, refuse as they do for any image they cannot read. Only a missing file: an
/// image that is there but not a PNG stb_image reads is still the reader's error.
struct MissingImage {
  std::string path;  // as the file writes it: relative to the file's folder, or absolute
  /// "FILE:LINE:COLUMN: warning: texture 'wood.png' not found; drawn as a magenta checker" (or
  /// "bump image 'grain.png'"), at the image's name in the file.
  std::string warning;
  bool operator==(const MissingImage&) const = default;
};

struct Document {
  std::vector<Object> objects;
  SourceText source;
  /// The images the reader did not find, in file order; empty for a document made in memory.
  /// What was beside the file when it was read, not what the document says: == ignores them.
  std::vector<MissingImage> missing_images;

  /// Index of the object with this name, or -1. Anonymous objects are never found.
  int find(std::string_view name) const;
  bool operator==(const Document& other) const { return objects == other.objects; }
};

/// True for a valid SWP object name: a letter or '_' followed by letters, digits, '_', '-' or
/// '.', at most limits::kMaxNameLength bytes (names become file names on export).
bool is_valid_object_name(std::string_view name);

/// `text` for a message: at most `max_bytes` bytes, control and non-ASCII bytes as \xHH, and
/// "..." when cut, so binary junk in a file never garbles a terminal.
std::string printable_excerpt(std::string_view text, std::size_t max_bytes);

/// True if `a` and `b` differ at most in the case of ASCII letters (keywords and clause keys are
/// read in any case).
bool equal_ignoring_case(std::string_view a, std::string_view b);

/// A display name: the object's name, or "kind#index" for an anonymous one.
std::string display_name(const Document& doc, int index);

/// Number of cubic pieces of a control-point curve with `count` points (0 if too few; cr/kb:
/// count - 1 segments).
std::int64_t piece_count(ObjectKind kind, std::int64_t count);
/// Number of samples a curve evaluates to (pieces * steps + 1; circle and knot: steps + 1;
/// helix: ceil(steps * turns) + 1).
std::int64_t curve_sample_count(const Object& curve);
/// The number an object's file line writes as STEPS: a curve's or a patch's segments
/// (StepsPart::steps), a surface of revolution's copies (CopiesPart::copies); nullptr for the
/// kinds without one (polylines, gcyl, birail, mesh, subd, materials, riders).
int* steps_field(Object& object);
const int* steps_field(const Object& object);

}  // namespace sweep
