// exp of affine logs [L t; 0 0] by scaling and squaring (lct/AffineExp.h), against Eigen's
// MatrixFunctions in long double (64-bit mantissa), on the logs it accepts: normal and strongly
// non-normal L up to the norm limit (turns up to 5.6 rad and beyond), translations of any size.
#include "lct/AffineExp.h"
#include "lct/Conditioning.h"
#include "lct/LogCoords.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include "RandomTransforms.h"

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <cmath>
#include <cstdio>
#include <limits>

namespace
{
using Matrix4l = Eigen::Matrix<long double, 4, 4>;

/// The classes of L swept; each is scaled to a 1-norm drawn uniformly in (0, limit].
enum class LogClass
{
  Rotation,      ///< skew: turns up to the norm limit
  Symmetric,     ///< stretches, eigenvalues of both signs
  Similarity,    ///< a turn plus a uniform scale
  Gaussian,      ///< entries N(0, 1): generic, mildly non-normal
  Shear,         ///< strictly upper triangular plus a negative diagonal: the "hump" of e^(tL)
  NegativeTrace, ///< most of the norm in -c I: a small determinant, e^-4 per axis
  Hump,          ///< half the norm a negative diagonal, half a shear: ||e^(tL)|| rises, then falls
  Count
};

const char* name(LogClass c)
{
  static const char* names[] = { "Rotation", "Symmetric", "Similarity", "Gaussian", "Shear",
    "NegativeTrace", "Hump" };
  return names[static_cast<int>(c)];
}

Eigen::Matrix3d randomLog(lct_test::RandomTransforms& random, LogClass c)
{
  Eigen::Matrix3d l;
  switch (c)
  {
    case LogClass::Rotation:
      l = lct::hat(random.UnitVector());
      break;
    case LogClass::Symmetric:
      l = Eigen::Matrix3d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return random.Normal(); });
      l = 0.5 * (l + l.transpose()).eval();
      break;
    case LogClass::Similarity:
      l = lct::hat(random.UnitVector()) + random.Uniform(-1.0, 1.0) * Eigen::Matrix3d::Identity();
      break;
    case LogClass::Gaussian:
      l = Eigen::Matrix3d::NullaryExpr([&](Eigen::Index, Eigen::Index) { return random.Normal(); });
      break;
    case LogClass::Shear:
      l << -random.Uniform(0, 0.3), random.Normal() * 3, random.Normal() * 3, 0,
        -random.Uniform(0, 0.3), random.Normal() * 3, 0, 0, -random.Uniform(0, 0.3);
      break;
    case LogClass::Hump:
    {
      const double diagonal = random.Uniform(0.3, 0.7);
      l << -diagonal, (1 - diagonal) * random.Uniform(-1, 1),
        (1 - diagonal) * random.Uniform(-1, 1), 0, -diagonal * random.Uniform(0.5, 1),
        (1 - diagonal) * random.Uniform(-1, 1), 0, 0, -diagonal * random.Uniform(0.5, 1);
      const Eigen::Matrix3d q = random.Rotation(random.Uniform(0.0, lct_test::kPi));
      l = q * l * q.transpose();
      break;
    }
    default:
      l = Eigen::Matrix3d::NullaryExpr(
            [&](Eigen::Index, Eigen::Index) { return 0.05 * random.Normal(); }) -
        Eigen::Matrix3d::Identity();
      break;
  }
  return l;
}

/// exp([L t; 0 0]) in long double, t at unit size.
Matrix4l oracle(const Eigen::Matrix3d& l, const Eigen::Vector3d& unitT)
{
  Matrix4l n = Matrix4l::Zero();
  n.topLeftCorner<3, 3>() = l.cast<long double>();
  n.topRightCorner<3, 1>() = unitT.cast<long double>();
  return n.exp();
}

struct Errors
{
  double linear = 0.0;      ///< ||ours - exact|| / ||exact||, the linear block
  double translation = 0.0; ///< ||ours - exact|| / (||phi1(L)|| ||t||), the translation
};

Errors errors(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation,
  const Eigen::Matrix3d& l, const Eigen::Vector3d& t)
{
  const int k = lct::unitScaleExponent(t);
  const Eigen::Vector3d unitT = lct::scaledByPowerOfTwo(t, -k);
  const Matrix4l exact = oracle(l, unitT);
  // ||phi1(L)||: the translation block of exp([L I; 0 0]) would give it; a bound from the
  // columns of unit translations is enough for a relative error.
  long double phiNorm = 0.0L;
  for (int i = 0; i < 3; ++i)
  {
    phiNorm = std::max(phiNorm, oracle(l, Eigen::Vector3d::Unit(i)).topRightCorner<3, 1>().norm());
  }
  Errors e;
  e.linear = static_cast<double>((linear.cast<long double>() - exact.topLeftCorner<3, 3>()).norm() /
    exact.topLeftCorner<3, 3>().norm());
  const Eigen::Vector3d unitOurs = lct::scaledByPowerOfTwo(translation, -k);
  e.translation = unitT.norm() == 0.0
    ? unitOurs.norm()
    : static_cast<double>((unitOurs.cast<long double>() - exact.topRightCorner<3, 1>()).norm() /
        (phiNorm * unitT.norm()));
  return e;
}
} // namespace

TEST(AffineExp, MatchesLongDoubleOracleOnEveryClassUpToTheNormLimit)
{
  // Measured when the path was added (4000 logs per class, up to the limit 8): at most 4.6e-15
  // (Gaussian), where the Schur form and divided differences it replaced reached 1.2e-14.
  lct_test::RandomTransforms random(77);
  for (int c = 0; c < static_cast<int>(LogClass::Count); ++c)
  {
    Errors worst;
    for (int i = 0; i < 4000; ++i)
    {
      Eigen::Matrix3d l = randomLog(random, static_cast<LogClass>(c));
      const double norm = l.cwiseAbs().colwise().sum().maxCoeff();
      l *= random.Uniform(0.0, lct::kAffineExpNormLimit) / norm;
      const Eigen::Vector3d t = std::pow(10.0, random.Uniform(-300.0, 300.0)) * random.UnitVector();
      Eigen::Matrix3d linear;
      Eigen::Vector3d translation;
      ASSERT_TRUE(lct::affineExpBySquaring(l, t, linear, translation)) << l;
      const Errors e = errors(linear, translation, l, t);
      worst.linear = std::max(worst.linear, e.linear);
      worst.translation = std::max(worst.translation, e.translation);
    }
    std::printf("  %-14s linear %.2e  translation %.2e\n", name(static_cast<LogClass>(c)),
      worst.linear, worst.translation);
    EXPECT_LT(worst.linear, 1e-14) << name(static_cast<LogClass>(c));
    EXPECT_LT(worst.translation, 1e-14) << name(static_cast<LogClass>(c));
  }
}

TEST(AffineExp, AgreesWithTheSchurPathAcrossTheNormLimit)
{
  // matrixExp takes the Schur form and divided differences beyond the limit: a log just inside
  // and its copy a few ulps larger, just outside, must give the same matrix.
  lct_test::RandomTransforms random(78);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i)
  {
    Eigen::Matrix3d l =
      randomLog(random, static_cast<LogClass>(i % static_cast<int>(LogClass::Count)));
    l *= lct::kAffineExpNormLimit / l.cwiseAbs().colwise().sum().maxCoeff();
    const Eigen::Matrix3d outside = l * (1.0 + 0x1p-50);
    Eigen::Matrix3d linear;
    Eigen::Vector3d translation;
    const Eigen::Vector3d t = random.UnitVector();
    if (!lct::affineExpBySquaring(l, t, linear, translation))
    {
      continue; // rounded just above the limit
    }
    ASSERT_FALSE(lct::affineExpBySquaring(outside, t, linear, translation));
    lct::LogCoords inside, beyond;
    const auto coords = [&](const Eigen::Matrix3d& m, lct::LogCoords& c) {
      lct::translationPart(c) = t;
      lct::rotationPart(c) = lct::vee(m);
      lct::symmetricPart(c) = lct::toSymmetricVector(0.5 * (m + m.transpose()));
    };
    coords(l, inside);
    coords(outside, beyond);
    const auto a = lct::matrixExp(inside);
    const auto b = lct::matrixExp(beyond);
    ASSERT_TRUE(a.ok() && b.ok()) << l;
    worst = std::max(worst, lct_test::blockError(a.value, b.value));
  }
  std::printf("  largest difference across the limit: %.2e\n", worst);
  EXPECT_LT(worst, 1e-13);
}

TEST(AffineExp, KeepsExactStructureAndRefusesWhatItDoesNotEvaluate)
{
  Eigen::Matrix3d linear = Eigen::Matrix3d::Constant(7.0);
  Eigen::Vector3d translation = Eigen::Vector3d::Constant(7.0);
  // Translations alone: [I t] exactly, at any size.
  for (double size : { 1e-300, 1.0, 1e300 })
  {
    const Eigen::Vector3d t = size * Eigen::Vector3d(1.0, -2.0, 3.0);
    ASSERT_TRUE(lct::affineExpBySquaring(Eigen::Matrix3d::Zero(), t, linear, translation));
    EXPECT_EQ(linear, Eigen::Matrix3d::Identity());
    EXPECT_EQ(translation, t);
  }
  // No translation: exactly none (linear maps stay linear under blending).
  const Eigen::Matrix3d l =
    2.0 * lct::hat(Eigen::Vector3d(0.3, -0.5, 0.2)) + 0.4 * Eigen::Matrix3d::Identity();
  ASSERT_TRUE(lct::affineExpBySquaring(l, Eigen::Vector3d::Zero(), linear, translation));
  EXPECT_EQ(translation, Eigen::Vector3d::Zero());
  // A turn is a rotation: orthogonal to round-off, at the limit's many squarings too.
  const Eigen::Matrix3d turn = lct::hat(5.6 * Eigen::Vector3d(0.6, 0.0, 0.8));
  ASSERT_TRUE(lct::affineExpBySquaring(turn, Eigen::Vector3d::Zero(), linear, translation));
  EXPECT_LT((linear.transpose() * linear - Eigen::Matrix3d::Identity()).norm(), 1e-14);
  EXPECT_NEAR(linear.determinant(), 1.0, 1e-14);

  // Beyond the limit, or not finite: false, outputs untouched.
  const Eigen::Matrix3d keptLinear = linear;
  const Eigen::Vector3d keptTranslation = translation;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const Eigen::Matrix3d& bad : { Eigen::Matrix3d(9.0 * Eigen::Matrix3d::Identity()),
         Eigen::Matrix3d(Eigen::Matrix3d::Constant(nan)),
         Eigen::Matrix3d(Eigen::Matrix3d::Constant(inf)) })
  {
    EXPECT_FALSE(lct::affineExpBySquaring(bad, Eigen::Vector3d::Zero(), linear, translation));
  }
  EXPECT_FALSE(lct::affineExpBySquaring(
    Eigen::Matrix3d::Zero(), Eigen::Vector3d(0.0, nan, 0.0), linear, translation));
  EXPECT_FALSE(lct::affineExpBySquaring(
    Eigen::Matrix3d::Zero(), Eigen::Vector3d(inf, 0.0, 0.0), linear, translation));
  EXPECT_EQ(linear, keptLinear);
  EXPECT_EQ(translation, keptTranslation);

  // A translation whose image leaves the double range: matrixExp refuses it, no Inf leaves.
  lct::LogCoords c = lct::LogCoords::Zero();
  lct::symmetricPart(c).head<3>().setConstant(2.0); // L = 2 I, phi1(2) = 3.19
  lct::translationPart(c) = Eigen::Vector3d(1e308, 0.0, 0.0);
  EXPECT_EQ(lct::matrixExp(c).status, lct::Status::OutOfRange);
  lct::translationPart(c) = Eigen::Vector3d(1e307, 0.0, 0.0);
  const auto fits = lct::matrixExp(c);
  ASSERT_TRUE(fits.ok());
  EXPECT_NEAR(fits.value(0, 3) / 1e307, (std::exp(2.0) - 1.0) / 2.0, 1e-14);
}
