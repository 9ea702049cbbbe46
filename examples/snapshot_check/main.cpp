// snapshot_check FILE.swp REFERENCES [NAME]
//
// Screenshot regression of one file, as `sweep snapshot` does for a folder: renders it, compares
// the picture with REFERENCES/NAME-smooth.png (NAME is the file's name without .swp by default)
// and, when it differs, names the objects that changed. The first run writes the reference and
// reports "new"; exits 0 when the check passed, 1 when not.
//
//   $ snapshot_check swp/wineglass.swp refs        # new: exit 1
//   $ snapshot_check swp/wineglass.swp refs        # pass: exit 0
//   $ snapshot_check moved/wineglass.swp refs      # after an edit: FAIL, exit 1
//   FAIL: 450 pixels changed where the model changed (profile, wineglass); 1 pixel differs ...
//     profile: 4 pixels changed (1 differ); its curve moved up to 0.0652
//     wineglass: 446 pixels changed (0 differ); its mesh moved up to 0.0652
#include <sweep/sweep.hpp>

#include <cstdio>
#include <filesystem>
#include <string>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: snapshot_check FILE.swp REFERENCES [NAME]\n");
    return 2;
  }
  const std::filesystem::path file = argv[1];
  const std::string name = argc == 4 ? argv[3] : file.stem().string();
  try {
    const sweep::Document doc = sweep::Document::load(file);

    // SnapshotOptions: mode, size (320 x 240), the comparison's threshold and pixel limit, and
    // `update` to accept a changed picture as the new reference.
    const sweep::SnapshotOptions options;
    const sweep::SnapshotResult result = sweep::check_snapshot(doc, argv[2], name, options);

    std::printf("%s: %s\n", result.status.c_str(), result.message.c_str());
    for (const std::string& object : result.objects) std::printf("  %s\n", object.c_str());
    return result.passed ? 0 : 1;
  } catch (const sweep::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
}
