#pragma once
// The "osmesa" GL context provider: an OpenGL 3.3 core context rendering into memory, for
// `sweep render` and the image tests. Needs no display and no GPU.
namespace sweep::headless {

/// Registers the provider under the name "osmesa" (see render::create_context). Idempotent.
void register_osmesa_provider();

}  // namespace sweep::headless
