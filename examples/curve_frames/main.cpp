// curve_frames FILE.swp CURVE [N]
//
// Evaluates a curve where you ask, not only at the samples the document keeps: N parameters
// (5 by default) evenly spaced across the curve's range, each with its position V and its unit
// tangent T (evaluate_curve gives the normal N and binormal B as well).
//
//   $ curve_frames swp/wineglass.swp profile 3
//   t 0.000000  V (0.000000, -0.459544, 0.000000)  T (0.000000, -1.000000, 0.000000)
//   t 11.500000  V (-0.649308, -0.499725, 0.000000)  T (0.859559, -0.511037, 0.000000)
//   t 23.000000  V (0.000000, -2.458801, 0.000000)  T (0.000000, -1.000000, 0.000000)
#include <sweep/sweep.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: curve_frames FILE.swp CURVE [N]\n");
    return 2;
  }
  const std::string curve = argv[2];
  const int count = argc == 4 ? std::atoi(argv[3]) : 5;
  if (count < 2) {
    std::fprintf(stderr, "curve_frames: N must be 2 or more\n");
    return 2;
  }
  try {
    const sweep::Document doc = sweep::Document::load(argv[1]);

    // The parameter runs over curve_range: 0..pieces for control-point curves, 0..1 for a
    // circle. evaluate_curve wants ascending parameters inside it (std::lerp ends exactly on
    // `high`, where low + (high - low) * 1.0 might round past it).
    const auto [low, high] = doc.curve_range(curve);
    std::vector<double> parameters;
    for (int i = 0; i < count; ++i) parameters.push_back(std::lerp(low, high, double(i) / double(count - 1)));

    // One frame per parameter, carried from each to the next as the document's evaluation does.
    const sweep::CurveFrames frames = doc.evaluate_curve(curve, parameters);
    for (std::size_t i = 0; i < parameters.size(); ++i) {
      const sweep::Frame& f = frames.frames[i];
      std::printf("t %f  V (%f, %f, %f)  T (%f, %f, %f)\n", parameters[i], f.V[0], f.V[1], f.V[2], f.T[0], f.T[1],
                  f.T[2]);
    }
  } catch (const sweep::Error& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
