// load_mesh FILE.swp
//
// The smallest use of the library: load an SWP file and list what it evaluated to. Every
// surface is a triangle mesh (positions, normals, indices, ready for a vertex buffer); every
// curve is a list of samples, each with its moving frame.
//
//   $ load_mesh swp/wineglass.swp
//   surface wineglass (srev): 16650 vertices, 33030 triangles
//   curve profile (bsp2): 185 samples
#include <sweep/sweep.hpp>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: load_mesh FILE.swp\n");
    return 2;
  }
  try {
    // load() reads and evaluates the file; bad input throws sweep::Error, whose what() is
    // "FILE:LINE:COLUMN: message" when it is about a place in the file.
    const sweep::Document doc = sweep::Document::load(argv[1]);

    // surfaces() and curves() are views: no array is copied, and each view keeps its arrays
    // alive on its own (its `owner`), even if the document is edited or destroyed.
    for (const sweep::SurfaceMesh& mesh : doc.surfaces()) {
      std::printf("surface %s (%s): %zu vertices, %zu triangles\n", mesh.name.c_str(), mesh.kind.c_str(),
                  mesh.vertex_count(), mesh.triangle_count());
    }
    for (const sweep::CurveView& curve : doc.curves()) {
      std::printf("curve %s (%s): %zu samples\n", curve.name.c_str(), curve.kind.c_str(), curve.sample_count());
    }
  } catch (const sweep::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
