#pragma once
// The material. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

#include <array>
#include <string_view>

namespace sweep {

/// A material: colour (0-1 each), shininess, a texture (PNG path as written, relative to the SWP
/// file) or an N x N checker (0: none), a bump (height PNG) and its height in model units.
struct MaterialLook {
  static constexpr KindTraits traits{.keyword = "material",
                                     .family = KindFamily::Material,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "material",
                                     .phrase = "a material"};
  glm::dvec3 color{kDefaultColor[0], kDefaultColor[1], kDefaultColor[2]};
  double shininess = kDefaultShininess;
  std::string texture;
  int checker = 0;
  std::string bump;
  double bump_height = 0.0;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const MaterialLook&) const = default;
};
/// A material's clause keys, each at most once and in any order: `color R G B`, `shininess S`,
/// `texture FILE.png`, `checker N`, `bump FILE.png H` (read in swp/reader_surfaces.cpp).
inline constexpr std::array<std::string_view, 5> kMaterialKeys = {"color", "shininess", "texture", "checker", "bump"};
/// A material's own clauses take several values (swp/reader_surfaces.cpp, read_material).
template <>
inline constexpr std::span<const SwpClause> kind_clauses<MaterialLook> = {};

}  // namespace sweep
