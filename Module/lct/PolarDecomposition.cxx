#include "lct/PolarDecomposition.h"

#include "lct/AccurateMinors.h"
#include "lct/Conditioning.h"
#include "lct/Eigenvalues3.h"
#include "lct/SVD3.h"

#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace lct
{

Eigen::Matrix3d PolarFactors::stretch() const
{
  return scaledByPowerOfTwo(this->unitStretch, this->exponent);
}

int determinantSign(const Eigen::Matrix3d& a)
{
  if (!a.allFinite())
  {
    return 0;
  }
  // Entries of moderate size whose plain determinant is far from 0 relative to their cube: the
  // sign is certain without scaling or exact minors (the common case).
  const double largest = a.cwiseAbs().maxCoeff();
  if (largest > 0x1p-300 && largest < 0x1p300)
  {
    const double det = a.determinant();
    if (std::abs(det) > 1e-6 * largest * largest * largest)
    {
      return det > 0.0 ? 1 : -1;
    }
  }
  const double det = unitScaleDeterminant(scaledByPowerOfTwo(a, -unitScaleExponent(a)));
  if (det != 0.0)
  {
    return det > 0.0 ? 1 : -1;
  }
  // 0 at unit scale may be an underflow of spread scales (lct::equilibrated); what is still 0
  // is singular in double (the refusal then says so).
  int exponent = 0;
  const double balanced = unitScaleDeterminant(equilibrated(a, exponent));
  return balanced > 0.0 ? 1 : (balanced < 0.0 ? -1 : 0);
}

Eigen::Matrix3d equilibrated(const Eigen::Matrix3d& a, int& exponent)
{
  // Positive factors: the sign of the determinant is kept, and powers of two keep it exact.
  Eigen::Matrix3d e = a;
  exponent = 0;
  for (int i = 0; i < 3; ++i)
  {
    const int k = unitScaleExponent(e.row(i));
    e.row(i) = scaledByPowerOfTwo(Eigen::RowVector3d(e.row(i)), -k);
    exponent += k;
  }
  for (int j = 0; j < 3; ++j)
  {
    const int k = unitScaleExponent(e.col(j));
    e.col(j) = scaledByPowerOfTwo(Eigen::Vector3d(e.col(j)), -k);
    exponent += k;
  }
  return e;
}

namespace
{

/// Newton's scaled iteration on a unit-size, well-enough conditioned matrix.
Eigen::Matrix3d newtonPolarFactor(const Eigen::Matrix3d& a)
{
  constexpr int kMaxIterations = 30;
  Eigen::Matrix3d x = a;
  bool scaling = true;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration)
  {
    const Eigen::Matrix3d inverseTranspose = x.inverse().transpose();
    double g = 1.0;
    if (scaling)
    {
      g = std::sqrt(std::sqrt(inverseTranspose.squaredNorm() / x.squaredNorm()));
    }
    const Eigen::Matrix3d next = 0.5 * (g * x + inverseTranspose / g);
    const double change = (next - x).squaredNorm();
    x = next;
    // Scaling only helps far from convergence; near it, it would slow the quadratic phase.
    if (change < 1e-4)
    {
      scaling = false;
    }
    // Quadratic convergence: once a step moves less than sqrt(eps), the next one is at
    // round-off, so take it and stop.
    if (change <= 1e-18)
    {
      x = 0.5 * (x + x.inverse().transpose());
      break;
    }
  }
  return x;
}

} // namespace

namespace
{
/// Ok, or OutOfRange when the smallest stretch 2^e sigma_min is subnormal. Compared as
/// sigma_min < DBL_MIN 2^-e (exact): in log space the ulp of 708 hid stretches up to 1e-13 below
/// DBL_MIN, whose Polar log polarExp then refused.
Status checkSmallestStretch(double unitSmallest, int exponent)
{
  return unitSmallest < timesPowerOfTwo(std::numeric_limits<double>::min(), -exponent)
    ? Status::OutOfRange
    : Status::Ok;
}
} // namespace

Result<PolarFactors> polarDecompose(const Eigen::Matrix3d& a)
{
  using R = Result<PolarFactors>;
  if (!a.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const int sign = determinantSign(a);
  if (sign < 0)
  {
    return R::failure(Status::NegativeDeterminant);
  }
  if (sign == 0)
  {
    return R::failure(Status::Singular);
  }
  PolarFactors f;
  f.exponent = unitScaleExponent(a);
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(a, -f.exponent);

  // k = ||A||_F^3 / det A lies in [cond, 3^(3/2) cond^2]: above 3^(3/2) 32^2 the closed-form
  // branch cannot apply, so Newton's iteration is not even started.
  const double det = unitScaleDeterminant(unit);
  const double norm = unit.norm();
  constexpr double kRootTwentySeven = 5.196152422706632;
  const bool clearlyIllConditioned = !(det > 0.0) ||
    norm * norm * norm >
      kRootTwentySeven * kClosedFormConditionLimit * kClosedFormConditionLimit * det;

  if (!clearlyIllConditioned)
  {
    f.rotation = newtonPolarFactor(unit);
    const Eigen::Matrix3d s = f.rotation.transpose() * unit;
    f.unitStretch = 0.5 * (s + s.transpose());
    f.unitEigenvalues = symmetricEigenvalues(f.unitStretch);
    if (f.rotation.allFinite() && f.unitEigenvalues.allFinite() &&
      f.unitEigenvalues[2] * kClosedFormConditionLimit >= f.unitEigenvalues[0])
    {
      const Status range = checkSmallestStretch(f.unitEigenvalues[2], f.exponent);
      return range == Status::Ok ? R{ f, Status::Ok } : R::failure(range);
    }
  }

  const SingularValueDecomposition3 svd = singularValueDecomposition3(unit);
  if (!svd.sigma.allFinite())
  {
    return R::failure(Status::NumericalFailure);
  }
  if (!(svd.sigma[2] > 0.0))
  {
    // The determinant is not 0 (its sign is known above): the smallest stretch underflowed at
    // unit scale, a condition far beyond kMaxConditionNumber (diag(1e-110, 1, 1e110), of
    // determinant 1, was called singular).
    return R::failure(Status::IllConditioned);
  }
  if (svd.sigma[0] > kMaxConditionNumber * svd.sigma[2])
  {
    return R::failure(Status::IllConditioned);
  }
  const Status range = checkSmallestStretch(svd.sigma[2], f.exponent);
  if (range != Status::Ok)
  {
    return R::failure(range);
  }
  f.rotation = svd.u * svd.v.transpose();
  f.unitEigenvalues = svd.sigma;
  f.stretchAxes = svd.v;
  f.hasStretchAxes = true;
  const Eigen::Matrix3d s = svd.v * svd.sigma.asDiagonal() * svd.v.transpose();
  f.unitStretch = 0.5 * (s + s.transpose());
  return { f, Status::Ok };
}

} // namespace lct
