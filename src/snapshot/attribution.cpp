#include "snapshot/attribution.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace sweep::snapshot {
namespace {

std::string number(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", value);
  return text;
}

/// Per object name: pixels that differ (beyond the threshold, not forgiven) and pixels that
/// changed at all, showing it in either picture; and those showing no object in either.
struct PixelCounts {
  std::map<std::string, std::size_t> differ;
  std::map<std::string, std::size_t> touched;
  std::size_t background = 0;
  std::size_t changed_objects = 0;  // touched pixels showing an object of `changed`
};

const std::string* name_at(const Sidecar& s, std::size_t p) {
  if (p >= s.ids.ids.size()) return nullptr;
  const std::uint16_t id = s.ids.ids[p];
  return id == 0 || id > s.objects.size() ? nullptr : &s.objects[id - 1u].name;
}

PixelCounts count_pixels(const Sidecar& reference, const Sidecar& current, const ImageDiff& diff,
                         const std::set<std::string>& changed) {
  PixelCounts counts;
  for (std::size_t p = 0; p < diff.classes.size(); ++p) {
    const bool differs = diff.classes[p] == PixelClass::Differs;
    const bool touched =
        differs || diff.classes[p] != PixelClass::Same || (p < diff.distance.size() && diff.distance[p] > 0.0f);
    if (!touched) continue;
    const std::string* before = name_at(reference, p);
    const std::string* now = name_at(current, p);
    if (now != nullptr && before != nullptr && *now == *before) before = nullptr;  // count it once
    for (const std::string* name : {before, now}) {
      if (name == nullptr) continue;
      ++counts.touched[*name];
      if (differs) ++counts.differ[*name];
    }
    if (before == nullptr && now == nullptr && differs) ++counts.background;
    if ((before != nullptr && changed.count(*before)) || (now != nullptr && changed.count(*now)))
      ++counts.changed_objects;
  }
  return counts;
}

/// "bounding box +0.03 in y, -0.01 in x" (the axes whose box moved more than `noise`), or "".
std::string box_change(const Fingerprint& before, const Fingerprint& now, double noise) {
  static const char* const kAxes[] = {"x", "y", "z"};
  std::string out;
  for (int c = 0; c < 3; ++c) {
    const double low = now.box_min[c] - before.box_min[c];
    const double high = now.box_max[c] - before.box_max[c];
    const double change = std::abs(high) >= std::abs(low) ? high : low;
    if (std::abs(change) <= noise) continue;
    out += (out.empty() ? "bounding box " : ", ") + std::string(change > 0 ? "+" : "") + number(change) + " in " +
           kAxes[c];
  }
  return out;
}

/// How far the geometry moved, at least: samples, box corners and centroid.
double largest_move(const Fingerprint& before, const Fingerprint& now) {
  double move = glm::length(now.centroid - before.centroid);
  move = std::max(move, glm::length(now.box_min - before.box_min));
  move = std::max(move, glm::length(now.box_max - before.box_max));
  for (std::size_t k = 0; k < std::min(before.samples.size(), now.samples.size()); ++k) {
    move = std::max(move, glm::length(now.samples[k] - before.samples[k]));
  }
  return move;
}

/// "its mesh moved up to 0.031 (bounding box +0.03 in y)" or the count change; "" if unchanged.
std::string geometry_change(const Fingerprint& before, const Fingerprint& now, double noise) {
  if (now.same_geometry(before)) return "";
  const char* what = now.surface ? "its mesh" : "its curve";
  const char* units = now.surface ? "vertices" : "samples";
  if (now.vertices != before.vertices || now.triangles != before.triangles) {
    std::string out = std::string(what) + " now has " + grouped_count(now.vertices) + " " + units;
    if (now.surface) out += " and " + grouped_count(now.triangles) + " triangles";
    out += " (was " + grouped_count(before.vertices);
    if (now.surface) out += " and " + grouped_count(before.triangles);
    out += ")";
    const std::string box = box_change(before, now, noise);
    return box.empty() ? out : out + "; " + box;
  }
  const double move = largest_move(before, now);
  const std::string box = box_change(before, now, noise);
  if (move <= noise)
    return std::string(what) + " changed between its sample points (by less than " + number(noise) + ")";
  return std::string(what) + " moved up to " + number(move) + (box.empty() ? "" : " (" + box + ")");
}

const Fingerprint* find(const std::vector<Fingerprint>& objects, const std::string& name) {
  const auto it = std::find_if(objects.begin(), objects.end(), [&](const Fingerprint& f) { return f.name == name; });
  return it == objects.end() ? nullptr : &*it;
}

/// The scene's size, for what counts as no move at all.
double noise_of(const Sidecar& s) {
  double extent = 0.0;
  for (const Fingerprint& f : s.objects) extent = std::max(extent, glm::length(f.box_max - f.box_min));
  return std::max(extent, 1e-9) * 1e-6;
}

/// Counts changed, moved beyond noise, or restyled: the picture may show it.
bool changed_visibly(const Fingerprint& before, const Fingerprint& now, double noise) {
  return now.vertices != before.vertices || now.triangles != before.triangles || now.material != before.material ||
         (!now.same_geometry(before) && largest_move(before, now) > noise);
}

ObjectChange compare_object(const Fingerprint& before, const Fingerprint& now, std::size_t differ, std::size_t touched,
                            double noise) {
  std::vector<std::string> parts;
  const std::string geometry = geometry_change(before, now, noise);
  const bool material = now.material != before.material;
  const bool changed = !geometry.empty() || material;
  if (changed && touched > 0) {
    parts.push_back(grouped_count(touched) + " pixels changed (" + grouped_count(differ) + " differ)");
  } else if (differ > 0) {
    parts.push_back(pixels_differ(differ));
  }
  if (!geometry.empty()) parts.push_back(geometry);
  if (material) parts.push_back("material changed (was " + before.material + ", now " + now.material + ")");
  if (now.coverage != before.coverage && !parts.empty()) {
    parts.push_back("covers " + grouped_count(now.coverage) + " pixels (was " + grouped_count(before.coverage) + ")");
  }
  ObjectChange change{now.name, "", !parts.empty()};
  if (material && geometry.empty() && touched == 0) {
    change.text = "material of '" + now.name + "' changed";
    return change;
  }
  if (parts.empty()) parts.push_back("unchanged");
  change.text = now.name + ": ";
  for (std::size_t i = 0; i < parts.size(); ++i) change.text += (i > 0 ? "; " : "") + parts[i];
  return change;
}

}  // namespace

/// The names of the objects whose change the picture may show: new, removed, or changed_visibly.
std::set<std::string> visibly_changed(const Sidecar& reference, const Sidecar& current, double noise) {
  std::set<std::string> out;
  for (const Fingerprint& now : current.objects) {
    const Fingerprint* before = find(reference.objects, now.name);
    if (before == nullptr || changed_visibly(*before, now, noise)) out.insert(now.name);
  }
  for (const Fingerprint& before : reference.objects) {
    if (find(current.objects, before.name) == nullptr) out.insert(before.name);
  }
  return out;
}

bool same_model(const Sidecar& reference, const Sidecar& current) {
  if (reference.objects.size() != current.objects.size()) return false;
  return std::all_of(current.objects.begin(), current.objects.end(), [&](const Fingerprint& now) {
    const Fingerprint* before = find(reference.objects, now.name);
    return before != nullptr && now.same_geometry(*before) && now.material == before->material;
  });
}

Attribution attribute(const Sidecar& reference, const Sidecar& current, const ImageDiff* diff) {
  const double noise = std::max(noise_of(reference), noise_of(current));
  const std::set<std::string> changed = visibly_changed(reference, current, noise);
  PixelCounts counts;
  const bool pixels = diff != nullptr && diff->same_size && reference.ids.ids.size() == diff->classes.size() &&
                      current.ids.ids.size() == diff->classes.size();
  if (pixels) counts = count_pixels(reference, current, *diff, changed);
  Attribution out;
  out.model_changed = !same_model(reference, current);
  out.changed_object_pixels = counts.changed_objects;
  std::vector<ObjectChange> unchanged;
  for (const Fingerprint& now : current.objects) {
    if (changed.count(now.name)) out.changed_objects.push_back(now.name);
    const Fingerprint* before = find(reference.objects, now.name);
    if (before == nullptr) {
      out.changes.push_back(
          {now.name, "new object '" + now.name + "' (covers " + grouped_count(now.coverage) + " pixels)", true});
      continue;
    }
    ObjectChange change = compare_object(*before, now, counts.differ[now.name], counts.touched[now.name], noise);
    (change.changed ? out.changes : unchanged).push_back(std::move(change));
  }
  for (const Fingerprint& before : reference.objects) {
    if (find(current.objects, before.name) != nullptr) continue;
    out.changed_objects.push_back(before.name);
    out.changes.push_back(
        {before.name, "object '" + before.name + "' removed (it covered " + grouped_count(before.coverage) + " pixels)",
         true});
  }
  if (counts.background > 0) {
    out.changes.push_back(
        {"", "background: " + pixels_differ(counts.background) + " (no object in either picture)", true});
  }
  out.changes.insert(out.changes.end(), unchanged.begin(), unchanged.end());
  return out;
}

}  // namespace sweep::snapshot
