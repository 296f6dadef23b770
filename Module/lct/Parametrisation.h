/**
 * @file Parametrisation.h
 * @brief log and exp in the chosen parametrisation (see LogCoords.h).
 */
#ifndef lct_Parametrisation_h
#define lct_Parametrisation_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// The log coordinates of an affine matrix. With a `reference`, the Polar rotation part is
/// the branch nearest to the reference's rotation part (Kaji & Ochiai Algorithm 1); the
/// MatrixLog parametrisation has only its principal branch and ignores it.
VTKLCT_EXPORT Result<LogCoords> logarithm(
  const Eigen::Matrix4d& m, Parametrisation p, const LogCoords* reference = nullptr);

/// The affine matrix of log coordinates. Fails with NonFinite, OutOfRange, IllConditioned,
/// MagnitudeOutOfRange (MatrixLog only) or InaccurateResult, a turn wound beyond
/// kMaxRotationWinding (see polarExp / matrixExp).
VTKLCT_EXPORT Result<Eigen::Matrix4d> exponential(const LogCoords& c, Parametrisation p);

/// For a failure in p that the other parametrisation would not have (MatrixLog: no real
/// logarithm, or magnitudes beyond its range), a parenthesised hint to switch to Polar; else "".
/// Messages never advise what is already in use.
VTKLCT_EXPORT const char* adviceFor(Status status, Parametrisation p) noexcept;

/// "Polar" or "MatrixLog".
VTKLCT_EXPORT const char* name(Parametrisation p) noexcept;

} // namespace lct

#endif
