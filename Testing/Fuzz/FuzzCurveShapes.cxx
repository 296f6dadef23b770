// Fuzz target: the shape of the Spline's segments (issue #12), called directly:
// lct::impactWeight on any four log steps and five times, and lct::curveWeights of a Spline
// segment with any tangent weights a tangent rule gives and any rational shape (lct/Curves.h:
// NaN, Inf, negative and huge shapes count as allowed input).
//
// Properties: no crash or sanitizer report; the impact weight is in [0, 1] (so never NaN); the
// curve weights are finite, index keys that exist and sum to 1.
#include "FuzzInput.h"

#include "lct/Curves.h"
#include "lct/MonotoneTangents.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace
{
void ImpactWeight(lct_fuzz::Input& in)
{
  lct::LogCoords steps[4];
  for (lct::LogCoords& step : steps)
  {
    step.setZero();
    const int nonZero = in.Int(0, 12);
    for (int i = 0; i < nonZero; ++i)
    {
      step[in.Int(0, 11)] = in.Double();
    }
  }
  double times[5];
  for (double& time : times)
  {
    time = in.Double();
  }
  if (in.Byte() % 2)
  {
    std::sort(times, times + 5); // mostly valid times (NaN aside)
  }
  const double w = lct::impactWeight(steps[0], steps[1], steps[2], steps[3], times);
  LCT_FUZZ_CHECK(w >= 0.0 && w <= 1.0,
    "impactWeight: " << w << " for times " << lct_fuzz::Show(times, 5) << " and steps "
                     << lct_fuzz::Show(steps[0]) << " / " << lct_fuzz::Show(steps[1]) << " / "
                     << lct_fuzz::Show(steps[2]) << " / " << lct_fuzz::Show(steps[3]));
}

void RationalSegment(lct_fuzz::Input& in)
{
  const std::vector<double> times = in.KeyTimes(2, 8);
  const int keys = static_cast<int>(times.size());
  if (keys < 2 || !std::isfinite(times.back() - times.front()))
  {
    return; // one key, or a span beyond the precondition (lct/Curves.h)
  }
  const double t = in.QueryTime();
  // Tangent weights as the rules give them: Catmull-Rom's times a factor in [-2, 2] (Kochanek-
  // Bartels scales them so; the monotone weights shrink with the time step of the faster side).
  // Weights independent of the time steps overflow with steps 1e8 and 1e-312 whatever the shape.
  const int segment = lct::curveSegment(times.data(), keys, t);
  const auto scaled = [&](int k) {
    const lct::KeyTangent catmullRom = lct::catmullRomTangent(times.data(), keys, k);
    return lct::KeyTangent{ std::clamp(in.Finite(), -2.0, 2.0) * catmullRom.before,
      std::clamp(in.Finite(), -2.0, 2.0) * catmullRom.after };
  };
  lct::SegmentTangents tangents{ scaled(segment), scaled(segment + 1) };
  tangents.shape = in.Double();
  const lct::CurveWeights w =
    lct::curveWeights(lct::CurveScheme::CatmullRom, times.data(), keys, t, tangents);
  LCT_FUZZ_CHECK(w.count >= 1 && w.count <= lct::CurveWeights::kCapacity,
    "curveWeights: " << w.count << " weights");
  double sum = 0.0, size = 0.0;
  for (int j = 0; j < w.count; ++j)
  {
    LCT_FUZZ_CHECK(w.key[j] >= 0 && w.key[j] < keys,
      "curveWeights: key index " << w.key[j] << " outside [0, " << keys << ")");
    LCT_FUZZ_CHECK(std::isfinite(w.weight[j]),
      "curveWeights: weight " << w.weight[j] << " at t = " << t << ", shape " << tangents.shape
                              << ", times " << lct_fuzz::Show(times.data(), keys));
    sum += w.weight[j];
    size = std::max(size, std::fabs(w.weight[j]));
  }
  // Tangent terms cancel in pairs (c, -c); their size bounds the round-off of the sum.
  LCT_FUZZ_CHECK(std::fabs(sum - 1.0) <= 1e-12 * std::max(1.0, size),
    "curveWeights: the weights sum to " << sum << " at t = " << t << ", shape " << tangents.shape
                                        << ", times " << lct_fuzz::Show(times.data(), keys));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  for (int op = 0; op < 8 && !in.Empty(); ++op)
  {
    if (in.Byte() % 2)
    {
      ImpactWeight(in);
    }
    else
    {
      RationalSegment(in);
    }
  }
  return 0;
}
