// Speed of the paths the resource caps are sized for: loading a million control points, and
// evaluating plus exporting a starter file at ten times its STEPS.
#include "geometry/subdivision/subdivision.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/surface_export.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "weird_document.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace {

/// A bsp2 with `count` control points on a spiral and STEPS 1, as SWP text.
std::string spiral_bspline_text(int count) {
  sweep::Document doc;
  sweep::Object curve;
  curve.set_kind(sweep::ObjectKind::BSpline2);
  curve.name = "spiral";
  curve.as<sweep::StepsPart>().steps = 1;
  curve.as<sweep::PointsPart>().points.reserve(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    const double t = 0.01 * i;
    curve.as<sweep::PointsPart>().points.emplace_back(t * std::cos(t), t * std::sin(t), 0.0);
  }
  doc.objects.push_back(std::move(curve));
  return sweep::io::write_swp(doc);
}

void BM_ParseMillionControlPoints(benchmark::State& state) {
  const std::string text = spiral_bspline_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    sweep::Document doc = sweep::io::parse_swp(text, "spiral.swp");
    benchmark::DoNotOptimize(doc.objects.data());
  }
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(text.size()));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_ParseMillionControlPoints)->Arg(250'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

void BM_LoadAndEvaluateMillionControlPoints(benchmark::State& state) {
  const std::string text = spiral_bspline_text(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    const sweep::Document doc = sweep::io::parse_swp(text, "spiral.swp");
    sweep::Scene scene = sweep::evaluate_document(doc);
    benchmark::DoNotOptimize(scene.objects.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LoadAndEvaluateMillionControlPoints)->Arg(250'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);

/// A one-point edit of a million-point file saved as the editor saves it (write_swp_preserving:
/// both texts of the edited curve tokenized and compared), against write_swp of the same document.
void BM_SaveMillionControlPointsEdited(benchmark::State& state) {
  sweep::Document doc = sweep::io::parse_swp_keeping_source(spiral_bspline_text(1'000'000), "spiral.swp");
  doc.objects[0].as<sweep::PointsPart>().points[500'000].x += 0.125;
  const bool preserving = state.range(0) == 1;
  for (auto _ : state) {
    const std::string text = preserving ? sweep::io::write_swp_preserving(doc) : sweep::io::write_swp(doc);
    benchmark::DoNotOptimize(text.data());
  }
}
BENCHMARK(BM_SaveMillionControlPointsEdited)->ArgName("preserving")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

using sweep::bench::scaled_weird;

void BM_ExportWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Document doc = scaled_weird(10);
  std::FILE* sink = std::fopen("/dev/null", "wb");
  if (!sink) throw std::runtime_error("cannot open /dev/null");
  std::size_t vertices = 0;
  // What `sweep export` evaluates: every surface with its texture coordinates (vt lines).
  const sweep::EvaluationOptions options = sweep::io::export_evaluation({}, sweep::io::ExportFormat::Obj);
  for (auto _ : state) {
    const sweep::Scene scene = sweep::evaluate_document(doc, options);
    for (const auto& object : scene.objects) {
      if (object.mesh.vertex_count() == 0) continue;
      vertices += object.mesh.vertex_count();
      if (!sweep::io::write_obj(sink, object.mesh, "weird x10")) state.SkipWithError("write failed");
    }
  }
  std::fclose(sink);
  state.counters["vertices"] =
      benchmark::Counter(static_cast<double>(vertices) / static_cast<double>(state.iterations()));
}
BENCHMARK(BM_ExportWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_EvaluateWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Document doc = scaled_weird(10);
  for (auto _ : state) {
    sweep::Scene scene = sweep::evaluate_document(doc);
    benchmark::DoNotOptimize(scene.objects.data());
  }
}
BENCHMARK(BM_EvaluateWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

/// What the viewer does on every frame of a drag of weird.swp's profile: the profile and the
/// surface re-evaluated into the same scene, whose mesh buffers are reused (no fresh pages).
void BM_ReevaluateWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Document doc = scaled_weird(10);
  sweep::Scene scene = sweep::evaluate_document(doc);
  for (auto _ : state) {
    benchmark::DoNotOptimize(sweep::reevaluate(scene, doc, 0).size());
    benchmark::DoNotOptimize(scene.objects.data());
  }
}
BENCHMARK(BM_ReevaluateWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

/// A curve whose control points all coincide: every tangent is zero and has to be repaired from
/// the neighbours. The argument is the number of samples; time per sample should not grow with it.
void BM_EvaluateCoincidentControlPoints(benchmark::State& state) {
  const std::string text = "bsp2 . " + std::to_string(state.range(0) - 1) + " 4 [0 0] [0 0] [0 0] [0 0]\n";
  const sweep::Document doc = sweep::io::parse_swp(text, "coincident.swp");
  for (auto _ : state) {
    sweep::Scene scene = sweep::evaluate_document(doc);
    benchmark::DoNotOptimize(scene.objects.data());
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_EvaluateCoincidentControlPoints)->Arg(2'000)->Arg(4'000)->Arg(8'000)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

// Adaptive sampling against uniform sampling of the same output size (issue 14: adaptive
// evaluation of weird.swp at D = 1e-4 of its size takes at most twice as long). The uniform copy's
// STEPS give about the adaptive sample counts (tests/sampling/sampling_reference.hpp). The ratio
// depends on the allocator's state (fresh pages for each mesh cost as much as building it):
// benchmarks/adaptive_report.cpp prints the comparison at three tolerances for both states.
#include "geometry/curves/adaptive.hpp"
#include "sampling/sampling_reference.hpp"

namespace {

sweep::EvaluationOptions weird_adaptive_options(const sweep::Document& doc) {
  sweep::EvaluationOptions options;
  options.tolerance = 1e-4 * sweep::document_extent(doc);
  return options;
}

std::size_t triangle_count(const sweep::Scene& scene) {
  std::size_t n = 0;
  for (const auto& object : scene.objects) n += object.mesh.triangle_count();
  return n;
}

void BM_EvaluateWeirdAdaptive(benchmark::State& state) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weird.swp");
  const sweep::EvaluationOptions options = weird_adaptive_options(doc);
  std::size_t triangles = 0;
  for (auto _ : state) {
    sweep::Scene scene = sweep::evaluate_document(doc, options);
    triangles = triangle_count(scene);
    benchmark::DoNotOptimize(scene.objects.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_EvaluateWeirdAdaptive)->Unit(benchmark::kMillisecond);

void BM_EvaluateWeirdUniformSameSize(benchmark::State& state) {
  const sweep::Document weird = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weird.swp");
  const sweep::Document doc = sweep::sampling::same_size_uniform_document(weird, weird_adaptive_options(weird));
  std::size_t triangles = 0;
  for (auto _ : state) {
    sweep::Scene scene = sweep::evaluate_document(doc);
    triangles = triangle_count(scene);
    benchmark::DoNotOptimize(scene.objects.data());
  }
  state.counters["triangles"] = static_cast<double>(triangles);
}
BENCHMARK(BM_EvaluateWeirdUniformSameSize)->Unit(benchmark::kMillisecond);

}  // namespace

// Controlled sweeps (issue 15): a scaled, twisted, capped tube against the same tube plain, so
// the cost of the stations, the tilted normals and the caps shows (README, Performance).
namespace {

std::string column_text(bool controlled) {
  std::string text = "cr2 flutes 16 17";
  for (int k = 0; k <= 16; ++k) {
    const double a = 2.0 * 3.141592653589793 * (k % 16) / 16.0;
    const double r = k % 2 == 0 ? 0.5 : 0.36;
    text += " [" + std::to_string(r * std::cos(a)) + " " + std::to_string(r * std::sin(a)) + "]";
  }
  text += "\nbsp3 shaft 200 8 [0 0 0] [0 1 0] [0.5 2 0.3] [0 3 0] [-0.5 4 -0.3] [0 5 0] [0.4 6 0.2] [0 7 0]\n";
  text += "cr2 entasis 64 4 [0 1] [0.35 1.1] [0.75 0.95] [1 0.75]\n";
  text += controlled ? "gcyl column flutes shaft scale entasis twist 360 caps\n" : "gcyl column flutes shaft\n";
  return text;
}

void BM_EvaluateColumn(benchmark::State& state) {
  const sweep::Document doc = sweep::io::parse_swp(column_text(state.range(0) != 0), "column.swp");
  std::size_t vertices = 0;
  for (auto _ : state) {
    sweep::Scene scene = sweep::evaluate_document(doc);
    vertices = scene.objects.back().mesh.vertex_count();
    benchmark::DoNotOptimize(scene.objects.data());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
}
BENCHMARK(BM_EvaluateColumn)->ArgName("controlled")->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

// Subdivision (issues 16 and 44): a closed torus cage of 100 x 100 = 10 000 quads refined to
// level 3 (640 000 faces) with limit positions and normals, the whole of subdivide() (README):
// since issue 44 each cage face's limit surface evaluated on every core (subdivision_faces.hpp).
// Time is wall-clock, CPU that of every thread. ByFaces runs that path on 1 and 2 threads;
// ByRefinement is the path subdivide took before (OpenSubdiv's topology refinement, the
// positions carried down, the limit masks and the triangles), for comparison.
#include "geometry/subdivision/subdivision_faces.hpp"
#include "geometry/subdivision/subdivision_limit.hpp"

#include <optional>

namespace {

sweep::Cage torus_cage(int around, int through) {
  sweep::Cage cage;
  for (int i = 0; i < around; ++i) {
    const double u = 2.0 * 3.141592653589793 * i / around;
    for (int j = 0; j < through; ++j) {
      const double v = 2.0 * 3.141592653589793 * j / through;
      const double r = 3.0 + std::cos(v);
      cage.points.emplace_back(r * std::cos(u), std::sin(v), -r * std::sin(u));
    }
  }
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < through; ++j) {
      const auto at = [through, around](int a, int b) { return (a % around) * through + b % through; };
      cage.face_sizes.push_back(4);
      cage.face_vertices.insert(cage.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return cage;
}

void BM_SubdivideTenThousandFaces(benchmark::State& state) {
  const sweep::Cage cage = torus_cage(100, 100);
  const int levels = static_cast<int>(state.range(0));
  std::size_t vertices = 0;
  for (auto _ : state) {
    const sweep::Subdivided s = sweep::subdivide(cage, {levels, sweep::SubdivisionScheme::CatmullClark, false});
    vertices = s.mesh.vertex_count();
    benchmark::DoNotOptimize(s.mesh.positions.data());
  }
  state.counters["vertices"] = static_cast<double>(vertices);
  state.counters["vertices/s"] = benchmark::Counter(
      static_cast<double>(vertices) * static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SubdivideTenThousandFaces)
    ->ArgName("level")
    ->Arg(3)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_SubdivideTenThousandFacesByFaces(benchmark::State& state) {
  const sweep::Cage cage = torus_cage(100, 100);
  const int threads = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const std::optional<sweep::Subdivided> s = sweep::subdivision_detail::subdivide_by_faces(
        cage, {3, sweep::SubdivisionScheme::CatmullClark, false}, threads);
    if (!s) throw std::runtime_error("the faces' path declined the torus");
    benchmark::DoNotOptimize(s->mesh.positions.data());
  }
}
BENCHMARK(BM_SubdivideTenThousandFacesByFaces)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_SubdivideTenThousandFacesByRefinement(benchmark::State& state) {
  const sweep::Cage cage = torus_cage(100, 100);
  for (auto _ : state) {
    const sweep::Subdivided s =
        sweep::subdivision_detail::subdivide_by_refinement(cage, {3, sweep::SubdivisionScheme::CatmullClark, false});
    benchmark::DoNotOptimize(s.mesh.positions.data());
  }
}
BENCHMARK(BM_SubdivideTenThousandFacesByRefinement)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

}  // namespace

// OBJ against binary glTF for weird.swp at ten times its STEPS (the scene evaluated once): the
// writing alone, into /dev/null (Write), and the whole atomic save to a file in the temp folder,
// fsync included (Save). The "file bytes" counter is the size of the file.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/mesh/gltf_vertices.hpp"
#include "io/mesh/gltf_writer.hpp"
#include "io/mesh/stl_writer.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <algorithm>
#include <filesystem>

namespace {

enum ExportKind : int { kObj = 0, kGlb = 1, kGlbQuantized = 2 };

const sweep::Mesh& weird_ten_times_mesh() {
  // With texture coordinates, as exported (OBJ and glb write them; STL ignores them).
  static const sweep::Scene scene =
      sweep::evaluate_document(scaled_weird(10), sweep::io::export_evaluation({}, sweep::io::ExportFormat::Obj));
  for (const auto& object : scene.objects) {
    if (object.mesh.vertex_count() > 0) return object.mesh;
  }
  throw std::runtime_error("weird.swp has no surface");
}

/// The error quantization adds (mesh/gltf_vertices.hpp), as counters: the largest position error
/// relative to the mesh's box diagonal, the largest angle between a normal and its quantized form
/// in degrees, and whether the texture coordinates were quantized (1) or stayed float (0).
void add_quantization_errors(benchmark::State& state, const sweep::Mesh& mesh) {
  const sweep::io::QuantizedPositions q = sweep::io::quantize_positions(mesh.positions);
  const auto normals = sweep::io::quantize_normals(mesh.normals);
  glm::dvec3 low(1e300), high(-1e300);
  double position = 0.0, angle = 0.0;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 p(mesh.positions[i]);
    low = glm::min(low, p);
    high = glm::max(high, p);
    const glm::dvec3 back = q.step * glm::dvec3(q.values[i][0], q.values[i][1], q.values[i][2]);
    position = std::max(position, glm::length(back - p));
    const glm::dvec3 n = glm::normalize(glm::dvec3(normals[i][0], normals[i][1], normals[i][2]) / 127.0);
    angle = std::max(angle, std::acos(std::clamp(glm::dot(n, glm::dvec3(mesh.normals[i])), -1.0, 1.0)));
  }
  state.counters["position error / diagonal"] = position / glm::length(high - low);
  state.counters["normal error deg"] = glm::degrees(angle);
  state.counters["uv quantized"] = sweep::io::quantize_uvs(mesh.uvs) ? 1.0 : 0.0;
}

void BM_WriteWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Mesh& mesh = weird_ten_times_mesh();
  std::FILE* sink = std::fopen("/dev/null", "wb");
  if (!sink) throw std::runtime_error("cannot open /dev/null");
  std::size_t bytes = 0;
  for (auto _ : state) {
    if (state.range(0) != kObj) {
      const sweep::io::GlbEncoding encoding =
          state.range(0) == kGlbQuantized ? sweep::io::GlbEncoding::Quantized : sweep::io::GlbEncoding::Float;
      if (!sweep::io::write_glb(sink, mesh, "weird", sweep::SurfaceMaterial{}, sweep::io::MaterialImages{},
                                {"sweep", encoding})) {
        state.SkipWithError("write failed");
      }
    } else if (!sweep::io::write_obj(sink, mesh, "weird x10")) {
      state.SkipWithError("write failed");
    }
  }
  std::fclose(sink);
  // The file's size, measured apart (as save_glb_file and write_obj, the loop writes into a FILE).
  if (state.range(0) == kObj) {
    bytes = sweep::io::obj_text(mesh, "weird x10").size();
  } else {
    const sweep::io::GlbEncoding encoding =
        state.range(0) == kGlbQuantized ? sweep::io::GlbEncoding::Quantized : sweep::io::GlbEncoding::Float;
    bytes =
        sweep::io::glb_bytes(mesh, "weird", sweep::SurfaceMaterial{}, sweep::io::MaterialImages{}, {"sweep", encoding})
            .size();
  }
  state.counters["file bytes"] = static_cast<double>(bytes);
  state.counters["vertices"] = static_cast<double>(mesh.vertex_count());
  if (state.range(0) == kGlbQuantized) add_quantization_errors(state, mesh);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
}
// glb:2 is --quantize, with the error it adds as counters.
BENCHMARK(BM_WriteWeirdTenTimesSteps)
    ->ArgName("glb")
    ->Arg(kObj)
    ->Arg(kGlb)
    ->Arg(kGlbQuantized)
    ->Unit(benchmark::kMillisecond);

/// Binary STL as `sweep export --format stl` makes it: the closed-manifold check (mesh_topology)
/// and the bytes, written into /dev/null; compare with BM_WriteWeirdTenTimesSteps/glb:0 (OBJ).
void BM_WriteStlWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Mesh& mesh = weird_ten_times_mesh();
  std::FILE* sink = std::fopen("/dev/null", "wb");
  if (!sink) throw std::runtime_error("cannot open /dev/null");
  const std::size_t bytes = 84 + 50 * mesh.triangle_count();
  for (auto _ : state) {
    const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
    benchmark::DoNotOptimize(topology.boundary_edges);
    if (!sweep::io::write_stl(sink, mesh, "weird x10")) state.SkipWithError("write failed");
  }
  std::fclose(sink);
  state.counters["file bytes"] = static_cast<double>(bytes);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_WriteStlWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_SaveWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Mesh& mesh = weird_ten_times_mesh();
  const bool glb = state.range(0) == kGlb;
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / (glb ? "sweep_bench_weird.glb" : "sweep_bench_weird.obj");
  for (auto _ : state) {
    if (glb) {
      sweep::io::save_glb_file(path, mesh, "weird", sweep::SurfaceMaterial{}, sweep::io::MaterialImages{});
    } else {
      sweep::io::save_obj_file(path, mesh, "weird x10");
    }
  }
  const auto bytes = std::filesystem::file_size(path);
  std::filesystem::remove(path);
  state.counters["file bytes"] = static_cast<double>(bytes);
  state.SetBytesProcessed(static_cast<std::int64_t>(state.iterations()) * static_cast<std::int64_t>(bytes));
}
BENCHMARK(BM_SaveWeirdTenTimesSteps)->ArgName("glb")->Arg(kObj)->Arg(kGlb)->Unit(benchmark::kMillisecond);

}  // namespace
