// sweep_adaptive_report: the measurements of docs/adaptive-sampling.md as Markdown tables.
//   (a) the bound: largest measured deviation / D over every curve and surface of every starter
//       file, D = 1e-2 ... 1e-5 of the scene's size;
//   (b) per curve, D = 1e-3 of the scene's size: adaptive samples against a greedy sampler with
//       the same constraints and against the best uniform STEPS;
//   (c) wineglass, weird, flircle: adaptive triangles against the best uniform mesh of the same
//       measured deviation;
//   (d) time: adaptive evaluation of weird.swp at 1e-4 of its size (and 1e-3, 1e-5) against
//       uniform evaluation of about as many triangles, with fresh and with warm heap pages.
// Usage: sweep_adaptive_report [--tables abcd] [--swp DIR]. Build it in Release: the references
// are slow (about a minute for everything on the 2-core development machine).
#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/evaluation/scene.hpp"
#include "sampling/representative_curves.hpp"
#include "sampling/sampling_reference.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace {

using sweep::Document;
using sweep::EvaluationOptions;
using sweep::Object;
using sweep::Scene;

/// Surfaces are measured with density 4 (5 x 5 exact points per quad), curves with 64 per chord.
constexpr int kSurfaceDensity = 4;

const char* const kStarterFiles[] = {"catmull-rom.swp", "circles.swp",          "core.swp",     "corners.swp",
                                     "flircle.swp",     "florus.swp",           "gentorus.swp", "helix.swp",
                                     "knots.swp",       "kochanek-bartels.swp", "norm.swp",     "tor.swp",
                                     "weird.swp",       "weirder.swp",          "wineglass.swp"};

std::string format(const char* pattern, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, pattern, value);
  return buffer;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string object_name(const Document& doc, int index) {
  return sweep::display_name(doc, index);
}

/// The largest deviation / D of the curves and of the surfaces of `doc` sampled for D.
struct BoundRatios {
  double curves = 0.0;
  double surfaces = 0.0;
  bool has_surfaces = false;
  std::string worst_surface;  // the surface of the largest ratio
};

BoundRatios bound_ratios(const Document& doc, double tolerance) {
  EvaluationOptions options;
  options.tolerance = tolerance;
  const Scene scene = sweep::evaluate_document(doc, options);
  BoundRatios r;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (sweep::is_curve(o.kind())) {
      r.curves = std::max(r.curves, sweep::curve_deviation(o, scene.objects[i].curve, 64) / tolerance);
    } else {
      r.has_surfaces = true;
      const double d = sweep::surface_deviation(doc, scene, static_cast<int>(i), options, kSurfaceDensity);
      if (d / tolerance > r.surfaces) r.worst_surface = object_name(doc, static_cast<int>(i));
      r.surfaces = std::max(r.surfaces, d / tolerance);
    }
  }
  return r;
}

void table_bound(const std::filesystem::path& dir) {
  std::printf("### (a) The bound: largest measured deviation / D\n\n");
  std::printf(
      "D relative to the scene's size (document_extent). Each cell: curves / surfaces (the largest\n"
      "ratio over the file's objects; <= 1 keeps the promise). Curves against 64 exact points per chord,\n"
      "surfaces against %d x %d per quad. `-`: the file has no surface. Over 1 in bold, with the\n"
      "surface's name. Nothing is skipped.\n\n",
      kSurfaceDensity + 1, kSurfaceDensity + 1);
  const double relative[] = {1e-2, 1e-3, 1e-4, 1e-5};
  std::printf(
      "| file | size | D = 1e-2 | 1e-3 | 1e-4 | 1e-5 | seconds |\n| --- | --- | --- | --- | --- | --- | --- |\n");
  double worst_curves = 0.0, worst_surfaces = 0.0;
  for (const char* file : kStarterFiles) {
    const Document doc = sweep::io::load_swp_file(dir / file);
    const double size = sweep::document_extent(doc);
    const auto start = std::chrono::steady_clock::now();
    std::printf("| %s | %s |", file, format("%.4g", size).c_str());
    for (const double rel : relative) {
      const BoundRatios r = bound_ratios(doc, rel * size);
      worst_curves = std::max(worst_curves, r.curves);
      worst_surfaces = std::max(worst_surfaces, r.surfaces);
      std::string surfaces = r.has_surfaces ? format("%.3f", r.surfaces) : "-";
      if (r.surfaces > 1.0) surfaces = "**" + surfaces + "** (" + r.worst_surface + ")";
      std::printf(" %s / %s |", format("%.3f", r.curves).c_str(), surfaces.c_str());
    }
    std::printf(" %.1f |\n", seconds_since(start));
    std::fflush(stdout);
  }
  // The representative curves (every kind, kb3 included), each at its own size.
  std::printf("| representative curves (each at its own size) | - |");
  for (const double rel : relative) {
    double worst = 0.0;
    for (const auto& c : sweep::sampling::representative_curves()) {
      const double tolerance = rel * sweep::curve_extent(c.curve);
      const sweep::CurveSamples s = sweep::evaluate_curve(c.curve, {}, {tolerance, 0.0});
      worst = std::max(worst, sweep::curve_deviation(c.curve, s, 64) / tolerance);
    }
    worst_curves = std::max(worst_curves, worst);
    std::printf(" %s / - |", format("%.3f", worst).c_str());
  }
  std::printf(" |\n\nLargest ratio: curves %.6f, surfaces %.3f.\n\n", worst_curves, worst_surfaces);
}

struct CurveRow {
  std::string file;
  std::string name;
  std::string kind;
  bool varying = false;
  double tolerance = 0.0;
  std::size_t adaptive = 0;
  double adaptive_deviation = 0.0;
  std::size_t greedy = 0;
  sweep::sampling::UniformCurve uniform;
  sweep::sampling::UniformCurve uniform_turn;  // with the turn limit
  int wang_steps = 0;                          // 0: not a control-point curve
  std::size_t wang_pieces = 0;
};

CurveRow measure_curve(const std::string& file, const std::string& name, const Object& curve, double tolerance,
                       bool turn_limited_uniform) {
  CurveRow row;
  row.file = file;
  row.name = name;
  row.kind = std::string(sweep::keyword(curve.kind()));
  row.tolerance = tolerance;
  const sweep::CurveSamples s = sweep::evaluate_curve(curve, {}, {tolerance, 0.0});
  row.adaptive = s.frames.size();
  row.adaptive_deviation = sweep::curve_deviation(curve, s, 64);
  row.greedy = sweep::sampling::greedy_sample_count(curve, tolerance);
  row.uniform = sweep::sampling::best_uniform_steps(curve, tolerance);
  row.wang_steps = sweep::sampling::wang_uniform_steps(curve, tolerance);
  const auto* points = curve.find<sweep::PointsPart>();  // none for a circle, helix or knot
  row.wang_pieces = static_cast<std::size_t>(std::max<std::int64_t>(
      sweep::piece_count(curve.kind(), points ? static_cast<std::int64_t>(points->points.size()) : 0), 0));
  if (turn_limited_uniform) row.uniform_turn = sweep::sampling::best_uniform_steps(curve, tolerance, true);
  return row;
}

/// Every curve of the starter files (D = rel x the scene's size) and the representative curves
/// (rel x their own size).
std::vector<CurveRow> measure_curves(const std::filesystem::path& dir, double rel, bool turn_limited_uniform) {
  std::vector<CurveRow> rows;
  for (const char* file : kStarterFiles) {
    const Document doc = sweep::io::load_swp_file(dir / file);
    const double tolerance = rel * sweep::document_extent(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (!sweep::is_curve(doc.objects[i].kind())) continue;
      rows.push_back(
          measure_curve(file, object_name(doc, static_cast<int>(i)), doc.objects[i], tolerance, turn_limited_uniform));
    }
  }
  for (const auto& c : sweep::sampling::representative_curves()) {
    rows.push_back(measure_curve("representative", c.curve.name, c.curve, rel * sweep::curve_extent(c.curve),
                                 turn_limited_uniform));
    rows.back().varying = c.varying;
  }
  return rows;
}

double ratio_of(std::size_t a, std::size_t b) {
  return static_cast<double>(a) / static_cast<double>(b);
}

std::string ratio_cell(std::size_t a, std::size_t b, double limit) {
  const double r = static_cast<double>(a) / static_cast<double>(b);
  const std::string text = format("%.3f", r);
  return r > limit ? "**" + text + "**" : text;
}

void print_curve_rows(const std::vector<CurveRow>& rows) {
  std::printf(
      "| file | curve | kind | adaptive | dev / D | greedy | uniform (STEPS) | uniform + turn limit (STEPS) | "
      "Wang (STEPS) | adaptive / greedy | adaptive / uniform | adaptive / uniform + turn limit |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const CurveRow& r : rows) {
    std::string wang = "-";
    if (r.wang_steps > 0) {
      wang = std::to_string(r.wang_pieces * static_cast<std::size_t>(r.wang_steps) + 1) + " (" +
             std::to_string(r.wang_steps) + ")";
    }
    std::printf("| %s | %s%s | %s | %zu | %.3f | %zu | %zu (%d)%s | %zu (%d)%s | %s | %s | %s | %s |\n", r.file.c_str(),
                r.name.c_str(), r.varying ? " (varying)" : "", r.kind.c_str(), r.adaptive,
                r.adaptive_deviation / r.tolerance, r.greedy, r.uniform.samples, r.uniform.steps,
                r.uniform.found ? "" : " not found", r.uniform_turn.samples, r.uniform_turn.steps,
                r.uniform_turn.found ? "" : " not found", wang.c_str(), ratio_cell(r.adaptive, r.greedy, 1.2).c_str(),
                ratio_cell(r.adaptive, r.uniform.samples, r.varying ? 0.6 : 1.2).c_str(),
                ratio_cell(r.adaptive, r.uniform_turn.samples, r.varying ? 0.6 : 1.2).c_str());
  }
}

void table_curves(const std::filesystem::path& dir) {
  std::printf("### (b) Samples per curve at D = 1e-3 of the size\n\n");
  std::printf(
      "Starter files: D = 1e-3 of the scene's size (what `--tolerance` would use); representative\n"
      "curves (tests/sampling/representative_curves.hpp): 1e-3 of the curve's own size. adaptive:\n"
      "samples of evaluate_curve with the tolerance; greedy: greedy_sample_count (same constraints:\n"
      "joints kept, tangents within kMaxTurn / 2 of each chord); uniform: the smallest STEPS whose\n"
      "measured deviation is <= D (best_uniform_steps) and its samples; uniform + turn limit: the same\n"
      "with every tangent within kMaxTurn / 2 of its chord too; Wang: the STEPS Wang's formula gives\n"
      "(wang_uniform_steps; control-point curves). Ratios over the targets (1.2; 0.6\n"
      "against uniform on the curves marked varying) in bold.\n\n");
  const auto start = std::chrono::steady_clock::now();
  const std::vector<CurveRow> rows = measure_curves(dir, 1e-3, true);
  print_curve_rows(rows);
  std::printf("\n(%.1f s)\n\n", seconds_since(start));

  std::printf("### (b2) Samples per curve: summary at every D\n\n");
  std::printf(
      "The same curves (without the turn-limited uniform reference, slow on wineglass's profile),\n"
      "D relative to the size as in (b). Largest ratios, and the curves over the targets.\n\n");
  std::printf(
      "| D / size | adaptive / greedy (knots) | adaptive / greedy (other curves) | adaptive / uniform | "
      "adaptive / uniform, varying curves | over 1.2 x uniform | seconds |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n");
  for (const double rel : {1e-2, 1e-3, 1e-4, 1e-5}) {
    const auto begin = std::chrono::steady_clock::now();
    const std::vector<CurveRow> all = measure_curves(dir, rel, false);
    double knots = 0.0, others = 0.0, uniform = 0.0, varying = 0.0;
    std::string over;
    for (const CurveRow& r : all) {
      const double g = ratio_of(r.adaptive, r.greedy), u = ratio_of(r.adaptive, r.uniform.samples);
      (r.kind == "knot" ? knots : others) = std::max(r.kind == "knot" ? knots : others, g);
      uniform = std::max(uniform, u);
      if (r.varying) varying = std::max(varying, u);
      if (u > 1.2) over += (over.empty() ? "" : ", ") + r.file + " " + r.name + " " + format("%.2f", u);
    }
    std::printf("| %s | %.3f | %.3f | %.3f | %.3f | %s | %.1f |\n", format("%.0e", rel).c_str(), knots, others, uniform,
                varying, over.empty() ? "none" : over.c_str(), seconds_since(begin));
    std::fflush(stdout);
  }
  std::printf("\n");
}

void table_surfaces(const std::filesystem::path& dir) {
  std::printf("### (c) Surfaces: adaptive against the best uniform mesh of the same deviation\n\n");
  std::printf(
      "adaptive: evaluate_document with the tolerance D (relative to the scene's size) and its\n"
      "measured deviation (surface_deviation, %d x %d exact points per quad); uniform: the pair\n"
      "(profile STEPS, sweep STEPS or srev copies) with the fewest triangles whose measured deviation\n"
      "is at most the adaptive one (best_uniform_surface). srev: the sweep is the turn (copies).\n"
      "Ratios over the target (0.5) in bold.\n\n",
      kSurfaceDensity + 1, kSurfaceDensity + 1);
  std::printf(
      "| file | surface | D / size | adaptive samples (profile x sweep) | adaptive triangles | adaptive deviation | "
      "uniform STEPS (profile, sweep) | uniform samples | uniform triangles | uniform deviation | adaptive / "
      "uniform | meshes searched | seconds |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n");
  for (const char* file : {"wineglass.swp", "weird.swp", "flircle.swp"}) {
    const Document doc = sweep::io::load_swp_file(dir / file);
    const double size = sweep::document_extent(doc);
    for (const double rel : {1e-2, 1e-3, 1e-4}) {
      EvaluationOptions options;
      options.tolerance = rel * size;
      const Scene scene = sweep::evaluate_document(doc, options);
      for (std::size_t i = 0; i < doc.objects.size(); ++i) {
        if (!sweep::is_surface(doc.objects[i].kind())) continue;
        const auto start = std::chrono::steady_clock::now();
        const int index = static_cast<int>(i);
        const double deviation = sweep::surface_deviation(doc, scene, index, options, kSurfaceDensity);
        const std::size_t triangles = scene.objects[i].mesh.triangle_count();
        const sweep::SurfaceSampling sampling = sweep::surface_sampling(doc, scene, index, options);
        const std::size_t sweep_samples = doc.objects[i].kind() == sweep::ObjectKind::SurfaceOfRevolution
                                              ? static_cast<std::size_t>(sampling.copies)
                                              : sampling.sweep.frames.size();
        const auto uniform = sweep::sampling::best_uniform_surface(doc, index, deviation, kSurfaceDensity);
        const Document uniform_doc = sweep::sampling::uniform_surface_document(
            doc, index, std::max(uniform.profile_steps, 1), std::max(uniform.sweep_steps, 1));
        const std::size_t uniform_sweep_samples =
            uniform_doc.objects.size() == 3
                ? static_cast<std::size_t>(sweep::curve_sample_count(uniform_doc.objects[1]))
                : static_cast<std::size_t>(uniform.sweep_steps);
        const double ratio = static_cast<double>(triangles) / static_cast<double>(uniform.triangles);
        std::printf(
            "| %s | %s | %s | %zu x %zu | %zu | %s | %d, %d%s | %zu x %zu | %zu | %s | %s%.3f%s | %d | %.1f |\n", file,
            object_name(doc, index).c_str(), format("%.0e", rel).c_str(), sampling.profile.frames.size(), sweep_samples,
            triangles, format("%.3g", deviation).c_str(), uniform.profile_steps, uniform.sweep_steps,
            uniform.found ? "" : " (not found)",
            static_cast<std::size_t>(sweep::curve_sample_count(uniform_doc.objects[0])), uniform_sweep_samples,
            uniform.triangles, format("%.3g", uniform.deviation).c_str(), ratio > 0.5 ? "**" : "", ratio,
            ratio > 0.5 ? "**" : "", uniform.measured, seconds_since(start));
        std::fflush(stdout);
      }
    }
  }
  std::printf("\n");
}

/// Milliseconds f takes once.
template <typename F>
double time_ms(F f) {
  const auto start = std::chrono::steady_clock::now();
  f();
  return 1e3 * seconds_since(start);
}

/// How the C library's allocator hands out the meshes' large arrays: the times depend on it,
/// because touching fresh pages costs as much as building the mesh.
enum class Heap {
  Fresh,  // blocks over 128 KiB mapped anew and returned at each free (glibc's start-up state)
  Warm,   // every block from the heap, never returned (what a long-running viewer tends to reach)
};

/// Sets the allocator to `heap` (glibc; elsewhere the times are those of the default allocator).
bool use_heap(Heap heap) {
#if defined(__GLIBC__)
  const int threshold = heap == Heap::Fresh ? 128 * 1024 : 1 << 30;
  return mallopt(M_MMAP_THRESHOLD, threshold) == 1 && mallopt(M_TRIM_THRESHOLD, threshold) == 1;
#else
  return heap == Heap::Fresh;
#endif
}

void table_timing(const std::filesystem::path& dir) {
  std::printf("### (d) Time: adaptive against uniform evaluation of the same size\n\n");
  const Document doc = sweep::io::load_swp_file(dir / "weird.swp");
  const double size = sweep::document_extent(doc);
  constexpr int kRuns = 31;
  std::printf(
      "weird.swp; evaluate_document (every object) with the tolerance D, and without it on a copy\n"
      "whose STEPS give about the same sample counts (same_size_uniform_document); median of %d runs\n"
      "each, the two alternated. The target is D = 1e-4; the other rows show how the ratio moves with\n"
      "the output's size. heap: fresh = the mesh arrays (over 128 KiB) are mapped anew for each\n"
      "evaluation and their pages first touched (glibc's default state, one `sweep export`); warm = they\n"
      "come from memory the process already touched (mallopt thresholds at 1 GiB, as a long-running\n"
      "viewer tends to reach).\n\n",
      kRuns);
  std::printf(
      "| heap | D / size | uniform STEPS (profile, sweep) | adaptive triangles | uniform triangles | "
      "adaptive ms | uniform ms | adaptive / uniform |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- |\n");
  const auto triangles = [](const Scene& s) {
    std::size_t n = 0;
    for (const auto& o : s.objects) n += o.mesh.triangle_count();
    return n;
  };
  for (const Heap heap : {Heap::Fresh, Heap::Warm}) {
    if (!use_heap(heap)) continue;
    for (const double rel : {1e-3, 1e-4, 1e-5}) {
      EvaluationOptions adaptive;
      adaptive.tolerance = rel * size;
      const Document uniform = sweep::sampling::same_size_uniform_document(doc, adaptive);
      const std::size_t adaptive_triangles = triangles(sweep::evaluate_document(doc, adaptive));
      const std::size_t uniform_triangles = triangles(sweep::evaluate_document(uniform));
      std::vector<double> adaptive_ms, uniform_ms;
      for (int i = 0; i < kRuns; ++i) {
        adaptive_ms.push_back(time_ms([&] { sweep::evaluate_document(doc, adaptive); }));
        uniform_ms.push_back(time_ms([&] { sweep::evaluate_document(uniform); }));
      }
      std::sort(adaptive_ms.begin(), adaptive_ms.end());
      std::sort(uniform_ms.begin(), uniform_ms.end());
      const double a = adaptive_ms[kRuns / 2], u = uniform_ms[kRuns / 2];
      const Object& gcyl = doc.objects[static_cast<std::size_t>(doc.find("weird"))];
      std::printf(
          "| %s | %s | %d, %d | %zu | %zu | %.2f | %.2f | %s%.2f%s |\n", heap == Heap::Fresh ? "fresh" : "warm",
          format("%.0e", rel).c_str(),
          uniform.objects[static_cast<std::size_t>(gcyl.as<sweep::ProfilePart>().profile)].as<sweep::StepsPart>().steps,
          uniform.objects[static_cast<std::size_t>(gcyl.as<sweep::CylinderSurface>().sweep)]
              .as<sweep::StepsPart>()
              .steps,
          adaptive_triangles, uniform_triangles, a, u, a / u > 2.0 ? "**" : "", a / u, a / u > 2.0 ? "**" : "");
      std::fflush(stdout);
    }
  }
  use_heap(Heap::Fresh);
  // Where the adaptive time goes: sampling the curves (once for the scene at D, once for the
  // surface at kSurfaceShare D) against building the mesh.
  std::printf(
      "\nCurve sampling alone at D = 1e-4 (the part that does not depend on the heap), median of %d runs;\n"
      "uniform: the same curve by the STEPS that give about as many samples.\n\n"
      "| curve | sampled for | samples | adaptive ms | microseconds per sample | uniform STEPS | uniform ms |\n"
      "| --- | --- | --- | --- | --- | --- | --- |\n",
      kRuns);
  const double tolerance = 1e-4 * size;
  const Object& gcyl = doc.objects[static_cast<std::size_t>(doc.find("weird"))];
  const Object& profile = doc.objects[static_cast<std::size_t>(gcyl.as<sweep::ProfilePart>().profile)];
  const Object& sweep_curve = doc.objects[static_cast<std::size_t>(gcyl.as<sweep::CylinderSurface>().sweep)];
  const double share = sweep::kSurfaceShare * tolerance;
  const double radius = sweep::profile_radius(sweep::evaluate_curve(profile, {}, {share, 0.0}));
  const struct {
    const Object* curve;
    const char* what;
    sweep::AdaptiveTolerance tolerance;
  } parts[] = {{&profile, "the scene (D)", {tolerance, 0.0}},
               {&sweep_curve, "the scene (D)", {tolerance, 0.0}},
               {&profile, "the surface (0.46 D)", {share, 0.0}},
               {&sweep_curve, "the surface (0.46 D, offset r)", {share, radius + share}}};
  const auto median_of = [&](auto f) {
    std::vector<double> times;
    for (int i = 0; i < kRuns; ++i) times.push_back(time_ms(f));
    std::sort(times.begin(), times.end());
    return times[kRuns / 2];
  };
  for (const auto& part : parts) {
    std::size_t samples = 0;
    const double a = median_of([&] { samples = sweep::evaluate_curve(*part.curve, {}, part.tolerance).frames.size(); });
    Object uniform = *part.curve;
    const auto pieces =
        sweep::piece_count(uniform.kind(), static_cast<std::int64_t>(uniform.as<sweep::PointsPart>().points.size()));
    uniform.as<sweep::StepsPart>().steps =
        std::max(1, static_cast<int>(std::lround(static_cast<double>(samples - 1) /
                                                 static_cast<double>(std::max<std::int64_t>(pieces, 1)))));
    uniform.as<sweep::TolerancePart>().tolerance = 0.0;
    const double u = median_of([&] { sweep::evaluate_curve(uniform); });
    std::printf("| %s | %s | %zu | %.3f | %.2f | %d | %.3f |\n", part.curve->name.c_str(), part.what, samples, a,
                1e3 * a / static_cast<double>(samples), uniform.as<sweep::StepsPart>().steps, u);
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::string tables = "abcd";
  std::filesystem::path dir = SWEEP_SWP_DIR;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--tables") == 0 && i + 1 < argc) {
      tables = argv[++i];
    } else if (std::strcmp(argv[i], "--swp") == 0 && i + 1 < argc) {
      dir = argv[++i];
    } else {
      std::fprintf(stderr, "usage: sweep_adaptive_report [--tables abcd] [--swp DIR]\n");
      return 2;
    }
  }
  if (tables.find('a') != std::string::npos) table_bound(dir);
  if (tables.find('b') != std::string::npos) table_curves(dir);
  if (tables.find('c') != std::string::npos) table_surfaces(dir);
  if (tables.find('d') != std::string::npos) table_timing(dir);
  return 0;
}
