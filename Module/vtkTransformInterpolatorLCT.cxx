#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/Curves.h"
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

/// Keys farther apart than this never share a curve point (the widest scheme, subdivision,
/// touches 6 neighbouring keys plus the folded end keys), so only these relative logs are kept.
constexpr int kReach = 7;

struct Key
{
  double Time;
  Eigen::Matrix4d Matrix;
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
  /// Relative[r * (2 kReach + 1) + (i - r + kReach)] = log(K_i K_r^-1), |i - r| <= kReach,
  /// where it exists (RelativeValid); neighbouring keys always have one.
  std::vector<lct::LogCoords> Relative;
  std::vector<char> RelativeValid;
  /// Absolute logs, each on the rotation branch nearest to the previous key's.
  std::vector<lct::LogCoords> Absolute;

  /// Computes every log for `keys` in parametrisation p; on failure reports the key index.
  lct::Status Build(const std::vector<Key>& keys, lct::Parametrisation p, int& failedKey)
  {
    const int n = static_cast<int>(keys.size());
    std::vector<lct::LogCoords> relative(static_cast<size_t>(n) * (2 * kReach + 1));
    std::vector<char> valid(relative.size(), 0);
    std::vector<lct::LogCoords> absolute(n);
    for (int r = 0; r < n; ++r)
    {
      const auto a = lct::logarithm(keys[r].Matrix, p, r > 0 ? &absolute[r - 1] : nullptr);
      if (!a)
      {
        failedKey = r;
        return a.status;
      }
      absolute[r] = a.value;
      const Eigen::Matrix4d inverse = lct::inverseAffine(keys[r].Matrix);
      for (int i = std::max(0, r - kReach); i <= std::min(n - 1, r + kReach); ++i)
      {
        const auto l = lct::logarithm(keys[i].Matrix * inverse, p);
        if (!l)
        {
          // MatrixLog only: a step without real log. Fatal between neighbours (no curve can
          // join them); farther apart it only matters if a curve point combines the two.
          if (std::abs(i - r) <= 1)
          {
            failedKey = std::max(i, r);
            return l.status;
          }
          continue;
        }
        relative[r * (2 * kReach + 1) + (i - r + kReach)] = l.value;
        valid[r * (2 * kReach + 1) + (i - r + kReach)] = 1;
      }
    }
    this->Keys = keys;
    this->Relative.swap(relative);
    this->RelativeValid.swap(valid);
    this->Absolute.swap(absolute);
    this->Times.resize(n);
    for (int i = 0; i < n; ++i)
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
  int unused;
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
  int failedKey = -1;
  const lct::Status built = this->Internal->Build(keys, toCore(this->Parametrisation), failedKey);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< caller << " at t = " << t << ": the step to the key at t = "
                  << keys[failedKey].Time << " has no " << lct::name(toCore(this->Parametrisation))
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
  int unused;
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
  int failedKey = -1;
  const std::vector<Key> keys = this->Internal->Keys;
  const lct::Status built = this->Internal->Build(keys, toCore(parametrisation), failedKey);
  if (built != lct::Status::Ok)
  {
    vtkErrorMacro(<< "SetParametrisation: the key at t = " << keys[failedKey].Time << " has no "
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
  const lct::CurveWeights w =
    lct::curveWeights(toScheme(this->InterpolationType), in.Times.data(), n, t);
  const lct::Parametrisation p = toCore(this->Parametrisation);
  lct::LogCoords sum = lct::LogCoords::Zero();
  Eigen::Matrix4d result;
  if (this->ConsistentRotation)
  {
    for (int j = 0; j < w.count; ++j)
    {
      sum += w.weight[j] * in.Absolute[w.key[j]];
    }
    const auto m = lct::exponential(sum, p);
    if (!m)
    {
      vtkErrorMacro(<< "InterpolateTransform(" << t << "): " << lct::describe(m.status));
      return false;
    }
    result = m.value;
  }
  else
  {
    int r = w.key[0];
    double largest = w.weight[0];
    for (int j = 1; j < w.count; ++j)
    {
      if (w.weight[j] > largest)
      {
        largest = w.weight[j];
        r = w.key[j];
      }
    }
    for (int j = 0; j < w.count; ++j)
    {
      const size_t slot = r * (2 * kReach + 1) + (w.key[j] - r + kReach);
      if (!in.RelativeValid[slot])
      {
        vtkErrorMacro(<< "InterpolateTransform(" << t << "): the keys at t = " << in.Times[r]
                      << " and t = " << in.Times[w.key[j]] << " have no real "
                      << "MatrixLog logarithm between them; use the Polar parametrisation. "
                         "Output unchanged.");
        return false;
      }
      sum += w.weight[j] * in.Relative[slot];
    }
    const auto m = lct::exponential(sum, p);
    if (!m)
    {
      vtkErrorMacro(<< "InterpolateTransform(" << t << "): " << lct::describe(m.status));
      return false;
    }
    result = m.value * in.Keys[r].Matrix;
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
  static const char* const types[] = { "Linear", "Spline", "BSpline", "Subdivision" };
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
