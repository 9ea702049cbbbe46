#include "render/draw_list.hpp"

#include "model/edit/shown_points.hpp"
#include "model/evaluation/riders.hpp"

#include <algorithm>

namespace sweep::render {

TextureCoordinates texture_coordinates_drawn(ColorMode mode) {
  return mode == ColorMode::Uv ? TextureCoordinates::Everywhere : TextureCoordinates::WhereTextured;
}

bool DrawList::is_visible(std::size_t index) const {
  return index >= visible.size() || visible[index];
}

bool DrawList::is_shaded(std::size_t index) const {
  return is_visible(index) && !(index < cage_only.size() && cage_only[index]) &&
         !(index < carried.size() && carried[index]);
}

bool DrawList::rides(std::size_t index) const {
  return std::any_of(riders.begin(), riders.end(),
                     [index](const RiderPlacement& r) { return r.model >= 0 && std::size_t(r.model) == index; });
}

bool DrawList::curve_rides(std::size_t index) const {
  return index < riding_curves.size() && riding_curves[index];
}

namespace {

/// The surfaces riders carry and the curves that ride with them.
void set_carried(DrawList& list, const Document& doc) {
  list.carried = carried_models(doc);
  list.carried_curves = carried_curves(doc);
  list.riding_curves.assign(doc.objects.size(), false);
  for (const std::vector<int>& curves : list.carried_curves) {
    for (const int c : curves) list.riding_curves[std::size_t(c)] = true;
  }
}

}  // namespace

DrawList draw_list(const Document& doc, const Scene& scene, const std::filesystem::path& image_folder) {
  DrawList list;
  list.scene = &scene;
  list.control_polygons.resize(scene.objects.size());
  // The minimum guards a scene that lags behind its document (as the renderer always did).
  const std::size_t count = std::min(scene.objects.size(), doc.objects.size());
  for (std::size_t i = 0; i < count; ++i) {
    const Object& object = doc.objects[i];
    if (point_layout(object.kind()).polygon == PolygonStyle::Through && has_control_points(object.kind())) {
      list.control_polygons[i] = object.as<PointsPart>().points;
    } else if (has_control_points(object.kind())) {
      list.control_polygons[i] = list.drawn_polygons.emplace_back(control_polygon(object));
    }
    if (is_surface(object.kind()) && object.as<MaterialPart>().material >= 0) {
      list.materials.resize(count);
      list.materials[i] = surface_material(doc, static_cast<int>(i), image_folder);
    }
    if (object.kind() == ObjectKind::Subdivision && object.as<SubdivisionSurface>().source >= 0) {
      list.cage_only.resize(count, false);
      list.cage_only[static_cast<std::size_t>(object.as<SubdivisionSurface>().source)] = true;
    }
  }
  set_carried(list, doc);
  return list;
}

void add_riders(DrawList& list, const Document& doc, const Scene& scene, double time) {
  set_carried(list, doc);
  list.riders.clear();
  for (const int index : riders_of(doc)) {
    if (static_cast<std::size_t>(index) >= scene.objects.size() || !list.is_visible(std::size_t(index))) continue;
    if (scene.objects[std::size_t(index)].track.frames.empty()) continue;  // not evaluated yet (background)
    const RiderObject& rider = doc.objects[std::size_t(index)].as<RiderObject>();
    list.riders.push_back({rider.model, glm::mat4(rider_matrix(doc, scene, index, time))});
  }
}

}  // namespace sweep::render
