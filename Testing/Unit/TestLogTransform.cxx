// vtkLogTransform as VTK uses it: set/get, the LCT operations, VTK's transform protocol
// (GetInverse, DeepCopy, MakeTransform, Concatenate, MTime) and every bad input.
#include "vtkLogTransform.h"

#include "lct/Combination.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"

#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "vtkCollection.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
using lct_test::ErrorCounter;
using lct_test::fromVtk;
using lct_test::toVtk;

Eigen::Matrix4d randomAffine(int seed)
{
  lct_test::RandomTransforms random(seed);
  return random.Affine(lct_test::TransformClass::GeneralAffine);
}

struct Watched
{
  vtkNew<vtkLogTransform> transform;
  vtkNew<ErrorCounter> errors;
  Watched() { transform->AddObserver(vtkCommand::ErrorEvent, errors); }
};
} // namespace

TEST(vtkLogTransform, DefaultIsPolarIdentity)
{
  vtkNew<vtkLogTransform> t;
  EXPECT_EQ(t->GetParametrisation(), vtkLogTransform::POLAR);
  EXPECT_STREQ(t->GetParametrisationAsString(), "Polar");
  EXPECT_TRUE(fromVtk(t->GetMatrix()).isIdentity(0.0));
}

TEST(vtkLogTransform, ReproducesTheMatrixItWasSetFrom)
{
  for (int p : { vtkLogTransform::POLAR, vtkLogTransform::MATRIX_LOG })
  {
    for (int seed = 0; seed < 200; ++seed)
    {
      const Eigen::Matrix4d m = randomAffine(seed);
      Watched w;
      ASSERT_EQ(w.transform->SetParametrisation(p), 1);
      vtkNew<vtkMatrix4x4> vm;
      toVtk(m, vm);
      if (!w.transform->SetMatrix(vm))
      {
        // Only MatrixLog may refuse, and then with a message.
        ASSERT_EQ(p, vtkLogTransform::MATRIX_LOG);
        ASSERT_EQ(w.errors->Count, 1);
        continue;
      }
      EXPECT_LT(lct_test::blockError(fromVtk(w.transform->GetMatrix()), m),
        p == vtkLogTransform::POLAR ? 1e-13 : 5e-12);
      double point[3] = { 1.0, -2.0, 0.5 };
      double out[3];
      w.transform->TransformPoint(point, out);
      const Eigen::Vector3d expected = (m * Eigen::Vector4d(1.0, -2.0, 0.5, 1.0)).head<3>();
      EXPECT_LT(
        (Eigen::Vector3d(out[0], out[1], out[2]) - expected).norm(), 1e-12 * (1 + expected.norm()));
    }
  }
}

TEST(vtkLogTransform, ScaleAddInterpolateAndLinearCombination)
{
  vtkNew<vtkTransform> source;
  source->Translate(1, 2, 3);
  source->RotateZ(40);
  source->Scale(2, 1, 1);
  vtkNew<vtkLogTransform> a;
  ASSERT_EQ(a->SetTransform(source), 1);

  // 2 (.) A = A (+) A; (1/2)(.)A (+) (1/2)(.)A = A.
  vtkNew<vtkLogTransform> twice;
  twice->DeepCopy(a);
  ASSERT_EQ(twice->Scale(2.0), 1);
  vtkNew<vtkLogTransform> sum;
  sum->DeepCopy(a);
  ASSERT_EQ(sum->Add(a), 1);
  EXPECT_LT(lct_test::blockError(fromVtk(twice->GetMatrix()), fromVtk(sum->GetMatrix())), 1e-14);

  vtkNew<vtkLogTransform> identity;
  vtkNew<vtkLogTransform> mid;
  ASSERT_EQ(mid->Interpolate(identity, a, 1.0), 1);
  EXPECT_LT(lct_test::blockError(fromVtk(mid->GetMatrix()), fromVtk(source->GetMatrix())), 1e-14);

  vtkNew<vtkCollection> items;
  items->AddItem(a);
  items->AddItem(twice);
  vtkNew<vtkDoubleArray> weights;
  weights->InsertNextValue(1.0);
  weights->InsertNextValue(-0.5);
  vtkNew<vtkLogTransform> combination;
  vtkNew<ErrorCounter> errors;
  combination->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(vtkLogTransform::LinearCombination(items, weights, combination), 1) << errors->Last;
  // 1 (.) A (+) (-1/2)(.)(2 (.) A) = identity.
  EXPECT_LT(
    lct_test::blockError(fromVtk(combination->GetMatrix()), Eigen::Matrix4d::Identity()), 1e-14);

  // Mixed parametrisations: inputs are converted to the result's, from their matrices. (The
  // polar 2 (.) A is not the MatrixLog 2 (.) A, so the result is not the identity.)
  vtkNew<vtkLogTransform> matrixLog;
  matrixLog->SetParametrisationToMatrixLog();
  ASSERT_EQ(vtkLogTransform::LinearCombination(items, weights, matrixLog), 1);
  const Eigen::Matrix4d keys[2] = { fromVtk(a->GetMatrix()), fromVtk(twice->GetMatrix()) };
  const double w[2] = { 1.0, -0.5 };
  const auto expected = lct::combine(w, keys, 2, lct::Parametrisation::MatrixLog);
  ASSERT_TRUE(expected.ok());
  EXPECT_LT(lct_test::blockError(fromVtk(matrixLog->GetMatrix()), expected.value), 1e-14);
}

TEST(vtkLogTransform, InverseGetInverseAndConcatenate)
{
  for (int p : { vtkLogTransform::POLAR, vtkLogTransform::MATRIX_LOG })
  {
    vtkNew<vtkLogTransform> t;
    t->SetParametrisation(p);
    vtkNew<vtkMatrix4x4> vm;
    toVtk(randomAffine(7), vm);
    ASSERT_EQ(t->SetMatrix(vm), 1);
    const Eigen::Matrix4d m = fromVtk(t->GetMatrix());

    vtkLinearTransform* inverse = t->GetLinearInverse();
    EXPECT_LT((fromVtk(inverse->GetMatrix()) * m - Eigen::Matrix4d::Identity()).norm(), 1e-13);
    // The inverse follows later changes of t.
    t->Scale(0.5);
    const Eigen::Matrix4d half = fromVtk(t->GetMatrix());
    EXPECT_LT((fromVtk(inverse->GetMatrix()) * half - Eigen::Matrix4d::Identity()).norm(), 1e-13);

    vtkNew<vtkTransform> chain;
    chain->Concatenate(t);
    chain->Concatenate(inverse);
    EXPECT_LT((fromVtk(chain->GetMatrix()) - Eigen::Matrix4d::Identity()).norm(), 1e-13);

    t->Inverse();
    EXPECT_LT((fromVtk(t->GetMatrix()) * half - Eigen::Matrix4d::Identity()).norm(), 1e-13);

    vtkAbstractTransform* made = t->MakeTransform();
    EXPECT_TRUE(vtkLogTransform::SafeDownCast(made) != nullptr);
    made->Delete();
  }
}

TEST(vtkLogTransform, InverseKeepsTheWindingOfASpin)
{
  vtkNew<vtkLogTransform> t;
  const double spin[12] = { 0, 0, 0, 0, 0, 3.0 * lct_test::kPi, 0, 0, 0, 0, 0, 0 };
  ASSERT_EQ(t->SetLogCoordinates(spin), 1);
  t->Inverse();
  double c[12];
  t->GetLogCoordinates(c);
  EXPECT_NEAR(c[5], -3.0 * lct_test::kPi, 1e-12);
}

TEST(vtkLogTransform, ReferenceKeepsTheRotationBranch)
{
  vtkNew<vtkLogTransform> previous;
  vtkNew<vtkLogTransform> current;
  for (int k = 1; k <= 6; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(170.0 * k);
    ASSERT_EQ(current->SetMatrix(key->GetMatrix(), previous), 1);
    double c[12];
    current->GetLogCoordinates(c);
    EXPECT_NEAR(c[5], 170.0 * k * lct_test::kPi / 180.0, 1e-12);
    previous->DeepCopy(current);
  }
}

TEST(vtkLogTransform, DeepCopyCopiesStateAndParametrisation)
{
  vtkNew<vtkLogTransform> a;
  a->SetParametrisationToMatrixLog();
  vtkNew<vtkMatrix4x4> vm;
  toVtk(randomAffine(3), vm);
  ASSERT_EQ(a->SetMatrix(vm), 1);
  vtkNew<vtkLogTransform> b;
  b->DeepCopy(a);
  EXPECT_EQ(b->GetParametrisation(), vtkLogTransform::MATRIX_LOG);
  double ca[12], cb[12];
  a->GetLogCoordinates(ca);
  b->GetLogCoordinates(cb);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(ca[i], cb[i]);
  }
  EXPECT_EQ(fromVtk(a->GetMatrix()), fromVtk(b->GetMatrix()));
}

TEST(vtkLogTransform, ModifiedOnEveryChangeAndOnlyThen)
{
  vtkNew<vtkLogTransform> t;
  vtkMTimeType before = t->GetMTime();
  t->Scale(2.0);
  EXPECT_GT(t->GetMTime(), before);
  before = t->GetMTime();
  const double c[12] = { 1, 0, 0, 0, 0, 0.5, 0, 0, 0, 0, 0, 0 };
  t->SetLogCoordinates(c);
  EXPECT_GT(t->GetMTime(), before);
  before = t->GetMTime();
  t->SetParametrisationToMatrixLog();
  EXPECT_GT(t->GetMTime(), before);
  before = t->GetMTime();
  t->Identity();
  EXPECT_GT(t->GetMTime(), before);
}

TEST(vtkLogTransform, BadInputIsReportedAndLeavesTheStateUnchanged)
{
  Watched w;
  vtkNew<vtkTransform> good;
  good->Translate(1, 2, 3);
  good->RotateX(30);
  ASSERT_EQ(w.transform->SetTransform(good), 1);
  double saved[12];
  w.transform->GetLogCoordinates(saved);
  const Eigen::Matrix4d savedMatrix = fromVtk(w.transform->GetMatrix());
  const vtkMTimeType savedTime = w.transform->GetMTime();

  auto expectUnchanged = [&](const char* what, int expectedErrors) {
    double now[12];
    w.transform->GetLogCoordinates(now);
    for (int i = 0; i < 12; ++i)
    {
      EXPECT_EQ(now[i], saved[i]) << what;
    }
    EXPECT_EQ(fromVtk(w.transform->GetMatrix()), savedMatrix) << what;
    EXPECT_EQ(w.transform->GetMTime(), savedTime) << what;
    EXPECT_EQ(w.errors->Count, expectedErrors) << what;
  };

  int expected = 0;
  vtkNew<vtkMatrix4x4> bad;

  bad->Identity();
  bad->SetElement(1, 2, std::nan(""));
  EXPECT_EQ(w.transform->SetMatrix(bad), 0);
  expectUnchanged("NaN", ++expected);
  EXPECT_NE(w.errors->Last.find("NaN"), std::string::npos) << w.errors->Last;

  bad->Identity();
  bad->SetElement(0, 3, std::numeric_limits<double>::infinity());
  EXPECT_EQ(w.transform->SetMatrix(bad), 0);
  expectUnchanged("Inf", ++expected);

  bad->Identity();
  bad->SetElement(3, 0, 0.1);
  EXPECT_EQ(w.transform->SetMatrix(bad), 0);
  expectUnchanged("projective", ++expected);
  EXPECT_NE(w.errors->Last.find("bottom row"), std::string::npos) << w.errors->Last;

  bad->Identity();
  bad->SetElement(2, 2, -1.0);
  EXPECT_EQ(w.transform->SetMatrix(bad), 0);
  expectUnchanged("reflection", ++expected);
  EXPECT_NE(w.errors->Last.find("determinant"), std::string::npos) << w.errors->Last;

  bad->Identity();
  bad->SetElement(2, 2, 0.0);
  EXPECT_EQ(w.transform->SetMatrix(bad), 0);
  expectUnchanged("singular", ++expected);

  EXPECT_EQ(w.transform->SetMatrix(static_cast<vtkMatrix4x4*>(nullptr)), 0);
  expectUnchanged("null matrix", ++expected);
  EXPECT_EQ(w.transform->SetTransform(nullptr), 0);
  expectUnchanged("null transform", ++expected);

  const double nanCoordinates[12] = { 0, 0, 0, 0, 0, 0, std::nan(""), 0, 0, 0, 0, 0 };
  EXPECT_EQ(w.transform->SetLogCoordinates(nanCoordinates), 0);
  expectUnchanged("NaN coordinates", ++expected);
  const double hugeCoordinates[12] = { 0, 0, 0, 0, 0, 0, 1000, 0, 0, 0, 0, 0 };
  EXPECT_EQ(w.transform->SetLogCoordinates(hugeCoordinates), 0);
  expectUnchanged("overflow", ++expected);
  EXPECT_EQ(w.transform->Scale(std::nan("")), 0);
  expectUnchanged("NaN factor", ++expected);
  EXPECT_EQ(w.transform->Scale(1e300), 0);
  expectUnchanged("overflowing factor", ++expected);
  EXPECT_EQ(w.transform->Add(nullptr), 0);
  expectUnchanged("null addend", ++expected);
  EXPECT_EQ(w.transform->Interpolate(nullptr, w.transform, 0.5), 0);
  expectUnchanged("null interpolant", ++expected);
  EXPECT_EQ(w.transform->SetParametrisation(7), 0);
  expectUnchanged("unknown parametrisation", ++expected);

  // MatrixLog mode: a half turn with non-uniform scale has no real logarithm.
  ASSERT_EQ(w.transform->SetParametrisationToMatrixLog(), 1);
  w.transform->GetLogCoordinates(saved);
  vtkNew<vtkMatrix4x4> halfTurn;
  halfTurn->Identity();
  halfTurn->SetElement(0, 0, -2.0);
  halfTurn->SetElement(1, 1, -1.0);
  EXPECT_EQ(w.transform->SetMatrix(halfTurn), 0);
  EXPECT_NE(w.errors->Last.find("no real matrix logarithm"), std::string::npos) << w.errors->Last;
  EXPECT_EQ(w.errors->Count, ++expected);

  // ... and a polar transform holding it cannot switch to MatrixLog.
  vtkNew<vtkLogTransform> polar;
  vtkNew<ErrorCounter> polarErrors;
  polar->AddObserver(vtkCommand::ErrorEvent, polarErrors);
  ASSERT_EQ(polar->SetMatrix(halfTurn), 1);
  EXPECT_EQ(polar->SetParametrisationToMatrixLog(), 0);
  EXPECT_EQ(polar->GetParametrisation(), vtkLogTransform::POLAR);
  EXPECT_EQ(polarErrors->Count, 1);

  // LinearCombination: count mismatch and wrong item types.
  vtkNew<vtkCollection> items;
  items->AddItem(polar);
  vtkNew<vtkDoubleArray> weights;
  EXPECT_EQ(vtkLogTransform::LinearCombination(items, weights, polar), 0);
  EXPECT_EQ(polarErrors->Count, 2);
  items->AddItem(halfTurn);
  weights->InsertNextValue(1.0);
  weights->InsertNextValue(1.0);
  EXPECT_EQ(vtkLogTransform::LinearCombination(items, weights, polar), 0);
  EXPECT_EQ(polarErrors->Count, 3);
}

// Audit (session 28): diag(1e-110, 1, 1e110), of determinant 1, was refused as "singular (a zero
// determinant)" in both parametrisations (its determinant underflows at unit scale, and MatrixLog
// called it out of its magnitude range); the cause is its condition, 1e220. And 3e307 I, whose
// inverse 3.3e-308 I is normal, was refused as not invertible (a Frobenius-norm test), while
// Inverse() of 3.3e-308 I held it.
TEST(vtkLogTransform, SpreadScalesAreIllConditionedNotSingularAndHugeScalesInvert)
{
  for (const int parametrisation : { vtkLogTransform::POLAR, vtkLogTransform::MATRIX_LOG })
  {
    for (const Eigen::Vector3d& d :
      { Eigen::Vector3d(1e-110, 1, 1e110), Eigen::Vector3d(1, 1, 1e200) })
    {
      vtkNew<vtkLogTransform> t;
      vtkNew<lct_test::ErrorCounter> errors;
      t->AddObserver(vtkCommand::ErrorEvent, errors);
      ASSERT_EQ(t->SetParametrisation(parametrisation), 1);
      vtkNew<vtkMatrix4x4> m;
      for (int i = 0; i < 3; ++i)
      {
        m->SetElement(i, i, d[i]);
      }
      EXPECT_EQ(t->SetMatrix(m), 0);
      EXPECT_NE(errors->Last.find("too ill-conditioned"), std::string::npos) << errors->Last;
      EXPECT_EQ(errors->Last.find("zero determinant"), std::string::npos) << errors->Last;
    }
    EXPECT_EQ(lct::determinantSign(Eigen::Vector3d(1e-110, 1, 1e110).asDiagonal()), 1);
  }
  vtkNew<vtkLogTransform> huge;
  vtkNew<vtkMatrix4x4> m;
  for (int i = 0; i < 3; ++i)
  {
    m->SetElement(i, i, 3e307);
  }
  ASSERT_EQ(huge->SetMatrix(m), 1);
  huge->Inverse();
  EXPECT_NEAR(huge->GetMatrix()->GetElement(0, 0) * 3e307, 1.0, 1e-12);
  vtkNew<vtkLogTransform> tiny;
  for (int i = 0; i < 3; ++i)
  {
    m->SetElement(i, i, 1.0 / 3e307);
  }
  ASSERT_EQ(tiny->SetMatrix(m), 1);
  ASSERT_EQ(tiny->Scale(-1.0), 1);
  EXPECT_NEAR(tiny->GetMatrix()->GetElement(0, 0) / 3e307, 1.0, 1e-12);
}

// Audit (session 28): Interpolate weighted the operands (1 - t, t), which cancel for a large t:
// a 30-degree turn interpolated with itself read 28.6 degrees at t = 1e15 and the identity from
// 1e16 on, with status 1. It is log a + t (log b - log a) now.
TEST(vtkLogTransform, InterpolateAtALargeParameterDoesNotCancel)
{
  vtkNew<vtkTransform> turn;
  turn->RotateZ(30.0);
  vtkNew<vtkLogTransform> a, b, out;
  ASSERT_EQ(a->SetMatrix(turn->GetMatrix()), 1);
  ASSERT_EQ(b->SetMatrix(turn->GetMatrix()), 1);
  for (const double t : { 0.5, 1e15, 1e16, 1e308, -1e308 })
  {
    ASSERT_EQ(out->Interpolate(a, b, t), 1) << t;
    EXPECT_NEAR(out->GetMatrix()->GetElement(1, 0), 0.5, 1e-15) << t;
  }
}

// Audit (session 29): the Polar inverse's translation came from Eigen's cofactor inverse of the
// map, whose determinant cancels at high condition (error ~ eps cond^2): at condition 1e12
// GetInverse() moved the origin by 160 % of the exact -A^-1 l, at 1e10 by up to 7e-4, with
// status 1. The oracle is -adj(A) l / det(A) of GetMatrix() in quadruple precision, where
// a product of two doubles is exact; the translation must match it to 1e-13.
TEST(vtkLogTransform, InverseOfAnIllConditionedMapMovesTheOriginRight)
{
  using Quad = __float128;
  lct_test::RandomTransforms random(2909);
  for (const double condition : { 1e4, 1e8, 1e10, 1e12 })
  {
    for (int trial = 0; trial < 20; ++trial)
    {
      const Eigen::Matrix3d v = random.Rotation();
      const Eigen::Vector3d s(
        std::sqrt(condition), random.LogUniform(0.5, 2.0), 1.0 / std::sqrt(condition));
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m.topLeftCorner<3, 3>() = random.Rotation() * v * s.asDiagonal() * v.transpose();
      m.topRightCorner<3, 1>() =
        Eigen::Vector3d(random.Normal(), random.Normal(), random.Normal()) * 10.0;
      vtkNew<vtkMatrix4x4> key;
      toVtk(m, key);
      vtkNew<vtkLogTransform> t;
      ASSERT_EQ(t->SetMatrix(key), 1) << condition;
      const Eigen::Matrix4d inverse = fromVtk(t->GetLinearInverse()->GetMatrix());
      m = fromVtk(t->GetMatrix()); // exp(log M): the map the transform applies

      Quad a[3][3], l[3], adjugate[3][3];
      for (int i = 0; i < 3; ++i)
      {
        l[i] = m(i, 3);
        for (int j = 0; j < 3; ++j)
        {
          a[i][j] = m(i, j);
        }
      }
      for (int i = 0; i < 3; ++i)
      {
        for (int j = 0; j < 3; ++j)
        {
          const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
          adjugate[i][j] = a[r0][c0] * a[r1][c1] - a[r0][c1] * a[r1][c0];
        }
      }
      const Quad det =
        a[0][0] * adjugate[0][0] + a[0][1] * adjugate[1][0] + a[0][2] * adjugate[2][0];
      double error = 0.0, size = 0.0;
      for (int i = 0; i < 3; ++i)
      {
        const Quad exact =
          -(adjugate[i][0] * l[0] + adjugate[i][1] * l[1] + adjugate[i][2] * l[2]) / det;
        error += std::pow(static_cast<double>(static_cast<Quad>(inverse(i, 3)) - exact), 2);
        size += std::pow(static_cast<double>(exact), 2);
      }
      EXPECT_LE(std::sqrt(error / size), 1e-13) << "condition " << condition << ", trial " << trial;
    }
  }
}

// Audit (session 29): MatrixLog coordinates whose exp is representable but beyond the
// parametrisation's 1e+-135 (e^320 I = 1e139 I; Polar takes it) were refused as "out of the
// range of double precision". The message names MatrixLog's range and the way out.
TEST(vtkLogTransform, MatrixLogCoordinatesBeyondItsRangeSayWhyAndPointToPolar)
{
  double c[12] = { 0, 0, 0, 0, 0, 0, 320, 320, 320, 0, 0, 0 };
  vtkNew<vtkLogTransform> polar;
  EXPECT_EQ(polar->SetLogCoordinates(c), 1);
  Watched w;
  ASSERT_EQ(w.transform->SetParametrisation(vtkLogTransform::MATRIX_LOG), 1);
  EXPECT_EQ(w.transform->SetLogCoordinates(c), 0);
  EXPECT_NE(w.errors->Last.find("1e-135 .. 1e135"), std::string::npos) << w.errors->Last;
  EXPECT_NE(w.errors->Last.find("SetParametrisationToPolar()"), std::string::npos)
    << w.errors->Last;
  EXPECT_EQ(w.errors->Last.find("range of double precision"), std::string::npos) << w.errors->Last;
  // A result that does overflow stays out of double's range.
  double huge[12] = { 0, 0, 0, 0, 0, 0, 800, 800, 800, 0, 0, 0 };
  EXPECT_EQ(w.transform->SetLogCoordinates(huge), 0);
  EXPECT_NE(w.errors->Last.find("range of double precision"), std::string::npos) << w.errors->Last;
}

// Audit (session 29): a change made to GetMatrix() from outside (SetElement) was used by
// TransformPoint while the log coordinates, the inverse and every operation kept the old map. The
// next Update puts the state's matrix back, with a warning.
TEST(vtkLogTransform, AMatrixChangedFromOutsideIsPutBackWithAWarning)
{
  vtkNew<vtkTransform> turn;
  turn->Translate(1, 2, 3);
  turn->RotateZ(30);
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> warnings;
  t->AddObserver(vtkCommand::WarningEvent, warnings);
  ASSERT_EQ(t->SetMatrix(turn->GetMatrix()), 1);
  double p[3];
  t->TransformPoint(Eigen::Vector3d::Zero().eval().data(), p);
  EXPECT_EQ(warnings->Count, 0);
  t->GetMatrix()->SetElement(0, 3, std::numeric_limits<double>::quiet_NaN());
  t->TransformPoint(Eigen::Vector3d::Zero().eval().data(), p);
  EXPECT_EQ(p[0], 1.0);
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_NE(warnings->Last.find("use SetMatrix"), std::string::npos) << warnings->Last;
  // Its own updates, DeepCopy and the inverse raise nothing.
  vtkNew<vtkLogTransform> copy;
  copy->AddObserver(vtkCommand::WarningEvent, warnings);
  copy->DeepCopy(t);
  copy->Update();
  t->Inverse();
  t->Update();
  t->GetLinearInverse()->Update();
  ASSERT_EQ(t->Scale(0.5), 1);
  t->Update();
  EXPECT_EQ(warnings->Count, 1) << warnings->Last;
  // Audit (session 30): editing GetMatrix() and then setting it, as the warning advises (or any
  // other new state), warned all the same: the edited matrix was still newer than the last
  // write, and exp(log M) differs from M in the last bits. A new state supersedes the edit.
  turn->Scale(1.3, 0.7, 2.1);
  ASSERT_EQ(t->SetMatrix(turn->GetMatrix()), 1);
  vtkMatrix4x4* held = t->GetMatrix(); // GetMatrix() itself runs an Update
  held->SetElement(0, 3, 5.0);
  ASSERT_EQ(t->SetMatrix(held), 1);
  t->Update();
  EXPECT_NEAR(t->GetMatrix()->GetElement(0, 3), 5.0, 1e-14);
  held->SetElement(0, 3, 7.0);
  const double coordinates[12] = { 1, 2, 3, 0, 0, 0.5, 0, 0, 0, 0, 0, 0 };
  ASSERT_EQ(t->SetLogCoordinates(coordinates), 1);
  t->Update();
  EXPECT_EQ(t->GetMatrix()->GetElement(2, 3), 3.0);
  EXPECT_EQ(warnings->Count, 1) << warnings->Last;
}

// Audit (session 30): Interpolate formed log a + t (log b - log a): log b - log a of translations
// +-1e308 overflowed, so even t = 0 and t = 1 were refused ("overflows"), and at t = 1 the
// digits of |log a| were lost (a key wound 1e8 radians gave b back 3e-9 off). Within [0, 1] the
// result is exact at the ends and finite for any finite keys.
TEST(vtkLogTransform, InterpolateGivesTheKeysExactlyAtItsEndsAndDoesNotOverflowBetween)
{
  vtkNew<vtkLogTransform> a, b, out;
  const double far[16] = { 1, 0, 0, 1e308, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  const double back[16] = { 1, 0, 0, -1e308, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
  ASSERT_EQ(a->SetMatrix(far), 1);
  ASSERT_EQ(b->SetMatrix(back), 1);
  for (const auto& [t, x] : { std::pair{ 0.0, 1e308 }, { 0.5, 0.0 }, { 1.0, -1e308 } })
  {
    ASSERT_EQ(out->Interpolate(a, b, t), 1) << t;
    EXPECT_EQ(out->GetMatrix()->GetElement(0, 3), x) << t;
  }
  const double wound[12] = { 0, 0, 0, 6e7, 0, 8e7, 0, 0, 0, 0, 0, 0 };
  const double key[12] = { 1, 2, 3, 0.1, 0.2, -0.05, 0.01, 0.02, 0, 0, 0, 0 };
  ASSERT_EQ(a->SetLogCoordinates(wound), 1);
  ASSERT_EQ(b->SetLogCoordinates(key), 1);
  double c[12];
  ASSERT_EQ(out->Interpolate(a, b, 1.0), 1);
  out->GetLogCoordinates(c);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(c[i], key[i]) << i;
  }
  ASSERT_EQ(out->Interpolate(a, b, 0.0), 1);
  out->GetLogCoordinates(c);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(c[i], wound[i]) << i;
  }
  // Extrapolation beyond the double range is still refused.
  vtkNew<ErrorCounter> errors;
  out->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(a->SetMatrix(far), 1);
  ASSERT_EQ(b->SetMatrix(back), 1);
  EXPECT_EQ(out->Interpolate(a, b, 2.0), 0);
  EXPECT_NE(errors->Last.find("overflow"), std::string::npos) << errors->Last;
}

// Audit (session 30): normals came from vtkLinearTransform, which inverts the matrix with
// vtkMatrix4x4::Invert: its determinant overflowed for a similarity of scale 1e103 (normals
// (0, 0, 0), NaN through vtkTransformPolyDataFilter) and underflowed for 1e-108, where Invert
// leaves the matrix as it is and every normal turned the wrong way, all with SetMatrix status 1.
TEST(vtkLogTransform, NormalsAreRightAtEveryScaleItAccepts)
{
  const Eigen::Matrix3d turn =
    Eigen::AngleAxisd(1.0, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
  const Eigen::Vector3d normal = Eigen::Vector3d(0.6, 0.8, 0.0);
  for (const auto& stretch :
    { Eigen::Vector3d(1e103, 1e103, 1e103), Eigen::Vector3d(1e-108, 1e-108, 1e-108),
      Eigen::Vector3d(1e200, 1e200, 1e200), Eigen::Vector3d(1e-200, 1e-200, 1e-200),
      Eigen::Vector3d(2e100, 1e100, 3e100), Eigen::Vector3d(2.0, 3.0, 0.5) })
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = turn * stretch.asDiagonal();
    m(0, 3) = 5.0;
    // A^-T n = R S^-1 n: the turn of the normal scaled the other way, then normalised.
    const Eigen::Vector3d scaled = stretch.cwiseInverse().cwiseProduct(normal);
    const Eigen::Vector3d expected = turn * (scaled / scaled.cwiseAbs().maxCoeff()).normalized();
    vtkNew<vtkLogTransform> t;
    vtkNew<vtkMatrix4x4> matrix;
    toVtk(m, matrix);
    ASSERT_EQ(t->SetMatrix(matrix), 1) << stretch.transpose();
    double out[3];
    const double in[3] = { normal[0], normal[1], normal[2] };
    t->TransformNormal(in, out);
    EXPECT_LE((Eigen::Vector3d(out[0], out[1], out[2]) - expected).norm(), 1e-13)
      << stretch.transpose();
    float outFloat[3];
    const float inFloat[3] = { 0.6f, 0.8f, 0.0f };
    t->TransformNormal(inFloat, outFloat);
    EXPECT_LE((Eigen::Vector3d(outFloat[0], outFloat[1], outFloat[2]) - expected).norm(), 1e-6)
      << stretch.transpose();
    // Arrays, as vtkTransformPolyDataFilter transforms them (appended to what is there).
    vtkNew<vtkDoubleArray> normals, transformed;
    normals->SetNumberOfComponents(3);
    normals->InsertNextTuple(in);
    transformed->SetNumberOfComponents(3);
    transformed->InsertNextTuple3(7, 7, 7);
    t->TransformNormals(normals, transformed);
    ASSERT_EQ(transformed->GetNumberOfTuples(), 2);
    EXPECT_EQ(transformed->GetTuple3(0)[0], 7.0);
    const double* tuple = transformed->GetTuple3(1);
    EXPECT_LE((Eigen::Vector3d(tuple[0], tuple[1], tuple[2]) - expected).norm(), 1e-13);
    // The inverse map turns normals back.
    t->Inverse();
    t->TransformNormal(out, out);
    EXPECT_LE((Eigen::Vector3d(out[0], out[1], out[2]) - normal).norm(), 1e-13)
      << stretch.transpose();
  }
}
