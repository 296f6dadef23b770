/**
 * @file Ease.h
 * @brief Ease in / ease out as a reparametrisation of time within a key segment: the curve is
 *        unchanged, only the time at which each of its points is reached; keys keep their times.
 *
 * On a segment of duration h, with u = (t - t_i) / h in [0, 1], the curve is evaluated at
 * t_i + h e(u), where e is the cubic Hermite function with e(0) = 0, e(1) = 1 and end slopes
 * 1 - leaving at u = 0 and 1 - arriving at u = 1:
 *   e(u) = (1 - leaving) (u^3 - 2u^2 + u) + (3u^2 - 2u^3) + (1 - arriving) (u^3 - u^2).
 * The speed along the curve is multiplied by e'(u): by 1 - leaving as the motion leaves the
 * segment's first key and by 1 - arriving as it reaches the second (0: from / to rest). With
 * both eases in [0, 1] the slopes lie in Fritsch & Carlson's monotone region (alpha, beta in
 * [0, 1], alpha^2 + beta^2 <= 9), so e is increasing: time never runs backwards. No ease
 * (0, 0) is the identity e(u) = u; full ease (1, 1) is smoothstep 3u^2 - 2u^3.
 * A key whose arriving and leaving eases differ changes speed there (C0 in time, the path
 * itself keeps its smoothness).
 */
#ifndef lct_Ease_h
#define lct_Ease_h

#include "vtkLCTModule.h"

namespace lct
{

/// Whether an ease amount is finite and in [0, 1].
inline bool isValidEase(double ease)
{
  return ease >= 0.0 && ease <= 1.0; // false for NaN
}

/// e(u) for u in [0, 1] (clamped), leaving and arriving eases in [0, 1].
VTKLCT_EXPORT double easeSegment(double u, double leaving, double arriving);

/// The u with easeSegment(u, leaving, arriving) = e, for e in [0, 1] (clamped): when an eased
/// segment reaches a given point of its curve. Bisection to the last bit (e is increasing, and
/// flat only where both eases are 1 at an end, where any u there is an answer).
VTKLCT_EXPORT double inverseEaseSegment(double e, double leaving, double arriving);

} // namespace lct

#endif
