#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/Curves.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"
#include "lct/Parametrisation.h"

#include "vtkLogTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkProp3D.h"
#include "vtkTransform.h"

#include <algorithm>
#include <cmath>
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

/// The keys and the logs derived from them, updated together whenever the keys change.
struct vtkTransformInterpolatorLCT::Internals
{
  lct::Keyframes<Key> Keys;
  /// Logs of the keys (Linear, Spline, BSpline, Subdivision), updated incrementally.
  lct::KeyLogs KeyLogs;
  /// Logs of the Bezier sequence K0, C0+, C1-, K1, ... (see lct/Curves.h), built on the first
  /// Bezier evaluation after a change, and why they are missing if they are (MatrixLog: a
  /// control transform without a real log), which only matters to the Bezier type.
  bool BezierCurrent = false;
  lct::KeyLogs BezierLogs;
  lct::Status BezierStatus = lct::Status::Ok;
  double BezierFailedTime = 0.0;

  /// The Bezier sequence: given control transforms, else automatic ones that put the
  /// Catmull-Rom tangent m of the logs relative to the key (in its frame) at each key:
  /// C+ = K exp(+h/3 m), C- = K exp(-h/3 m), with h the segment's duration.
  lct::Status BezierSequence(std::vector<Eigen::Matrix4d>& out, int& failedKey) const
  {
    const int n = static_cast<int>(this->Keys.size());
    const lct::Parametrisation p = this->KeyLogs.parametrisation();
    out.clear();
    // Neighbours always have relative logs (the key logs require it).
    auto tangent = [&](int k) -> lct::LogCoords {
      const int lo = std::max(k - 1, 0);
      const int hi = std::min(k + 1, n - 1);
      return (*this->KeyLogs.relative(hi, k) - *this->KeyLogs.relative(lo, k)) /
        (this->Keys.times()[hi] - this->Keys.times()[lo]);
    };
    auto automatic = [&](int k, double signedThird, Eigen::Matrix4d& control) {
      const auto c = lct::exponential(signedThird * tangent(k), p);
      if (c)
      {
        control = this->Keys[k].Matrix * c.value;
      }
      failedKey = k;
      return c.status;
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

  /// The Bezier logs, built if the keys changed since the last call.
  const lct::KeyLogs& Bezier()
  {
    if (!this->BezierCurrent)
    {
      std::vector<Eigen::Matrix4d> sequence;
      int failed = 0;
      this->BezierStatus = this->BezierSequence(sequence, failed);
      if (this->BezierStatus == lct::Status::Ok)
      {
        this->BezierStatus =
          this->BezierLogs.build(sequence, this->KeyLogs.parametrisation(), false, &failed);
        failed = (failed + 1) / 3;
      }
      this->BezierFailedTime =
        this->Keys.empty() ? 0.0 : this->Keys[std::min<size_t>(failed, this->Keys.size() - 1)].Time;
      this->BezierCurrent = true;
    }
    return this->BezierLogs;
  }

  void KeysChanged() { this->BezierCurrent = false; }

  /// Adds or replaces (same time) a key. On failure nothing changes.
  lct::Status Add(const Key& key)
  {
    const int index = this->Keys.position(key.Time);
    const bool replaces = this->Keys.find(key.Time) == index;
    const lct::Status status = replaces ? this->KeyLogs.replace(index, key.Matrix, true)
                                        : this->KeyLogs.insert(index, key.Matrix, true);
    if (status == lct::Status::Ok)
    {
      if (replaces)
      {
        this->Keys.replace(index, key);
      }
      else
      {
        this->Keys.insert(index, key);
      }
      this->KeysChanged();
    }
    return status;
  }

  /// Removes the key at `index`. On failure nothing changes.
  lct::Status Remove(int index)
  {
    const lct::Status status = this->KeyLogs.erase(index, true);
    if (status == lct::Status::Ok)
    {
      this->Keys.erase(index);
      this->KeysChanged();
    }
    return status;
  }

  /// Recomputes every log in parametrisation p. On failure nothing changes.
  lct::Status Rebuild(lct::Parametrisation p, double& failedTime)
  {
    std::vector<Eigen::Matrix4d> matrices;
    for (size_t i = 0; i < this->Keys.size(); ++i)
    {
      matrices.push_back(this->Keys[i].Matrix);
    }
    int failed = 0;
    const lct::Status status = this->KeyLogs.build(matrices, p, true, &failed);
    if (status != lct::Status::Ok)
    {
      failedTime = this->Keys[failed].Time;
      return status;
    }
    this->KeysChanged();
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
  this->Internal->Keys.clear();
  this->Internal->KeyLogs = lct::KeyLogs(toCore(this->Parametrisation));
  this->Internal->KeysChanged();
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
  Key key;
  key.Time = t;
  key.Matrix = RowMajor4(Eigen::Map<const RowMajor4>(elements));
  const lct::Status valid = lct::validateAffine(key.Matrix);
  if (valid != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << t << ": " << lct::describe(valid)
                  << "; key rejected.");
    return 0;
  }
  // A key at an existing time replaces it, as vtkTransformInterpolator does.
  const lct::Status added = this->Internal->Add(key);
  if (added != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << t << ": the step between this key and a "
                  << "neighbour has no real " << lct::name(toCore(this->Parametrisation))
                  << " logarithm (" << lct::describe(added) << "); key rejected.");
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
  const int index = this->Internal->Keys.find(t);
  if (index < 0)
  {
    vtkErrorMacro(<< "SetBezierControls: no key at t = " << t << "; unchanged.");
    return 0;
  }
  Key* key = &this->Internal->Keys[index];
  vtkMatrix4x4* given[2] = { incoming, outgoing };
  for (vtkMatrix4x4* m : given)
  {
    const lct::Status valid = m
      ? lct::validateAffine(RowMajor4(Eigen::Map<const RowMajor4>(m->GetData())))
      : lct::Status::Ok;
    if (valid != lct::Status::Ok)
    {
      vtkErrorMacro(<< "SetBezierControls(t = " << t << "): " << lct::describe(valid)
                    << "; unchanged.");
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
  this->Internal->KeysChanged();
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::RemoveTransform(double t)
{
  const int index = this->Internal->Keys.find(t);
  if (index < 0)
  {
    return;
  }
  // Removing a key cannot create a missing log in Polar; in MatrixLog its two neighbours may
  // have none between them, so check.
  if (this->Internal->Remove(index) != lct::Status::Ok)
  {
    vtkErrorMacro(<< "RemoveTransform(" << t << "): the remaining keys have no common "
                  << lct::name(toCore(this->Parametrisation)) << " logarithms; not removed.");
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
  const lct::Status built = this->Internal->Rebuild(toCore(parametrisation), failedTime);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< "SetParametrisation: the key at t = " << failedTime << " has no "
                  << lct::name(toCore(parametrisation)) << " logarithm (" << lct::describe(built)
                  << "); unchanged.");
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
  if (std::isnan(t))
  {
    vtkErrorMacro(<< "InterpolateTransform: t is NaN; output unchanged.");
    return false;
  }
  const lct::CurveScheme scheme = toScheme(this->InterpolationType);
  const lct::KeyLogs& logs = scheme == lct::CurveScheme::Bezier ? in.Bezier() : in.KeyLogs;
  if (scheme == lct::CurveScheme::Bezier && in.BezierStatus != lct::Status::Ok)
  {
    vtkErrorMacro(<< "InterpolateTransform(" << t << "): the Bezier control transforms near the "
                  << "key at t = " << in.BezierFailedTime << " have no "
                  << lct::name(toCore(this->Parametrisation)) << " logarithm ("
                  << lct::describe(in.BezierStatus) << "); output unchanged.");
    return false;
  }
  const lct::CurveWeights w = lct::curveWeights(scheme, in.Keys.times().data(), n, t);
  Eigen::Matrix4d result;
  const lct::Status status =
    this->ConsistentRotation ? logs.combineAbsolute(w, result) : logs.combineRelative(w, result);
  if (status != lct::Status::Ok)
  {
    vtkErrorMacro(<< "InterpolateTransform(" << t << "): "
                  << (status == lct::Status::NoRealLogarithm
                         ? "two transforms combined here have no real MatrixLog logarithm "
                           "between them; use the Polar parametrisation"
                         : lct::describe(status))
                  << ". Output unchanged.");
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
