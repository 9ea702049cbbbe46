#pragma once
// What no image-diff tool can say: which named object's pixels changed and how its geometry
// moved. Compares the reference's sidecar with the current scene's, both seen by the same camera.
#include "snapshot/image_diff.hpp"
#include "snapshot/sidecar.hpp"
#include "snapshot/snapshot_case.hpp"

#include <vector>

namespace sweep::snapshot {

struct Attribution {
  /// One line per object of either sidecar (changed ones first, in document order), then the
  /// background's when differing pixels show no object in either picture.
  std::vector<ObjectChange> changes;
  /// Some object's geometry or material differs, or an object was added or removed.
  bool model_changed = false;
  /// Pixels that changed at all (any colour distance) where a changed object shows in either
  /// picture: the anti-aliasing and shift allowances are for renderer noise, and a picture that
  /// changed where the model did is not noise. 0 without a pixel comparison.
  std::size_t changed_object_pixels = 0;
  /// The objects counted there, in document order.
  std::vector<std::string> changed_objects;
};

/// Whether both sidecars hold the same objects (by name, in any order) with the same geometry
/// (fingerprint hash and counts) and material: the model the pictures show is the same.
bool same_model(const Sidecar& reference, const Sidecar& current);

/// Lines such as "bowl: 1,204 px differ; its mesh moved up to 0.031 (bounding box +0.03 in y)",
/// "rope: unchanged", "new object 'lid' (covers 310 px)", "object 'stem' removed (it covered
/// 812 px)", "material of 'glass' changed (was ..., now ...)". Distances are in model units: the
/// largest move of the fingerprints' sample points, or of the bounding box or centroid when that
/// is larger (a lower bound of the largest vertex move). `diff` (null: no pixel comparison) gives
/// the pixels counted against each object: those showing it in either picture; a changed object
/// counts every pixel that changed at all ("px changed"), an unchanged one those that differ.
/// Precondition: both id maps have diff's size when diff is given and same_size.
Attribution attribute(const Sidecar& reference, const Sidecar& current, const ImageDiff* diff);

}  // namespace sweep::snapshot
