/**
 * @file AffineExp.h
 * @brief exp of an affine log [L t; 0 0] of moderate size by scaling and squaring a Taylor
 *        polynomial: Alexa's exp (MatrixLog parametrisation) without a Schur form.
 *
 * exp([L t; 0 0]) = [e^L, phi1(L) t; 0 1] with phi1(z) = (e^z - 1) / z. With N = [L t; 0 0] and
 * s the least integer with ||L||_1 2^-s <= kTaylorRadius,
 *
 *   exp(N) = T16(N 2^-s)^(2^s),   T16(Y) = sum_{k=0}^{16} Y^k / k!,
 *
 * the polynomial evaluated by Paterson & Stockmeyer's scheme in Y^4 (6 products of 4x4 blocks)
 * and squared s times (Higham, "Functions of Matrices", §10.3 and §4.2). The truncation error is
 * below ||Y||^17 / 17! (1 + ...) <= 2^-53 for ||Y||_1 <= kTaylorRadius, in the linear block and,
 * relative to |t|, in the translation (the powers' last column is L^(k-1) t, so t is scaled to
 * unit size beforehand and back after, exactly, and no size of t overflows on the way).
 *
 * The squarings can multiply rounding errors by up to ||e^(L 2^-j)||^(2^j) / ||e^L|| (at most
 * e^(2 ||L||), a bound that normal logs never approach), so the path is taken only for
 * ||L||_1 <= kAffineExpNormLimit: every turn up to 5.6 rad (8 / sqrt 2), stretches up to e^8.
 * There, on seven classes of logs (turns, stretches, similarities, Gaussian, shears, small
 * determinants, the "hump" of a shear over a negative diagonal), its error against a long-double
 * oracle is at or below that of the Schur form and divided differences
 * (Testing/Unit/TestAffineExp.cxx: 4.6e-15 at most, where the Schur path reaches 1.2e-14); larger
 * logs go through the Schur path (lct/MatrixLogParametrisation.h), which keeps its accuracy at any
 * size.
 */
#ifndef lct_AffineExp_h
#define lct_AffineExp_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

namespace lct
{

/// ||Y||_1 of the scaled block below which the degree-16 Taylor polynomial is exact to 2^-53.
constexpr double kTaylorRadius = 0.8;

/// The largest ||L||_1 for which affineExpBySquaring evaluates (see above).
constexpr double kAffineExpNormLimit = 8.0;

/// exp([L t; 0 0]) into `linear` (e^L) and `translation` (phi1(L) t). False, with the outputs
/// untouched, when ||L||_1 > kAffineExpNormLimit or an input is not finite; the outputs can still
/// be non-finite for a translation near the end of the double range (callers check).
VTKLCT_EXPORT bool affineExpBySquaring(const Eigen::Matrix3d& l, const Eigen::Vector3d& t,
  Eigen::Matrix3d& linear, Eigen::Vector3d& translation);

} // namespace lct

#endif
