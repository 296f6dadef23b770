/**
 * @file AccurateMinors.h
 * @brief The cofactors and the determinant of a 3x3 matrix to relative accuracy, whatever the
 *        cancellation: the inputs of the relatively accurate singular values of lct/SVD3.h.
 *
 * Evaluated naively, det A = sum of six triple products cancels down to eps sigma_max^3 absolute,
 * so an ill-conditioned matrix gets a determinant with few or no correct digits. Here every
 * product is split exactly into a sum of doubles with fused multiply-adds (Dekker's TwoProduct:
 * a b = p + e, e = fma(a, b, -p)), and the 24 exact terms are summed in three times the working
 * precision (Ogita, Rump & Oishi 2005, "Accurate sum and dot product", Algorithm 4.8 SumK,
 * K = 3), so the determinant is accurate to a few ulps unless the cancellation exceeds 1/eps^3.
 * A cofactor (a 2x2 determinant) uses Kahan's algorithm, accurate to 2 ulps (Jeannerod, Louvet &
 * Muller 2013).
 *
 * Preconditions: entries of moderate size (after lct::unitScaleExponent scaling), so that the
 * products neither overflow nor underflow.
 */
#ifndef lct_AccurateMinors_h
#define lct_AccurateMinors_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

namespace lct
{

/// ad - bc to 2 ulps (Kahan).
VTKLCT_EXPORT double accurateDeterminant2(double a, double b, double c, double d) noexcept;

/// The cofactor matrix C (C_ij = (-1)^(i+j) minor_ij, so adj A = C^T), each entry to 2 ulps.
VTKLCT_EXPORT Eigen::Matrix3d accurateCofactors(const Eigen::Matrix3d& a) noexcept;

/// det A to a few ulps, from the 24 exact parts of its six triple products.
VTKLCT_EXPORT double accurateDeterminant(const Eigen::Matrix3d& a) noexcept;

/// A^-1 B for a unit-size A (entries at most 1 in magnitude) with det A != 0: every entry from the
/// exact adjugate and exact products, summed like the determinant, then divided by it. The
/// plain product A^-1 B is off by eps cond(A) relative, which for the relative steps of
/// ill-conditioned keys moved their interpolated determinants by 1e-4.
VTKLCT_EXPORT Eigen::Matrix3d accurateInverseTimes(
  const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) noexcept;
/// A^-1 v, likewise.
VTKLCT_EXPORT Eigen::Vector3d accurateInverseTimes(
  const Eigen::Matrix3d& a, const Eigen::Vector3d& v) noexcept;

/// A B with every entry a compensated dot product (Ogita, Rump & Oishi Dot2): as if computed in
/// twice the working precision, then rounded. For an ill-conditioned A the plain product loses
/// the small singular directions of the result to cancellation (eps ||A|| ||B|| absolute).
VTKLCT_EXPORT Eigen::Matrix4d accurateProduct(
  const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) noexcept;

/// det A, by the plain cofactor expansion when that is accurate and by accurateDeterminant when
/// it may not be (|det| < 1e-6 for entries of at most unit size: then cancellation may have left
/// too few digits, or even the wrong sign).
VTKLCT_EXPORT double unitScaleDeterminant(const Eigen::Matrix3d& a) noexcept;

} // namespace lct

#endif
