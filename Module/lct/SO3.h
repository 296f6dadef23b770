/**
 * @file SO3.h
 * @brief Rotations: the exponential and logarithm between so(3) and SO(3).
 *
 * A rotation vector `w` stands for the skew matrix `hat(w)`; its length is the angle.
 * - `expSO3`: Rodrigues' formula (Kaji & Ochiai eq. 4), exact for every angle, with the
 *   half-angle form of `(1 - cos t) / t^2` so that no cancellation occurs near 0.
 * - `logSO3`: the principal logarithm, angle in [0, pi] (Kaji & Ochiai eq. 8). The angle is
 *   taken from atan2(sin, cos), never from acos; near pi the axis comes from the symmetric
 *   part of R (the eigenvector of eigenvalue 1), where the skew part has lost its digits.
 * - `logSO3Nearest`: the logarithm among all `w + 2 pi k w/|w|` closest to a reference
 *   (Kaji & Ochiai Algorithm 1), so that sampled spins beyond 2 pi keep their winding.
 */
#ifndef lct_SO3_h
#define lct_SO3_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

namespace lct
{

/// The skew-symmetric matrix with hat(w) v = w x v.
inline Eigen::Matrix3d hat(const Eigen::Vector3d& w)
{
  Eigen::Matrix3d m;
  m << 0.0, -w.z(), w.y(), w.z(), 0.0, -w.x(), -w.y(), w.x(), 0.0;
  return m;
}

/// The vector of the skew part of X: vee(hat(w)) = w; for any X, vee((X - X^T)/2).
inline Eigen::Vector3d vee(const Eigen::Matrix3d& x)
{
  return 0.5 * Eigen::Vector3d(x(2, 1) - x(1, 2), x(0, 2) - x(2, 0), x(1, 0) - x(0, 1));
}

/// exp(hat(w)), Rodrigues' formula.
VTKLCT_EXPORT Eigen::Matrix3d expSO3(const Eigen::Vector3d& w);

/// exp(hat(w)) - I without forming I: zero exactly for w = 0 and free of the cancellation of
/// (I + E) - I for small angles, so that p + (R - I) (p - c) leaves p untouched at rest.
VTKLCT_EXPORT Eigen::Matrix3d expSO3MinusIdentity(const Eigen::Vector3d& w);

/// The principal logarithm of a rotation matrix: |result| in [0, pi].
/// At exactly pi either of the two opposite vectors may be returned.
/// Precondition: R is orthogonal with det +1 to round-off (callers validate).
VTKLCT_EXPORT Eigen::Vector3d logSO3(const Eigen::Matrix3d& rotation);

/// The logarithm of R closest to `reference` (Kaji & Ochiai Algorithm 1).
VTKLCT_EXPORT Eigen::Vector3d logSO3Nearest(
  const Eigen::Matrix3d& rotation, const Eigen::Vector3d& reference);

/// Among the rotation vectors of the same rotation as `w`, the one closest to `reference`.
VTKLCT_EXPORT Eigen::Vector3d nearestEquivalentRotation(
  const Eigen::Vector3d& w, const Eigen::Vector3d& reference);

} // namespace lct

#endif
