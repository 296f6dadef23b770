/**
 * @file Affine.h
 * @brief 4x4 homogeneous affine matrices: validation, assembly and inverse.
 *
 * The domain of both parametrisations is Aff+(3): finite 4x4 matrices with bottom row
 * (0, 0, 0, 1) and a linear part of positive determinant.
 */
#ifndef lct_Affine_h
#define lct_Affine_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// Ok, NonFinite, NotAffine (bottom row not (0,0,0,1)), NegativeDeterminant or Singular
/// (det = 0). Conditioning is checked by the logarithms, not here.
VTKLCT_EXPORT Status validateAffine(const Eigen::Matrix4d& m);

/// [linear translation; 0 0 0 1]
inline Eigen::Matrix4d makeAffine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

/// The inverse of an affine matrix, using its block structure (no 4x4 inversion), at any
/// magnitude. Entries overflow to Inf when the inverse is out of range (callers check).
VTKLCT_EXPORT Eigen::Matrix4d inverseAffine(const Eigen::Matrix4d& m);

} // namespace lct

#endif
