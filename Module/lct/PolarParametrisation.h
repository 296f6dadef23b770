/**
 * @file PolarParametrisation.h
 * @brief Kaji & Ochiai's parametrisation of Aff+(3): psi (log) and phi (exp), eq. 2-3.
 *
 *   phi(l, w, Y) = T(l) exp(hat w) exp(Y)
 *   psi(M)       = (l, log U, log S)   with  U S  the polar decomposition of the linear part.
 *
 * Surjective on Aff+(3); rigid maps are exactly Y = 0 and similarities Y = c I, so blends of
 * rigid keys stay rigid (condition V). The rotation log is principal (angle <= pi) unless a
 * reference rotation vector is given, in which case the branch nearest to it is taken
 * (Kaji & Ochiai Algorithm 1), so spins beyond 2 pi survive.
 */
#ifndef lct_PolarParametrisation_h
#define lct_PolarParametrisation_h

#include "vtkLCTModule.h"

#include "lct/Conditioning.h" // kMaxRotationWinding, the largest |rotation reference|
#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// psi(M). Fails with NonFinite (M or the reference), NotAffine, NegativeDeterminant, Singular,
/// IllConditioned (lct/Conditioning.h) or OutOfRange (a subnormal stretch, or a reference or
/// its nearest branch wound beyond kMaxRotationWinding).
VTKLCT_EXPORT Result<LogCoords> polarLog(
  const Eigen::Matrix4d& m, const Eigen::Vector3d* rotationReference = nullptr);

/// psi(M^-1) from psi(M) = (l, w, Y) without a logarithm, keeping the winding of w exactly:
/// M^-1 = T(-A^-1 l) U^T (U exp(-Y) U^T), so psi(M^-1) = (-A^-1 l, -w, -U Y U^T) with U = exp(w).
/// Fails with OutOfRange when the inverse is not representable.
VTKLCT_EXPORT Result<LogCoords> polarInverse(const LogCoords& c);
/// The same for a caller that has already computed m = polarExp(c).value (vtkLogTransform
/// commits a state with its inverse), without exponentiating c again.
VTKLCT_EXPORT Result<LogCoords> polarInverse(const LogCoords& c, const Eigen::Matrix4d& m);

/// phi(c). Fails with NonFinite (c not finite), InaccurateResult (a turn wound beyond
/// kMaxRotationWinding), OutOfRange (the result overflows, or a stretch underflows below the
/// normal range) or IllConditioned (stretch condition number above kMaxConditionNumber: the
/// result could not hold its smallest stretch).
VTKLCT_EXPORT Result<Eigen::Matrix4d> polarExp(const LogCoords& c);

} // namespace lct

#endif
