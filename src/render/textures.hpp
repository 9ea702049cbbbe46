#pragma once
// The renderer's textures (internal to src/render): material images and generated checkers,
// loaded once per file and kept until clear(). An image that cannot be loaded is remembered with
// its reason, so the surface is drawn in its colour and the warning is given once.
#include "model/material.hpp"
#include "render/display_settings.hpp"
#include "render/shader_program.hpp"

#include <glad/gl.h>

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace sweep::render {

class TextureCache {
 public:
  TextureCache() = default;
  ~TextureCache() { clear(); }
  TextureCache(const TextureCache&) = delete;
  TextureCache& operator=(const TextureCache&) = delete;

  /// The texture of the PNG at `path` (repeating, mipmapped), or 0 with `error` set.
  /// Precondition: a current context.
  GLuint image(const std::filesystem::path& path, std::string& error);
  /// An N x N checker of two greys over the texture square.
  GLuint checker(int cells);
  /// The placeholder of a missing image: a kPlaceholderCells checker of magenta and black.
  GLuint placeholder();
  void clear();

 private:
  std::map<std::string, GLuint> images_;
  std::map<std::string, std::string> failures_;
  std::map<int, GLuint> checkers_;
  GLuint placeholder_ = 0;
};

/// Binds a surface's look for mesh.frag: colour, shininess, texture (unit 0) and bump (unit 1).
/// A look whose image was missing when the file was read (SurfaceMaterial::placeholder) is the
/// placeholder checker, untinted, with no bump; the reader has warned of it. An image that cannot
/// be loaded when drawn leaves the surface in its colour and is named once in warnings().
class MaterialBinder {
 public:
  /// `material` null: the default look `fallback`. Precondition: `program` in use.
  void bind(const Program& program, const SurfaceMaterial* material, const Material& fallback);
  const std::vector<std::string>& warnings() const { return warned_; }
  void clear();

 private:
  GLuint image(const std::filesystem::path& path);

  TextureCache textures_;
  std::vector<std::string> warned_;
};

}  // namespace sweep::render
