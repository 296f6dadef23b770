/**
 * @file MonotoneTangents.h
 * @brief Spline tangents in log space that do not overshoot where the motion slows down, stops
 *        or turns back at a key: Fritsch & Butland's harmonic-mean tangent, for vectors.
 *
 * Catmull-Rom's tangent at a key is the time-weighted mean of the neighbouring secants, so after
 * a long step and before a short one (keys at 0, 179.9 and 180 degrees, one time unit apart) the
 * curve swings 11 degrees past 180, and on motion capture its max error exceeds Linear's.
 * Fritsch & Butland ("A method for constructing local monotone piecewise cubic interpolants",
 * SIAM J. Sci. Stat. Comput. 5(2), 1984) take the harmonic mean 2 d- d+ / (d- + d+) of the
 * secants d-, d+ of scalar data (0 where they differ in sign), which lies in Fritsch & Carlson's
 * monotone region (0 <= m <= 3 min(d-, d+); SIAM J. Numer. Anal. 17(2), 1980). Written as
 * m = (|d+| d- + |d-| d+) / (|d-| + |d+|), each secant weighted by the other's speed, it applies
 * to the secant vectors of the log steps at a key (x[k +- 1] - x[k] = log(K_k^-1 K_(k +- 1)),
 * in the key's own frame): it is that harmonic mean where they are parallel, 0 where they are
 * opposite, |m| <= 2 min(|d-|, |d+|) always, and equal to their mean where the speeds agree.
 * The speeds combine the translation and the linear part (rotation and stretch, both unit-free
 * logs) of the logs, each made unit-free by its own scale |d-| + |d+|; a part whose steps are at
 * round-off level (1e-12 of the steps' largest entry) is left out, so that noise does
 * not steer the tangent. The tangent is a combination of the two secants
 * (lct::KeyTangent), so a curve point is still ONE weighted combination of the keys (then one
 * exp); every key is reproduced and the curve is C1 (a key's tangent is its own, the same on
 * both of its segments).
 */
#ifndef lct_MonotoneTangents_h
#define lct_MonotoneTangents_h

#include "vtkLCTModule.h"

#include "lct/Curves.h"
#include "lct/LogCoords.h"

namespace lct
{

/// The tangent at a key: `previous` = log(K^-1 K_prev), `next` = log(K^-1 K_next), `hPrevious`,
/// `hNext` > 0 the time steps to them. Catmull-Rom's when a time step is not positive and
/// finite, a log is not finite, or the key's neighbours do not move.
VTKLCT_EXPORT KeyTangent monotoneTangent(
  const LogCoords& previous, const LogCoords& next, double hPrevious, double hNext);

} // namespace lct

#endif
