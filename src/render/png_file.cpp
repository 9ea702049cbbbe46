#include "render/png_file.hpp"

#include "io/files/atomic_file.hpp"

#include <stb_image.h>
#include <stb_image_write.h>

#include <memory>
#include <stdexcept>

namespace sweep::render {
namespace {

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

}  // namespace

std::string encode_png(const Image& image) {
  if (image.empty()) throw std::runtime_error("cannot encode an empty image as PNG");
  std::string rgb(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3, '\0');
  for (std::size_t i = 0, n = rgb.size() / 3; i < n; ++i) {
    for (std::size_t c = 0; c < 3; ++c) rgb[i * 3 + c] = static_cast<char>(image.rgba[i * 4 + c]);
  }
  std::string png;
  if (stbi_write_png_to_func(append_bytes, &png, image.width, image.height, 3, rgb.data(), image.width * 3) == 0) {
    throw std::runtime_error("stb_image_write could not encode the PNG");
  }
  return png;
}

void save_png_file(const std::filesystem::path& path, const Image& image) {
  io::write_file_atomically(path, encode_png(image));
}

Image load_png_file(const std::filesystem::path& path) {
  int width = 0;
  int height = 0;
  int channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(stbi_load(path.c_str(), &width, &height, &channels, 4),
                                                         stbi_image_free);
  if (!pixels) {
    throw std::runtime_error("cannot read PNG " + path.string() + ": " + stbi_failure_reason());
  }
  Image image;
  image.width = width;
  image.height = height;
  image.rgba.assign(pixels.get(),
                    pixels.get() + static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  return image;
}

}  // namespace sweep::render
