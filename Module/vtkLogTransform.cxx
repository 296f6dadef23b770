#include "vtkLogTransform.h"

#include "lct/Combination.h"
#include "lct/Format.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"

#include "vtkCollection.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkLogTransform);

namespace
{
lct::Parametrisation toCore(int parametrisation)
{
  return parametrisation == vtkLogTransform::MATRIX_LOG ? lct::Parametrisation::MatrixLog
                                                        : lct::Parametrisation::Polar;
}

Eigen::Matrix4d toEigen(const double elements[16])
{
  // vtkMatrix4x4 stores row-major elements.
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(elements);
}
} // namespace

/// The coordinates and the matrix they stand for, and those of the inverse map, always updated
/// together. The inverse is computed when a state is committed, by the only path Inverse() could
/// take (MatrixLog: exp(-c); Polar: lct::polarInverse, then its exp), so that a state whose
/// inverse is not representable is refused where it is set, and Inverse() only swaps the two:
/// it cannot fail, inverting twice restores the state exactly, and GetInverse() (VTK's DeepCopy
/// + Inverse() on a hidden object) always holds the inverse.
struct vtkLogTransform::State
{
  lct::LogCoords Coordinates = lct::LogCoords::Zero();
  Eigen::Matrix4d Matrix = Eigen::Matrix4d::Identity();
  lct::LogCoords InverseCoordinates = lct::LogCoords::Zero();
  Eigen::Matrix4d InverseMatrix = Eigen::Matrix4d::Identity();
};

//------------------------------------------------------------------------------
vtkLogTransform::vtkLogTransform()
  : Internal(new State)
{
  this->MatrixWrittenTime = this->Matrix->GetMTime();
}

//------------------------------------------------------------------------------
vtkLogTransform::~vtkLogTransform()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
// The only place the state changes: the coordinates are committed with their matrix and the
// inverse state, and only when both matrices are finite.
bool vtkLogTransform::Commit(const double* coordinates, int parametrisation, const char* caller)
{
  const lct::LogCoords c = Eigen::Map<const lct::LogCoords>(coordinates);
  const lct::Parametrisation p = toCore(parametrisation);
  const auto matrix = lct::exponential(c, p);
  if (!matrix)
  {
    vtkErrorMacro(<< caller << ": the resulting transform is not representable: "
                  << lct::describe(matrix.status) << lct::adviceFor(matrix.status, p)
                  << "; unchanged.");
    return false;
  }
  // The inverse state, as Inverse() will hand it out. MatrixLog: the principal log of M^-1 is
  // -log M. Polar: psi(M^-1) != -psi(M) unless the factors commute, but it has a closed form that
  // keeps the winding of the rotation exactly, (-A^-1 l, -w, -U Y U^T). Its matrix must be finite
  // and its smallest stretch 1 / sigma_max normal: ||A||_F < 1 / DBL_MIN guarantees it, and
  // beyond that sigma_max itself decides (||A||_F exceeds it by up to sqrt(3): 3e307 I, whose
  // inverse 3.3e-308 I is normal, was refused while Inverse() of 3.3e-308 I held it).
  const auto inverseCoordinates = p == lct::Parametrisation::MatrixLog
    ? lct::Result<lct::LogCoords>{ lct::LogCoords(-c), lct::Status::Ok }
    : lct::polarInverse(c, matrix.value);
  const auto inverse = inverseCoordinates
    ? lct::exponential(inverseCoordinates.value, p)
    : lct::Result<Eigen::Matrix4d>::failure(inverseCoordinates.status);
  const Eigen::Matrix3d linear = matrix.value.topLeftCorner<3, 3>();
  const double largest = linear.cwiseAbs().maxCoeff();
  const double limit = 1.0 / std::numeric_limits<double>::min();
  const Eigen::Matrix3d unit = linear / largest;
  const bool invertible = largest * unit.norm() < limit ||
    largest * Eigen::JacobiSVD<Eigen::Matrix3d>(unit).singularValues()(0) < limit;
  if (!inverse || !inverse.value.allFinite() || !invertible)
  {
    vtkErrorMacro(<< caller << ": the inverse of the resulting transform is not representable: "
                  << lct::describe(inverse ? lct::Status::OutOfRange : inverse.status)
                  << "; a vtkLogTransform only holds maps it can also invert, so that Inverse() "
                  << "and GetInverse() always succeed; unchanged.");
    return false;
  }
  State& state = *this->Internal;
  state.Coordinates = c;
  state.Matrix = matrix.value;
  state.InverseCoordinates = inverseCoordinates.value;
  state.InverseMatrix = inverse.value;
  // A new state supersedes an edit made to GetMatrix() since the last Update: that edit is not
  // "put back" with a warning (SetMatrix(GetMatrix()) after editing it is the documented way).
  this->WriteStateMatrix();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetParametrisation(int parametrisation)
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
  const auto c = lct::logarithm(this->Internal->Matrix, toCore(parametrisation));
  if (!c)
  {
    vtkErrorMacro(<< "SetParametrisation: the current transform has no "
                  << lct::name(toCore(parametrisation))
                  << " coordinates: " << lct::describe(c.status) << "; unchanged.");
    return 0;
  }
  if (!this->Commit(c.value.data(), parametrisation, "SetParametrisation"))
  {
    return 0;
  }
  this->Parametrisation = parametrisation;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
const char* vtkLogTransform::GetParametrisationAsString()
{
  return lct::name(toCore(this->Parametrisation));
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetMatrix(vtkMatrix4x4* matrix)
{
  return this->SetMatrix(matrix, nullptr);
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetMatrix(const double elements[16])
{
  return this->SetMatrixNear(elements, nullptr);
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetMatrix(vtkMatrix4x4* matrix, vtkLogTransform* reference)
{
  if (!matrix)
  {
    vtkErrorMacro(<< "SetMatrix: null matrix; unchanged.");
    return 0;
  }
  return this->SetMatrixNear(
    matrix->GetData(), reference ? reference->Internal->Coordinates.data() : nullptr);
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetMatrixNear(const double elements[16], const double* reference)
{
  if (!elements)
  {
    vtkErrorMacro(<< "SetMatrix: null elements; unchanged.");
    return 0;
  }
  const lct::LogCoords referenceCoordinates =
    reference ? lct::LogCoords(Eigen::Map<const lct::LogCoords>(reference)) : lct::LogCoords();
  const auto c = lct::logarithm(
    toEigen(elements), toCore(this->Parametrisation), reference ? &referenceCoordinates : nullptr);
  if (!c)
  {
    vtkErrorMacro(<< "SetMatrix: " << lct::describe(c.status)
                  << lct::adviceFor(c.status, toCore(this->Parametrisation)) << "; unchanged.");
    return 0;
  }
  return this->Commit(c.value.data(), this->Parametrisation, "SetMatrix") ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetTransform(vtkLinearTransform* transform)
{
  if (!transform)
  {
    vtkErrorMacro(<< "SetTransform: null transform; unchanged.");
    return 0;
  }
  if (transform == this)
  {
    return 1;
  }
  return this->SetMatrix(transform->GetMatrix());
}

//------------------------------------------------------------------------------
int vtkLogTransform::SetLogCoordinates(const double coordinates[12])
{
  if (!coordinates)
  {
    vtkErrorMacro(<< "SetLogCoordinates: null coordinates; unchanged.");
    return 0;
  }
  const lct::LogCoords c = Eigen::Map<const lct::LogCoords>(coordinates);
  if (!c.allFinite())
  {
    vtkErrorMacro(<< "SetLogCoordinates: " << lct::describe(lct::Status::NonFinite)
                  << "; unchanged.");
    return 0;
  }
  if (!this->Commit(c.data(), this->Parametrisation, "SetLogCoordinates"))
  {
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLogTransform::GetLogCoordinates(double coordinates[12])
{
  Eigen::Map<lct::LogCoords> out(coordinates);
  out = this->Internal->Coordinates;
}

//------------------------------------------------------------------------------
int vtkLogTransform::Scale(double s)
{
  if (!std::isfinite(s))
  {
    vtkErrorMacro(<< "Scale: the factor " << s << " is not finite; unchanged.");
    return 0;
  }
  const lct::LogCoords scaled = s * this->Internal->Coordinates;
  if (!scaled.allFinite())
  {
    vtkErrorMacro(<< "Scale: " << lct::formatNumber(s)
                  << " times the coordinates overflows; unchanged.");
    return 0;
  }
  if (!this->Commit(scaled.data(), this->Parametrisation, "Scale"))
  {
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLogTransform::Add(vtkLogTransform* other)
{
  if (!other)
  {
    vtkErrorMacro(<< "Add: null transform; unchanged.");
    return 0;
  }
  vtkLogTransform* operands[2] = { this, other };
  const double weights[2] = { 1.0, 1.0 };
  return vtkLogTransform::Combine(2, weights, operands, this, "Add");
}

//------------------------------------------------------------------------------
bool vtkLogTransform::CoordinatesIn(vtkLogTransform* t, int parametrisation,
  vtkLogTransform* result, const char* caller, int index, double out[12])
{
  Eigen::Map<lct::LogCoords> coordinates(out);
  if (t->Parametrisation == parametrisation)
  {
    coordinates = t->Internal->Coordinates;
    return true;
  }
  const auto c = lct::logarithm(t->Internal->Matrix, toCore(parametrisation));
  if (!c)
  {
    vtkErrorWithObjectMacro(
      result, << caller << ": transform " << index << " has no "
              << lct::name(toCore(parametrisation)) << " coordinates: " << lct::describe(c.status)
              << lct::adviceFor(c.status, toCore(parametrisation)) << "; result unchanged.");
    return false;
  }
  coordinates = c.value;
  return true;
}

//------------------------------------------------------------------------------
int vtkLogTransform::LinearCombination(
  int count, const double* weights, vtkLogTransform* const* transforms, vtkLogTransform* result)
{
  return vtkLogTransform::Combine(count, weights, transforms, result, "LinearCombination");
}

//------------------------------------------------------------------------------
int vtkLogTransform::Combine(int count, const double* weights, vtkLogTransform* const* transforms,
  vtkLogTransform* result, const char* caller)
{
  if (!result)
  {
    vtkGenericWarningMacro(<< "vtkLogTransform::" << caller << ": null result.");
    return 0;
  }
  if (count < 0 || (count > 0 && (!weights || !transforms)))
  {
    vtkErrorWithObjectMacro(result, << caller
                                    << ": invalid count or null arrays; "
                                       "result unchanged.");
    return 0;
  }
  const int parametrisation = result->Parametrisation;
  lct::LogCoords sum = lct::LogCoords::Zero();
  for (int i = 0; i < count; ++i)
  {
    vtkLogTransform* t = transforms[i];
    if (!t || !std::isfinite(weights[i]))
    {
      vtkErrorWithObjectMacro(result, << caller << ": transform " << i
                                      << " is null or its weight is not finite; result "
                                         "unchanged.");
      return 0;
    }
    lct::LogCoords c;
    if (!vtkLogTransform::CoordinatesIn(t, parametrisation, result, caller, i, c.data()))
    {
      return 0;
    }
    sum += weights[i] * c;
  }
  if (!sum.allFinite())
  {
    vtkErrorWithObjectMacro(result, << caller
                                    << ": the weighted sum of the coordinates "
                                       "overflows; result unchanged.");
    return 0;
  }
  return result->Commit(sum.data(), parametrisation, caller) ? 1 : 0;
}

//------------------------------------------------------------------------------
int vtkLogTransform::LinearCombination(
  vtkCollection* transforms, vtkDoubleArray* weights, vtkLogTransform* result)
{
  if (!transforms || !weights || !result)
  {
    // An error (on `result` when there is one, so its observers see it), not a warning.
    vtkErrorWithObjectMacro(result, << "LinearCombination: null "
                                    << (!transforms   ? "transforms"
                                           : !weights ? "weights"
                                                      : "result")
                                    << "; nothing changed.");
    return 0;
  }
  const int count = transforms->GetNumberOfItems();
  if (weights->GetNumberOfComponents() != 1 || weights->GetNumberOfTuples() != count)
  {
    vtkErrorWithObjectMacro(result, << "LinearCombination: " << count << " transforms but "
                                    << weights->GetNumberOfTuples() << " weights of "
                                    << weights->GetNumberOfComponents()
                                    << " component(s) (one weight of 1 component per "
                                       "transform); result unchanged.");
    return 0;
  }
  std::vector<vtkLogTransform*> items(count);
  std::vector<double> w(count);
  for (int i = 0; i < count; ++i)
  {
    items[i] = vtkLogTransform::SafeDownCast(transforms->GetItemAsObject(i));
    if (!items[i])
    {
      vtkErrorWithObjectMacro(result,
        << "LinearCombination: item " << i << " is not a vtkLogTransform; result unchanged.");
      return 0;
    }
    w[i] = weights->GetValue(i);
  }
  return vtkLogTransform::LinearCombination(count, w.data(), items.data(), result);
}

//------------------------------------------------------------------------------
int vtkLogTransform::Interpolate(vtkLogTransform* a, vtkLogTransform* b, double t)
{
  if (!a || !b || !std::isfinite(t))
  {
    vtkErrorMacro(<< "Interpolate: null transform or non-finite t; unchanged.");
    return 0;
  }
  // Within [0, 1] the weights (1 - t, t): exact keys at the ends (log a + t (log b - log a)
  // lost the digits of |log a| at t = 1) and no overflow (log b - log a of translations
  // +-1e308 did). Outside, from the nearer key: with the weights the two terms cancel for a
  // large t (a turn interpolated with itself at t = 1e16 came out as the identity).
  lct::LogCoords la, lb;
  if (!vtkLogTransform::CoordinatesIn(
        a, this->Parametrisation, this, "Interpolate", 0, la.data()) ||
    !vtkLogTransform::CoordinatesIn(b, this->Parametrisation, this, "Interpolate", 1, lb.data()))
  {
    return 0;
  }
  lct::LogCoords result = (1.0 - t) * la + t * lb;
  if (t < 0.0 || t > 1.0)
  {
    const bool nearA = t < 0.5;
    const lct::LogCoords step = nearA ? lct::LogCoords(lb - la) : lct::LogCoords(la - lb);
    if (step.allFinite())
    {
      result = nearA ? lct::LogCoords(la + t * step) : lct::LogCoords(lb + (1.0 - t) * step);
    }
  }
  if (!result.allFinite())
  {
    vtkErrorMacro(<< "Interpolate: at t = " << lct::formatNumber(t)
                  << " the interpolated coordinates overflow; unchanged.");
    return 0;
  }
  return this->Commit(result.data(), this->Parametrisation, "Interpolate") ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkLogTransform::Identity()
{
  *this->Internal = State();
  this->WriteStateMatrix();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLogTransform::Inverse()
{
  // The inverse state was computed, and found representable, when this state was committed.
  State& s = *this->Internal;
  std::swap(s.Coordinates, s.InverseCoordinates);
  std::swap(s.Matrix, s.InverseMatrix);
  this->WriteStateMatrix();
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLogTransform::DeepCopy(vtkAbstractTransform* transform)
{
  // vtkAbstractTransform::DeepCopy dereferences its argument unchecked.
  if (!transform)
  {
    vtkErrorMacro(<< "DeepCopy: null transform; unchanged.");
    return;
  }
  if (transform != this && !vtkLogTransform::SafeDownCast(transform))
  {
    vtkErrorMacro(<< "DeepCopy: a " << transform->GetClassName()
                  << " is not a vtkLogTransform (use SetTransform() for any linear transform); "
                  << "unchanged.");
    return;
  }
  this->Superclass::DeepCopy(transform);
}

//------------------------------------------------------------------------------
vtkAbstractTransform* vtkLogTransform::MakeTransform()
{
  return vtkLogTransform::New();
}

//------------------------------------------------------------------------------
namespace
{
/// A^-T n, normalised: `inverse` is the linear part of A^-1. The input is scaled to a largest
/// component of 1 first and the result before normalising, whose squares would overflow or
/// underflow for components beyond 1e+-154 (scales of 1e+-200 give such normals). A zero normal
/// stays zero, as with vtkMath::Normalize.
Eigen::Vector3d inverseTransposeTimes(const Eigen::Matrix3d& inverse, const Eigen::Vector3d& n)
{
  if (!n.allFinite())
  {
    return n; // the caller's NaN or Inf, not one of ours
  }
  const double inputScale = n.cwiseAbs().maxCoeff();
  if (inputScale == 0.0)
  {
    return n;
  }
  Eigen::Vector3d out = inverse.transpose() * (n / inputScale);
  const double outputScale = out.cwiseAbs().maxCoeff();
  if (outputScale > 0.0)
  {
    out /= outputScale;
    out.normalize();
  }
  return out;
}
} // namespace

void vtkLogTransform::InternalTransformNormal(const double in[3], double out[3])
{
  const Eigen::Matrix3d inverse = this->Internal->InverseMatrix.topLeftCorner<3, 3>();
  const Eigen::Vector3d n = inverseTransposeTimes(inverse, Eigen::Vector3d(in[0], in[1], in[2]));
  std::copy(n.data(), n.data() + 3, out);
}

void vtkLogTransform::InternalTransformNormal(const float in[3], float out[3])
{
  const Eigen::Matrix3d inverse = this->Internal->InverseMatrix.topLeftCorner<3, 3>();
  const Eigen::Vector3d n = inverseTransposeTimes(inverse, Eigen::Vector3d(in[0], in[1], in[2]));
  for (int i = 0; i < 3; ++i)
  {
    out[i] = static_cast<float>(n[i]);
  }
}

void vtkLogTransform::TransformNormals(vtkDataArray* inNms, vtkDataArray* outNms)
{
  this->Update();
  const Eigen::Matrix3d inverse = this->Internal->InverseMatrix.topLeftCorner<3, 3>();
  const vtkIdType n = inNms->GetNumberOfTuples();
  // Appended, as vtkLinearTransform does (SetNumberOfTuples would not keep what is there).
  outNms->Resize(outNms->GetNumberOfTuples() + n);
  double normal[3];
  for (vtkIdType i = 0; i < n; ++i)
  {
    inNms->GetTuple(i, normal);
    const Eigen::Vector3d transformed =
      inverseTransposeTimes(inverse, Eigen::Vector3d(normal[0], normal[1], normal[2]));
    outNms->InsertNextTuple(transformed.data());
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLogTransform::GetMTime()
{
  const vtkMTimeType mtime = this->Superclass::GetMTime();
  const vtkMTimeType matrixTime = this->Matrix->GetMTime();
  return matrixTime > this->MatrixWrittenTime ? std::max(mtime, matrixTime) : mtime;
}

//------------------------------------------------------------------------------
void vtkLogTransform::InternalUpdate()
{
  // Every state change writes its matrix (WriteStateMatrix), so there is nothing to do unless
  // the matrix was changed from outside since (and rewriting it unchanged would race with other
  // threads' TransformPoint).
  if (this->Matrix->GetMTime() <= this->MatrixWrittenTime)
  {
    return;
  }
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> matrix(this->Matrix->GetData());
  if (matrix != this->Internal->Matrix)
  {
    // vtkTransform adopts such a change (its deprecated "legacy hack"); here the coordinates,
    // the inverse and every operation would keep the old map while TransformPoint used the new.
    vtkWarningMacro(<< "the matrix was changed directly (GetMatrix()->SetElement or alike); a "
                       "vtkLogTransform's state is its log coordinates, so their matrix is put "
                       "back: use SetMatrix to change the transform.");
  }
  this->WriteStateMatrix();
}

//------------------------------------------------------------------------------
void vtkLogTransform::WriteStateMatrix()
{
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(this->Matrix->GetData()) =
    this->Internal->Matrix;
  this->Matrix->Modified();
  this->MatrixWrittenTime = this->Matrix->GetMTime();
}

//------------------------------------------------------------------------------
void vtkLogTransform::InternalDeepCopy(vtkAbstractTransform* transform)
{
  this->Superclass::InternalDeepCopy(transform);
  auto* other = static_cast<vtkLogTransform*>(transform);
  *this->Internal = *other->Internal;
  this->Parametrisation = other->Parametrisation;
  // The superclass copied the other's matrix: written by this class, not changed from outside.
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(this->Matrix->GetData()) =
    this->Internal->Matrix;
  this->Matrix->Modified();
  this->MatrixWrittenTime = this->Matrix->GetMTime();
}

//------------------------------------------------------------------------------
void vtkLogTransform::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  const lct::LogCoords& c = this->Internal->Coordinates;
  os << indent << "Parametrisation: " << this->GetParametrisationAsString() << "\n";
  os << indent << "Translation part: (" << c[0] << ", " << c[1] << ", " << c[2] << ")\n";
  os << indent << "Rotation part: (" << c[3] << ", " << c[4] << ", " << c[5] << ")\n";
  os << indent << "Symmetric part (xx, yy, zz, xy, yz, xz): (" << c[6] << ", " << c[7] << ", "
     << c[8] << ", " << c[9] << ", " << c[10] << ", " << c[11] << ")\n";
}
