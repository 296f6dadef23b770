// The cyclic Jacobi eigensolver of the symmetric matrix functions (lct/SymmetricEigen3.h) against
// Eigen's SelfAdjointEigenSolver in long double, on the spectra the core hands it: spread
// (condition up to 1e13), indefinite, repeated and nearly repeated eigenvalues, graded positive
// definite matrices, diagonal ones, any magnitude.
#include "lct/SymmetricEigen3.h"

#include "RandomTransforms.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace
{
using Matrix3l = Eigen::Matrix<long double, 3, 3>;
using Vector3l = Eigen::Matrix<long double, 3, 1>;
constexpr double kEps = std::numeric_limits<double>::epsilon();

/// Eigenvalues of the shapes the core meets: spread, indefinite, two or three equal, two within
/// 1e-15 ... 1e-9 relative, all of one size.
Eigen::Vector3d spectrum(lct_test::RandomTransforms& random, int i)
{
  const double a = random.LogUniform(1.0, 1e13), b = random.LogUniform(1.0, 1e13);
  switch (i % 6)
  {
    case 0:
      return Eigen::Vector3d(1.0, a, b);
    case 1:
      return Eigen::Vector3d(-1.0, a, -b);
    case 2:
      return Eigen::Vector3d(1.0, a, a);
    case 3:
      return Eigen::Vector3d::Constant(a);
    case 4:
      return Eigen::Vector3d(a, a * (1.0 + random.LogUniform(1e-15, 1e-9)), b);
    default:
      return Eigen::Vector3d(
        random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0));
  }
}

struct Errors
{
  double values = 0.0;     ///< |l - l_ref| / ||Y||
  double residual = 0.0;   ///< ||Y - V diag(l) V^T|| / ||Y||
  double orthogonal = 0.0; ///< ||V^T V - I||
};

void measure(const Eigen::Matrix3d& y, Errors& worst)
{
  const lct::SymmetricEigen3 e = lct::symmetricEigen3(y);
  ASSERT_TRUE(e.values.allFinite() && e.vectors.allFinite()) << y;
  ASSERT_GE(e.values[0], e.values[1]);
  ASSERT_GE(e.values[1], e.values[2]);
  const Eigen::SelfAdjointEigenSolver<Matrix3l> reference(y.cast<long double>());
  const long double norm = y.cast<long double>().norm();
  const Vector3l referenceValues = reference.eigenvalues().reverse();
  worst.values = std::max(worst.values,
    static_cast<double>(
      (e.values.cast<long double>() - referenceValues).cwiseAbs().maxCoeff() / norm));
  const Matrix3l back = e.vectors.cast<long double>() * e.values.cast<long double>().asDiagonal() *
    e.vectors.cast<long double>().transpose();
  worst.residual =
    std::max(worst.residual, static_cast<double>((back - y.cast<long double>()).norm() / norm));
  worst.orthogonal = std::max(worst.orthogonal,
    static_cast<double>((e.vectors.cast<long double>().transpose() * e.vectors.cast<long double>() -
      Matrix3l::Identity())
                          .norm()));
}
} // namespace

TEST(SymmetricEigen3, BackwardStableOnEveryShapeOfSpectrumAndMagnitude)
{
  lct_test::RandomTransforms random(3);
  Errors worst;
  for (int i = 0; i < 60000; ++i)
  {
    const Eigen::Matrix3d v = random.Rotation();
    const double scale = std::pow(2.0, random.Uniform(-1000.0, 1000.0));
    const Eigen::Matrix3d product = v * spectrum(random, i).asDiagonal() * v.transpose();
    Eigen::Matrix3d y = 0.5 * (product + product.transpose()) / product.norm();
    if (i % 50 == 0)
    {
      // Diagonal input, with or without a coupling below the stopping test: no rotation.
      y = Eigen::Vector3d(1.0, random.Uniform(-1.0, 1.0), 1e-3).asDiagonal();
      y(0, 2) = y(2, 0) = i % 100 == 0 ? 0.0 : 1e-40;
    }
    measure(scale * y, worst);
  }
  std::printf("  eigenvalues %.2e ||Y||, residual %.2e, orthogonality %.2e\n", worst.values,
    worst.residual, worst.orthogonal);
  EXPECT_LT(worst.values, 4.0 * kEps);
  EXPECT_LT(worst.residual, 8.0 * kEps);
  EXPECT_LT(worst.orthogonal, 8.0 * kEps);
}

TEST(SymmetricEigen3, GradedPositiveDefiniteMatricesKeepTheirSmallEigenvaluesRelatively)
{
  // Y = D S D with S well conditioned and D spanning up to 1e12: its eigenvalues are determined to
  // ~eps cond(S) relative by its entries (Demmel & Veselić), whatever cond(Y); a solver that only
  // keeps eps ||Y|| loses the small ones entirely.
  lct_test::RandomTransforms random(5);
  double worst = 0.0, worstQR = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    const Eigen::Matrix3d v = random.Rotation();
    const Eigen::Vector3d s(1.0, random.LogUniform(0.5, 2.0), random.LogUniform(0.5, 2.0));
    const Eigen::Vector3d d(1.0, random.LogUniform(1e-6, 1.0), random.LogUniform(1e-12, 1e-6));
    const Eigen::Matrix3d y =
      d.asDiagonal() * (v * s.asDiagonal() * v.transpose()) * d.asDiagonal();
    const lct::SymmetricEigen3 e = lct::symmetricEigen3(y);
    // A QR-based reference keeps only eps ||Y|| even in long double, too little here: the largest
    // eigenvalue from it, the smallest as 1 / the largest of Y^-1 = D^-1 V diag(1/s) V^T D^-1
    // (formed from the factors), the middle one from det Y = det(D)^2 det(S).
    const Matrix3l vl = v.cast<long double>();
    const Vector3l sl = s.cast<long double>(), dl = d.cast<long double>();
    const Matrix3l inverse = dl.cwiseInverse().asDiagonal() *
      (vl * sl.cwiseInverse().asDiagonal() * vl.transpose()) * dl.cwiseInverse().asDiagonal();
    const long double largest =
      Eigen::SelfAdjointEigenSolver<Matrix3l>(y.cast<long double>()).eigenvalues()[2];
    const long double smallest =
      1.0L / Eigen::SelfAdjointEigenSolver<Matrix3l>(inverse).eigenvalues()[2];
    const long double det = dl.prod() * dl.prod() * sl.prod();
    const Vector3l exact(largest, det / (largest * smallest), smallest);
    const Eigen::Vector3d qr = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(y).eigenvalues();
    for (int k = 0; k < 3; ++k)
    {
      worst = std::max(worst, static_cast<double>(std::abs(e.values[k] - exact[k]) / exact[k]));
      worstQR = std::max(worstQR, static_cast<double>(std::abs(qr[2 - k] - exact[k]) / exact[k]));
    }
  }
  std::printf("  graded SPD: eigenvalues %.2e relative (Eigen's SelfAdjointEigenSolver %.2e)\n",
    worst, worstQR);
  EXPECT_LT(worst, 1e-14);
}

TEST(SymmetricEigen3, ZeroAndScalarMatricesAreTheirOwnDecomposition)
{
  for (const double c : { 0.0, 1.0, -3.0, 1e-310, 1e300 })
  {
    const lct::SymmetricEigen3 e = lct::symmetricEigen3(c * Eigen::Matrix3d::Identity());
    EXPECT_EQ(e.values, Eigen::Vector3d::Constant(c));
    // No rotation: the vectors are the axes (in some order).
    EXPECT_TRUE((e.vectors.transpose() * e.vectors).isIdentity(0.0)) << e.vectors;
    EXPECT_EQ(e.vectors.cwiseAbs().sum(), 3.0);
  }
}

TEST(SymmetricEigen3, EigenvaluesBeyondTheDoubleRangeAreInfWithOrthogonalVectors)
{
  // FuzzCorePieces D34: |eigenvalue| <= 3 max|y_ij| may exceed DBL_MAX. The values then overflow
  // (as the exact ones would), but the vectors stay finite and orthogonal, and just below the
  // range the values are finite and right.
  constexpr double kMax = std::numeric_limits<double>::max();
  Eigen::Matrix3d y;
  y << 1e308, 1e308, -kMax, 1e308, 0.0, 1.9e-313, -kMax, 1.9e-313, 1.6e-306;
  const lct::SymmetricEigen3 huge = lct::symmetricEigen3(y);
  EXPECT_TRUE(huge.vectors.allFinite());
  EXPECT_LT((huge.vectors.transpose() * huge.vectors - Eigen::Matrix3d::Identity()).norm(), 1e-15);
  EXPECT_EQ(huge.values[0], std::numeric_limits<double>::infinity());

  const Eigen::Matrix3d representable = y / 4.0;
  const lct::SymmetricEigen3 e = lct::symmetricEigen3(representable);
  ASSERT_TRUE(e.values.allFinite());
  // The values of Y are 4 times those of Y / 4: Inf where that leaves the range, else the same.
  for (int k = 0; k < 3; ++k)
  {
    const double expected = 4.0 * e.values[k];
    if (std::isinf(expected))
    {
      EXPECT_EQ(huge.values[k], expected) << k;
    }
    else
    {
      EXPECT_NEAR(huge.values[k], expected, 1e-15 * kMax) << k;
    }
  }
  // Compared at unit size (the residual itself would overflow).
  const Eigen::Matrix3d unit = representable / kMax;
  const Eigen::Matrix3d rebuilt =
    e.vectors * (e.values / kMax).asDiagonal() * e.vectors.transpose();
  EXPECT_LT((rebuilt - unit).norm(), 4.0 * kEps * unit.norm());
}
