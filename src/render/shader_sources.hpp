#pragma once
// GLSL sources from shaders/, embedded into the binary at build time (cmake/embed_files.cmake).
#include <optional>
#include <string_view>

namespace sweep::render {

/// The source of the shader file `name` ("mesh.vert", ...), or nullopt if no such file was
/// embedded.
std::optional<std::string_view> shader_source(std::string_view name);

}  // namespace sweep::render
