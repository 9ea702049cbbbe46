#pragma once
// PNG files through stb_image_write / stb_image (the Debian libstb build). No GL: the sweep_png
// library, usable without a context.
#include "render/image.hpp"

#include <filesystem>
#include <string>

namespace sweep::render {

/// PNG bytes of `image` (RGB; the alpha channel is dropped since every picture is opaque).
/// Precondition: !image.empty(). Throws std::runtime_error if encoding fails.
std::string encode_png(const Image& image);

/// Writes `image` as a PNG through a temporary file and a rename, so readers never see half a
/// file and a failed write leaves the old one. Throws std::runtime_error naming the path.
void save_png_file(const std::filesystem::path& path, const Image& image);

/// Reads a PNG as RGBA. Throws std::runtime_error naming the path if it cannot be read.
Image load_png_file(const std::filesystem::path& path);

}  // namespace sweep::render
