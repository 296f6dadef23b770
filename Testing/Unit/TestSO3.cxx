// so(3) <-> SO(3): Rodrigues exp and the principal / nearest logarithm, against Eigen's
// MatrixFunctions and AngleAxis as independent oracles.
#include "lct/SO3.h"

#include "RandomTransforms.h"

#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

using lct_test::kPi;

TEST(SO3, ExpMatchesEigenMatrixExponential)
{
  lct_test::RandomTransforms random(11);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    // Angles from 1e-12 to 3 pi, including the series branch and beyond one turn.
    const double angle =
      (i % 4 == 0) ? random.LogUniform(1e-12, 1e-3) : random.Uniform(0.0, 3 * kPi);
    const Eigen::Vector3d w = angle * random.UnitVector();
    const Eigen::Matrix3d oracle = lct::hat(w).exp();
    worst = std::max(worst, (lct::expSO3(w) - oracle).norm());
  }
  // Eigen's Pade exp itself is at ~2e-15 here.
  EXPECT_LT(worst, 5e-15);
}

TEST(SO3, LogInvertsExpOnThePrincipalDomain)
{
  lct_test::RandomTransforms random(12);
  double worst = 0.0;
  for (int i = 0; i < 100000; ++i)
  {
    double angle;
    switch (i % 4)
    {
      case 0:
        angle = random.LogUniform(1e-14, 1e-2); // near 0
        break;
      case 1:
        angle = kPi - random.LogUniform(1e-12, 1e-2); // near pi
        break;
      default:
        angle = random.Uniform(0.0, kPi);
    }
    const Eigen::Vector3d w = angle * random.UnitVector();
    const Eigen::Vector3d back = lct::logSO3(lct::expSO3(w));
    // Near pi the vector is determined only to eps / (pi - angle) across the axis.
    worst = std::max(worst, (back - w).norm());
  }
  EXPECT_LT(worst, 1e-8);
}

TEST(SO3, LogAccuracyAwayFromHalfTurnMatchesEigen)
{
  lct_test::RandomTransforms random(13);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    const Eigen::Matrix3d r = random.Rotation(random.Uniform(0.0, 3.0));
    const Eigen::Matrix3d oracle = r.log();
    worst = std::max(worst, (lct::hat(lct::logSO3(r)) - oracle).norm());
  }
  // Up to 3 rad the log amplifies the round-off of R by t / sin t <= 21.
  EXPECT_LT(worst, 4e-14);
}

TEST(SO3, LogAtExactHalfTurnIsAHalfTurnAboutTheAxis)
{
  lct_test::RandomTransforms random(14);
  for (int i = 0; i < 1000; ++i)
  {
    const Eigen::Vector3d axis = random.UnitVector();
    const Eigen::Matrix3d r = Eigen::AngleAxisd(kPi, axis).toRotationMatrix();
    const Eigen::Vector3d w = lct::logSO3(r);
    EXPECT_NEAR(w.norm(), kPi, 1e-14);
    EXPECT_NEAR(std::abs(w.normalized().dot(axis)), 1.0, 1e-14);
    EXPECT_LT((lct::expSO3(w) - r).norm(), 1e-14);
  }
}

TEST(SO3, NearestLogKeepsWindingBeyondTwoPi)
{
  // A spin sampled every 170 degrees: each key's log nearest to the previous one keeps
  // growing (Kaji & Ochiai Algorithm 1), where the principal log would wrap.
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 2, 3).normalized();
  Eigen::Vector3d previous = Eigen::Vector3d::Zero();
  for (int k = 1; k <= 12; ++k)
  {
    const double angle = k * 170.0 * kPi / 180.0;
    const Eigen::Matrix3d r = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
    const Eigen::Vector3d w = lct::logSO3Nearest(r, previous);
    EXPECT_NEAR((w - angle * axis).norm(), 0.0, 1e-12) << "key " << k;
    previous = w;
  }
}

TEST(SO3, NearestLogOfIdentityFollowsTheReference)
{
  const Eigen::Vector3d reference(0.0, 0.0, 2 * kPi - 0.1);
  const Eigen::Vector3d w = lct::logSO3Nearest(Eigen::Matrix3d::Identity(), reference);
  EXPECT_NEAR((w - Eigen::Vector3d(0, 0, 2 * kPi)).norm(), 0.0, 1e-15);
  // A small reference keeps the zero vector.
  EXPECT_EQ(lct::logSO3Nearest(Eigen::Matrix3d::Identity(), Eigen::Vector3d(0.1, 0, 0)),
    Eigen::Vector3d::Zero());
}
