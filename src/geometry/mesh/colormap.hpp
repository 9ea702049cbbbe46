#pragma once
// Colours for signed scalars on a surface (curvature): Moreland's cool-warm diverging map, and
// a robust symmetric range to scale the values into it.
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sweep {

/// Kenneth Moreland, "Diverging Color Maps for Scientific Visualization", Advances in Visual
/// Computing (ISVC 2009), LNCS 5876, pp. 92-103: the cool-warm map, interpolated in his Msh
/// space from blue to red through grey, as the 33 RGB entries he publishes (CoolWarmFloat33,
/// https://www.kennethmoreland.com/color-maps/), entry i at scalar i / 32 of [0, 1].
inline constexpr std::array<glm::vec3, 33> kCoolWarmTable{{
    {0.2298057f, 0.298717966f, 0.753683153f},   {0.26623388f, 0.353094838f, 0.801466763f},
    {0.30386891f, 0.406535296f, 0.84495867f},   {0.342804478f, 0.458757618f, 0.883725899f},
    {0.38301334f, 0.50941904f, 0.917387822f},   {0.424369608f, 0.558148092f, 0.945619588f},
    {0.46666708f, 0.604562568f, 0.968154911f},  {0.509635204f, 0.648280772f, 0.98478814f},
    {0.552953156f, 0.688929332f, 0.995375608f}, {0.596262162f, 0.726149107f, 0.999836203f},
    {0.639176211f, 0.759599947f, 0.998151185f}, {0.681291281f, 0.788964712f, 0.990363227f},
    {0.722193294f, 0.813952739f, 0.976574709f}, {0.761464949f, 0.834302879f, 0.956945269f},
    {0.798691636f, 0.849786142f, 0.931688648f}, {0.833466556f, 0.860207984f, 0.901068838f},
    {0.865395197f, 0.86541021f, 0.865395561f},  {0.897787179f, 0.848937047f, 0.820880546f},
    {0.924127593f, 0.827384882f, 0.774508472f}, {0.944468518f, 0.800927443f, 0.726736146f},
    {0.958852946f, 0.769767752f, 0.678007945f}, {0.96732803f, 0.734132809f, 0.628751763f},
    {0.969954137f, 0.694266682f, 0.579375448f}, {0.966811177f, 0.650421156f, 0.530263762f},
    {0.958003065f, 0.602842431f, 0.481775914f}, {0.943660866f, 0.551750968f, 0.434243684f},
    {0.923944917f, 0.49730856f, 0.387970225f},  {0.89904617f, 0.439559467f, 0.343229596f},
    {0.869186849f, 0.378313092f, 0.300267182f}, {0.834620542f, 0.312874446f, 0.259301199f},
    {0.795631745f, 0.24128379f, 0.220525627f},  {0.752534934f, 0.157246067f, 0.184115123f},
    {0.705673158f, 0.01555616f, 0.150232812f},
}};

/// Moreland's cool-warm colour of t in [-1, 1] (clamped; NaN is the middle): -1 blue
/// (0.230, 0.299, 0.754), 0 light grey (0.865, 0.865, 0.865), +1 red (0.706, 0.016, 0.150),
/// linear in RGB between the table's entries (which are 1/16 of the range apart), so -1, 0 and 1
/// give their entries exactly.
inline glm::vec3 cool_warm(float t) {
  if (std::isnan(t)) t = 0.0f;
  const float x = (std::clamp(t, -1.0f, 1.0f) + 1.0f) * 16.0f;  // 0 .. 32
  const auto i = static_cast<std::size_t>(std::floor(x));
  const float f = x - static_cast<float>(i);
  if (f == 0.0f) return kCoolWarmTable[i];  // an entry, exactly (also the last one)
  return kCoolWarmTable[i] + f * (kCoolWarmTable[i + 1] - kCoolWarmTable[i]);
}

/// A symmetric range [-r, r] for colouring `values` with cool_warm(v / r): the 98th percentile of
/// |v| (nearest rank: the smallest |v| with at least 98% of the values at or below it), so a few
/// spikes (up to 2%) do not wash the map out. Non-finite values are ignored. Never 0, always
/// finite: when the percentile is 0 the largest |v|, and 1 if that is 0 too (all zero) or there
/// are no finite values.
inline float symmetric_range(const std::vector<float>& values) {
  std::vector<float> magnitudes;
  magnitudes.reserve(values.size());
  for (const float v : values) {
    if (std::isfinite(v)) magnitudes.push_back(std::fabs(v));
  }
  if (magnitudes.empty()) return 1.0f;
  // Nearest rank ceil(0.98 n), 1-based; integer arithmetic, so 100 values give rank 98 exactly.
  const std::size_t n = magnitudes.size();
  const std::size_t rank = std::max<std::size_t>(1, (98 * n + 99) / 100);
  const auto nth = magnitudes.begin() + static_cast<std::ptrdiff_t>(rank - 1);
  std::nth_element(magnitudes.begin(), nth, magnitudes.end());
  if (*nth > 0.0f) return *nth;
  // Mostly zeros: the largest magnitude, if any, so the rest still shows.
  const float largest = *std::max_element(nth, magnitudes.end());
  return largest > 0.0f ? largest : 1.0f;
}

}  // namespace sweep
