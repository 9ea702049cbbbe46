#pragma once
// A case's accepted references in the references folder: NAME.png (with NAME.json, its sidecar),
// and any further accepted ones NAME_1.png, NAME_2.png, ... (VTK's idea: one from llvmpipe, one
// from a GPU driver); a case passes when any of them matches. Written atomically.
#include "render/image.hpp"
#include "snapshot/sidecar.hpp"

#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace sweep::snapshot {

struct Reference {
  std::filesystem::path image;    // NAME.png or NAME_K.png
  std::filesystem::path sidecar;  // NAME.json or NAME_K.json (may not exist)
};

/// The case a reference file's stem (its path below the folder, without extension) belongs to:
/// "bowl-smooth_2" -> "bowl-smooth", "bowl-smooth" -> itself.
std::string case_of(std::string stem);

/// NAME.png first if it exists, then NAME_1.png, NAME_2.png, ... while they exist (at most 99).
std::vector<Reference> accepted_references(const std::filesystem::path& folder, const std::string& name);

/// Where the case's next accepted reference goes: NAME.png when there is none, else the first
/// NAME_K.png that does not exist (K from 1), so accepted_references finds it.
Reference next_reference(const std::filesystem::path& folder, const std::string& name);

/// Moves every accepted reference of case `from` (images and sidecars) to case `to`, keeping
/// their order; returns the files written. Where `to` has the one reference a first run wrote
/// for it, showing the same model as `from`'s (a renamed model), that one is replaced. Throws
/// std::runtime_error, before moving anything, when `from` has no reference or `to` has others.
std::vector<std::filesystem::path> rename_references(const std::filesystem::path& folder, const std::string& from,
                                                     const std::string& to);

/// Writes `image` and its sidecar as `reference` through temporary files and renames (a failed
/// write leaves the old files). Throws std::runtime_error naming the file and the reason.
void write_reference(const Reference& reference, const render::Image& image, const Sidecar& sidecar);

/// Reference files (.png and .json) under `folder` that belong to no case named in `names`.
std::vector<std::filesystem::path> orphan_references(const std::filesystem::path& folder,
                                                     const std::set<std::string>& names);

}  // namespace sweep::snapshot
