// Fuzz target: vtkLogTransform. Each input is a sequence of operations on three transforms:
// SetMatrix (vtkMatrix4x4 / elements / with a reference), SetTransform, SetLogCoordinates,
// Scale, Add, Interpolate, LinearCombination (both forms, aliasing the result), Inverse,
// GetInverse, SetParametrisation, DeepCopy, Identity.
//
// Properties: no crash, sanitizer report or hang; after every call every transform's matrix and
// coordinates are finite and its matrix is affine; a call that returns 0 (or reports an error)
// leaves the object exactly as it was (coordinates, matrix, parametrisation, MTime); a call that
// returns 1 reports no error; SetMatrix of a well-conditioned matrix gives that matrix back, and
// an Inverse / GetInverse that reports nothing is the inverse (loosely).
#include "FuzzInput.h"

#include "vtkLogTransform.h"

#include "lct/Affine.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <Eigen/SVD>

#include <vector>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

Eigen::Matrix4d MatrixOf(vtkLinearTransform* t)
{
  return RowMajor4(Eigen::Map<const RowMajor4>(t->GetMatrix()->GetData()));
}

lct::LogCoords CoordinatesOf(vtkLogTransform* t)
{
  lct::LogCoords c;
  t->GetLogCoordinates(c.data());
  return c;
}

/// Everything a failed call must leave as it was.
struct Snapshot
{
  lct::LogCoords Coordinates;
  Eigen::Matrix4d Matrix;
  int Parametrisation;
  vtkMTimeType MTime;

  static Snapshot Of(vtkLogTransform* t)
  {
    Snapshot s;
    s.Coordinates = CoordinatesOf(t);
    s.Matrix = MatrixOf(t); // updates the transform, so the MTime is read after it
    s.Parametrisation = t->GetParametrisation();
    s.MTime = t->GetMTime();
    return s;
  }
  bool SameAs(const Snapshot& o) const
  {
    return lct_fuzz::SameBits(this->Coordinates.data(), o.Coordinates.data(), 12) &&
      lct_fuzz::SameBits(this->Matrix.data(), o.Matrix.data(), 16) &&
      this->Parametrisation == o.Parametrisation && this->MTime == o.MTime;
  }
};

/// Singular values within [1e-30, 1e30] spanning at most `condition`, translation below 1e30.
bool WellConditioned(const Eigen::Matrix4d& m, double condition)
{
  if (lct::validateAffine(m) != lct::Status::Ok)
  {
    return false;
  }
  const Eigen::Vector3d s =
    Eigen::JacobiSVD<Eigen::Matrix3d>(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).singularValues();
  return s[2] >= 1e-30 && s[0] <= 1e30 && s[0] <= condition * s[2] &&
    m.topRightCorner<3, 1>().norm() <= 1e30;
}

/// max relative error of a against b, block by block (as the README measures).
double RelativeError(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b)
{
  const double linear =
    (a.topLeftCorner<3, 3>() - b.topLeftCorner<3, 3>()).norm() / b.topLeftCorner<3, 3>().norm();
  const double translation = (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).norm() /
    std::max(1.0, b.topRightCorner<3, 1>().norm()) / std::max(1.0, b.topLeftCorner<3, 3>().norm());
  return std::max(linear, translation);
}

class Session
{
public:
  explicit Session(lct_fuzz::Input& in)
    : In(in)
  {
    lct_fuzz::QuietOutputWindow::Install();
    for (auto& t : this->T)
    {
      t = vtkSmartPointer<vtkLogTransform>::New();
      this->Errors.Observe(t);
    }
  }

  void Run()
  {
    for (int op = 0; op < 48 && !this->In.Empty(); ++op)
    {
      this->Step();
      for (int i = 0; i < 3; ++i)
      {
        this->CheckInvariants(i);
      }
    }
  }

private:
  vtkLogTransform* Pick() { return this->T[this->In.Int(0, 2)]; }
  int Index(vtkLogTransform* t) const { return t == this->T[0] ? 0 : (t == this->T[1] ? 1 : 2); }

  int ErrorCount() const
  {
    return this->Errors.Errors + lct_fuzz::QuietOutputWindow::Install()->Errors;
  }

  void CheckInvariants(int i)
  {
    vtkLogTransform* t = this->T[i];
    const lct::LogCoords c = CoordinatesOf(t);
    const Eigen::Matrix4d m = MatrixOf(t);
    LCT_FUZZ_CHECK(AllFinite(c) && AllFinite(m),
      "transform " << i << " (" << t->GetParametrisationAsString()
                   << ") holds non-finite state\ncoordinates " << Show(c.transpose())
                   << "\nmatrix\n"
                   << Show(m));
    LCT_FUZZ_CHECK(m.row(3) == Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0),
      "transform " << i << " is not affine:\n"
                   << Show(m));
  }

  /// Checks a call's result: 0 means an error was reported and nothing changed; 1 means no
  /// error.
  void Outcome(
    int result, vtkLogTransform* t, const Snapshot& before, int errorsBefore, const char* what)
  {
    const vtkMTimeType mtime = t->GetMTime();
    if (result == 0)
    {
      LCT_FUZZ_CHECK(this->ErrorCount() > errorsBefore, what << " returned 0 without an error");
      Snapshot after = Snapshot::Of(t);
      after.MTime = mtime;
      LCT_FUZZ_CHECK(after.SameAs(before),
        what << " failed but changed the transform\nbefore: "
             << Show(before.Coordinates.transpose())
             << "\nafter:  " << Show(after.Coordinates.transpose()) << "\nMTime " << before.MTime
             << " -> " << mtime);
    }
    else
    {
      LCT_FUZZ_CHECK(result == 1, what << " returned " << result);
      LCT_FUZZ_CHECK(this->ErrorCount() == errorsBefore,
        what << " returned 1 but reported an error: " << this->Errors.Last);
    }
  }

  void SetMatrix()
  {
    vtkLogTransform* t = this->Pick();
    const Eigen::Matrix4d m = this->In.Matrix();
    const int form = this->In.Int(0, 3);
    vtkLogTransform* reference = form == 2 ? this->Pick() : nullptr;
    LCT_FUZZ_TRACE("T" << this->Index(t) << " (" << t->GetParametrisationAsString()
                       << ") SetMatrix form " << form << " ref "
                       << (reference ? this->Index(reference) : -1) << "\n"
                       << Show(m));
    const Snapshot before = Snapshot::Of(t);
    const int errors = this->ErrorCount();
    RowMajor4 rowMajor = m;
    vtkNew<vtkMatrix4x4> matrix;
    matrix->DeepCopy(rowMajor.data());
    int result = 0;
    switch (form)
    {
      case 0:
        result = t->SetMatrix(matrix);
        break;
      case 1:
        result = t->SetMatrix(rowMajor.data());
        break;
      case 2:
        result = t->SetMatrix(matrix, reference);
        break;
      default:
      {
        vtkNew<vtkTransform> source;
        source->SetMatrix(matrix);
        result = t->SetTransform(source);
        break;
      }
    }
    this->Outcome(result, t, before, errors, "SetMatrix");
    // Polar has coordinates for every map of Aff+(3) (condition <= 1e13, a normal stretch); the
    // only other refusal is a reference wound beyond kMaxRotationWinding (Polar, the reference
    // being in any parametrisation).
    const bool woundReference = reference &&
      lct::rotationPart(CoordinatesOf(reference)).norm() > 0.99 * lct::kMaxRotationWinding;
    LCT_FUZZ_CHECK(result == 1 || t->GetParametrisation() != vtkLogTransform::POLAR ||
        !WellConditioned(m, 1e6) || woundReference,
      "SetMatrix (Polar) refused a well-conditioned map: " << this->Errors.Last << "\n"
                                                           << Show(m));
    if (result == 1 && WellConditioned(m, 1e6))
    {
      // Within 1e-2 even for a reference wound up to kMaxRotationWinding (ulp(1e9) ~ 1e-7).
      const double error = RelativeError(MatrixOf(t), m);
      LCT_FUZZ_CHECK(error <= 1e-2,
        "SetMatrix (" << t->GetParametrisationAsString() << ") does not give the matrix back:"
                      << " relative error " << error << "\ngiven\n"
                      << Show(m) << "\ngot\n"
                      << Show(MatrixOf(t)));
    }
  }

  void SetLogCoordinates()
  {
    vtkLogTransform* t = this->Pick();
    const lct::LogCoords c = this->In.Coordinates();
    LCT_FUZZ_TRACE("T" << this->Index(t) << " SetLogCoordinates " << Show(c.transpose()));
    const Snapshot before = Snapshot::Of(t);
    const int errors = this->ErrorCount();
    const int result = t->SetLogCoordinates(c.data());
    this->Outcome(result, t, before, errors, "SetLogCoordinates");
    if (result == 1)
    {
      LCT_FUZZ_CHECK(CoordinatesOf(t) == c, "SetLogCoordinates stored other coordinates");
    }
  }

  void Scale()
  {
    vtkLogTransform* t = this->Pick();
    const double s = this->In.Double();
    LCT_FUZZ_TRACE("T" << this->Index(t) << " Scale " << s);
    const Snapshot before = Snapshot::Of(t);
    const int errors = this->ErrorCount();
    this->Outcome(t->Scale(s), t, before, errors, "Scale");
  }

  /// Add, Interpolate and the pointer form of LinearCombination: result <- sum w_i T_i.
  void Combine(int kind)
  {
    vtkLogTransform* result = this->Pick();
    std::vector<vtkLogTransform*> operands;
    std::vector<double> weights;
    double t = 0.0;
    switch (kind)
    {
      case 0: // Add
        operands = { result, this->In.Int(0, 7) == 0 ? nullptr : this->Pick() };
        weights = { 1.0, 1.0 };
        break;
      case 1: // Interpolate
        operands = { this->Pick(), this->Pick() };
        t = this->In.Double();
        weights = { 1.0 - t, t };
        break;
      default:
      {
        const int count = this->In.Int(0, 4);
        for (int i = 0; i < count; ++i)
        {
          operands.push_back(this->In.Int(0, 9) == 0 ? nullptr : this->Pick());
          weights.push_back(this->In.Byte() % 2
              ? this->In.Double()
              : this->In.Provider().ConsumeFloatingPointInRange<double>(-1.0, 2.0));
        }
        break;
      }
    }
    LCT_FUZZ_TRACE("T" << this->Index(result) << " combine kind " << kind << " of "
                       << operands.size() << " t " << t);
    for (size_t i = 0; i < operands.size(); ++i)
    {
      LCT_FUZZ_TRACE(
        "  operand T" << (operands[i] ? this->Index(operands[i]) : -1) << " weight " << weights[i]);
    }
    const Snapshot before = Snapshot::Of(result);
    const int errors = this->ErrorCount();
    int r = 0;
    switch (kind)
    {
      case 0:
        r = result->Add(operands[1]);
        break;
      case 1:
        r = result->Interpolate(operands[0], operands[1], t);
        break;
      default:
        r = vtkLogTransform::LinearCombination(static_cast<int>(operands.size()),
          weights.empty() ? nullptr : weights.data(), operands.empty() ? nullptr : operands.data(),
          result);
        break;
    }
    this->Outcome(r, result, before, errors,
      kind == 0 ? "Add" : (kind == 1 ? "Interpolate" : "LinearCombination"));
  }

  /// The collection form, with items that are not vtkLogTransforms and weight arrays of the
  /// wrong shape.
  void CombineCollection()
  {
    vtkLogTransform* result = this->Pick();
    vtkNew<vtkCollection> items;
    vtkNew<vtkDoubleArray> weights;
    const int count = this->In.Int(0, 4);
    weights->SetNumberOfComponents(this->In.Int(0, 15) == 0 ? 2 : 1);
    std::vector<vtkLogTransform*> operands;
    std::vector<double> w;
    for (int i = 0; i < count; ++i)
    {
      if (this->In.Int(0, 15) == 0)
      {
        vtkNew<vtkTransform> other;
        items->AddItem(other);
      }
      else
      {
        operands.push_back(this->Pick());
        items->AddItem(operands.back());
      }
      const double weight = this->In.Provider().ConsumeFloatingPointInRange<double>(-1.0, 2.0);
      w.push_back(weight);
      const double tuple[2] = { weight, weight }; // the array may have 2 components
      weights->InsertNextTuple(tuple);
    }
    if (this->In.Int(0, 15) == 0)
    {
      const double extra[2] = { 1.0, 1.0 };
      weights->InsertNextTuple(extra);
    }
    LCT_FUZZ_TRACE("T" << this->Index(result) << " LinearCombination(collection) of " << count);
    const Snapshot before = Snapshot::Of(result);
    const int errors = this->ErrorCount();
    const int r = vtkLogTransform::LinearCombination(items, weights, result);
    this->Outcome(r, result, before, errors, "LinearCombination(collection)");
  }

  /// vtkLogTransform.h: every state has a finite matrix and a finite inverse, so Inverse() and
  /// GetInverse() always succeed, without an error, and are the inverse (the Polar one in closed
  /// form, winding kept exactly); inverting twice restores the state bit for bit.
  void Inverse()
  {
    vtkLogTransform* t = this->Pick();
    const Snapshot before = Snapshot::Of(t);
    const Eigen::Matrix4d& m = before.Matrix;
    LCT_FUZZ_TRACE("T" << this->Index(t) << " (" << t->GetParametrisationAsString()
                       << ") Inverse, coordinates " << Show(before.Coordinates.transpose()));
    const int errors = this->ErrorCount();
    t->Inverse();
    LCT_FUZZ_CHECK(this->ErrorCount() == errors,
      "Inverse reported an error: " << this->Errors.Last << "\n"
                                    << Show(m));
    this->CheckInverse(m, MatrixOf(t), "Inverse");
    vtkNew<vtkLogTransform> back;
    back->DeepCopy(t);
    back->Inverse();
    Snapshot restored = Snapshot::Of(back);
    restored.MTime = before.MTime;
    LCT_FUZZ_CHECK(restored.SameAs(before),
      "Inverse twice does not restore the state\nbefore: "
        << Show(before.Coordinates.transpose())
        << "\nafter:  " << Show(restored.Coordinates.transpose()));
  }

  void GetInverse()
  {
    vtkLogTransform* t = this->Pick();
    const Eigen::Matrix4d m = MatrixOf(t);
    LCT_FUZZ_TRACE("T" << this->Index(t) << " GetInverse");
    const int errors = this->ErrorCount();
    auto* inverse = vtkLinearTransform::SafeDownCast(t->GetInverse());
    LCT_FUZZ_CHECK(inverse, "GetInverse is not a vtkLinearTransform");
    const Eigen::Matrix4d mi = MatrixOf(inverse);
    LCT_FUZZ_CHECK(this->ErrorCount() == errors,
      "GetInverse reported an error: " << this->Errors.Last << "\n"
                                       << Show(m));
    this->CheckInverse(m, mi, "GetInverse");
  }

  static void CheckInverse(const Eigen::Matrix4d& m, const Eigen::Matrix4d& mi, const char* what)
  {
    LCT_FUZZ_CHECK(AllFinite(mi), what << " is not finite:\n" << Show(mi));
    if (WellConditioned(m, 1e6))
    {
      LCT_FUZZ_CHECK(RelativeError(mi, lct::inverseAffine(m)) <= 1e-2,
        what << " is not the inverse:\n"
             << Show(m) << "\n->\n"
             << Show(mi));
    }
  }

  void SetParametrisation()
  {
    vtkLogTransform* t = this->Pick();
    const int choice = this->In.Int(0, 7);
    const int p = choice < 3 ? vtkLogTransform::POLAR
                             : (choice < 6 ? vtkLogTransform::MATRIX_LOG : this->In.Int(-3, 5));
    LCT_FUZZ_TRACE("T" << this->Index(t) << " SetParametrisation " << p);
    const Snapshot before = Snapshot::Of(t);
    const int errors = this->ErrorCount();
    const int r = t->SetParametrisation(p);
    this->Outcome(r, t, before, errors, "SetParametrisation");
    if (r == 1)
    {
      LCT_FUZZ_CHECK(t->GetParametrisation() == p, "SetParametrisation did not take");
    }
  }

  void DeepCopy()
  {
    vtkLogTransform* to = this->Pick();
    vtkLogTransform* from = this->Pick();
    LCT_FUZZ_TRACE("T" << this->Index(to) << " DeepCopy T" << this->Index(from));
    to->DeepCopy(from);
    LCT_FUZZ_CHECK(CoordinatesOf(to) == CoordinatesOf(from) && MatrixOf(to) == MatrixOf(from) &&
        to->GetParametrisation() == from->GetParametrisation(),
      "DeepCopy did not copy");
  }

  void Step()
  {
    switch (this->In.Byte() % 13)
    {
      case 0:
      case 1:
      case 2:
        this->SetMatrix();
        break;
      case 3:
        this->SetLogCoordinates();
        break;
      case 4:
        this->Scale();
        break;
      case 5:
        this->Combine(0);
        break;
      case 6:
        this->Combine(1);
        break;
      case 7:
        this->Combine(2);
        break;
      case 8:
        this->CombineCollection();
        break;
      case 9:
        this->In.Bool() ? this->Inverse() : this->GetInverse();
        break;
      case 10:
        this->SetParametrisation();
        break;
      case 11:
        this->DeepCopy();
        break;
      default:
      {
        vtkLogTransform* t = this->Pick();
        LCT_FUZZ_TRACE("T" << this->Index(t) << " Identity");
        t->Identity();
        break;
      }
    }
  }

  lct_fuzz::Input& In;
  vtkSmartPointer<vtkLogTransform> T[3];
  lct_fuzz::ErrorObserver Errors;
};
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  Session session(in);
  session.Run();
  return 0;
}
