// Ill-conditioned and extreme-magnitude input: accurate to what double precision allows, or an
// explicit IllConditioned / OutOfRange, never a wrong matrix with status Ok (lct/Conditioning.h).
//
// The oracle for singular values is independent of the code under test: the exact cofactors
// and determinant in __float128 (products of two doubles are exact in its 113-bit mantissa) and
// Eigen's JacobiSVD in long double, so sigma_1, sigma_1 sigma_2 and det A of the *stored* matrix
// are known to ~1e-18 whatever its condition number.
#include "lct/AccurateMinors.h"
#include "lct/Affine.h"
#include "lct/Combination.h"
#include "lct/Conditioning.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarDecomposition.h"
#include "lct/PolarParametrisation.h"
#include "lct/SVD3.h"
#include "lct/Sym3.h"

#include "RandomTransforms.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using lct::Parametrisation;
using lct::Status;

namespace
{
using LongMatrix3 = Eigen::Matrix<long double, 3, 3>;
const Parametrisation kBoth[] = { Parametrisation::Polar, Parametrisation::MatrixLog };

/// Singular values of the stored matrix a (det > 0), each to ~1e-18 relative.
Eigen::Matrix<long double, 3, 1> oracleSingularValues(const Eigen::Matrix3d& a)
{
  using Quad = __float128;
  auto q = [&](int i, int j) { return static_cast<Quad>(a(i, j)); };
  LongMatrix3 cofactors;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
      // The cyclic minor carries the cofactor sign.
      cofactors(i, j) = static_cast<long double>(q(r0, c0) * q(r1, c1) - q(r0, c1) * q(r1, c0));
    }
  }
  Quad det = 0;
  for (int j = 0; j < 3; ++j)
  {
    const Quad minor =
      q(1, (j + 1) % 3) * q(2, (j + 2) % 3) - q(1, (j + 2) % 3) * q(2, (j + 1) % 3);
    det += q(0, j) * minor;
  }
  const Eigen::JacobiSVD<LongMatrix3> svd(a.cast<long double>());
  const Eigen::JacobiSVD<LongMatrix3> compound(cofactors);
  const long double s1 = svd.singularValues()[0];
  const long double s12 = compound.singularValues()[0];
  return Eigen::Matrix<long double, 3, 1>(s1, s12 / s1, static_cast<long double>(det) / s12);
}

/// The stretch eigenvalues exp(eigenvalues of Y) of Polar log coordinates, descending.
Eigen::Vector3d stretchOf(const lct::LogCoords& c)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(
    lct::fromSymmetricVector(lct::symmetricPart(c)));
  return solver.eigenvalues().reverse().array().exp();
}

Eigen::Matrix4d affine(const Eigen::Matrix3d& linear)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  return m;
}
} // namespace

TEST(Conditioning, AccurateMinors)
{
  // Exactly representable cancellation: det = 1 from terms of 1e16.
  Eigen::Matrix3d a;
  a << 1e8, 1e8 + 1, 0, 1e8 - 1, 1e8, 0, 0, 0, 1;
  EXPECT_EQ(lct::accurateDeterminant(a), 1.0);
  EXPECT_EQ(lct::accurateDeterminant2(1e8, 1e8 + 1, 1e8 - 1, 1e8), 1.0);
  EXPECT_EQ(lct::accurateCofactors(a)(2, 2), 1.0);
  lct_test::RandomTransforms random(11);
  for (int k = 0; k < 2000; ++k)
  {
    const Eigen::Matrix3d m = random.Linear(lct_test::TransformClass::GeneralAffine);
    const long double exact = oracleSingularValues(m).prod();
    EXPECT_NEAR(lct::accurateDeterminant(m) / exact, 1.0, 4e-16);
  }
}

TEST(Conditioning, DiagonalStretchesAreExactInBothParametrisations)
{
  // The case: Scale(1e-6, 1, 1e6) came back as diag(3.2e-6, 1.0000256, 1e6), status Ok.
  for (const Eigen::Vector3d& d : { Eigen::Vector3d(1e-6, 1, 1e6), Eigen::Vector3d(1e6, 1e-6, 1),
         Eigen::Vector3d(3e-5, 2e-5, 4e7), Eigen::Vector3d(1e-12, 1, 1) })
  {
    const Eigen::Matrix4d m = affine(d.asDiagonal());
    for (Parametrisation p : kBoth)
    {
      const auto log = lct::logarithm(m, p);
      ASSERT_TRUE(log.ok()) << lct::name(p) << " " << d.transpose();
      const auto back = lct::exponential(log.value, p);
      ASSERT_TRUE(back.ok());
      for (int i = 0; i < 3; ++i)
      {
        EXPECT_NEAR(back.value(i, i) / d[i], 1.0, 1e-14) << lct::name(p) << " " << d.transpose();
      }
      EXPECT_LE((back.value - m).cwiseAbs().maxCoeff(), 1e-14 * d.maxCoeff());
    }
  }
}

TEST(Conditioning, RotatedStretchesUpToTheLimit)
{
  // U diag(sigma) V with sigma_1 / sigma_3 = 10^k: the Polar log keeps every singular value to
  // relative accuracy (their products come from exact minors), the round trip is backward
  // stable, and beyond kMaxConditionNumber the input is refused. Before: cond 1e8 gave det
  // errors of 2e-3, 1e12 a factor 168.
  lct_test::RandomTransforms random(12);
  for (int k = 0; k <= 16; ++k)
  {
    const double cond = std::pow(10.0, k);
    double worstSigma = 0.0, worstRoundTrip = 0.0;
    int refused = 0;
    for (int n = 0; n < 300; ++n)
    {
      const Eigen::Vector3d s(
        std::sqrt(cond), std::pow(cond, random.Uniform(-0.5, 0.5)), 1.0 / std::sqrt(cond));
      const Eigen::Matrix3d a = random.Rotation() * s.asDiagonal() * random.Rotation();
      const auto oracle = oracleSingularValues(a);
      const long double trueCondition = oracle[0] / oracle[2];
      const auto log = lct::logarithm(affine(a), Parametrisation::Polar);
      if (!log)
      {
        EXPECT_EQ(log.status, Status::IllConditioned);
        EXPECT_GT(trueCondition, 0.99 * lct::kMaxConditionNumber);
        ++refused;
        continue;
      }
      EXPECT_LT(trueCondition, 1.01 * lct::kMaxConditionNumber);
      const Eigen::Vector3d sigma = stretchOf(log.value);
      for (int i = 0; i < 3; ++i)
      {
        worstSigma = std::max(worstSigma, static_cast<double>(std::abs(sigma[i] / oracle[i] - 1)));
      }
      const auto back = lct::exponential(log.value, Parametrisation::Polar);
      ASSERT_TRUE(back.ok());
      worstRoundTrip =
        std::max(worstRoundTrip, (back.value.topLeftCorner<3, 3>() - a).norm() / a.norm());
    }
    EXPECT_LT(worstSigma, 1e-13) << "cond 1e" << k;
    EXPECT_LT(worstRoundTrip, 1e-13) << "cond 1e" << k;
    if (k <= 12)
    {
      EXPECT_EQ(refused, 0) << "cond 1e" << k;
    }
    if (k >= 14)
    {
      EXPECT_EQ(refused, 300) << "cond 1e" << k;
    }
  }
}

TEST(Conditioning, MatrixLogIsAccurateOrRefused)
{
  // Turns up to 115 degrees (no negative eigenvalues) with a non-normal ill-conditioned stretch.
  lct_test::RandomTransforms random(13);
  for (int k = 0; k <= 14; k += 2)
  {
    const double cond = std::pow(10.0, k);
    for (int n = 0; n < 200; ++n)
    {
      const Eigen::Vector3d s(
        std::sqrt(cond), std::pow(cond, random.Uniform(-0.5, 0.5)), 1.0 / std::sqrt(cond));
      const Eigen::Matrix3d a = random.Rotation(random.Uniform(0, 2.0)) * s.asDiagonal() *
        random.Rotation(random.Uniform(0, 0.3));
      Eigen::Matrix4d m = affine(a);
      m.topRightCorner<3, 1>() = Eigen::Vector3d(random.Normal(), random.Normal(), random.Normal());
      const auto log = lct::matrixLog(m);
      if (!log)
      {
        EXPECT_TRUE(log.status == Status::IllConditioned || log.status == Status::NoRealLogarithm)
          << lct::describe(log.status);
        continue;
      }
      const auto back = lct::matrixExp(log.value);
      ASSERT_TRUE(back.ok()) << lct::describe(back.status);
      // Measured: 2e-13 at cond 1e2, 2e-11 at 1e8, 2e-10 at 1e12 (a non-normal log).
      EXPECT_LT((back.value - m).norm() / m.norm(), 1e-14 * std::sqrt(cond) + 5e-13)
        << "cond 1e" << k;
    }
  }
}

TEST(Conditioning, ExtremeMagnitudesOfWellConditionedMaps)
{
  // Uniform scales 1e102 .. 1e-300 (whose inverse 1e300 is representable): as accurate as I.
  lct_test::RandomTransforms random(14);
  for (double scale : { 1e102, 1e200, 1e300, std::exp(-300.0), 1e-200, 1e-300 })
  {
    const Eigen::Matrix3d r = random.Rotation();
    const Eigen::Matrix4d m = affine(scale * r);
    const auto log = lct::logarithm(m, Parametrisation::Polar);
    ASSERT_TRUE(log.ok()) << scale << ": " << lct::describe(log.status);
    const double logScale = std::log(scale);
    const lct::SymmetricVector y = lct::symmetricPart(log.value);
    for (int i = 0; i < 3; ++i)
    {
      EXPECT_NEAR(y[i], logScale, 1e-12 * std::abs(logScale)) << scale;
      EXPECT_NEAR(y[i + 3], 0.0, 1e-12) << scale;
    }
    const auto back = lct::exponential(log.value, Parametrisation::Polar);
    ASSERT_TRUE(back.ok()) << scale;
    EXPECT_LT((back.value.topLeftCorner<3, 3>() / scale - r).norm(), 1e-12) << scale;
  }
  // Subnormal stretches have lost their digits: refused both ways, like exp's underflow.
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::logarithm(affine(4e-320 * Eigen::Matrix3d::Identity()), p).status,
      p == Parametrisation::Polar ? Status::OutOfRange : Status::MagnitudeOutOfRange);
  }
  // MatrixLog: within its documented range 1e-135 .. 1e135, and refused with that reason
  // beyond it.
  for (double scale : { 1e102, std::exp(-300.0) })
  {
    const Eigen::Matrix4d m = affine(scale * random.Rotation(1.0));
    const auto log = lct::matrixLog(m);
    ASSERT_TRUE(log.ok()) << scale << ": " << lct::describe(log.status);
    const auto back = lct::matrixExp(log.value);
    ASSERT_TRUE(back.ok());
    // The log's entries are ~log(scale): their round-off is eps |log scale|.
    EXPECT_LT((back.value.topLeftCorner<3, 3>() - m.topLeftCorner<3, 3>()).norm() / scale,
      4e-15 * std::abs(std::log(scale)));
  }
  for (double scale : { 1e200, 1e-200 })
  {
    EXPECT_EQ(lct::matrixLog(affine(scale * Eigen::Matrix3d::Identity())).status,
      Status::MagnitudeOutOfRange);
  }
}

TEST(Conditioning, InterpolationBetweenIllConditionedKeys)
{
  // The 2-key case: K0 = diag(1e-6, 1, 1e6), K1 = Rz(10 deg) K0: the same stretch,
  // turned. The step in world axes, K1 K0^-1 = Rz(10 deg), is a plain turn, so halfway is
  // Rz(5 deg) K0 (entry (1, 1) cos 5 deg). The step in K0's frame, K0^-1 K1, has condition ~3e10
  // and its polar stretch turned by its rotation: that relative form gave 294.7 there (the
  // cubic formula once -179.9), an in-between 295 times taller than either key.
  Eigen::Matrix4d keys[2];
  keys[0] = affine(Eigen::Vector3d(1e-6, 1, 1e6).asDiagonal());
  keys[1] = keys[0];
  const auto turn = [](double degrees) {
    return Eigen::AngleAxisd(degrees * lct_test::kPi / 180.0, Eigen::Vector3d::UnitZ())
      .toRotationMatrix();
  };
  keys[1].topLeftCorner<3, 3>() = turn(10.0) * keys[0].topLeftCorner<3, 3>();
  const Eigen::Matrix3d expected = turn(5.0) * keys[0].topLeftCorner<3, 3>();
  const double w[2] = { 0.5, 0.5 };
  for (const std::size_t reference : { 0, 1 })
  {
    const auto half = lct::combineRelative(w, keys, 2, reference, Parametrisation::Polar);
    ASSERT_TRUE(half.ok()) << lct::describe(half.status);
    const Eigen::Matrix3d got = half.value.topLeftCorner<3, 3>();
    // Entrywise relative to each column's size (the columns are 1e-6, 1 and 1e6 long).
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_LT((got.col(c) - expected.col(c)).norm() / expected.col(c).norm(), 1e-13)
        << reference << " " << c;
    }
    EXPECT_NEAR(got(1, 1), std::cos(5.0 * lct_test::kPi / 180.0), 1e-14) << reference;
  }
  // And between keys of different stretch along turned axes, nothing in between is larger than
  // the keys: a key squashed to 1e-3 along x and one turned 90 degrees about z, unsquashed.
  keys[0] = affine(Eigen::Vector3d(1e-3, 1, 1).asDiagonal());
  keys[1] = affine(turn(90.0));
  for (int s = 1; s < 20; ++s)
  {
    const double v[2] = { 1.0 - s / 20.0, s / 20.0 };
    const auto m = lct::combineRelative(v, keys, 2, s < 10 ? 0 : 1, Parametrisation::Polar);
    ASSERT_TRUE(m.ok());
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(m.value.topLeftCorner<3, 3>());
    EXPECT_LE(svd.singularValues()[0], 1.0 + 1e-12) << s;
  }
}

TEST(Conditioning, SymmetricFunctionsOfSpreadSpectra)
{
  // exp, log and sqrt of sym(3) / SPD(3) with condition 1e3 .. 1e12: from eigenvectors, so
  // diagonal input is exact and rotated input is backward stable.
  const Eigen::Matrix3d d = Eigen::Vector3d(1e-6, 1, 1e6).asDiagonal();
  const auto log = lct::logSPD(d);
  ASSERT_TRUE(log.ok());
  EXPECT_NEAR(log.value(0, 0), std::log(1e-6), 1e-14);
  EXPECT_NEAR(log.value(2, 2), std::log(1e6), 1e-14);
  EXPECT_NEAR(lct::expSym(log.value)(0, 0) / 1e-6, 1.0, 1e-14);
  const auto root = lct::sqrtSPD(d);
  ASSERT_TRUE(root.ok());
  EXPECT_NEAR(root.value(0, 0) / 1e-3, 1.0, 1e-15);
  EXPECT_EQ(lct::logSPD(Eigen::Vector3d(1e-14, 1, 1).asDiagonal().toDenseMatrix()).status,
    Status::IllConditioned);
  EXPECT_EQ(lct::logSPD(Eigen::Vector3d(1e300, 1e300, 1e300).asDiagonal().toDenseMatrix()).status,
    Status::Ok);
  lct_test::RandomTransforms random(15);
  for (int n = 0; n < 500; ++n)
  {
    const double spread = random.Uniform(3.0, 27.0); // cond e^3 .. e^27 ~ 5e11
    const Eigen::Vector3d mu(0.5 * spread, random.Uniform(-0.5, 0.5) * spread, -0.5 * spread);
    const Eigen::Matrix3d r = random.Rotation();
    const Eigen::Matrix3d y = r * mu.asDiagonal() * r.transpose();
    const Eigen::Matrix3d e = lct::expSym(y);
    const Eigen::Matrix3d expected = r * mu.array().exp().matrix().asDiagonal() * r.transpose();
    EXPECT_LT((e - expected).norm() / expected.norm(), 1e-13);
  }
}

// Defects the fuzz targets found (Testing/Fuzz/README.md, the D ids), each at its regression input.

TEST(FuzzFindings, D20MatrixExpUnderflowingToSingularIsOutOfRange)
{
  // exp(L) is never singular; for this L (|entries| ~ 710) the computed exp's smallest singular
  // value rounds to 0. matrixExp reported Singular, which its header does not promise and whose
  // message ("a zero scale ... start from a tiny positive scale") misleads: it is an underflow.
  lct::LogCoords c;
  c << 710, 710, 710, 710, 710, 0.7803921568627451, 709, 0.78039215686274566, 0.7803921567763431,
    0.066433416628370101, 0.7803921568627451, 0.7793393004174326;
  const auto e = lct::matrixExp(c);
  ASSERT_FALSE(e.ok());
  EXPECT_EQ(e.status, Status::OutOfRange) << lct::describe(e.status);
}

TEST(FuzzFindings, D21MatrixExpOfHugeCoordinatesIsOutOfRange)
{
  // Eigen's RealSchur did not converge on entries near DBL_MAX (its norms overflow): matrixExp
  // reported NumericalFailure, "a defect of vtkLCT", for finite coordinates whose exp simply
  // overflows (or is a rotation by an angle with no digits left).
  for (const double x : { std::numeric_limits<double>::max(), 1e300, 1e200 })
  {
    const auto e = lct::matrixExp(lct::LogCoords::Constant(x));
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.status, Status::OutOfRange) << x << ": " << lct::describe(e.status);
  }
  // A huge skew part alone: a rotation whose angle has no digits left.
  lct::LogCoords spin = lct::LogCoords::Zero();
  lct::rotationPart(spin) = Eigen::Vector3d(1e300, 0, 0);
  EXPECT_EQ(lct::matrixExp(spin).status, Status::OutOfRange);
}

TEST(FuzzFindings, D22SymmetricEigenvaluesNearADoubleRootToEpsNorm)
{
  // The polar stretch of 0.9 I - 0.1 (J - I) + 8.6e-9 e_xx has eigenvalues 1 + 5.7e-9, 1, 0.7;
  // acos near r = 1 gave them to sqrt(eps) (1 + 5.0e-9, 1 + 7.6e-10), not to eps ||A|| as
  // lct/Eigenvalues3.h says. Checked against Eigen's solver at double roots split by 1e-k.
  for (int k = 0; k <= 16; ++k)
  {
    for (const double sign : { 1.0, -1.0 })
    {
      const Eigen::Matrix3d r =
        Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
      const Eigen::Vector3d d(1.0 + sign * 0.3, 1.0 + std::pow(10.0, -k), 1.0);
      const Eigen::Matrix3d a = r * d.asDiagonal() * r.transpose();
      const Eigen::Vector3d l = lct::symmetricEigenvalues(a);
      const Eigen::Vector3d expected =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(a).eigenvalues().reverse();
      EXPECT_LT((l - expected).cwiseAbs().maxCoeff(), 1e-14)
        << "split 1e-" << k << ", sign " << sign;
    }
  }
  // The triple root stays exact, and the ordering is kept.
  EXPECT_EQ(lct::symmetricEigenvalues(2.0 * Eigen::Matrix3d::Identity()), Eigen::Vector3d(2, 2, 2));
  const Eigen::Vector3d l = lct::symmetricEigenvalues(Eigen::Vector3d(2, 1, 1).asDiagonal());
  EXPECT_LT((l - Eigen::Vector3d(2, 1, 1)).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(FuzzFindings, D23GeneralEigenvaluesWithOneHugeEntry)
{
  // One entry 2e243 among entries of order 1: at unit size p ~ 1e-244 and q underflows, and the
  // three-real-roots branch formed r = 0 / (p m) with p m underflowing: NaN eigenvalues. The cubic
  // is now solved at the scale of its roots (here ~1e121).
  Eigen::Matrix3d a;
  a << 0.95065230504496867, 1.9679776426950188e+243, 0.5, 0.59631819117302964, 0.99998475031689837,
    -7.8039215686274508, -7.8039215686274508, -9.9999998693560563, 0;
  for (const double sign : { 1.0, -1.0 })
  {
    Eigen::Matrix3d m = a;
    m(1, 0) *= sign; // a real pair and a complex pair
    const lct::GeneralEigenvalues e = lct::generalEigenvalues(m);
    // Eigen's EigenSolver does not balance and is no reference here; the invariants are: the
    // trace, and the sum of the principal 2x2 minors (exact in long double for these entries),
    // both to eps times the roots' size (~3.4e121).
    const long double c1 = (long double)m(0, 0) * m(1, 1) - (long double)m(0, 1) * m(1, 0) +
      (long double)m(0, 0) * m(2, 2) - (long double)m(0, 2) * m(2, 0) +
      (long double)m(1, 1) * m(2, 2) - (long double)m(1, 2) * m(2, 1);
    const double size = std::sqrt(std::abs(static_cast<double>(c1)));
    std::complex<double> sum = 0.0, pairs = 0.0;
    for (int i = 0; i < 3; ++i)
    {
      ASSERT_TRUE(std::isfinite(e.values[i].real()) && std::isfinite(e.values[i].imag()));
      sum += e.values[i];
      pairs += e.values[i] * e.values[(i + 1) % 3];
    }
    EXPECT_LT(std::abs(sum - m.trace()), 1e-14 * size) << "sign " << sign;
    EXPECT_LT(std::abs(pairs - static_cast<double>(c1)), 1e-14 * size * size) << "sign " << sign;
    EXPECT_EQ(e.complexPair, sign < 0.0);
  }
}

TEST(FuzzFindings, D27PolarLogAndExpAgreeAtTheSmallestNormalStretch)
{
  // Singular values 2^-1022 (1 - 1.1e-16): polarLog compared log(sigma_min) with log(DBL_MIN),
  // where the ulp of 708 hid the difference, and accepted the map; polarExp then refused its own
  // log as OutOfRange. Now the subnormal stretch is refused by the log, and a stretch of exactly
  // DBL_MIN round-trips.
  Eigen::Matrix3d a;
  a << -2.2250717129565946e-308, 7.7040197059094641e-315, 3.0899857501685743e-311,
    7.1811043516060584e-315, -2.2250736003369703e-308, 1.071865234863786e-311,
    3.0899857627632957e-311, 1.0718651985549017e-311, 2.225071454786365e-308;
  Eigen::Matrix4d m = affine(a);
  m.topRightCorner<3, 1>() = Eigen::Vector3d(-2.8483943054992686e+18, 2, 2);
  EXPECT_EQ(lct::polarLog(m).status, Status::OutOfRange);
  const Eigen::Matrix4d smallest = affine(std::numeric_limits<double>::min() *
    Eigen::Matrix3d(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ())));
  const auto log = lct::polarLog(smallest);
  ASSERT_TRUE(log.ok()) << lct::describe(log.status);
  const auto back = lct::polarExp(log.value);
  ASSERT_TRUE(back.ok()) << lct::describe(back.status);
  EXPECT_LT(
    (back.value - smallest).cwiseAbs().maxCoeff(), 1e-12 * std::numeric_limits<double>::min());
}
