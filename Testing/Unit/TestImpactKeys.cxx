// Issue #12 §3: a key where the motion turns back abruptly (reached and left faster than the
// steps around it move: a bounce, a strike, a glitch in a recording) gets nearly straight Spline
// segments instead of the cubic's dwell at its ~0 tangent; a swing keyed at its extremes and a
// smooth crest keep the cubic. The rational segment (lct::SegmentTangents::shape) keeps the keys,
// the tangents and the sum of the weights.
#include "lct/Curves.h"
#include "lct/MonotoneTangents.h"

#include "vtkTransformInterpolatorLCT.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
constexpr double kPi = 3.14159265358979323846;

lct::LogCoords translationLog(double x, double y = 0.0)
{
  lct::LogCoords c = lct::LogCoords::Zero();
  c[0] = x;
  c[1] = y;
  return c;
}

/// impactWeight at the middle of five 1-D translation keys x at times t.
double impactOf(const double (&x)[5], const double (&t)[5])
{
  return lct::impactWeight(translationLog(x[0] - x[1]), translationLog(x[1] - x[2]),
    translationLog(x[3] - x[2]), translationLog(x[4] - x[3]), t);
}

/// The Spline (default) of 1-D translation keys x[k] at times k, or with rotations about z of
/// x[k] degrees; the translation (or the angle, degrees) at time t.
double splineAt(const std::vector<double>& x, bool rotate, double t, bool straighten = true)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  path->SetStraightenImpacts(straighten);
  for (size_t k = 0; k < x.size(); ++k)
  {
    vtkNew<vtkTransform> key;
    if (rotate)
    {
      key->RotateZ(x[k]);
    }
    else
    {
      key->Translate(x[k], 0, 0);
    }
    EXPECT_EQ(path->AddTransform(static_cast<double>(k), key), 1);
  }
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(path->InterpolateTransform(t, m), 1);
  return rotate ? std::atan2(m->GetElement(1, 0), m->GetElement(0, 0)) * 180.0 / kPi
                : m->GetElement(0, 3);
}
} // namespace

TEST(ImpactKeys, SwingsAndCrestsAreNotImpactsBouncesAndSpikesAre)
{
  const double even[5] = { 0, 1, 2, 3, 4 };
  // A swing keyed at its extremes moves at one speed: unchanged (the smooth turn).
  EXPECT_EQ(impactOf({ 0, 30, 0, 30, 0 }, even), 0.0);
  EXPECT_EQ(impactOf({ 30, 0, 30, 0, 30 }, even), 0.0);
  // A sampled sine's crest is reached slowly (8 keys per period).
  const double s = std::sqrt(0.5);
  EXPECT_EQ(impactOf({ 0, s, 1, s, 0 }, even), 0.0);
  // Monotone motion does not turn back.
  EXPECT_EQ(impactOf({ 0, 1, 5, 9, 10 }, even), 0.0);
  // A bounce keyed at quarter periods of |sin|: the ground is reached 2.4 times as fast as the
  // crest steps move, (2.41 - 1.5) / (2.5 - 1.5) of a full impact.
  EXPECT_NEAR(impactOf({ 1, s, 0, s, 1 }, even),
    (s / (1 - s) - lct::kImpactOnset) / (lct::kImpactFull - lct::kImpactOnset), 1e-12);
  // A spike on a line: reached and left 5-7 times as fast as the line moves.
  EXPECT_EQ(impactOf({ 2, 3, 10, 5, 6 }, even), 1.0);
  // Times count: the same spike reached slowly is not one.
  EXPECT_EQ(impactOf({ 2, 3, 10, 5, 6 }, { 0, 1, 20, 40, 41 }), 0.0);
  // The turn counts as cos^4: straight back 1, at 60 degrees 1/16, at 90 degrees or more 0.
  const double t[5] = { 0, 1, 2, 3, 4 };
  const auto turnedBy = [&](double degrees) {
    const double a = degrees * kPi / 180.0;
    return lct::impactWeight(translationLog(-1), translationLog(-10),
      translationLog(-10 * std::cos(a), 10 * std::sin(a)), translationLog(1), t);
  };
  EXPECT_EQ(turnedBy(0.0), 1.0);
  EXPECT_NEAR(turnedBy(60.0), 1.0 / 16.0, 1e-12);
  EXPECT_NEAR(turnedBy(90.0), 0.0, 1e-30); // cos(pi / 2) rounds to 6e-17
  EXPECT_EQ(turnedBy(150.0), 0.0);
  // Rotations count as the linear part: a spike of a turn about z.
  const auto turnZ = [](double radians) {
    lct::LogCoords c = lct::LogCoords::Zero();
    lct::rotationPart(c)[2] = radians;
    return c;
  };
  EXPECT_EQ(lct::impactWeight(turnZ(-0.1), turnZ(-1.2), turnZ(-0.9), turnZ(0.1), t), 1.0);
}

TEST(ImpactKeys, WeightIsUnitFreeAndSafeOnBadInput)
{
  const double t[5] = { 0, 1, 2, 3, 4 };
  const auto spike = [&](double size, double timeScale) {
    const double ts[5] = { t[0] * timeScale, t[1] * timeScale, t[2] * timeScale, t[3] * timeScale,
      t[4] * timeScale };
    return lct::impactWeight(translationLog(-1 * size), translationLog(-4 * size),
      translationLog(-3.5 * size), translationLog(1 * size), ts);
  };
  const double reference = spike(1.0, 1.0);
  EXPECT_GT(reference, 0.5);
  for (const double size : { 1e-300, 1e-150, 1e150, 1e300 })
  {
    for (const double timeScale : { 1e-300, 1e-100, 1e100, 1e300 })
    {
      EXPECT_NEAR(spike(size, timeScale), reference, 1e-12) << size << " " << timeScale;
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : { nan, inf, -inf })
  {
    EXPECT_EQ(lct::impactWeight(
                translationLog(-1), translationLog(bad), translationLog(-3), translationLog(1), t),
      0.0);
    EXPECT_EQ(lct::impactWeight(
                translationLog(bad), translationLog(-4), translationLog(-3), translationLog(1), t),
      0.0);
    const double times[5] = { 0, 1, bad, 3, 4 };
    EXPECT_EQ(lct::impactWeight(translationLog(-1), translationLog(-4), translationLog(-3),
                translationLog(1), times),
      0.0);
  }
  const double repeated[5] = { 0, 1, 1, 3, 4 }, decreasing[5] = { 0, 2, 1, 3, 4 },
               overflowing[5] = { -1e308, 1e308, 1.5e308, 1.6e308, 1.7e308 };
  for (const double* times : { repeated, decreasing, overflowing })
  {
    EXPECT_EQ(lct::impactWeight(translationLog(-1), translationLog(-4), translationLog(-3),
                translationLog(1), times),
      0.0);
  }
  // Still outer steps: any turn-back counts fully; still inner steps (or round-off) never.
  EXPECT_EQ(lct::impactWeight(lct::LogCoords::Zero(), translationLog(-4), translationLog(-3),
              lct::LogCoords::Zero(), t),
    1.0);
  EXPECT_EQ(lct::impactWeight(
              translationLog(-1), lct::LogCoords::Zero(), translationLog(-3), translationLog(1), t),
    0.0);
  EXPECT_EQ(lct::impactWeight(translationLog(-1), translationLog(-1e-14, 0), translationLog(-3),
              translationLog(1), t),
    0.0);
  // Steps near the double range: the turn's cosine does not overflow.
  EXPECT_EQ(lct::impactWeight(translationLog(-1e306, 1e306), translationLog(-1e308, 1e308),
              translationLog(-1e308, 1e308), translationLog(1e306, -1e306), t),
    1.0);
}

TEST(ImpactKeys, RationalSegmentKeepsKeysTangentsAndWeightSum)
{
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> gap(0.1, 3.0), share(-0.5, 1.5);
  for (int trial = 0; trial < 200; ++trial)
  {
    double times[4] = { 0.0, 0.0, 0.0, 0.0 };
    for (int k = 1; k < 4; ++k)
    {
      times[k] = times[k - 1] + gap(rng);
    }
    lct::SegmentTangents cubic{ { share(rng), share(rng) }, { share(rng), share(rng) } };
    const double values[] = { std::sin(trial), std::cos(trial), 0.3 * trial, -1.0 };
    const auto curve = [&](const lct::SegmentTangents& tangents, double time) {
      const lct::CurveWeights w =
        lct::curveWeights(lct::CurveScheme::CatmullRom, times, 4, time, tangents);
      double x = 0.0, sum = 0.0;
      for (int i = 0; i < w.count; ++i)
      {
        x += w.weight[i] * values[w.key[i]];
        sum += w.weight[i];
      }
      EXPECT_NEAR(sum, 1.0, 1e-14);
      return x;
    };
    for (const double r : { 3.5, 10.0, lct::kImpactShape, 1e6 })
    {
      lct::SegmentTangents rational = cubic;
      rational.shape = r;
      EXPECT_NEAR(curve(rational, times[1]), values[1], 1e-14) << r;
      EXPECT_NEAR(curve(rational, times[2]), values[2], 1e-14) << r;
      if (r > 1e3)
      {
        continue; // its ease zones are too narrow for the difference quotients below
      }
      // The same tangents at the keys (so C1 with the neighbouring cubic segments): one-sided
      // second-order differences into the segment.
      const double span = times[2] - times[1], h = 1e-5 * span;
      for (const double key : { times[1], times[2] })
      {
        const double side = key == times[1] ? 1.0 : -1.0;
        const auto slope = [&](const lct::SegmentTangents& tangents) {
          return side *
            (-3 * curve(tangents, key) + 4 * curve(tangents, key + side * h) -
              curve(tangents, key + 2 * side * h)) /
            (2 * h);
        };
        EXPECT_NEAR(slope(rational), slope(cubic), 1e-5 * r * r * (1 + 10 / span)) << r;
      }
    }
    // Toward the chord as r grows; r <= 3 or NaN is the cubic itself.
    lct::SegmentTangents nearlyStraight = cubic;
    nearlyStraight.shape = 1e9;
    const double middle = 0.5 * (times[1] + times[2]);
    EXPECT_NEAR(curve(nearlyStraight, middle), 0.5 * (values[1] + values[2]), 1e-6);
    for (const double r : { 3.0, 2.0, -5.0, std::numeric_limits<double>::quiet_NaN() })
    {
      lct::SegmentTangents same = cubic;
      same.shape = r;
      EXPECT_EQ(curve(same, middle), curve(cubic, middle)) << r;
    }
  }
}

TEST(ImpactKeys, SplineIsNearlyStraightBesideAnImpactAndKeepsSmoothTurns)
{
  for (const bool rotate : { false, true })
  {
    // A spike on a line (translations, or turns in degrees): a quarter into the segment after it
    // the curve is within 1 % of the step from the chord (the cubic, with the spike's zero
    // tangent, dwells: 10 - 5 h01(1/4) = 9.22 against the chord's 8.75).
    const std::vector<double> spike = { 0, 10, 20, 30, 100, 50, 60, 70, 80 };
    EXPECT_NEAR(splineAt(spike, rotate, 4.25), 87.5, 0.5) << rotate;
    EXPECT_NEAR(splineAt(spike, rotate, 4.0), 100.0, 1e-12) << rotate;
    // StraightenImpactsOff: the cubic, 100 - 50 h01(1/4).
    EXPECT_NEAR(splineAt(spike, rotate, 4.25, false), 100.0 - 50 * 0.15625, 1e-9) << rotate;
  }
  // A ball bouncing, keyed at quarter periods of |sin|: half-way from the ground key the curve
  // is within 0.04 of the true height sin(pi/8) = 0.383 (the cubic's dwell gives 0.302).
  std::vector<double> bounce;
  for (int k = 0; k <= 12; ++k)
  {
    bounce.push_back(std::fabs(std::sin(k * kPi / 4)));
  }
  EXPECT_NEAR(splineAt(bounce, false, 4.5), std::sin(kPi / 8), 0.04);
  EXPECT_NEAR(splineAt(bounce, false, 3.5), std::sin(kPi / 8), 0.04);
  // A swing keyed at its extremes keeps the smooth turn: zero tangents, the cubic's
  // 30 h01(1/4) = 4.6875.
  const std::vector<double> swing = { 0, 30, 0, 30, 0, 30, 0 };
  for (const bool rotate : { false, true })
  {
    EXPECT_NEAR(splineAt(swing, rotate, 2.25), 4.6875, 1e-9) << rotate;
    EXPECT_NEAR(splineAt(swing, rotate, 3.25), 30.0 - 4.6875, 1e-9) << rotate;
  }
}
