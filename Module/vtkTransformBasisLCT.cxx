#include "vtkTransformBasisLCT.h"

#include "vtkLCTCheckedSet.h"

#include "lct/Format.h"
#include "lct/LogBasis.h"
#include "lct/Parametrisation.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <vector>

vtkStandardNewMacro(vtkTransformBasisLCT);

namespace
{
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

lct::Parametrisation toCore(int parametrisation)
{
  return parametrisation == vtkTransformBasisLCT::MATRIX_LOG ? lct::Parametrisation::MatrixLog
                                                             : lct::Parametrisation::Polar;
}

Eigen::Matrix4d toEigen(vtkMatrix4x4* m)
{
  return RowMajor4(Eigen::Map<const RowMajor4>(m->GetData()));
}

void toVtk(const Eigen::Matrix4d& m, vtkMatrix4x4* result)
{
  const RowMajor4 rows = m;
  result->DeepCopy(rows.data());
}
} // namespace

/// What the basis is made from; a candidate becomes the state only when it analyses cleanly.
struct vtkTransformBasisLCT::Candidate
{
  std::vector<Eigen::Matrix4d> Sources; // the basis transforms, or the examples
  bool FromExamples = false;
  bool Centred = false;
  int Parametrisation = POLAR;
  double RankTolerance = 1e-8;
  int MaximumRank = 0;
};

struct vtkTransformBasisLCT::Internals
{
  Candidate Made;
  bool HasBasis = false;
  lct::LogBasis Basis;
  lct::BasisCoefficients SingularValues;
};

//------------------------------------------------------------------------------
vtkTransformBasisLCT::vtkTransformBasisLCT()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkTransformBasisLCT::~vtkTransformBasisLCT()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
// The only place the basis changes: the logs of every source and their analysis, all or nothing.
bool vtkTransformBasisLCT::Commit(const Candidate& candidate, const char* caller)
{
  const lct::Parametrisation p = toCore(candidate.Parametrisation);
  std::vector<lct::LogCoords> logs;
  logs.reserve(candidate.Sources.size());
  for (std::size_t i = 0; i < candidate.Sources.size(); ++i)
  {
    const auto c = lct::logarithm(candidate.Sources[i], p);
    if (!c)
    {
      vtkErrorMacro(<< caller << ": " << (candidate.FromExamples ? "example " : "basis transform ")
                    << i << " has no " << lct::name(p) << " log: " << lct::describe(c.status)
                    << lct::adviceFor(c.status, p) << "; unchanged.");
      return false;
    }
    logs.push_back(c.value);
  }
  Internals next;
  next.Made = candidate;
  if (candidate.FromExamples)
  {
    const auto found = lct::basisFromExamples(
      logs.data(), logs.size(), candidate.Centred, candidate.RankTolerance, candidate.MaximumRank);
    if (!found)
    {
      vtkErrorMacro(<< caller << ": no basis from these " << logs.size() << " examples: "
                    << (found.status == lct::Status::RankDeficient
                           ? (candidate.Centred ? "they are all equal, so they span nothing"
                                                : "they are all the identity")
                           : lct::describe(found.status))
                    << "; unchanged.");
      return false;
    }
    next.Basis = found.value.basis;
    next.SingularValues = found.value.singularValues;
  }
  else if (!logs.empty())
  {
    const auto analysed =
      lct::analyseBasis(logs.data(), logs.size(), lct::LogCoords::Zero(), candidate.RankTolerance);
    if (!analysed)
    {
      vtkErrorMacro(<< caller << ": the basis cannot be analysed: "
                    << lct::describe(analysed.status) << "; unchanged.");
      return false;
    }
    next.Basis = analysed.value;
    next.SingularValues = analysed.value.singularValues;
    if (!next.Basis.fullRank())
    {
      vtkWarningMacro(<< caller << ": the basis is rank deficient (rank " << next.Basis.rank
                      << " of " << next.Basis.size() << " transforms at rank tolerance "
                      << lct::formatNumber(candidate.RankTolerance)
                      << "): Factor() will refuse it, Project() still works.");
    }
  }
  next.HasBasis = !logs.empty();
  *this->Internal = next;
  this->Parametrisation = candidate.Parametrisation;
  this->RankTolerance = candidate.RankTolerance;
  this->MaximumRank = candidate.MaximumRank;
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransformBasisLCT::Ready(const char* caller)
{
  if (!this->Internal->HasBasis)
  {
    vtkErrorMacro(<< caller << ": no basis (AddBasisTransform or SetBasisFromExamples first).");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkTransformBasisLCT::LogOfInput(vtkMatrix4x4* transform, const void* output,
  const char* outputName, const char* caller, double log[12])
{
  if (!transform || !output)
  {
    vtkErrorMacro(<< caller << ": null " << (transform ? outputName : "transform") << ".");
    return false;
  }
  if (!this->Ready(caller))
  {
    return false;
  }
  const lct::Parametrisation p = toCore(this->Parametrisation);
  const auto c = lct::logarithm(toEigen(transform), p);
  if (!c)
  {
    vtkErrorMacro(<< caller << ": the transform has no " << lct::name(p)
                  << " log: " << lct::describe(c.status) << lct::adviceFor(c.status, p) << ".");
    return false;
  }
  std::copy(c.value.data(), c.value.data() + 12, log);
  return true;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::SetParametrisation(int parametrisation)
{
  if (parametrisation != POLAR && parametrisation != MATRIX_LOG)
  {
    vtkErrorMacro(<< "SetParametrisation: unknown parametrisation " << parametrisation
                  << " (use POLAR or MATRIX_LOG); unchanged.");
    return 0;
  }
  if (parametrisation == this->Parametrisation)
  {
    return 1;
  }
  Candidate next = this->Internal->Made;
  next.Parametrisation = parametrisation;
  return this->Commit(next, "SetParametrisation") ? 1 : 0;
}

//------------------------------------------------------------------------------
const char* vtkTransformBasisLCT::GetParametrisationAsString()
{
  return lct::name(toCore(this->Parametrisation));
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::SetRankTolerance(double tolerance)
{
  if (!(tolerance >= 0.0 && tolerance < 1.0))
  {
    vtkErrorMacro(<< "SetRankTolerance: " << lct::formatNumber(tolerance)
                  << " is outside [0, 1); unchanged.");
    return 0;
  }
  if (tolerance == this->RankTolerance)
  {
    return 1;
  }
  Candidate next = this->Internal->Made;
  next.RankTolerance = tolerance;
  return this->Commit(next, "SetRankTolerance") ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::AddBasisTransform(vtkMatrix4x4* matrix)
{
  if (!matrix)
  {
    vtkErrorMacro(<< "AddBasisTransform: null matrix; unchanged.");
    return 0;
  }
  Candidate next = this->Internal->Made;
  if (next.FromExamples)
  {
    next.Sources.clear();
    next.FromExamples = false;
  }
  if (next.Sources.size() >= static_cast<std::size_t>(lct::kLogDimension))
  {
    vtkErrorMacro(<< "AddBasisTransform: the basis already has 12 transforms, the dimension of "
                     "the log space (any more would be dependent); unchanged.");
    return 0;
  }
  next.Sources.push_back(toEigen(matrix));
  return this->Commit(next, "AddBasisTransform") ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::AddBasisTransform(vtkLinearTransform* transform)
{
  if (!transform)
  {
    vtkErrorMacro(<< "AddBasisTransform: null transform; unchanged.");
    return 0;
  }
  return this->AddBasisTransform(transform->GetMatrix());
}

//------------------------------------------------------------------------------
void vtkTransformBasisLCT::RemoveAllBasisTransforms()
{
  if (!this->Internal->HasBasis && this->Internal->Made.Sources.empty())
  {
    return;
  }
  Candidate next = this->Internal->Made;
  next.Sources.clear();
  next.FromExamples = false;
  this->Commit(next, "RemoveAllBasisTransforms");
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::SetBasisFromExamples(vtkCollection* examples, int centred)
{
  if (!examples || examples->GetNumberOfItems() == 0)
  {
    vtkErrorMacro(<< "SetBasisFromExamples: " << (examples ? "no examples" : "null collection")
                  << "; unchanged.");
    return 0;
  }
  Candidate next = this->Internal->Made;
  next.Sources.clear();
  next.FromExamples = true;
  next.Centred = centred != 0;
  for (int i = 0; i < examples->GetNumberOfItems(); ++i)
  {
    vtkObject* item = examples->GetItemAsObject(i);
    vtkMatrix4x4* matrix = vtkMatrix4x4::SafeDownCast(item);
    if (auto* transform = vtkLinearTransform::SafeDownCast(item))
    {
      matrix = transform->GetMatrix();
    }
    if (!matrix)
    {
      vtkErrorMacro(<< "SetBasisFromExamples: item " << i << " is "
                    << (item ? item->GetClassName() : "null")
                    << ", not a vtkMatrix4x4 or vtkLinearTransform; unchanged.");
      return 0;
    }
    next.Sources.push_back(toEigen(matrix));
  }
  return this->Commit(next, "SetBasisFromExamples") ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::GetNumberOfBasisTransforms()
{
  return this->Internal->HasBasis ? this->Internal->Basis.size() : 0;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::GetRank()
{
  return this->Internal->HasBasis ? this->Internal->Basis.rank : 0;
}

//------------------------------------------------------------------------------
double vtkTransformBasisLCT::GetConditionNumber()
{
  return this->Internal->HasBasis ? this->Internal->Basis.conditionNumber : 0.0;
}

//------------------------------------------------------------------------------
void vtkTransformBasisLCT::GetSingularValues(vtkDoubleArray* values)
{
  if (!values)
  {
    vtkErrorMacro(<< "GetSingularValues: null array.");
    return;
  }
  const lct::BasisCoefficients& s = this->Internal->SingularValues;
  const vtkIdType n = this->Internal->HasBasis ? static_cast<vtkIdType>(s.size()) : 0;
  values->SetNumberOfComponents(1);
  values->SetNumberOfTuples(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    values->SetValue(i, s[static_cast<Eigen::Index>(i)]);
  }
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::GetBasisTransform(int i, vtkMatrix4x4* result)
{
  if (!result)
  {
    vtkErrorMacro(<< "GetBasisTransform: null result matrix.");
    return 0;
  }
  if (!this->Ready("GetBasisTransform"))
  {
    return 0;
  }
  const Internals& in = *this->Internal;
  if (i < 0 || i >= in.Basis.size())
  {
    vtkErrorMacro(<< "GetBasisTransform: index " << i << " is outside [0, " << in.Basis.size()
                  << ").");
    return 0;
  }
  if (!in.Made.FromExamples)
  {
    toVtk(in.Made.Sources[static_cast<std::size_t>(i)], result);
    return 1;
  }
  const auto m = lct::exponential(in.Basis.vectors.col(i), toCore(this->Parametrisation));
  if (!m)
  {
    vtkErrorMacro(<< "GetBasisTransform: direction " << i
                  << " has no representable transform: " << lct::describe(m.status) << ".");
    return 0;
  }
  toVtk(m.value, result);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::GetOrigin(vtkMatrix4x4* result)
{
  if (!result)
  {
    vtkErrorMacro(<< "GetOrigin: null result matrix.");
    return 0;
  }
  if (!this->Ready("GetOrigin"))
  {
    return 0;
  }
  const auto m = lct::exponential(this->Internal->Basis.origin, toCore(this->Parametrisation));
  if (!m)
  {
    vtkErrorMacro(<< "GetOrigin: the origin has no representable transform: "
                  << lct::describe(m.status) << ".");
    return 0;
  }
  toVtk(m.value, result);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::Factor(vtkMatrix4x4* transform, vtkDoubleArray* coefficients)
{
  lct::LogCoords c;
  if (!this->LogOfInput(transform, coefficients, "coefficient array", "Factor", c.data()))
  {
    return 0;
  }
  const lct::LogBasis& basis = this->Internal->Basis;
  const auto f = lct::factorOntoBasis(basis, c);
  if (!f)
  {
    if (f.status == lct::Status::RankDeficient)
    {
      vtkErrorMacro(<< "Factor: the basis is rank deficient (rank " << basis.rank << " of "
                    << basis.size() << " at rank tolerance "
                    << lct::formatNumber(basis.rankTolerance)
                    << "), so the coefficients are not unique; Project() gives the nearest "
                       "transform in its span.");
    }
    else
    {
      vtkErrorMacro(<< "Factor: " << lct::describe(f.status) << ".");
    }
    return 0;
  }
  const double size = f.value.coefficients.cwiseAbs().maxCoeff();
  if (!(f.value.errorBound <= this->CoefficientTolerance * (1.0 + size)))
  {
    vtkErrorMacro(<< "Factor: the coefficients cannot be computed accurately in double "
                     "precision: they are determined only to "
                  << lct::formatNumber(f.value.errorBound) << " (largest coefficient "
                  << lct::formatNumber(size) << ", coefficient tolerance "
                  << lct::formatNumber(this->CoefficientTolerance)
                  << " times 1 + that): the transform's log is known to about eps (1 + "
                  << lct::formatNumber(lct::logNorm(c))
                  << ") and the basis's smallest singular value is "
                  << lct::formatNumber(basis.singularValues[basis.size() - 1])
                  << " (Gram condition " << lct::formatNumber(basis.conditionNumber)
                  << "); basis transforms close to the identity, or nearly dependent ones, tell "
                     "transforms apart only as far as double precision holds them "
                     "(SetCoefficientTolerance accepts less); coefficients unchanged.");
    return 0;
  }
  coefficients->SetNumberOfComponents(1);
  coefficients->SetNumberOfTuples(basis.size());
  for (int i = 0; i < basis.size(); ++i)
  {
    coefficients->SetValue(i, f.value.coefficients[i]);
  }
  this->Residual = f.value.residual;
  this->CoefficientErrorBound = f.value.errorBound;
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::SetCoefficientTolerance(double tolerance)
{
  if (!(tolerance > 0.0))
  {
    vtkErrorMacro(<< "SetCoefficientTolerance: " << lct::formatNumber(tolerance)
                  << " is not positive; unchanged.");
    return 0;
  }
  if (tolerance != this->CoefficientTolerance)
  {
    this->CoefficientTolerance = tolerance;
    this->Modified();
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::Reconstruct(vtkDoubleArray* coefficients, vtkMatrix4x4* result)
{
  if (!coefficients || !result)
  {
    vtkErrorMacro(<< "Reconstruct: null " << (result ? "coefficient array" : "result matrix")
                  << ".");
    return 0;
  }
  if (!this->Ready("Reconstruct"))
  {
    return 0;
  }
  const lct::LogBasis& basis = this->Internal->Basis;
  if (coefficients->GetNumberOfComponents() != 1 ||
    coefficients->GetNumberOfTuples() != basis.size())
  {
    vtkErrorMacro(<< "Reconstruct: " << coefficients->GetNumberOfTuples() << " x "
                  << coefficients->GetNumberOfComponents() << " coefficients for a basis of "
                  << basis.size() << " transforms (want " << basis.size() << " x 1).");
    return 0;
  }
  lct::BasisCoefficients x(basis.size());
  for (int i = 0; i < basis.size(); ++i)
  {
    x[i] = coefficients->GetValue(i);
  }
  const auto c = lct::combineBasis(basis, x);
  const auto m = c ? lct::exponential(c.value, toCore(this->Parametrisation))
                   : lct::Result<Eigen::Matrix4d>::failure(c.status);
  if (!m)
  {
    vtkErrorMacro(<< "Reconstruct: "
                  << (m.status == lct::Status::NonFinite ? "the coefficients contain NaN or Inf"
                                                         : lct::describe(m.status))
                  << "; result unchanged.");
    return 0;
  }
  toVtk(m.value, result);
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::Project(vtkMatrix4x4* transform, vtkMatrix4x4* result)
{
  lct::LogCoords c;
  if (!this->LogOfInput(transform, result, "result matrix", "Project", c.data()))
  {
    return 0;
  }
  const auto f = lct::projectOntoBasis(this->Internal->Basis, c);
  const auto m = f ? lct::exponential(f.value.projection, toCore(this->Parametrisation))
                   : lct::Result<Eigen::Matrix4d>::failure(f.status);
  if (!m)
  {
    vtkErrorMacro(<< "Project: the projection is not representable: " << lct::describe(m.status)
                  << "; result unchanged.");
    return 0;
  }
  toVtk(m.value, result);
  this->Residual = f.value.residual;
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformBasisLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const Internals& in = *this->Internal;
  os << indent << "Parametrisation: " << this->GetParametrisationAsString() << "\n";
  os << indent << "RankTolerance: " << this->RankTolerance << "\n";
  os << indent << "MaximumRank: " << this->MaximumRank << "\n";
  os << indent << "Basis: "
     << (!in.HasBasis              ? "none"
            : in.Made.FromExamples ? (in.Made.Centred ? "from examples, centred" : "from examples")
                                   : "explicit")
     << "\n";
  os << indent << "NumberOfBasisTransforms: " << this->GetNumberOfBasisTransforms() << "\n";
  os << indent << "Rank: " << this->GetRank() << "\n";
  os << indent << "ConditionNumber: " << this->GetConditionNumber() << "\n";
  os << indent << "Residual: " << this->Residual << "\n";
  os << indent << "CoefficientTolerance: " << this->CoefficientTolerance << "\n";
  os << indent << "CoefficientErrorBound: " << this->CoefficientErrorBound << "\n";
}

//------------------------------------------------------------------------------
int vtkTransformBasisLCT::SetMaximumRank(int value)
{
  if (!vtkLCTCheckedSet::InRange(
        this, "MaximumRank", this->MaximumRank, value, static_cast<int>(0), static_cast<int>(12)))
  {
    return 0;
  }
  if (value == this->MaximumRank)
  {
    return 1;
  }
  // A basis from examples is analysed again, as for SetRankTolerance: the basis always reflects
  // the settings GetMaximumRank reports (it kept the rank in force when the examples were set).
  Candidate next = this->Internal->Made;
  next.MaximumRank = value;
  if (next.FromExamples)
  {
    return this->Commit(next, "SetMaximumRank") ? 1 : 0;
  }
  this->Internal->Made.MaximumRank = value;
  this->MaximumRank = value;
  this->Modified();
  return 1;
}
