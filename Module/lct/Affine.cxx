#include "lct/Affine.h"

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
  if (!(m.topLeftCorner<3, 3>().determinant() > 0.0))
  {
    return Status::NonPositiveDeterminant;
  }
  return Status::Ok;
}

Eigen::Matrix4d inverseAffine(const Eigen::Matrix4d& m)
{
  const Eigen::Matrix3d inverseLinear = m.topLeftCorner<3, 3>().inverse();
  return makeAffine(inverseLinear, -(inverseLinear * m.topRightCorner<3, 1>()));
}

} // namespace lct
