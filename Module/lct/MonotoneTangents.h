/**
 * @file MonotoneTangents.h
 * @brief Spline tangents in log space that do not overshoot where the motion slows down, stops
 *        or turns back at a key: Fritsch & Butland's harmonic-mean tangent, for vectors.
 *
 * Catmull-Rom's tangent at a key is the time-weighted mean of the neighbouring secants, so after
 * a long step and before a short one (keys at 0, 179.9 and 180 degrees, one time unit apart) the
 * curve swings 13 degrees past 180 (the issue measured ~11), and on motion capture its max error
 * exceeds Linear's. Fritsch & Butland ("A method for constructing local monotone piecewise cubic
 * interpolants", SIAM J. Sci. Stat. Comput. 5(2), 1984) take the harmonic mean 2 d- d+ / (d- + d+)
 * of the secants d-, d+ of scalar data (0 where they differ in sign), which lies in Fritsch &
 * Carlson's monotone region (0 <= m <= 3 min(d-, d+); SIAM J. Numer. Anal. 17(2), 1980). Written as
 * m = (|d+| d- + |d-| d+) / (|d-| + |d+|), each secant weighted by the other's speed, it applies
 * to the secant vectors of the log steps at a key (x[k +- 1] - x[k] = the log of the step from
 * K_k to K_(k +- 1), lct::relativeLog, as the curve combines them): it is that harmonic
 * mean where they are parallel, 0 where they are opposite, |m| <= 2 min(|d-|, |d+|) always, and
 * equal to their mean where the speeds agree. The speeds combine the translation and the linear
 * part (rotation and stretch, both unit-free logs) of the logs, each made unit-free by its own
 * scale |d-| + |d+|; a part whose steps are at round-off level (1e-12 of the steps' largest entry)
 * is left out, so that noise does not steer the tangent. The tangent is a combination of the two
 * secants (lct::KeyTangent), so a curve point is still ONE weighted combination of the keys (then
 * one exp); every key is reproduced and the curve is C1 (a key's tangent is its own, the same on
 * both of its segments).
 */
#ifndef lct_MonotoneTangents_h
#define lct_MonotoneTangents_h

#include "vtkLCTModule.h"

#include "lct/CameraKey.h"
#include "lct/Curves.h"
#include "lct/LogCoords.h"

namespace lct
{

/// The tangent at a key: `previous` = log(K^-1 K_prev), `next` = log(K^-1 K_next), `hPrevious`,
/// `hNext` > 0 the time steps to them. Catmull-Rom's when a time step is not positive and
/// finite, a log is not finite, or the key's neighbours do not move.
VTKLCT_EXPORT KeyTangent monotoneTangent(
  const LogCoords& previous, const LogCoords& next, double hPrevious, double hNext);

/// A part of a step whose norm is at most this fraction of the steps' largest entry is round-off.
constexpr double kRoundOffPart = 1e-12;

/// The same tangent from the steps' parts, each part's entries of one unit (a length; unit-free
/// logs): `partBefore[g]`, `partAfter[g]` the Euclidean norms of part g of the steps to the
/// previous and the next key; parts at or below `roundOff` are left out. Catmull-Rom's when a time
/// step is not positive and finite, a norm is not finite, or no part moves. Cameras use it with
/// their own parts (lct::monotoneCameraTangents).
VTKLCT_EXPORT KeyTangent monotoneTangentOfParts(const double* partBefore, const double* partAfter,
  int partCount, double roundOff, double hPrevious, double hNext);

/// Impacts: where the motion turns back at a key that it reaches and leaves FASTER than it moves
/// on the steps around it (a bounce, a strike, a glitch in a recording), the key is a corner of
/// the motion, not the slow turn of a swing. The monotone tangent there is ~0 (the turn), and a
/// cubic dwells near the key for about a third of each segment beside it: on CMU 01_03 (keys
/// every 8 frames) a foot keyed on a tracking glitch read 27.5 degrees two frames later where the
/// recording has 24.2 and Linear 23.1: the pooled max error 8.02 % against Linear's 7.55 %. Such a
/// key's segments are made nearly straight (the rational cubic of lct::SegmentTangents, shape up to
/// kImpactShape) with the same keys and tangents, so still C1 and without overshoot. A smooth turn
/// is reached slowly (a sampled sine at its crest: the inner steps are slower than the outer ones),
/// and a swing keyed at its extremes (0, 30, 0, 30 degrees) at the same speed throughout: neither
/// changes.

/// Inner speed over outer speed at which a reversal starts to count as an impact, and at which it
/// counts fully (chosen on the motion capture benchmark, where 8 of the 9 combinations of an
/// onset of 1.25-1.75 and a width of 0.5-2 meet issue #12's goal; README).
constexpr double kImpactOnset = 1.5;
constexpr double kImpactFull = 2.5;
/// The shape r of a segment beside a full impact (3 is the cubic).
constexpr double kImpactShape = 203.0;

/// How much key k is an impact, in [0, 1]: for the translation and for the linear part of the
/// steps (each on its own, the larger counts), (cos of the turn)^4 (1 where the motion turns
/// straight back, 0 where it turns by 90 degrees or less) times the ramp from kImpactOnset to
/// kImpactFull of min(inner speeds) / max(outer speeds). `previous` = log(K_k^-1 K_(k-1)),
/// `next` = log(K_k^-1 K_(k+1)) (lct::relativeLog, as for monotoneTangent), `outerPrevious` =
/// log(K_(k-1)^-1 K_(k-2)), `outerNext` = log(K_(k+1)^-1 K_(k+2)); `times` = t[k-2] .. t[k+2],
/// strictly increasing. A part whose inner steps are at round-off level (kRoundOffPart) does not
/// count; non-finite steps or times give 0.
VTKLCT_EXPORT double impactWeight(const LogCoords& outerPrevious, const LogCoords& previous,
  const LogCoords& next, const LogCoords& outerNext, const double times[5]);

/// The shape of the segment between keys of impact weights `start` and `end`.
inline double impactSegmentShape(double start, double end)
{
  return 3.0 + (kImpactShape - 3.0) * (start > end ? start : end);
}

/// The parts of a camera key (lct/CameraKey.h) that are interpolated each with its own curve
/// weights, so with its own tangent: the orientation, the focal point, and the channel groups
/// that move together (the distance, the view angle, the parallel scale, the window centre, the
/// view shear, the clipping range).
enum CameraPart
{
  CameraOrientation = 0,
  CameraFocalPoint,
  CameraDistance,
  CameraViewAngle,
  CameraParallelScale,
  CameraWindowCenter,
  CameraViewShear,
  CameraClippingRange,
  CameraPartCount
};
/// The part of channel c (a CameraKey::Channel).
VTKLCT_EXPORT CameraPart cameraChannelPart(int channel);

/// The monotone tangent of each part at a camera key.
struct CameraTangents
{
  KeyTangent part[CameraPartCount];
};

/// The tangents at camera key `key` between `previous` and `next`, whose orientations differ
/// from the key's by the rotation vectors `rotationBefore`, `rotationAfter` (in the key's
/// frame), each part's from its own steps: a part that stops, slows down or turns back at the
/// key does not overshoot, whatever the others do (a camera that orbits, then only pans, or only
/// zooms, then turns; Catmull-Rom's tangent, or one tangent for several parts, would swing the
/// still one). The steps are unit-free: the turn in radians, the focal point's in units of the
/// key's distance, the channels as they are (logs, or relative to the viewport), so the tangents
/// do not change with the scene's scale; steps within round-off of their values (1e-12 rad,
/// 1e-12 of the focal points' coordinates) count as still.
VTKLCT_EXPORT CameraTangents monotoneCameraTangents(const CameraKey& previous, const CameraKey& key,
  const CameraKey& next, const Eigen::Vector3d& rotationBefore,
  const Eigen::Vector3d& rotationAfter, double hPrevious, double hNext);

} // namespace lct

#endif
