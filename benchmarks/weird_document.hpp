#pragma once
// weird.swp at a multiple of its STEPS: the large model the speed claims are measured on.
#include "io/swp/read.hpp"
#include "model/document.hpp"

namespace sweep::bench {

/// weird.swp with every STEPS multiplied by `factor` (10: 819 200 vertices, 1.64 M triangles).
inline Document scaled_weird(int factor) {
  Document doc = io::load_swp_file(SWEEP_SWP_DIR "/weird.swp");
  for (auto& object : doc.objects) {
    if (int* steps = steps_field(object)) *steps *= factor;
  }
  io::validate_document(doc);
  return doc;
}

}  // namespace sweep::bench
