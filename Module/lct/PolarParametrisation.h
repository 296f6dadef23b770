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

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// psi(M). Fails with NonFinite, NotAffine, NegativeDeterminant, Singular, IllConditioned
/// (lct/Conditioning.h) or OutOfRange (a subnormal stretch).
VTKLCT_EXPORT Result<LogCoords> polarLog(
  const Eigen::Matrix4d& m, const Eigen::Vector3d* rotationReference = nullptr);

/// phi(c). Fails with NonFinite (c not finite), OutOfRange (the result overflows, or a stretch
/// underflows below the normal range) or IllConditioned (stretch condition number above
/// kMaxConditionNumber: the result could not hold its smallest stretch).
VTKLCT_EXPORT Result<Eigen::Matrix4d> polarExp(const LogCoords& c);

} // namespace lct

#endif
