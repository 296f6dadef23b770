/**
 * @file MatrixLogParametrisation.h
 * @brief Alexa's parametrisation: the principal logarithm of the whole 4x4 affine matrix.
 *
 * log [A t; 0 1] = [log A, g(A) t; 0 0]  with g(x) = log(x)/(x - 1) = log[x, 1]
 * exp [L u; 0 0] = [exp L, h(L) u; 0 1]  with h(x) = (e^x - 1)/x  = exp[x, 0]
 *
 * exp of a log with ||L||_1 <= kAffineExpNormLimit (turns up to 5.6 rad, stretches up to e^8)
 * is a scaled and squared Taylor polynomial (lct/AffineExp.h), as accurate there and ~4-10x
 * faster. Larger exps, and every log, are evaluated on the real Schur form A = Q T Q^T (Eigen's
 * RealSchur): every entry of f(T) is a sum of products of T's entries with divided differences
 * of f at the eigenvalues (and at the extra node 1 for log, 0 for exp, which gives the
 * translation block), accurate for close and coincident eigenvalues (lct/DividedDifferences.h).
 * Nothing is formed as a polynomial in A itself, which would cancel for spread spectra
 * (diag(1e-6, 1, 1e6) lost 4 digits that way; the Taylor path's spectra stay within e^+-8).
 * Alexa App. A: a real logarithm exists only without negative real eigenvalues; such input fails
 * with NoRealLogarithm. Near the negative real axis the log is ill-conditioned, so there the
 * result is checked a posteriori (exp(log M) against M) and refused if inaccurate. Domain:
 * condition number up to kMaxConditionNumber (IllConditioned beyond) and eigenvalue magnitudes
 * within 1e-135 .. 1e135 (MagnitudeOutOfRange beyond; the Polar parametrisation has no such
 * limit).
 */
#ifndef lct_MatrixLogParametrisation_h
#define lct_MatrixLogParametrisation_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// The principal log of M in LogCoords layout. Fails with NonFinite, NotAffine,
/// NegativeDeterminant, Singular, IllConditioned, MagnitudeOutOfRange or NoRealLogarithm.
VTKLCT_EXPORT Result<LogCoords> matrixLog(const Eigen::Matrix4d& m);

/// exp of the 4x4 log matrix held by c. Fails with NonFinite (c), OutOfRange (the result
/// overflows or underflows), MagnitudeOutOfRange (a representable result whose eigenvalue
/// magnitudes lie outside 1e-135 .. 1e135), IllConditioned (the result's condition number exceeds
/// kMaxConditionNumber) or InaccurateResult (a turn wound beyond kMaxRotationWinding: an
/// eigenvalue of the linear part with an imaginary part above 1e9).
VTKLCT_EXPORT Result<Eigen::Matrix4d> matrixExp(const LogCoords& c);

/// The principal power M^s = exp(s log M) (Alexa's s (.) M). Near the identity
/// (||M - I||_F < 1/4) and for |s| <= 2 it sums the binomial series (I + E)^s = sum_k binom(s, k)
/// E^k, which converges geometrically and needs no eigenvalues; elsewhere it is matrixExp(s
/// matrixLog(M)). Fails like matrixLog.
VTKLCT_EXPORT Result<Eigen::Matrix4d> matrixPower(const Eigen::Matrix4d& m, double s);

/// The 3x3 log matrix (skew + symmetric part) held by c.
VTKLCT_EXPORT Eigen::Matrix3d logLinearPart(const LogCoords& c);

} // namespace lct

#endif
