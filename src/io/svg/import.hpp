#pragma once
// Reading an SVG drawing's paths and shapes as `bez2` curves, one per subpath. tinyxml2 reads the
// XML; svg/detail/path.hpp reads path data, svg/detail/transform.hpp the transforms.
//
// Units: SWP (x, y) = s * (X, -Y) for user coordinates (X, Y) after every transform, with
// s = `scale` times the length of one user unit in the document's unit. The document's unit is the
// millimetre when the root's width or height has a physical unit (mm, cm, in, pt, pc, Q), and the
// CSS pixel otherwise (no width and height, a plain number, px or %). One user unit is width /
// viewBox width of those (height / viewBox height if smaller, preserveAspectRatio="none" keeps both),
// or 1 px without a viewBox. So an Inkscape drawing in mm is in mm, and a plain <path> in a
// document without units or viewBox keeps its numbers exactly (y negated). The user space's origin
// stays SWP's origin (the viewBox's offset moves nothing). Lengths of shape attributes may carry
// units: 96 px per inch, 1 px per user unit; percentages are of the viewport (the root's viewBox,
// else its width and height; a symbol's), x lengths of its width, y lengths of its height, others
// of its diagonal / sqrt(2) (SVG 1.1 section 7.10).
//
// Imported: path, rect (rounded corners too), circle, ellipse (one radius given or `auto`: both
// are it), line, polyline, polygon, inside any groups (g, a; of a switch only its first child
// whose conditions hold: no requiredExtensions, a systemLanguage with English), each with its
// transforms: the `transform` attribute, or the CSS `transform` in its `style`, turned about its
// `transform-origin` (of the viewport: transform-box view-box). A <use> draws the shape, group or
// <use> it references again, after its transform and its x and y; a <symbol> it references is
// drawn in a viewport of the use's width and height (else the symbol's, else 100%), its viewBox
// fitted as preserveAspectRatio says. Elements are SVG by their namespace, with any prefix
// (<s:rect xmlns:s="http://www.w3.org/2000/svg">). Skipped silently: what is never drawn directly
// (defs, symbol, clipPath, mask, marker, pattern, gradients, filter), what holds no curves (text,
// image, metadata, title, desc, style, script), elements of other namespaces
// (sodipodi:namedview), elements with display none or whose conditions fail, shapes with
// visibility hidden or collapse (a child may be visible again), and shapes of no length (every
// control point at one place). Refused: a nested <svg>; a <use> whose reference is not an element
// of this file ('#id') or contains it (a cycle); transform-box other than view-box; a DOCTYPE that
// declares entities.
//
// Revolved (`sweep import --revolve`): each curve is then the profile of a surface of revolution
// about the y axis (model/evaluation/revolve_curves.hpp: curve NAME becomes NAME_profile, followed by
// `srev NAME 48 NAME_profile`). A vase drawn from the axis (x = 0) outwards becomes the vase.
#include "io/mesh/obj_import.hpp"
#include "model/document.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace sweep::io {

/// What the imported curves become: bez2 curves, or each also the profile of a surface of revolution.
enum class DrawingImport { Curves, Revolved };

/// Turns around the y axis of each surface of a revolved import: the starter files' srev STEPS
/// (bezier-vase.swp, solids.swp), smooth in a picture of a vase at any size (7.5 degrees a step).
inline constexpr int kRevolvedSteps = 48;

/// The drawing of SVG text as bez2 curves in document order, named after their element's id
/// (made valid and unique: "vase", "vase_2"), or `unnamed` for elements with no id; each with 16
/// steps per piece. `file_name` is only used in messages ("FILE:LINE: ..." or "FILE: ...").
/// DrawingImport::Revolved adds a surface of revolution per curve (see above); the document's caps
/// then count the surfaces' vertices too. Preconditions: is_valid_object_name(unnamed), scale
/// finite and > 0. Throws ImportError.
Document parse_svg_drawing(const std::string& text, std::string_view file_name, const std::string& unnamed,
                           double scale, DrawingImport what = DrawingImport::Curves);

/// Reads the SVG file at `path` (at most limits::kMaxFileBytes) with parse_svg_drawing. Throws
/// ImportError.
Document import_svg_drawing(const std::filesystem::path& path, const std::string& unnamed, double scale,
                            DrawingImport what = DrawingImport::Curves);

}  // namespace sweep::io
