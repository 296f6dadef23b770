// Fuzz target: the analysis classes in log space, vtkTransformBasisLCT (factoring, Alexa §6.2)
// and vtkTransformSequencePCA (PCA, §6.3), with arbitrary matrices (NaN/Inf, projective,
// reflections, singular and extreme maps, exact half turns), coefficients, indices and settings.
// Each input is a sequence of operations on one basis and one PCA.
//
// Properties: no crash, sanitizer report or hang; a call that returns 1 reports no error and
// writes only finite values (matrices affine); a call that returns 0 reports an error and leaves
// its output untouched and the object's observable state (basis size, rank, component count,
// MTime for the basis) as it was; in Polar, Factor of a small combination Reconstruct made gives
// its coefficients back within GetCoefficientErrorBound() (times 1 + cond of the matrix), or
// refuses with an error (A4).
#include "FuzzInput.h"

#include "vtkTransformBasisLCT.h"
#include "vtkTransformSequencePCA.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace
{
using lct_fuzz::FromVtk;
using lct_fuzz::Show;
using lct_fuzz::ToVtk;

/// A sentinel output: untouched means still this.
void Poison(vtkMatrix4x4* m)
{
  for (int i = 0; i < 16; ++i)
  {
    m->SetElement(i / 4, i % 4, 7.25 + i);
  }
}

bool Poisoned(vtkMatrix4x4* m)
{
  for (int i = 0; i < 16; ++i)
  {
    if (m->GetElement(i / 4, i % 4) != 7.25 + i)
    {
      return false;
    }
  }
  return true;
}

bool FiniteAffine(vtkMatrix4x4* m)
{
  const Eigen::Matrix4d e = FromVtk(m);
  return e.allFinite() && e(3, 0) == 0.0 && e(3, 1) == 0.0 && e(3, 2) == 0.0 && e(3, 3) == 1.0;
}

class Session
{
public:
  explicit Session(lct_fuzz::Input& in)
    : In(in)
  {
    lct_fuzz::QuietOutputWindow::Install();
    this->Errors.Observe(this->Basis);
    this->Errors.Observe(this->Pca);
  }

  void Run()
  {
    // Bounded by the input: every operation consumes at least one byte.
    for (int step = 0; step < 64 && !this->In.Empty(); ++step)
    {
      switch (this->In.Byte() % 10)
      {
        case 0:
        case 1:
          this->AddBasisTransform();
          break;
        case 2:
          this->FromExamples();
          break;
        case 3:
          this->FactorAndReconstruct();
          break;
        case 4:
          this->Project();
          break;
        case 5:
          this->Settings();
          break;
        case 6:
        case 7:
          this->AddFrame();
          break;
        case 8:
          this->Compute();
          break;
        default:
          this->QueryPca();
          break;
      }
    }
  }

private:
  struct BasisState
  {
    int Size, Rank;
    vtkMTimeType MTime;
    bool operator==(const BasisState& o) const
    {
      return this->Size == o.Size && this->Rank == o.Rank && this->MTime == o.MTime;
    }
  };
  BasisState StateOfBasis()
  {
    return { this->Basis->GetNumberOfBasisTransforms(), this->Basis->GetRank(),
      this->Basis->GetMTime() };
  }

  /// Checks the contract of a call on the basis that returned `result`.
  void CheckBasisCall(int result, int errorsBefore, const BasisState& before, const char* what)
  {
    const bool reported = this->Errors.Errors > errorsBefore;
    LCT_FUZZ_CHECK(reported == (result == 0),
      what << " returned " << result << " but " << (reported ? "reported" : "did not report")
           << " an error: " << this->Errors.Last);
    if (result == 0)
    {
      LCT_FUZZ_CHECK(this->StateOfBasis() == before, what << " failed but changed the basis");
    }
  }

  void AddBasisTransform()
  {
    const Eigen::Matrix4d m = this->In.Matrix();
    LCT_FUZZ_TRACE("AddBasisTransform\n" << Show(m));
    const int errors = this->Errors.Errors;
    const BasisState before = this->StateOfBasis();
    const int result = this->Basis->AddBasisTransform(ToVtk(m));
    CheckBasisCall(result, errors, before, "AddBasisTransform");
  }

  void FromExamples()
  {
    vtkNew<vtkCollection> examples;
    const int n = this->In.Int(0, 20);
    for (int i = 0; i < n; ++i)
    {
      examples->AddItem(ToVtk(this->In.Matrix()));
    }
    LCT_FUZZ_TRACE("SetBasisFromExamples of " << n);
    const int errors = this->Errors.Errors;
    const BasisState before = this->StateOfBasis();
    const int result = this->Basis->SetBasisFromExamples(examples, this->In.Bool());
    CheckBasisCall(result, errors, before, "SetBasisFromExamples");
  }

  void FactorAndReconstruct()
  {
    const Eigen::Matrix4d m = this->In.Matrix();
    vtkNew<vtkDoubleArray> x;
    x->InsertNextValue(42.0);
    const int errors = this->Errors.Errors;
    const int result = this->Basis->Factor(ToVtk(m), x);
    LCT_FUZZ_TRACE("Factor -> " << result << "\n" << Show(m));
    LCT_FUZZ_CHECK((this->Errors.Errors > errors) == (result == 0), "Factor error reporting");
    if (result == 0)
    {
      LCT_FUZZ_CHECK(x->GetNumberOfTuples() == 1 && x->GetValue(0) == 42.0,
        "a failed Factor wrote its coefficients");
    }
    else
    {
      LCT_FUZZ_CHECK(x->GetNumberOfTuples() == this->Basis->GetNumberOfBasisTransforms(),
        "Factor gave the wrong number of coefficients");
      for (vtkIdType i = 0; i < x->GetNumberOfTuples(); ++i)
      {
        LCT_FUZZ_CHECK(std::isfinite(x->GetValue(i)), "Factor: a non-finite coefficient");
      }
      LCT_FUZZ_CHECK(std::isfinite(this->Basis->GetResidual()) && this->Basis->GetResidual() >= 0,
        "Factor: a non-finite residual");
    }
    // Reconstruct arbitrary coefficients (of the right count or not).
    vtkNew<vtkDoubleArray> y;
    const int count =
      this->In.Bool() ? this->Basis->GetNumberOfBasisTransforms() : this->In.Int(0, 13);
    for (int i = 0; i < count; ++i)
    {
      y->InsertNextValue(this->In.Double());
    }
    vtkNew<vtkMatrix4x4> t;
    Poison(t);
    const int before = this->Errors.Errors;
    const int built = this->Basis->Reconstruct(y, t);
    LCT_FUZZ_CHECK((this->Errors.Errors > before) == (built == 0), "Reconstruct error reporting");
    LCT_FUZZ_CHECK(built ? FiniteAffine(t) : Poisoned(t),
      "Reconstruct " << (built ? "wrote a non-finite matrix" : "failed but wrote its result"));
    // Round trip, in Polar, for small coefficients: every basis log's rotation is at most pi,
    // so |sum x_i w_i| <= 0.2 pi and log(exp(c)) = c (no branch). Factor either refuses (its
    // error bound beyond CoefficientTolerance: a basis close to the identity, A4) or gives x
    // back within its bound, plus the rounding of the reconstruction, ~cond(A) times it.
    if (built && this->Basis->GetParametrisation() == vtkTransformBasisLCT::POLAR &&
      this->Basis->GetRank() == count && count > 0)
    {
      double size = 0.0;
      for (int i = 0; i < count; ++i)
      {
        size = std::max(size, std::abs(y->GetValue(i)));
      }
      if (size < 0.2 / count)
      {
        vtkNew<vtkDoubleArray> back;
        const int errorsBefore = this->Errors.Errors;
        const int factored = this->Basis->Factor(t, back);
        LCT_FUZZ_CHECK((this->Errors.Errors > errorsBefore) == (factored == 0),
          "Factor of a reconstruction: error reporting");
        if (factored)
        {
          double error = 0.0;
          for (int i = 0; i < count; ++i)
          {
            const double d = back->GetValue(i) - y->GetValue(i);
            error += d * d;
          }
          error = std::sqrt(error);
          const Eigen::Matrix3d a = FromVtk(t).topLeftCorner<3, 3>();
          const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a);
          const double cond = svd.singularValues()[0] / svd.singularValues()[2];
          const double bound = this->Basis->GetCoefficientErrorBound();
          LCT_FUZZ_CHECK(error <= (1.0 + cond) * bound,
            "Factor(Reconstruct(x)) != x: error " << error << ", bound " << bound << ", cond "
                                                  << cond);
        }
      }
    }
  }

  void Project()
  {
    const Eigen::Matrix4d m = this->In.Matrix();
    vtkNew<vtkMatrix4x4> t;
    Poison(t);
    const int errors = this->Errors.Errors;
    const int result = this->Basis->Project(ToVtk(m), t);
    LCT_FUZZ_TRACE("Project -> " << result << "\n" << Show(m));
    LCT_FUZZ_CHECK((this->Errors.Errors > errors) == (result == 0), "Project error reporting");
    LCT_FUZZ_CHECK(result ? FiniteAffine(t) : Poisoned(t), "Project output");
    vtkNew<vtkMatrix4x4> b;
    Poison(b);
    const int i = this->In.Int(-1, 13);
    const int got = this->Basis->GetBasisTransform(i, b);
    LCT_FUZZ_CHECK(got ? FiniteAffine(b) : Poisoned(b), "GetBasisTransform output");
    Poison(b);
    const int origin = this->Basis->GetOrigin(b);
    LCT_FUZZ_CHECK(origin ? FiniteAffine(b) : Poisoned(b), "GetOrigin output");
  }

  void Settings()
  {
    const int errors = this->Errors.Errors;
    const BasisState before = this->StateOfBasis();
    switch (this->In.Byte() % 4)
    {
      case 0:
        CheckBasisCall(this->Basis->SetParametrisation(this->In.Int(-1, 2)), errors, before,
          "SetParametrisation");
        break;
      case 1:
        CheckBasisCall(
          this->Basis->SetRankTolerance(this->In.Double()), errors, before, "SetRankTolerance");
        break;
      case 2:
      {
        // Out of range: refused with an error, the setting unchanged.
        const int rank = this->In.Int(-5, 20), components = this->In.Int(-5, 50);
        const int rankBefore = this->Basis->GetMaximumRank();
        const int rankSet = this->Basis->SetMaximumRank(rank);
        LCT_FUZZ_CHECK(rankSet == (rank >= 0 && rank <= 12) &&
            this->Basis->GetMaximumRank() == (rankSet ? rank : rankBefore),
          "SetMaximumRank(" << rank << ") returned " << rankSet);
        LCT_FUZZ_CHECK(this->Pca->SetMaximumNumberOfComponents(components) == (components >= 0),
          "SetMaximumNumberOfComponents(" << components << ")");
        break;
      }
      default:
      {
        const int parametrisation = this->In.Int(-1, 2);
        LCT_FUZZ_CHECK(this->Pca->SetParametrisation(parametrisation) ==
            (parametrisation >= 0 && parametrisation <= 1),
          "SetParametrisation(" << parametrisation << ")");
        this->Pca->SetRootChannel(this->In.Int(-3, 5));
        this->Pca->SetChannelWeight(this->In.Int(-1, 4), this->In.Double());
        break;
      }
    }
  }

  void AddFrame()
  {
    vtkNew<vtkCollection> frame;
    const int channels = this->Pca->GetNumberOfChannels() > 0 && this->In.Bool()
      ? this->Pca->GetNumberOfChannels()
      : this->In.Int(0, 4);
    for (int c = 0; c < channels; ++c)
    {
      frame->AddItem(ToVtk(this->In.Matrix()));
    }
    const int frames = this->Pca->GetNumberOfFrames();
    const int errors = this->Errors.Errors;
    const int result = this->Pca->AddFrame(frame);
    LCT_FUZZ_CHECK((this->Errors.Errors > errors) == (result == 0), "AddFrame error reporting");
    LCT_FUZZ_CHECK(this->Pca->GetNumberOfFrames() == frames + result, "AddFrame frame count");
  }

  void Compute()
  {
    const int errors = this->Errors.Errors;
    const int result = this->Pca->Compute();
    LCT_FUZZ_TRACE("Compute -> " << result);
    LCT_FUZZ_CHECK((this->Errors.Errors > errors) == (result == 0), "Compute error reporting");
    if (result)
    {
      const int k = this->Pca->GetNumberOfComponents();
      vtkNew<vtkDoubleArray> fractions;
      LCT_FUZZ_CHECK(this->Pca->GetExplainedVariance(fractions) == 1, "GetExplainedVariance");
      double sum = 0.0;
      for (int i = 0; i < k; ++i)
      {
        LCT_FUZZ_CHECK(std::isfinite(fractions->GetValue(i)) && fractions->GetValue(i) >= 0.0,
          "a non-finite explained fraction");
        sum += fractions->GetValue(i);
      }
      LCT_FUZZ_CHECK(sum <= 1.0 + 1e-9, "explained fractions sum to " << sum);
    }
    else
    {
      LCT_FUZZ_CHECK(this->Pca->GetNumberOfComponents() == 0, "a failed Compute kept components");
    }
  }

  void QueryPca()
  {
    const int frame = this->In.Int(-1, 4), channel = this->In.Int(-1, 5);
    const int r = this->In.Int(-2, 60);
    vtkNew<vtkMatrix4x4> m;
    auto check = [&](int result, const char* what) {
      LCT_FUZZ_CHECK(result ? FiniteAffine(m) : Poisoned(m), what << " output");
      Poison(m);
    };
    Poison(m);
    check(this->Pca->GetReconstructedTransform(frame, channel, r, m), "GetReconstructedTransform");
    check(this->Pca->GetEigenMotion(this->In.Int(-1, 5), channel, this->In.Double(), m),
      "GetEigenMotion");
    check(this->Pca->GetMeanTransform(channel, m), "GetMeanTransform");
    vtkNew<vtkDoubleArray> scores;
    if (this->Pca->GetScores(frame, scores))
    {
      for (vtkIdType i = 0; i < scores->GetNumberOfTuples(); ++i)
      {
        LCT_FUZZ_CHECK(std::isfinite(scores->GetValue(i)), "a non-finite score");
      }
    }
  }

  lct_fuzz::Input& In;
  lct_fuzz::ErrorObserver Errors;
  vtkNew<vtkTransformBasisLCT> Basis;
  vtkNew<vtkTransformSequencePCA> Pca;
};
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  Session session(in);
  session.Run();
  return 0;
}
