#pragma once
// A document as a printer gets it: its printable surfaces placed on the plate together
// (millimetres, z up) and welded into shells. What the 3MF and placed STL exports write and what
// the printability checks (printability.hpp) read, so they see one model.
#include "geometry/mesh/print_placement.hpp"
#include "geometry/mesh/shell.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <vector>

namespace sweep {

/// One printable surface: its object's index in the document, its name and base colour
/// (0..1 RGB, its material's or the default look's), and its placed, welded shell.
struct PrintPart {
  std::size_t object = 0;
  std::string name;
  glm::vec3 color{0.8f};
  Shell shell;
};

struct PrintModel {
  PrintPlacement placement;
  std::vector<PrintPart> parts;  // in document order
};

/// The surfaces a print holds: every named surface except the polygon meshes that subdivision
/// surfaces are made from (a cage is scaffolding, not a part), in document order. Curves and
/// riders are not surfaces.
std::vector<std::size_t> printable_objects(const Document& doc);

/// The printable surfaces of `doc` placed together (place_on_plate: `height_mm` tall, or 1 model
/// unit = 1 mm when it is 0) and welded (welded_shell), each surface's shell built on a core of
/// its own. Precondition: `scene` is evaluated from `doc`, its meshes finite; height_mm >= 0.
PrintModel print_model(const Document& doc, const Scene& scene, double height_mm);

/// "model size 58.2 x 58.2 x 80.0 mm (1 model unit = 22.3 mm)": what the exports and `sweep
/// check` say of a model's size. `scaled`: the scale was chosen to reach a height asked for.
std::string model_size_text(const PrintPlacement& placement, bool scaled);

}  // namespace sweep
