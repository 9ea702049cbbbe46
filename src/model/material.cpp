#include "model/material.hpp"

#include "base/precondition.hpp"

#include <stb_image.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

namespace sweep {

bool image_missing(const std::filesystem::path& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  return ec || !std::filesystem::exists(status);
}

std::string image_problem(const std::filesystem::path& path) {
  if (image_missing(path)) return "cannot open " + path.string() + ": no such file";
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return path.string() + " is not a regular file";
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), &std::fclose);
  if (!file) return "cannot open " + path.string() + ": " + std::strerror(errno);
  // PNG only: what every exporter copies and every reader of an OBJ or glb takes.
  unsigned char signature[8] = {};
  const unsigned char png[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (std::fread(signature, 1, 8, file.get()) != 8 || std::memcmp(signature, png, 8) != 0) {
    return path.string() + " is not a PNG image";
  }
  std::rewind(file.get());
  int width = 0, height = 0, channels = 0;
  if (stbi_info_from_file(file.get(), &width, &height, &channels) == 0) {
    return path.string() + " is not an image stb_image can read (" + stbi_failure_reason() + ")";
  }
  if (width <= 0 || height <= 0 || width > 16384 || height > 16384) {
    return path.string() + " is " + std::to_string(width) + "x" + std::to_string(height) +
           " pixels; at most 16384 on a side";
  }
  return {};
}

bool puts_image_on(const Document& doc, const Object& surface) {
  if (surface.as<MaterialPart>().material < 0) return false;
  const Object& m = doc.objects[static_cast<std::size_t>(surface.as<MaterialPart>().material)];
  return m.as<MaterialLook>().checker > 0 || !m.as<MaterialLook>().texture.empty() ||
         !m.as<MaterialLook>().bump.empty();
}

std::filesystem::path image_base(const std::filesystem::path& swp_file) {
  return swp_file.parent_path();
}

SurfaceMaterial surface_material(const Document& doc, int index, const std::filesystem::path& base) {
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    is_surface(doc.objects[static_cast<std::size_t>(index)].kind()),
                "doc.objects[index] is a surface");
  SurfaceMaterial out;
  const Object& surface = doc.objects.at(static_cast<std::size_t>(index));
  if (surface.as<MaterialPart>().material < 0) return out;
  const Object& m = doc.objects.at(static_cast<std::size_t>(surface.as<MaterialPart>().material));
  out.name = m.name;
  out.color = glm::vec3(m.as<MaterialLook>().color);
  out.shininess = static_cast<float>(m.as<MaterialLook>().shininess);
  const auto resolve = [&base](const std::string& path) {
    if (path.empty()) return std::filesystem::path();
    const std::filesystem::path p(path);
    return p.is_absolute() ? p : base / p;
  };
  out.texture = resolve(m.as<MaterialLook>().texture);
  out.checker = m.as<MaterialLook>().checker;
  out.bump = resolve(m.as<MaterialLook>().bump);
  out.bump_height = static_cast<float>(m.as<MaterialLook>().bump_height);
  for (const MissingImage& missing : doc.missing_images) {
    if (missing.path == m.as<MaterialLook>().texture || missing.path == m.as<MaterialLook>().bump)
      out.placeholder = true;
  }
  return out;
}

}  // namespace sweep
