#pragma once
// Can a printer print it? The checks a slicer (or Blender's 3D-Print Toolbox) would make, run on
// the print model (print_model.hpp) and each naming the SWP object that fails it and its line:
// `sweep check`, every 3MF or STL export, and the viewer's Export dialog report them.
#include "model/document.hpp"
#include "model/print/print_model.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace sweep {

enum class PrintCheck {
  Open,              // boundary edges: holes in the surface
  NonManifold,       // edges of more than two triangles
  Orientation,       // neighbours facing opposite ways, or a closed shell inside out
  SelfIntersection,  // the surface passes through itself
  Intersection,      // two surfaces cross where one of them is open (a slicer cannot tell inside)
  Overlap,           // two closed surfaces overlap: a note, the slicer prints them as one solid
  ThinWall,          // walls thinner than the smallest a nozzle prints
  Floating,          // parts that touch nothing below them
};

/// One finding: the check, the surface (its object's index in the document) and, for two
/// surfaces, the other; where it is, in millimetres on the plate and in model coordinates (the
/// viewer marks it there); what it says (`text`: "surface 'tube' is open: ...") and the message
/// as printed, `text` after the object's place ("SOURCE:LINE:COLUMN: warning: TEXT", or
/// "...: note: TEXT"); and whether it fails the check (every finding but an Overlap note).
struct PrintFinding {
  PrintCheck check = PrintCheck::Open;
  std::size_t object = 0;
  std::optional<std::size_t> other;
  glm::dvec3 where_mm{0.0};
  glm::dvec3 where{0.0};
  std::string text;
  int line = 0;  // the object's line in the file
  std::string message;
  bool fails = true;
};

struct PrintCheckOptions {
  double min_wall_mm = 0.8;               // walls thinner than this (at the model's printed size) are warned of
  std::size_t intersection_limit = 1000;  // crossing triangle pairs counted per surface or pair
  /// The parts print as one object where the model puts them (3MF, a merged STL): check how they
  /// cross and whether they float. False for an STL file per surface, which a slicer places alone.
  bool together = true;
};

/// Every finding for `model` (made from `doc`), part by part in document order: open, non-manifold,
/// orientation, self-intersection, thin walls (closed, consistently oriented shells only: a ray
/// from inside an open one finds no opposite wall it can trust), then, when options.together,
/// each pair of parts that cross, touch or overlap, then parts that float. Messages start with `source`:LINE:COLUMN of
/// the object. Intersections use a bounding volume hierarchy (intersections.hpp): about n log n. Precondition:
/// options.min_wall_mm > 0.
std::vector<PrintFinding> check_print(const Document& doc, const PrintModel& model, const std::string& source,
                                      const PrintCheckOptions& options = {});

/// The check's name in one word as the public API gives it: "open", "non-manifold",
/// "orientation", "self-intersection", "intersection", "overlap", "thin-wall", "floating".
const char* print_check_name(PrintCheck check);

/// Whether any finding fails: `sweep check` exits 1 then.
bool print_fails(const std::vector<PrintFinding>& findings);

}  // namespace sweep
