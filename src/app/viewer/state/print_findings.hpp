#pragma once
// The printability findings of the last 3MF or STL export (model/print/printability.hpp), as the
// Export panel lists them: a click on one selects the object it names.
#include "editor/view_state.hpp"

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace sweep::viewer {

struct PrintFindingRow {
  editor::ObjectId object = editor::kNoObject;  // the surface the finding names
  std::string message;                          // as `sweep check` prints it
  std::string shown;                            // as the panel lists it: "line 7: surface ..."
  glm::dvec3 where{0.0};                        // model coordinates
  bool fails = true;                            // a warning (false: a note)
};

/// The rows of the last print export, and the file they are about ("" before any).
struct PrintFindings {
  std::string file;
  std::vector<PrintFindingRow> rows;
};

}  // namespace sweep::viewer
