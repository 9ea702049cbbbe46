#pragma once
// The renderer's textures (internal to src/render): material images and generated checkers,
// loaded once per file and kept until clear(). An image that cannot be loaded is remembered with
// its reason, so the surface is drawn in its colour and the warning is given once.
#include <glad/gl.h>

#include <filesystem>
#include <map>
#include <string>

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
  void clear();

 private:
  std::map<std::string, GLuint> images_;
  std::map<std::string, std::string> failures_;
  std::map<int, GLuint> checkers_;
};

}  // namespace sweep::render
