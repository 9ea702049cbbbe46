#pragma once
// The document's size caps (model/file_limits.hpp), stated once. The reader adds each object's
// counts as it reads them and reports a breach at the token it is about (file:line:column); the
// editor adds the counts of the document it would make and names the object. Both say the
// words below.
#include "model/document.hpp"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace sweep {

/// A cap that an object breaks, in the reader's words: "expected at most 10000000 samples per
/// curve" and the note "STEPS 100000 gives 20100001".
struct CapBreach {
  bool whole_document = false;  // the document's total, not the object's own cap
  std::string expected;
  std::string note;
};

/// The running totals of a document, object by object, in file order.
class CapTally {
 public:
  /// `count` control points of `what` ("this curve", "this object"): the document's total.
  std::optional<CapBreach> add_points(std::int64_t count, const char* what);
  /// A mesh face's `corners`, which cost memory like points: the document's total of both.
  std::optional<CapBreach> add_face_corners(std::int64_t corners);
  /// A curve's `samples`, which `cause` gives ("STEPS 100000 gives", "STEPS 5 and TURNS 3
  /// give"): the cap per curve, then the document's total.
  std::optional<CapBreach> add_samples(std::int64_t samples, const std::string& cause);
  /// A surface's `vertices`: the cap per surface, then the document's total.
  std::optional<CapBreach> add_vertices(std::int64_t vertices);

 private:
  std::int64_t points_ = 0;
  std::int64_t samples_ = 0;
  std::int64_t vertices_ = 0;
};

/// "expected at most 10000000 samples per curve".
std::string expected_samples_per_curve();

/// The object at an index of the document being checked (the editor's document with an edit
/// applied).
using ObjectAt = std::function<const Object&(int index)>;

/// What `o` adds to the document's counts: its control points, a curve's samples (and what gives
/// them, for add_samples), a surface's vertices. `vertices_of(i)`: what object i (earlier) has,
/// for a subd's source. Precondition: its references name earlier objects, valid in `object_at`.
struct ObjectCounts {
  std::int64_t points = 0;
  std::int64_t face_corners = 0;  // a mesh's
  std::int64_t samples = 0;
  std::string samples_cause;
  std::int64_t vertices = 0;
};
ObjectCounts object_counts(const Object& o, const ObjectAt& object_at,
                           const std::function<std::int64_t(int index)>& vertices_of);

/// The vertices of a subdivision of `source` (its cage: `source_vertices`) `levels` times: a mesh
/// refined exactly, a grid or subd by about 4 a level (at most until past the cap).
std::int64_t subdivision_vertex_count(const SubdivisionSurface& subd, const Object& source,
                                      std::int64_t source_vertices);

/// The work of evaluating objects `indices` of `doc`: their curve samples, surface vertices and
/// control points, as object_counts gives them. The editor evaluates an edit whose work passes a
/// threshold in the background. Precondition: `doc` is valid and the indices are in range.
std::int64_t evaluation_work(const Document& doc, const std::vector<int>& indices);

/// The first breach of `count` objects (object_at(0) ... object_at(count - 1)), with the index of
/// the object that breaks it; nullopt if the document fits.
std::optional<std::pair<int, CapBreach>> first_cap_breach(int count, const ObjectAt& object_at);

}  // namespace sweep
