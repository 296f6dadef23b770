// lct/BSplineFit: the least-squares fit against a dense solve over an independently evaluated
// basis (the Cox-de Boor recursion, written out), polynomial reproduction, the tolerance fit on
// smooth, noisy and discontinuous tracks with per-sample tolerances and a quantising
// adjustment, and the refusals.
#include "lct/BSplineFit.h"

#include <Eigen/QR>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{

/// N_{i,p}(u) by the recursive definition (de Boor), 0/0 = 0; at the right end the last basis
/// function is 1 (the clamped convention).
double basisFunction(const std::vector<double>& u, int i, int p, double x)
{
  if (p == 0)
  {
    const double last = u.back();
    if (x == last)
    {
      // The last non-empty span owns the right end.
      std::size_t k = u.size() - 1;
      while (k > 0 && u[k - 1] == last)
      {
        --k;
      }
      return static_cast<std::size_t>(i) == k - 1 ? 1.0 : 0.0;
    }
    return u[static_cast<std::size_t>(i)] <= x && x < u[static_cast<std::size_t>(i) + 1] ? 1.0 : 0.0;
  }
  double value = 0.0;
  const double left = u[static_cast<std::size_t>(i + p)] - u[static_cast<std::size_t>(i)];
  const double right = u[static_cast<std::size_t>(i + p + 1)] - u[static_cast<std::size_t>(i + 1)];
  if (left > 0.0)
  {
    value += (x - u[static_cast<std::size_t>(i)]) / left * basisFunction(u, i, p - 1, x);
  }
  if (right > 0.0)
  {
    value += (u[static_cast<std::size_t>(i + p + 1)] - x) / right * basisFunction(u, i + 1, p - 1, x);
  }
  return value;
}

Eigen::MatrixXd designMatrix(int samples, int degree, const std::vector<int>& knots)
{
  std::vector<double> u(static_cast<std::size_t>(degree) + 1, 0.0);
  u.insert(u.end(), knots.begin(), knots.end());
  u.insert(u.end(), static_cast<std::size_t>(degree) + 1, samples - 1.0);
  const int count = static_cast<int>(knots.size()) + degree + 1;
  Eigen::MatrixXd a(samples, count);
  for (int f = 0; f < samples; ++f)
  {
    for (int i = 0; i < count; ++i)
    {
      a(f, i) = basisFunction(u, i, degree, f);
    }
  }
  return a;
}

Eigen::MatrixXd smoothTrack(int d, int n, std::mt19937& rng, double noise = 0.0)
{
  std::normal_distribution<double> gauss(0.0, 1.0);
  Eigen::MatrixXd y(d, n);
  for (int i = 0; i < d; ++i)
  {
    const double a = gauss(rng);
    const double b = gauss(rng);
    const double w = 0.01 + 0.05 * std::abs(gauss(rng));
    for (int f = 0; f < n; ++f)
    {
      y(i, f) = a * std::sin(w * f + b) + 0.3 * a * std::cos(3.1 * w * f) + noise * gauss(rng);
    }
  }
  return y;
}

TEST(BSplineFit, LeastSquaresMatchesADenseSolveOverTheRecursiveBasis)
{
  std::mt19937 rng(5);
  for (int degree = 1; degree <= 3; ++degree)
  {
    for (int trial = 0; trial < 10; ++trial)
    {
      const int n = 40 + 17 * trial;
      std::vector<int> knots;
      for (int k = 3 + trial % 4; k < n - 3; k += 5 + (k * 7 + trial) % 6)
      {
        knots.push_back(k);
      }
      const Eigen::MatrixXd y = smoothTrack(3, n, rng, 0.1);
      const lct::Result<lct::BSplineCurve> fit = lct::fitLeastSquares(y, degree, knots);
      ASSERT_TRUE(fit.ok());
      ASSERT_TRUE(lct::isWellFormed(fit.value));
      const Eigen::MatrixXd a = designMatrix(n, degree, knots);
      const Eigen::MatrixXd oracle = a.colPivHouseholderQr().solve(y.transpose()).transpose();
      // The penalty is 1e-10 of the data term: invisible at this precision.
      EXPECT_LT((fit.value.controlPoints - oracle).cwiseAbs().maxCoeff(), 1e-7)
        << "degree " << degree << " trial " << trial;
      EXPECT_LT((lct::evaluateAtSamples(fit.value) - oracle * a.transpose()).cwiseAbs().maxCoeff(),
        1e-7);
    }
  }
}

TEST(BSplineFit, ReproducesPolynomialsOfItsDegree)
{
  const int n = 101;
  for (int degree = 1; degree <= 3; ++degree)
  {
    Eigen::MatrixXd y(1, n);
    for (int f = 0; f < n; ++f)
    {
      const double t = f / 10.0;
      y(0, f) = degree == 1 ? 2.0 * t - 1.0 : degree == 2 ? t * t - t : 0.1 * t * t * t - t;
    }
    const lct::Result<lct::BSplineCurve> fit = lct::fitLeastSquares(y, degree, { 13, 50, 77 });
    ASSERT_TRUE(fit.ok());
    EXPECT_LT((lct::evaluateAtSamples(fit.value) - y).cwiseAbs().maxCoeff(), 1e-8) << degree;
  }
}

TEST(BSplineFit, EveryKnotInterpolatesEvenWhereTheFitIsUnderdetermined)
{
  std::mt19937 rng(9);
  const int n = 30;
  std::vector<int> all;
  for (int k = 1; k < n - 1; ++k)
  {
    all.push_back(k);
  }
  const Eigen::MatrixXd y = smoothTrack(2, n, rng, 0.5);
  for (int degree = 1; degree <= 3; ++degree)
  {
    const lct::Result<lct::BSplineCurve> fit = lct::fitLeastSquares(y, degree, all);
    ASSERT_TRUE(fit.ok());
    EXPECT_LT((lct::evaluateAtSamples(fit.value) - y).cwiseAbs().maxCoeff(), 1e-6) << degree;
  }
}

TEST(BSplineFit, ToleranceFitHoldsOnSmoothNoisyAndJumpingTracks)
{
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> share(0.3, 3.0);
  for (int trial = 0; trial < 24; ++trial)
  {
    const int n = 200 + 50 * (trial % 5);
    Eigen::MatrixXd y = smoothTrack(3, n, rng, trial % 3 == 0 ? 0.02 : 0.0);
    if (trial % 4 == 1)
    {
      y.rightCols(n - n / 3).array() += 5.0; // a jump between two samples
    }
    lct::ToleranceFit options;
    options.tolerance = trial % 2 ? 1e-3 : 0.05;
    if (trial % 3 == 2)
    {
      options.sampleTolerances.resize(n);
      for (int f = 0; f < n; ++f)
      {
        options.sampleTolerances(f) = options.tolerance * share(rng);
      }
    }
    const double quantum = 0.2 * options.tolerance;
    if (trial % 2 == 0)
    {
      options.adjust = [quantum](lct::BSplineCurve& c) {
        c.controlPoints = (c.controlPoints / quantum).array().round().matrix() * quantum;
      };
    }
    const int degree = 1 + trial % 3;
    const lct::Result<lct::BSplineCurve> fit = lct::fitWithinTolerance(y, degree, options);
    ASSERT_TRUE(fit.ok()) << trial;
    ASSERT_TRUE(lct::isWellFormed(fit.value));
    const Eigen::MatrixXd s = lct::evaluateAtSamples(fit.value);
    for (int f = 0; f < n; ++f)
    {
      const double tolerance =
        options.sampleTolerances.size() ? options.sampleTolerances(f) : options.tolerance;
      ASSERT_LE((s.col(f) - y.col(f)).norm(), tolerance) << "trial " << trial << " frame " << f;
    }
    if (options.adjust)
    {
      const Eigen::MatrixXd steps = fit.value.controlPoints / quantum;
      EXPECT_LT((steps - steps.array().round().matrix()).cwiseAbs().maxCoeff(), 1e-6);
    }
    // Far fewer coefficients than samples for a smooth track at a loose tolerance.
    if (trial % 4 != 1 && trial % 3 != 0 && options.tolerance > 0.01)
    {
      EXPECT_LT(fit.value.controlPointCount(), n / 4) << trial;
    }
  }
}

TEST(BSplineFit, ACustomErrorDrivesTheKnots)
{
  // Only the first component counts: the second, however wild, needs no knot.
  std::mt19937 rng(3);
  const int n = 300;
  Eigen::MatrixXd y(2, n);
  for (int f = 0; f < n; ++f)
  {
    y(0, f) = 0.01 * f;
    y(1, f) = std::sin(0.7 * f);
  }
  lct::ToleranceFit options;
  options.tolerance = 1e-6;
  options.error = [&y](int f, const Eigen::VectorXd& v) { return std::abs(v(0) - y(0, f)); };
  const lct::Result<lct::BSplineCurve> fit = lct::fitWithinTolerance(y, 1, options);
  ASSERT_TRUE(fit.ok());
  EXPECT_EQ(fit.value.interiorKnots.size(), 0u);
}

TEST(BSplineFit, BadArgumentsAreRefused)
{
  const Eigen::MatrixXd y = Eigen::MatrixXd::Ones(3, 10);
  EXPECT_EQ(lct::fitLeastSquares(Eigen::MatrixXd(3, 0), 1, {}).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::fitLeastSquares(y, 4, {}).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::fitLeastSquares(y, -1, {}).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::fitLeastSquares(y, 1, { 5, 5 }).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::fitLeastSquares(y, 1, { 0 }).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::fitLeastSquares(y, 1, { 9 }).status, lct::Status::InvalidArgument);
  Eigen::MatrixXd bad = y;
  bad(1, 4) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(lct::fitLeastSquares(bad, 1, {}).status, lct::Status::NonFinite);
  lct::ToleranceFit options;
  for (double t : { 0.0, -1.0, std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::quiet_NaN() })
  {
    options.tolerance = t;
    EXPECT_EQ(lct::fitWithinTolerance(y, 1, options).status, lct::Status::InvalidArgument) << t;
  }
  options.tolerance = 1.0;
  options.sampleTolerances = Eigen::VectorXd::Ones(9);
  EXPECT_EQ(lct::fitWithinTolerance(y, 1, options).status, lct::Status::InvalidArgument);
  options.sampleTolerances = Eigen::VectorXd::Ones(10);
  options.sampleTolerances(3) = 0.0;
  EXPECT_EQ(lct::fitWithinTolerance(y, 1, options).status, lct::Status::InvalidArgument);
  // Short tracks lower the degree instead of failing.
  const lct::Result<lct::BSplineCurve> one = lct::fitLeastSquares(Eigen::MatrixXd::Ones(2, 1), 3, {});
  ASSERT_TRUE(one.ok());
  EXPECT_EQ(one.value.degree, 0);
  const lct::Result<lct::BSplineCurve> two = lct::fitLeastSquares(Eigen::MatrixXd::Ones(2, 2), 3, {});
  ASSERT_TRUE(two.ok());
  EXPECT_EQ(two.value.degree, 1);
}

TEST(BSplineFit, MalformedCurvesAreNamed)
{
  lct::BSplineCurve c;
  c.degree = 1;
  c.samples = 10;
  c.interiorKnots = { 3, 6 };
  c.controlPoints = Eigen::MatrixXd::Zero(3, 4);
  EXPECT_TRUE(lct::isWellFormed(c));
  const char* why = nullptr;
  lct::BSplineCurve bad = c;
  bad.interiorKnots = { 6, 3 };
  EXPECT_FALSE(lct::isWellFormed(bad, &why));
  EXPECT_NE(why, nullptr);
  bad = c;
  bad.controlPoints = Eigen::MatrixXd::Zero(3, 5);
  EXPECT_FALSE(lct::isWellFormed(bad));
  bad = c;
  bad.degree = 4;
  EXPECT_FALSE(lct::isWellFormed(bad));
  bad = c;
  bad.controlPoints(1, 2) = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(lct::isWellFormed(bad));
  bad = c;
  bad.samples = 0;
  EXPECT_FALSE(lct::isWellFormed(bad));
}

} // namespace
