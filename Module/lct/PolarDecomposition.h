/**
 * @file PolarDecomposition.h
 * @brief A = U S with U a rotation and S symmetric positive definite, for det A > 0.
 *
 * Kaji & Ochiai eq. 3 define S = sqrt(A^T A), but forming A^T A squares the condition
 * number (with scales in 0.1..10 the rotation is orthogonal only to ~3e-8). Their §4.4
 * recommends Higham's algorithm for near-singular input. Two branches:
 *
 * - cond(A) <= kClosedFormConditionLimit (lct/Conditioning.h), the common case: Newton's
 *   iteration X <- (g X + X^-T / g) / 2 with Frobenius-norm scaling g (Higham 1986, "Computing
 *   the polar decomposition — with applications", §3), S = sym(U^T A), and the eigenvalues of S
 *   from the cubic formula. It converges quadratically; with scaling it needs at most 9 steps
 *   for cond(A) <= 1e16 in double precision, and the loop is bounded.
 * - above it: the SVD A = W diag(sigma) V^T with relatively accurate singular values
 *   (lct/SVD3.h), U = W V^T and S = V diag(sigma) V^T, so that the stretch keeps every digit of
 *   its smallest eigenvalue that the input holds (the cubic formula keeps only eps ||S||).
 *
 * Input of any magnitude is scaled by a power of two first (exact). Condition numbers above
 * kMaxConditionNumber are refused (IllConditioned).
 */
#ifndef lct_PolarDecomposition_h
#define lct_PolarDecomposition_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// The factors of 2^exponent A_unit, A_unit of unit size: the stretch of A is 2^exponent
/// unitStretch, so magnitudes near the ends of the double range keep their logarithms.
struct PolarFactors
{
  Eigen::Matrix3d rotation;    ///< U, orthogonal, det +1
  Eigen::Matrix3d unitStretch; ///< S 2^-exponent, symmetric positive definite
  int exponent = 0;
  /// The eigenvalues of unitStretch, descending; relatively accurate when `hasStretchAxes`.
  Eigen::Vector3d unitEigenvalues;
  /// When the stretch is ill-conditioned (the SVD branch): unitStretch = stretchAxes
  /// diag(unitEigenvalues) stretchAxes^T.
  bool hasStretchAxes = false;
  Eigen::Matrix3d stretchAxes;

  /// S = 2^exponent unitStretch (overflows to Inf only for entries beyond the double range).
  Eigen::Matrix3d stretch() const;
};

/// Fails with NonFinite, NegativeDeterminant, Singular (det A = 0, or sigma_min = 0 in double),
/// IllConditioned (sigma_max / sigma_min > kMaxConditionNumber) or OutOfRange (sigma_min below
/// the normal range: the stretch would be subnormal, with fewer digits than its input).
VTKLCT_EXPORT Result<PolarFactors> polarDecompose(const Eigen::Matrix3d& a);

/// The sign of det A, decided accurately: -1, 0 or +1 (NaN input gives 0).
VTKLCT_EXPORT int determinantSign(const Eigen::Matrix3d& a);

/// A with its rows, then its columns, scaled to unit size by powers of two: det A =
/// det(result) 2^exponent exactly, and det(result) does not underflow where A's scales are
/// merely spread (diag(1e-110, 1, 1e110): det 1, but 1e-330 at unit scale).
VTKLCT_EXPORT Eigen::Matrix3d equilibrated(const Eigen::Matrix3d& a, int& exponent);

} // namespace lct

#endif
