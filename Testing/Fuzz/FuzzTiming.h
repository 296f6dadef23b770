// The timing controls of the interpolators (issue #12 §3) under the fuzzers: one operation that
// both interpolator targets interleave with their key edits and evaluations. Tension,
// continuity, bias, eases per path and per key (values in range, at its ends, just outside, or
// any double: NaN, Inf, denormals), ClearKeyTiming, ConstantSpeed with the interpolator's own
// measure setting, and GetKeyArrivalTimes.
//
// Properties: a setter returns 1 exactly for a value in its range (and, per key, a key at the
// time), else 0 with an error and the interpolator's MTime unchanged; a successful getter holds
// the value set; arrival times are one per key, finite, in order, the first and last at the end
// keys' own times.
#ifndef lct_fuzz_FuzzTiming_h
#define lct_fuzz_FuzzTiming_h

#include "FuzzInput.h"

#include "vtkDoubleArray.h"
#include "vtkNew.h"

#include <cmath>
#include <utility>

namespace lct_fuzz
{

/// A timing value: in [lo, hi], at its ends, just outside, or any double.
inline double TimingValue(Input& in, double lo, double hi)
{
  switch (in.Int(0, 4))
  {
    case 0:
      return in.Provider().ConsumeFloatingPointInRange<double>(lo, hi);
    case 1:
      return in.Bool() ? lo : hi;
    case 2:
      return in.Bool() ? std::nextafter(lo, -2.0) : std::nextafter(hi, 2.0);
    default:
      return in.Double();
  }
}

/// Whether an evaluation's error under ConstantSpeed is one the interpolators document: the
/// path has a curve point that cannot be computed (a documented refusal of the combination, or
/// a camera overshoot), the measured point leaves double precision there (a ConstantSpeedPoint
/// near 1e308 moved by the keys), or the path's length overflows.
inline bool ExplainedConstantSpeedRefusal(const std::string& message)
{
  return message.find("ConstantSpeed cannot measure the path") != std::string::npos &&
    (message.find("the length of the measured path is out of the range of double precision") !=
        std::string::npos ||
      message.find("the measured point is out of the range of double precision") !=
        std::string::npos ||
      message.find("overshoot") != std::string::npos || ExplainedRefusal(message));
}

/// One timing operation on `path` (a vtkTransformInterpolatorLCT or vtkCameraInterpolatorLCT).
/// `time()` draws a key time, `hasKey(t)` says whether the shadow model has a key at t,
/// first / last / count describe the shadow's keys, `errors()` counts the errors reported so
/// far, and `measure(in)` sets the interpolator's own constant-speed measure, returning
/// (result, whether 1 was expected).
template <typename Path, typename Time, typename HasKey, typename Errors, typename Measure>
void FuzzTiming(Input& in, Path* path, Time&& time, HasKey&& hasKey, double first, double last,
  int count, Errors&& errors, Measure&& measure)
{
  const int before = errors();
  const vtkMTimeType mtime = path->GetMTime();
  const auto inRange = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
  int result = 1;
  bool expected = true;
  const int which = in.Int(0, 9);
  switch (which)
  {
    case 0:
    case 1:
    case 2:
    {
      const double v = TimingValue(in, -1.0, 1.0);
      LCT_FUZZ_TRACE("Set TCB " << which << " " << v);
      result =
        which == 0 ? path->SetTension(v) : (which == 1 ? path->SetContinuity(v) : path->SetBias(v));
      expected = inRange(v, -1.0, 1.0);
      if (result == 1)
      {
        const double got =
          which == 0 ? path->GetTension() : (which == 1 ? path->GetContinuity() : path->GetBias());
        LCT_FUZZ_CHECK(got == v, "a TCB setter returned 1 but holds " << got);
      }
      break;
    }
    case 3:
    case 4:
    {
      const double v = TimingValue(in, 0.0, 1.0);
      LCT_FUZZ_TRACE("SetEase" << (which == 3 ? "In " : "Out ") << v);
      result = which == 3 ? path->SetEaseIn(v) : path->SetEaseOut(v);
      expected = inRange(v, 0.0, 1.0);
      break;
    }
    case 5:
    {
      const double t = time();
      const double tcb[3] = { TimingValue(in, -1.0, 1.0), TimingValue(in, -1.0, 1.0),
        TimingValue(in, -1.0, 1.0) };
      LCT_FUZZ_TRACE(
        "SetKeyTensionContinuityBias " << t << " " << tcb[0] << " " << tcb[1] << " " << tcb[2]);
      result = path->SetKeyTensionContinuityBias(t, tcb[0], tcb[1], tcb[2]);
      expected = hasKey(t) && inRange(tcb[0], -1.0, 1.0) && inRange(tcb[1], -1.0, 1.0) &&
        inRange(tcb[2], -1.0, 1.0);
      break;
    }
    case 6:
    {
      const double t = time();
      const double arriving = TimingValue(in, 0.0, 1.0), leaving = TimingValue(in, 0.0, 1.0);
      LCT_FUZZ_TRACE("SetKeyEase " << t << " " << arriving << " " << leaving);
      result = path->SetKeyEase(t, arriving, leaving);
      expected = hasKey(t) && inRange(arriving, 0.0, 1.0) && inRange(leaving, 0.0, 1.0);
      break;
    }
    case 7:
    {
      const double t = time();
      LCT_FUZZ_TRACE("ClearKeyTiming " << t);
      result = path->ClearKeyTiming(t);
      expected = hasKey(t);
      break;
    }
    case 8:
    {
      const bool on = in.Bool();
      LCT_FUZZ_TRACE("ConstantSpeed " << on);
      path->SetConstantSpeed(on);
      std::tie(result, expected) = measure(in);
      LCT_FUZZ_CHECK(
        result == (expected ? 1 : 0), "the constant-speed measure setter returned " << result);
      LCT_FUZZ_CHECK((errors() > before) == (result == 0),
        "the constant-speed measure setter: error reporting does not match the result");
      return; // SetConstantSpeed itself modifies the path
    }
    default:
    {
      LCT_FUZZ_TRACE("GetKeyArrivalTimes");
      vtkNew<vtkDoubleArray> arrivals;
      result = path->GetKeyArrivalTimes(arrivals);
      LCT_FUZZ_CHECK(result == 1 || errors() > before, "GetKeyArrivalTimes returned 0 silently");
      if (result == 1)
      {
        const vtkIdType n = arrivals->GetNumberOfTuples();
        LCT_FUZZ_CHECK(n == count, n << " arrival times for " << count << " keys");
        for (vtkIdType k = 0; k < n; ++k)
        {
          const double a = arrivals->GetValue(k);
          LCT_FUZZ_CHECK(std::isfinite(a) && (k == 0 || a >= arrivals->GetValue(k - 1)),
            "arrival time " << k << " = " << a << " is not finite or out of order");
        }
        LCT_FUZZ_CHECK(n > 0 && arrivals->GetValue(0) == first && arrivals->GetValue(n - 1) == last,
          "the first and last keys are not passed at their own times");
      }
      else
      {
        // No keys, or a path ConstantSpeed cannot measure (the evaluations check that it is
        // explained).
        LCT_FUZZ_CHECK(count == 0 || path->GetConstantSpeed(),
          "GetKeyArrivalTimes failed with keys and without ConstantSpeed");
      }
      return;
    }
  }
  LCT_FUZZ_CHECK(result == (expected ? 1 : 0),
    "timing call " << which << " returned " << result << ", expected " << expected);
  LCT_FUZZ_CHECK((errors() > before) == (result == 0),
    "timing call " << which << ": error reporting does not match the result");
  LCT_FUZZ_CHECK(
    result == 1 || path->GetMTime() == mtime, "a refused timing call modified the interpolator");
}

} // namespace lct_fuzz

#endif
