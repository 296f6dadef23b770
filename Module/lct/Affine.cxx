#include "lct/Affine.h"

#include "lct/AccurateMinors.h"
#include "lct/Conditioning.h"
#include "lct/PolarDecomposition.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <cmath>
#include <limits>

namespace lct
{

Status validateAffine(const Eigen::Matrix4d& m)
{
  if (!m.allFinite())
  {
    return Status::NonFinite;
  }
  if (m(3, 0) != 0.0 || m(3, 1) != 0.0 || m(3, 2) != 0.0 || m(3, 3) != 1.0)
  {
    return Status::NotAffine;
  }
  // The sign is decided at unit scale and with exact minors when close to 0: a plain determinant
  // of 1e-120 I underflows to 0, and one of a rotated stretch of condition 1e12 may have either
  // sign.
  const int sign = determinantSign(m.topLeftCorner<3, 3>());
  if (sign < 0)
  {
    return Status::NegativeDeterminant;
  }
  return sign == 0 ? Status::Singular : Status::Ok;
}

Eigen::Matrix4d inverseAffine(const Eigen::Matrix4d& m)
{
  // (2^e A)^-1 = 2^-e A^-1: the cofactors and the determinant of a unit-size A stay in range
  // (for entries of 1e300 they would overflow, for 1e-300 underflow).
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  const int e = unitScaleExponent(linear);
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(linear, -e);
  // -A^-1 t at the unit size of t as well: with t near DBL_MAX the products of the row sums
  // overflow before they cancel (the inverse of a map whose own inverse is in range).
  const Eigen::Vector3d t = m.topRightCorner<3, 1>();
  const int k = unitScaleExponent(t);
  const Eigen::Vector3d unitT = scaledByPowerOfTwo(t, -k);
  // An ill-conditioned A (the test of needsAccurateProducts): the plain cofactor inverse takes
  // det A from products of the size of ||A||^3 that cancel, so its error grows like
  // eps cond(A)^2; at condition 1e12 the inverse translation of a Polar map was off by 160 %.
  // There every entry comes from exact minors (lct/AccurateMinors.h), to a few ulps.
  const double det = unitScaleDeterminant(unit);
  const double norm = unit.norm();
  if (det != 0.0 && std::isfinite(det) && !(norm * norm * norm <= 1e3 * std::abs(det)))
  {
    return makeAffine(scaledByPowerOfTwo(Eigen::Matrix3d(accurateInverseTimes(
                                           unit, Eigen::Matrix3d(Eigen::Matrix3d::Identity()))),
                        -e),
      scaledByPowerOfTwo(Eigen::Vector3d(-accurateInverseTimes(unit, unitT)), k - e));
  }
  const Eigen::Matrix3d inverseLinear = scaledByPowerOfTwo(Eigen::Matrix3d(unit.inverse()), -e);
  return makeAffine(
    inverseLinear, scaledByPowerOfTwo(Eigen::Vector3d(-(inverseLinear * unitT)), k));
}

double accurateLogDeterminant(const Eigen::Matrix4d& m)
{
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const int e = unitScaleExponent(a);
  return std::log(std::abs(accurateDeterminant(scaledByPowerOfTwo(a, -e)))) +
    3.0 * e * 0.69314718055994530942;
}

bool determinantMatches(const Eigen::Matrix4d& result, double expected)
{
  const Eigen::Matrix3d a = result.topLeftCorner<3, 3>();
  const int e = unitScaleExponent(a);
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(a, -e);
  const double det = std::abs(accurateDeterminant(unit));
  const double got = std::log(det) + 3.0 * e * 0.69314718055994530942;
  const double representable = 2.0 * std::numeric_limits<double>::epsilon() *
    (accurateCofactors(unit).cwiseAbs().cwiseProduct(unit.cwiseAbs())).sum() / det;
  return std::abs(got - expected) <= 1e-9 * (1.0 + std::abs(expected)) + representable;
}

double linearConditionNumber(const Eigen::Matrix4d& m)
{
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(linear, -unitScaleExponent(linear));
  const Eigen::Vector3d sigma = Eigen::JacobiSVD<Eigen::Matrix3d>(unit).singularValues();
  return sigma[2] > 0.0 ? sigma[0] / sigma[2] : std::numeric_limits<double>::infinity();
}

bool needsAccurateProducts(const Eigen::Matrix4d& m)
{
  // Subnormal entries carry fewer bits than the products assume.
  const double smallest = m.topLeftCorner<3, 3>()
                            .cwiseAbs()
                            .unaryExpr([](double x) { return x == 0.0 ? 1.0 : x; })
                            .minCoeff();
  if (smallest < std::numeric_limits<double>::min())
  {
    return true;
  }
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(
    Eigen::Matrix3d(m.topLeftCorner<3, 3>()), -unitScaleExponent(m.topLeftCorner<3, 3>()));
  const double det = unitScaleDeterminant(unit);
  const double norm = unit.norm();
  return !(det > 0.0 && norm * norm * norm <= 1e3 * det);
}

Eigen::Matrix4d productWith(const Eigen::Matrix4d& r, const Eigen::Matrix4d& x, bool accurate)
{
  return accurate ? accurateProduct(r, x) : Eigen::Matrix4d(r * x);
}

Eigen::Matrix4d relativeStep(const Eigen::Matrix4d& reference, const Eigen::Matrix4d& m)
{
  if (!needsAccurateProducts(reference))
  {
    return inverseAffine(reference) * m;
  }
  const Eigen::Matrix3d a = reference.topLeftCorner<3, 3>();
  const int e = unitScaleExponent(a);
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(a, -e);
  // (2^e U)^-1 B = 2^-e U^-1 B, and U^-1 (t_m - t_r) for the translation.
  const Eigen::Vector3d difference = m.topRightCorner<3, 1>() - reference.topRightCorner<3, 1>();
  return makeAffine(
    scaledByPowerOfTwo(
      Eigen::Matrix3d(accurateInverseTimes(unit, Eigen::Matrix3d(m.topLeftCorner<3, 3>()))), -e),
    scaledByPowerOfTwo(Eigen::Vector3d(accurateInverseTimes(unit, difference)), -e));
}

namespace
{
/// [L^T, 0; 0 1]: products on the right of L are transposed products on its left.
Eigen::Matrix4d transposedLinear(const Eigen::Matrix4d& m)
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topLeftCorner<3, 3>() = m.topLeftCorner<3, 3>().transpose();
  return t;
}
} // namespace

Eigen::Matrix4d worldStep(const Eigen::Matrix4d& reference, const Eigen::Matrix4d& m)
{
  // L_m L_r^-1 = (L_r^-T L_m^T)^T, with relativeStep's exact minors for L_r^-T.
  const Eigen::Matrix4d transposed = relativeStep(transposedLinear(reference), transposedLinear(m));
  return makeAffine(transposed.topLeftCorner<3, 3>().transpose(),
    m.topRightCorner<3, 1>() - reference.topRightCorner<3, 1>());
}

Eigen::Matrix4d applyWorldStep(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& step, bool accurate)
{
  const Eigen::Matrix4d transposed =
    productWith(transposedLinear(reference), transposedLinear(step), accurate);
  return makeAffine(transposed.topLeftCorner<3, 3>().transpose(),
    reference.topRightCorner<3, 1>() + step.topRightCorner<3, 1>());
}

} // namespace lct
