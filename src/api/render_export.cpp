#include "api/document_state.hpp"

#include "api/thread_worker.hpp"
#include "render/png_file.hpp"
#include "snapshot/image_diff.hpp"
#include "snapshot/run_render.hpp"

#include <memory>

// The public Document's pictures and files: exports as `sweep export` writes them, headless
// renders as `sweep render` and `sweep snapshot` draw them, PNG files and the one comparison.

namespace sweep::v0 {
namespace {

::sweep::render::Image internal(const Image& image) {
  if (image.width < 0 || image.height < 0 || image.rgba.size() != std::size_t(image.width) * image.height * 4) {
    throw Error("an image's rgba must hold width * height * 4 bytes");
  }
  return {image.width, image.height, image.rgba};
}

Image public_image(::sweep::render::Image image) {
  return {image.width, image.height, std::move(image.rgba)};
}

}  // namespace

std::string Image::png() const {
  if (width < 1 || height < 1) throw Error("an empty image has no PNG");
  try {
    return ::sweep::render::encode_png(internal(*this));
  } catch (...) {
    detail::throw_public_error();
  }
}

void Image::save_png(const std::filesystem::path& file) const {
  try {
    ::sweep::render::save_png_file(file, internal(*this));
  } catch (...) {
    detail::throw_public_error();
  }
}

Image Image::load_png(const std::filesystem::path& file) {
  try {
    return public_image(::sweep::render::load_png_file(file));
  } catch (...) {
    detail::throw_public_error();
  }
}

Comparison compare_images(const Image& actual, const Image& reference, const CompareOptions& options) {
  if (!(options.threshold >= 0.0 && options.threshold <= 1.0)) throw Error("the threshold must be within 0..1");
  ::sweep::snapshot::DiffOptions diff_options;
  diff_options.threshold = options.threshold;
  const ::sweep::snapshot::ImageDiff diff =
      ::sweep::snapshot::diff_images(internal(actual), internal(reference), diff_options);
  return {diff.same_size,        diff.passes({options.max_diff_pixels, 1.0}),
          diff.differing_pixels, diff.changed_pixels,
          diff.max_distance,     diff.summary()};
}

Image Document::render(int width, int height, const RenderOptions& options) const {
  if (width < 1 || height < 1 || width > ::sweep::snapshot::kMaxSnapshotSide ||
      height > ::sweep::snapshot::kMaxSnapshotSide) {
    throw Error("a picture is 1 to " + std::to_string(::sweep::snapshot::kMaxSnapshotSide) + " pixels a side, not " +
                std::to_string(width) + "x" + std::to_string(height));
  }
  ::sweep::snapshot::CaseSpec spec;
  spec.mode = detail::mode_named(options.mode);
  spec.color = detail::color_named(options.color);
  spec.size = {width, height};
  spec.view.yaw = options.yaw;
  spec.view.pitch = options.pitch;
  try {
    const ::sweep::render::Camera camera = ::sweep::snapshot::fitted_camera(*state_->scene, spec);
    const std::filesystem::path images = state_->file.empty() ? std::filesystem::path() : state_->file.parent_path();
    return public_image(
        detail::thread_worker().renderer().render(state_->doc, *state_->scene, camera, spec.size,
                                                  ::sweep::snapshot::settings_for(spec.mode, spec.color), images));
  } catch (...) {
    detail::throw_public_error();
  }
}

}  // namespace sweep::v0
