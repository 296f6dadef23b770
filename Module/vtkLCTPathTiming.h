/**
 * @file    vtkLCTPathTiming.h
 * @brief   (private to the module) the timing controls of the two interpolators
 *          (lct/PathTiming.h): the checks of their setters, with the messages, and the
 *          constant-speed table, built once per modification of the interpolator.
 */
#ifndef vtkLCTPathTiming_h
#define vtkLCTPathTiming_h

#include "lct/ArcLength.h"
#include "lct/Format.h"
#include "lct/PathTiming.h"

#include "vtkDoubleArray.h"
#include "vtkIndent.h"
#include "vtkObject.h"
#include "vtkSetGet.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

namespace vtkLCTPathTiming
{

/// The sampling of the constant-speed table (lct/ArcLength.h): kIntervalsPerSegment equal
/// intervals per key segment (fewer, down to 1, for more than kMaximumSamples / 16 keys), each
/// halved while the sum of its half chords exceeds its chord by more than kFlatness of it (a chord
/// then misses at most ~kFlatness / 3 of its arc), at most kMaximumHalvings times, and never beyond
/// kMaximumSamples samples in all (about 2 M evaluations, a few seconds; beyond it the intervals
/// are left as they are).
constexpr int kIntervalsPerSegment = 16;
constexpr double kFlatness = 1e-5;
constexpr int kMaximumHalvings = 12;
constexpr size_t kMaximumSamples = size_t(1) << 21;

/// Whether `value` may be a Kochanek-Bartels parameter; else an error from `self` naming the
/// call (`caller`, with the key's time for a per-key setter) and the argument (`name`).
inline bool CheckTensionContinuityBias(
  vtkObject* self, const std::string& caller, double value, const char* name = nullptr)
{
  if (value >= -1.0 && value <= 1.0)
  {
    return true;
  }
  vtkErrorWithObjectMacro(self, << caller << ": " << (name ? name : "the value") << " "
                                << lct::formatNumber(value)
                                << " is outside [-1, 1], the range of tension, continuity and "
                                   "bias (vtkKochanekSpline's); unchanged.");
  return false;
}

/// Whether `value` may be an ease amount; else an error from `self` (as above).
inline bool CheckEase(
  vtkObject* self, const std::string& caller, double value, const char* name = nullptr)
{
  if (lct::isValidEase(value))
  {
    return true;
  }
  vtkErrorWithObjectMacro(self, << caller << ": " << (name ? name : "the ease") << " "
                                << lct::formatNumber(value)
                                << " is outside [0, 1] (0: none, 1: from or to rest); "
                                   "unchanged.");
  return false;
}

/// A per-key setter's name with the key's time, for its messages: "SetKeyEase(t = 2)".
inline std::string KeyCaller(const char* caller, double t)
{
  return std::string(caller) + "(t = " + lct::formatNumber(t) + ")";
}

/// The error for a per-key setter given a time without a key.
inline void ReportNoKey(vtkObject* self, const char* caller, double t)
{
  vtkErrorWithObjectMacro(
    self, << caller << ": there is no key at t = " << lct::formatNumber(t) << "; unchanged.");
}

/// The parameter of a path's timing that a setter changes.
enum class Setting
{
  Tension,
  Continuity,
  Bias,
  EaseIn,
  EaseOut
};

/// Sets one path-wide timing parameter of `self` after checking it (else an error, unchanged);
/// 1 or 0, the setters' return value.
inline int SetPathTiming(vtkObject* self, lct::PathTiming& timing, Setting setting, double value)
{
  static const char* const callers[] = { "SetTension", "SetContinuity", "SetBias", "SetEaseIn",
    "SetEaseOut" };
  const char* caller = callers[static_cast<int>(setting)];
  const bool ease = setting == Setting::EaseIn || setting == Setting::EaseOut;
  if (ease ? !CheckEase(self, caller, value) : !CheckTensionContinuityBias(self, caller, value))
  {
    return 0;
  }
  lct::TensionContinuityBias& tcb = timing.tensionContinuityBias;
  double* const fields[] = { &tcb.tension, &tcb.continuity, &tcb.bias, &timing.easeIn,
    &timing.easeOut };
  *fields[static_cast<int>(setting)] = value;
  self->Modified();
  return 1;
}

/// The per-key setters of both interpolators on their keys `keys` (lct::Keyframes of a Key type
/// with a `lct::KeyTiming Timing` member): check, then set, then Modified; 1 or 0.
template <typename Keys>
int SetKeyTensionContinuityBias(
  vtkObject* self, Keys& keys, double t, const lct::TensionContinuityBias& tcb)
{
  const char* caller = "SetKeyTensionContinuityBias";
  auto* key = keys.find(t);
  if (!key)
  {
    ReportNoKey(self, caller, t);
    return 0;
  }
  const std::string at = KeyCaller(caller, t);
  if (!CheckTensionContinuityBias(self, at, tcb.tension, "the tension") ||
    !CheckTensionContinuityBias(self, at, tcb.continuity, "the continuity") ||
    !CheckTensionContinuityBias(self, at, tcb.bias, "the bias"))
  {
    return 0;
  }
  key->Timing.hasTensionContinuityBias = true;
  key->Timing.tensionContinuityBias = tcb;
  self->Modified();
  return 1;
}

template <typename Keys>
int SetKeyEase(vtkObject* self, Keys& keys, double t, double arriving, double leaving)
{
  const char* caller = "SetKeyEase";
  auto* key = keys.find(t);
  if (!key)
  {
    ReportNoKey(self, caller, t);
    return 0;
  }
  const std::string at = KeyCaller(caller, t);
  if (!CheckEase(self, at, arriving, "the arriving ease") ||
    !CheckEase(self, at, leaving, "the leaving ease"))
  {
    return 0;
  }
  key->Timing.arrivingEase = arriving;
  key->Timing.leavingEase = leaving;
  self->Modified();
  return 1;
}

template <typename Keys>
int ClearKeyTiming(vtkObject* self, Keys& keys, double t)
{
  auto* key = keys.find(t);
  if (!key)
  {
    ReportNoKey(self, "ClearKeyTiming", t);
    return 0;
  }
  key->Timing = lct::KeyTiming();
  self->Modified();
  return 1;
}

/// The curve time of output time t from the eases of `keys` (flat lct::Keyframes of a Key type
/// with a `lct::KeyTiming Timing` member) and of the path.
template <typename Keys>
double EasedCurveTime(const Keys& keys, const lct::PathTiming& timing, double t)
{
  return lct::easedCurveTime(keys.times().data(), static_cast<int>(keys.size()), t, timing,
    [&keys](int k) -> const lct::KeyTiming& { return keys[k].Timing; });
}

/// The key times, for GetKeyArrivalTimes without ConstantSpeed.
inline void KeyTimes(const std::vector<double>& times, vtkDoubleArray* out)
{
  out->SetNumberOfComponents(1);
  out->SetNumberOfTuples(static_cast<vtkIdType>(times.size()));
  for (size_t k = 0; k < times.size(); ++k)
  {
    out->SetValue(static_cast<vtkIdType>(k), times[k]);
  }
}

/// The PrintSelf lines of the path's timing.
inline void Print(ostream& os, vtkIndent indent, const lct::PathTiming& timing, bool constantSpeed)
{
  const lct::TensionContinuityBias& tcb = timing.tensionContinuityBias;
  os << indent << "Tension, Continuity, Bias: " << tcb.tension << ", " << tcb.continuity << ", "
     << tcb.bias << "\n";
  os << indent << "EaseIn, EaseOut: " << timing.easeIn << ", " << timing.easeOut << "\n";
  os << indent << "ConstantSpeed: " << (constantSpeed ? "On" : "Off") << "\n";
}

/// The constant-speed table of an interpolator, rebuilt by the first query after the
/// interpolator's modification time changed (under a mutex: queries may run concurrently once
/// the keys and settings stop changing, as the interpolators document).
template <int Dim>
class ConstantSpeedTable
{
public:
  using Point = typename lct::ArcLengthTime<Dim>::Point;

  /// The table for keys at `times` (n >= 2) at modification time `mtime`;
  /// positionAt(tau, p, cause) gives the measured point at curve time tau, or false with the
  /// cause. Null, with `why` set, when the path cannot be measured (a curve point that cannot be
  /// computed, a length that overflows).
  template <typename PositionAt>
  const lct::ArcLengthTime<Dim>* Get(
    vtkMTimeType mtime, const double* times, int n, PositionAt&& positionAt, std::string& why)
  {
    if (this->Built.load(std::memory_order_acquire) != mtime)
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      if (this->Built.load(std::memory_order_relaxed) != mtime)
      {
        this->Build(times, n, positionAt);
        this->Built.store(mtime, std::memory_order_release);
      }
    }
    why = this->Why;
    return this->Why.empty() ? &this->Table : nullptr;
  }

  /// The curve time of output time t on the path of keys at `times` (n >= 2) at modification
  /// time `mtime`: eased over the whole path (timing.easeIn, timing.easeOut), then mapped by arc
  /// length. False, with an error from `self` naming `caller`, when the path cannot be measured.
  template <typename PositionAt>
  bool CurveTime(vtkObject* self, const char* caller, vtkMTimeType mtime, const double* times,
    int n, const lct::PathTiming& timing, double t, PositionAt&& positionAt, double& curveTime)
  {
    std::string why;
    const lct::ArcLengthTime<Dim>* table = this->Get(mtime, times, n, positionAt, why);
    if (!table)
    {
      vtkErrorWithObjectMacro(self, << caller << "(" << lct::formatNumber(t)
                                    << "): ConstantSpeed cannot measure the path: " << why
                                    << "; output unchanged.");
      return false;
    }
    std::string ignored;
    curveTime = table->curveTime(lct::easedPathTime(times[0], times[n - 1], t, timing),
      [&](double tau, Point& p) { return positionAt(tau, p, ignored); });
    return true;
  }

  /// The output times at which the path passes its keys (a valid table of n keys at `times`):
  /// the arc-length times of the keys through the inverse of the path's ease. The end keys
  /// keep their own times exactly.
  void ArrivalTimes(
    const double* times, int n, const lct::PathTiming& timing, vtkDoubleArray* out) const
  {
    out->SetNumberOfComponents(1);
    out->SetNumberOfTuples(n);
    for (int k = 0; k < n; ++k)
    {
      const double eased = this->Table.outputTime(this->KeySamples[k]);
      out->SetValue(k,
        k == 0 || k == n - 1 ? times[k]
                             : lct::inverseEasedPathTime(times[0], times[n - 1], eased, timing));
    }
  }

private:
  template <typename PositionAt>
  bool Sample(double tau, PositionAt&& positionAt, Point& p)
  {
    std::string cause;
    if (positionAt(tau, p, cause) && p.allFinite())
    {
      return true;
    }
    std::ostringstream os;
    os << "the curve point at curve time " << lct::formatNumber(tau) << " cannot be measured: "
       << (cause.empty() ? "the measured point is out of the range of double precision there"
                         : cause);
    this->Why = os.str();
    return false;
  }

  template <typename PositionAt>
  void Build(const double* times, int n, PositionAt&& positionAt)
  {
    this->Why.clear();
    this->KeySamples.assign(n, 0);
    std::vector<double> taus;
    std::vector<Point> points;
    // Appends the samples of (a, b] to taus / points, halving where the path curves; depth-first
    // with an explicit stack of pending right halves, so the samples come in time order.
    struct Pending
    {
      double tau;
      Point p;
      int depth;
    };
    std::vector<Pending> stack;
    const auto refine = [&](double a, const Point& pa, double b, const Point& pb) {
      stack.clear();
      stack.push_back({ b, pb, 0 });
      double left = a;
      Point leftPoint = pa;
      while (!stack.empty())
      {
        const Pending right = stack.back();
        const double middle = 0.5 * (left + right.tau);
        Point pm;
        if (right.depth < kMaximumHalvings && taus.size() + stack.size() < kMaximumSamples &&
          middle > left && middle < right.tau)
        {
          if (!this->Sample(middle, positionAt, pm))
          {
            return false;
          }
          const double chord = (right.p - leftPoint).stableNorm();
          const double halves = (pm - leftPoint).stableNorm() + (right.p - pm).stableNorm();
          if (halves - chord > kFlatness * halves)
          {
            stack.back().depth = right.depth + 1;
            stack.push_back({ middle, pm, right.depth + 1 });
            continue;
          }
        }
        stack.pop_back();
        taus.push_back(right.tau);
        points.push_back(right.p);
        left = right.tau;
        leftPoint = right.p;
      }
      return true;
    };
    // The table stays within kMaximumSamples (plus one per key) however many keys there are.
    const int intervals = static_cast<int>(
      std::clamp<size_t>(kMaximumSamples / static_cast<size_t>(n - 1), 1, kIntervalsPerSegment));
    Point previous, p;
    if (!this->Sample(times[0], positionAt, previous))
    {
      return;
    }
    taus.push_back(times[0]);
    points.push_back(previous);
    for (int i = 0; i + 1 < n; ++i)
    {
      this->KeySamples[i] = static_cast<int>(taus.size()) - 1;
      const double h = times[i + 1] - times[i];
      for (int j = 1; j <= intervals; ++j)
      {
        const double tau = j == intervals ? times[i + 1] : times[i] + h * j / intervals;
        if (j < intervals && !(tau > taus.back() && tau < times[i + 1]))
        {
          continue; // keys a few ulps apart: no room for this sample
        }
        if (!this->Sample(tau, positionAt, p) || !refine(taus.back(), previous, tau, p))
        {
          return;
        }
        previous = p;
      }
    }
    this->KeySamples[n - 1] = static_cast<int>(taus.size()) - 1;
    if (!this->Table.build(taus, points))
    {
      this->Why = "the length of the measured path is out of the range of double precision";
    }
  }

  std::mutex Mutex;
  std::atomic<vtkMTimeType> Built{ 0 };
  lct::ArcLengthTime<Dim> Table;
  std::vector<int> KeySamples;
  std::string Why;
};

} // namespace vtkLCTPathTiming

#endif
