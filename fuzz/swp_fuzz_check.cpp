#include "swp_fuzz_check.hpp"

#include "geometry/curves/adaptive.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/unit_vector.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/evaluation/riders.hpp"
#include "model/evaluation/scene.hpp"
#include "model/material.hpp"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <exception>
#include <vector>

namespace sweep::fuzz {
namespace {

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
bool unit(const glm::dvec3& v) {
  return finite(v) && std::abs(glm::length(v) - 1.0) < 1e-6;
}

/// Vertex and triangle counts the surface must have, from its inputs' sample counts.
struct SurfaceCounts {
  std::int64_t vertices = 0;
  std::int64_t triangles = 0;
  /// Tubes and birails leave out triangles with two corners at one place where rings are clipped
  /// together or meet (add_quad_without_collapsed): `triangles` is then at most.
  bool at_most = false;
};

/// True if `mesh` has the triangle count `expected` asks for.
bool triangles_as_expected(const Mesh& mesh, const SurfaceCounts& expected) {
  const auto triangles = static_cast<std::int64_t>(mesh.triangle_count());
  if (!expected.at_most) return triangles == expected.triangles;
  return triangles <= expected.triangles;
}

/// The caps' share (caps.hpp): a copy of the end rings (gcyl: n - 2 triangles each; srev: a fan
/// from a centre vertex at each end off the axis).
SurfaceCounts cap_counts(const Object& object, const CurveSamples& profile, const CurveSamples& sweep) {
  const auto* caps = object.find<sweep::CapsPart>();
  if (caps == nullptr || !caps->caps) return {0, 0};
  const auto ring = static_cast<std::int64_t>(profile.frames.size()) - (profile.closed ? 1 : 0);
  if (object.kind() == ObjectKind::GeneralizedCylinder) {
    if (!profile.closed || sweep.closed || ring < 3) return {0, 0};
    return {2 * ring, 2 * (ring - 2)};
  }
  const int copies = object.as<sweep::RevolutionSurface>().copies;
  if (profile.closed || copies < 3) return {0, 0};
  glm::dvec3 lo = profile.frames.front().V, hi = lo;
  for (const Frame& f : profile.frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  const double on_axis = 1e-6 * vector_length(hi - lo);
  std::int64_t ends = 0;
  for (const Frame* end : {&profile.frames.front(), &profile.frames.back()}) ends += std::abs(end->V.x) > on_axis;
  return {ends * (copies + 1), ends * copies};
}

/// Patches, cages and subdivision surfaces: exact counts where the topology says them (a cage;
/// a subd of a cage), bounds where welding decides (patches; grids as cages).
SurfaceCounts net_counts(const Object& object, const Document& doc, const Mesh& mesh) {
  const SurfaceCounts actual{static_cast<std::int64_t>(mesh.vertex_count()),
                             static_cast<std::int64_t>(mesh.triangle_count())};
  std::int64_t most_vertices = 0;
  std::int64_t most_triangles = 0;
  const int* steps_part = sweep::steps_field(object);
  const std::int64_t steps = steps_part ? *steps_part : 0;
  if (const auto* patches = object.find<sweep::BezierPatchSurface>()) {
    const auto count = static_cast<std::int64_t>(patches->points.size() / 16);
    most_vertices = bezier_patch_vertex_count(count, steps);
    most_triangles = 2 * count * steps * steps;
  } else if (const auto* patch = object.find<sweep::BSplinePatchSurface>()) {
    most_vertices = bspline_patch_vertex_count(patch->rows, patch->columns, steps);
    most_triangles = 2 * (patch->rows - 3) * (patch->columns - 3) * steps * steps;
  } else if (const auto* cage = object.find<sweep::PolygonMeshSurface>()) {
    std::int64_t triangles = 0;
    for (const int n : cage->face_sizes) triangles += n - 2;
    return {static_cast<std::int64_t>(cage->points.size()), triangles};
  } else {
    const sweep::SubdivisionSurface& subd = object.as<sweep::SubdivisionSurface>();
    const Object& source = doc.objects[static_cast<std::size_t>(subd.source)];
    if (source.kind() != ObjectKind::PolygonMesh) return actual;
    const SubdivisionScheme scheme = subd.loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
    const CageCounts c = refined_counts(cage_of(source), subd.levels, scheme);
    if (subd.levels == 0) return net_counts(source, doc, mesh);
    return {c.vertices, scheme == SubdivisionScheme::Loop ? c.faces : 2 * c.faces};
  }
  return actual.vertices <= most_vertices && actual.triangles <= most_triangles ? actual : SurfaceCounts{-1, -1};
}

SurfaceCounts expected_counts(const Object& object, const Document& doc, const Scene& scene, const Mesh& mesh) {
  if (has_control_net(object.kind()) || object.kind() == ObjectKind::Subdivision) return net_counts(object, doc, mesh);
  const sweep::SweptCurves curves = sweep::swept_curves(object);
  const CurveSamples& profile = scene.objects[static_cast<std::size_t>(curves.profile)].curve;
  const auto profile_samples = static_cast<std::int64_t>(profile.frames.size());
  static const CurveSamples none;
  const CurveSamples& sweep = curves.path >= 0 ? scene.objects[static_cast<std::size_t>(curves.path)].curve : none;
  const SurfaceCounts caps = cap_counts(object, profile, sweep);
  if (const auto* revolution = object.find<sweep::RevolutionSurface>()) {
    return {revolution_vertex_count(profile_samples, profile.closed, revolution->copies) + caps.vertices,
            sweep::revolution_triangle_count(profile, revolution->copies) + caps.triangles};
  }
  const auto sweep_samples = static_cast<std::int64_t>(sweep.frames.size());
  if (object.kind() == ObjectKind::Birail) {
    // One ring per station; the stations merge both rails' samples, so at least the more of them.
    const CurveSamples& rail2 = scene.objects[static_cast<std::size_t>(curves.rail2)].curve;
    const bool closed = sweep.closed && rail2.closed;
    const std::int64_t rings = static_cast<std::int64_t>(mesh.vertex_count()) / profile_samples;
    const auto most = static_cast<std::int64_t>(std::max(sweep.frames.size(), rail2.frames.size()));
    if (rings * profile_samples != static_cast<std::int64_t>(mesh.vertex_count()) || rings < most - (closed ? 1 : 0) ||
        rings > sweep_samples + static_cast<std::int64_t>(rail2.frames.size())) {
      return {-1, -1};
    }
    return {rings * profile_samples, 2 * (profile_samples - 1) * (closed ? rings : rings - 1), true};
  }
  // evaluate_document's default options: the default mitre limit.
  const auto bevels = static_cast<std::int64_t>(sweep::bevel_count(sweep, sweep::kMitreLimit));
  return {cylinder_vertex_count(profile_samples, profile.closed, sweep_samples, sweep.closed, bevels) + caps.vertices,
          cylinder_triangle_count(profile_samples, sweep_samples, bevels) + caps.triangles, true};
}

/// How many seam vertices texturing may add to a swept surface (0 for other surfaces).
std::int64_t seam_copy_bound(const Object& o, const Scene& scene) {
  const sweep::SweptCurves curves = sweep::swept_curves(o);
  if (curves.profile < 0) return 0;
  const auto samples = [&scene](int index) {
    return index >= 0 ? static_cast<std::int64_t>(scene.objects[static_cast<std::size_t>(index)].curve.frames.size())
                      : std::int64_t{0};
  };
  const auto* revolution = o.find<sweep::RevolutionSurface>();
  const std::int64_t around = revolution ? revolution->copies : samples(curves.path) + samples(curves.rail2);
  return samples(curves.profile) + around + 1;
}

/// Work the document asks for, with the parser's own (upper bound) formulas.
bool within_fuzz_bounds(const Document& doc) {
  std::int64_t samples = 0;
  std::int64_t vertices = 0;
  std::vector<std::int64_t> each;  // per object, its vertices (a subd's source)
  for (const Object& o : doc.objects) {
    const std::int64_t before = vertices;
    if (is_material(o.kind()) || is_rider(o.kind())) {
      // no geometry of its own (a rider draws its model where it rides)
    } else if (o.kind() == ObjectKind::BezierPatch) {
      vertices += bezier_patch_vertex_count(static_cast<std::int64_t>(o.as<sweep::PointsPart>().points.size() / 16),
                                            o.as<sweep::StepsPart>().steps);
    } else if (o.kind() == ObjectKind::BSplinePatch) {
      vertices +=
          bspline_patch_vertex_count(o.as<sweep::BSplinePatchSurface>().rows,
                                     o.as<sweep::BSplinePatchSurface>().columns, o.as<sweep::StepsPart>().steps);
    } else if (o.kind() == ObjectKind::PolygonMesh) {
      vertices += static_cast<std::int64_t>(o.as<sweep::PointsPart>().points.size());
    } else if (o.kind() == ObjectKind::Subdivision) {
      std::int64_t v = each[static_cast<std::size_t>(o.as<sweep::SubdivisionSurface>().source)];
      for (int level = 0; level < o.as<sweep::SubdivisionSurface>().levels && v <= kMaxFuzzMeshVertices; ++level)
        v *= 4;
      vertices += v;
    } else if (is_curve(o.kind())) {
      samples += curve_sample_count(o);
    } else {
      const auto samples_of = [&doc](int index) {
        return curve_sample_count(doc.objects[static_cast<std::size_t>(index)]);
      };
      const sweep::SweptCurves curves = sweep::swept_curves(o);
      const std::int64_t profile = samples_of(curves.profile);
      if (const auto* revolution = o.find<sweep::RevolutionSurface>()) {
        vertices += revolution_vertex_count(profile, false, revolution->copies);
      } else if (curves.rail2 >= 0) {
        vertices += birail_vertex_count(profile, samples_of(curves.path), samples_of(curves.rail2));
      } else {
        // Bevels can come only at the path's joints, and a curve has fewer joints than points.
        const sweep::Object& path = doc.objects[static_cast<std::size_t>(curves.path)];
        const auto* points = path.find<sweep::PointsPart>();
        const std::int64_t joints = points ? static_cast<std::int64_t>(points->points.size()) : 0;
        vertices += cylinder_vertex_count(profile, false, samples_of(curves.path), false, joints);
      }
    }
    each.push_back(vertices - before);
  }
  return samples <= kMaxFuzzCurveSamples && vertices <= kMaxFuzzMeshVertices;
}

/// One face corner "a//a" or "a/a/a" (texture coordinates share the vertex's index).
bool face_corner_ok(std::string_view field, std::size_t vertices) {
  std::array<unsigned long, 3> index{};
  std::size_t count = 0;
  std::size_t p = 0;
  while (p <= field.size() && count < 3) {
    std::size_t q = field.find('/', p);
    if (q == std::string_view::npos) q = field.size();
    if (q > p) {
      unsigned long value = 0;
      if (std::from_chars(field.data() + p, field.data() + q, value).ptr != field.data() + q) return false;
      index[count++] = value;
    }
    p = q + 1;
  }
  if (count < 2) return false;
  for (std::size_t k = 1; k < count; ++k) {
    if (index[k] != index[0]) return false;
  }
  return index[0] >= 1 && index[0] <= vertices;
}

std::string check_obj(const Mesh& mesh, const std::string& where) {
  const std::string text = io::obj_text(mesh, "fuzz");
  std::size_t v = 0, vn = 0, vt = 0, f = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    std::size_t end = text.find('\n', pos);
    if (end == std::string::npos) return where + ": OBJ text does not end with a newline";
    const std::string_view line(text.data() + pos, end - pos);
    pos = end + 1;
    if (line.starts_with("# ") || line.starts_with("mtllib ") || line.starts_with("usemtl ")) continue;
    const bool is_v = line.starts_with("v "), is_vn = line.starts_with("vn "), is_vt = line.starts_with("vt "),
               is_f = line.starts_with("f ");
    if (!is_v && !is_vn && !is_vt && !is_f) return where + ": unexpected OBJ line '" + std::string(line) + "'";
    std::size_t p = line.find(' ') + 1;
    int fields = 0;
    while (p <= line.size()) {
      std::size_t q = line.find(' ', p);
      if (q == std::string_view::npos) q = line.size();
      const std::string_view field = line.substr(p, q - p);
      ++fields;
      if (is_f) {
        if (!face_corner_ok(field, mesh.vertex_count())) {
          return where + ": bad OBJ face field '" + std::string(field) + "'";
        }
      } else {
        double value = 0.0;
        const auto r = std::from_chars(field.data(), field.data() + field.size(), value);
        if (r.ec != std::errc() || r.ptr != field.data() + field.size() || !std::isfinite(value)) {
          return where + ": bad OBJ number '" + std::string(field) + "'";
        }
      }
      p = q + 1;
    }
    const int wanted = is_vt ? 2 : 3;
    if (is_f ? fields < 3 : fields != wanted) return where + ": OBJ line with " + std::to_string(fields) + " fields";
    (is_v ? v : is_vn ? vn : is_vt ? vt : f) += 1;
  }
  const std::size_t faces = mesh.polygon_sizes.empty() ? mesh.triangle_count() : mesh.polygon_sizes.size();
  if (v != mesh.vertex_count() || vn != mesh.vertex_count() || f != faces || (vt != 0 && vt != v)) {
    return where + ": OBJ has " + std::to_string(v) + " v, " + std::to_string(vn) + " vn, " + std::to_string(vt) +
           " vt, " + std::to_string(f) + " f lines for " + std::to_string(mesh.vertex_count()) + " vertices and " +
           std::to_string(faces) + " faces";
  }
  return {};
}

/// An adaptively sampled curve: parameters in order, one per sample, and every chord within
/// the tolerance of the curve (measured when the curve is small enough to measure quickly).
std::string check_adaptive_curve(const Object& o, const CurveSamples& c, double tolerance, const std::string& where) {
  if (c.parameters.size() != c.frames.size()) return where + ": one parameter per sample expected";
  for (std::size_t k = 1; k < c.parameters.size(); ++k) {
    if (!(c.parameters[k] >= c.parameters[k - 1])) return where + ": sample parameters out of order";
  }
  if (c.capped || c.frames.size() > kMaxFuzzObjVertices) return {};
  // Float noise of the coordinates themselves is not a sampling error.
  const double slack = 1e-9 * std::max(curve_extent(o), 1.0);
  const double deviation = curve_deviation(o, c, 16);
  if (deviation > tolerance * (1.0 + 1e-9) + slack) {
    return where + ": adaptive samples stray " + std::to_string(deviation) + " from the curve, tolerance " +
           std::to_string(tolerance);
  }
  return {};
}

bool orthonormal(const Frame& f) {
  return finite(f.V) && unit(f.T) && unit(f.N) && unit(f.B) && std::abs(glm::dot(f.T, f.N)) <= 1e-6 &&
         std::abs(glm::dot(f.T, f.B)) <= 1e-6 && glm::dot(glm::cross(f.T, f.N), f.B) >= 1.0 - 1e-6;
}

/// A rider at a few times (before the start, across a loop, far on): a finite, right-handed
/// orthonormal frame within the box of its path's samples (grown by a share of its size).
std::string check_rider(const Document& doc, const Scene& scene, int index, const std::string& where) {
  const RiderTrack& track = scene.objects[static_cast<std::size_t>(index)].track;
  if (track.frames.empty()) return where + ": rider without a track";
  glm::dvec3 lo = track.frames.front().V, hi = lo;
  for (const Frame& f : track.frames) lo = glm::min(lo, f.V), hi = glm::max(hi, f.V);
  const double slack = 0.5 * vector_length(hi - lo) + 1e-9;
  for (const double time : {-3.5, 0.0, 0.37, 1.0, 2.5, 9.99, 1e6}) {
    const Frame f = rider_frame(doc, scene, index, time);
    if (!orthonormal(f)) return where + ": rider frame at time " + std::to_string(time) + " is not orthonormal";
    if (glm::any(glm::lessThan(f.V, lo - slack)) || glm::any(glm::greaterThan(f.V, hi + slack))) {
      return where + ": rider at time " + std::to_string(time) + " is off its path";
    }
  }
  return {};
}

std::string check_scene(const Document& doc, const Scene& scene, double tolerance) {
  if (scene.objects.size() != doc.objects.size()) return "scene size differs from the document's";
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    const EvaluatedObject& e = scene.objects[i];
    const std::string where = display_name(doc, static_cast<int>(i));
    if (is_curve(o.kind())) {
      const double adaptive = tolerance > 0.0 ? tolerance : o.as<sweep::TolerancePart>().tolerance;
      if (adaptive > 0.0) {
        if (std::string problem = check_adaptive_curve(o, e.curve, adaptive, where); !problem.empty()) return problem;
      } else if (static_cast<std::int64_t>(e.curve.frames.size()) != curve_sample_count(o)) {
        return where + ": wrong sample count";
      }
      for (std::size_t k = 0; k < e.curve.frames.size(); ++k) {
        const Frame& f = e.curve.frames[k];
        if (!finite(f.V) || !unit(f.T) || !unit(f.N) || !unit(f.B)) {
          return where + ": sample " + std::to_string(k) + " has a non-finite position or a non-unit frame";
        }
        if (std::abs(glm::dot(f.T, f.N)) > 1e-6 || std::abs(glm::dot(f.T, f.B)) > 1e-6 ||
            glm::dot(glm::cross(f.T, f.N), f.B) < 1.0 - 1e-6) {
          return where + ": sample " + std::to_string(k) + " has a frame that is not right-handed orthonormal";
        }
      }
      continue;
    }
    if (is_material(o.kind())) continue;
    if (is_rider(o.kind())) {
      if (std::string problem = check_rider(doc, scene, static_cast<int>(i), where); !problem.empty()) return problem;
      continue;
    }
    const Mesh& mesh = e.mesh;
    // With a scene-wide tolerance a surface samples its curves for itself (scene.hpp).
    const SurfaceCounts expected = tolerance > 0.0 ? SurfaceCounts{static_cast<std::int64_t>(mesh.vertex_count()),
                                                                   static_cast<std::int64_t>(mesh.triangle_count())}
                                                   : expected_counts(o, doc, scene, mesh);
    // A textured swept surface has its closed seams' vertices again (texture_coordinates.hpp): at
    // most one per ring and one per profile sample, and one at the corner.
    const std::int64_t seam_copies = puts_image_on(doc, o) ? seam_copy_bound(o, scene) : 0;
    const auto vertices = static_cast<std::int64_t>(mesh.vertex_count());
    if (vertices < expected.vertices || vertices > expected.vertices + seam_copies ||
        !triangles_as_expected(mesh, expected) || mesh.normals.size() != mesh.positions.size() ||
        mesh.indices.size() % 3 != 0) {
      return where + ": mesh has " + std::to_string(mesh.vertex_count()) + " vertices and " +
             std::to_string(mesh.triangle_count()) + " triangles, expected " + std::to_string(expected.vertices) +
             " and " + std::to_string(expected.triangles);
    }
    if (!io::mesh_is_finite(mesh)) return where + ": mesh has a NaN or infinite coordinate";
    for (std::uint32_t index : mesh.indices) {
      if (index >= mesh.vertex_count()) return where + ": triangle index out of range";
    }
    if (mesh.vertex_count() <= kMaxFuzzObjVertices) {
      if (std::string problem = check_obj(mesh, where); !problem.empty()) return problem;
    }
  }
  return {};
}

}  // namespace

std::string check_swp_input(std::string_view bytes) {
  Document doc;
  try {
    doc = io::parse_swp(bytes, "fuzz.swp");
  } catch (const io::ParseError& e) {
    if (e.line() < 1 || e.column() < 1) return std::string("parse error without a position: ") + e.what();
    return {};
  } catch (const std::exception& e) {
    return std::string("parse_swp threw something other than ParseError: ") + e.what();
  }

  const std::string written = io::write_swp(doc);
  try {
    const Document again = io::parse_swp(written, "written.swp");
    if (!(again == doc)) return "parse_swp(write_swp(doc)) != doc";
    if (io::write_swp(again) != written) return "write_swp is not stable across a round trip";
    io::validate_document(doc);
  } catch (const std::exception& e) {
    return std::string("the written document does not read back: ") + e.what() + "\n" + written;
  }
  // Saved unchanged, a file comes back byte for byte (the format-preserving writer).
  if (io::write_swp_preserving(io::parse_swp_keeping_source(std::string(bytes), "fuzz.swp")) != bytes) {
    return "write_swp_preserving(the file unchanged) is not the file";
  }

  if (!within_fuzz_bounds(doc)) return {};
  // Both ways of carrying 3D frames, since either can be chosen in the viewer.
  for (const FrameMethod method : {FrameMethod::Projection, FrameMethod::RotationMinimizing}) {
    EvaluationOptions options;
    options.frames.method = method;
    Scene scene;
    try {
      scene = evaluate_document(doc, options);
    } catch (const std::exception& e) {
      return std::string("evaluate_document threw: ") + e.what();
    }
    if (std::string problem = check_scene(doc, scene, 0.0); !problem.empty()) {
      return (method == FrameMethod::Projection ? "projection frames: " : "rotation-minimizing frames: ") + problem;
    }
  }
  // Adaptive sampling of everything, as `--tolerance` does, at 1 % of the scene's size.
  const double extent = document_extent(doc);
  if (!(extent > 0.0) || !std::isfinite(extent)) return {};
  EvaluationOptions options;
  options.tolerance = 1e-2 * extent;
  try {
    const Scene scene = evaluate_document(doc, options);
    if (std::string problem = check_scene(doc, scene, options.tolerance); !problem.empty()) {
      return "--tolerance " + std::to_string(options.tolerance) + ": " + problem;
    }
  } catch (const std::exception& e) {
    return std::string("evaluate_document with a tolerance threw: ") + e.what();
  }
  return {};
}

}  // namespace sweep::fuzz
