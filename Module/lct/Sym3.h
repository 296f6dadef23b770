/**
 * @file Sym3.h
 * @brief exp of a symmetric 3x3 matrix; log and sqrt of a symmetric positive definite one.
 *
 * Kaji & Ochiai §4.2 and App. B (eq. 6, 7): with the eigenvalues l1 >= l2 >= l3 from the
 * cubic formula and Z = Y - l2 I,
 *
 *   f(Y) = f[l2] I + f[l2,l1] Z + f[l2,l1,l3] Z (Z - (l1 - l2) I),
 *
 * which is the paper's a I + b Z + c Z^2 in Newton form. No eigenvectors are needed. The
 * divided differences come from `dividedDifferences`, which sums Taylor series where the
 * eigenvalues nearly coincide, so the result keeps full accuracy there too (the naive form
 * of eq. 7 loses about six digits).
 *
 * exp of a Y whose traceless part Z is moderate (||Z||_F <= 4: stretches up to ~e^3.3, every
 * relative log of interpolation) skips the cubic: Cayley-Hamilton (Z^3 = p Z + q I) folds the
 * exponential series of Z 2^-s (||Z 2^-s||_F <= 1) onto three scalars, squared s times on those
 * scalars, e^(tr Y / 3) (a I + b Z + c Z^2).
 *
 * Spread spectra (condition number above kClosedFormConditionLimit, lct/Conditioning.h) are
 * evaluated from the eigenvectors of a backward-stable solver instead (cyclic Jacobi,
 * lct/SymmetricEigen3.h): the Newton form would build the smallest eigenvalue's part from terms
 * the size of the largest. Input of any magnitude is scaled by a power of two (exact).
 *
 * Accuracy: about eps * cond(Y) relative; see Testing/Unit/TestSym3.cxx for the measured
 * errors against Eigen's MatrixFunctions.
 */
#ifndef lct_Sym3_h
#define lct_Sym3_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// exp(Y) for symmetric Y (the upper triangle is read). Entries overflow to Inf when an
/// eigenvalue exceeds log(DBL_MAX); callers check. With `eigenvalueBounds`, receives a lower
/// and an upper bound of Y's eigenvalues (the extreme eigenvalues themselves when Y is not
/// near a multiple of I), so callers can tell an underflowing or ill-conditioned result.
VTKLCT_EXPORT Eigen::Matrix3d expSym(
  const Eigen::Matrix3d& y, Eigen::Vector2d* eigenvalueBounds = nullptr);

/// The symmetric logarithm of an SPD matrix, of any magnitude. Fails with NonFinite,
/// Singular (an eigenvalue not positive), IllConditioned (lambda_max / lambda_min above
/// kMaxConditionNumber) or OutOfRange.
VTKLCT_EXPORT Result<Eigen::Matrix3d> logSPD(const Eigen::Matrix3d& s);

/// The SPD square root of an SPD matrix; fails like `logSPD`.
VTKLCT_EXPORT Result<Eigen::Matrix3d> sqrtSPD(const Eigen::Matrix3d& s);

/// log S by the closed form about given eigenvalues (descending, as from symmetricEigenvalues):
/// for callers that already have them and know S is well-conditioned (cond <=
/// kClosedFormConditionLimit, eigenvalues positive).
VTKLCT_EXPORT Eigen::Matrix3d logSPDClosedForm(const Eigen::Matrix3d& s, const Eigen::Vector3d& l);

/// sym(3) as 6 numbers (xx, yy, zz, xy, yz, xz) and back.
using SymmetricVector = Eigen::Matrix<double, 6, 1>;
inline SymmetricVector toSymmetricVector(const Eigen::Matrix3d& y)
{
  SymmetricVector v;
  v << y(0, 0), y(1, 1), y(2, 2), 0.5 * (y(0, 1) + y(1, 0)), 0.5 * (y(1, 2) + y(2, 1)),
    0.5 * (y(0, 2) + y(2, 0));
  return v;
}
inline Eigen::Matrix3d fromSymmetricVector(const SymmetricVector& v)
{
  Eigen::Matrix3d y;
  y << v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2];
  return y;
}

} // namespace lct

#endif
