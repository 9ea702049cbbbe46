// Edits of materials: a new material, a surface's choice of material, and a material's look.
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/material.hpp"

#include <cmath>

namespace sweep {

using namespace edit_support;

namespace {

/// Every reference of every object moved up by one (an object was inserted first).
void shift_references(Document& doc) {
  for (Object& o : doc.objects) {
    for (int* r : reference_slots(o)) {
      if (*r >= 0) ++*r;
    }
  }
}

/// "" if `look` is a valid material, else what is wrong (the reader's words). An image the
/// material has already (`current`'s) is not checked again: one missing since the file was read
/// (MissingImage) stays, so its colour or shininess can still be changed.
std::string look_problem(const Object& object, const MaterialLook& current, const std::filesystem::path& image_folder) {
  const MaterialLook& look = object.as<MaterialLook>();
  for (int c = 0; c < 3; ++c) {
    if (!(look.color[c] >= 0.0 && look.color[c] <= 1.0)) return "colour components must be from 0 to 1";
  }
  if (!(look.shininess >= 1.0 && look.shininess <= 1000.0)) return "the shininess must be from 1 to 1000";
  if (look.checker < 0 || look.checker > 256) return "the checker must have from 1 to 256 cells per side (0: none)";
  if (look.checker > 0 && !look.texture.empty()) return "a material has a texture or a checker, not both";
  if (!(look.bump_height >= 0.0 && look.bump_height <= 1e12)) return "the bump height must be from 0 to 1e12";
  for (const std::string* image : {&look.texture, &look.bump}) {
    if (image->empty() || *image == current.texture || *image == current.bump) continue;
    const std::filesystem::path p(*image);
    const std::string problem = image_problem(p.is_absolute() ? p : image_folder / p);
    if (!problem.empty()) return problem;
  }
  return {};
}

}  // namespace

int add_material(Document& doc, const std::string& name) {
  check_new_name(doc, -1, name);
  Object material;
  material.set_kind(ObjectKind::Material);
  material.name = name;
  shift_references(doc);
  doc.objects.insert(doc.objects.begin(), std::move(material));
  return 0;
}

Change set_surface_material(Document& doc, int surface, int material) {
  check_object_index(doc, surface);
  Object changed = doc.objects[to_size(surface)];
  if (!is_surface(changed.kind())) throw EditError(quoted(doc, surface) + " is not a surface: it takes no material");
  if (material >= 0) {
    check_object_index(doc, material);
    if (!is_material(doc.objects[to_size(material)].kind())) {
      throw EditError(quoted(doc, material) + " is not a material");
    }
    if (material > surface) {
      throw EditError("material " + quoted(doc, material) + " is defined after " + quoted(doc, surface) +
                      "; references point backwards only");
    }
  }
  changed.as<MaterialPart>().material = material;
  return commit(doc, surface, std::move(changed));
}

Change set_material_look(Document& doc, int material, const Object& look, const std::filesystem::path& image_folder) {
  check_object_index(doc, material);
  Object changed = doc.objects[to_size(material)];
  if (!is_material(changed.kind())) throw EditError(quoted(doc, material) + " is not a material");
  if (const std::string problem = look_problem(look, changed.as<MaterialLook>(), image_folder); !problem.empty()) {
    throw EditError("material " + quoted(doc, material) + ": " + problem);
  }
  changed.as<MaterialLook>() = look.as<MaterialLook>();
  Change change = commit(doc, material, std::move(changed));
  change.structure = true;  // the surfaces that use it are drawn again (their seams may split)
  return change;
}

}  // namespace sweep
