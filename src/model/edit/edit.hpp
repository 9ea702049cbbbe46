#pragma once
// Editing operations on a Document, as the viewer's editor performs them. Each operation
// either succeeds or throws EditError with a message for the user and leaves the document
// exactly as it was. Each returns a Change saying what to re-evaluate.
#include "model/document.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sweep {

class EditError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What an edit changed. When `structure` is false only the listed objects changed in place
/// (their dependents must be re-evaluated too: see dependents_of); when true, objects were
/// added, removed or re-pointed and the whole scene must be re-evaluated.
struct Change {
  std::vector<int> objects;
  bool structure = false;
};

/// True for a control-point curve that is closed by its basis's rule (is_closed,
/// geometry/curves/curve.hpp): a B-spline whose last three points repeat its first three (and it has at
/// least 6), any other whose last point equals its first (at least 4 points): exactly, as files
/// write them, or within 1e-9 times the size of the seam points (ends_repeat). O(1).
bool is_closed_polygon(const Object& curve);

/// The indices of the points that must move with `point` to keep a closed polygon closed
/// (`point` first; just {point} for an open curve).
std::vector<int> seam_partners(const Object& curve, int point);

/// Moves control point `point` of curve `object` to `position` (z is dropped for planar
/// curves) together with its seam partners. Throws for a bad index or a non-finite or
/// out-of-range (limits::kMaxCoordinate) position, and when a surface using the curve would no
/// longer accept it (a scale or twist graph whose x goes back, a scale <= 0, a birail profile
/// whose ends meet: check_users). Cost: a scan of the later objects' references, plus an
/// evaluation of the curves of a surface that reads this one as a graph or rail; no whole-
/// document check. At a closed
/// Bezier's seam only the end points move; the handles beside them stay where they are, so
/// the user decides how smooth the joint is.
Change move_point(Document& doc, int object, int point, const glm::dvec3& position);

/// One control point's new position in a move of several (move_points).
struct PointMove {
  int point = -1;
  glm::dvec3 to{0.0};
};

/// Moves several control points of curve `object` at once, as move_point moves one (each with
/// its seam partners, z dropped for planar curves), checked as one edit: a bad index, a non-
/// finite or out-of-range position, or a user surface that would refuse the curve throws and
/// changes nothing. A point listed twice ends where its last move puts it. Cost: one copy of the
/// curve's points and one check_users.
Change move_points(Document& doc, int object, std::span<const PointMove> moves);

/// Sets what a kind samples by: STEPS of a curve or a patch surface, an srev's copies about the
/// axis (its STEPS field), or a subd's LEVELS. Throws outside 1..limits::kMaxSteps (LEVELS: 0 to
/// kMaxSubdivisionLevel), for a kind with neither, or when the new mesh or sample count would
/// exceed a cap.
Change set_steps_or_levels(Document& doc, int object, int steps);

/// Sets a circle's radius. Throws unless limits::kMinRadius <= radius <= limits::kMaxCoordinate.
Change set_radius(Document& doc, int object, double radius);

/// The numbers of the curve kinds besides points and STEPS, as the Edit panel changes them.
enum class CurveParameter {
  Alpha,        // cr: knot spacing exponent
  Tension,      // cr, kb
  Continuity,   // kb
  Bias,         // kb
  Radius,       // circ, helix; knot: the tube radius r
  Pitch,        // helix
  Turns,        // helix
  MajorRadius,  // knot: R
  KnotP,        // knot (a whole number)
  KnotQ,        // knot (a whole number)
  AtX,          // helix, knot: where it stands (the `at X Y Z` clause)
  AtY,
  AtZ,
  Tolerance,  // every curve: adaptive sampling within it; 0 samples by STEPS
};

/// The parameter's name as the SWP file and the Edit panel spell it ("alpha", "R", "P", ...).
std::string_view parameter_name(CurveParameter parameter);
/// True if objects of `kind` have `parameter`.
bool has_parameter(ObjectKind kind, CurveParameter parameter);
/// The parameters objects of `kind` have, in the order an SWP file writes them: the kind's fixed
/// fields first (`knot NAME STEPS P Q R r`), then its clauses in their order (`[alpha A]
/// [tension T]`, ..., `tolerance`). The Edit panel lists them so.
std::vector<CurveParameter> parameters_in_file_order(ObjectKind kind);
/// The current value of `parameter` of `object` (P and Q as doubles). Precondition: has_parameter.
double parameter_value(const Object& object, CurveParameter parameter);
/// Sets `parameter` of curve `object`. Throws EditError for a kind without it and with the
/// reader's message (core/curve_parameters.hpp) for a value out of range; P and Q must be whole;
/// turns must keep the samples within the caps; a tolerance is 0 (off) or at least the floor
/// relative to the curve's size (adaptive.hpp). edit_parameters.cpp
Change set_curve_parameter(Document& doc, int object, CurveParameter parameter, double value);

/// Splits Bezier piece `piece` (0-based) of a bez2/bez3 curve at parameter t in (0, 1) by
/// de Casteljau: the curve keeps its exact shape and gains one piece (3 points).
Change split_bezier_piece(Document& doc, int object, int piece, double t);

/// Joins the two Bezier pieces that meet at joint point `joint` (a multiple of 3, not an end
/// point) into one, removing the joint and its two handles. The split parameter is recovered
/// as t = |joint - left handle| / (|joint - left handle| + |right handle - joint|) and the
/// outer handles keep their directions, scaled by 1/t and 1/(1-t): when the pieces came from a
/// split (collinear handles) this is the exact curve before the split (up to rounding);
/// otherwise an approximation with the same ends and end tangents' directions. A joint with a
/// zero-length handle uses the ratio of the pieces' chords instead. Throws if a new handle
/// would leave the coordinate range.
Change join_bezier_pieces(Document& doc, int object, int joint);

/// Inserts a control point into a B-spline or an interpolating curve (cr, kb) before index
/// `before` (0..size); a point inserted inside the repeated seam points of a closed curve keeps
/// it closed.
Change insert_bspline_point(Document& doc, int object, int before, const glm::dvec3& position);

/// An end of an open curve.
enum class CurveEnd { Start, End };
/// Adds past end `end` of open control-point curve `object` what its point layout adds (edit_extend.cpp):
/// a point (bsp, cr, kb, poly), a point and its tangent (herm: the neighbouring tangent), or a
/// whole Bezier piece whose first handle mirrors the end joint's handle, so the joint stays smooth
/// (G1, and C1: the handles are equally long). The new end is at `to` if given, else one step
/// further on (the last step between points; for a Bezier, three handle lengths straight on).
/// Throws for a closed curve ("... is closed: it has no end to extend"), a curve without points
/// or a position out of range.
Change extend_curve(Document& doc, int object, CurveEnd end, const std::optional<glm::dvec3>& to = std::nullopt);
/// Which end of open control-point curve `curve` its entry `point` is (the first entry, or the
/// last joint of a Bezier, the last group's point of the others), if any.
std::optional<CurveEnd> end_at(const Object& curve, int point);
/// The entry of control-point curve `curve` at `end` (end_at's converse). Precondition: it has points.
int end_point(const Object& curve, CurveEnd end);

/// A curve converted to another kind (edit_convert.cpp): the new curve, the largest distance
/// between it and the old one (0 when exact), and whether the conversion is exact.
struct Conversion {
  Object curve;
  double deviation = 0.0;
  bool exact = true;
};
/// `curve` (a kind with control points) as kind `to` of the same dimension, keeping its name,
/// place, STEPS and tolerance: exactly to Bezier (its cubic pieces) and to Hermite (throws,
/// naming the joint, at a corner: one tangent per point); to B-spline by least squares, to
/// Catmull-Rom through points on the curve, each with twice the points until the deviation
/// (curve_deviation_between) is within `tolerance` > 0 or 4096 points are reached. Throws
/// EditError for a kind without points, another dimension or the curve's own kind.
Conversion convert_curve(const Object& curve, ObjectKind to, double tolerance);
/// Replaces curve `object` by its conversion (one change; references to it are kept: same index
/// and name); the result in `*result` when given.
Change convert_curve(Document& doc, int object, ObjectKind to, double tolerance, Conversion* result = nullptr);
/// The largest distance from either curve's dense samples (32 per piece) to the other's polyline.
double curve_deviation_between(const Object& a, const Object& b);

/// Deletes a B-spline control point (keeping at least 4; a closed B-spline stays closed and
/// keeps at least 4 distinct points + its 3 repeats, or says why not), or for a Bezier curve
/// joins the pieces at a joint (handles and end points cannot be deleted: says so).
Change delete_point(Document& doc, int object, int point);

/// A Create-panel template, as a curve kind declares it (`templates`, kind_fields.hpp): its label,
/// the stem of a new curve's name, its kind, and the curve it makes (name empty).
struct CurveTemplateInfo {
  std::string_view label;
  std::string_view base_name;
  ObjectKind kind;
  int order;
  Object (*make)();
};
/// Every kind's templates, in the order the Create panel lists them.
std::span<const CurveTemplateInfo> curve_templates();

/// A name not used by any object, made from `base` ("profile", "profile2", ...).
std::string unique_name(const Document& doc, std::string_view base);

/// Appends a new curve made from the template labelled `label` (curve_templates). Returns its
/// index. Throws if there is no such template, or `name` is taken or not a valid SWP name (one
/// token of letters, digits, '_', '-', '.'; "" means anonymous).
int add_curve(Document& doc, std::string_view label, const std::string& name);

/// Appends a curve of control-point kind `kind` named `name` ("": anonymous) with `points` (STEPS
/// 16, as the templates), as the pen draws it (editor/pen.hpp). Throws EditError for a kind without
/// control points, a taken or invalid name, a count the reader refuses ("a drawn bsp2: expected
/// ..."), a position out of range or a curve over the caps. Returns its index. edit_draw.cpp
int add_drawn_curve(Document& doc, ObjectKind kind, const std::string& name, std::vector<glm::dvec3> points);
/// Replaces every point of control-point curve `object` with `points`, checked as add_drawn_curve
/// checks them and as the surfaces using the curve need.
Change set_curve_points(Document& doc, int object, std::vector<glm::dvec3> points);

/// What a new object is placed beside (edit_place.cpp): the box of what the view shows (lo > hi
/// on some axis: nothing) and its ground grid (height and spacing, editor/overlay_builder.hpp).
struct SceneBox {
  glm::dvec3 lo{1.0};
  glm::dvec3 hi{-1.0};
  double ground = 0.0;
  double step = 1.0;
};
/// Sizes and places a new curve where the user can see it, when the scene has something in it
/// (its largest side from 1e-6 to 1e9, so that the numbers stay within the reader's ranges):
/// scaled about the origin by a nice factor (1, 2 or 5 times a power of ten) so that its largest
/// side is near half the scene's, then, for a 3D curve, moved (its points, or a helix's or torus
/// knot's `at`) beside the scene: on the +x side, a gap of a quarter of the scene's largest side
/// away, its lowest point on the ground, its middle at the scene's middle in z, on grid lines.
/// A 2D curve is a profile whose coordinates are its place in the frame of every surface made
/// from it, so it is only scaled. Returns what it did (" (scaled by 2, beside the scene)"; ""
/// for an empty scene), for the status bar.
std::string place_new_curve(Object& curve, const SceneBox& scene);
/// add_curve, then place_new_curve; `how` receives what the placing did.
int add_curve(Document& doc, std::string_view label, const std::string& name, const SceneBox& scene, std::string& how);
/// Multiplies every length of a curve by `factor` > 0 about the origin: its points (a Hermite
/// curve's tangents too), radii, pitch and place.
void scale_curve(Object& curve, double factor);
/// How much a generalized cylinder's profile must shrink so that its tube never folds over itself
/// where the sweep bends most: the largest nice factor (1, 2 or 5 times a power of ten) that brings
/// the profile's reach from its origin within half the sweep's smallest bend radius (1 / its
/// largest curvature); 1 when it is within already. Both are curves of `doc`.
double profile_fit_factor(const Document& doc, int profile, int sweep);
/// True when some object refers to object `index` (references, document.hpp).
bool is_referenced(const Document& doc, int index);

/// Inserts a material named `name` (the default look) as the document's first object, so every
/// surface may use it; returns its index, 0. Throws EditError for a name in use or not valid.
int add_material(Document& doc, const std::string& name);
/// Gives surface `surface` material `material` (-1: the default look). The material must be
/// defined before the surface.
Change set_surface_material(Document& doc, int surface, int material);
/// Sets a material's colour, shininess, texture or checker and bump from `look`'s fields,
/// checked as the reader checks them (image paths relative to `image_folder`), except that an
/// image it names anew must be there (the reader lets a missing one pass with a warning), and
/// one the material has already is not checked again (a missing one stays a placeholder).
Change set_material_look(Document& doc, int material, const Object& look, const std::filesystem::path& image_folder);

/// Appends a surface of revolution of 2D curve `profile`, or (kind GeneralizedCylinder) a
/// generalized cylinder of `profile` along `sweep`, or (kind Birail) a birail surface of
/// `profile` along the rails `sweep` and `rail2` (which must be both open or both closed, with a
/// profile whose ends are apart). `sweep` is ignored for srev and `steps`
/// (1..limits::kMaxSteps) for gcyl. Throws for a 3D profile, a reference to a non-curve or to an
/// anonymous curve (files refer by name: name it first), a taken or invalid name, or a mesh over
/// the caps. Returns its index.
int add_surface(Document& doc, ObjectKind kind, const std::string& name, int profile, int sweep, int steps,
                int rail2 = -1);

/// The curves a generalized cylinder reads as graphs over its sweep (sweep_controls.hpp).
enum class SurfaceGraph { Scale, Twist };
/// Sets (`curve` >= 0) or removes (-1) the scale or twist graph of generalized cylinder
/// `object`. The curve must be a named 2D curve before the surface; throws with the reader's
/// message when its samples are no graph (x going back, a scale <= 0) or a twist would not
/// close a closed sweep. edit_surface.cpp
Change set_surface_graph(Document& doc, int object, SurfaceGraph graph, int curve);
/// Sets the linear twist (degrees, |degrees| <= 1e6) of generalized cylinder `object`, which
/// replaces a twist graph; throws if it would not close a closed sweep.
Change set_twist(Document& doc, int object, double degrees);
/// The on/off clauses of the surfaces: `caps` (srev, gcyl) and `height` (birail).
enum class SurfaceFlag { Caps, Height, Loop, SmoothBoundary };
/// True if surfaces of `kind` have the flag.
bool has_flag(ObjectKind kind, SurfaceFlag flag);
/// The flag's value on `object` (false for kinds without it).
bool flag_value(const Object& object, SurfaceFlag flag);
Change set_surface_flag(Document& doc, int object, SurfaceFlag flag, bool on);

/// Appends a rider of surface `model` along curve `path` (both named, before it) with the default
/// clauses. Throws for a path that is not a curve, a model that is not a surface, an anonymous
/// one (files refer by name), or a taken or invalid name. Returns its index. edit_rider.cpp
int add_rider(Document& doc, const std::string& name, int path, int model);
/// Sets rider `object`'s path, model, seconds, start and up from `value`, each checked as the
/// reader checks it (references, seconds > 0, start in [0, 1), up finite: zero means none).
Change set_rider(Document& doc, int object, const RiderObject& value);

/// Renames an object ("" makes it anonymous). Throws if the name is taken or not a valid SWP
/// name, or for "" when a surface uses the object (references are written by name).
Change rename_object(Document& doc, int object, const std::string& name);

/// Replaces the document's objects by those of `replacement` (a recovery copy read back), keeping
/// the file's text: an object equal to one of the document's with its name keeps that one (its
/// place in the text, so a save writes its lines as they were); the others are new objects.
/// Precondition: `replacement` is valid. A structure change (or nothing, when the two are equal).
Change replace_objects(Document& doc, const Document& replacement);

/// Deletes an object and updates the references of later objects. Throws
/// "cannot delete 'NAME': surface 'S' uses it" when a surface refers to it.
Change delete_object(Document& doc, int object);

}  // namespace sweep
