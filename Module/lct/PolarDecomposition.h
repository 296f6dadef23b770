/**
 * @file PolarDecomposition.h
 * @brief A = U S with U a rotation and S symmetric positive definite, for det A > 0.
 *
 * Kaji & Ochiai eq. 3 define S = sqrt(A^T A), but forming A^T A squares the condition
 * number (with scales in 0.1..10 the rotation is orthogonal only to ~3e-8). Their §4.4
 * recommends Higham's algorithm for near-singular input; we use it for all input:
 * Newton's iteration X <- (g X + X^-T / g) / 2 with Frobenius-norm scaling g (Higham 1986,
 * "Computing the polar decomposition — with applications", §3). It converges quadratically
 * from any nonsingular start; with scaling it needs at most 9 steps for cond(A) <= 1e16 in
 * double precision, so the loop is bounded, and it does not square the condition number.
 * S = sym(U^T A).
 */
#ifndef lct_PolarDecomposition_h
#define lct_PolarDecomposition_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

struct PolarFactors
{
  Eigen::Matrix3d rotation; ///< U, orthogonal, det +1
  Eigen::Matrix3d stretch;  ///< S, symmetric positive definite
};

/// Fails with NonFinite, NonPositiveDeterminant or Singular (det A below round-off).
VTKLCT_EXPORT Result<PolarFactors> polarDecompose(const Eigen::Matrix3d& a);

} // namespace lct

#endif
