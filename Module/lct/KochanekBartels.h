/**
 * @file KochanekBartels.h
 * @brief Kochanek-Bartels (TCB) tangents at a key, as combinations of its two secants, so that
 *        a curve point with them is still ONE weighted combination of keys (lct/Curves.h).
 *
 * Kochanek & Bartels, "Interpolating splines with local tension, continuity, and bias control"
 * (SIGGRAPH 1984), eq. 7-9, the parameters of VTK's vtkKochanekSpline. With the differences
 * D- = x[k] - x[k-1] and D+ = x[k+1] - x[k] (here log steps, in log space), the tangent leaving
 * key k (the start of segment k) and the one arriving at it (the end of segment k-1) are
 *   leaving  = (1-T)(1+C)(1+B)/2 D- + (1-T)(1-C)(1-B)/2 D+
 *   arriving = (1-T)(1-C)(1+B)/2 D- + (1-T)(1+C)(1-B)/2 D+
 * in units of the segment parameter; on non-uniform key times eq. 9 scales each by
 * 2 h / (h- + h+) for its own segment of duration h, so that per unit time both are
 * 2 (a D- + b D+) / (h- + h+). T = C = B = 0 is Catmull-Rom on the key times
 * (lct::catmullRomTangent). At the end keys only one secant exists: the tangent is (1-T) times
 * it. Tension T > 0 tightens the curve (T = 1: zero tangents), T < 0 slackens it; continuity
 * C != 0 makes the leaving and arriving tangents differ (a corner: C1 only at C = 0); bias B > 0
 * favours the step before the key (overshoot), B < 0 the one after.
 *
 * Each parameter is restricted to [-1, 1], the range of VTK's and every animation tool's
 * controls: there a, b >= 0, so the weights of the outer keys of a segment stay <= 0 and the
 * largest weights stay on the segment's own keys, as lct::curveStencil promises for CatmullRom.
 */
#ifndef lct_KochanekBartels_h
#define lct_KochanekBartels_h

#include "vtkLCTModule.h"

#include "lct/Curves.h"

namespace lct
{

struct TensionContinuityBias
{
  double tension = 0.0;
  double continuity = 0.0;
  double bias = 0.0;

  bool isZero() const { return tension == 0.0 && continuity == 0.0 && bias == 0.0; }
};

/// Whether each parameter is finite and in [-1, 1].
VTKLCT_EXPORT bool isValid(const TensionContinuityBias& tcb);

/// The tangents at key k of keyCount keys at strictly increasing `times`: `arriving` is the
/// end tangent of segment k - 1, `leaving` the start tangent of segment k (lct::SegmentTangents).
struct KeyTangents
{
  KeyTangent arriving;
  KeyTangent leaving;
};
VTKLCT_EXPORT KeyTangents kochanekBartelsTangents(
  const double* times, int keyCount, int k, const TensionContinuityBias& tcb);

} // namespace lct

#endif
