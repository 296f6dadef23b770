// Curve schemes as weights over keys: partition of unity, interpolation of keys, continuity,
// locality, and the subdivision limit against explicit 4-point subdivision.
#include "lct/Curves.h"
#include "lct/KeyLogs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

using lct::CurveScheme;

namespace
{
const CurveScheme kAll[] = { CurveScheme::Linear, CurveScheme::CatmullRom, CurveScheme::BSpline,
  CurveScheme::Subdivision };

/// sum_k w_k(t) p_k for scalar key values p.
double evaluate(
  CurveScheme s, const std::vector<double>& times, const std::vector<double>& p, double t)
{
  const lct::CurveWeights w = lct::curveWeights(s, times.data(), static_cast<int>(times.size()), t);
  double sum = 0.0;
  for (int j = 0; j < w.count; ++j)
  {
    sum += w.weight[j] * p[w.key[j]];
  }
  return sum;
}

std::vector<double> randomTimes(std::mt19937& rng, int n, bool uniform)
{
  std::uniform_real_distribution<double> gap(0.2, 2.0);
  std::vector<double> t(n);
  t[0] = -1.0;
  for (int i = 1; i < n; ++i)
  {
    t[i] = t[i - 1] + (uniform ? 0.5 : gap(rng));
  }
  return t;
}
} // namespace

TEST(Curves, WeightsSumToOneAndInterpolatingSchemesHitTheKeys)
{
  std::mt19937 rng(5);
  for (CurveScheme s : kAll)
  {
    for (int n : { 1, 2, 3, 4, 7, 20 })
    {
      const std::vector<double> times = randomTimes(rng, n, false);
      for (int k = 0; k <= 200; ++k)
      {
        const double t = times.front() + (times.back() - times.front()) * k / 200.0;
        const lct::CurveWeights w = lct::curveWeights(s, times.data(), n, t);
        double sum = 0.0;
        for (int j = 0; j < w.count; ++j)
        {
          sum += w.weight[j];
          ASSERT_GE(w.key[j], 0);
          ASSERT_LT(w.key[j], n);
        }
        ASSERT_NEAR(sum, 1.0, 1e-14);
      }
      if (s == CurveScheme::BSpline)
      {
        continue; // approximating: only the end keys are reproduced (below)
      }
      for (int i = 0; i < n; ++i)
      {
        const lct::CurveWeights w = lct::curveWeights(s, times.data(), n, times[i]);
        for (int j = 0; j < w.count; ++j)
        {
          ASSERT_NEAR(w.weight[j], w.key[j] == i ? 1.0 : 0.0, 1e-15);
        }
      }
    }
  }
}

TEST(Curves, BSplineStartsAndEndsOnTheEndKeys)
{
  const std::vector<double> times = { 0, 1, 2, 3, 4 };
  const std::vector<double> p = { 3, -1, 4, 1, 5 };
  EXPECT_NEAR(evaluate(CurveScheme::BSpline, times, p, 0.0), 3.0, 1e-15);
  EXPECT_NEAR(evaluate(CurveScheme::BSpline, times, p, 4.0), 5.0, 1e-15);
}

TEST(Curves, TimeIsClamped)
{
  const std::vector<double> times = { 0, 1, 3 };
  const std::vector<double> p = { 1, 2, 7 };
  for (CurveScheme s : kAll)
  {
    EXPECT_EQ(evaluate(s, times, p, -5.0), evaluate(s, times, p, 0.0));
    EXPECT_EQ(evaluate(s, times, p, 9.0), evaluate(s, times, p, 3.0));
  }
}

TEST(Curves, SplineAndSubdivisionAreC1AcrossKeys)
{
  // One-sided difference quotients at each inner key agree (Catmull-Rom on any times;
  // subdivision and B-spline on uniform times, where the index map is smooth).
  std::mt19937 rng(6);
  std::normal_distribution<double> value(0.0, 1.0);
  for (CurveScheme s : { CurveScheme::CatmullRom, CurveScheme::Subdivision, CurveScheme::BSpline })
  {
    const std::vector<double> times = randomTimes(rng, 9, s != CurveScheme::CatmullRom);
    std::vector<double> p(times.size());
    for (double& x : p)
    {
      x = value(rng);
    }
    for (size_t i = 1; i + 1 < times.size(); ++i)
    {
      const double h = 1e-8;
      const double left =
        (evaluate(s, times, p, times[i]) - evaluate(s, times, p, times[i] - h)) / h;
      const double right =
        (evaluate(s, times, p, times[i] + h) - evaluate(s, times, p, times[i])) / h;
      const double tolerance = 1e-4;
      EXPECT_NEAR(left, right, tolerance * (1.0 + std::abs(left))) << "key " << i;
    }
  }
}

TEST(Curves, SubdivisionMatchesExplicitFourPointRefinement)
{
  // Extend 8 uniform keys by 6 reflected dummies on each side (linear extrapolation, the
  // corrected Hawkins & Grimm boundary), refine 5 times with (-1, 9, 9, -1)/16, and compare
  // on the keys' range (the truncated outer dummies influence only 3 units inward).
  const std::vector<double> p = { 0.3, -1.2, 2.0, 0.7, 1.5, -0.4, 0.9, 2.2 };
  const int n = static_cast<int>(p.size());
  constexpr int kPad = 6;
  std::vector<double> level;
  for (int k = -kPad; k < n + kPad; ++k)
  {
    level.push_back(k < 0 ? p[0] + k * (p[1] - p[0])
        : k >= n          ? p[n - 1] + (k - n + 1) * (p[n - 1] - p[n - 2])
                          : p[k]);
  }
  constexpr int kRefinements = 5;
  for (int refinement = 0; refinement < kRefinements; ++refinement)
  {
    const int m = static_cast<int>(level.size());
    auto at = [&](int k) { return (k < 0 || k >= m) ? 0.0 : level[k]; };
    std::vector<double> next(2 * m - 1);
    for (int k = 0; k < m; ++k)
    {
      next[2 * k] = level[k];
    }
    for (int k = 0; k + 1 < m; ++k)
    {
      next[2 * k + 1] = (9.0 * (at(k) + at(k + 1)) - (at(k - 1) + at(k + 2))) / 16.0;
    }
    level.swap(next);
  }
  std::vector<double> times(n);
  for (int i = 0; i < n; ++i)
  {
    times[i] = i;
  }
  const int perUnit = 1 << kRefinements;
  double worst = 0.0;
  for (int k = 0; k <= (n - 1) * perUnit; ++k)
  {
    const double t = static_cast<double>(k) / perUnit;
    const double refined = level[(k + kPad * perUnit)];
    worst = std::max(worst, std::abs(evaluate(CurveScheme::Subdivision, times, p, t) - refined));
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(Curves, StencilsBoundTheWeightedKeysAndTheReferences)
{
  // lct::curveStencil is what the interpolators validate when a key is added (every relative log
  // a curve point may combine), so it must hold for any key times: every key curveWeights lists
  // lies in the segment's stencil, and the keys of largest and (within the hand-over gap) second
  // largest weight among its references.
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> gap(0.01, 3.0);
  const CurveScheme schemes[] = { CurveScheme::Linear, CurveScheme::CatmullRom,
    CurveScheme::BSpline, CurveScheme::Subdivision, CurveScheme::Bezier };
  for (const CurveScheme s : schemes)
  {
    for (int n = 1; n <= 9; ++n)
    {
      for (int trial = 0; trial < 20; ++trial)
      {
        // Uniform, random and wildly uneven gaps (a short segment next to a long one stretches
        // the Catmull-Rom tangents most).
        std::vector<double> times(n);
        times[0] = 0.0;
        for (int i = 1; i < n; ++i)
        {
          times[i] = times[i - 1] + (trial == 0 ? 1.0 : (trial % 2 ? gap(rng) : gap(rng) * 1e-3));
        }
        const double span = times[n - 1] - times[0];
        for (int k = 0; k <= 400; ++k)
        {
          // The key times exactly, and a grid between.
          const double t = k <= n - 1 ? times[k] : times[0] + span * (k - n) / 400.0;
          const lct::CurveWeights w = lct::curveWeights(s, times.data(), n, t);
          const int segment = n == 1
            ? 0
            : std::min(
                static_cast<int>(std::upper_bound(times.begin(), times.end(), t) - times.begin()) -
                  1,
                n - 2);
          const lct::CurveStencil stencil = lct::curveStencil(s, n, segment);
          int a = -1;
          int b = -1;
          for (int j = 0; j < w.count; ++j)
          {
            EXPECT_GE(w.key[j], stencil.first) << static_cast<int>(s) << " n " << n << " t " << t;
            EXPECT_LE(w.key[j], stencil.last) << static_cast<int>(s) << " n " << n << " t " << t;
            if (a < 0 || w.weight[j] > w.weight[a])
            {
              b = a;
              a = j;
            }
            else if (b < 0 || w.weight[j] > w.weight[b])
            {
              b = j;
            }
          }
          ASSERT_GE(a, 0);
          EXPECT_GE(w.key[a], stencil.firstReference) << static_cast<int>(s) << " t " << t;
          EXPECT_LE(w.key[a], stencil.lastReference) << static_cast<int>(s) << " t " << t;
          if (b >= 0 && w.weight[a] - w.weight[b] < lct::KeyLogs::kHandOver)
          {
            EXPECT_GE(w.key[b], stencil.firstReference) << static_cast<int>(s) << " t " << t;
            EXPECT_LE(w.key[b], stencil.lastReference) << static_cast<int>(s) << " t " << t;
          }
        }
      }
    }
  }
}
