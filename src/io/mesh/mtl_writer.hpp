#pragma once
// Wavefront MTL output (the material library an OBJ file names with `mtllib`) and the images a
// material brings along: its texture and bump files read whole, or its built-in checker made as a
// PNG. One material per library:
//
//   newmtl NAME
//   Kd R G B            the colour
//   Ks 0.45 0.45 0.45   the viewer's specular
//   Ns SHININESS
//   illum 2
//   map_Kd FILE         when textured (a copied texture or the generated checker)
//   map_Bump -bm H FILE when bumped (H: the bump height)
//
// Image file names are written as given (the exporter puts the images beside the .mtl file).
#include "model/material.hpp"

#include <filesystem>
#include <string>

namespace sweep::io {

/// The specular colour the viewer lights every surface with (Ks).
inline constexpr float kSpecularGrey = 0.45f;
/// The two greys of the generated checker (8-bit), the viewer's (render/textures.cpp): the cell
/// at the texture's origin (u = 0, v = 0, the image's bottom-left corner) is light, and the
/// colours alternate from there.
inline constexpr unsigned char kCheckerLightGrey = 255;
inline constexpr unsigned char kCheckerDarkGrey = 110;

/// The name a material is written under: its own, or "default" for the default look.
std::string mtl_material_name(const SurfaceMaterial& material);

/// The image files the MTL text refers to (names relative to the .mtl file); empty: none.
struct MtlImageFiles {
  std::string texture;  // map_Kd
  std::string bump;     // map_Bump
};

/// The MTL text of one material, an optional comment line first. Numbers are shortest
/// round-trip floats.
std::string mtl_text(const SurfaceMaterial& material, const MtlImageFiles& images, const std::string& comment = {});

/// Writes the MTL text to `path` atomically (std::runtime_error naming the path on failure).
void save_mtl_file(const std::filesystem::path& path, const SurfaceMaterial& material, const MtlImageFiles& images,
                   const std::string& comment = {});

/// The bytes of the images a material needs, read before anything is written.
struct MaterialImages {
  std::string texture;  // PNG bytes of the texture or of the generated checker; empty: untextured
  std::string bump;     // PNG bytes of the bump (height) image; empty: none
};

/// Reads the texture and bump files of `material` (or makes its checker). Throws
/// std::runtime_error "cannot read texture PATH: REASON" (or "bump image") when a file cannot be
/// read or is not a PNG ("not a PNG image").
MaterialImages read_material_images(const SurfaceMaterial& material);

/// A PNG of an N x N checker of kCheckerPixelsPerCell-pixel cells in kCheckerLightGrey and
/// kCheckerDarkGrey (8-bit greyscale), the light cell in the bottom-left corner.
/// Precondition: 1 <= cells <= 256.
std::string checker_png(int cells);

/// The name of the generated checker file of N cells: "checkerN.png".
std::string checker_file_name(int cells);

/// True if `bytes` start with the PNG signature.
bool is_png(const std::string& bytes);

}  // namespace sweep::io
