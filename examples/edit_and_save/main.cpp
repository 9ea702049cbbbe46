// edit_and_save IN.swp OUT.swp [OBJECT INDEX DX DY]
//
// Edits a document as the viewer does and saves it: moves control point INDEX of OBJECT by
// (DX, DY) (by default point 6 of wineglass.swp's `profile`, 0.1 to the right) and writes
// OUT.swp. The saved file is the input's text with only the moved point's numbers changed:
// spacing, comments and the other numbers' decimals stay as they were.
//
//   $ edit_and_save swp/wineglass.swp moved.swp
//   moved profile point 6 from (-1.164785, 1.105511) to (-1.064785, 1.105511)
//   saved moved.swp
#include <sweep/sweep.hpp>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 7) {
    std::fprintf(stderr, "usage: edit_and_save IN.swp OUT.swp [OBJECT INDEX DX DY]\n");
    return 2;
  }
  const std::string object = argc == 7 ? argv[3] : "profile";
  const int index = argc == 7 ? std::atoi(argv[4]) : 6;
  const double dx = argc == 7 ? std::atof(argv[5]) : 0.1;
  const double dy = argc == 7 ? std::atof(argv[6]) : 0.0;
  try {
    sweep::Document doc = sweep::Document::load(argv[1]);

    // point() and move_point() take x, y, z (z is 0 and ignored for a planar curve). A bad name
    // or index, or a position a surface built on the curve refuses, throws and changes nothing.
    const std::array<double, 3> from = doc.point(object, index);
    const std::array<double, 3> to = {from[0] + dx, from[1] + dy, from[2]};
    doc.move_point(object, index, to);  // one undoable step: doc.undo() would put it back
    std::printf("moved %s point %d from (%f, %f) to (%f, %f)\n", object.c_str(), index, from[0], from[1], to[0], to[1]);

    // save() writes through a temporary file and a rename, so a failed write keeps the old file.
    doc.save(argv[2]);
    std::printf("saved %s\n", argv[2]);
  } catch (const sweep::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
