// vtkTransformInterpolatorLCT: keys reproduced (where vtkTransformInterpolator is not), subgroup
// closure, continuity, rotation branches, VTK semantics (clamping, replacement, MTime) and every
// bad input.
#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/SO3.h"

#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "vtkActor.h"
#include "vtkCommand.h"
#include "vtkLogTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolator.h"

#include <Eigen/SVD>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace
{
using lct_test::ErrorCounter;
using lct_test::fromVtk;
using lct_test::toVtk;

/// Keys with shear and non-uniform scale along rotated axes, turning well over 180 degrees
/// overall, at non-uniform times.
std::vector<std::pair<double, Eigen::Matrix4d>> shearedKeys(int seed, int n)
{
  lct_test::RandomTransforms random(seed);
  std::vector<std::pair<double, Eigen::Matrix4d>> keys;
  double t = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const Eigen::Vector3d s(
      random.LogUniform(0.5, 2.0), random.LogUniform(0.5, 2.0), random.LogUniform(0.5, 2.0));
    const Eigen::Matrix3d linear =
      lct::expSO3(Eigen::Vector3d(0, 0, 1.1 * i) + 0.2 * random.UnitVector()) *
      random.Rotation(0.4) * s.asDiagonal() * random.Rotation(0.4).transpose();
    keys.emplace_back(
      t, lct::makeAffine(linear, random.Translation(lct_test::TransformClass::Rigid)));
    t += random.Uniform(0.5, 2.0);
  }
  return keys;
}

const int kInterpolatingTypes[] = { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR,
  vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
  vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION };
const int kAllTypes[] = { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR,
  vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
  vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE,
  vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION };
} // namespace

TEST(TransformInterpolatorLCT, ReproducesShearedKeysWhereVtkDoesNot)
{
  const auto keys = shearedKeys(1, 6);
  vtkNew<vtkTransformInterpolatorLCT> ours;
  vtkNew<vtkTransformInterpolator> vtk;
  for (const auto& [t, m] : keys)
  {
    vtkNew<vtkMatrix4x4> vm;
    toVtk(m, vm);
    ASSERT_EQ(ours->AddTransform(t, vm), 1);
    vtk->AddTransform(t, vm);
  }
  double worstVtk = 0.0;
  for (int type : kInterpolatingTypes)
  {
    for (int p : { vtkTransformInterpolatorLCT::POLAR, vtkTransformInterpolatorLCT::MATRIX_LOG })
    {
      ours->SetInterpolationType(type);
      if (!ours->SetParametrisation(p))
      {
        continue; // a step without real log: MatrixLog refuses, tested below
      }
      for (const auto& [t, m] : keys)
      {
        vtkNew<vtkMatrix4x4> out;
        ASSERT_EQ(ours->InterpolateTransform(t, out), 1);
        EXPECT_LT(lct_test::blockError(fromVtk(out), m), 1e-12) << "type " << type << " t " << t;
      }
    }
  }
  for (int type : { 0, 1 })
  {
    vtk->SetInterpolationType(type);
    for (const auto& [t, m] : keys)
    {
      vtkNew<vtkTransform> out;
      vtk->InterpolateTransform(t, out);
      worstVtk = std::max(worstVtk, lct_test::blockError(fromVtk(out->GetMatrix()), m));
    }
  }
  // VTK's T R diag(S) split cannot represent the shear: its keys come back wrong.
  EXPECT_GT(worstVtk, 1e-2);
}

TEST(TransformInterpolatorLCT, SplineReproducesRotationKeysThatVtkDefaultSplineMisses)
{
  vtkNew<vtkTransformInterpolatorLCT> ours;
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(30.0 * k);
    ASSERT_EQ(ours->AddTransform(k, key), 1);
  }
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkTransform> out;
    ASSERT_EQ(ours->InterpolateTransform(k, out), 1);
    const double angle =
      std::atan2(out->GetMatrix()->GetElement(1, 0), out->GetMatrix()->GetElement(0, 0));
    EXPECT_NEAR(angle * 180.0 / lct_test::kPi, 30.0 * k, 1e-11);
  }
}

TEST(TransformInterpolatorLCT, RigidAndSimilarityKeysStayInTheirGroup)
{
  lct_test::RandomTransforms random(3);
  for (int type : kAllTypes)
  {
    vtkNew<vtkTransformInterpolatorLCT> rigid;
    vtkNew<vtkTransformInterpolatorLCT> similar;
    rigid->SetInterpolationType(type);
    similar->SetInterpolationType(type);
    for (int k = 0; k < 7; ++k)
    {
      vtkNew<vtkMatrix4x4> r;
      toVtk(random.Affine(lct_test::TransformClass::Rigid), r);
      ASSERT_EQ(rigid->AddTransform(k, r), 1);
      vtkNew<vtkMatrix4x4> s;
      toVtk(random.Affine(lct_test::TransformClass::Similarity), s);
      ASSERT_EQ(similar->AddTransform(k, s), 1);
    }
    for (int i = 0; i <= 600; ++i)
    {
      vtkNew<vtkMatrix4x4> out;
      ASSERT_EQ(rigid->InterpolateTransform(i / 100.0, out), 1);
      const Eigen::Matrix3d r = fromVtk(out).topLeftCorner<3, 3>();
      ASSERT_LT((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 1e-13);
      ASSERT_NEAR(r.determinant(), 1.0, 1e-13);
      ASSERT_EQ(similar->InterpolateTransform(i / 100.0, out), 1);
      const Eigen::Matrix3d s = fromVtk(out).topLeftCorner<3, 3>();
      const Eigen::Matrix3d gram = s.transpose() * s;
      ASSERT_LT((gram / (gram.trace() / 3) - Eigen::Matrix3d::Identity()).norm(), 1e-13);
    }
  }
}

TEST(TransformInterpolatorLCT, InBetweensStayWithinTheKeysStretches)
{
  // Keys stretched along different axes and turned: with convex weights (Linear, BSpline) no
  // in-between may be larger, in any direction, than the largest key. The relative form with the
  // step in the reference's own frame grew a key squashed to 1/10 blended with a turned one to
  // 2.2 times either; random keys of stretch up to e^2.3 to 4.4 times, and between
  // diag(1e-6, 1, 1) and a 2.5 rad turn it refused t = 0.477 .. 0.53 as inaccurate.
  lct_test::RandomTransforms random(27);
  for (int trial = 0; trial < 40; ++trial)
  {
    std::vector<Eigen::Matrix4d> keys;
    double largest = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      const Eigen::Vector3d s(std::exp(random.Uniform(-2.3, 2.3)),
        std::exp(random.Uniform(-2.3, 2.3)), std::exp(random.Uniform(-2.3, 2.3)));
      keys.push_back(lct::makeAffine(
        random.Rotation() * s.asDiagonal() * random.Rotation(), Eigen::Vector3d::Zero()));
      largest = std::max(largest, s.maxCoeff());
    }
    for (const int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR,
           vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE })
    {
      vtkNew<vtkTransformInterpolatorLCT> path;
      path->SetInterpolationType(type);
      vtkNew<vtkMatrix4x4> m;
      for (int k = 0; k < 4; ++k)
      {
        toVtk(keys[k], m);
        ASSERT_EQ(path->AddTransform(k, m), 1);
      }
      for (int i = 0; i <= 60; ++i)
      {
        ASSERT_EQ(path->InterpolateTransform(i / 20.0, m), 1) << trial << " " << i;
        const Eigen::JacobiSVD<Eigen::Matrix3d> svd(fromVtk(m).topLeftCorner<3, 3>());
        EXPECT_LE(svd.singularValues()[0], largest * (1.0 + 1e-12)) << trial << " " << i;
      }
    }
  }
  // The refused band: every t between diag(1e-6, 1, 1) and a 2.5 rad turn.
  vtkNew<vtkTransformInterpolatorLCT> path;
  path->SetInterpolationTypeToLinear();
  vtkNew<vtkMatrix4x4> m;
  toVtk(lct::makeAffine(Eigen::Vector3d(1e-6, 1, 1).asDiagonal(), Eigen::Vector3d::Zero()), m);
  ASSERT_EQ(path->AddTransform(0.0, m), 1);
  toVtk(lct::makeAffine(lct::expSO3(Eigen::Vector3d(0, 0, 2.5)), Eigen::Vector3d::Zero()), m);
  ASSERT_EQ(path->AddTransform(1.0, m), 1);
  for (int i = 0; i <= 1000; ++i)
  {
    ASSERT_EQ(path->InterpolateTransform(i / 1000.0, m), 1) << i;
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(fromVtk(m).topLeftCorner<3, 3>());
    EXPECT_LE(svd.singularValues()[0], 1.0 + 1e-12) << i;
  }
}

TEST(TransformInterpolatorLCT, NoJumpWhereTheReferenceKeyChangesBetweenStretchedKeys)
{
  // Keys R_k diag(100, 1, 0.01) (condition 1e4): the results about the two keys of a segment
  // are blended where their weights cross. The blend took the matrix power of the step between
  // them in the result's own frame, far from normal here; it failed and the curve snapped to
  // one side: a sample step 22 times its neighbours. Now the step is a relative log like every
  // other, and no sample step exceeds 1.5 times the larger of its two neighbours (a smooth curve
  // sampled this finely stays within a few percent; its speed over the window may vary more).
  lct_test::RandomTransforms random(11);
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<vtkMatrix4x4> m;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Matrix3d linear =
      random.Rotation() * Eigen::Vector3d(100.0, 1.0, 0.01).asDiagonal().toDenseMatrix();
    toVtk(lct::makeAffine(linear, Eigen::Vector3d::Zero()), m);
    ASSERT_EQ(path->AddTransform(k, m), 1);
  }
  for (const double middle : { 0.5, 1.5, 2.5 })
  {
    std::vector<double> steps;
    Eigen::Matrix4d previous = Eigen::Matrix4d::Zero();
    for (int i = 0; i <= 400; ++i)
    {
      ASSERT_EQ(path->InterpolateTransform(middle - 0.2 + 0.4 * i / 400, m), 1);
      const Eigen::Matrix4d current = fromVtk(m);
      if (i > 0)
      {
        steps.push_back((current - previous).norm() / current.norm());
      }
      previous = current;
    }
    double worst = 0.0;
    for (std::size_t i = 1; i + 1 < steps.size(); ++i)
    {
      worst = std::max(worst, steps[i] / std::max(steps[i - 1], steps[i + 1]));
    }
    EXPECT_LE(worst, 1.5) << middle;
  }
}

TEST(TransformInterpolatorLCT, AStepTooIllConditionedIsNotCalledAReflection)
{
  // Two keys of positive determinant (1 and 2e-15) whose step is beyond double's reach: its
  // computed determinant rounded below 0, and the key was refused as "negative (a reflection)".
  const double first[9] = { 235.18507057736505, -34542.573377627676, -64861.954964248485,
    95.31575106815572, -14000.65998962326, -26288.67779145755, -70.1542915326977,
    10301.192711569443, 19344.88579024852 };
  const double second[9] = { 0.0778424907124333, -0.03210076401567792, -0.0010934846826013574,
    -0.3315266039332908, 0.13971813090656796, 0.001780309450494782, -0.856716073813885,
    0.35983323261090316, 0.005769418686698595 };
  vtkNew<vtkTransformInterpolatorLCT> path;
  path->SetInterpolationTypeToLinear();
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkMatrix4x4> m;
  for (int i = 0; i < 9; ++i)
  {
    m->SetElement(i / 3, i % 3, first[i]);
  }
  ASSERT_EQ(path->AddTransform(3.933536, m), 1) << errors->Last;
  for (int i = 0; i < 9; ++i)
  {
    m->SetElement(i / 3, i % 3, second[i]);
  }
  EXPECT_EQ(path->AddTransform(9.409135, m), 0);
  EXPECT_NE(errors->Last.find("numerically singular"), std::string::npos) << errors->Last;
  EXPECT_EQ(errors->Last.find("negative"), std::string::npos) << errors->Last;
  EXPECT_EQ(path->GetNumberOfTransforms(), 1);
}

TEST(TransformInterpolatorLCT, SplineAndSubdivisionAreC1AcrossKeys)
{
  // Uniform key times (subdivision is C1 in the key index).
  const auto sheared = shearedKeys(4, 6);
  for (int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION })
  {
    vtkNew<vtkTransformInterpolatorLCT> interpolator;
    interpolator->SetInterpolationType(type);
    for (size_t k = 0; k < sheared.size(); ++k)
    {
      vtkNew<vtkMatrix4x4> m;
      toVtk(sheared[k].second, m);
      ASSERT_EQ(interpolator->AddTransform(static_cast<double>(k), m), 1);
    }
    vtkNew<vtkLogTransform> a, b, c;
    for (size_t k = 1; k + 1 < sheared.size(); ++k)
    {
      const double h = 1e-4;
      interpolator->InterpolateTransform(k - h, a);
      interpolator->InterpolateTransform(static_cast<double>(k), b);
      interpolator->InterpolateTransform(k + h, c);
      double ca[12], cb[12], cc[12];
      a->GetLogCoordinates(ca);
      b->GetLogCoordinates(cb);
      c->GetLogCoordinates(cc);
      for (int i = 0; i < 12; ++i)
      {
        const double left = (cb[i] - ca[i]) / h;
        const double right = (cc[i] - cb[i]) / h;
        EXPECT_NEAR(left, right, 2e-2 * (1.0 + std::abs(left)))
          << "type " << type << " key " << k << " coordinate " << i;
      }
    }
  }
}

TEST(TransformInterpolatorLCT, ShortWayByDefaultSpinWithConsistentRotation)
{
  auto angleAt = [](vtkTransformInterpolatorLCT* interpolator, double t) {
    vtkNew<vtkTransform> out;
    interpolator->InterpolateTransform(t, out);
    return std::atan2(out->GetMatrix()->GetElement(1, 0), out->GetMatrix()->GetElement(0, 0)) *
      180.0 / lct_test::kPi;
  };
  // A 190 degree step is taken the short way (-170).
  vtkNew<vtkTransformInterpolatorLCT> step;
  step->SetInterpolationTypeToLinear();
  vtkNew<vtkTransform> zero, turned;
  turned->RotateZ(190.0);
  step->AddTransform(0.0, zero);
  step->AddTransform(1.0, turned);
  EXPECT_NEAR(angleAt(step, 0.5), -85.0, 1e-9);

  // A spin sampled at 0, 170, 340, 510 degrees: with ConsistentRotation the spline sees the
  // winding (its keys' logs are 0, 170, 340, 510 degrees, and Catmull-Rom reproduces that
  // linear motion exactly: 255 degrees at t = 1.5). Without it too: the step from the key at
  // 170 to the key at 510, relative to the reference key, is taken on the branch continued
  // through the key between (340 degrees, not the short way's -20, which bent the spline by
  // more than 10 degrees before).
  vtkNew<vtkTransformInterpolatorLCT> spin;
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(170.0 * k);
    ASSERT_EQ(spin->AddTransform(k, key), 1);
  }
  spin->ConsistentRotationOn();
  for (int i = 0; i <= 30; ++i)
  {
    const double t = i / 10.0;
    EXPECT_NEAR(std::remainder(angleAt(spin, t) - 170.0 * t, 360.0), 0.0, 1e-9) << t;
  }
  spin->ConsistentRotationOff();
  double worst = 0.0;
  for (int i = 10; i <= 20; ++i)
  {
    const double t = i / 10.0;
    worst = std::max(worst, std::abs(std::remainder(angleAt(spin, t) - 170.0 * t, 360.0)));
  }
  EXPECT_LT(worst, 1e-9);
}

TEST(TransformInterpolatorLCT, KeysTurningLessThanHalfATurnEachAreFollowedTheWholeWay)
{
  // Keys 100 to 170 degrees apart about z (unevenly): each step is taken the short way, and the
  // curve between keys keeps turning the same way. Catmull-Rom, the B-spline and the 4-point
  // scheme combine keys two steps from their reference, more than 180 degrees away: taken the
  // short way, those wound the curve back by up to 6.6 degrees in each segment.
  const double steps[] = { 100, 150, 170, 120, 135, 100 };
  for (const int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION })
  {
    vtkNew<vtkTransformInterpolatorLCT> path;
    ASSERT_EQ(path->SetInterpolationType(type), 1);
    double angle = 0.0;
    for (int k = 0; k <= 6; ++k)
    {
      vtkNew<vtkTransform> key;
      key->RotateZ(angle);
      ASSERT_EQ(path->AddTransform(k, key), 1);
      angle += k < 6 ? steps[k] : 0.0;
    }
    vtkNew<vtkMatrix4x4> m;
    double previous = 0.0, largestBack = 0.0;
    for (int i = 0; i <= 600; ++i)
    {
      ASSERT_EQ(path->InterpolateTransform(i / 100.0, m), 1);
      const double a = std::atan2(m->GetElement(1, 0), m->GetElement(0, 0)) * 180.0 / lct_test::kPi;
      if (i > 0)
      {
        largestBack = std::min(largestBack, std::remainder(a - previous, 360.0));
      }
      previous = a;
    }
    EXPECT_GE(largestBack, -1e-9) << "type " << type;
  }
}

TEST(TransformInterpolatorLCT, VtkSemanticsClampReplaceRemoveAndMTime)
{
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  EXPECT_EQ(
    interpolator->GetInterpolationType(), vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE);
  vtkNew<vtkTransform> a, b, c;
  a->Translate(1, 0, 0);
  b->Translate(0, 2, 0);
  c->Translate(0, 0, 3);
  vtkMTimeType before = interpolator->GetMTime();
  interpolator->AddTransform(1.0, a);
  EXPECT_GT(interpolator->GetMTime(), before);
  interpolator->AddTransform(3.0, b);
  EXPECT_EQ(interpolator->GetNumberOfTransforms(), 2);
  EXPECT_EQ(interpolator->GetMinimumT(), 1.0);
  EXPECT_EQ(interpolator->GetMaximumT(), 3.0);
  // Clamped outside the range.
  vtkNew<vtkMatrix4x4> out;
  ASSERT_EQ(interpolator->InterpolateTransform(-10.0, out), 1);
  EXPECT_EQ(out->GetElement(0, 3), 1.0);
  ASSERT_EQ(interpolator->InterpolateTransform(10.0, out), 1);
  EXPECT_EQ(out->GetElement(1, 3), 2.0);
  // Same time replaces.
  before = interpolator->GetMTime();
  interpolator->AddTransform(3.0, c);
  EXPECT_GT(interpolator->GetMTime(), before);
  EXPECT_EQ(interpolator->GetNumberOfTransforms(), 2);
  interpolator->InterpolateTransform(3.0, out);
  EXPECT_EQ(out->GetElement(2, 3), 3.0);
  // Props: their full matrix is the key.
  vtkNew<vtkActor> actor;
  actor->SetPosition(4, 5, 6);
  actor->RotateY(30);
  ASSERT_EQ(interpolator->AddTransform(5.0, actor), 1);
  interpolator->InterpolateTransform(5.0, out);
  EXPECT_LT((fromVtk(out) - fromVtk(actor->GetMatrix())).norm(), 1e-14);
  before = interpolator->GetMTime();
  interpolator->RemoveTransform(5.0);
  EXPECT_EQ(interpolator->GetNumberOfTransforms(), 2);
  EXPECT_GT(interpolator->GetMTime(), before);
  before = interpolator->GetMTime();
  interpolator->RemoveTransform(42.0); // no such key: no change
  EXPECT_EQ(interpolator->GetMTime(), before);
  interpolator->Initialize();
  EXPECT_EQ(interpolator->GetNumberOfTransforms(), 0);
  EXPECT_GT(interpolator->GetMTime(), before);
}

TEST(TransformInterpolatorLCT, BadInputIsRejectedAndLeavesEverythingUnchanged)
{
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  vtkNew<ErrorCounter> errors;
  interpolator->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkMatrix4x4> out;
  out->SetElement(0, 3, 42.0);

  // No keys.
  EXPECT_EQ(interpolator->InterpolateTransform(0.0, out), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_EQ(out->GetElement(0, 3), 42.0);

  vtkNew<vtkTransform> good;
  good->RotateX(20);
  ASSERT_EQ(interpolator->AddTransform(0.0, good), 1);
  ASSERT_EQ(interpolator->AddTransform(1.0, good), 1);
  const vtkMTimeType saved = interpolator->GetMTime();

  int expected = 1;
  vtkNew<vtkMatrix4x4> bad;
  auto reject = [&](double t, const char* what, const char* phrase) {
    EXPECT_EQ(interpolator->AddTransform(t, bad), 0) << what;
    EXPECT_EQ(errors->Count, ++expected) << what;
    EXPECT_NE(errors->Last.find(phrase), std::string::npos) << what << ": " << errors->Last;
    EXPECT_EQ(interpolator->GetNumberOfTransforms(), 2) << what;
    EXPECT_EQ(interpolator->GetMTime(), saved) << what;
  };
  bad->Identity();
  bad->SetElement(0, 1, std::nan(""));
  reject(0.5, "NaN", "NaN");
  bad->Identity();
  bad->SetElement(2, 3, std::numeric_limits<double>::infinity());
  reject(0.5, "Inf", "NaN or Inf");
  bad->Identity();
  bad->SetElement(3, 2, 0.5);
  reject(0.5, "projective", "bottom row");
  bad->Identity();
  bad->SetElement(1, 1, -1.0);
  reject(0.5, "reflection", "determinant");
  bad->Identity();
  bad->SetElement(1, 1, 0.0);
  reject(0.5, "singular", "determinant");
  bad->Identity();
  reject(std::nan(""), "NaN time", "not finite");
  // Replacing an existing key with a bad one keeps the old key.
  bad->SetElement(0, 0, -1.0);
  reject(1.0, "bad replacement", "determinant");
  EXPECT_EQ(interpolator->AddTransform(0.5, static_cast<vtkMatrix4x4*>(nullptr)), 0);
  EXPECT_EQ(errors->Count, ++expected);

  // NaN time at evaluation.
  EXPECT_EQ(interpolator->InterpolateTransform(std::nan(""), out), 0);
  EXPECT_EQ(errors->Count, ++expected);
  EXPECT_EQ(out->GetElement(0, 3), 42.0);

  // MatrixLog: a half turn with non-uniform scale has no real log: rejected in that mode, and
  // switching to MatrixLog with such a key present is refused.
  vtkNew<vtkMatrix4x4> halfTurn;
  halfTurn->Identity();
  halfTurn->SetElement(0, 0, -2.0);
  halfTurn->SetElement(1, 1, -1.0);
  ASSERT_EQ(interpolator->AddTransform(2.0, halfTurn), 1); // fine in Polar
  EXPECT_EQ(interpolator->SetParametrisationToMatrixLog(), 0);
  EXPECT_EQ(errors->Count, ++expected);
  EXPECT_EQ(interpolator->GetParametrisation(), vtkTransformInterpolatorLCT::POLAR);
  interpolator->RemoveTransform(2.0);
  ASSERT_EQ(interpolator->SetParametrisationToMatrixLog(), 1);
  EXPECT_EQ(interpolator->AddTransform(2.0, halfTurn), 0);
  EXPECT_EQ(errors->Count, ++expected);
  EXPECT_NE(errors->Last.find("no real matrix logarithm"), std::string::npos) << errors->Last;
  EXPECT_EQ(interpolator->GetNumberOfTransforms(), 2);
}

TEST(TransformInterpolatorLCT, BezierFollowsItsControlTransforms)
{
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  interpolator->SetInterpolationTypeToBezier();
  EXPECT_EQ(
    interpolator->GetInterpolationType(), vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER);
  vtkNew<vtkTransform> k0, k1;
  k1->Translate(1, 0, 0);
  ASSERT_EQ(interpolator->AddTransform(0.0, k0), 1);
  ASSERT_EQ(interpolator->AddTransform(1.0, k1), 1);
  vtkNew<vtkTransform> out0, in1;
  out0->Translate(0, 1, 0);
  in1->Translate(1, 1, 0);
  ASSERT_EQ(interpolator->SetBezierControls(0.0, nullptr, out0->GetMatrix()), 1);
  ASSERT_EQ(interpolator->SetBezierControls(1.0, in1->GetMatrix(), nullptr), 1);
  // Translations: the Bezier of (0,0), (0,1), (1,1), (1,0) at u = 1/2 is (1/2, 3/4).
  vtkNew<vtkMatrix4x4> m;
  ASSERT_EQ(interpolator->InterpolateTransform(0.5, m), 1);
  EXPECT_NEAR(m->GetElement(0, 3), 0.5, 1e-14);
  EXPECT_NEAR(m->GetElement(1, 3), 0.75, 1e-14);
  ASSERT_EQ(interpolator->InterpolateTransform(1.0, m), 1);
  EXPECT_NEAR(m->GetElement(0, 3), 1.0, 1e-14);
  EXPECT_NEAR(m->GetElement(1, 3), 0.0, 1e-14);

  // Bad controls: no key there, a reflection.
  vtkNew<ErrorCounter> errors;
  interpolator->AddObserver(vtkCommand::ErrorEvent, errors);
  const vtkMTimeType saved = interpolator->GetMTime();
  EXPECT_EQ(interpolator->SetBezierControls(0.5, nullptr, out0->GetMatrix()), 0);
  vtkNew<vtkMatrix4x4> reflection;
  reflection->SetElement(0, 0, -1.0);
  EXPECT_EQ(interpolator->SetBezierControls(0.0, reflection, nullptr), 0);
  EXPECT_EQ(errors->Count, 2);
  EXPECT_EQ(interpolator->GetMTime(), saved);
}

TEST(TransformInterpolatorLCT, BezierReproducesKeysAndWithoutControlsMatchesTheSplineOnTranslations)
{
  const auto keys = shearedKeys(9, 6);
  vtkNew<vtkTransformInterpolatorLCT> bezier;
  bezier->SetInterpolationTypeToBezier();
  for (const auto& [t, m] : keys)
  {
    vtkNew<vtkMatrix4x4> vm;
    toVtk(m, vm);
    ASSERT_EQ(bezier->AddTransform(t, vm), 1);
  }
  for (const auto& [t, m] : keys)
  {
    vtkNew<vtkMatrix4x4> out;
    ASSERT_EQ(bezier->InterpolateTransform(t, out), 1);
    EXPECT_LT(lct_test::blockError(fromVtk(out), m), 1e-12);
  }
  // Automatic controls put the Catmull-Rom tangent at each key. Where the logs add exactly
  // (pure translations), the Bezier curve is then the plain Catmull-Rom Spline itself. (With
  // rotations the two differ: the controls live in their key's frame, the spline's tangents in
  // the reference's.)
  vtkNew<vtkTransformInterpolatorLCT> translations, spline;
  spline->MonotoneTangentsOff();
  translations->SetInterpolationTypeToBezier();
  lct_test::RandomTransforms random(10);
  double time = 0.0;
  for (int k = 0; k < 6; ++k)
  {
    vtkNew<vtkTransform> key;
    const Eigen::Vector3d v = random.Translation(lct_test::TransformClass::Rigid);
    key->Translate(v.x(), v.y(), v.z());
    translations->AddTransform(time, key);
    spline->AddTransform(time, key);
    time += random.Uniform(0.5, 2.0);
  }
  double worst = 0.0;
  for (int i = 0; i <= 200; ++i)
  {
    const double t = spline->GetMaximumT() * i / 200.0;
    vtkNew<vtkMatrix4x4> a, b;
    translations->InterpolateTransform(t, a);
    spline->InterpolateTransform(t, b);
    worst = std::max(worst, (fromVtk(a) - fromVtk(b)).norm());
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(TransformInterpolatorLCT, BezierControlsOfKeysSubnormallyCloseInTime)
{
  // The automatic control beside a key is exp(third of the segment x tangent); the tangent
  // alone overflows where the neighbouring keys are 1e-310 apart in time, which refused every
  // curve point as "NaN or Inf". Taken as the time ratio times the step, it is representable.
  for (const double close : { 1e-300, 1e-310, 5e-324 })
  {
    vtkNew<vtkTransformInterpolatorLCT> bezier;
    bezier->SetInterpolationTypeToBezier();
    const double times[] = { 0.0, close, 1.0 };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkTransform> key;
      key->RotateZ(30.0 * k);
      key->Translate(k, 0, 0);
      ASSERT_EQ(bezier->AddTransform(times[k], key), 1);
    }
    vtkNew<vtkMatrix4x4> m;
    for (int s = 0; s <= 20; ++s)
    {
      ASSERT_EQ(bezier->InterpolateTransform(s / 20.0, m), 1) << close << " " << s;
      for (int i = 0; i < 16; ++i)
      {
        ASSERT_TRUE(std::isfinite(m->GetElement(i / 4, i % 4)));
      }
    }
    vtkNew<vtkTransform> last;
    last->RotateZ(60.0);
    last->Translate(2, 0, 0);
    ASSERT_EQ(bezier->InterpolateTransform(1.0, m), 1);
    EXPECT_LT((fromVtk(m) - fromVtk(last->GetMatrix())).cwiseAbs().maxCoeff(), 1e-12) << close;
  }
}

TEST(TransformInterpolatorLCT, NoJumpWhereTheReferenceKeyChanges)
{
  // The relative form depends on its reference key; where two weights cross, the hand-over
  // must not show. Sample densely and compare every step with the typical step.
  const auto keys = shearedKeys(11, 5);
  for (int type : { 0, 1, 2, 3, 4 })
  {
    for (int p : { vtkTransformInterpolatorLCT::POLAR, vtkTransformInterpolatorLCT::MATRIX_LOG })
    {
      vtkNew<vtkTransformInterpolatorLCT> interpolator;
      interpolator->SetInterpolationType(type);
      interpolator->SetParametrisation(p);
      bool all = true;
      for (const auto& [t, m] : keys)
      {
        vtkNew<vtkMatrix4x4> vm;
        toVtk(m, vm);
        all = all && interpolator->AddTransform(t, vm);
      }
      if (!all)
      {
        continue; // MatrixLog without a real log between two keys
      }
      const int samples = 20000;
      const double span = keys.back().first;
      std::vector<double> steps;
      vtkNew<vtkMatrix4x4> previous, current;
      ASSERT_EQ(interpolator->InterpolateTransform(0.0, previous), 1);
      for (int i = 1; i <= samples; ++i)
      {
        if (!interpolator->InterpolateTransform(span * i / samples, current))
        {
          break; // MatrixLog: a combination without real log, reported by an error
        }
        steps.push_back((fromVtk(current) - fromVtk(previous)).norm());
        previous->DeepCopy(current);
      }
      std::vector<double> sorted = steps;
      std::sort(sorted.begin(), sorted.end());
      const double typical = sorted[sorted.size() / 2];
      // A smooth curve's steps vary with its speed (a few times the median); a jump of the
      // reference would be thousands of steps at once.
      EXPECT_LT(sorted.back(), 20.0 * typical) << "type " << type << " parametrisation " << p;
    }
  }
}

// Audit (session 29): the clamp warning is "reported once"; Initialize() did not reset that, so
// an interpolator reused for new keys clamped silently.
TEST(TransformInterpolatorLCT, InitializeReportsTheNextClampAgain)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<lct_test::ErrorCounter> warnings;
  path->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<vtkTransform> key;
  vtkNew<vtkMatrix4x4> out;
  for (int round = 1; round <= 2; ++round)
  {
    path->Initialize();
    ASSERT_EQ(path->AddTransform(0.0, key), 1);
    ASSERT_EQ(path->AddTransform(1.0, key), 1);
    ASSERT_EQ(path->InterpolateTransform(2.0, out), 1);
    ASSERT_EQ(path->InterpolateTransform(3.0, out), 1);
    EXPECT_EQ(warnings->Count, round) << warnings->Last;
  }
}

// Audit (session 30): between the identity and a stretch of condition 1e8-1e12, the Polar relative
// form took each point about the key of larger weight; past the midpoint that is the
// ill-conditioned key, whose step's rounding is amplified by its condition: the largest stretch
// came out 1e-10 (condition 1e8) to 1e-6 (1e12) off, relative, with status 1 (the determinant
// check sees only their product). Two keys give the same point about either, so it is taken
// about the better-conditioned one. The exact |L|_F^2 of U^t S^t is trace(D^2t).
TEST(vtkTransformInterpolatorLCT, TwoKeysWithAnIllConditionedOneAreAccurateOrRefused)
{
  for (const double exponent : { 4.0, 5.0, 6.0 })
  {
    vtkNew<vtkTransform> stretch;
    stretch->RotateWXYZ(143.2, 3, 1, 0);
    stretch->Scale(std::pow(10.0, exponent), 1, std::pow(10.0, -exponent));
    stretch->RotateWXYZ(57.3, 1, 1, 1);
    for (const bool stretchFirst : { false, true })
    {
      vtkNew<vtkTransformInterpolatorLCT> path;
      path->SetInterpolationTypeToLinear();
      vtkNew<vtkMatrix4x4> identity;
      ASSERT_EQ(path->AddTransform(stretchFirst ? 1.0 : 0.0, identity), 1);
      ASSERT_EQ(path->AddTransform(stretchFirst ? 0.0 : 1.0, stretch->GetMatrix()), 1);
      int accepted = 0;
      for (const double t : { 0.1, 0.4, 0.6, 0.8, 0.9, 0.99 })
      {
        vtkNew<vtkMatrix4x4> m;
        if (!path->InterpolateTransform(stretchFirst ? 1.0 - t : t, m))
        {
          continue;
        }
        ++accepted;
        double squares = 0.0;
        for (int i = 0; i < 3; ++i)
        {
          for (int j = 0; j < 3; ++j)
          {
            squares += m->GetElement(i, j) * m->GetElement(i, j);
          }
        }
        const double exact =
          std::pow(10.0, 2 * exponent * t) + 1.0 + std::pow(10.0, -2 * exponent * t);
        // Before the midpoint (about the identity either way) the error is the problem's own,
        // up to ~6e-9 at condition 1e12; past it the old reference added 1e-10 to 1e-6.
        EXPECT_LE(std::abs(squares - exact) / exact, t > 0.5 ? 1e-12 : 1e-8)
          << exponent << " " << t;
      }
      EXPECT_GE(accepted, 5) << exponent; // accurate where it can be, not refused wholesale
    }
  }
}

// Speed (session 31): the Spline's monotone tangents are cached per key. After every kind of
// edit, made after evaluations, the curve must be the one a fresh interpolator with the same
// keys and settings gives: a key added, one replaced in place, one removed, the parametrisation
// switched (new logs), Initialize and new keys, the monotone tangents turned off and on.
TEST(TransformInterpolatorLCT, CachedTangentsFollowEveryEditOfTheKeys)
{
  // A keyframed walk (<= 30 degrees and 15 % of stretch per key) at uneven times: every
  // stencil has its MatrixLog logs too.
  lct_test::RandomTransforms random(3102);
  std::vector<std::pair<double, Eigen::Matrix4d>> keys;
  Eigen::Matrix4d walk = Eigen::Matrix4d::Identity();
  for (double t = 0.0; keys.size() < 7; t += random.Uniform(0.3, 2.0))
  {
    keys.emplace_back(t, walk);
    walk = random.KeyframeStep() * walk;
  }
  vtkNew<vtkTransformInterpolatorLCT> edited;
  std::vector<std::pair<double, Eigen::Matrix4d>> current;
  bool monotone = true;
  int parametrisation = vtkTransformInterpolatorLCT::POLAR;
  const auto add = [&](double t, const Eigen::Matrix4d& m) {
    vtkNew<vtkMatrix4x4> matrix;
    toVtk(m, matrix);
    ASSERT_EQ(edited->AddTransform(t, matrix), 1);
    current.erase(std::remove_if(current.begin(), current.end(),
                    [t](const std::pair<double, Eigen::Matrix4d>& k) { return k.first == t; }),
      current.end());
    current.emplace_back(t, m);
  };
  const auto compare = [&](const char* after) {
    vtkNew<vtkTransformInterpolatorLCT> fresh;
    fresh->SetParametrisation(parametrisation);
    fresh->SetMonotoneTangents(monotone);
    for (const auto& k : current)
    {
      vtkNew<vtkMatrix4x4> matrix;
      toVtk(k.second, matrix);
      ASSERT_EQ(fresh->AddTransform(k.first, matrix), 1) << after;
    }
    const double t0 = edited->GetMinimumT(), t1 = edited->GetMaximumT();
    ASSERT_EQ(t0, fresh->GetMinimumT());
    ASSERT_EQ(t1, fresh->GetMaximumT());
    for (int s = 0; s <= 60; ++s)
    {
      const double t = t0 + (t1 - t0) * s / 60.0;
      vtkNew<vtkMatrix4x4> a, b;
      ASSERT_EQ(edited->InterpolateTransform(t, a), 1) << after;
      ASSERT_EQ(fresh->InterpolateTransform(t, b), 1) << after;
      const Eigen::Matrix4d difference = fromVtk(a) - fromVtk(b);
      ASSERT_LE(difference.cwiseAbs().maxCoeff(), 1e-12 * fromVtk(b).cwiseAbs().maxCoeff())
        << after << " at t = " << t;
    }
  };
  for (int k = 0; k < 5; ++k)
  {
    add(keys[k].first, keys[k].second);
  }
  compare("the first keys");
  add(keys[5].first, keys[5].second);
  compare("a key added at the end");
  add(0.5 * (keys[1].first + keys[2].first), keys[6].second);
  compare("a key added between two");
  add(keys[3].first,
    keys[3].second *
      lct::makeAffine(Eigen::Matrix3d::Identity() * 1.5, Eigen::Vector3d(0.3, -0.2, 0.1)));
  compare("a key replaced in place");
  ASSERT_EQ(edited->RemoveTransform(keys[2].first), 1);
  current.erase(
    std::remove_if(current.begin(), current.end(),
      [&](const std::pair<double, Eigen::Matrix4d>& k) { return k.first == keys[2].first; }),
    current.end());
  compare("a key removed");
  parametrisation = vtkTransformInterpolatorLCT::MATRIX_LOG;
  ASSERT_EQ(edited->SetParametrisation(parametrisation), 1);
  compare("MatrixLog");
  monotone = false;
  edited->SetMonotoneTangents(monotone);
  compare("Catmull-Rom");
  monotone = true;
  edited->SetMonotoneTangents(monotone);
  compare("monotone again");
  edited->Initialize();
  current.clear();
  for (int k = 6; k >= 3; --k)
  {
    add(keys[k].first + 0.25, keys[k].second);
  }
  compare("Initialize and new keys");
}
