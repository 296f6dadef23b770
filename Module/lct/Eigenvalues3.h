/**
 * @file Eigenvalues3.h
 * @brief Eigenvalues of 3x3 matrices by the cubic formula (no iteration).
 *
 * Kaji & Ochiai §4.2: the eigenvalues are the roots of the characteristic polynomial. The
 * matrix is shifted by trace/3 first so that the depressed cubic y^3 + p y + q is formed
 * from the shifted entries, which keeps the coefficients accurate.
 * - Symmetric input: p = -tr(B^2)/2 is a sum of squares and the trigonometric solution
 *   gives every eigenvalue to about eps * ||A|| (absolute), coincident ones included.
 * - General input: one real root and a complex pair (Cardano), or three real roots
 *   (trigonometric). Near a double root, roots of a polynomial are only accurate to
 *   sqrt(eps); the matrix functions built on them stay accurate because the Hermite
 *   interpolant depends smoothly on the nodes, except near the branch cut of log, which
 *   `MatrixLog` detects and checks a posteriori.
 */
#ifndef lct_Eigenvalues3_h
#define lct_Eigenvalues3_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

#include <complex>

namespace lct
{

/// Eigenvalues of the symmetric part of A (only the upper triangle is read), in
/// descending order.
VTKLCT_EXPORT Eigen::Vector3d symmetricEigenvalues(const Eigen::Matrix3d& a);

/// Eigenvalues of a general real 3x3 matrix.
struct GeneralEigenvalues
{
  /// When `complexPair`, values[0] and values[1] are the conjugate pair (imag(values[0]) > 0)
  /// and values[2] is real; otherwise all three are real, in descending order.
  std::complex<double> values[3];
  bool complexPair = false;
};

VTKLCT_EXPORT GeneralEigenvalues generalEigenvalues(const Eigen::Matrix3d& a);

} // namespace lct

#endif
