// sym(3) / SPD(3): eigenvalues by the cubic formula, exp, log and sqrt as quadratic
// polynomials (Kaji & Ochiai eq. 6-7), against Eigen's iterative eigensolver and
// MatrixFunctions; near-coincident eigenvalues get their own sweep.
#include "lct/Eigenvalues3.h"
#include "lct/Sym3.h"

#include "RandomTransforms.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <cstdio>
#include <limits>

namespace
{
/// Q diag(l) Q^T with a random rotation Q.
Eigen::Matrix3d symmetricWithEigenvalues(
  lct_test::RandomTransforms& random, const Eigen::Vector3d& l)
{
  const Eigen::Matrix3d q = random.Rotation();
  Eigen::Matrix3d m = q * l.asDiagonal() * q.transpose();
  return 0.5 * (m + m.transpose()).eval();
}

/// Eigenvalue sets: generic, two coinciding to 10^-k, all three coinciding to 10^-k.
Eigen::Vector3d eigenvalueSet(lct_test::RandomTransforms& random, int i, double spread)
{
  const double base = random.Uniform(-spread, spread);
  const double gap = std::pow(10.0, -random.Uniform(0.0, 16.0));
  switch (i % 4)
  {
    case 0:
      return Eigen::Vector3d(
        base, base + gap * random.Uniform(-1, 1), random.Uniform(-spread, spread));
    case 1:
      return Eigen::Vector3d(
        base, base + gap * random.Uniform(-1, 1), base + gap * random.Uniform(-1, 1));
    case 2:
      return Eigen::Vector3d(base, base, base);
    default:
      return Eigen::Vector3d(random.Uniform(-spread, spread), random.Uniform(-spread, spread),
        random.Uniform(-spread, spread));
  }
}
} // namespace

TEST(Sym3, EigenvaluesMatchIterativeSolver)
{
  // Every eigenvalue to ~eps ||Y||, near-double roots of the cubic included (there the
  // isolated root and its eigenvector reduce the pair to a 2x2 problem).
  lct_test::RandomTransforms random(21);
  double worstSeparated = 0.0;
  double worstClustered = 0.0;
  double worstTrace = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    const Eigen::Matrix3d y = symmetricWithEigenvalues(random, eigenvalueSet(random, i, 5.0));
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> oracle(y, Eigen::EigenvaluesOnly);
    const Eigen::Vector3d ours = lct::symmetricEigenvalues(y);
    const Eigen::Vector3d expected = oracle.eigenvalues().reverse();
    ASSERT_GE(ours[0], ours[1]);
    ASSERT_GE(ours[1], ours[2]);
    const double scale = std::max(1.0, y.norm());
    worstTrace = std::max(worstTrace, std::abs(ours.sum() - y.trace()) / scale);
    for (int k = 0; k < 3; ++k)
    {
      double gap = std::numeric_limits<double>::infinity();
      for (int j = 0; j < 3; ++j)
      {
        if (j != k)
        {
          gap = std::min(gap, std::abs(expected[k] - expected[j]));
        }
      }
      double& worst = gap > 1e-2 * scale ? worstSeparated : worstClustered;
      worst = std::max(worst, std::abs(ours[k] - expected[k]) / scale);
    }
  }
  EXPECT_LT(worstSeparated, 1e-14);
  EXPECT_LT(worstClustered, 1e-14);
  EXPECT_LT(worstTrace, 1e-14);
}

namespace
{
/// f(Y) in long double by Eigen's iterative eigensolver: a reference ~1000x more accurate than
/// any double-precision method, so errors are ours, not the oracle's.
Eigen::Matrix3d reference(long double (*f)(long double), const Eigen::Matrix3d& y)
{
  using Matrix3l = Eigen::Matrix<long double, 3, 3>;
  Eigen::SelfAdjointEigenSolver<Matrix3l> es(y.cast<long double>());
  Eigen::Matrix<long double, 3, 1> l = es.eigenvalues();
  for (int i = 0; i < 3; ++i)
  {
    l[i] = f(l[i]);
  }
  return (es.eigenvectors() * l.asDiagonal() * es.eigenvectors().transpose()).cast<double>();
}
long double expl_(long double x)
{
  return std::exp(x);
}
long double logl_(long double x)
{
  return std::log(x);
}
long double sqrtl_(long double x)
{
  return std::sqrt(x);
}

struct Errors
{
  double ours = 0.0;
  double eigen = 0.0;
};

/// Worst relative errors of ours and of Eigen's MatrixFunctions against the long double
/// reference, for symmetric matrices with eigenvalues in [-spread, spread] (exp) or
/// exp([-spread, spread]) (log, sqrt), a quarter of them with near-coincident eigenvalues.
void sweep(double spread, Errors& exp, Errors& log, Errors& sqrt, int seed)
{
  lct_test::RandomTransforms random(seed);
  for (int i = 0; i < 100000; ++i)
  {
    const Eigen::Vector3d l = eigenvalueSet(random, i, spread);
    const Eigen::Matrix3d y = symmetricWithEigenvalues(random, l);
    Eigen::Matrix3d r = reference(expl_, y);
    exp.ours = std::max(exp.ours, (lct::expSym(y) - r).norm() / r.norm());
    exp.eigen = std::max(exp.eigen, (Eigen::Matrix3d(y.exp()) - r).norm() / r.norm());

    const Eigen::Matrix3d s = symmetricWithEigenvalues(random, l.array().exp());
    const auto ourLog = lct::logSPD(s);
    const auto ourSqrt = lct::sqrtSPD(s);
    ASSERT_TRUE(ourLog.ok() && ourSqrt.ok());
    r = reference(logl_, s);
    const double logScale = std::max(1.0, r.norm());
    log.ours = std::max(log.ours, (ourLog.value - r).norm() / logScale);
    log.eigen = std::max(log.eigen, (Eigen::Matrix3d(s.log()) - r).norm() / logScale);
    r = reference(sqrtl_, s);
    sqrt.ours = std::max(sqrt.ours, (ourSqrt.value - r).norm() / r.norm());
    sqrt.eigen = std::max(sqrt.eigen, (Eigen::Matrix3d(s.sqrt()) - r).norm() / r.norm());
  }
}
} // namespace

TEST(Sym3, FunctionsReachFullAccuracyForStretchesUpToCondition20)
{
  // Stretches with singular values in [0.22, 4.5] (the scales of everyday transforms).
  Errors exp, log, sqrt;
  sweep(1.5, exp, log, sqrt, 22);
  RecordProperty("exp", std::to_string(exp.ours));
  RecordProperty("log", std::to_string(log.ours));
  RecordProperty("sqrt", std::to_string(sqrt.ours));
  EXPECT_LT(exp.ours, 1e-14);
  EXPECT_LT(log.ours, 1e-14);
  EXPECT_LT(sqrt.ours, 1e-14);
  // ... and no worse than Eigen's MatrixFunctions on the same inputs.
  EXPECT_LT(exp.ours, 2.0 * exp.eigen);
  EXPECT_LT(log.ours, 2.0 * log.eigen);
  EXPECT_LT(sqrt.ours, 2.0 * sqrt.eigen);
}

TEST(Sym3, FunctionsOnWideStretchesStayWithinTheConditionBound)
{
  // Condition numbers up to e^6 ~ 400. The Newton form on the cubic formula's eigenvalues would
  // lose ~ eps cond(S)^2 in log S (measured 7e-13 when it served every condition); beyond
  // condition 32 the eigenvectors come from the Jacobi solver instead (lct/SymmetricEigen3.h):
  // measured 1.2e-14, Eigen's Schur-based log 1.6e-14. exp has no such loss.
  Errors exp, log, sqrt;
  sweep(3.0, exp, log, sqrt, 23);
  std::printf(
    "  exp %.2e, log %.2e (Eigen %.2e), sqrt %.2e\n", exp.ours, log.ours, log.eigen, sqrt.ours);
  EXPECT_LT(exp.ours, 1e-14);
  EXPECT_LT(log.ours, 4e-14);
  EXPECT_LT(sqrt.ours, 400 * 4 * std::numeric_limits<double>::epsilon());
}

TEST(Sym3, ExpSeriesBranchMatchesTheClosedFormAcrossItsRadius)
{
  // expSym sums a Cayley-Hamilton series when the traceless part has ||Z||_F <= 1 and solves
  // the cubic above that. Both sides of the switch, and the switch itself, against the long
  // double reference: traceless norms log-uniform in [1e-12, 0.5] and uniform in [0.9, 1.1],
  // with a trace shift, near-coincident eigenvalues included.
  lct_test::RandomTransforms random(26);
  double worstInside = 0.0;
  double worstOutside = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    Eigen::Vector3d l = eigenvalueSet(random, i, 1.0);
    l.array() -= l.mean();
    const double norm = l.norm();
    const double target = i % 2 == 0 ? random.LogUniform(1e-12, 0.5) : random.Uniform(0.9, 1.1);
    if (norm > 0.0)
    {
      l *= target / norm;
    }
    l.array() += random.Uniform(-2.0, 2.0);
    const Eigen::Matrix3d y = symmetricWithEigenvalues(random, l);
    const Eigen::Matrix3d r = reference(expl_, y);
    const double error = (lct::expSym(y) - r).norm() / r.norm();
    Eigen::Matrix3d z = y;
    z.diagonal().array() -= y.trace() / 3.0;
    double& worst = z.norm() <= 1.0 ? worstInside : worstOutside;
    worst = std::max(worst, error);
  }
  // Measured: 8e-16 inside, 4e-16 outside.
  RecordProperty("inside", (testing::Message() << worstInside).GetString());
  RecordProperty("outside", (testing::Message() << worstOutside).GetString());
  EXPECT_LT(worstInside, 2e-15);
  EXPECT_LT(worstOutside, 1e-14);
  // A multiple of I is exact: the series is not entered with rounding.
  EXPECT_EQ(lct::expSym(Eigen::Matrix3d::Zero()), Eigen::Matrix3d::Identity());
  EXPECT_EQ(lct::expSym(0.7 * Eigen::Matrix3d::Identity()),
    (std::exp(0.7) * Eigen::Matrix3d::Identity()).eval());
}

TEST(Sym3, ExpSquaredSeriesMatchesTheReferenceUpToItsRadius)
{
  // For 1 < ||Z||_F <= 4 the series is summed for Z 2^-s and squared s <= 3 times on its three
  // scalars. Against the long double reference, with Eigen's MatrixFunctions on the same
  // matrices beside it, near-coincident eigenvalues included; and just beyond the radius, where
  // the closed form takes over. Near the end of exp's range (Y + 700 I) the closed form gives the
  // eigenvalue bounds instead: exact there, where callers compare them with log(DBL_MIN).
  lct_test::RandomTransforms random(27);
  double worstSquared = 0.0, worstEigen = 0.0, worstBeyond = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    Eigen::Vector3d l = eigenvalueSet(random, i, 3.0);
    l.array() -= l.mean();
    const double norm = l.norm();
    const bool beyond = i % 10 == 0;
    if (norm > 0.0)
    {
      l *= (beyond ? random.Uniform(4.0, 4.5) : random.Uniform(1.0, 4.0)) / norm;
    }
    l.array() += random.Uniform(-2.0, 2.0);
    const Eigen::Matrix3d y = symmetricWithEigenvalues(random, l);
    const Eigen::Matrix3d r = reference(expl_, y);
    Eigen::Vector2d bounds;
    const double error = (lct::expSym(y, &bounds) - r).norm() / r.norm();
    if (beyond)
    {
      worstBeyond = std::max(worstBeyond, error);
      continue;
    }
    worstSquared = std::max(worstSquared, error);
    worstEigen = std::max(worstEigen, (Eigen::Matrix3d(y.exp()) - r).norm() / r.norm());
    // Inside the squaring radius the bounds are mean +- sqrt(2/3) ||Z||_F: they hold.
    EXPECT_LE(bounds[0], l.minCoeff() + 1e-14);
    EXPECT_GE(bounds[1], l.maxCoeff() - 1e-14);
    lct::expSym(y + Eigen::Matrix3d::Identity() * -700.0, &bounds);
    EXPECT_NEAR(bounds[0], l.minCoeff() - 700.0, 1e-11) << l.transpose();
  }
  // Measured: 1.0e-15 (Eigen 2.2e-15 on the same matrices), 6.1e-15 beyond the radius.
  std::printf("  squared series %.2e (Eigen %.2e), beyond the radius %.2e\n", worstSquared,
    worstEigen, worstBeyond);
  EXPECT_LT(worstSquared, 3e-15);
  EXPECT_LT(worstSquared, 2.0 * worstEigen);
  EXPECT_LT(worstBeyond, 1e-14);
}

TEST(Sym3, LogOfExpRoundTrip)
{
  lct_test::RandomTransforms random(24);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    const Eigen::Matrix3d y = symmetricWithEigenvalues(random, eigenvalueSet(random, i, 1.5));
    const auto back = lct::logSPD(lct::expSym(y));
    ASSERT_TRUE(back.ok());
    worst = std::max(worst, (back.value - y).norm() / std::max(1.0, y.norm()));
  }
  EXPECT_LT(worst, 1e-14);
}

TEST(Sym3, NearCoincidentEigenvaluesKeepFullAccuracy)
{
  // The naive eq. 7 loses ~6 digits when two eigenvalues agree to ~1e-6 (SEEDS.md).
  lct_test::RandomTransforms random(25);
  double worst = 0.0;
  for (int k = 1; k <= 15; ++k)
  {
    for (int i = 0; i < 200; ++i)
    {
      const double gap = std::pow(10.0, -k);
      const Eigen::Vector3d l(2.0, 2.0 * (1.0 + gap), 0.5 + random.Uniform(0.0, 1.0));
      const Eigen::Matrix3d s = symmetricWithEigenvalues(random, l);
      const auto ours = lct::logSPD(s);
      ASSERT_TRUE(ours.ok());
      worst = std::max(worst, (ours.value - s.log()).norm() / s.log().norm());
    }
  }
  EXPECT_LT(worst, 1e-14);
}

// Two eigenvalues at every relative gap from 1 down to 0, the third well apart: the band of
// gaps 1e-4 .. 1e-1 of the spread (|r| just above the near-double-root threshold) once had
// eigenvalue errors of 1e-9 and exp/log errors of 3e-10, from an approximate isolated root.
TEST(Sym3, EveryGapBetweenTwoEigenvaluesKeepsFullAccuracy)
{
  lct_test::RandomTransforms random(26);
  for (const double gap :
    { 1.0, 0.3, 0.1, 0.03, 0.01, 3e-3, 1e-3, 1e-4, 1e-6, 1e-8, 1e-10, 1e-13, 0.0 })
  {
    double worstEigenvalue = 0.0, worstExp = 0.0, worstLog = 0.0;
    for (int i = 0; i < 2000; ++i)
    {
      const double a = random.Normal(), side = i % 2 ? 1.0 : -1.0;
      const Eigen::Vector3d l(a, a + side * gap, a + side * (0.5 + std::abs(random.Normal())));
      const Eigen::Matrix3d r = random.Rotation();
      Eigen::Matrix3d y = r * l.asDiagonal() * r.transpose();
      y = 0.5 * (y + y.transpose()).eval();
      const Eigen::Vector3d expected =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(y, Eigen::EigenvaluesOnly)
          .eigenvalues()
          .reverse();
      worstEigenvalue = std::max(worstEigenvalue,
        (lct::symmetricEigenvalues(y) - expected).cwiseAbs().maxCoeff() / y.norm());
      const Eigen::Matrix3d e = r * l.array().exp().matrix().asDiagonal() * r.transpose();
      worstExp = std::max(worstExp, (lct::expSym(y) - e).norm() / e.norm());
      const auto log = lct::logSPD(e);
      ASSERT_TRUE(log.ok());
      worstLog = std::max(worstLog, (log.value - y).norm() / std::max(1.0, y.norm()));
    }
    EXPECT_LT(worstEigenvalue, 1e-14) << "gap " << gap;
    EXPECT_LT(worstExp, 3e-14) << "gap " << gap;
    EXPECT_LT(worstLog, 3e-14) << "gap " << gap;
  }
}

TEST(Sym3, SingularOrIndefiniteStretchIsRefused)
{
  EXPECT_EQ(lct::logSPD(Eigen::Vector3d(1.0, 1.0, 0.0).asDiagonal().toDenseMatrix()).status,
    lct::Status::Singular);
  EXPECT_EQ(lct::logSPD(Eigen::Vector3d(1.0, -1.0, 2.0).asDiagonal().toDenseMatrix()).status,
    lct::Status::Singular);
  EXPECT_EQ(lct::sqrtSPD(Eigen::Matrix3d::Constant(std::nan(""))).status, lct::Status::NonFinite);
}
