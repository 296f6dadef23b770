/**
 * @file SVD3.h
 * @brief The singular value decomposition of a 3x3 matrix with positive determinant, with every
 *        singular value to relative accuracy: the ill-conditioned branch of the polar
 *        decomposition (lct/PolarDecomposition.h).
 *
 * A backward-stable SVD (Eigen's two-sided JacobiSVD) gives sigma_max to a few ulps but
 * sigma_min only to eps sigma_max absolute, i.e. relative eps cond. The products of singular
 * values are better conditioned than the values themselves when they are computed from exact
 * minors: sigma_1 sigma_2 is the largest singular value of the cofactor matrix (the second
 * compound of A, up to signs: adj A = det A V diag(1/sigma) U^T), and sigma_1 sigma_2 sigma_3 =
 * det A. With the cofactors and the determinant from lct/AccurateMinors.h,
 *
 *   sigma_2 = ||cof A||_2 / sigma_1,   sigma_3 = det A / ||cof A||_2
 *
 * are accurate to a few ulps relative, for any condition number below 1/eps. The singular vectors
 * come from JacobiSVD (backward stable: A = U diag(sigma) V^T holds to eps ||A||).
 */
#ifndef lct_SVD3_h
#define lct_SVD3_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

namespace lct
{

struct SingularValueDecomposition3
{
  Eigen::Matrix3d u;     ///< left singular vectors, a rotation (det +1)
  Eigen::Vector3d sigma; ///< singular values, descending, each to a few ulps relative
  Eigen::Matrix3d v;     ///< right singular vectors, a rotation (det +1)
};

/// A = u diag(sigma) v^T. Preconditions: det A > 0 and entries of moderate size (scale with
/// lct::unitScaleExponent first). A rank-deficient A gives sigma_3 = 0 (and sigma_2 = 0).
VTKLCT_EXPORT SingularValueDecomposition3 singularValueDecomposition3(const Eigen::Matrix3d& a);

} // namespace lct

#endif
