#include "snapshot/references.hpp"

#include "io/files/atomic_file.hpp"
#include "render/png_file.hpp"
#include "snapshot/attribution.hpp"

#include <cctype>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

Reference reference_at(const fs::path& folder, const std::string& stem) {
  return {folder / (stem + ".png"), folder / (stem + ".json")};
}

/// Whether `present` is the single reference a first run wrote for a case, showing the same
/// model as `old` (what the "looks like OLD (renamed?)" hint saw).
bool just_written_for(const std::vector<Reference>& present, const Reference& old) {
  if (present.size() != 1) return false;
  try {
    return same_model(read_sidecar(old.sidecar), read_sidecar(present.front().sidecar));
  } catch (const SidecarError&) {
    return false;
  }
}

}  // namespace

std::string case_of(std::string stem) {
  const std::size_t underscore = stem.rfind('_');
  if (underscore == std::string::npos || underscore + 1 == stem.size()) return stem;
  for (std::size_t i = underscore + 1; i < stem.size(); ++i) {
    if (!std::isdigit(static_cast<unsigned char>(stem[i]))) return stem;
  }
  return stem.substr(0, underscore);
}

std::vector<Reference> accepted_references(const fs::path& folder, const std::string& name) {
  std::vector<Reference> out;
  std::error_code ec;
  const Reference primary = reference_at(folder, name);
  if (fs::exists(primary.image, ec)) out.push_back(primary);
  for (int k = 1; k <= 99; ++k) {
    const Reference other = reference_at(folder, name + "_" + std::to_string(k));
    if (!fs::exists(other.image, ec)) break;
    out.push_back(other);
  }
  return out;
}

Reference next_reference(const fs::path& folder, const std::string& name) {
  const std::vector<Reference> existing = accepted_references(folder, name);
  std::error_code ec;
  if (!fs::exists(folder / (name + ".png"), ec)) return reference_at(folder, name);
  return reference_at(folder, name + "_" + std::to_string(existing.size()));
}

std::vector<fs::path> rename_references(const fs::path& folder, const std::string& from, const std::string& to) {
  const std::vector<Reference> old = accepted_references(folder, from);
  if (old.empty()) throw std::runtime_error("no reference of case '" + from + "' in " + folder.string());
  const std::vector<Reference> present = accepted_references(folder, to);
  if (!present.empty() && !just_written_for(present, old.front())) {
    throw std::runtime_error("case '" + to + "' already has references in " + folder.string() +
                             " that show another model; nothing moved");
  }
  std::error_code ignored;
  for (const Reference& r : present) {  // the one reference a first run wrote for the renamed case
    fs::remove(r.sidecar, ignored);
    fs::remove(r.image, ignored);
  }
  std::vector<fs::path> written;
  for (std::size_t k = 0; k < old.size(); ++k) {
    const Reference target = reference_at(folder, k == 0 ? to : to + "_" + std::to_string(k));
    std::error_code ec;
    fs::create_directories(target.image.parent_path(), ec);
    for (const auto& [source, destination] :
         {std::pair{old[k].sidecar, target.sidecar}, {old[k].image, target.image}}) {
      if (!fs::exists(source, ec)) continue;
      fs::rename(source, destination, ec);
      if (ec)
        throw std::runtime_error("cannot move " + source.string() + " to " + destination.string() + ": " +
                                 ec.message());
      written.push_back(destination);
    }
  }
  return written;
}

void write_reference(const Reference& reference, const render::Image& image, const Sidecar& sidecar) {
  std::error_code ec;
  fs::create_directories(reference.image.parent_path(), ec);
  if (ec) throw std::runtime_error("cannot create " + reference.image.parent_path().string() + ": " + ec.message());
  // The sidecar first: a reference image never stands beside another picture's sidecar for long,
  // and the image is what marks the reference as there.
  io::write_file_atomically(reference.sidecar, sidecar_json(sidecar));
  render::save_png_file(reference.image, image);
}

std::vector<fs::path> orphan_references(const fs::path& folder, const std::set<std::string>& names) {
  std::vector<fs::path> out;
  std::error_code ec;
  if (!fs::is_directory(folder, ec)) return out;
  for (auto it = fs::recursive_directory_iterator(folder, ec); !ec && it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    if (!it->is_regular_file(ec)) continue;
    const fs::path& file = it->path();
    if (file.extension() != ".png" && file.extension() != ".json") continue;
    const fs::path relative = file.lexically_relative(folder);
    const std::string stem = (relative.parent_path() / relative.stem()).generic_string();
    if (names.count(case_of(stem)) == 0) out.push_back(file);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace sweep::snapshot
