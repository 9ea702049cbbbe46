#pragma once
// The walk of an SVG drawing's elements into bez2 curves (svg/import.hpp states the rules), split
// over svg/import.cpp (the walk and the curves), svg/element.cpp (namespaces, conditions,
// visibility, transforms, lengths), svg/use.cpp (<use> clones and <symbol>s) and svg/shapes.cpp
// (shapes as path data). Internal to sweep_io.
#include "io/files/import_file.hpp"
#include "io/svg/detail/length.hpp"
#include "io/svg/detail/path.hpp"
#include "io/svg/detail/transform.hpp"
#include "model/caps.hpp"
#include "model/document.hpp"

#include <tinyxml2.h>

#include <array>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace sweep::io::svg_detail {

/// What an element gets from where it is drawn.
struct DrawContext {
  Affine2 to_swp;       // its parent's user space to SWP
  Viewport viewport;    // the nearest viewport, which percentages refer to
  bool visible = true;  // the inherited visibility
};

/// Reads one drawing: the file's name for messages, the curves so far, their names and counts.
class DrawingReader {
 public:
  using XMLElement = tinyxml2::XMLElement;

  /// Preconditions: is_valid_object_name(unnamed), scale finite and > 0.
  DrawingReader(std::string_view file, const std::string& unnamed, double scale)
      : file_(file), unnamed_(unnamed), scale_(scale) {}

  /// The curves of the drawing whose root element is `root`. Throws ImportError.
  Document read(const XMLElement& root);

  /// The element's name without its prefix if it is in the SVG namespace (unprefixed elements
  /// are unless a default namespace says otherwise; the prefix "svg" is even undeclared); empty
  /// for elements of other namespaces (sodipodi:namedview).
  static std::string_view svg_name(const XMLElement& e);

 private:
  // svg/import.cpp: the walk and the curves.
  glm::dvec2 root_units(const XMLElement& root) const;
  Viewport root_viewport(const XMLElement& root) const;
  std::optional<Length> root_length(const XMLElement& root, const char* name) const;
  void walk_children(const XMLElement& parent, const DrawContext& context);
  void visit(const XMLElement& e, const DrawContext& context);
  void add_curves(const XMLElement& e, std::string_view name, const DrawContext& context);
  void add_curve(const XMLElement& e, const BezierSubpath& subpath, const Affine2& to_swp);
  std::string unique_name(const char* id);

  // svg/element.cpp: what applies to every element.
  static bool applies(const XMLElement& e);
  static bool displayed(const XMLElement& e);
  static bool visibility(const XMLElement& e, bool inherited);
  static const XMLElement* switch_choice(const XMLElement& e);
  Affine2 transform_of(const XMLElement& e, const Viewport& viewport) const;
  std::optional<double> length_or_auto(const XMLElement& e, const char* name, LengthAxis axis,
                                       const Viewport& viewport) const;
  double length_attribute(const XMLElement& e, const char* name, LengthAxis axis, const Viewport& viewport) const;
  std::optional<std::array<double, 4>> view_box(const XMLElement& e) const;

  // svg/use.cpp: clones.
  void draw_use(const XMLElement& use, const DrawContext& context);
  void draw_symbol(const XMLElement& symbol, const XMLElement& use, DrawContext context);
  const XMLElement& referenced(const XMLElement& use);

  // svg/shapes.cpp: a shape's outline as path data.
  std::string path_data(const XMLElement& e, std::string_view name, const Viewport& viewport) const;

  std::string_view file_;
  std::string unnamed_;
  double scale_;
  const XMLElement* root_ = nullptr;
  Document doc_;
  std::set<std::string> used_;
  CapTally tally_;
  std::int64_t points_ = 0;
  std::unordered_map<std::string, const XMLElement*> ids_;  // filled at the first <use>
  std::vector<const XMLElement*> uses_;                     // the <use>s being drawn, outermost first
  std::int64_t cloned_elements_ = 0;                        // elements drawn through <use>s, at most:
  static constexpr std::int64_t kMaxClonedElements = 1'000'000;
};

}  // namespace sweep::io::svg_detail
