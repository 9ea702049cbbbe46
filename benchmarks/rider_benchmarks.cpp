// Speed of riders: what an edit of a path costs them (the track: arc lengths by quadrature at every
// sample), and what a frame of playback costs (every rider's frame at a time).
#include "io/swp/read.hpp"
#include "model/evaluation/riders.hpp"
#include "model/evaluation/scene.hpp"

#include <benchmark/benchmark.h>

#include <string>

namespace {

/// A torus knot of `samples` samples with `riders` riders on it (a train), as SWP text.
std::string train_text(int samples, int riders) {
  std::string text = "knot track " + std::to_string(samples - 1) + " 2 3 2 0.6\n";
  text += "circ body 12 0.1\npoly3 spine 2\n[0 0 -0.2]\n[0 0 0.2]\ngcyl car body spine caps\n";
  for (int k = 0; k < riders; ++k) {
    text += "rider r" + std::to_string(k) + " track car start " + std::to_string(double(k) / riders) + " up 0 0 1\n";
  }
  return text;
}

/// Evaluating a path of 100 000 samples with one rider: the rider's share is its track.
void BM_RiderTrackOfLongPath(benchmark::State& state) {
  const sweep::Document doc = sweep::io::parse_swp(train_text(100'000, 1), "train.swp");
  sweep::Scene scene = sweep::evaluate_document(doc);
  const int track = doc.find("track");
  for (auto _ : state) {
    benchmark::DoNotOptimize(sweep::reevaluate(scene, doc, track).size());
  }
  state.SetItemsProcessed(state.iterations() * 100'000);
}
BENCHMARK(BM_RiderTrackOfLongPath)->Unit(benchmark::kMillisecond);

/// One frame of playback: the frames of 1 000 riders at a time on a path of 10 000 samples.
void BM_RiderFramesOfATrain(benchmark::State& state) {
  const sweep::Document doc = sweep::io::parse_swp(train_text(10'000, 1'000), "train.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const std::vector<int> riders = sweep::riders_of(doc);
  double time = 0.0;
  for (auto _ : state) {
    time += 1.0 / 60.0;
    for (const int r : riders) benchmark::DoNotOptimize(sweep::rider_frame(doc, scene, r, time).V.x);
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(riders.size()));
}
BENCHMARK(BM_RiderFramesOfATrain)->Unit(benchmark::kMicrosecond);

}  // namespace
