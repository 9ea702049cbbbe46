#pragma once
// A surface's look, resolved from its `material` clause for renderers and exporters: colour,
// shininess, a texture (a PNG, or a built-in N x N checker) and a bump (a height PNG). Image
// paths are written relative to the SWP file; here they are resolved against its folder.
#include "model/document.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <string>

namespace sweep {

struct SurfaceMaterial {
  std::string name;  // the material object's name; "" for the default look
  glm::vec3 color{static_cast<float>(kDefaultColor[0]), static_cast<float>(kDefaultColor[1]),
                  static_cast<float>(kDefaultColor[2])};
  float shininess = static_cast<float>(kDefaultShininess);
  std::filesystem::path texture;  // resolved; empty: none
  int checker = 0;                // > 0: an N x N checker over the texture square (no file)
  std::filesystem::path bump;     // resolved height image; empty: none
  float bump_height = 0.0f;       // model units the image's full range (black to white) spans
  /// Its texture or bump was missing when the file was read (Document::missing_images): drawn
  /// as the placeholder checker (kPlaceholderCells, magenta and black, not tinted by the colour)
  /// instead of the images. Exports ignore it and read the images, which refuses.
  bool placeholder = false;

  bool textured() const { return !texture.empty() || checker > 0; }
};

/// The placeholder for a missing image: a magenta and black checker of this many cells per side
/// over the texture square, as Blender draws one.
inline constexpr int kPlaceholderCells = 8;

/// True when surface `surface`'s material puts an image on it (a texture, a checker or a bump):
/// its closed seams then get their own vertices (texture_coordinates.hpp).
bool puts_image_on(const Document& doc, const Object& surface);

/// The folder image paths of a file named `swp_file` are relative to ("" -> the working folder).
std::filesystem::path image_base(const std::filesystem::path& swp_file);

/// The material of surface `index`: its `material` clause's, or the default look. Paths are
/// resolved against `base`; `placeholder` is set when its texture or bump is one of
/// doc.missing_images. Precondition: doc.objects[index] is a surface of a valid document.
SurfaceMaterial surface_material(const Document& doc, int index, const std::filesystem::path& base);

/// True if nothing is at `path` (image_problem's "no such file"): the one problem the reader
/// lets pass, with a warning (MissingImage).
bool image_missing(const std::filesystem::path& path);

/// "" if `path` is a PNG image stb_image can read (its header is read, not the pixels), else
/// why not ("cannot open PATH: no such file", "PATH is not a PNG image"). Only regular files
/// are opened (a FIFO or a device would block or never end).
std::string image_problem(const std::filesystem::path& path);

/// Side of the square checker image made for `checker N` (exporters write it as a PNG).
inline constexpr int kCheckerPixelsPerCell = 32;

}  // namespace sweep
