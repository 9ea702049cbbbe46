#include "snapshot/stale_references.hpp"

#include "snapshot/attribution.hpp"
#include "snapshot/references.hpp"

#include <cstdio>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

/// The summary names this many files; `--prune --dry-run` lists them all.
constexpr std::size_t kNamedInSummary = 5;

/// Same model, seen in the same mode, colour, view and size (the camera is refitted for a new
/// case, so it is not compared).
bool same_picture(const Sidecar& old, const Sidecar& now) {
  return old.mode == now.mode && old.setup.color == now.setup.color && old.setup.view == now.setup.view &&
         old.setup.size == now.setup.size && same_model(old, now);
}

}  // namespace

StaleReferences::StaleReferences(const fs::path& folder, const std::set<std::string>& names, std::string command)
    : folder_(folder), files_(orphan_references(folder, names)), command_(std::move(command)) {}

std::string StaleReferences::renamed_hint(const std::string& name, const Sidecar& now) const {
  if (files_.empty()) return "";
  std::call_once(read_once_, [this] {
    for (const fs::path& file : files_) {
      const fs::path relative = file.lexically_relative(folder_);
      const std::string stem = (relative.parent_path() / relative.stem()).generic_string();
      if (file.extension() != ".json" || case_of(stem) != stem) continue;  // each case's first sidecar
      try {
        sidecars_.emplace_back(stem, read_sidecar(file));
      } catch (const SidecarError&) {
      }
    }
  });
  for (const auto& [old, sidecar] : sidecars_) {
    if (same_picture(sidecar, now)) {
      return "; looks like " + old + " (renamed?): move its references with `" + command_ + " --rename " + old + " " +
             name + "`";
    }
  }
  return "";
}

std::string StaleReferences::summary() const {
  if (files_.empty()) return "";
  std::string text = std::to_string(files_.size()) +
                     (files_.size() == 1 ? " reference file belongs" : " reference files belong") + " to no case: ";
  for (std::size_t i = 0; i < std::min(files_.size(), kNamedInSummary); ++i) {
    text += (i > 0 ? ", " : "") + files_[i].lexically_relative(folder_).generic_string();
  }
  if (files_.size() > kNamedInSummary) text += " (and " + std::to_string(files_.size() - kNamedInSummary) + " more)";
  return text + "; kept (`" + command_ + " --prune --dry-run` lists them all, --prune deletes them)";
}

void prune(const std::vector<fs::path>& files, bool dry_run) {
  for (const fs::path& file : files) {
    if (dry_run) {
      std::printf("would prune %s\n", file.c_str());
      continue;
    }
    std::error_code ec;
    fs::remove(file, ec);
    std::printf("pruned %s%s\n", file.c_str(), ec ? (": " + ec.message()).c_str() : "");
  }
}

}  // namespace sweep::snapshot
