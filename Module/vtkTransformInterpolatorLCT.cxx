#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/Curves.h"
#include "lct/KeyLogs.h"
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

/// The keys and the logs derived from them, rebuilt together whenever the keys change.
struct vtkTransformInterpolatorLCT::Internals
{
  std::vector<Key> Keys;
  std::vector<double> Times;
  /// Logs of the keys (Linear, Spline, BSpline, Subdivision).
  lct::KeyLogs KeyLogs;
  /// Logs of the Bezier sequence K0, C0+, C1-, K1, ... (see lct/Curves.h), and why they are
  /// missing if they are (MatrixLog: a control transform without a real log). That only
  /// matters to the Bezier type, so it does not stop keys from being added.
  lct::KeyLogs BezierLogs;
  lct::Status BezierStatus = lct::Status::Ok;
  double BezierFailedTime = 0.0;

  /// The Bezier sequence: given control transforms, else automatic ones that put the
  /// Catmull-Rom tangent at each key, taken relative to the key (so C- K C+ are collinear in the
  /// key's frame): C+ = exp(+h/3 m) K, C- = exp(-h/3 m) K with h the segment's duration.
  static lct::Status BezierSequence(const std::vector<Key>& keys, const lct::KeyLogs& keyLogs,
    lct::Parametrisation p, std::vector<Eigen::Matrix4d>& out)
  {
    const int n = static_cast<int>(keys.size());
    out.clear();
    // Neighbours always have relative logs (KeyLogs::build with neighboursMustCombine).
    auto tangent = [&](int k) -> lct::LogCoords {
      const int lo = std::max(k - 1, 0);
      const int hi = std::min(k + 1, n - 1);
      return (*keyLogs.relative(hi, k) - *keyLogs.relative(lo, k)) /
        (keys[hi].Time - keys[lo].Time);
    };
    for (int k = 0; k < n; ++k)
    {
      if (k > 0)
      {
        if (keys[k].HasIncoming)
        {
          out.push_back(keys[k].Incoming);
        }
        else
        {
          const double h = keys[k].Time - keys[k - 1].Time;
          const auto c = lct::exponential(-h / 3.0 * tangent(k), p);
          if (!c)
          {
            return c.status;
          }
          out.push_back(c.value * keys[k].Matrix);
        }
      }
      out.push_back(keys[k].Matrix);
      if (k + 1 < n)
      {
        if (keys[k].HasOutgoing)
        {
          out.push_back(keys[k].Outgoing);
        }
        else
        {
          const double h = keys[k + 1].Time - keys[k].Time;
          const auto c = lct::exponential(h / 3.0 * tangent(k), p);
          if (!c)
          {
            return c.status;
          }
          out.push_back(c.value * keys[k].Matrix);
        }
      }
    }
    return lct::Status::Ok;
  }

  /// Computes every log for `keys` in parametrisation p and, on success, makes them current.
  /// On failure nothing changes and `failedTime` is the time of the offending key.
  lct::Status Build(const std::vector<Key>& keys, lct::Parametrisation p, double& failedTime)
  {
    std::vector<Eigen::Matrix4d> matrices;
    for (const Key& k : keys)
    {
      matrices.push_back(k.Matrix);
    }
    lct::KeyLogs keyLogs;
    int failed = -1;
    lct::Status status = keyLogs.build(matrices, p, true, &failed);
    if (status != lct::Status::Ok)
    {
      failedTime = keys[failed].Time;
      return status;
    }
    std::vector<Eigen::Matrix4d> sequence;
    lct::KeyLogs bezierLogs;
    failed = 0;
    this->BezierStatus = BezierSequence(keys, keyLogs, p, sequence);
    if (this->BezierStatus == lct::Status::Ok)
    {
      this->BezierStatus = bezierLogs.build(sequence, p, false, &failed);
    }
    this->BezierFailedTime = keys.empty() ? 0.0 : keys[std::min<int>((failed + 1) / 3, static_cast<int>(keys.size()) - 1)].Time;
    this->Keys = keys;
    this->KeyLogs = std::move(keyLogs);
    this->BezierLogs = std::move(bezierLogs);
    this->Times.resize(keys.size());
    for (size_t i = 0; i < keys.size(); ++i)
    {
      this->Times[i] = keys[i].Time;
    }
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
  return this->Internal->Keys.empty() ? 0.0 : this->Internal->Keys.front().Time;
}

//------------------------------------------------------------------------------
double vtkTransformInterpolatorLCT::GetMaximumT()
{
  return this->Internal->Keys.empty() ? 0.0 : this->Internal->Keys.back().Time;
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::Initialize()
{
  double unused;
  this->Internal->Build({}, toCore(this->Parametrisation), unused);
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
  Key key{ t, RowMajor4(Eigen::Map<const RowMajor4>(elements)) };
  const lct::Status valid = lct::validateAffine(key.Matrix);
  if (valid != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << t << ": " << lct::describe(valid)
                  << "; key rejected.");
    return 0;
  }
  std::vector<Key> keys = this->Internal->Keys;
  auto at = std::lower_bound(
    keys.begin(), keys.end(), t, [](const Key& k, double time) { return k.Time < time; });
  if (at != keys.end() && at->Time == t)
  {
    *at = key; // same time: replace, as vtkTransformInterpolator does
  }
  else
  {
    keys.insert(at, key);
  }
  double failedTime = t;
  const lct::Status built = this->Internal->Build(keys, toCore(this->Parametrisation), failedTime);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << t << ": the key at t = " << failedTime
                  << " (or the step to it) has no " << lct::name(toCore(this->Parametrisation))
                  << " logarithm (" << lct::describe(built) << "); key rejected.");
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
  std::vector<Key> keys = this->Internal->Keys;
  auto key = std::find_if(keys.begin(), keys.end(), [t](const Key& k) { return k.Time == t; });
  if (key == keys.end())
  {
    vtkErrorMacro(<< "SetBezierControls: no key at t = " << t << "; unchanged.");
    return 0;
  }
  vtkMatrix4x4* given[2] = { incoming, outgoing };
  for (vtkMatrix4x4* m : given)
  {
    const lct::Status valid = m ? lct::validateAffine(RowMajor4(Eigen::Map<const RowMajor4>(m->GetData())))
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
  double failedTime = t;
  if (this->Internal->Build(keys, toCore(this->Parametrisation), failedTime) != lct::Status::Ok)
  {
    vtkErrorMacro(<< "SetBezierControls(t = " << t << "): the keys no longer have logarithms; "
                  << "unchanged.");
    return 0;
  }
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformInterpolatorLCT::RemoveTransform(double t)
{
  std::vector<Key> keys = this->Internal->Keys;
  const auto end =
    std::remove_if(keys.begin(), keys.end(), [t](const Key& k) { return k.Time == t; });
  if (end == keys.end())
  {
    return;
  }
  keys.erase(end, keys.end());
  double unused;
  // Removing a key cannot create a missing log in Polar; in MatrixLog it can bring keys
  // farther apart into one curve point, so check.
  if (this->Internal->Build(keys, toCore(this->Parametrisation), unused) != lct::Status::Ok)
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
  const std::vector<Key> keys = this->Internal->Keys;
  const lct::Status built = this->Internal->Build(keys, toCore(parametrisation), failedTime);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< "SetParametrisation: the key at t = " << failedTime << " has no "
                  << lct::name(toCore(parametrisation)) << " logarithm ("
                  << lct::describe(built) << "); unchanged.");
    return 0;
  }
  this->Parametrisation = parametrisation;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTransformInterpolatorLCT::Evaluate(double t, double out[16])
{
  const Internals& in = *this->Internal;
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
  if (scheme == lct::CurveScheme::Bezier && in.BezierStatus != lct::Status::Ok)
  {
    vtkErrorMacro(<< "InterpolateTransform(" << t << "): the Bezier control transforms near the "
                  << "key at t = " << in.BezierFailedTime << " have no "
                  << lct::name(toCore(this->Parametrisation)) << " logarithm ("
                  << lct::describe(in.BezierStatus) << "); output unchanged.");
    return false;
  }
  const lct::KeyLogs& logs = scheme == lct::CurveScheme::Bezier ? in.BezierLogs : in.KeyLogs;
  const lct::CurveWeights w = lct::curveWeights(scheme, in.Times.data(), n, t);
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
    os << indent << "Time range: [" << this->GetMinimumT() << ", " << this->GetMaximumT()
       << "]\n";
  }
}
