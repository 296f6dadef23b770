/**
 * @file Combination.h
 * @brief Linear combinations of transformations in log space (Alexa eq. 5-7,
 *        Kaji & Ochiai eq. 9) and the relative form (Hawkins & Grimm eq. 7).
 *
 *   r (.) A            = exp(r log A)
 *   A (+) B            = exp(log A + log B)
 *   (+)_i w_i (.) T_i  = exp(sum_i w_i log T_i)
 *
 * The absolute form combines the logs of the keys themselves. The relative form combines the
 * logs of the steps from a reference key R to the keys and applies the sum to R (weights summing
 * to 1), so that R sits at the identity, where both logs are best conditioned, and rotations
 * between a key and R are taken the short way. Hawkins & Grimm put the key with the largest
 * weight at the identity. The step (relativeLog, applyRelativeStep): MatrixLog, R^-1 T_i,
 * applied as R exp(.); Polar, [L_i L_r^-1, t_i - t_r] in world axes (lct::worldStep), applied as
 * [E L_r, t_r + d], so the translation combines as sum_i w_i t_i and the linear part stays within
 * the keys' stretches (lct/KeyLogs.h says why not R^-1 T_i).
 */
#ifndef lct_Combination_h
#define lct_Combination_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <cstddef>

namespace lct
{

/// sum_i weights[i] * coords[i]
VTKLCT_EXPORT LogCoords weightedSum(
  const double* weights, const LogCoords* coords, std::size_t count) noexcept;

/// (1 - t) a + t b
inline LogCoords lerp(const LogCoords& a, const LogCoords& b, double t)
{
  return (1.0 - t) * a + t * b;
}

/// exp(sum_i w_i log T_i). Fails when a key has no log or the result is not finite.
VTKLCT_EXPORT Result<Eigen::Matrix4d> combine(
  const double* weights, const Eigen::Matrix4d* keys, std::size_t count, Parametrisation p);

/// The log in p of the step from `reference` to `key` (Polar: lct::worldStep, MatrixLog:
/// reference^-1 key): every relative log a KeyLogs holds or a check computes is this one
/// computation. A step that overflows is OutOfRange.
VTKLCT_EXPORT Result<LogCoords> relativeLog(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& key, Parametrisation p);

/// The point that `step`, the exp of a combination of relativeLog's, reaches from `reference`:
/// Polar, lct::applyWorldStep; MatrixLog, reference * step. `accurate`:
/// lct::needsAccurateProducts(reference).
VTKLCT_EXPORT Eigen::Matrix4d applyRelativeStep(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& step, Parametrisation p, bool accurate);

/// The relative form about R = keys[reference] (Hawkins & Grimm eq. 7, lct/KeyLogs.h): Polar,
/// the steps in world axes, exp(sum_i w_i log [L_i L_r^-1, t_i - t_r]) applied to R as
/// [E L_r, t_r + d] (lct::worldStep), so the translation combines as sum_i w_i t_i and the
/// linear part stays within the keys' stretches; MatrixLog, R exp(sum_i w_i log(R^-1 T_i)), the
/// same on either side.
VTKLCT_EXPORT Result<Eigen::Matrix4d> combineRelative(const double* weights,
  const Eigen::Matrix4d* keys, std::size_t count, std::size_t reference, Parametrisation p);

/// The index of the largest weight (the first one on ties); 0 when count is 0.
VTKLCT_EXPORT std::size_t largestWeight(const double* weights, std::size_t count) noexcept;

} // namespace lct

#endif
