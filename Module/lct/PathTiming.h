/**
 * @file PathTiming.h
 * @brief The timing controls of a keyframe path, shared by the interpolators: Kochanek-Bartels
 *        tangents per key or per path (lct/KochanekBartels.h), eases per key or at the path's
 *        ends (lct/Ease.h), and the constant-speed reparametrisation (lct/ArcLength.h).
 *
 * A curve point is computed at a curve time: with the eases, output time t on segment i maps to
 * t_i + h e(u) with the leaving ease of key i and the arriving ease of key i + 1, so keys keep
 * their times; with constant speed the output time is first eased over the whole path (EaseIn,
 * EaseOut as the leaving ease of the path's start and the arriving ease of its end) and then
 * mapped by arc length, so keys are passed at the times their distance along the path gives
 * and the per-key eases (which the constant speed would undo) do not apply.
 */
#ifndef lct_PathTiming_h
#define lct_PathTiming_h

#include "lct/Curves.h"
#include "lct/Ease.h"
#include "lct/KochanekBartels.h"

#include <algorithm>

namespace lct
{

/// The timing a user set on one key.
struct KeyTiming
{
  /// The key's own tension, continuity and bias (else the path's).
  bool hasTensionContinuityBias = false;
  TensionContinuityBias tensionContinuityBias;
  /// Eases of the motion arriving at the key and leaving it, in [0, 1] (After Effects' ease in
  /// and ease out of a keyframe).
  double arrivingEase = 0.0;
  double leavingEase = 0.0;
};

/// The timing settings of a whole path.
struct PathTiming
{
  /// For every key without its own.
  TensionContinuityBias tensionContinuityBias;
  /// The path starts slowly (the first key's leaving ease) / ends slowly (the last key's
  /// arriving ease), in [0, 1]; a key's own eases take the larger of the two.
  double easeIn = 0.0;
  double easeOut = 0.0;
  bool constantSpeed = false;
};

/// The tension, continuity and bias that apply at a key with timing `key`.
inline const TensionContinuityBias& tensionContinuityBiasOf(
  const KeyTiming& key, const PathTiming& path)
{
  return key.hasTensionContinuityBias ? key.tensionContinuityBias : path.tensionContinuityBias;
}

/// The curve time of output time t from the eases alone (no constant speed). `timingOf(k)`
/// gives key k's KeyTiming. Keys map to themselves.
template <typename TimingOf>
double easedCurveTime(
  const double* times, int keyCount, double t, const PathTiming& path, TimingOf&& timingOf)
{
  if (keyCount < 2)
  {
    return t;
  }
  t = std::clamp(t, times[0], times[keyCount - 1]);
  const int i = curveSegment(times, keyCount, t);
  double leaving = timingOf(i).leavingEase;
  double arriving = timingOf(i + 1).arrivingEase;
  if (i == 0)
  {
    leaving = std::max(leaving, path.easeIn);
  }
  if (i + 1 == keyCount - 1)
  {
    arriving = std::max(arriving, path.easeOut);
  }
  if (leaving == 0.0 && arriving == 0.0)
  {
    return t;
  }
  const double h = times[i + 1] - times[i];
  const double eased = times[i] + h * easeSegment((t - times[i]) / h, leaving, arriving);
  return std::clamp(eased, times[i], times[i + 1]);
}

/// The path-wide ease of constant speed: output time t in [first, last] eased as one segment.
inline double easedPathTime(double first, double last, double t, const PathTiming& path)
{
  if (!(last > first) || (path.easeIn == 0.0 && path.easeOut == 0.0))
  {
    return std::clamp(t, first, last);
  }
  const double u = (std::clamp(t, first, last) - first) / (last - first);
  return std::clamp(
    first + (last - first) * easeSegment(u, path.easeIn, path.easeOut), first, last);
}

/// The output time t with easedPathTime(first, last, t, path) = eased: when a path under
/// constant speed passes the point that the uneased arc-length time `eased` reaches.
inline double inverseEasedPathTime(double first, double last, double eased, const PathTiming& path)
{
  if (!(last > first) || (path.easeIn == 0.0 && path.easeOut == 0.0))
  {
    return std::clamp(eased, first, last);
  }
  const double e = (std::clamp(eased, first, last) - first) / (last - first);
  return std::clamp(
    first + (last - first) * inverseEaseSegment(e, path.easeIn, path.easeOut), first, last);
}

/// The Spline tangents of segment `segment` (0 <= segment < keyCount - 1): Kochanek-Bartels at a
/// key whose tension, continuity and bias are not all 0, else `defaultTangent(k)` (Catmull-Rom, or
/// the monotone tangent of lct/MonotoneTangents.h).
template <typename TimingOf, typename DefaultTangent>
SegmentTangents splineTangents(const double* times, int keyCount, int segment,
  const PathTiming& path, TimingOf&& timingOf, DefaultTangent&& defaultTangent)
{
  if (keyCount < 2)
  {
    return {}; // one key: no segment, no tangent
  }
  const auto at = [&](int k, bool leaving) {
    const TensionContinuityBias& tcb = tensionContinuityBiasOf(timingOf(k), path);
    if (tcb.isZero())
    {
      return KeyTangent(defaultTangent(k));
    }
    const KeyTangents tangents = kochanekBartelsTangents(times, keyCount, k, tcb);
    return leaving ? tangents.leaving : tangents.arriving;
  };
  return { at(segment, true), at(segment + 1, false) };
}

} // namespace lct

#endif
