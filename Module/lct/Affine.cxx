#include "lct/Affine.h"

#include "lct/Conditioning.h"
#include "lct/PolarDecomposition.h"

#include <Eigen/LU>

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
  const Eigen::Matrix3d inverseLinear =
    scaledByPowerOfTwo(Eigen::Matrix3d(scaledByPowerOfTwo(linear, -e).inverse()), -e);
  return makeAffine(inverseLinear, -(inverseLinear * m.topRightCorner<3, 1>()));
}

} // namespace lct
