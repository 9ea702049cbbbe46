#include "io/mesh/mtl_writer.hpp"

#include "io/files/atomic_file.hpp"

#include <stb_image_write.h>

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace sweep::io {
namespace {

void append_number(std::string& out, float value) {
  char buffer[32];
  out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr);
}

void append_color(std::string& out, const char* tag, const glm::vec3& c) {
  out += tag;
  for (int k = 0; k < 3; ++k) {
    out += ' ';
    append_number(out, c[k]);
  }
  out += '\n';
}

void append_bytes(void* context, void* data, int size) {
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}

/// The whole file; std::runtime_error "cannot read ROLE PATH: REASON" when it cannot be read.
std::string read_whole_file(const std::filesystem::path& path, const char* role) {
  const auto failure = [&](int error) {
    std::string message = "cannot read ";
    message += role;
    message += ' ';
    message += path.string();
    message += ": ";
    message += std::generic_category().message(error);
    return std::runtime_error(message);
  };
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"), std::fclose);
  if (!file) throw failure(errno);
  std::string bytes;
  char buffer[1 << 16];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, file.get())) > 0) bytes.append(buffer, n);
  if (std::ferror(file.get())) throw failure(errno != 0 ? errno : EIO);
  if (!is_png(bytes)) {
    std::string message = "cannot read ";
    message += role;
    message += ' ';
    message += path.string();
    message += ": not a PNG image";
    throw std::runtime_error(message);
  }
  return bytes;
}

}  // namespace

std::string mtl_material_name(const SurfaceMaterial& material) {
  return material.name.empty() ? "default" : material.name;
}

std::string mtl_text(const SurfaceMaterial& material, const MtlImageFiles& images, const std::string& comment) {
  std::string out;
  if (!comment.empty()) {
    out += "# ";
    out += comment;
    out += '\n';
  }
  out += "newmtl ";
  out += mtl_material_name(material);
  out += '\n';
  append_color(out, "Kd", material.color);
  append_color(out, "Ks", glm::vec3(kSpecularGrey));
  out += "Ns ";
  append_number(out, material.shininess);
  out += "\nillum 2\n";
  if (!images.texture.empty()) {
    out += "map_Kd ";
    out += images.texture;
    out += '\n';
  }
  if (!images.bump.empty()) {
    out += "map_Bump -bm ";
    append_number(out, material.bump_height);
    out += ' ';
    out += images.bump;
    out += '\n';
  }
  return out;
}

void save_mtl_file(const std::filesystem::path& path, const SurfaceMaterial& material, const MtlImageFiles& images,
                   const std::string& comment) {
  write_file_atomically(path, mtl_text(material, images, comment));
}

MaterialImages read_material_images(const SurfaceMaterial& material) {
  MaterialImages images;
  if (!material.texture.empty()) {
    images.texture = read_whole_file(material.texture, "texture");
  } else if (material.checker > 0) {
    images.texture = checker_png(material.checker);
  }
  if (!material.bump.empty()) images.bump = read_whole_file(material.bump, "bump image");
  return images;
}

std::string checker_png(int cells) {
  if (cells < 1 || cells > 256) throw std::invalid_argument("checker_png: cells out of range");
  const int side = cells * kCheckerPixelsPerCell;
  const auto count = static_cast<std::size_t>(side);
  std::vector<unsigned char> pixels(count * count);
  for (int row = 0; row < side; ++row) {
    // Image rows run top to bottom; cell rows count from the bottom (v = 0).
    const int cell_row = cells - 1 - row / kCheckerPixelsPerCell;
    unsigned char* line = pixels.data() + static_cast<std::size_t>(row) * count;
    for (int column = 0; column < side; ++column) {
      const bool light = (column / kCheckerPixelsPerCell + cell_row) % 2 == 0;
      line[column] = light ? kCheckerLightGrey : kCheckerDarkGrey;
    }
  }
  std::string png;
  if (stbi_write_png_to_func(append_bytes, &png, side, side, 1, pixels.data(), side) == 0) {
    throw std::runtime_error("stb_image_write could not encode the checker PNG");
  }
  return png;
}

std::string checker_file_name(int cells) {
  std::string name = "checker";
  name += std::to_string(cells);
  name += ".png";
  return name;
}

bool is_png(const std::string& bytes) {
  static constexpr char kSignature[] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  return bytes.size() >= sizeof kSignature && bytes.compare(0, sizeof kSignature, kSignature, sizeof kSignature) == 0;
}

}  // namespace sweep::io
