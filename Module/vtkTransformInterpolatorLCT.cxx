#include "vtkTransformInterpolatorLCT.h"

#include "vtkLCTCheckedSet.h"

#include "lct/Affine.h"
#include "lct/Curves.h"
#include "lct/Format.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"
#include "lct/MonotoneTangents.h"
#include "lct/Parametrisation.h"
#include "lct/PathTiming.h"
#include "lct/PolarParametrisation.h"
#include "lct/RebuildOnce.h"

#include "vtkDoubleArray.h"
#include "vtkLCTPathTiming.h"
#include "vtkLogTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProp3D.h"
#include "vtkTransform.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTransformInterpolatorLCT);

namespace
{
/// Why ConsistentRotation and MatrixLog exclude each other.
constexpr const char* kConsistentRotationNeedsPolar =
  "ConsistentRotation continues each key's rotation on the branch of the previous key's, which "
  "only the Polar parametrisation has (MatrixLog's logs are principal: a spin of 0, 170, 340, "
  "510 degrees would turn back the short way)";
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

struct Key
{
  double Time;
  Eigen::Matrix4d Matrix;
  /// Bezier control transforms before and after the key, when the user gave them.
  bool HasIncoming = false;
  bool HasOutgoing = false;
  Eigen::Matrix4d Incoming;
  Eigen::Matrix4d Outgoing;
  /// Its own tension, continuity, bias and eases (lct/PathTiming.h).
  lct::KeyTiming Timing;
};

lct::Parametrisation toCore(int parametrisation)
{
  return parametrisation == vtkTransformInterpolatorLCT::MATRIX_LOG
    ? lct::Parametrisation::MatrixLog
    : lct::Parametrisation::Polar;
}

lct::CurveScheme toScheme(int type)
{
  switch (type)
  {
    case vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR:
      return lct::CurveScheme::Linear;
    case vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE:
      return lct::CurveScheme::BSpline;
    case vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION:
      return lct::CurveScheme::Subdivision;
    case vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER:
      return lct::CurveScheme::Bezier;
    default:
      return lct::CurveScheme::CatmullRom;
  }
}

const char* typeName(int type)
{
  static const char* const names[] = { "Linear", "Spline", "BSpline", "Subdivision", "Bezier" };
  return names[std::clamp(type, 0, 4)];
}

/// A point of the curve's key-and-control sequence (the keys, and for Bezier the control
/// transforms beside them), as a message names it.
struct Point
{
  enum Role
  {
    KEY,
    INCOMING, ///< the Bezier control before the key
    OUTGOING  ///< the Bezier control after the key
  };
  Role Kind = KEY;
  double Time = 0.0;
};

std::ostream& operator<<(std::ostream& os, const Point& p)
{
  return os << (p.Kind == Point::KEY           ? "the key"
                   : p.Kind == Point::INCOMING ? "the control transform before the key"
                                               : "the control transform after the key")
            << " at t = " << lct::formatNumber(p.Time);
}

/// A log that a curve point needs and that does not exist (an edit or a setting that would
/// leave it missing is refused), and why.
struct Refusal
{
  enum Kinds
  {
    RELATIVE, ///< log(Reference^-1 Key)
    ABSOLUTE, ///< the absolute log of Key (ConsistentRotation)
    TANGENT,  ///< the automatic Bezier control beside Reference needs log(Reference^-1 Key)
    CONTROL   ///< the automatic Bezier control beside Reference is not representable
  };
  lct::Status Status = lct::Status::Ok;
  Kinds Kind = RELATIVE;
  Point Key;
  Point Reference;
};

/// Writes why `r` is refused, naming its points, the parametrisation in use and, only for a
/// MatrixLog failure that Polar would not have, the advice to switch.
std::string describe(const Refusal& r, lct::Parametrisation p, int type)
{
  std::ostringstream os;
  switch (r.Kind)
  {
    case Refusal::RELATIVE:
      os << "the " << typeName(type) << " curve combines " << r.Key << " with " << r.Reference
         << " as its reference, but the step from " << r.Reference << " to " << r.Key << " has no "
         << lct::name(p) << " logarithm: ";
      break;
    case Refusal::ABSOLUTE:
      os << "ConsistentRotation combines the absolute " << lct::name(p)
         << " logarithm of every key, and " << r.Key << " has none: ";
      break;
    case Refusal::TANGENT:
      os << "the automatic Bezier controls beside " << r.Reference << " need the step from it to "
         << r.Key << ", which has no " << lct::name(p) << " logarithm: ";
      break;
    case Refusal::CONTROL:
      os << "an automatic Bezier control beside " << r.Reference << " is not representable: ";
      break;
  }
  os << lct::describe(r.Status) << lct::adviceFor(r.Status, p);
  return os.str();
}
} // namespace

/// The keys, and the logs derived from them. Edits change the keys in O(log n) and mark the logs
/// stale (an append or a replacement updates them in place when they are current); the first
/// evaluation after that rebuilds them in O(n), under a mutex, so that evaluations may run
/// concurrently once the keys stop changing.
///
/// Every edit and every setting is checked first (Add, Remove, SetControls, Validate): every log
/// that a curve point of the interpolation type may combine must exist (lct::CurveNeeds), so the
/// rebuilds, which compute the same logs, cannot fail and evaluations never miss a log. An edit
/// checks only the keys within the stencil of the change (a window of a few keys around it),
/// from the logs in place when they are current, else by computing the logs it adds.
struct vtkTransformInterpolatorLCT::Internals
{
  lct::Keyframes<Key> Keys;
  lct::Parametrisation P = lct::Parametrisation::Polar;

  std::mutex Mutex;
  /// Logs of the keys (Linear, Spline, BSpline, Subdivision) and why they are missing.
  std::atomic<bool> LogsCurrent{ true };
  lct::KeyLogs KeyLogs;
  lct::Status LogsStatus = lct::Status::Ok;
  double LogsFailedTime = 0.0;
  /// Logs of the Bezier sequence K0, C0+, C1-, K1, ... (see lct/Curves.h), built on the first
  /// Bezier evaluation after a change, and why they are missing if they are.
  std::atomic<bool> BezierCurrent{ false };
  lct::KeyLogs BezierLogs;
  lct::Status BezierStatus = lct::Status::Ok;
  double BezierFailedTime = 0.0;
  /// The monotone tangent of each key (lct::monotoneTangent of its steps to its neighbours, or
  /// Catmull-Rom's where a step is missing or at the end keys), built on the first Spline
  /// evaluation after a change of the keys or their logs: it depends on nothing else, and was
  /// ~20 % of a Spline evaluation when computed per call.
  std::atomic<bool> TangentsCurrent{ false };
  std::vector<lct::KeyTangent> Tangents;
  /// With Tangents: how much each key is an impact (lct::impactWeight), which shapes the Spline
  /// segments beside it.
  std::vector<double> ImpactWeights;
  /// Whether a query outside the key range has been reported (once per interpolator).
  std::atomic<bool> ClampReported{ false };
  /// The timing controls, the point whose speed ConstantSpeed makes even, and its table.
  lct::PathTiming Timing;
  Eigen::Vector3d ConstantSpeedPoint = Eigen::Vector3d::Zero();
  vtkLCTPathTiming::ConstantSpeedTable<3> ConstantSpeedTable;

  /// The logs the key logs must hold for curve points of `type`: Bezier takes the steps between
  /// neighbours both ways (the tangents of its automatic controls; its own sequence is checked
  /// by CheckBezier).
  static lct::CurveNeeds KeyNeeds(int type, bool absolute)
  {
    const lct::CurveScheme scheme = toScheme(type);
    if (scheme == lct::CurveScheme::Bezier)
    {
      return { lct::CurveScheme::Linear, false };
    }
    return { scheme, absolute };
  }

  void KeysChanged(bool logsCurrent)
  {
    this->LogsCurrent = logsCurrent;
    this->BezierCurrent = false;
    this->TangentsCurrent = false;
  }

  /// All keys in time order, for code shared with Window.
  std::vector<const Key*> FlatKeys()
  {
    this->Keys.flatten();
    std::vector<const Key*> keys(this->Keys.size());
    for (size_t i = 0; i < keys.size(); ++i)
    {
      keys[i] = &this->Keys[i];
    }
    return keys;
  }

  static std::vector<Eigen::Matrix4d> MatricesOf(const std::vector<const Key*>& keys)
  {
    std::vector<Eigen::Matrix4d> matrices;
    matrices.reserve(keys.size());
    for (const Key* key : keys)
    {
      matrices.push_back(key->Matrix);
    }
    return matrices;
  }

  static lct::KeyTangent MonotoneTangent(
    const lct::KeyLogs& logs, const double* times, int n, int k, bool monotone)
  {
    const lct::LogCoords* previous = monotone && k > 0 ? logs.relative(k - 1, k) : nullptr;
    const lct::LogCoords* next = monotone && k + 1 < n ? logs.relative(k + 1, k) : nullptr;
    return previous && next
      ? lct::monotoneTangent(*previous, *next, times[k] - times[k - 1], times[k + 1] - times[k])
      : lct::catmullRomTangent(times, n, k);
  }

  /// lct::impactWeight of key k from its steps to the keys two either side (0 within two keys of
  /// an end, or where a step is missing).
  static double ImpactWeight(const lct::KeyLogs& logs, const double* times, int n, int k)
  {
    if (k < 2 || k + 2 >= n)
    {
      return 0.0;
    }
    const lct::LogCoords* outerPrevious = logs.relative(k - 2, k - 1);
    const lct::LogCoords* previous = logs.relative(k - 1, k);
    const lct::LogCoords* next = logs.relative(k + 1, k);
    const lct::LogCoords* outerNext = logs.relative(k + 2, k + 1);
    return outerPrevious && previous && next && outerNext
      ? lct::impactWeight(*outerPrevious, *previous, *next, *outerNext, times + k - 2)
      : 0.0;
  }

  /// Every key's monotone tangent (Tangents) and impact weight, rebuilt if stale; the key logs
  /// must be current.
  const lct::KeyTangent* MonotoneTangents()
  {
    lct::rebuildOnce(this->TangentsCurrent, this->Mutex, [this] {
      const int n = static_cast<int>(this->Keys.size());
      const double* times = this->Keys.times().data();
      this->Tangents.resize(n);
      this->ImpactWeights.resize(n);
      for (int k = 0; k < n; ++k)
      {
        this->Tangents[k] = MonotoneTangent(this->KeyLogs, times, n, k, true);
        this->ImpactWeights[k] = ImpactWeight(this->KeyLogs, times, n, k);
      }
    });
    return this->Tangents.data();
  }

  /// The Spline tangents of the segment holding t: Kochanek-Bartels at keys with tension,
  /// continuity or bias (lct/PathTiming.h), else the monotone tangent (lct/MonotoneTangents.h)
  /// from the steps from the key to its neighbours (lct::relativeLog), or Catmull-Rom's
  /// when `monotone` is off; the end keys keep their one-sided tangents (the secant). With the
  /// monotone tangents and `straightenImpacts`, a segment beside an impact (lct::impactWeight) of
  /// a key with the default tangent is nearly straight (its shape).
  lct::SegmentTangents TangentsAt(const lct::KeyLogs& logs, const double* times, int n, double t,
    bool monotone, bool straightenImpacts)
  {
    const lct::KeyTangent* cached =
      monotone && &logs == &this->KeyLogs ? this->MonotoneTangents() : nullptr;
    const auto defaultTangent = [&](int k) {
      return cached ? cached[k] : MonotoneTangent(logs, times, n, k, monotone);
    };
    const auto timingOf = [this](int k) -> const lct::KeyTiming& { return this->Keys[k].Timing; };
    const int segment = lct::curveSegment(times, n, t);
    lct::SegmentTangents tangents =
      lct::splineTangents(times, n, segment, this->Timing, timingOf, defaultTangent);
    if (monotone && straightenImpacts && n > 1)
    {
      const auto impact = [&](int k) {
        if (!lct::tensionContinuityBiasOf(timingOf(k), this->Timing).isZero())
        {
          return 0.0; // the key's own tangent: the user shapes it
        }
        return cached ? this->ImpactWeights[k] : ImpactWeight(logs, times, n, k);
      };
      tangents.shape = lct::impactSegmentShape(impact(segment), impact(segment + 1));
    }
    return tangents;
  }

  /// The curve point at curve time t: the weights of `scheme` (Spline with TangentsAt), combined
  /// relative to the key of largest weight or, with `absolute`, from the absolute logs.
  lct::Status CurveAt(const lct::KeyLogs& logs, lct::CurveScheme scheme, bool monotone,
    bool straightenImpacts, bool absolute, double t, Eigen::Matrix4d& result,
    lct::MissingLog* missing)
  {
    const int n = static_cast<int>(this->Keys.size());
    const double* times = this->Keys.times().data();
    const lct::CurveWeights w = scheme == lct::CurveScheme::CatmullRom && n > 1
      ? lct::curveWeights(
          scheme, times, n, t, this->TangentsAt(logs, times, n, t, monotone, straightenImpacts))
      : lct::curveWeights(scheme, times, n, t);
    return absolute ? logs.combineAbsolute(w, result, missing)
                    : logs.combineRelative(w, result, missing);
  }

  /// The key logs, rebuilt if stale. Null, with LogsStatus saying why, when they cannot be.
  const lct::KeyLogs* Logs()
  {
    lct::rebuildOnce(this->LogsCurrent, this->Mutex, [this] {
      const std::vector<const Key*> keys = this->FlatKeys();
      int failed = 0;
      this->LogsStatus = this->KeyLogs.build(MatricesOf(keys), this->P, true, &failed);
      this->TangentsCurrent = false;
      this->LogsFailedTime = this->LogsStatus == lct::Status::Ok ? 0.0 : keys[failed]->Time;
    });
    return this->LogsStatus == lct::Status::Ok ? &this->KeyLogs : nullptr;
  }

  /// The Bezier key-and-control points of segments firstSegment..lastSegment of `keys` (in time
  /// order; `reachesFirst` / `reachesLast`: whether they include the first / last key of the
  /// interpolator), points 3 firstSegment .. 3 lastSegment + 3 of the sequence. Given control
  /// transforms, else automatic ones that put the Catmull-Rom tangent m of the logs of the steps
  /// from the key at each key: C+ = exp(+h/3 m) applied to K, C- = exp(-h/3 m) applied to K
  /// (lct::applyRelativeStep), with h the segment's duration. `step(i, r)` gives the log of the
  /// step from K_r to K_i (lct::relativeLog) as a Result (0 for i == r).
  template <typename Step>
  static bool BezierPoints(const std::vector<const Key*>& keys, int firstSegment, int lastSegment,
    bool reachesFirst, bool reachesLast, lct::Parametrisation p, Step&& step,
    std::vector<Eigen::Matrix4d>& out, Refusal& refusal)
  {
    const int n = static_cast<int>(keys.size());
    out.clear();
    auto automatic = [&](int k, double signedThird, Eigen::Matrix4d& control) {
      const int lo = (k == 0 && reachesFirst) ? k : k - 1;
      const int hi = (k == n - 1 && reachesLast) ? k : k + 1;
      const lct::Result<lct::LogCoords> logs[2] = { step(hi, k), step(lo, k) };
      for (int side = 0; side < 2; ++side)
      {
        if (!logs[side])
        {
          refusal = Refusal{ logs[side].status, Refusal::TANGENT,
            Point{ Point::KEY, keys[side == 0 ? hi : lo]->Time },
            Point{ Point::KEY, keys[k]->Time } };
          return false;
        }
      }
      // A third of the segment times the tangent, with the time ratio taken first (it lies in
      // [-1/3, 1/3]): the tangent itself overflows where key times are subnormally close.
      const double ratio = signedThird / (keys[hi]->Time - keys[lo]->Time);
      const auto c = lct::exponential(ratio * (logs[0].value - logs[1].value), p);
      if (c)
      {
        control = lct::applyRelativeStep(
          keys[k]->Matrix, c.value, p, lct::needsAccurateProducts(keys[k]->Matrix));
      }
      const lct::Status status =
        !c ? c.status : (control.allFinite() ? lct::Status::Ok : lct::Status::OutOfRange);
      if (status != lct::Status::Ok)
      {
        refusal = Refusal{ status, Refusal::CONTROL, Point{}, Point{ Point::KEY, keys[k]->Time } };
        return false;
      }
      return true;
    };
    if (n == 1)
    {
      out.push_back(keys[0]->Matrix);
      return true;
    }
    for (int s = firstSegment; s <= lastSegment; ++s)
    {
      const Key& from = *keys[s];
      const Key& to = *keys[s + 1];
      const double third = (to.Time - from.Time) / 3.0;
      Eigen::Matrix4d outgoing = from.Outgoing;
      Eigen::Matrix4d incoming = to.Incoming;
      if ((!from.HasOutgoing && !automatic(s, third, outgoing)) ||
        (!to.HasIncoming && !automatic(s + 1, -third, incoming)))
      {
        return false;
      }
      if (s == firstSegment)
      {
        out.push_back(from.Matrix);
      }
      out.push_back(outgoing);
      out.push_back(incoming);
      out.push_back(to.Matrix);
    }
    return true;
  }

  /// Point q of the Bezier sequence of `keys`.
  static Point BezierPoint(const std::vector<const Key*>& keys, int q)
  {
    const int k = q / 3;
    switch (q % 3)
    {
      case 0:
        return Point{ Point::KEY, keys[k]->Time };
      case 1:
        return Point{ Point::OUTGOING, keys[k]->Time };
      default:
        return Point{ Point::INCOMING, keys[k + 1]->Time };
    }
  }

  static Refusal FromMissing(
    const lct::MissingLog& missing, const std::vector<const Key*>& keys, int offset, bool bezier)
  {
    auto point = [&](int j) {
      return bezier ? BezierPoint(keys, j - offset) : Point{ Point::KEY, keys[j - offset]->Time };
    };
    return Refusal{ missing.status,
      missing.key == missing.reference ? Refusal::ABSOLUTE : Refusal::RELATIVE, point(missing.key),
      point(missing.reference) };
  }

  /// The Bezier logs, built if the keys changed since. Null, with BezierStatus saying why, when
  /// they cannot be.
  const lct::KeyLogs* Bezier()
  {
    const lct::KeyLogs* logs = this->Logs();
    if (!logs)
    {
      this->BezierStatus = this->LogsStatus;
      this->BezierFailedTime = this->LogsFailedTime;
      return nullptr;
    }
    lct::rebuildOnce(this->BezierCurrent, this->Mutex, [this, logs] {
      const std::vector<const Key*> keys = this->FlatKeys();
      std::vector<Eigen::Matrix4d> sequence;
      Refusal refusal;
      int failed = 0;
      this->BezierStatus = BezierSequence(*logs, keys, sequence, refusal)
        ? this->BezierLogs.build(sequence, this->P, false, &failed)
        : refusal.Status;
      this->BezierFailedTime = keys.empty() ? 0.0
        : this->BezierStatus == lct::Status::Ok
        ? 0.0
        : keys[std::min<size_t>((failed + 1) / 3, keys.size() - 1)]->Time;
    });
    return this->BezierStatus == lct::Status::Ok ? &this->BezierLogs : nullptr;
  }

  /// The whole Bezier sequence, its tangents from the key logs (in their parametrisation).
  static bool BezierSequence(const lct::KeyLogs& logs, const std::vector<const Key*>& keys,
    std::vector<Eigen::Matrix4d>& sequence, Refusal& refusal)
  {
    auto step = [&logs](int i, int r) {
      const lct::LogCoords* l = logs.relative(i, r);
      return l ? lct::Result<lct::LogCoords>{ *l, lct::Status::Ok }
               : lct::Result<lct::LogCoords>::failure(logs.relativeStatus(i, r));
    };
    return BezierPoints(keys, 0, static_cast<int>(keys.size()) - 2, true, true,
      logs.parametrisation(), step, sequence, refusal);
  }

  using Window = lct::KeyWindow<Key>;

  /// The logs on the keys of the window that an edit adds (of the edited key, or for a removal
  /// those across it), computed here for stale logs.
  bool CheckKeys(
    const Window& w, const lct::CurveNeeds& needs, bool removal, Refusal& refusal) const
  {
    const lct::MissingLog missing = lct::missingAfterEdit(
      w, removal, [](const Key& key) { return key.Matrix; }, this->P, needs, needs.absolute);
    if (missing.missing())
    {
      refusal = FromMissing(missing, w.keys, 0, false);
      return false;
    }
    return true;
  }

  /// The Bezier sequence of segments firstSegment..lastSegment of the window and every log its
  /// curve points combine, computed here (each edit changes automatic controls up to two keys
  /// away).
  bool CheckBezier(
    const Window& w, int firstSegment, int lastSegment, bool absolute, Refusal& refusal) const
  {
    const int m = static_cast<int>(w.keys.size());
    firstSegment = std::max(firstSegment, 0);
    // A single key is a sequence of one point (whose absolute log ConsistentRotation combines).
    lastSegment = std::min(lastSegment, lct::curveSegments(m) - 1);
    if (m == 0 || firstSegment > lastSegment)
    {
      return true;
    }
    auto step = [&](int i, int r) {
      return i == r ? lct::Result<lct::LogCoords>{ lct::LogCoords::Zero(), lct::Status::Ok }
                    : lct::relativeLog(w.keys[r]->Matrix, w.keys[i]->Matrix, this->P);
    };
    std::vector<Eigen::Matrix4d> points;
    if (!BezierPoints(w.keys, firstSegment, lastSegment, w.reachesFirst, w.reachesLast, this->P,
          step, points, refusal))
    {
      return false;
    }
    const lct::MissingLog missing = lct::KeyLogs::missingLog(points, 3 * firstSegment, m, this->P,
      { lct::CurveScheme::Bezier, absolute }, firstSegment, lastSegment);
    if (missing.missing())
    {
      refusal = FromMissing(missing, w.keys, 0, true);
      return false;
    }
    return true;
  }

  /// Adds or replaces (same time) a key whose own validity was checked, for curve points of
  /// `type`. On failure nothing changes and `refusal` says which log would be missing.
  bool Add(const Key& key, int type, bool absolute, Refusal& refusal)
  {
    const lct::CurveNeeds needs = KeyNeeds(type, absolute);
    const Window window = lct::keyWindow(this->Keys, key.Time, &key);
    if (toScheme(type) == lct::CurveScheme::Bezier &&
      !this->CheckBezier(window, window.edited - 2, window.edited + 1, absolute, refusal))
    {
      return false;
    }
    const bool replaces = this->Keys.find(key.Time) != nullptr;
    const bool append = this->Keys.isAppend(key.Time);
    // An append or a replacement updates current logs in place (O(1) logs), which checks them
    // too; anything else computes the logs it adds, and leaves the rest to the next
    // evaluation's rebuild.
    const bool inPlace =
      this->LogsCurrent && this->LogsStatus == lct::Status::Ok && (append || replaces);
    if (inPlace)
    {
      this->Keys.flatten();
      const int index = replaces ? this->Keys.index(key.Time) : static_cast<int>(this->Keys.size());
      lct::MissingLog missing;
      const lct::Status status = replaces
        ? this->KeyLogs.replace(index, key.Matrix, true, needs, &missing)
        : this->KeyLogs.insert(index, key.Matrix, true, needs, &missing);
      if (status != lct::Status::Ok)
      {
        refusal = FromMissing(missing, window.keys, index - window.edited, false);
        return false;
      }
    }
    else if (!this->CheckKeys(window, needs, false, refusal))
    {
      return false;
    }
    this->Keys.set(key);
    this->KeysChanged(inPlace);
    return true;
  }

  /// Removes the key at time t. Fails (nothing changes) when the keys it leaves would miss a log
  /// that curve points of `type` combine.
  bool Remove(double t, int type, bool absolute, Refusal& refusal)
  {
    const Window window = lct::keyWindow(this->Keys, t, static_cast<const Key*>(nullptr));
    if (!this->CheckKeys(window, KeyNeeds(type, absolute), true, refusal) ||
      (toScheme(type) == lct::CurveScheme::Bezier &&
        !this->CheckBezier(window, window.edited - 2, window.edited, absolute, refusal)))
    {
      return false;
    }
    this->Keys.erase(t);
    this->KeysChanged(false);
    return true;
  }

  /// Whether the Bezier controls of `key` (the key at its time, with new controls) keep every
  /// log of the two segments beside it.
  bool SetControls(const Key& key, bool absolute, Refusal& refusal) const
  {
    const Window window = lct::keyWindow(this->Keys, key.Time, &key);
    return this->CheckBezier(window, window.edited - 1, window.edited, absolute, refusal);
  }

  /// Checks every log that curve points of `type` combine in parametrisation p (recomputing the
  /// logs unless they are current in p) and makes p current. On failure nothing changes.
  bool Validate(lct::Parametrisation p, int type, bool absolute, Refusal& refusal)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    const std::vector<const Key*> keys = this->FlatKeys();
    const lct::CurveNeeds needs = KeyNeeds(type, absolute);
    const bool current = p == this->P && this->LogsCurrent && this->LogsStatus == lct::Status::Ok;
    lct::KeyLogs rebuilt;
    lct::MissingLog missing;
    if (current)
    {
      missing = this->KeyLogs.missingLog(needs);
    }
    else
    {
      rebuilt.build(MatricesOf(keys), p, true, needs, &missing);
    }
    if (missing.missing())
    {
      refusal = FromMissing(missing, keys, 0, false);
      return false;
    }
    const lct::KeyLogs& logs = current ? this->KeyLogs : rebuilt;
    lct::KeyLogs bezier;
    const bool isBezier = toScheme(type) == lct::CurveScheme::Bezier;
    if (isBezier)
    {
      std::vector<Eigen::Matrix4d> sequence;
      if (!BezierSequence(logs, keys, sequence, refusal))
      {
        return false;
      }
      bezier.build(sequence, p, false, { lct::CurveScheme::Bezier, absolute }, &missing);
      if (missing.missing())
      {
        refusal = FromMissing(missing, keys, 0, true);
        return false;
      }
    }
    if (!current)
    {
      this->KeyLogs = std::move(rebuilt);
      this->P = p;
      this->LogsStatus = lct::Status::Ok;
      this->LogsCurrent = true;
      this->TangentsCurrent = false;
    }
    if (isBezier)
    {
      this->BezierLogs = std::move(bezier);
      this->BezierStatus = lct::Status::Ok;
    }
    this->BezierCurrent = isBezier;
    return true;
  }
};

//------------------------------------------------------------------------------
vtkTransformInterpolatorLCT::vtkTransformInterpolatorLCT()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkTransformInterpolatorLCT::~vtkTransformInterpolatorLCT()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::GetNumberOfTransforms()
{
  return static_cast<int>(this->Internal->Keys.size());
}

//------------------------------------------------------------------------------
double vtkTransformInterpolatorLCT::GetMinimumT()
{
  return this->Internal->Keys.minimumTime();
}

//------------------------------------------------------------------------------
double vtkTransformInterpolatorLCT::GetMaximumT()
{
  return this->Internal->Keys.maximumTime();
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::Initialize()
{
  Internals& in = *this->Internal;
  in.Keys.clear();
  in.KeyLogs = lct::KeyLogs(in.P);
  in.LogsStatus = lct::Status::Ok;
  in.KeysChanged(true);
  in.ClampReported = false; // new keys, a new range: its first clamp is reported again
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::AddKey(double t, const double elements[16], const char* caller)
{
  if (!std::isfinite(t))
  {
    vtkErrorMacro(<< caller << ": the key time " << t << " is not finite; key rejected.");
    return 0;
  }
  if (!this->Internal->Keys.keepsFiniteSpan(t))
  {
    vtkErrorMacro(<< caller << ": the key time " << lct::formatNumber(t)
                  << " would make the key times span more than the double range; key rejected.");
    return 0;
  }
  Key key;
  key.Time = t;
  key.Matrix = RowMajor4(Eigen::Map<const RowMajor4>(elements));
  // Each key on its own first, so that a bad key is named as the cause (and never a good
  // neighbour after it): finite, affine, det > 0, and within the conditioning and range of the
  // core. Then the logs the curve combines (Internals::Add): MatrixLog keys need an absolute log
  // only with ConsistentRotation.
  const lct::Status own = lct::polarLog(key.Matrix).status;
  if (own != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << lct::formatNumber(t) << ": " << lct::describe(own)
                  << "; key rejected.");
    return 0;
  }
  // A key at an existing time replaces it, as vtkTransformInterpolator does.
  Refusal refusal;
  if (!this->Internal->Add(key, this->InterpolationType, this->ConsistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< caller << " at t = " << lct::formatNumber(t) << ": "
                  << describe(refusal, this->Internal->P, this->InterpolationType)
                  << "; key rejected.");
    return 0;
  }
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::AddTransform(double t, vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    vtkErrorMacro(<< "AddTransform: null matrix; key rejected.");
    return 0;
  }
  return this->AddKey(t, matrix->GetData(), "AddTransform");
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::AddTransform(double t, vtkTransform* xform)
{
  if (!xform)
  {
    vtkErrorMacro(<< "AddTransform: null transform; key rejected.");
    return 0;
  }
  return this->AddKey(t, xform->GetMatrix()->GetData(), "AddTransform");
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::AddTransform(double t, vtkProp3D* prop3D)
{
  if (!prop3D)
  {
    vtkErrorMacro(<< "AddTransform: null prop; key rejected.");
    return 0;
  }
  return this->AddKey(t, prop3D->GetMatrix()->GetData(), "AddTransform");
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetBezierControls(
  double t, vtkMatrix4x4* incoming, vtkMatrix4x4* outgoing)
{
  Key* key = this->Internal->Keys.find(t);
  if (!key)
  {
    vtkErrorMacro(<< "SetBezierControls: no key at t = " << lct::formatNumber(t) << "; unchanged.");
    return 0;
  }
  vtkMatrix4x4* given[2] = { incoming, outgoing };
  for (vtkMatrix4x4* m : given)
  {
    const lct::Status valid = m
      ? lct::polarLog(RowMajor4(Eigen::Map<const RowMajor4>(m->GetData()))).status
      : lct::Status::Ok;
    if (valid != lct::Status::Ok)
    {
      vtkErrorMacro(<< "SetBezierControls(t = " << lct::formatNumber(t)
                    << "): " << lct::describe(valid) << "; unchanged.");
      return 0;
    }
  }
  Key changed = *key;
  changed.HasIncoming = incoming != nullptr;
  changed.HasOutgoing = outgoing != nullptr;
  if (incoming)
  {
    changed.Incoming = RowMajor4(Eigen::Map<const RowMajor4>(incoming->GetData()));
  }
  if (outgoing)
  {
    changed.Outgoing = RowMajor4(Eigen::Map<const RowMajor4>(outgoing->GetData()));
  }
  // Only a Bezier curve uses the controls (SetInterpolationType checks them when it switches).
  Refusal refusal;
  if (this->InterpolationType == INTERPOLATION_TYPE_BEZIER &&
    !this->Internal->SetControls(changed, this->ConsistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< "SetBezierControls(t = " << lct::formatNumber(t)
                  << "): " << describe(refusal, this->Internal->P, this->InterpolationType)
                  << "; unchanged.");
    return 0;
  }
  *key = changed;
  this->Internal->BezierCurrent = false;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::RemoveTransform(double t)
{
  if (!this->Internal->Keys.find(t))
  {
    return 1;
  }
  // Removing a key brings the keys on either side of it closer: they may then share curve
  // points whose logs do not exist (in MatrixLog, or for steps beyond the conditioning limit).
  Refusal refusal;
  if (!this->Internal->Remove(t, this->InterpolationType, this->ConsistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< "RemoveTransform(" << lct::formatNumber(t) << "): without this key, "
                  << describe(refusal, this->Internal->P, this->InterpolationType)
                  << "; not removed.");
    return 0;
  }
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetParametrisation(int parametrisation)
{
  if (parametrisation != POLAR && parametrisation != MATRIX_LOG)
  {
    vtkErrorMacro(<< "SetParametrisation: unknown parametrisation " << parametrisation
                  << "; unchanged.");
    return 0;
  }
  if (parametrisation == this->Parametrisation)
  {
    return 1;
  }
  const lct::Parametrisation p = toCore(parametrisation);
  if (parametrisation == MATRIX_LOG && this->ConsistentRotation)
  {
    vtkErrorMacro(<< "SetParametrisation(MatrixLog): " << kConsistentRotationNeedsPolar
                  << " (ConsistentRotationOff() first); unchanged.");
    return 0;
  }
  Refusal refusal;
  if (!this->Internal->Validate(p, this->InterpolationType, this->ConsistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< "SetParametrisation(" << lct::name(p)
                  << "): " << describe(refusal, p, this->InterpolationType) << "; unchanged.");
    return 0;
  }
  this->Parametrisation = parametrisation;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetInterpolationType(int type)
{
  if (!vtkLCTCheckedSet::InRange(this, "InterpolationType", this->InterpolationType, type,
        static_cast<int>(INTERPOLATION_TYPE_LINEAR), static_cast<int>(INTERPOLATION_TYPE_BEZIER)))
  {
    return 0;
  }
  if (type == this->InterpolationType)
  {
    return 1;
  }
  Refusal refusal;
  if (!this->Internal->Validate(this->Internal->P, type, this->ConsistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< "SetInterpolationType(" << typeName(type)
                  << "): " << describe(refusal, this->Internal->P, type) << "; unchanged.");
    return 0;
  }
  this->InterpolationType = type;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetConsistentRotation(vtkTypeBool consistentRotation)
{
  if (consistentRotation == this->ConsistentRotation)
  {
    return 1;
  }
  if (consistentRotation && this->Parametrisation == MATRIX_LOG)
  {
    vtkErrorMacro(<< "SetConsistentRotation(on): " << kConsistentRotationNeedsPolar
                  << " (SetParametrisationToPolar() first); unchanged.");
    return 0;
  }
  Refusal refusal;
  if ((consistentRotation != 0) != (this->ConsistentRotation != 0) &&
    !this->Internal->Validate(
      this->Internal->P, this->InterpolationType, consistentRotation != 0, refusal))
  {
    vtkErrorMacro(<< "SetConsistentRotation(" << (consistentRotation ? "on" : "off")
                  << "): " << describe(refusal, this->Internal->P, this->InterpolationType)
                  << "; unchanged.");
    return 0;
  }
  this->ConsistentRotation = consistentRotation;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTransformInterpolatorLCT::Evaluate(double t, double out[16])
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (n == 0)
  {
    vtkErrorMacro(<< "InterpolateTransform: no keys; output unchanged.");
    return false;
  }
  if (!std::isfinite(t))
  {
    vtkErrorMacro(<< "InterpolateTransform: "
                  << (std::isnan(t) ? "t is NaN"
                                    : (t > 0 ? "t = inf is infinite" : "t = -inf is infinite"))
                  << "; output unchanged.");
    return false;
  }
  if ((t < in.Keys.minimumTime() || t > in.Keys.maximumTime()) && !in.ClampReported.exchange(true))
  {
    vtkWarningMacro(<< "InterpolateTransform: t = " << lct::formatNumber(t)
                    << " is outside the key times [" << lct::formatNumber(in.Keys.minimumTime())
                    << ", " << lct::formatNumber(in.Keys.maximumTime())
                    << "]: clamped, as vtkTransformInterpolator does (reported once).");
  }
  const lct::CurveScheme scheme = toScheme(this->InterpolationType);
  const lct::KeyLogs* logs = scheme == lct::CurveScheme::Bezier ? in.Bezier() : in.Logs();
  if (!logs)
  {
    const bool bezier = scheme == lct::CurveScheme::Bezier;
    vtkErrorMacro(<< "InterpolateTransform(" << lct::formatNumber(t) << "): the "
                  << (bezier ? "Bezier control transforms near the key" : "step to the key")
                  << " at t = "
                  << lct::formatNumber(bezier ? in.BezierFailedTime : in.LogsFailedTime)
                  << (bezier ? " have no " : " has no ") << lct::name(in.P)
                  << " logarithm: " << lct::describe(bezier ? in.BezierStatus : in.LogsStatus)
                  << lct::adviceFor(bezier ? in.BezierStatus : in.LogsStatus, in.P)
                  << "; output unchanged.");
    return false;
  }
  double curveTime = t;
  if (!this->CurveTime(t, curveTime, "InterpolateTransform"))
  {
    return false;
  }
  Eigen::Matrix4d result;
  lct::MissingLog missing;
  const lct::Status status = in.CurveAt(*logs, scheme, this->MonotoneTangents,
    this->StraightenImpacts, this->ConsistentRotation, curveTime, result, &missing);
  if (missing.missing())
  {
    // Every edit and setting checks the logs its curve points combine, so this is a defect.
    const std::vector<const Key*> keys = in.FlatKeys();
    vtkErrorMacro(<< "InterpolateTransform(" << lct::formatNumber(t) << "): "
                  << describe(
                       Internals::FromMissing(missing, keys, 0, scheme == lct::CurveScheme::Bezier),
                       in.P, this->InterpolationType)
                  << " (a defect of vtkLCT: the keys should have been refused; please report "
                     "them); output unchanged.");
    return false;
  }
  if (status != lct::Status::Ok)
  {
    vtkErrorMacro(<< "InterpolateTransform(" << lct::formatNumber(t) << "): "
                  << (this->ConsistentRotation ? "the absolute logarithms (ConsistentRotation) "
                                               : "the combination of the keys ")
                  << "failed: " << lct::describe(status) << lct::adviceFor(status, in.P)
                  << "; output unchanged.");
    return false;
  }
  Eigen::Map<RowMajor4> output(out);
  output = result;
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransformInterpolatorLCT::CurveTime(double t, double& curveTime, const char* caller)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (!this->ConstantSpeed || n < 2)
  {
    curveTime = n < 2 ? t : vtkLCTPathTiming::EasedCurveTime(in.Keys, in.Timing, t);
    return true;
  }
  const lct::CurveScheme scheme = toScheme(this->InterpolationType);
  const lct::KeyLogs* logs = scheme == lct::CurveScheme::Bezier ? in.Bezier() : in.Logs();
  const auto positionAt = [&](double tau, Eigen::Vector3d& p, std::string& cause) {
    Eigen::Matrix4d m;
    const lct::Status status = logs
      ? in.CurveAt(*logs, scheme, this->MonotoneTangents, this->StraightenImpacts,
          this->ConsistentRotation, tau, m, nullptr)
      : lct::Status::InvalidArgument;
    if (status != lct::Status::Ok)
    {
      cause = logs ? std::string("the combination of the keys failed: ") + lct::describe(status)
                   : std::string("the key logs are missing");
      return false;
    }
    p = m.topLeftCorner<3, 3>() * in.ConstantSpeedPoint + m.topRightCorner<3, 1>();
    return true;
  };
  return in.ConstantSpeedTable.CurveTime(
    this, caller, this->GetMTime(), in.Keys.times().data(), n, in.Timing, t, positionAt, curveTime);
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::GetKeyArrivalTimes(vtkDoubleArray* arrivals)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (!arrivals || n == 0)
  {
    vtkErrorMacro(<< "GetKeyArrivalTimes: " << (arrivals ? "no keys" : "null array")
                  << "; nothing written.");
    return 0;
  }
  in.Keys.flatten();
  if (!this->ConstantSpeed || n < 2)
  {
    vtkLCTPathTiming::KeyTimes(in.Keys.times(), arrivals);
    return 1;
  }
  double ignored;
  if (!this->CurveTime(in.Keys.minimumTime(), ignored, "GetKeyArrivalTimes"))
  {
    return 0; // CurveTime reported why
  }
  // Built for this MTime by CurveTime.
  in.ConstantSpeedTable.ArrivalTimes(in.Keys.times().data(), n, in.Timing, arrivals);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetTension(double tension)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Tension, tension);
}
int vtkTransformInterpolatorLCT::SetContinuity(double continuity)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Continuity, continuity);
}
int vtkTransformInterpolatorLCT::SetBias(double bias)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Bias, bias);
}
int vtkTransformInterpolatorLCT::SetEaseIn(double ease)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::EaseIn, ease);
}
int vtkTransformInterpolatorLCT::SetEaseOut(double ease)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::EaseOut, ease);
}
double vtkTransformInterpolatorLCT::GetTension()
{
  return this->Internal->Timing.tensionContinuityBias.tension;
}
double vtkTransformInterpolatorLCT::GetContinuity()
{
  return this->Internal->Timing.tensionContinuityBias.continuity;
}
double vtkTransformInterpolatorLCT::GetBias()
{
  return this->Internal->Timing.tensionContinuityBias.bias;
}
double vtkTransformInterpolatorLCT::GetEaseIn()
{
  return this->Internal->Timing.easeIn;
}
double vtkTransformInterpolatorLCT::GetEaseOut()
{
  return this->Internal->Timing.easeOut;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetKeyTensionContinuityBias(
  double t, double tension, double continuity, double bias)
{
  return vtkLCTPathTiming::SetKeyTensionContinuityBias(
    this, this->Internal->Keys, t, { tension, continuity, bias });
}
int vtkTransformInterpolatorLCT::SetKeyEase(double t, double arriving, double leaving)
{
  return vtkLCTPathTiming::SetKeyEase(this, this->Internal->Keys, t, arriving, leaving);
}
int vtkTransformInterpolatorLCT::ClearKeyTiming(double t)
{
  return vtkLCTPathTiming::ClearKeyTiming(this, this->Internal->Keys, t);
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::SetConstantSpeedPoint(double x, double y, double z)
{
  const Eigen::Vector3d point(x, y, z);
  if (!point.allFinite())
  {
    vtkErrorMacro(<< "SetConstantSpeedPoint(" << lct::formatNumber(x) << ", "
                  << lct::formatNumber(y) << ", " << lct::formatNumber(z)
                  << "): the point is not finite; unchanged.");
    return 0;
  }
  if (point != this->Internal->ConstantSpeedPoint)
  {
    this->Internal->ConstantSpeedPoint = point;
    this->Modified();
  }
  return 1;
}

void vtkTransformInterpolatorLCT::GetConstantSpeedPoint(double point[3])
{
  Eigen::Map<Eigen::Vector3d> out(point);
  out = this->Internal->ConstantSpeedPoint;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::InterpolateTransform(double t, vtkMatrix4x4* matrix)
{
  double elements[16];
  if (!matrix || !this->Evaluate(t, elements))
  {
    return 0;
  }
  matrix->DeepCopy(elements);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::InterpolateTransform(double t, vtkTransform* xform)
{
  double elements[16];
  if (!xform || !this->Evaluate(t, elements))
  {
    return 0;
  }
  xform->SetMatrix(elements);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformInterpolatorLCT::InterpolateTransform(double t, vtkLogTransform* xform)
{
  double elements[16];
  if (!xform || !this->Evaluate(t, elements))
  {
    return 0;
  }
  return xform->SetMatrix(elements);
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const types[] = { "Linear", "Spline", "BSpline", "Subdivision", "Bezier" };
  os << indent << "InterpolationType: " << types[this->InterpolationType] << "\n";
  os << indent << "Parametrisation: " << lct::name(toCore(this->Parametrisation)) << "\n";
  os << indent << "ConsistentRotation: " << (this->ConsistentRotation ? "On" : "Off") << "\n";
  os << indent << "MonotoneTangents: " << (this->MonotoneTangents ? "On" : "Off") << "\n";
  os << indent << "StraightenImpacts: " << (this->StraightenImpacts ? "On" : "Off") << "\n";
  vtkLCTPathTiming::Print(os, indent, this->Internal->Timing, this->ConstantSpeed);
  const Eigen::Vector3d& point = this->Internal->ConstantSpeedPoint;
  os << indent << "ConstantSpeedPoint: (" << point.x() << ", " << point.y() << ", " << point.z()
     << ")\n";
  os << indent << "NumberOfTransforms: " << this->GetNumberOfTransforms() << "\n";
  if (!this->Internal->Keys.empty())
  {
    os << indent << "Time range: [" << this->GetMinimumT() << ", " << this->GetMaximumT() << "]\n";
  }
}
