#include "render/textures.hpp"

#include "model/material.hpp"
#include "render/png_file.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <exception>
#include <stdexcept>

namespace sweep::render {
namespace {

GLuint upload(const Image& image) {
  GLuint texture = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, image.width, image.height, 0, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  glGenerateMipmap(GL_TEXTURE_2D);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glBindTexture(GL_TEXTURE_2D, 0);
  return texture;
}

/// A `cells` x `cells` checker of kCheckerPixelsPerCell-pixel cells, `light` and `dark` (RGB).
Image checker_image(int cells, const std::array<std::uint8_t, 3>& light, const std::array<std::uint8_t, 3>& dark) {
  Image image;
  image.width = image.height = cells * kCheckerPixelsPerCell;
  image.rgba.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const bool is_light = ((x / kCheckerPixelsPerCell) + (y / kCheckerPixelsPerCell)) % 2 == 0;
      std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) +
                                     static_cast<std::size_t>(x)) *
                                    4];
      std::copy_n((is_light ? light : dark).begin(), 3, p);
      p[3] = 255;
    }
  }
  return image;
}

}  // namespace

GLuint TextureCache::image(const std::filesystem::path& path, std::string& error) {
  const std::string key = path.string();
  if (const auto it = images_.find(key); it != images_.end()) return it->second;
  if (const auto it = failures_.find(key); it != failures_.end()) {
    error = it->second;
    return 0;
  }
  try {
    Image image = load_png_file(path);
    if (image.empty()) throw std::runtime_error("empty image");
    // Rows bottom-up: v = 0 is the image's bottom row, as in OBJ and Blender (the exports agree).
    const std::size_t row = static_cast<std::size_t>(image.width) * 4;
    for (int y = 0; y < image.height / 2; ++y) {
      std::swap_ranges(
          image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y)),
          image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(y + 1)),
          image.rgba.begin() + static_cast<std::ptrdiff_t>(row * static_cast<std::size_t>(image.height - 1 - y)));
    }
    return images_[key] = upload(image);
  } catch (const std::exception& e) {
    error = failures_[key] = e.what();
    return 0;
  }
}

GLuint TextureCache::checker(int cells) {
  if (const auto it = checkers_.find(cells); it != checkers_.end()) return it->second;
  return checkers_[cells] = upload(checker_image(cells, {255, 255, 255}, {110, 110, 110}));
}

GLuint TextureCache::placeholder() {
  if (placeholder_ == 0) placeholder_ = upload(checker_image(kPlaceholderCells, {255, 0, 255}, {0, 0, 0}));
  return placeholder_;
}

void TextureCache::clear() {
  for (auto& [key, texture] : images_) glDeleteTextures(1, &texture);
  for (auto& [cells, texture] : checkers_) glDeleteTextures(1, &texture);
  if (placeholder_ != 0) glDeleteTextures(1, &placeholder_);
  placeholder_ = 0;
  images_.clear();
  failures_.clear();
  checkers_.clear();
}

void MaterialBinder::bind(const Program& program, const SurfaceMaterial* m, const Material& fallback) {
  const bool placeholder = m && m->placeholder;
  program.set("u_color", placeholder ? glm::vec3(1.0f) : m ? m->color : fallback.color);
  program.set("u_shininess", std::max(m ? m->shininess : fallback.shininess, 1.0f));
  GLuint texture = 0;
  GLuint height = 0;
  if (placeholder) {
    texture = textures_.placeholder();  // neither image is loaded: the reader said which is missing
  } else if (m) {
    if (m->checker > 0) texture = textures_.checker(m->checker);
    if (!m->texture.empty()) texture = image(m->texture);
    if (!m->bump.empty() && m->bump_height > 0.0f) height = image(m->bump);
  }
  program.set("u_textured", texture != 0);
  program.set("u_bumped", height != 0);
  program.set("u_bump_height", m ? m->bump_height : 0.0f);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, texture);
  glActiveTexture(GL_TEXTURE1);
  glBindTexture(GL_TEXTURE_2D, height);
  glActiveTexture(GL_TEXTURE0);
}

GLuint MaterialBinder::image(const std::filesystem::path& path) {
  std::string error;
  const GLuint texture = textures_.image(path, error);
  if (texture == 0 && std::find(warned_.begin(), warned_.end(), error) == warned_.end()) warned_.push_back(error);
  return texture;
}

void MaterialBinder::clear() {
  textures_.clear();
  warned_.clear();
}

}  // namespace sweep::render
