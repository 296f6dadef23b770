#include "vtkProbeDeformerLCT.h"

#include "vtkLCTCheckedSet.h"

#include "lct/Affine.h"
#include "lct/Conditioning.h"
#include "lct/Format.h"
#include "lct/PolarParametrisation.h"
#include "lct/ProbeBlend.h"
#include "lct/Status.h"

#include "vtkArrayDispatch.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataArrayRange.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLCTLastOutput.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkProp3D.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <mutex>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkProbeDeformerLCT);

namespace
{
constexpr int kMaxProbes = 65536;
/// Probes that all shrink by more than 1/kMinimumShrink are refused (RequestData): the blend
/// would keep fewer than 8 digits of the result's own size.
constexpr double kMinimumShrink = 1e-8;
constexpr double kDefaultRadius = 8.0;

struct Probe
{
  vtkSmartPointer<vtkObject> Current;
  vtkSmartPointer<vtkObject> Rest;
  double Radius = kDefaultRadius;
  bool HasReference = false;
  Eigen::Vector3d Reference = Eigen::Vector3d::Zero();
};

bool isProbeObject(vtkObject* o)
{
  return vtkLinearTransform::SafeDownCast(o) || vtkMatrix4x4::SafeDownCast(o) ||
    vtkProp3D::SafeDownCast(o);
}

/// Empty when (current, rest) can be a probe, else what is wrong with it.
std::string probeTypeError(vtkObject* current, vtkObject* rest)
{
  const bool currentOk = current && isProbeObject(current);
  if (currentOk && (!rest || isProbeObject(rest)))
  {
    return {};
  }
  vtkObject* bad = currentOk ? rest : current;
  return std::string(currentOk ? "rest" : "current") + " is " +
    (bad ? bad->GetClassName() : "null") +
    "; a probe is a vtkLinearTransform, vtkMatrix4x4 or vtkProp3D";
}

Eigen::Matrix4d toEigen(const vtkMatrix4x4* m)
{
  Eigen::Matrix4d r;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      r(i, j) = m->GetElement(i, j);
    }
  }
  return r;
}

/// The matrix of a probe object (null: the identity).
Eigen::Matrix4d matrixOf(vtkObject* o)
{
  if (!o)
  {
    return Eigen::Matrix4d::Identity();
  }
  if (auto* t = vtkLinearTransform::SafeDownCast(o))
  {
    t->Update();
    return toEigen(t->GetMatrix());
  }
  if (auto* p = vtkProp3D::SafeDownCast(o))
  {
    return toEigen(p->GetMatrix());
  }
  return toEigen(vtkMatrix4x4::SafeDownCast(o));
}

/// Copies any real array into doubles (one pass, vtkArrayDispatch over the value types).
struct ToDoubles
{
  template <typename Array>
  void operator()(Array* array, std::vector<double>& out) const
  {
    const auto values = vtk::DataArrayValueRange(array);
    out.assign(values.begin(), values.end());
  }
};

/// Copies an index array into int32; false at the first value that is not an integer in range.
struct ToIndices
{
  template <typename Array>
  void operator()(Array* array, int probes, std::vector<std::int32_t>& out, vtkIdType& bad) const
  {
    const auto values = vtk::DataArrayValueRange(array);
    out.resize(values.size());
    vtkIdType k = 0;
    for (const auto v : values)
    {
      const double d = static_cast<double>(v);
      if (!(d >= 0.0 && d < static_cast<double>(probes)) || d != std::floor(d))
      {
        bad = k;
        return;
      }
      out[k++] = static_cast<std::int32_t>(d);
    }
  }
};

std::string formatVector(const Eigen::Vector3d& v)
{
  return "(" + lct::formatNumber(v[0]) + ", " + lct::formatNumber(v[1]) + ", " +
    lct::formatNumber(v[2]) + ")";
}
} // namespace

struct vtkProbeDeformerLCT::Internals
{
  std::vector<Probe> Probes;
  std::vector<std::string> NormalArrays;
  std::vector<std::string> VectorArrays;
  /// Rotation logs of the last successful execution (one per probe), for ConsistentRotation.
  std::vector<Eigen::Vector3d> History;
  /// The last valid output, handed back when an execution fails.
  vtkLCTLastOutput LastOutput;
};

vtkProbeDeformerLCT::vtkProbeDeformerLCT()
  : Internal(new Internals)
{
}

vtkProbeDeformerLCT::~vtkProbeDeformerLCT()
{
  this->SetWeightArrayName(nullptr);
  this->SetTransformIndexArrayName(nullptr);
}

int vtkProbeDeformerLCT::AddProbe(vtkObject* current, vtkObject* rest)
{
  const std::string typeError = probeTypeError(current, rest);
  if (!typeError.empty())
  {
    vtkErrorMacro(<< "AddProbe: " << typeError);
    return -1;
  }
  if (static_cast<int>(this->Internal->Probes.size()) >= kMaxProbes)
  {
    vtkErrorMacro(<< "AddProbe: at most " << kMaxProbes << " probes");
    return -1;
  }
  Probe p;
  p.Current = current;
  p.Rest = rest;
  this->Internal->Probes.push_back(p);
  // The other probes keep their rotation logs (clearing them snapped a 3 pi twist back to pi);
  // the new one has none yet, so its first log is the principal one.
  std::vector<Eigen::Vector3d>& history = this->Internal->History;
  if (history.size() + 1 == this->Internal->Probes.size())
  {
    history.push_back(Eigen::Vector3d::Zero());
  }
  this->Modified();
  return static_cast<int>(this->Internal->Probes.size()) - 1;
}

int vtkProbeDeformerLCT::SetProbe(int i, vtkObject* current, vtkObject* rest)
{
  if (i < 0 || i >= this->GetNumberOfProbes())
  {
    vtkErrorMacro(<< "SetProbe: probe " << i << " is outside [0, " << this->GetNumberOfProbes()
                  << ")");
    return 0;
  }
  const std::string typeError = probeTypeError(current, rest);
  if (!typeError.empty())
  {
    vtkErrorMacro(<< "SetProbe: " << typeError);
    return 0;
  }
  this->Internal->Probes[i].Current = current;
  this->Internal->Probes[i].Rest = rest;
  this->Modified();
  return 1;
}

void vtkProbeDeformerLCT::RemoveAllProbes()
{
  this->Internal->Probes.clear();
  this->Internal->History.clear();
  this->Modified();
}

int vtkProbeDeformerLCT::GetNumberOfProbes()
{
  return static_cast<int>(this->Internal->Probes.size());
}

int vtkProbeDeformerLCT::SetProbeRadius(int i, double radius)
{
  if (i < 0 || i >= this->GetNumberOfProbes())
  {
    vtkErrorMacro(<< "SetProbeRadius: probe " << i << " is outside [0, "
                  << this->GetNumberOfProbes() << ")");
    return 0;
  }
  if (!(radius > 0.0) || !std::isfinite(radius))
  {
    vtkErrorMacro(<< "SetProbeRadius: the radius of probe " << i
                  << " must be finite and positive, not " << lct::formatNumber(radius));
    return 0;
  }
  if (this->Internal->Probes[i].Radius != radius)
  {
    this->Internal->Probes[i].Radius = radius;
    this->Modified();
  }
  return 1;
}

double vtkProbeDeformerLCT::GetProbeRadius(int i)
{
  return (i >= 0 && i < this->GetNumberOfProbes()) ? this->Internal->Probes[i].Radius : 0.0;
}

int vtkProbeDeformerLCT::SetProbeRotationReference(int i, const double reference[3])
{
  if (i < 0 || i >= this->GetNumberOfProbes())
  {
    vtkErrorMacro(<< "SetProbeRotationReference: probe " << i << " is outside [0, "
                  << this->GetNumberOfProbes() << ")");
    return 0;
  }
  const Eigen::Vector3d r(reference[0], reference[1], reference[2]);
  if (!r.allFinite() || r.norm() > lct::kMaxRotationWinding)
  {
    vtkErrorMacro(<< "SetProbeRotationReference: the reference of probe " << i
                  << " must be finite and at most " << lct::kMaxRotationWinding << " rad long, not "
                  << formatVector(r));
    return 0;
  }
  this->Internal->Probes[i].HasReference = true;
  this->Internal->Probes[i].Reference = r;
  this->Modified();
  return 1;
}

int vtkProbeDeformerLCT::ClearProbeRotationReference(int i)
{
  if (i < 0 || i >= this->GetNumberOfProbes())
  {
    vtkErrorMacro(<< "ClearProbeRotationReference: probe " << i << " is outside [0, "
                  << this->GetNumberOfProbes() << ")");
    return 0;
  }
  this->Internal->Probes[i].HasReference = false;
  this->Modified();
  return 1;
}

void vtkProbeDeformerLCT::ResetRotationHistory()
{
  this->Internal->History.clear();
  this->Modified();
}

int vtkProbeDeformerLCT::GetProbeRotationLog(int i, double log[3])
{
  if (i < 0 || i >= static_cast<int>(this->Internal->History.size()))
  {
    return 0;
  }
  for (int k = 0; k < 3; ++k)
  {
    log[k] = this->Internal->History[i][k];
  }
  return 1;
}

void vtkProbeDeformerLCT::AddNormalArrayName(const char* name)
{
  if (name)
  {
    this->Internal->NormalArrays.emplace_back(name);
    this->Modified();
  }
}

void vtkProbeDeformerLCT::AddVectorArrayName(const char* name)
{
  if (name)
  {
    this->Internal->VectorArrays.emplace_back(name);
    this->Modified();
  }
}

void vtkProbeDeformerLCT::RemoveAllArrayNames()
{
  this->Internal->NormalArrays.clear();
  this->Internal->VectorArrays.clear();
  this->Modified();
}

const char* vtkProbeDeformerLCT::GetBlendModeAsString()
{
  switch (this->BlendMode)
  {
    case MATRIX_LOG:
      return "MatrixLog";
    case LINEAR:
      return "Linear";
    case DUAL_QUATERNION:
      return "DualQuaternion";
    default:
      return "Polar";
  }
}

vtkMTimeType vtkProbeDeformerLCT::GetMTime()
{
  vtkMTimeType m = this->Superclass::GetMTime();
  for (const Probe& p : this->Internal->Probes)
  {
    for (vtkObject* o : { p.Current.Get(), p.Rest.Get() })
    {
      if (o)
      {
        m = std::max(m, o->GetMTime());
      }
    }
  }
  return this->Internal->LastOutput.WithFailure(m);
}

int vtkProbeDeformerLCT::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPointSet* input = vtkPointSet::GetData(inputVector[0]);
  vtkPointSet* output = vtkPointSet::GetData(outputVector);
  Internals& in = *this->Internal;
  // On any failure: the message, and the last valid output back in place.
  const auto fail = [&]() { return in.LastOutput.Restore(output); };
  if (!input || !output)
  {
    vtkErrorMacro(<< "no input point set");
    return fail();
  }
  const int n = static_cast<int>(in.Probes.size());
  if (n == 0)
  {
    vtkErrorMacro(<< "no probes: add at least one with AddProbe(current, rest)");
    return fail();
  }
  if (this->WeightMode != POINT_DATA && (!(this->Exponent > 0.0) || !std::isfinite(this->Exponent)))
  {
    vtkErrorMacro(<< "the exponent of the distance weights must be finite and positive, not "
                  << lct::formatNumber(this->Exponent));
    return fail();
  }

  // The probes: A_i = current_i rest_i^-1, centred at rest_i's origin.
  std::vector<Eigen::Matrix4d> relative(n);
  std::vector<Eigen::Vector3d> centres(n);
  std::vector<Eigen::Vector3d> references;
  std::vector<double> radii(n);
  const bool useHistory = this->ConsistentRotation && static_cast<int>(in.History.size()) == n;
  bool anyReference = useHistory;
  for (const Probe& p : in.Probes)
  {
    anyReference = anyReference || p.HasReference;
  }
  if (anyReference && this->BlendMode == POLAR)
  {
    references.resize(n);
  }
  for (int i = 0; i < n; ++i)
  {
    const Probe& p = in.Probes[i];
    const Eigen::Matrix4d current = matrixOf(p.Current);
    const Eigen::Matrix4d rest = matrixOf(p.Rest);
    for (const auto& [m, which] :
      { std::make_pair(&current, "current"), std::make_pair(&rest, "rest") })
    {
      const lct::Status s = lct::validateAffine(*m);
      if (s != lct::Status::Ok)
      {
        vtkErrorMacro(<< "probe " << i << ": the " << which
                      << " matrix is invalid: " << lct::describe(s));
        return fail();
      }
    }
    // The rest matrix is inverted: within the module's condition limit, as every other one.
    const double condition = lct::linearConditionNumber(rest);
    if (!(condition <= lct::kMaxConditionNumber))
    {
      vtkErrorMacro(<< "probe " << i
                    << ": the rest matrix is singular or too ill-conditioned to invert (condition "
                       "number "
                    << lct::formatNumber(condition) << ", the limit "
                    << lct::formatNumber(lct::kMaxConditionNumber) << ")");
      return fail();
    }
    // A probe at rest (current == rest, e.g. one matrix for both) is exactly the identity:
    // current * rest^-1 rounds to within an ulp of it, which moved points by ~1e-15. Otherwise
    // its linear part L_c L_r^-1 comes from exact minors where L_r is ill-conditioned (the plain
    // product with the inverse cancels: 8 % off at condition 1e15, 2e-4 at 1e13), and its
    // translation is t_c - A t_r.
    relative[i] = Eigen::Matrix4d::Identity();
    if (current != rest)
    {
      relative[i] = lct::worldStep(rest, current);
      relative[i].topRightCorner<3, 1>() = current.topRightCorner<3, 1>() -
        relative[i].topLeftCorner<3, 3>() * rest.topRightCorner<3, 1>();
      // Both matrices are valid, yet their step can leave the double range (current 1e300 I,
      // rest 1e-300 I) or compound their conditions beyond the limit: said so here, not as
      // "NaN or Inf" or a "reflection" (a determinant rounded to the wrong sign) further on.
      if (!relative[i].allFinite())
      {
        vtkErrorMacro(<< "probe " << i
                      << ": its transform current rest^-1 overflows the double range (the "
                         "current matrix is beyond the rest one by more than ~1e308)");
        return fail();
      }
      const double stepCondition = lct::linearConditionNumber(relative[i]);
      if (!(stepCondition <= lct::kMaxConditionNumber))
      {
        vtkErrorMacro(<< "probe " << i
                      << ": its transform current rest^-1 is too ill-conditioned to blend "
                         "(condition number "
                      << lct::formatNumber(stepCondition) << ", the limit "
                      << lct::formatNumber(lct::kMaxConditionNumber)
                      << "; the conditions of the current and rest matrices compound)");
        return fail();
      }
    }
    centres[i] = rest.topRightCorner<3, 1>();
    radii[i] = p.Radius;
    if (!references.empty())
    {
      // An explicit reference wins; else the previous execution's log; else the principal log
      // (a zero reference picks it).
      references[i] =
        p.HasReference ? p.Reference : (useHistory ? in.History[i] : Eigen::Vector3d::Zero());
    }
  }
  // Points move as p + (A - I)(p - c) + t, accurate near the identity with round-off on the
  // scale of the input: where every probe shrinks by 1e8 or more, so does every point's blend,
  // and the result keeps fewer than 8 digits of its own size (one probe scaling by 1e-15 put
  // points 4 % off, by 1e-20 at 0). ||L||_F bounds the largest stretch from above.
  if (std::all_of(relative.begin(), relative.end(),
        [](const Eigen::Matrix4d& a) { return a.topLeftCorner<3, 3>().norm() < kMinimumShrink; }))
  {
    // ||L||_F scaled by the largest entry: norm()'s sum of squares underflows to 0 below ~1e-154
    // (a scale of 1e-200 was reported as "at most 0"; the test above only compares it with 1e-8).
    // Not Eigen's stableNorm(), which asserts on fixed-size matrices in Eigen 3.4.0.
    const Eigen::Matrix3d linear = relative[0].topLeftCorner<3, 3>();
    const double largest = linear.cwiseAbs().maxCoeff();
    vtkErrorMacro(<< "every probe shrinks by more than " << lct::formatNumber(1.0 / kMinimumShrink)
                  << " (probe 0: largest stretch at most "
                  << lct::formatNumber(largest > 0.0 ? largest * (linear / largest).norm() : 0.0)
                  << "): the deformed points would keep fewer than 8 digits of their own size "
                     "(they move as p + (A - I) p, with round-off on the input's scale); "
                     "deform with probes nearer the identity, then scale the result.");
    return fail();
  }
  const lct::BlendMode mode = this->BlendMode == MATRIX_LOG ? lct::BlendMode::MatrixLog
    : this->BlendMode == LINEAR                             ? lct::BlendMode::Linear
    : this->BlendMode == DUAL_QUATERNION                    ? lct::BlendMode::DualQuaternion
                                                            : lct::BlendMode::Polar;
  const lct::ProbePreparation prepared = lct::prepareProbes(relative, centres, references, mode);
  if (!prepared.ok())
  {
    vtkErrorMacro(<< "probe " << prepared.failedProbe
                  << ": its transform current rest^-1 cannot be blended in "
                  << this->GetBlendModeAsString() << " mode: " << lct::describe(prepared.status));
    return fail();
  }

  // The weights.
  const vtkIdType points = input->GetNumberOfPoints();
  lct::WeightSource source;
  source.normalization = this->Normalization == NORMALIZE_SOFTMAX
    ? lct::WeightNormalization::Softmax
    : this->Normalization == NORMALIZE_NONE ? lct::WeightNormalization::None
                                            : lct::WeightNormalization::Linear;
  source.radii = radii.data();
  source.exponent = this->Exponent;
  std::vector<double> weights;
  std::vector<std::int32_t> indices;
  vtkDataArray* weightArray = nullptr;
  if (this->WeightMode == POINT_DATA)
  {
    source.kind = lct::WeightSource::Kind::Slots;
    vtkDataArray* w =
      this->WeightArrayName ? input->GetPointData()->GetArray(this->WeightArrayName) : nullptr;
    if (!w)
    {
      vtkErrorMacro(<< "POINT_DATA weights: "
                    << (this->WeightArrayName
                           ? "the input has no point-data array named '" +
                             std::string(this->WeightArrayName) + "'"
                           : std::string("no weight array name set (SetWeightArrayName)")));
      return fail();
    }
    if (w->GetNumberOfTuples() != points)
    {
      vtkErrorMacro(<< "weight array '" << this->WeightArrayName << "' has "
                    << w->GetNumberOfTuples() << " tuples for " << points << " points");
      return fail();
    }
    source.slots = w->GetNumberOfComponents();
    // float and double weights are read in place; other types converted once.
    if (w->GetDataType() == VTK_FLOAT)
    {
      source.floatWeights = static_cast<const float*>(w->GetVoidPointer(0));
    }
    else if (w->GetDataType() == VTK_DOUBLE)
    {
      source.weights = static_cast<const double*>(w->GetVoidPointer(0));
    }
    else
    {
      if (!vtkArrayDispatch::Dispatch::Execute(w, ToDoubles{}, weights))
      {
        ToDoubles{}(w, weights);
      }
      source.weights = weights.data();
    }
    if (this->TransformIndexArrayName)
    {
      vtkDataArray* idx = input->GetPointData()->GetArray(this->TransformIndexArrayName);
      if (!idx)
      {
        vtkErrorMacro(<< "the input has no point-data array named '"
                      << this->TransformIndexArrayName << "' (the transform-index array)");
        return fail();
      }
      if (idx->GetNumberOfTuples() != points || idx->GetNumberOfComponents() != source.slots)
      {
        vtkErrorMacro(<< "transform-index array '" << this->TransformIndexArrayName << "' is "
                      << idx->GetNumberOfTuples() << " x " << idx->GetNumberOfComponents()
                      << " where the weight array '" << this->WeightArrayName << "' is " << points
                      << " x " << source.slots << ": they must match");
        return fail();
      }
      vtkIdType bad = -1;
      if (!vtkArrayDispatch::Dispatch::Execute(idx, ToIndices{}, n, indices, bad))
      {
        ToIndices{}(idx, n, indices, bad);
      }
      if (bad >= 0)
      {
        vtkErrorMacro(<< "transform-index array '" << this->TransformIndexArrayName << "': point "
                      << bad / source.slots << " slot " << bad % source.slots << " holds "
                      << lct::formatNumber(
                           idx->GetComponent(bad / source.slots, bad % source.slots))
                      << ", not a probe index (an integer in [0, " << n << "))");
        return fail();
      }
      source.indices = indices.data();
    }
    else if (source.slots > n)
    {
      vtkErrorMacro(<< "weight array '" << this->WeightArrayName << "' has " << source.slots
                    << " components for " << n
                    << " probes; without a transform-index array component j is probe j");
      return fail();
    }
    weightArray = w;
  }
  else
  {
    source.kind = this->WeightMode == CUTOFF ? lct::WeightSource::Kind::Cutoff
                                             : lct::WeightSource::Kind::InverseDistance;
  }

  // The output: the input's structure and data, new points, new carried arrays.
  vtkPoints* inPoints = input->GetPoints();
  vtkNew<vtkPoints> outPoints;
  std::vector<lct::CarriedVectors> carried;
  std::vector<vtkSmartPointer<vtkDataArray>> carriedOut;
  std::vector<vtkDataArray*> carriedIn; // the input arrays of `carried`, for messages
  output->CopyStructure(input);
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->PassData(input->GetCellData());
  if (inPoints)
  {
    // Float points stay float; any other type (double, and integer points, which a deformation
    // moves off the integers) is blended and stored as double.
    const int type = inPoints->GetDataType() == VTK_FLOAT ? VTK_FLOAT : VTK_DOUBLE;
    outPoints->SetDataType(type);
    outPoints->SetNumberOfPoints(points);
    vtkPointData* pd = input->GetPointData();
    const auto addCarried = [&](vtkDataArray* a, bool isNormal) -> bool {
      if (!a)
      {
        return true;
      }
      if (a->GetNumberOfComponents() != 3 || a->GetNumberOfTuples() != points ||
        (a->GetDataType() != VTK_FLOAT && a->GetDataType() != VTK_DOUBLE))
      {
        vtkErrorMacro(<< (isNormal ? "normal" : "vector") << " array '"
                      << (a->GetName() ? a->GetName() : "")
                      << "' must be a float or double array of " << points
                      << " 3-component tuples");
        return false;
      }
      for (const auto& c : carriedOut)
      {
        if (c->GetName() && a->GetName() && std::string(c->GetName()) == a->GetName())
        {
          return true;
        }
      }
      vtkSmartPointer<vtkDataArray> out;
      out.TakeReference(a->NewInstance());
      out->SetName(a->GetName());
      out->SetNumberOfComponents(3);
      out->SetNumberOfTuples(points);
      lct::CarriedVectors c;
      c.in = a->GetVoidPointer(0);
      c.out = out->GetVoidPointer(0);
      c.isDouble = a->GetDataType() == VTK_DOUBLE;
      c.isNormal = isNormal;
      carried.push_back(c);
      carriedOut.push_back(out);
      carriedIn.push_back(a);
      // The attributes replace the input's copy in place (AddArray first appended an unnamed
      // one beside it: the output listed the normals twice).
      if (a == pd->GetNormals())
      {
        output->GetPointData()->SetNormals(out);
      }
      else if (a == pd->GetVectors())
      {
        output->GetPointData()->SetVectors(out);
      }
      else
      {
        output->GetPointData()->AddArray(out);
      }
      return true;
    };
    bool ok = addCarried(pd->GetNormals(), true) && addCarried(pd->GetVectors(), false);
    for (const std::string& name : in.NormalArrays)
    {
      vtkDataArray* a = pd->GetArray(name.c_str());
      if (!a)
      {
        vtkErrorMacro(<< "no point-data array named '" << name << "' (AddNormalArrayName)");
        ok = false;
      }
      ok = ok && addCarried(a, true);
    }
    for (const std::string& name : in.VectorArrays)
    {
      vtkDataArray* a = pd->GetArray(name.c_str());
      if (!a)
      {
        vtkErrorMacro(<< "no point-data array named '" << name << "' (AddVectorArrayName)");
        ok = false;
      }
      ok = ok && addCarried(a, false);
    }
    if (!ok)
    {
      return fail();
    }
    // Points of another type than float or double are converted to double (type is VTK_DOUBLE
    // for them): the buffer read below must be of `type`.
    vtkSmartPointer<vtkDataArray> pointData = inPoints->GetData();
    if (pointData->GetDataType() != type)
    {
      vtkNew<vtkDoubleArray> converted;
      converted->DeepCopy(pointData);
      pointData = converted;
    }
    std::mutex failureLock;
    lct::DeformFailure failure;
    auto run = [&](vtkIdType begin, vtkIdType end) {
      const lct::DeformFailure f = type == VTK_DOUBLE
        ? lct::deformPoints(prepared.set, source,
            static_cast<const double*>(pointData->GetVoidPointer(0)),
            static_cast<double*>(outPoints->GetData()->GetVoidPointer(0)), carried.data(),
            static_cast<int>(carried.size()), begin, end)
        : lct::deformPoints(prepared.set, source,
            static_cast<const float*>(pointData->GetVoidPointer(0)),
            static_cast<float*>(outPoints->GetData()->GetVoidPointer(0)), carried.data(),
            static_cast<int>(carried.size()), begin, end);
      if (!f.ok())
      {
        const std::lock_guard<std::mutex> guard(failureLock);
        if (failure.ok() || f.point < failure.point)
        {
          failure = f;
        }
      }
    };
    if (points < this->SerialThreshold)
    {
      run(0, points);
    }
    else
    {
      vtkSMPTools::For(0, points, run);
    }
    if (!failure.ok())
    {
      double p[3];
      inPoints->GetPoint(failure.point, p);
      const Eigen::Vector3d point(p[0], p[1], p[2]);
      if (!point.allFinite())
      {
        // A NaN or Inf input point fails whichever check it meets first (weights from its
        // distances, the blend, the result): name it, not that check.
        vtkErrorMacro(<< "point " << failure.point << " is " << formatVector(point)
                      << ": an input point must be finite.");
      }
      else if (weightArray &&
        (failure.status == lct::Status::NonFinite ||
          failure.status == lct::Status::InvalidArgument))
      {
        std::string values;
        for (int k = 0; k < source.slots; ++k)
        {
          values +=
            (k ? ", " : "") + lct::formatNumber(weightArray->GetComponent(failure.point, k));
          if (source.indices)
          {
            values += " (probe " + std::to_string(indices[failure.point * source.slots + k]) + ")";
          }
        }
        vtkErrorMacro(<< "point " << failure.point << " has weights " << values << ": "
                      << (failure.status == lct::Status::NonFinite
                             ? "NaN or Inf"
                             : "a sum the normalisation cannot divide by (LINEAR needs a "
                               "positive sum where any weight is not 0)"));
      }
      else if (vtkDataArray* bad = [&]() -> vtkDataArray* {
                 for (vtkDataArray* a : carriedIn)
                 {
                   Eigen::Vector3d v;
                   a->GetTuple(failure.point, v.data());
                   if (!v.allFinite())
                   {
                     return a;
                   }
                 }
                 return nullptr;
               }())
      {
        // A NaN in a carried normal or vector was reported as an overflow of the result.
        Eigen::Vector3d v;
        bad->GetTuple(failure.point, v.data());
        vtkErrorMacro(<< "point " << failure.point << "'s vector in the array '"
                      << (bad->GetName() ? bad->GetName() : "") << "' is " << formatVector(v)
                      << ": a carried normal or vector must be finite.");
      }
      else
      {
        // NumericalFailure here is the blend's own refusal, not the eigensolver defect that
        // lct::describe names for it.
        vtkErrorMacro(<< "point " << failure.point << " at " << formatVector(point)
                      << " cannot be deformed in " << this->GetBlendModeAsString() << " mode: "
                      << (failure.status == lct::Status::NumericalFailure
                             ? "its weighted rotations cancel, or with stretched probes its "
                               "weights sum to 0 (NormalizationToLinear keeps them from that)"
                             : lct::describe(failure.status))
                      << (failure.status == lct::Status::InaccurateResult
                             ? " (its weights wind the blended turn beyond 1e9 radians: "
                               "NormalizationToLinear keeps them from that)"
                             : failure.status == lct::Status::OutOfRange && !carried.empty()
                             ? " (its position, or a vector array carried with it)"
                             : ""));
      }
      return fail();
    }
    output->SetPoints(outPoints);
  }

  // Success: remember the (Polar) rotation logs and this output. Another blend mode has no
  // Polar logs to remember and leaves the history as it was (it cleared it, so one look at
  // Linear snapped a 3 pi twist back to pi when Polar came back).
  if (this->BlendMode == POLAR)
  {
    in.History.resize(n);
    for (int i = 0; i < n; ++i)
    {
      in.History[i] = lct::rotationPart(prepared.set.probes[i].logs);
    }
  }
  in.LastOutput.Remember(output);
  return 1;
}

void vtkProbeDeformerLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BlendMode: " << this->GetBlendModeAsString() << "\n";
  os << indent << "WeightMode: "
     << (this->WeightMode == CUTOFF          ? "Cutoff"
            : this->WeightMode == POINT_DATA ? "PointData"
                                             : "InverseDistance")
     << "\n";
  os << indent << "Normalization: "
     << (this->Normalization == NORMALIZE_SOFTMAX   ? "Softmax"
            : this->Normalization == NORMALIZE_NONE ? "None"
                                                    : "Linear")
     << "\n";
  os << indent << "Exponent: " << this->Exponent << "\n";
  os << indent << "WeightArrayName: " << (this->WeightArrayName ? this->WeightArrayName : "(none)")
     << "\n";
  os << indent << "TransformIndexArrayName: "
     << (this->TransformIndexArrayName ? this->TransformIndexArrayName : "(none)") << "\n";
  os << indent << "ConsistentRotation: " << this->ConsistentRotation << "\n";
  os << indent << "SerialThreshold: " << this->SerialThreshold << "\n";
  os << indent << "NumberOfProbes: " << this->Internal->Probes.size() << "\n";
  for (std::size_t i = 0; i < this->Internal->Probes.size(); ++i)
  {
    const Probe& p = this->Internal->Probes[i];
    os << indent.GetNextIndent() << "Probe " << i << ": current " << p.Current->GetClassName()
       << ", rest " << (p.Rest ? p.Rest->GetClassName() : "identity") << ", radius " << p.Radius;
    if (p.HasReference)
    {
      os << ", rotation reference " << formatVector(p.Reference);
    }
    os << "\n";
  }
  for (const std::string& name : this->Internal->NormalArrays)
  {
    os << indent << "NormalArrayName: " << name << "\n";
  }
  for (const std::string& name : this->Internal->VectorArrays)
  {
    os << indent << "VectorArrayName: " << name << "\n";
  }
}

//------------------------------------------------------------------------------
int vtkProbeDeformerLCT::SetBlendMode(int value)
{
  return vtkLCTCheckedSet::Set(this, "BlendMode", this->BlendMode, value, static_cast<int>(POLAR),
    static_cast<int>(DUAL_QUATERNION));
}

//------------------------------------------------------------------------------
int vtkProbeDeformerLCT::SetWeightMode(int value)
{
  return vtkLCTCheckedSet::Set(this, "WeightMode", this->WeightMode, value,
    static_cast<int>(INVERSE_DISTANCE), static_cast<int>(POINT_DATA));
}

//------------------------------------------------------------------------------
int vtkProbeDeformerLCT::SetNormalization(int value)
{
  return vtkLCTCheckedSet::Set(this, "Normalization", this->Normalization, value,
    static_cast<int>(NORMALIZE_LINEAR), static_cast<int>(NORMALIZE_NONE));
}

//------------------------------------------------------------------------------
int vtkProbeDeformerLCT::SetSerialThreshold(vtkIdType value)
{
  return vtkLCTCheckedSet::Set(this, "SerialThreshold", this->SerialThreshold, value,
    static_cast<vtkIdType>(0), static_cast<vtkIdType>(VTK_ID_MAX));
}
