// vtkTransformBasisLCT: factoring onto an explicit basis and onto one found from examples,
// reconstruction, projection ("constraining"), rank deficiency and every bad input.
#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "vtkTransformBasisLCT.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using lct_test::ErrorCounter;
using lct_test::fromVtk;
using lct_test::kPi;
using lct_test::toVtk;

struct Watched
{
  vtkNew<vtkTransformBasisLCT> basis;
  vtkNew<ErrorCounter> errors;
  vtkNew<ErrorCounter> warnings;
  Watched()
  {
    basis->AddObserver(vtkCommand::ErrorEvent, errors);
    basis->AddObserver(vtkCommand::WarningEvent, warnings);
  }
};

vtkNew<vtkMatrix4x4> matrixOf(const Eigen::Matrix4d& m)
{
  vtkNew<vtkMatrix4x4> v;
  toVtk(m, v);
  return v;
}

vtkNew<vtkTransform> rotateWXYZ(double degrees, double x, double y, double z)
{
  vtkNew<vtkTransform> t;
  t->RotateWXYZ(degrees, x, y, z);
  return t;
}

Eigen::Vector3d valuesOf(vtkDoubleArray* a)
{
  return Eigen::Vector3d(a->GetValue(0), a->GetValue(1), a->GetValue(2));
}
} // namespace

TEST(vtkTransformBasisLCT, AlexaRotationBasis)
{
  for (const int p : { vtkTransformBasisLCT::POLAR, vtkTransformBasisLCT::MATRIX_LOG })
  {
    Watched w;
    ASSERT_EQ(w.basis->SetParametrisation(p), 1);
    const double phiDegrees = 40.0, phi = phiDegrees * kPi / 180.0;
    ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(phiDegrees, 1, 0, 0).Get()), 1);
    ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(phiDegrees, 0, 1, 0).Get()), 1);
    ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(phiDegrees, 0, 0, 1).Get()), 1);
    EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 3);
    EXPECT_EQ(w.basis->GetRank(), 3);
    EXPECT_NEAR(w.basis->GetConditionNumber(), 1.0, 1e-12);
    const Eigen::Vector3d axis = Eigen::Vector3d(1.0, -2.0, 0.5).normalized();
    const double theta = 2.5;
    vtkNew<vtkDoubleArray> x;
    ASSERT_EQ(
      w.basis->Factor(rotateWXYZ(theta * 180.0 / kPi, axis[0], axis[1], axis[2])->GetMatrix(), x),
      1);
    ASSERT_EQ(x->GetNumberOfTuples(), 3);
    EXPECT_LE((valuesOf(x) - theta / phi * axis).norm(), 1e-12);
    EXPECT_LE(w.basis->GetResidual(), 1e-14);
    vtkNew<vtkMatrix4x4> back;
    ASSERT_EQ(w.basis->Reconstruct(x, back), 1);
    EXPECT_LE((fromVtk(back) -
                fromVtk(rotateWXYZ(theta * 180.0 / kPi, axis[0], axis[1], axis[2])->GetMatrix()))
                .norm(),
      1e-12);
    // The basis transforms come back as they were given.
    vtkNew<vtkMatrix4x4> b1;
    ASSERT_EQ(w.basis->GetBasisTransform(1, b1), 1);
    EXPECT_EQ(fromVtk(b1), fromVtk(rotateWXYZ(phiDegrees, 0, 1, 0)->GetMatrix()));
    EXPECT_EQ(w.errors->Count, 0);
  }
}

TEST(vtkTransformBasisLCT, FactorThenReconstructIsExactInTheSpan)
{
  lct_test::RandomTransforms random(21);
  for (const int p : { vtkTransformBasisLCT::POLAR, vtkTransformBasisLCT::MATRIX_LOG })
  {
    for (int trial = 0; trial < 40; ++trial)
    {
      Watched w;
      ASSERT_EQ(w.basis->SetParametrisation(p), 1);
      const int k = 1 + trial % 12;
      // MatrixLog: draw again where a key has no real log (about one in seven).
      int errors = 0;
      while (w.basis->GetNumberOfBasisTransforms() < k)
      {
        errors += w.basis->AddBasisTransform(
                    matrixOf(random.Affine(lct_test::TransformClass::GeneralAffine))) == 0;
      }
      EXPECT_EQ(w.errors->Count, errors);
      EXPECT_TRUE(errors == 0 || p == vtkTransformBasisLCT::MATRIX_LOG);
      vtkNew<vtkDoubleArray> x;
      x->SetNumberOfTuples(k);
      for (int i = 0; i < k; ++i)
      {
        x->SetValue(i, random.Uniform(-0.5, 0.5) / std::sqrt(double(k)));
      }
      vtkNew<vtkMatrix4x4> t;
      ASSERT_EQ(w.basis->Reconstruct(x, t), 1);
      vtkNew<vtkDoubleArray> back;
      if (!w.basis->Factor(t, back))
      {
        // MatrixLog: the combination may have no real log (reported, not wrong).
        ASSERT_EQ(p, vtkTransformBasisLCT::MATRIX_LOG);
        continue;
      }
      ASSERT_EQ(back->GetNumberOfTuples(), k);
      for (int i = 0; i < k; ++i)
      {
        EXPECT_NEAR(back->GetValue(i), x->GetValue(i), 1e-10);
      }
      EXPECT_LE(w.basis->GetResidual(), 1e-10);
    }
  }
}

// "Constraining a transform" (Alexa §6.2): examples of rotations about z combined with
// translations along x span a 2-D subspace; any transform projects to one of that form.
TEST(vtkTransformBasisLCT, BasisFromExamplesConstrainsTransforms)
{
  Watched w;
  vtkNew<vtkCollection> examples;
  for (int i = 0; i < 9; ++i)
  {
    vtkNew<vtkTransform> t;
    t->Translate((i % 3) - 1.0, 0, 0);
    t->RotateZ(17.0 * i - 60.0);
    examples->AddItem(t);
  }
  ASSERT_EQ(w.basis->SetBasisFromExamples(examples, 1), 1);
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 2);
  EXPECT_NEAR(w.basis->GetConditionNumber(), 1.0, 1e-12);
  vtkNew<vtkDoubleArray> singular;
  w.basis->GetSingularValues(singular);
  ASSERT_EQ(singular->GetNumberOfTuples(), 9); // min(9 examples, 12)
  EXPECT_GT(singular->GetValue(1), 0.1);
  EXPECT_LE(singular->GetValue(2), 1e-14 * singular->GetValue(0));
  // Every example lies in the subspace.
  for (int i = 0; i < examples->GetNumberOfItems(); ++i)
  {
    vtkNew<vtkMatrix4x4> projected;
    auto* t = vtkTransform::SafeDownCast(examples->GetItemAsObject(i));
    ASSERT_EQ(w.basis->Project(t->GetMatrix(), projected), 1);
    EXPECT_LE(w.basis->GetResidual(), 1e-13);
    EXPECT_LE((fromVtk(projected) - fromVtk(t->GetMatrix())).norm(), 1e-12);
  }
  // A general transform projects onto a rotation about z with a translation along x: a
  // transform of the form the examples allow.
  vtkNew<vtkTransform> general;
  general->Translate(1.0, 2.0, -3.0);
  general->RotateWXYZ(50.0, 0.3, 0.4, 1.0);
  general->Scale(1.2, 0.9, 1.1);
  vtkNew<vtkMatrix4x4> constrained;
  ASSERT_EQ(w.basis->Project(general->GetMatrix(), constrained), 1);
  EXPECT_GT(w.basis->GetResidual(), 0.1);
  const Eigen::Matrix4d c = fromVtk(constrained);
  EXPECT_NEAR(c(2, 2), 1.0, 1e-12);
  EXPECT_NEAR(c(1, 3), 0.0, 1e-12);
  EXPECT_NEAR(c(2, 3), 0.0, 1e-12);
  const Eigen::Matrix3d linear = c.topLeftCorner<3, 3>();
  EXPECT_NEAR(linear.determinant(), 1.0, 1e-12);
  EXPECT_LE((linear.transpose() * linear - Eigen::Matrix3d::Identity()).norm(), 1e-12);
  vtkNew<vtkMatrix4x4> origin;
  ASSERT_EQ(w.basis->GetOrigin(origin), 1);
  EXPECT_NEAR(fromVtk(origin)(0, 3), 0.0, 1e-12); // the mean translation of -1, 0, 1
  // MaximumRank keeps the strongest direction only.
  const int all = w.basis->GetNumberOfBasisTransforms();
  ASSERT_GT(all, 1);
  w.basis->SetMaximumRank(1);
  ASSERT_EQ(w.basis->SetBasisFromExamples(examples, 1), 1);
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 1);
  // Changing it re-analyses the examples (SetRankTolerance re-analysed with the rank in force
  // when they were set, and SetMaximumRank not at all: GetMaximumRank described another basis).
  ASSERT_EQ(w.basis->SetMaximumRank(0), 1);
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), all);
  ASSERT_EQ(w.basis->SetMaximumRank(1), 1);
  ASSERT_EQ(w.basis->SetRankTolerance(1e-6), 1);
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 1);
  EXPECT_EQ(w.basis->GetMaximumRank(), 1);
  EXPECT_EQ(w.errors->Count, 0);
}

TEST(vtkTransformBasisLCT, RankDeficientBasisIsReportedNotSolved)
{
  Watched w;
  vtkNew<vtkTransform> a, b, ab;
  a->RotateX(30.0);
  b->RotateX(-45.0); // the same axis: dependent
  ASSERT_EQ(w.basis->AddBasisTransform(a.Get()), 1);
  EXPECT_EQ(w.warnings->Count, 0);
  ASSERT_EQ(w.basis->AddBasisTransform(b.Get()), 1);
  EXPECT_EQ(w.warnings->Count, 1);
  EXPECT_NE(w.warnings->Last.find("rank deficient (rank 1 of 2"), std::string::npos)
    << w.warnings->Last;
  EXPECT_EQ(w.basis->GetRank(), 1);
  EXPECT_TRUE(std::isinf(w.basis->GetConditionNumber()));
  vtkNew<vtkDoubleArray> x;
  x->InsertNextValue(42.0);
  EXPECT_EQ(w.basis->Factor(a->GetMatrix(), x), 0);
  EXPECT_EQ(w.errors->Count, 1);
  EXPECT_NE(w.errors->Last.find("not unique"), std::string::npos) << w.errors->Last;
  EXPECT_EQ(x->GetNumberOfTuples(), 1);
  EXPECT_EQ(x->GetValue(0), 42.0);
  vtkNew<vtkMatrix4x4> projected;
  ab->RotateX(10.0);
  ASSERT_EQ(w.basis->Project(ab->GetMatrix(), projected), 1);
  EXPECT_LE((fromVtk(projected) - fromVtk(ab->GetMatrix())).norm(), 1e-12);
  // A looser tolerance cannot repair it, a tighter one cannot either (exact dependence).
  ASSERT_EQ(w.basis->SetRankTolerance(1e-14), 1);
  EXPECT_EQ(w.basis->GetRank(), 1);
}

TEST(vtkTransformBasisLCT, BadInputIsRefusedAndLeavesTheStateAlone)
{
  Watched w;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkMatrix4x4> result, probe;
  result->SetElement(0, 3, 7.0);
  vtkNew<vtkDoubleArray> x;
  // No basis yet.
  EXPECT_EQ(w.basis->Factor(probe, x), 0);
  EXPECT_EQ(w.basis->Project(probe, result), 0);
  EXPECT_EQ(w.basis->Reconstruct(x, result), 0);
  EXPECT_EQ(w.basis->GetOrigin(result), 0);
  EXPECT_EQ(w.basis->GetBasisTransform(0, result), 0);
  EXPECT_EQ(w.errors->Count, 5);
  EXPECT_NE(w.errors->Last.find("no basis"), std::string::npos) << w.errors->Last;

  ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(30, 1, 0, 0).Get()), 1);
  ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(30, 0, 1, 0).Get()), 1);
  const vtkMTimeType before = w.basis->GetMTime();
  int errors = w.errors->Count;
  auto refused = [&](int returned, const char* fragment) {
    EXPECT_EQ(returned, 0) << fragment;
    EXPECT_EQ(w.errors->Count, ++errors) << fragment;
    EXPECT_NE(w.errors->Last.find(fragment), std::string::npos)
      << "wanted \"" << fragment << "\" in: " << w.errors->Last;
  };
  refused(w.basis->AddBasisTransform(static_cast<vtkMatrix4x4*>(nullptr)), "null matrix");
  refused(w.basis->AddBasisTransform(static_cast<vtkLinearTransform*>(nullptr)), "null transform");
  vtkNew<vtkMatrix4x4> bad;
  bad->SetElement(1, 1, nan);
  refused(w.basis->AddBasisTransform(bad), "NaN");
  bad->Identity();
  bad->SetElement(3, 0, 0.5);
  refused(w.basis->AddBasisTransform(bad), "bottom row");
  bad->Identity();
  bad->SetElement(2, 2, -1.0);
  refused(w.basis->AddBasisTransform(bad), "determinant");
  bad->SetElement(2, 2, 0.0);
  refused(w.basis->AddBasisTransform(bad), "singular");
  EXPECT_EQ(w.basis->GetMTime(), before);
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 2);

  refused(w.basis->Factor(nullptr, x), "null transform");
  refused(w.basis->Factor(probe, nullptr), "null coefficient array");
  bad->Identity();
  bad->SetElement(0, 0, nan);
  refused(w.basis->Factor(bad, x), "NaN");
  refused(w.basis->Project(bad, result), "NaN");
  EXPECT_EQ(result->GetElement(0, 3), 7.0);

  refused(w.basis->Reconstruct(x, result), "0 x 1 coefficients for a basis of 2");
  x->SetNumberOfTuples(2);
  x->SetValue(0, 0.5);
  x->SetValue(1, nan);
  refused(w.basis->Reconstruct(x, result), "NaN");
  EXPECT_EQ(result->GetElement(0, 3), 7.0);
  refused(w.basis->GetBasisTransform(2, result), "index 2 is outside [0, 2)");
  refused(w.basis->GetBasisTransform(-1, result), "index -1");
  refused(w.basis->SetParametrisation(7), "unknown parametrisation");
  refused(w.basis->SetRankTolerance(1.0), "outside [0, 1)");
  refused(w.basis->SetRankTolerance(nan), "outside [0, 1)");

  // At most 12 basis transforms.
  lct_test::RandomTransforms random(22);
  for (int i = 2; i < 12; ++i)
  {
    ASSERT_EQ(
      w.basis->AddBasisTransform(matrixOf(random.Affine(lct_test::TransformClass::GeneralAffine))),
      1);
  }
  refused(w.basis->AddBasisTransform(rotateWXYZ(10, 0, 0, 1).Get()), "already has 12");
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 12);
  // Coefficients whose transform overflows.
  x->SetNumberOfTuples(12);
  x->FillValue(1e300);
  refused(w.basis->Reconstruct(x, result), "out of the range");
  EXPECT_EQ(result->GetElement(0, 3), 7.0);

  // MatrixLog cannot take a half turn with non-uniform scale: the switch is refused.
  w.basis->RemoveAllBasisTransforms();
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 0);
  vtkNew<vtkTransform> halfTurn;
  halfTurn->RotateZ(180.0);
  halfTurn->Scale(1.0, 2.0, 1.0);
  ASSERT_EQ(w.basis->AddBasisTransform(halfTurn.Get()), 1);
  refused(w.basis->SetParametrisationToMatrixLog(), "negative real eigenvalue");
  EXPECT_EQ(w.basis->GetParametrisation(), vtkTransformBasisLCT::POLAR);

  // Examples: a null, empty or mixed collection, and examples spanning nothing.
  refused(w.basis->SetBasisFromExamples(nullptr, 1), "null collection");
  vtkNew<vtkCollection> examples;
  refused(w.basis->SetBasisFromExamples(examples, 1), "no examples");
  examples->AddItem(rotateWXYZ(20, 1, 0, 0).Get());
  examples->AddItem(x.Get());
  refused(w.basis->SetBasisFromExamples(examples, 1), "item 1 is vtkDoubleArray");
  examples->RemoveAllItems();
  examples->AddItem(rotateWXYZ(20, 1, 0, 0).Get());
  examples->AddItem(rotateWXYZ(20, 1, 0, 0).Get());
  refused(w.basis->SetBasisFromExamples(examples, 1), "all equal");
  EXPECT_EQ(w.basis->GetNumberOfBasisTransforms(), 1); // still the half-turn basis
}

TEST(vtkTransformBasisLCT, ParametrisationSwitchReanalyses)
{
  Watched w;
  ASSERT_EQ(w.basis->AddBasisTransform(rotateWXYZ(30, 1, 0, 0).Get()), 1);
  vtkNew<vtkTransform> scaled;
  scaled->Scale(2.0, 1.0, 1.0);
  ASSERT_EQ(w.basis->AddBasisTransform(scaled.Get()), 1);
  ASSERT_EQ(w.basis->SetParametrisationToMatrixLog(), 1);
  EXPECT_STREQ(w.basis->GetParametrisationAsString(), "MatrixLog");
  EXPECT_EQ(w.basis->GetRank(), 2);
  vtkNew<vtkTransform> t;
  t->RotateX(15.0);
  t->Scale(std::sqrt(2.0), 1.0, 1.0);
  vtkNew<vtkDoubleArray> x;
  ASSERT_EQ(w.basis->Factor(t->GetMatrix(), x), 1);
  EXPECT_NEAR(x->GetValue(0), 0.5, 1e-12);
  EXPECT_NEAR(x->GetValue(1), 0.5, 1e-12);
  EXPECT_EQ(w.errors->Count, 0);
}
