/**
 * @file Curves.h
 * @brief Keyframe curve schemes as weights over keys: every curve point is ONE weighted
 *        combination of keys, which the parametrisations turn into one exp (Alexa §6.1,
 *        Hawkins & Grimm §3.3).
 *
 * Key times must be strictly increasing with a finite span (last - first representable: the
 * interpolators refuse keys that would break it); t is clamped to [first, last].
 * - Linear: (1 - u, u) on the segment holding t.
 * - CatmullRom: the interpolating C1 cubic Hermite spline with tangents
 *   (p[i+1] - p[i-1]) / (t[i+1] - t[i-1]) on non-uniform times (one-sided at the ends), the
 *   scheme of VTK's default Kochanek spline with zero tension, bias and continuity.
 * - BSpline: the approximating uniform cubic B-spline over the key index (Hawkins & Grimm
 *   §3.3.1 use degree 2; the cubic is C2), with reflected phantom keys
 *   p[-1] = 2 p[0] - p[1] so that the curve starts and ends on the end keys.
 * - Subdivision: the limit of the 4-point scheme (-1/16, 9/16, 9/16, -1/16), i.e. the
 *   Deslauriers-Dubuc fundamental function (support [-3, 3]) over the key index, sampled once
 *   at 2^-10 and interpolated by C1 cubic Hermite pieces; interpolating and C1. Boundary keys by
 * the corrected reflection log M[-1] = 2 log M[0] - log M[1] (SEEDS.md erratum to Hawkins & Grimm
 * eq. 11).
 * - Bezier: Alexa §6.1, cubic Bezier segments whose tangents are given by control transforms.
 *   Its weights refer to the sequence of 3 (n - 1) + 1 points K0, C0+, C1-, K1, C1+, C2-, K2, ...
 *   (key i is point 3 i; C_i+ and C_(i+1)- are the control points of segment i), with the
 *   Bernstein weights of u on segment i. Interpolating; C1 where C_i- , K_i, C_i+ are collinear
 *   in log space with proportional spacing.
 * BSpline and Subdivision map time to the key index piecewise-linearly, so with non-uniform key
 * times they are C1 in the index and C0 in time at the keys.
 */
#ifndef lct_Curves_h
#define lct_Curves_h

#include "vtkLCTModule.h"

#include <cstddef>

namespace lct
{

enum class CurveScheme
{
  Linear,
  CatmullRom,
  BSpline,
  Subdivision,
  Bezier
};

/// A sparse weight vector over keys (at most 8 keys carry weight at any t).
struct CurveWeights
{
  static constexpr int kCapacity = 8;
  int count = 0;
  int key[kCapacity];
  double weight[kCapacity];

  /// Adds w to the weight of key k (merging with an existing entry).
  void add(int k, double w);
};

/// The weights of the curve point at time t. Preconditions: keyCount >= 1, times strictly
/// increasing (callers validate). With one key, that key has weight 1. For Bezier the weights
/// index the key-and-control sequence described above, not the keys.
VTKLCT_EXPORT CurveWeights curveWeights(
  CurveScheme scheme, const double* times, int keyCount, double t);

/// The tangent at a key k as a combination of its two secants, m = before (x[k] - x[k-1]) / h-
/// + after (x[k+1] - x[k]) / h+ (h-, h+ the time steps). Catmull-Rom on non-uniform times is
/// before = h- / (h- + h+), after = h+ / (h- + h+): m = (x[k+1] - x[k-1]) / (t[k+1] - t[k-1]).
/// At the first key only `after` counts, at the last only `before` (there is no other secant).
struct KeyTangent
{
  double before = 0.5;
  double after = 0.5;
};
/// Catmull-Rom's KeyTangent at key k of keyCount keys (one-sided at the ends: the secant).
VTKLCT_EXPORT KeyTangent catmullRomTangent(const double* times, int keyCount, int k);

/// The tangents of the Hermite segment holding t, at its first key (`start`, key
/// curveSegment(t)) and at the next (`end`), for CatmullRom (the other schemes ignore them).
/// A key's tangent must be the same on both segments beside it for the curve to be C1.
///
/// `shape` is r of Delbourgo & Gregory's rational cubic Hermite segment ("Shape preserving
/// piecewise rational interpolation", SIAM J. Sci. Stat. Comput. 6(4), 1985):
///   p(u) = [p0 (1-u)^3 + (r p0 + h m0) u (1-u)^2 + (r p1 - h m1) u^2 (1-u) + p1 u^3]
///          / (1 + (r - 3) u (1 - u)).
/// r = 3 is the cubic; any r >= 3 keeps the keys, the tangents (so C1 with the neighbouring
/// segments) and the sum of the weights (1), and shrinks every tangent term by the denominator
/// (>= 1), so the curve tends to the chord as r grows, leaving it only within ~1/r of the
/// segment beside each key. Values below 3 (or not finite) count as 3.
struct SegmentTangents
{
  KeyTangent start;
  KeyTangent end;
  double shape = 3.0;
};
/// CatmullRom with the given tangents (e.g. lct::monotoneTangent); with catmullRomTangent at both
/// keys it equals curveWeights(CatmullRom, ...).
VTKLCT_EXPORT CurveWeights curveWeights(
  CurveScheme scheme, const double* times, int keyCount, double t, const SegmentTangents& tangents);

/// The segment i with times[i] <= t <= times[i + 1] that curveWeights uses for t (t clamped to
/// the keys; 0 with fewer than two keys).
VTKLCT_EXPORT int curveSegment(const double* times, int keyCount, double t);

/// The number of segments of keyCount keys (1 for a single key).
inline int curveSegments(int keyCount)
{
  return keyCount > 1 ? keyCount - 1 : 1;
}

/// What the curve points of one segment (times[segment] <= t <= times[segment + 1]) combine,
/// for any key times: curveWeights lists only keys in [first, last] (some with weight 0), and its
/// largest weight, and its second largest wherever the two are within 0.1 of each other, are on
/// keys in [firstReference, lastReference]. These are the keys lct::KeyLogs takes as the
/// reference of the relative form, so a curve point on the segment needs the relative logs of
/// keys first..last about each reference (Testing/Unit/TestCurves.cxx checks the bounds).
/// - Linear: keys segment, segment + 1, both references.
/// - CatmullRom and BSpline: keys segment - 1 .. segment + 2 (clamped to the keys); the outer
///   two weigh at most 1/6 (BSpline) or <= 0 (CatmullRom), so the references are segment and
///   segment + 1.
/// - Subdivision: keys segment - 2 .. segment + 3 (clamped; phantom keys fold onto the end
///   keys), references segment and segment + 1 (the outer weights stay below 0.07).
/// - Bezier: points 3 segment .. 3 segment + 3 of the key-and-control sequence, each of which
///   can have the largest weight.
/// With one key: that key alone. Preconditions: keyCount >= 1 and
/// 0 <= segment < curveSegments(keyCount).
struct CurveStencil
{
  int first = 0;
  int last = 0;
  int firstReference = 0;
  int lastReference = 0;
};
VTKLCT_EXPORT CurveStencil curveStencil(CurveScheme scheme, int keyCount, int segment);

/// Calls visit(i, r) for every pair of distinct keys (Bezier: sequence points) that a curve point
/// on segments firstSegment..lastSegment (clamped to the segments) combines: i in a segment's
/// stencil, r one of its references, so that its relative log (the step from M_r to M_i,
/// lct::relativeLog) is needed. A pair may come more than once (neighbouring segments
/// share keys). Stops, returning false, at the first visit that returns false.
template <typename Visit>
bool forEachCombinedPair(
  CurveScheme scheme, int keyCount, int firstSegment, int lastSegment, Visit&& visit)
{
  const int segments = curveSegments(keyCount);
  for (int s = firstSegment < 0 ? 0 : firstSegment; s <= lastSegment && s < segments; ++s)
  {
    const CurveStencil stencil = curveStencil(scheme, keyCount, s);
    for (int r = stencil.firstReference; r <= stencil.lastReference; ++r)
    {
      for (int i = stencil.first; i <= stencil.last; ++i)
      {
        if (i != r && !visit(i, r))
        {
          return false;
        }
      }
    }
  }
  return true;
}

} // namespace lct

#endif
