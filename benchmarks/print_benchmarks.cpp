// Speed of printing (issue 58) on weird.swp at ten times its STEPS (1.64 M triangles) at 80 mm:
// the weld into shells, each check, all of them, and writing the 3MF they are made for. The
// self-intersection check must cost less than the export it guards (README, Speed).
#include "geometry/mesh/intersections.hpp"
#include "geometry/mesh/shell_topology.hpp"
#include "geometry/mesh/wall_thickness.hpp"
#include "io/mesh/threemf_writer.hpp"
#include "model/evaluation/scene.hpp"
#include "model/print/printability.hpp"
#include "weird_document.hpp"

#include <benchmark/benchmark.h>

#include <filesystem>

namespace {

/// The evaluated model and its print model, made once for every benchmark here.
struct WeirdPrint {
  sweep::Document doc = sweep::bench::scaled_weird(10);
  sweep::Scene scene = sweep::evaluate_document(doc);
  sweep::PrintModel model = sweep::print_model(doc, scene, 80.0);
};

const WeirdPrint& weird_print() {
  static const WeirdPrint print;
  return print;
}

void BM_PrintModelWeirdTenTimesSteps(benchmark::State& state) {
  const WeirdPrint& w = weird_print();
  for (auto _ : state) benchmark::DoNotOptimize(sweep::print_model(w.doc, w.scene, 80.0));
}
BENCHMARK(BM_PrintModelWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_ShellTopologyWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Shell& shell = weird_print().model.parts.front().shell;
  for (auto _ : state) benchmark::DoNotOptimize(sweep::shell_topology(shell));
}
BENCHMARK(BM_ShellTopologyWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_SelfIntersectionWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Shell& shell = weird_print().model.parts.front().shell;
  for (auto _ : state) benchmark::DoNotOptimize(sweep::self_intersections(shell));
}
BENCHMARK(BM_SelfIntersectionWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_ThinWallsWeirdTenTimesSteps(benchmark::State& state) {
  const sweep::Shell& shell = weird_print().model.parts.front().shell;
  for (auto _ : state) benchmark::DoNotOptimize(sweep::thin_walls(shell, 0.8));
}
BENCHMARK(BM_ThinWallsWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_CheckPrintWeirdTenTimesSteps(benchmark::State& state) {
  const WeirdPrint& w = weird_print();
  for (auto _ : state) benchmark::DoNotOptimize(sweep::check_print(w.doc, w.model, "weird.swp"));
}
BENCHMARK(BM_CheckPrintWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

void BM_Write3mfWeirdTenTimesSteps(benchmark::State& state) {
  const WeirdPrint& w = weird_print();
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "sweep-bench-weird.3mf";
  for (auto _ : state) sweep::io::save_3mf_file(path, w.model, "weird");
  std::filesystem::remove(path);
}
BENCHMARK(BM_Write3mfWeirdTenTimesSteps)->Unit(benchmark::kMillisecond);

}  // namespace
