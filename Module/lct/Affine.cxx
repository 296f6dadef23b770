#include "lct/Affine.h"

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
  const Eigen::Matrix3d inverseLinear = m.topLeftCorner<3, 3>().inverse();
  return makeAffine(inverseLinear, -(inverseLinear * m.topRightCorner<3, 1>()));
}

} // namespace lct
