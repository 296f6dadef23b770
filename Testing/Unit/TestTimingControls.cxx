// Issue #12 §3, timing controls: Kochanek-Bartels tension / continuity / bias in log space,
// per-key and per-path eases, and constant speed by arc length, on both interpolators. Each
// behaviour is checked against an independent reference (a scalar Hermite spline written out
// here from Kochanek & Bartels' equations, finite-difference speeds along the path), so a wrong
// tangent, a missed key or an uneven speed fails.
#include "lct/ArcLength.h"
#include "lct/Curves.h"
#include "lct/Ease.h"
#include "lct/KochanekBartels.h"

#include "vtkCameraInterpolatorLCT.h"
#include "vtkTransformInterpolatorLCT.h"

#include "VtkTestHelpers.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <thread>
#include <vector>

namespace
{
struct Tcb
{
  double t, c, b;
};

/// Kochanek & Bartels' scalar spline through (times[k], x[k]), written out independently of
/// lct/KochanekBartels.h: eq. 7-8 with the non-uniform adjustment of eq. 9, one-sided
/// (1 - T) secants at the ends.
double referenceKochanek(const std::vector<double>& times, const std::vector<double>& x,
  const std::vector<Tcb>& p, double t)
{
  const int n = static_cast<int>(times.size());
  int i = 0;
  while (i + 2 < n && t > times[i + 1])
  {
    ++i;
  }
  const auto tangent = [&](int k, bool leaving) {
    // Derivative with respect to time at key k.
    if (k == 0)
    {
      return (1 - p[k].t) * (x[1] - x[0]) / (times[1] - times[0]);
    }
    if (k == n - 1)
    {
      return (1 - p[k].t) * (x[k] - x[k - 1]) / (times[k] - times[k - 1]);
    }
    const double dm = x[k] - x[k - 1], dp = x[k + 1] - x[k];
    const double T = p[k].t, C = p[k].c, B = p[k].b;
    const double a = leaving ? (1 - T) * (1 + C) * (1 + B) / 2 : (1 - T) * (1 - C) * (1 + B) / 2;
    const double b = leaving ? (1 - T) * (1 - C) * (1 - B) / 2 : (1 - T) * (1 + C) * (1 - B) / 2;
    const double perSegment = a * dm + b * dp; // d x / d u on a unit segment
    const double h = leaving ? times[k + 1] - times[k] : times[k] - times[k - 1];
    const double adjusted = perSegment * 2 * h / (times[k + 1] - times[k - 1]); // eq. 9
    return adjusted / h;
  };
  const double h = times[i + 1] - times[i];
  const double u = (t - times[i]) / h;
  const double u2 = u * u, u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * x[i] + (u3 - 2 * u2 + u) * h * tangent(i, true) +
    (-2 * u3 + 3 * u2) * x[i + 1] + (u3 - u2) * h * tangent(i + 1, false);
}

/// Translation keys along x; the Polar log of a translation step is the step, so the
/// interpolated x follows the scalar spline of the key values exactly.
void addTranslations(
  vtkTransformInterpolatorLCT* path, const std::vector<double>& times, const std::vector<double>& x)
{
  for (size_t k = 0; k < times.size(); ++k)
  {
    vtkNew<vtkTransform> key;
    key->Translate(x[k], 0.5 * x[k], 0);
    ASSERT_EQ(path->AddTransform(times[k], key), 1);
  }
}

double xAt(vtkTransformInterpolatorLCT* path, double t)
{
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(path->InterpolateTransform(t, m), 1);
  return m->GetElement(0, 3);
}

Eigen::Vector3d pointAt(vtkTransformInterpolatorLCT* path, double t, const Eigen::Vector3d& p)
{
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(path->InterpolateTransform(t, m), 1);
  const Eigen::Matrix4d e = lct_test::fromVtk(m);
  return e.topLeftCorner<3, 3>() * p + e.topRightCorner<3, 1>();
}

/// The largest relative deviation of the speed from its mean over `samples` equal time steps
/// of [t0, t1]: the distance covered in each step, measured along the path (64 chords per step,
/// so that a tight turn or a turning back within a step is not cut short).
template <typename At>
double speedDeviation(At&& at, double t0, double t1, int samples)
{
  constexpr int kChords = 64;
  std::vector<double> steps;
  Eigen::VectorXd previous = at(t0);
  for (int j = 0; j < samples; ++j)
  {
    double covered = 0;
    for (int c = 1; c <= kChords; ++c)
    {
      const Eigen::VectorXd p = at(t0 + (t1 - t0) * (j + double(c) / kChords) / samples);
      covered += (p - previous).norm();
      previous = p;
    }
    steps.push_back(covered);
  }
  double mean = 0;
  for (double s : steps)
  {
    mean += s / steps.size();
  }
  double worst = 0;
  for (double s : steps)
  {
    worst = std::max(worst, std::abs(s / mean - 1));
  }
  return worst;
}
} // namespace

// ---- the core -----------------------------------------------------------------------------

TEST(TimingControls, ZeroTensionContinuityBiasIsCatmullRom)
{
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> step(0.1, 3.0);
  for (int trial = 0; trial < 100; ++trial)
  {
    std::vector<double> times{ 0.0 };
    for (int k = 1; k < 7; ++k)
    {
      times.push_back(times.back() + step(rng));
    }
    for (int k = 0; k < 7; ++k)
    {
      const lct::KeyTangent cr = lct::catmullRomTangent(times.data(), 7, k);
      const lct::KeyTangents kb = lct::kochanekBartelsTangents(times.data(), 7, k, {});
      for (const lct::KeyTangent& side : { kb.arriving, kb.leaving })
      {
        EXPECT_NEAR(side.before, cr.before, 1e-15);
        EXPECT_NEAR(side.after, cr.after, 1e-15);
      }
    }
  }
}

TEST(TimingControls, ParametersOutsideMinusOneToOneAreInvalid)
{
  EXPECT_TRUE(lct::isValid(lct::TensionContinuityBias{ -1, 1, 0.5 }));
  EXPECT_FALSE(lct::isValid(lct::TensionContinuityBias{ 1.0001, 0, 0 }));
  EXPECT_FALSE(lct::isValid(lct::TensionContinuityBias{ 0, std::nan(""), 0 }));
  EXPECT_FALSE(lct::isValid(lct::TensionContinuityBias{ 0, 0, -INFINITY }));
}

TEST(TimingControls, EaseIsIncreasingWithTheGivenEndSlopes)
{
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> amount(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial)
  {
    const double leaving = trial == 0 ? 1.0 : amount(rng),
                 arriving = trial == 0 ? 1.0 : amount(rng);
    EXPECT_EQ(lct::easeSegment(0.0, leaving, arriving), 0.0);
    EXPECT_EQ(lct::easeSegment(1.0, leaving, arriving), 1.0);
    double previous = 0.0;
    for (int j = 1; j <= 1000; ++j)
    {
      const double e = lct::easeSegment(j / 1000.0, leaving, arriving);
      EXPECT_GE(e, previous);
      previous = e;
    }
    const double h = 1e-6;
    EXPECT_NEAR(lct::easeSegment(h, leaving, arriving) / h, 1 - leaving, 1e-5);
    EXPECT_NEAR((1 - lct::easeSegment(1 - h, leaving, arriving)) / h, 1 - arriving, 1e-5);
  }
  for (double u : { 0.0, 0.1, 0.37, 0.9, 1.0 })
  {
    EXPECT_EQ(lct::easeSegment(u, 0.0, 0.0), u); // no ease: exactly the identity
  }
}

TEST(TimingControls, ArcLengthTableGivesEvenSpeedOnAnUnevenlyTimedCircle)
{
  // p(tau) on the unit circle at angle tau^3 (speed 3 tau^2: still at tau = 0).
  const auto at = [](double tau, Eigen::Vector3d& p) {
    p = Eigen::Vector3d(std::cos(tau * tau * tau), std::sin(tau * tau * tau), 0);
    return true;
  };
  std::vector<double> taus;
  std::vector<Eigen::Vector3d> points;
  for (int j = 0; j <= 1024; ++j)
  {
    taus.push_back(1.5 * j / 1024);
    Eigen::Vector3d p;
    at(taus.back(), p);
    points.push_back(p);
  }
  lct::ArcLengthTime<3> table;
  ASSERT_TRUE(table.build(taus, points));
  EXPECT_NEAR(table.length(), 1.5 * 1.5 * 1.5, 1e-5); // the arc: angle 3.375 on a unit circle
  const double deviation = speedDeviation(
    [&](double t) {
      Eigen::Vector3d p;
      at(table.curveTime(t, at), p);
      return Eigen::VectorXd(p);
    },
    0.0, 1.5, 300);
  EXPECT_LT(deviation, 2e-3); // the chord of a 1/1024 interval misses 2e-4 of its arc
}

TEST(TimingControls, ArcLengthTableRefusesNonFinitePoints)
{
  lct::ArcLengthTime<3> table;
  EXPECT_FALSE(table.build({ 0, 1 }, { Eigen::Vector3d::Zero(), Eigen::Vector3d(NAN, 0, 0) }));
  EXPECT_FALSE(table.build({ 0, 1 },
    { Eigen::Vector3d(-1e308, 0, 0), Eigen::Vector3d(1e308, 0, 0) })); // the length overflows
  EXPECT_FALSE(table.build({ 1, 0 }, { Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones() }));
  EXPECT_FALSE(table.build({ 0, 1 }, { Eigen::Vector3d::Zero() }));
  EXPECT_TRUE(table.empty());
}

// ---- vtkTransformInterpolatorLCT ----------------------------------------------------------

TEST(TimingControls, TransformSplineFollowsKochanekBartelsReference)
{
  const std::vector<double> times{ 0, 0.7, 2.0, 2.4, 4.0, 5.5 };
  const std::vector<double> x{ 0, 3, -1, 2, 2.5, 7 };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> parameter(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial)
  {
    vtkNew<vtkTransformInterpolatorLCT> path;
    path->MonotoneTangentsOff();
    addTranslations(path, times, x);
    const Tcb common{ trial == 0 ? 0.0 : parameter(rng), trial == 0 ? 0.0 : parameter(rng),
      trial == 0 ? 0.0 : parameter(rng) };
    ASSERT_EQ(path->SetTension(common.t), 1);
    ASSERT_EQ(path->SetContinuity(common.c), 1);
    ASSERT_EQ(path->SetBias(common.b), 1);
    std::vector<Tcb> p(times.size(), common);
    if (trial > 0)
    {
      p[2] = { parameter(rng), parameter(rng), parameter(rng) }; // one key of its own
      ASSERT_EQ(path->SetKeyTensionContinuityBias(times[2], p[2].t, p[2].c, p[2].b), 1);
    }
    for (int j = 0; j <= 200; ++j)
    {
      const double t = 5.5 * j / 200;
      EXPECT_NEAR(xAt(path, t), referenceKochanek(times, x, p, t), 1e-9) << "trial " << trial;
    }
  }
}

TEST(TimingControls, TensionOneStopsAtEveryKeyAndKeysStayExact)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  const std::vector<double> times{ 0, 1, 3, 4 };
  const std::vector<double> x{ 0, 2, 5, 9 };
  addTranslations(path, times, x);
  ASSERT_EQ(path->SetTension(1.0), 1);
  for (size_t k = 0; k < times.size(); ++k)
  {
    EXPECT_NEAR(xAt(path, times[k]), x[k], 1e-12);
  }
  const double h = 1e-5;
  for (double t : { 1.0, 3.0 })
  {
    EXPECT_NEAR((xAt(path, t + h) - xAt(path, t)) / h, 0.0, 1e-3);
    EXPECT_NEAR((xAt(path, t) - xAt(path, t - h)) / h, 0.0, 1e-3);
  }
}

TEST(TimingControls, KeyEaseSlowsArrivalAndDepartureButKeepsKeyTimes)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  const std::vector<double> times{ 0, 1, 2, 3 };
  const std::vector<double> x{ 0, 1, 2, 3 }; // uniform motion: speed 1 without eases
  addTranslations(path, times, x);
  ASSERT_EQ(path->SetKeyEase(1.0, 1.0, 0.5), 1); // arrive at rest, leave at half speed
  for (size_t k = 0; k < times.size(); ++k)
  {
    EXPECT_NEAR(xAt(path, times[k]), x[k], 1e-12);
  }
  const double h = 1e-6;
  EXPECT_NEAR((xAt(path, 1.0) - xAt(path, 1.0 - h)) / h, 0.0, 1e-4);
  EXPECT_NEAR((xAt(path, 1.0 + h) - xAt(path, 1.0)) / h, 0.5, 1e-4);
  EXPECT_NEAR((xAt(path, 2.5 + h) - xAt(path, 2.5)) / h, 1.0, 1e-4); // untouched segment
  // Path-wide: starts from rest, ends at half speed.
  ASSERT_EQ(path->ClearKeyTiming(1.0), 1);
  ASSERT_EQ(path->SetEaseIn(1.0), 1);
  ASSERT_EQ(path->SetEaseOut(0.5), 1);
  EXPECT_NEAR((xAt(path, h) - xAt(path, 0.0)) / h, 0.0, 1e-4);
  EXPECT_NEAR((xAt(path, 3.0) - xAt(path, 3.0 - h)) / h, 0.5, 1e-4);
  EXPECT_NEAR((xAt(path, 1.5 + h) - xAt(path, 1.5)) / h, 1.0, 1e-4);
}

TEST(TimingControls, TransformConstantSpeedIsEvenWithinOnePercent)
{
  // Keys unevenly spaced in space and in time, with turns: the translation's speed varies by
  // a factor of ~20 along the plain Spline.
  vtkNew<vtkTransformInterpolatorLCT> path;
  const double keyTimes[] = { 0, 1, 1.5, 4, 5 };
  const double positions[][3] = { { 0, 0, 0 }, { 0.5, 0, 0 }, { 6, 2, 0 }, { 7, 2.5, 1 },
    { 20, 0, 3 } };
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkTransform> key;
    key->Translate(positions[k]);
    key->RotateZ(40.0 * k);
    key->Scale(1 + 0.1 * k, 1, 1);
    ASSERT_EQ(path->AddTransform(keyTimes[k], key), 1);
  }
  const Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  const auto at = [&](double t) { return Eigen::VectorXd(pointAt(path, t, origin)); };
  EXPECT_GT(speedDeviation(at, 0, 5, 400), 0.5); // the plain path is far from even
  path->ConstantSpeedOn();
  EXPECT_LT(speedDeviation(at, 0, 5, 400), 0.01);
  // Keys are passed at their arc-length times, in order, from the first time to the last.
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
  ASSERT_EQ(arrivals->GetNumberOfTuples(), 5);
  EXPECT_EQ(arrivals->GetValue(0), 0.0);
  EXPECT_EQ(arrivals->GetValue(4), 5.0);
  for (int k = 0; k < 5; ++k)
  {
    const Eigen::Vector3d passed = pointAt(path, arrivals->GetValue(k), origin);
    EXPECT_LT((passed - Eigen::Vector3d(positions[k])).norm(), 1e-6) << "key " << k;
    if (k > 0)
    {
      EXPECT_GT(arrivals->GetValue(k), arrivals->GetValue(k - 1));
    }
  }
  // A user point off the axis: its path is even too.
  ASSERT_EQ(path->SetConstantSpeedPoint(0, 3, 0), 1);
  const Eigen::Vector3d off(0, 3, 0);
  EXPECT_LT(
    speedDeviation([&](double t) { return Eigen::VectorXd(pointAt(path, t, off)); }, 0, 5, 400),
    0.01);
}

TEST(TimingControls, ConstantSpeedOfAStillPointKeepsTheKeyTimes)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(50.0 * k * k); // a turn about the origin, unevenly timed
    ASSERT_EQ(path->AddTransform(k, key), 1);
  }
  vtkNew<vtkMatrix4x4> plain, even;
  ASSERT_EQ(path->InterpolateTransform(1.3, plain), 1);
  path->ConstantSpeedOn();
  ASSERT_EQ(path->InterpolateTransform(1.3, even), 1);
  EXPECT_LT((lct_test::fromVtk(plain) - lct_test::fromVtk(even)).norm(), 1e-15);
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
  for (int k = 0; k < 4; ++k)
  {
    EXPECT_EQ(arrivals->GetValue(k), k);
  }
}

TEST(TimingControls, TransformTimingBadInputIsRefusedAndChangesNothing)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<lct_test::ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  addTranslations(path, { 0, 1, 2 }, { 0, 1, 3 });
  ASSERT_EQ(path->SetTension(0.25), 1);
  ASSERT_EQ(path->SetEaseIn(0.5), 1);
  const vtkMTimeType before = path->GetMTime();
  EXPECT_EQ(path->SetTension(1.5), 0);
  EXPECT_EQ(path->SetContinuity(std::nan("")), 0);
  EXPECT_EQ(path->SetBias(-INFINITY), 0);
  EXPECT_EQ(path->SetEaseIn(-0.1), 0);
  EXPECT_EQ(path->SetEaseOut(1.01), 0);
  EXPECT_EQ(path->SetKeyEase(0.5, 0.2, 0.2), 0); // no key at 0.5
  EXPECT_EQ(path->SetKeyEase(1.0, 0.2, std::nan("")), 0);
  // The message names the key and the argument (it read "SetKeyEase(nan)", like a key time).
  EXPECT_NE(errors->Last.find("SetKeyEase(t = 1): the leaving ease nan is outside [0, 1]"),
    std::string::npos)
    << errors->Last;
  EXPECT_EQ(path->SetKeyTensionContinuityBias(1.0, 0, 2, 0), 0);
  EXPECT_NE(errors->Last.find("SetKeyTensionContinuityBias(t = 1): the continuity 2 is outside"),
    std::string::npos)
    << errors->Last;
  EXPECT_EQ(path->SetKeyTensionContinuityBias(std::nan(""), 0, 0, 0), 0);
  EXPECT_EQ(path->ClearKeyTiming(7.0), 0);
  EXPECT_EQ(path->SetConstantSpeedPoint(0, NAN, 0), 0);
  EXPECT_EQ(path->GetKeyArrivalTimes(nullptr), 0);
  EXPECT_EQ(errors->Count, 12);
  EXPECT_NE(errors->Last.find("null array"), std::string::npos);
  EXPECT_EQ(path->GetMTime(), before);
  EXPECT_EQ(path->GetTension(), 0.25);
  EXPECT_EQ(path->GetContinuity(), 0.0);
  EXPECT_EQ(path->GetEaseIn(), 0.5);
  double point[3];
  path->GetConstantSpeedPoint(point);
  EXPECT_EQ(Eigen::Vector3d(point[0], point[1], point[2]), Eigen::Vector3d::Zero());
  vtkNew<vtkTransformInterpolatorLCT> empty;
  empty->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkDoubleArray> arrivals;
  EXPECT_EQ(empty->GetKeyArrivalTimes(arrivals), 0);
  EXPECT_EQ(arrivals->GetNumberOfTuples(), 0);
}

TEST(TimingControls, ConstantSpeedOfHugeAndTinyPathsIsTheSameAsOfAUnitOne)
{
  // Constant speed depends on the path's shape, not its size. From ~1.3e154 on, the distance in
  // the query's solve squared out of double (Inf): it gave up silently and the point ran up to
  // 16 % of the path off even, with every call returning 1.
  const auto normalisedPath = [](double size) {
    vtkNew<vtkTransformInterpolatorLCT> path;
    addTranslations(path, { 0, 1, 2 }, { 0, size, -size });
    path->ConstantSpeedOn();
    std::vector<double> x;
    for (int i = 0; i <= 16; ++i)
    {
      x.push_back(xAt(path, i / 8.0) / size);
    }
    return x;
  };
  const std::vector<double> unit = normalisedPath(1.0);
  for (const double size : { 1e-300, 1e-160, 1e155, 1e160, 1e200 })
  {
    const std::vector<double> scaled = normalisedPath(size);
    for (size_t i = 0; i < unit.size(); ++i)
    {
      EXPECT_NEAR(scaled[i], unit[i], 1e-9) << "size " << size << " at t = " << i / 8.0;
    }
  }
}

TEST(TimingControls, ConstantSpeedOfAnOverflowingPathIsAnErrorNotInf)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<lct_test::ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  addTranslations(path, { 0, 1, 2 }, { 0, 1e308, 0 }); // the summed chords overflow
  path->SetInterpolationTypeToLinear();
  path->ConstantSpeedOn();
  vtkNew<vtkMatrix4x4> m;
  m->SetElement(0, 3, 42);
  EXPECT_EQ(path->InterpolateTransform(0.5, m), 0);
  EXPECT_EQ(m->GetElement(0, 3), 42);
  EXPECT_NE(errors->Last.find("ConstantSpeed"), std::string::npos);
  vtkNew<vtkDoubleArray> arrivals;
  EXPECT_EQ(path->GetKeyArrivalTimes(arrivals), 0);
}

TEST(Concurrency, ConstantSpeedTableIsBuiltOnceAcrossThreads)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  for (int k = 0; k < 12; ++k)
  {
    vtkNew<vtkTransform> key;
    key->Translate(k * k, std::sin(k), 0);
    key->RotateX(30.0 * k);
    ASSERT_EQ(path->AddTransform(0.5 * k, key), 1);
  }
  path->ConstantSpeedOn();
  path->SetEaseIn(0.5);
  std::vector<double> serial(64), parallel(64);
  {
    vtkNew<vtkTransformInterpolatorLCT> copy; // the same keys, evaluated serially
    for (int k = 0; k < 12; ++k)
    {
      vtkNew<vtkTransform> key;
      key->Translate(k * k, std::sin(k), 0);
      key->RotateX(30.0 * k);
      ASSERT_EQ(copy->AddTransform(0.5 * k, key), 1);
    }
    copy->ConstantSpeedOn();
    copy->SetEaseIn(0.5);
    for (int j = 0; j < 64; ++j)
    {
      serial[j] = xAt(copy, 5.5 * j / 63);
    }
  }
  std::vector<std::thread> threads;
  for (int thread = 0; thread < 4; ++thread)
  {
    threads.emplace_back([&, thread] {
      vtkNew<vtkMatrix4x4> m;
      for (int j = thread; j < 64; j += 4)
      {
        path->InterpolateTransform(5.5 * j / 63, m);
        parallel[j] = m->GetElement(0, 3);
      }
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  for (int j = 0; j < 64; ++j)
  {
    EXPECT_EQ(parallel[j], serial[j]) << j;
  }
}

// ---- vtkCameraInterpolatorLCT -------------------------------------------------------------

namespace
{
void addDolly(vtkCameraInterpolatorLCT* path, const std::vector<double>& times,
  const std::vector<double>& z, double roll = 0)
{
  for (size_t k = 0; k < times.size(); ++k)
  {
    vtkNew<vtkCamera> key;
    key->SetFocalPoint(0.3 * z[k], 0, 0);
    key->SetPosition(0.3 * z[k], 0, 10 + z[k]);
    key->SetViewUp(0, 1, 0);
    key->Roll(roll * k);
    ASSERT_EQ(path->AddCamera(times[k], key), 1);
  }
}

Eigen::VectorXd eyeAndFocalPoint(vtkCameraInterpolatorLCT* path, double t)
{
  vtkNew<vtkCamera> c;
  EXPECT_EQ(path->InterpolateCamera(t, c), 1);
  Eigen::VectorXd p(6);
  p << c->GetPosition()[0], c->GetPosition()[1], c->GetPosition()[2], c->GetFocalPoint()[0],
    c->GetFocalPoint()[1], c->GetFocalPoint()[2];
  return p;
}
} // namespace

TEST(TimingControls, CameraChannelsFollowKochanekBartelsReference)
{
  // A dolly: the distance is interpolated geometrically, i.e. its log follows the scalar spline.
  const std::vector<double> times{ 0, 1, 1.5, 3, 4 };
  const std::vector<double> z{ 0, 5, 6, 20, 21 };
  vtkNew<vtkCameraInterpolatorLCT> path;
  path->ScrewMotionOff();
  for (size_t k = 0; k < times.size(); ++k)
  {
    vtkNew<vtkCamera> key;
    key->SetFocalPoint(0, 0, 0);
    key->SetPosition(0, 0, std::exp(0.1 * z[k]));
    ASSERT_EQ(path->AddCamera(times[k], key), 1);
  }
  const Tcb p{ 0.3, -0.4, 0.6 };
  ASSERT_EQ(path->SetTension(p.t), 1);
  ASSERT_EQ(path->SetContinuity(p.c), 1);
  ASSERT_EQ(path->SetBias(p.b), 1);
  std::vector<double> logDistance;
  for (double v : z)
  {
    logDistance.push_back(0.1 * v);
  }
  const std::vector<Tcb> all(times.size(), p);
  for (int j = 0; j <= 100; ++j)
  {
    const double t = 4.0 * j / 100;
    vtkNew<vtkCamera> c;
    ASSERT_EQ(path->InterpolateCamera(t, c), 1);
    EXPECT_NEAR(std::log(c->GetDistance()), referenceKochanek(times, logDistance, all, t), 1e-9);
  }
}

TEST(TimingControls, CameraKeysStayExactWithTimingAndConstantSpeedIsEven)
{
  const std::vector<double> times{ 0, 0.5, 3, 3.2, 6 };
  const std::vector<double> z{ 0, 8, 9, 30, 31 };
  vtkNew<vtkCameraInterpolatorLCT> path;
  addDolly(path, times, z, 25.0);
  ASSERT_EQ(path->SetBias(0.4), 1);
  for (size_t k = 0; k < times.size(); ++k)
  {
    ASSERT_EQ(path->SetKeyEase(times[k], 0.7, 0.3), 1);
  }
  for (size_t k = 0; k < times.size(); ++k)
  {
    const Eigen::VectorXd p = eyeAndFocalPoint(path, times[k]);
    EXPECT_NEAR(p[2], 10 + z[k], 1e-9);
    EXPECT_NEAR(p[3], 0.3 * z[k], 1e-9);
  }
  const auto at = [&](double t) { return eyeAndFocalPoint(path, t); };
  EXPECT_GT(speedDeviation(at, 0, 6, 300), 0.5);
  path->ConstantSpeedOn();
  EXPECT_LT(speedDeviation(at, 0, 6, 300), 0.01);
  path->SetConstantSpeedMeasure(vtkCameraInterpolatorLCT::CONSTANT_SPEED_EYE);
  EXPECT_LT(
    speedDeviation([&](double t) { return Eigen::VectorXd(at(t).head(3)); }, 0, 6, 300), 0.01);
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
  for (size_t k = 0; k < times.size(); ++k)
  {
    EXPECT_NEAR(at(arrivals->GetValue(k))[2], 10 + z[k], 1e-6);
  }
}

TEST(TimingControls, CameraTimingBadInputIsRefusedAndChangesNothing)
{
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<lct_test::ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  addDolly(path, { 0, 1, 2 }, { 0, 1, 3 });
  const vtkMTimeType before = path->GetMTime();
  EXPECT_EQ(path->SetTension(-1.5), 0);
  EXPECT_EQ(path->SetEaseOut(std::nan("")), 0);
  EXPECT_EQ(path->SetKeyEase(3.0, 0, 0), 0);
  EXPECT_EQ(path->SetKeyTensionContinuityBias(1.0, 0, 0, 7), 0);
  EXPECT_EQ(path->ClearKeyTiming(-1.0), 0);
  EXPECT_EQ(errors->Count, 5);
  EXPECT_EQ(path->GetMTime(), before);
  EXPECT_EQ(path->GetTension(), 0.0);
}

TEST(TimingControls, OneKeyWithEveryTimingControlIsThatKey)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<vtkTransform> key;
  key->Translate(1, 2, 3);
  key->RotateY(30);
  ASSERT_EQ(path->AddTransform(2.0, key), 1);
  ASSERT_EQ(path->SetTension(0.5), 1);
  ASSERT_EQ(path->SetKeyEase(2.0, 1, 1), 1);
  path->ConstantSpeedOn();
  vtkNew<vtkMatrix4x4> m;
  ASSERT_EQ(path->InterpolateTransform(2.0, m), 1);
  EXPECT_LT((lct_test::fromVtk(m) - lct_test::fromVtk(key->GetMatrix())).norm(), 1e-15);
  vtkNew<vtkCameraInterpolatorLCT> camera;
  vtkNew<vtkCamera> c;
  c->SetPosition(1, 2, 3);
  ASSERT_EQ(camera->AddCamera(0.0, c), 1);
  ASSERT_EQ(camera->SetBias(0.5), 1);
  camera->ConstantSpeedOn();
  vtkNew<vtkCamera> out;
  ASSERT_EQ(camera->InterpolateCamera(0.0, out), 1);
  EXPECT_NEAR(out->GetPosition()[1], 2.0, 1e-12);
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(camera->GetKeyArrivalTimes(arrivals), 1);
  EXPECT_EQ(arrivals->GetValue(0), 0.0);
}

TEST(Concurrency, CameraConstantSpeedTableIsBuiltOnceAcrossThreads)
{
  const auto fill = [](vtkCameraInterpolatorLCT* path) {
    addDolly(path, { 0, 0.5, 3, 3.2, 6 }, { 0, 8, 9, 30, 31 }, 25.0);
    path->ConstantSpeedOn();
  };
  vtkNew<vtkCameraInterpolatorLCT> shared, serialPath;
  fill(shared);
  fill(serialPath);
  std::vector<Eigen::VectorXd> serial(48), parallel(48);
  for (int j = 0; j < 48; ++j)
  {
    serial[j] = eyeAndFocalPoint(serialPath, 6.0 * j / 47);
  }
  std::vector<std::thread> threads;
  for (int thread = 0; thread < 4; ++thread)
  {
    threads.emplace_back([&, thread] {
      for (int j = thread; j < 48; j += 4)
      {
        parallel[j] = eyeAndFocalPoint(shared, 6.0 * j / 47);
      }
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
  for (int j = 0; j < 48; ++j)
  {
    EXPECT_EQ(parallel[j], serial[j]) << j;
  }
}

TEST(TimingControls, ArrivalTimesUnderConstantSpeedAndPathEasesPassTheKeys)
{
  // helper-11's case: with a path ease, the arrival times are the eased ones.
  for (const double easeIn : { 0.0, 0.3, 1.0 })
  {
    for (const double easeOut : { 0.0, 0.5, 1.0 })
    {
      vtkNew<vtkTransformInterpolatorLCT> path;
      addTranslations(path, { 0, 0.5, 2, 3 }, { 0, 0.25, 1.5, 4 });
      path->ConstantSpeedOn();
      ASSERT_EQ(path->SetEaseIn(easeIn), 1);
      ASSERT_EQ(path->SetEaseOut(easeOut), 1);
      vtkNew<vtkDoubleArray> arrivals;
      ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
      const double keys[] = { 0, 0.25, 1.5, 4 };
      for (int k = 0; k < 4; ++k)
      {
        EXPECT_NEAR(xAt(path, arrivals->GetValue(k)), keys[k], 1e-9)
          << "ease in " << easeIn << ", out " << easeOut << ", key " << k;
      }
    }
  }
  for (const double e : { 0.0, 1e-9, 0.2, 0.5, 0.77, 1.0 })
  {
    EXPECT_NEAR(lct::easeSegment(lct::inverseEaseSegment(e, 0.4, 0.9), 0.4, 0.9), e, 1e-15);
  }
}

TEST(TimingControls, ConstantSpeedWithKeysOneUlpApartStillWorks)
{
  // Key times at neighbouring doubles leave no room for samples between them.
  vtkNew<vtkTransformInterpolatorLCT> path;
  const double t1 = std::nextafter(1.0, 2.0), t2 = std::nextafter(t1, 2.0);
  addTranslations(path, { 0.0, 1.0, t1, t2, 2.0 }, { 0.0, 1.0, 1.5, 2.0, 3.0 });
  path->SetInterpolationTypeToLinear();
  path->ConstantSpeedOn();
  vtkNew<lct_test::ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
  EXPECT_EQ(errors->Count, 0);
  for (int k = 1; k < 5; ++k)
  {
    EXPECT_GE(arrivals->GetValue(k), arrivals->GetValue(k - 1));
  }
  // The jumps between the ulp-apart keys take their share of the time by length.
  EXPECT_NEAR(arrivals->GetValue(1), 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(arrivals->GetValue(3), 2.0 * 2.0 / 3.0, 1e-9);
  EXPECT_NEAR(xAt(path, 1.0), 1.5, 1e-9);
}

TEST(TimingControls, ConstantSpeedOfAPointThatOverflowsNamesTheCause)
{
  // FuzzTransformInterpolator: a measured point near 1e308 that the keys move out of range.
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<lct_test::ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  addTranslations(path, { 0, 1 }, { 0, 1 });
  vtkNew<vtkTransform> turned;
  turned->RotateZ(90);
  turned->Scale(4, 4, 4);
  ASSERT_EQ(path->AddTransform(2.0, turned), 1);
  path->ConstantSpeedOn();
  ASSERT_EQ(path->SetConstantSpeedPoint(1e308, 0, 0), 1);
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(path->InterpolateTransform(1.0, m), 0);
  EXPECT_NE(errors->Last.find("the measured point is out of the range of double precision"),
    std::string::npos)
    << errors->Last;
  EXPECT_TRUE(m->IsIdentity());
}

// Audit (session 28): the constant-speed table called a sample interval still below 1e-12 of the
// coordinates' size, so a path of unit steps 1e12 from the origin (or of 1e-4 steps in
// Earth-centred coordinates, 6.4e6) kept its plain timing with status 1. Still is now round-off
// of the coordinates (64 ulps).
TEST(ConstantSpeed, APathFarFromTheOriginMovesEvenly)
{
  for (const double origin : { 0.0, 6.4e6, 1e12 })
  {
    const double unit = origin == 6.4e6 ? 1e-4 : 1.0; // steps well above the coordinates' ulp
    vtkNew<vtkTransformInterpolatorLCT> path;
    path->SetInterpolationTypeToLinear();
    const double times[3] = { 0, 1, 4 };
    const double xy[3][2] = { { 0, 0 }, { 1, 0 }, { 2, 1 } };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkTransform> key;
      key->Translate(origin + unit * xy[k][0], unit * xy[k][1], 0);
      ASSERT_EQ(path->AddTransform(times[k], key), 1);
    }
    path->ConstantSpeedOn();
    vtkNew<vtkDoubleArray> arrivals;
    ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
    // Segments of length 1 and sqrt(2) shared out over 4 time units.
    const double expected = 4.0 / (1.0 + std::sqrt(2.0));
    EXPECT_NEAR(arrivals->GetValue(1), expected, origin == 0.0 ? 1e-9 : 1e-3) << origin;
    vtkNew<vtkMatrix4x4> m;
    ASSERT_EQ(path->InterpolateTransform(0.5, m), 1);
    EXPECT_NEAR((m->GetElement(0, 3) - origin) / unit, 0.5 / expected, 2e-3) << origin;
  }
}

// Audit (session 28): the arc-length solve stopped after 12 Illinois steps and returned the last
// iterate, on either side of the root: between keys 1e-12 apart in time the point moved
// backwards 950 times (by up to 3e-4 of the segment). It now ends on a one-ulp bracket.
TEST(ConstantSpeed, ThePointNeverMovesBackwardsBetweenKeysCloseInTime)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  const double times[4] = { 0, 1, 1 + 1e-12, 2 };
  const double xy[4][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 2, 1 } };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkTransform> key;
    key->Translate(xy[k][0], xy[k][1], 0);
    ASSERT_EQ(path->AddTransform(times[k], key), 1);
  }
  path->ConstantSpeedOn();
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(path->GetKeyArrivalTimes(arrivals), 1);
  const double t1 = arrivals->GetValue(1), t2 = arrivals->GetValue(2);
  ASSERT_LT(t1, t2);
  vtkNew<vtkMatrix4x4> m;
  double previous = -1.0;
  int backwards = 0;
  for (int i = 0; i <= 20000; ++i)
  {
    ASSERT_EQ(path->InterpolateTransform(t1 + (t2 - t1) * i / 20000.0, m), 1);
    const double y = m->GetElement(1, 3);
    backwards += y < previous ? 1 : 0;
    previous = y;
  }
  EXPECT_EQ(backwards, 0);
}
