#pragma once
// Writing a test's input files and reading files back, byte for byte (binary mode, so what a
// test writes or expects is exactly what is on disk, text or image alike).
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <string>
#include <string_view>

namespace sweep::test {

/// Writes `text` to `path` exactly as given, replacing the file.
inline void write_text(const std::filesystem::path& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

/// Writes binary content held in a string (a PNG made by the program, say) to `path`: write_text.
inline void write_bytes(const std::filesystem::path& path, std::string_view bytes) {
  write_text(path, bytes);
}

/// Writes raw bytes (an image made by hand, say) to `path`, replacing the file.
inline void write_bytes(const std::filesystem::path& path, std::span<const unsigned char> bytes) {
  write_text(path, std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

/// A valid 1x1 RGBA PNG (67 bytes; signature, IHDR, IDAT, IEND with correct CRCs), made by hand
/// so the tests need no image writer.
inline constexpr unsigned char kTinyPng[] = {
    0x89, 0x50, 0x4E, 0x47, 0x0D, 0x0A, 0x1A, 0x0A, 0x00, 0x00, 0x00, 0x0D, 0x49, 0x48, 0x44, 0x52, 0x00,
    0x00, 0x00, 0x01, 0x00, 0x00, 0x00, 0x01, 0x08, 0x06, 0x00, 0x00, 0x00, 0x1F, 0x15, 0xC4, 0x89, 0x00,
    0x00, 0x00, 0x0A, 0x49, 0x44, 0x41, 0x54, 0x78, 0x9C, 0x63, 0x00, 0x01, 0x00, 0x00, 0x05, 0x00, 0x01,
    0x0D, 0x0A, 0x2D, 0xB4, 0x00, 0x00, 0x00, 0x00, 0x49, 0x45, 0x4E, 0x44, 0xAE, 0x42, 0x60, 0x82};

/// Writes kTinyPng to `path`: an image file that every image reader accepts.
inline void write_tiny_png(const std::filesystem::path& path) {
  write_bytes(path, kTinyPng);
}

/// The whole content of a file, text or binary, byte for byte ("" when it cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  return content.str();
}

}  // namespace sweep::test
