// Every bad input of the core fails with its own status, never NaN, never an exception.
#include "lct/Combination.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarDecomposition.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using lct::Parametrisation;
using lct::Status;

namespace
{
const Parametrisation kBoth[] = { Parametrisation::Polar, Parametrisation::MatrixLog };

Eigen::Matrix4d diagonal(double x, double y, double z)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = x;
  m(1, 1) = y;
  m(2, 2) = z;
  return m;
}
} // namespace

TEST(BadInput, NonFiniteEntries)
{
  for (Parametrisation p : kBoth)
  {
    for (double bad : { std::nan(""), std::numeric_limits<double>::infinity() })
    {
      for (int entry = 0; entry < 12; ++entry)
      {
        Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
        m(entry / 4, entry % 4) = bad;
        EXPECT_EQ(lct::logarithm(m, p).status, Status::NonFinite);
      }
      lct::LogCoords c = lct::LogCoords::Zero();
      c[7] = bad;
      EXPECT_EQ(lct::exponential(c, p).status, Status::NonFinite);
    }
  }
}

TEST(BadInput, ProjectiveBottomRow)
{
  for (Parametrisation p : kBoth)
  {
    for (int entry = 0; entry < 4; ++entry)
    {
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m(3, entry) += 0.5;
      EXPECT_EQ(lct::logarithm(m, p).status, Status::NotAffine);
    }
  }
}

TEST(BadInput, ReflectionsAndSingularMaps)
{
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::logarithm(diagonal(-1, 1, 1), p).status, Status::NegativeDeterminant);
    EXPECT_EQ(lct::logarithm(diagonal(1, 0, 1), p).status, Status::Singular);
    EXPECT_EQ(lct::logarithm(diagonal(0, 0, 0), p).status, Status::Singular);
    // Positive, but a condition number of 1e300: refused, not computed with no digits left.
    EXPECT_EQ(lct::logarithm(diagonal(1, 1e-300, 1), p).status, Status::IllConditioned);
    EXPECT_EQ(lct::logarithm(diagonal(1, 1e-14, 1), p).status, Status::IllConditioned);
  }
  EXPECT_EQ(lct::polarDecompose(Eigen::Vector3d(1, 1e-300, 1).asDiagonal().toDenseMatrix()).status,
    Status::IllConditioned);
  // A rank-one map with a positive-looking determinant of round-off: singular or refused.
  Eigen::Matrix4d rankOne = Eigen::Matrix4d::Identity();
  rankOne.topLeftCorner<3, 3>() = Eigen::Vector3d(1, 2, 3) * Eigen::RowVector3d(0.1, 0.7, 0.3);
  for (Parametrisation p : kBoth)
  {
    const Status s = lct::logarithm(rankOne, p).status;
    EXPECT_TRUE(s == Status::Singular || s == Status::IllConditioned) << lct::describe(s);
  }
}

TEST(BadInput, NoRealLogarithmInMatrixLogButPolarWorks)
{
  // A half turn about z with non-uniform scale: eigenvalues -2, -1, 1 (Alexa App. A).
  const Eigen::Matrix4d m = diagonal(-2, -1, 1);
  EXPECT_EQ(lct::matrixLog(m).status, Status::NoRealLogarithm);
  const auto polar = lct::logarithm(m, Parametrisation::Polar);
  ASSERT_TRUE(polar.ok());
  EXPECT_LT((lct::exponential(polar.value, Parametrisation::Polar).value - m).norm(), 1e-15);
  // A shear with a negative eigenvalue pair that is not a rotation: [[-1, 1], [0, -1]].
  Eigen::Matrix4d jordan = Eigen::Matrix4d::Identity();
  jordan(0, 0) = -1;
  jordan(0, 1) = 1;
  jordan(1, 1) = -1;
  EXPECT_EQ(lct::matrixLog(jordan).status, Status::NoRealLogarithm);
}

TEST(BadInput, OverflowingCoordinates)
{
  lct::LogCoords c = lct::LogCoords::Zero();
  c[6] = 1000.0; // exp(1000) overflows
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::exponential(c, p).status, Status::OutOfRange);
  }
  // A uniform stretch e^-1000 underflows: the map would be singular, not a transform.
  c[6] = c[7] = c[8] = -1000.0;
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::exponential(c, p).status, Status::OutOfRange);
  }
  // Representable but too ill-conditioned to hold its smallest stretch: e^(+-20).
  c[6] = 20.0;
  c[7] = 0.0;
  c[8] = -20.0;
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::exponential(c, p).status, Status::IllConditioned);
  }
  // Translations that overflow when combined are NonFinite input to exp, reported as such.
  c.setZero();
  c[0] = std::numeric_limits<double>::infinity();
  for (Parametrisation p : kBoth)
  {
    EXPECT_EQ(lct::exponential(c, p).status, Status::NonFinite);
  }
}

TEST(BadInput, RelativeCombinationWithBadReference)
{
  const Eigen::Matrix4d keys[2] = { Eigen::Matrix4d::Identity(), diagonal(-1, 1, 1) };
  const double w[2] = { 0.5, 0.5 };
  EXPECT_EQ(
    lct::combineRelative(w, keys, 2, 5, Parametrisation::Polar).status, Status::InvalidArgument);
  EXPECT_EQ(lct::combineRelative(w, keys, 2, 1, Parametrisation::Polar).status,
    Status::NegativeDeterminant);
  EXPECT_EQ(lct::combine(w, keys, 2, Parametrisation::Polar).status, Status::NegativeDeterminant);
}

TEST(BadInput, EveryStatusHasADescription)
{
  for (Status s : { Status::Ok, Status::NonFinite, Status::NotAffine, Status::NegativeDeterminant,
         Status::Singular, Status::IllConditioned, Status::NoRealLogarithm, Status::OutOfRange,
         Status::MagnitudeOutOfRange, Status::NumericalFailure, Status::InvalidArgument })
  {
    const std::string text = lct::describe(s);
    EXPECT_GT(text.size(), 1u);
    // The core does not know which parametrisation the caller uses: no advice to switch.
    EXPECT_EQ(text.find("use the"), std::string::npos) << text;
  }
}
