#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/Curves.h"
#include "lct/Format.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"
#include "lct/RebuildOnce.h"

#include "vtkLogTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProp3D.h"
#include "vtkTransform.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <mutex>
#include <vector>

vtkStandardNewMacro(vtkTransformInterpolatorLCT);

namespace
{
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
} // namespace

/// The keys, and the logs derived from them. Edits change the keys in O(log n) and mark the logs
/// stale (an append or a replacement updates them in place when they are current); the first
/// evaluation after that rebuilds them in O(n), under a mutex, so that evaluations may run
/// concurrently once the keys stop changing.
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
  /// Whether a query outside the key range has been reported (once per interpolator).
  std::atomic<bool> ClampReported{ false };

  void KeysChanged(bool logsCurrent)
  {
    this->LogsCurrent = logsCurrent;
    this->BezierCurrent = false;
  }

  /// The key logs, rebuilt if stale. Null, with LogsStatus saying why, when they cannot be.
  const lct::KeyLogs* Logs()
  {
    lct::rebuildOnce(this->LogsCurrent, this->Mutex, [this] {
      this->Keys.flatten();
      std::vector<Eigen::Matrix4d> matrices;
      matrices.reserve(this->Keys.size());
      for (size_t i = 0; i < this->Keys.size(); ++i)
      {
        matrices.push_back(this->Keys[i].Matrix);
      }
      int failed = 0;
      this->LogsStatus = this->KeyLogs.build(matrices, this->P, true, &failed);
      this->LogsFailedTime = this->LogsStatus == lct::Status::Ok ? 0.0 : this->Keys[failed].Time;
    });
    return this->LogsStatus == lct::Status::Ok ? &this->KeyLogs : nullptr;
  }

  /// The Bezier sequence: given control transforms, else automatic ones that put the
  /// Catmull-Rom tangent m of the logs relative to the key (in its frame) at each key:
  /// C+ = K exp(+h/3 m), C- = K exp(-h/3 m), with h the segment's duration.
  lct::Status BezierSequence(
    const lct::KeyLogs& logs, std::vector<Eigen::Matrix4d>& out, int& failedKey) const
  {
    const int n = static_cast<int>(this->Keys.size());
    out.clear();
    auto automatic = [&](int k, double signedThird, Eigen::Matrix4d& control) {
      failedKey = k;
      const int lo = std::max(k - 1, 0);
      const int hi = std::min(k + 1, n - 1);
      const lct::LogCoords* forward = logs.relative(hi, k);
      const lct::LogCoords* backward = logs.relative(lo, k);
      if (!forward || !backward)
      {
        return !forward ? logs.relativeStatus(hi, k) : logs.relativeStatus(lo, k);
      }
      const lct::LogCoords tangent =
        (*forward - *backward) / (this->Keys.times()[hi] - this->Keys.times()[lo]);
      const auto c = lct::exponential(signedThird * tangent, this->P);
      if (!c)
      {
        return c.status;
      }
      control = this->Keys[k].Matrix * c.value;
      return control.allFinite() ? lct::Status::Ok : lct::Status::OutOfRange;
    };
    for (int k = 0; k < n; ++k)
    {
      const Key& key = this->Keys[k];
      Eigen::Matrix4d control;
      if (k > 0)
      {
        if (!key.HasIncoming)
        {
          const lct::Status status =
            automatic(k, -(this->Keys[k].Time - this->Keys[k - 1].Time) / 3.0, control);
          if (status != lct::Status::Ok)
          {
            return status;
          }
        }
        out.push_back(key.HasIncoming ? key.Incoming : control);
      }
      out.push_back(key.Matrix);
      if (k + 1 < n)
      {
        if (!key.HasOutgoing)
        {
          const lct::Status status =
            automatic(k, (this->Keys[k + 1].Time - this->Keys[k].Time) / 3.0, control);
          if (status != lct::Status::Ok)
          {
            return status;
          }
        }
        out.push_back(key.HasOutgoing ? key.Outgoing : control);
      }
    }
    return lct::Status::Ok;
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
      std::vector<Eigen::Matrix4d> sequence;
      int failed = 0;
      this->BezierStatus = this->BezierSequence(*logs, sequence, failed);
      if (this->BezierStatus == lct::Status::Ok)
      {
        this->BezierStatus = this->BezierLogs.build(sequence, this->P, false, &failed);
        failed = (failed + 1) / 3;
      }
      this->BezierFailedTime =
        this->Keys.empty() ? 0.0 : this->Keys[std::min<size_t>(failed, this->Keys.size() - 1)].Time;
    });
    return this->BezierStatus == lct::Status::Ok ? &this->BezierLogs : nullptr;
  }

  /// Why a step from `from` to `to` cannot be interpolated in P, or Ok.
  lct::Status StepStatus(const Eigen::Matrix4d& from, const Eigen::Matrix4d& to) const
  {
    const Eigen::Matrix4d step = lct::relativeStep(from, to);
    if (!step.allFinite())
    {
      return lct::Status::OutOfRange;
    }
    return lct::logarithm(step, this->P).status;
  }

  /// Adds or replaces (same time) a key whose own validity was checked; `neighbourTime`
  /// receives the time of a neighbour the key cannot be joined to. On failure nothing changes.
  lct::Status Add(const Key& key, double& neighbourTime)
  {
    for (const Key* neighbour : { this->Keys.before(key.Time), this->Keys.after(key.Time) })
    {
      if (neighbour)
      {
        const lct::Status step = neighbour->Time < key.Time
          ? this->StepStatus(neighbour->Matrix, key.Matrix)
          : this->StepStatus(key.Matrix, neighbour->Matrix);
        if (step != lct::Status::Ok)
        {
          neighbourTime = neighbour->Time;
          return step;
        }
      }
    }
    const bool replaces = this->Keys.find(key.Time) != nullptr;
    const bool append = this->Keys.isAppend(key.Time);
    bool logsCurrent = false;
    // An append or a replacement updates current logs in place (O(1) logs); anything else
    // leaves them to the next evaluation's rebuild.
    if (this->LogsCurrent && this->LogsStatus == lct::Status::Ok && (append || replaces))
    {
      this->Keys.flatten();
      const int index = replaces ? this->Keys.index(key.Time) : static_cast<int>(this->Keys.size());
      logsCurrent = (replaces ? this->KeyLogs.replace(index, key.Matrix, true)
                              : this->KeyLogs.insert(index, key.Matrix, true)) == lct::Status::Ok;
    }
    this->Keys.set(key);
    this->KeysChanged(logsCurrent);
    return lct::Status::Ok;
  }

  /// Removes the key at time t. Fails (nothing changes) when its neighbours cannot be joined.
  lct::Status Remove(double t)
  {
    const Key* before = this->Keys.before(t);
    const Key* after = this->Keys.after(t);
    if (before && after)
    {
      const lct::Status step = this->StepStatus(before->Matrix, after->Matrix);
      if (step != lct::Status::Ok)
      {
        return step;
      }
    }
    this->Keys.erase(t);
    this->KeysChanged(false);
    return lct::Status::Ok;
  }

  /// Recomputes every log in parametrisation p. On failure nothing changes.
  lct::Status Rebuild(lct::Parametrisation p, double& failedTime)
  {
    std::lock_guard<std::mutex> lock(this->Mutex);
    this->Keys.flatten();
    std::vector<Eigen::Matrix4d> matrices;
    for (size_t i = 0; i < this->Keys.size(); ++i)
    {
      matrices.push_back(this->Keys[i].Matrix);
    }
    int failed = 0;
    lct::KeyLogs logs;
    const lct::Status status = logs.build(matrices, p, true, &failed);
    if (status != lct::Status::Ok)
    {
      failedTime = this->Keys[failed].Time;
      return status;
    }
    this->KeyLogs = std::move(logs);
    this->P = p;
    this->LogsStatus = lct::Status::Ok;
    this->LogsCurrent = true;
    this->BezierCurrent = false;
    return lct::Status::Ok;
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
  // core. MatrixLog keys need no absolute log: only their steps to the neighbours must have one.
  const lct::Status own = lct::polarLog(key.Matrix).status;
  if (own != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << lct::formatNumber(t) << ": " << lct::describe(own)
                  << "; key rejected.");
    return 0;
  }
  // A key at an existing time replaces it, as vtkTransformInterpolator does.
  double neighbourTime = 0.0;
  const lct::Status added = this->Internal->Add(key, neighbourTime);
  if (added != lct::Status::Ok)
  {
    const lct::Parametrisation p = this->Internal->P;
    vtkErrorMacro(<< caller << " at t = " << lct::formatNumber(t)
                  << ": the step between this key and the key at t = "
                  << lct::formatNumber(neighbourTime) << " has no " << lct::name(p)
                  << " logarithm: " << lct::describe(added) << lct::adviceFor(added, p)
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
  key->HasIncoming = incoming != nullptr;
  key->HasOutgoing = outgoing != nullptr;
  if (incoming)
  {
    key->Incoming = RowMajor4(Eigen::Map<const RowMajor4>(incoming->GetData()));
  }
  if (outgoing)
  {
    key->Outgoing = RowMajor4(Eigen::Map<const RowMajor4>(outgoing->GetData()));
  }
  this->Internal->BezierCurrent = false;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::RemoveTransform(double t)
{
  if (!this->Internal->Keys.find(t))
  {
    return;
  }
  // Removing a key makes its two neighbours adjacent: in MatrixLog (or for steps beyond the
  // conditioning limit) they may not be joinable, so check.
  const lct::Status removed = this->Internal->Remove(t);
  if (removed != lct::Status::Ok)
  {
    const lct::Parametrisation p = this->Internal->P;
    vtkErrorMacro(<< "RemoveTransform(" << lct::formatNumber(t)
                  << "): its two neighbours would be joined by a step without a " << lct::name(p)
                  << " logarithm: " << lct::describe(removed) << lct::adviceFor(removed, p)
                  << "; not removed.");
    return;
  }
  this->Modified();
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
  double failedTime = 0.0;
  const lct::Parametrisation p = toCore(parametrisation);
  const lct::Status built = this->Internal->Rebuild(p, failedTime);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< "SetParametrisation: the step to the key at t = "
                  << lct::formatNumber(failedTime) << " has no " << lct::name(p)
                  << " logarithm: " << lct::describe(built) << "; unchanged.");
    return 0;
  }
  this->Parametrisation = parametrisation;
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
  const lct::CurveWeights w = lct::curveWeights(scheme, in.Keys.times().data(), n, t);
  Eigen::Matrix4d result;
  const lct::Status status =
    this->ConsistentRotation ? logs->combineAbsolute(w, result) : logs->combineRelative(w, result);
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
  os << indent << "NumberOfTransforms: " << this->GetNumberOfTransforms() << "\n";
  if (!this->Internal->Keys.empty())
  {
    os << indent << "Time range: [" << this->GetMinimumT() << ", " << this->GetMaximumT() << "]\n";
  }
}
