// render_png FILE.swp OUT.png [WIDTH HEIGHT]
//
// Draws a document headless, as `sweep render` does, and writes the picture as a PNG file
// (320 x 240 by default). Rendering needs no display: the library draws with OSMesa in
// software, in one offscreen context per thread, made on the thread's first render.
//
//   $ render_png swp/wineglass.swp wineglass.png 640 480
//   wrote wineglass.png (640 x 480)
#include <sweep/sweep.hpp>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 5) {
    std::fprintf(stderr, "usage: render_png FILE.swp OUT.png [WIDTH HEIGHT]\n");
    return 2;
  }
  const int width = argc == 5 ? std::atoi(argv[3]) : 320;
  const int height = argc == 5 ? std::atoi(argv[4]) : 240;
  try {
    const sweep::Document doc = sweep::Document::load(argv[1]);

    // RenderOptions picks the mode ("smooth", "wire", "frames"), the colouring and the view
    // (yaw and pitch about the scene, which is fitted to the picture).
    sweep::RenderOptions options;
    options.yaw = 30.0;
    options.pitch = 20.0;
    const sweep::Image image = doc.render(width, height, options);  // RGBA, rows top to bottom

    image.save_png(argv[2]);
    std::printf("wrote %s (%d x %d)\n", argv[2], image.width, image.height);
  } catch (const sweep::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
