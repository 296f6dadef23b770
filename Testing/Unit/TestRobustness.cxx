// The hostile-input classes of the robustness issue, through the VTK classes: every one gets an
// error naming its true cause and a return value to test, the object keeps its last valid state,
// and nothing non-finite is ever written.
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCameraPathMetric.h"
#include "vtkInterpolatorCueLCT.h"
#include "vtkLogTransform.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkShapeBlenderLCT.h"
#include "vtkTransformBasisLCT.h"
#include "vtkTransformInterpolatorLCT.h"
#include "vtkTransformSequencePCA.h"

#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCollection.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using lct_test::ErrorCounter;

namespace
{
vtkNew<vtkMatrix4x4> diagonalMatrix(double x, double y, double z)
{
  vtkNew<vtkMatrix4x4> m;
  m->SetElement(0, 0, x);
  m->SetElement(1, 1, y);
  m->SetElement(2, 2, z);
  return m;
}

bool allFinite(vtkMatrix4x4* m)
{
  for (int i = 0; i < 16; ++i)
  {
    if (!std::isfinite(m->GetElement(i / 4, i % 4)))
    {
      return false;
    }
  }
  return true;
}

bool contains(const std::string& text, const char* phrase)
{
  return text.find(phrase) != std::string::npos;
}
} // namespace

TEST(Robustness, IllConditionedStretchThroughVtkLogTransform)
{
  // The first case, through the VTK class in both parametrisations.
  for (int p : { vtkLogTransform::POLAR, vtkLogTransform::MATRIX_LOG })
  {
    vtkNew<vtkLogTransform> t;
    t->SetParametrisation(p);
    vtkNew<vtkTransform> scale;
    scale->Scale(1e-6, 1, 1e6);
    ASSERT_EQ(t->SetTransform(scale), 1);
    vtkMatrix4x4* m = t->GetMatrix();
    EXPECT_NEAR(m->GetElement(0, 0) / 1e-6, 1.0, 1e-14);
    EXPECT_NEAR(m->GetElement(1, 1), 1.0, 1e-14);
    EXPECT_NEAR(m->GetElement(2, 2) / 1e6, 1.0, 1e-14);
    // Beyond the conditioning limit: refused by name, state kept.
    vtkNew<ErrorCounter> errors;
    t->AddObserver(vtkCommand::ErrorEvent, errors);
    EXPECT_EQ(t->SetMatrix(diagonalMatrix(1e-8, 1, 1e8)), 0);
    EXPECT_TRUE(contains(errors->Last, "ill-conditioned")) << errors->Last;
    EXPECT_NEAR(t->GetMatrix()->GetElement(2, 2) / 1e6, 1.0, 1e-14);
  }
}

TEST(Robustness, ExtremeMagnitudesThroughVtkLogTransform)
{
  vtkNew<vtkLogTransform> t;
  for (double scale : { 1e102, 1e300, std::exp(-300.0), 1e-300 })
  {
    ASSERT_EQ(t->SetMatrix(diagonalMatrix(scale, scale, scale)), 1) << scale;
    EXPECT_NEAR(t->GetMatrix()->GetElement(1, 1) / scale, 1.0, 1e-13) << scale;
    // The inverse is representable, so Inverse() and GetInverse() hold it.
    vtkLinearTransform* inverse = t->GetLinearInverse();
    inverse->Update();
    // Within the round-off of a log coordinate of size |log scale|.
    EXPECT_NEAR(inverse->GetMatrix()->GetElement(1, 1) * scale, 1.0,
      1e-14 + 1e-15 * std::abs(std::log(scale)))
      << scale;
  }
}

TEST(Robustness, StatesWhoseInverseOverflowsAreRefused)
{
  // Translate(1e300) after Scale(1e-10): the map is finite, its inverse translation 1e310 is not.
  // A vtkLogTransform only holds maps it can invert, so GetInverse() never holds a wrong matrix.
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkMatrix4x4> m;
  m->SetElement(0, 0, 1e-10);
  m->SetElement(1, 1, 1e-10);
  m->SetElement(2, 2, 1e-10);
  m->SetElement(0, 3, 1e300);
  EXPECT_EQ(t->SetMatrix(m), 0);
  EXPECT_TRUE(contains(errors->Last, "inverse")) << errors->Last;
  EXPECT_TRUE(t->GetMatrix()->IsIdentity());
  vtkLinearTransform* inverse = t->GetLinearInverse();
  inverse->Update();
  EXPECT_TRUE(inverse->GetMatrix()->IsIdentity());
}

TEST(Robustness, DeepCopyOfNullOrForeignTransforms)
{
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  t->Scale(1.0);
  t->DeepCopy(nullptr); // VTK's own DeepCopy dereferences it
  EXPECT_EQ(errors->Count, 1);
  vtkNew<vtkTransform> foreign;
  foreign->RotateZ(30);
  t->DeepCopy(foreign);
  EXPECT_EQ(errors->Count, 2);
  EXPECT_TRUE(contains(errors->Last, "SetTransform")) << errors->Last;
  EXPECT_TRUE(t->GetMatrix()->IsIdentity());
}

TEST(Robustness, OverflowingOperationsLeaveTheStateUnchanged)
{
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkTransform> big;
  big->Translate(1e307, 0, 0);
  big->Scale(10, 1, 1);
  ASSERT_EQ(t->SetTransform(big), 1);
  const double saved = t->GetMatrix()->GetElement(0, 3);
  EXPECT_EQ(t->Scale(1e300), 0); // coordinates overflow
  EXPECT_EQ(t->Scale(100.0), 0); // translation 1e309 overflows
  EXPECT_EQ(errors->Count, 2);
  EXPECT_EQ(t->GetMatrix()->GetElement(0, 3), saved);
  EXPECT_FALSE(contains(errors->Last, "NaN")) << errors->Last;
}

TEST(Robustness, SingularKeyIsRejectedNotTheGoodKeyAfterIt)
{
  // diag(1e-20, 1, 1) used to be accepted as a first key, and a good identity key rejected with
  // "use the polar parametrisation" although Polar was in use.
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  EXPECT_EQ(path->AddTransform(0.0, diagonalMatrix(1e-20, 1, 1)), 0);
  // The key itself is named, with the words vtkLogTransform::SetMatrix uses for it.
  EXPECT_TRUE(contains(errors->Last,
    "AddTransform at t = 0: the linear part is numerically "
    "singular"))
    << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "step")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "Polar")) << errors->Last; // the one in use: no advice
  EXPECT_EQ(path->AddTransform(0.0, diagonalMatrix(0, 0, 0)), 0);
  // A zero scale is singular, not a mirror, and the message gives the workaround.
  EXPECT_TRUE(contains(errors->Last, "singular")) << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "tiny positive scale")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "mirror")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "reflection")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "use the")) << errors->Last;
  EXPECT_EQ(path->AddTransform(0.0, diagonalMatrix(-1, 1, 1)), 0);
  EXPECT_TRUE(contains(errors->Last, "reflection")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "singular")) << errors->Last;
  EXPECT_EQ(errors->Count, 3);
  vtkNew<vtkMatrix4x4> identity;
  EXPECT_EQ(path->AddTransform(1.0, identity), 1);
  EXPECT_EQ(path->GetNumberOfTransforms(), 1);
  EXPECT_EQ(errors->Count, 3);
  // The same key as a vtkLogTransform gets the same cause.
  vtkNew<vtkLogTransform> single;
  single->AddObserver(vtkCommand::ErrorEvent, errors);
  EXPECT_EQ(single->SetMatrix(diagonalMatrix(1e-20, 1, 1)), 0);
  EXPECT_TRUE(contains(errors->Last, "numerically singular")) << errors->Last;
  // MatrixLog refuses it for the same reason, and does not advise Polar, which refuses it too.
  vtkNew<vtkTransformInterpolatorLCT> matrixLog;
  matrixLog->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(matrixLog->SetParametrisationToMatrixLog(), 1);
  EXPECT_EQ(matrixLog->AddTransform(0.0, diagonalMatrix(1e-20, 1, 1)), 0);
  EXPECT_TRUE(contains(errors->Last, "numerically singular")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "Polar")) << errors->Last;
  EXPECT_EQ(matrixLog->AddTransform(1.0, identity), 1);
}

TEST(Robustness, ZeroScaleOfAPropIsSingularWithTheWorkaround)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkActor> prop;
  prop->SetScale(0, 0, 0); // "grow from nothing"
  EXPECT_EQ(path->AddTransform(0.0, prop), 0);
  EXPECT_TRUE(contains(errors->Last, "singular")) << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "1e-6")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "mirror")) << errors->Last;
  // The documented workaround is accepted and grows the prop.
  prop->SetScale(1e-6, 1e-6, 1e-6);
  ASSERT_EQ(path->AddTransform(0.0, prop), 1);
  prop->SetScale(1, 1, 1);
  ASSERT_EQ(path->AddTransform(1.0, prop), 1);
  vtkNew<vtkMatrix4x4> m;
  ASSERT_EQ(path->InterpolateTransform(0.5, m), 1);
  EXPECT_NEAR(m->GetElement(0, 0), 1e-3, 1e-12); // geometric mean of 1e-6 and 1
  EXPECT_EQ(errors->Count, 1);
}

TEST(Robustness, StepBetweenExtremeKeysIsNamed)
{
  // Each key within the limit (cond 1e12), their step far beyond it (1e24).
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(path->AddTransform(0.0, diagonalMatrix(1e-6, 1, 1e6)), 1);
  EXPECT_EQ(path->AddTransform(1e-7, diagonalMatrix(1e6, 1, 1e-6)), 0);
  EXPECT_TRUE(contains(errors->Last, "t = 1e-07")) << errors->Last; // not 0.000000
  EXPECT_TRUE(contains(errors->Last, "the key at t = 0")) << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "ill-conditioned")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "use the")) << errors->Last;
  EXPECT_EQ(path->GetNumberOfTransforms(), 1);
  // In MatrixLog the advice to switch is given, and only there.
  vtkNew<vtkTransformInterpolatorLCT> matrixLog;
  matrixLog->AddObserver(vtkCommand::ErrorEvent, errors);
  matrixLog->SetParametrisationToMatrixLog();
  vtkNew<vtkMatrix4x4> identity;
  ASSERT_EQ(matrixLog->AddTransform(0.0, identity), 1);
  EXPECT_EQ(matrixLog->AddTransform(1.0, diagonalMatrix(-2, -1, 1)), 0); // half turn, scale
  EXPECT_TRUE(contains(errors->Last, "SetParametrisationToPolar")) << errors->Last;
}

/// Translation keys 0, 1.65e308, 1.65e308, 0 at t = 0 .. 3.
static void addHugePlateau(vtkTransformInterpolatorLCT* path)
{
  const double x[4] = { 0.0, 1.65e308, 1.65e308, 0.0 };
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkMatrix4x4> m;
    m->SetElement(0, 3, x[k]);
    ASSERT_EQ(path->AddTransform(k, m), 1);
  }
}

TEST(Robustness, SplineOvershootThatOverflowsIsAnErrorNotInf)
{
  for (int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION })
  {
    vtkNew<vtkTransformInterpolatorLCT> path;
    path->MonotoneTangentsOff(); // plain Catmull-Rom overshoots (the default does not: below)
    path->SetInterpolationType(type);
    vtkNew<ErrorCounter> errors;
    path->AddObserver(vtkCommand::ErrorEvent, errors);
    // Steps of 1.65e308 are representable; the overshoot between the middle keys (12.5 % above
    // them for uniform Catmull-Rom) is not.
    addHugePlateau(path);
    vtkNew<vtkMatrix4x4> out;
    int failures = 0;
    for (int i = 0; i <= 60; ++i)
    {
      out->SetElement(1, 3, 42.0);
      if (path->InterpolateTransform(i / 20.0, out))
      {
        EXPECT_TRUE(allFinite(out)) << i;
      }
      else
      {
        ++failures;
        EXPECT_EQ(out->GetElement(1, 3), 42.0);
      }
    }
    EXPECT_GT(failures, 0); // the overshoot past 1.7e308 does overflow
    EXPECT_EQ(errors->Count, failures);
    EXPECT_TRUE(contains(errors->Last, "out of the range")) << errors->Last;
  }
}

TEST(Robustness, MonotoneSplineDoesNotOvershootIntoOverflow)
{
  // The keys of the test above: the default Spline's tangents stay below the secants, so the
  // curve stays within [0, 1.65e308] and every point is finite.
  vtkNew<vtkTransformInterpolatorLCT> path;
  addHugePlateau(path);
  vtkNew<vtkMatrix4x4> out;
  for (int i = 0; i <= 60; ++i)
  {
    ASSERT_EQ(path->InterpolateTransform(i / 20.0, out), 1) << i;
    EXPECT_GE(out->GetElement(0, 3), 0.0);
    EXPECT_LE(out->GetElement(0, 3), 1.65e308);
  }
}

TEST(Robustness, BezierWithAMissingLogDoesNotCrash)
{
  // Keys identity and Translate(1e306) Scale(1e-3): the step's translation overflows, so the
  // backward log of the Bezier tangent is missing (it was dereferenced).
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkMatrix4x4> identity;
  vtkNew<vtkTransform> far;
  far->Translate(1e306, 0, 0);
  far->Scale(1e-3, 1e-3, 1e-3);
  path->AddTransform(0.0, identity);
  const int added = path->AddTransform(1.0, far);
  path->SetInterpolationTypeToBezier();
  vtkNew<vtkMatrix4x4> out;
  for (double t : { 0.0, 0.5, 1.0 })
  {
    if (path->InterpolateTransform(t, out))
    {
      EXPECT_TRUE(allFinite(out)) << t;
    }
  }
  EXPECT_TRUE(added == 1 || errors->Count > 0);
}

TEST(Robustness, TimesOutsideTheRangeAreClampedWithOneWarningAndInfinityIsAnError)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors, warnings;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  path->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<vtkMatrix4x4> a, b, out;
  b->SetElement(0, 3, 1.0);
  path->AddTransform(0.0, a);
  path->AddTransform(1.0, b);
  EXPECT_EQ(path->InterpolateTransform(5.0, out), 1);
  EXPECT_EQ(out->GetElement(0, 3), 1.0);
  EXPECT_EQ(path->InterpolateTransform(-5.0, out), 1);
  EXPECT_EQ(warnings->Count, 1);
  EXPECT_TRUE(contains(warnings->Last, "clamped")) << warnings->Last;
  out->SetElement(2, 3, 42.0);
  EXPECT_EQ(path->InterpolateTransform(std::numeric_limits<double>::infinity(), out), 0);
  EXPECT_EQ(out->GetElement(2, 3), 42.0);
  EXPECT_EQ(errors->Count, 1);
}

TEST(Robustness, KeysInReverseOrderGiveTheSameCurve)
{
  vtkNew<vtkTransformInterpolatorLCT> forward, reverse;
  const int n = 200;
  for (int k = 0; k < n; ++k)
  {
    vtkNew<vtkTransform> a, b;
    a->RotateZ(7.0 * k);
    a->Translate(k, 0.1 * k * k, 0);
    a->Scale(1.0 + 0.01 * k, 1.0, 1.0);
    b->RotateZ(7.0 * (n - 1 - k));
    b->Translate(n - 1 - k, 0.1 * (n - 1 - k) * (n - 1 - k), 0);
    b->Scale(1.0 + 0.01 * (n - 1 - k), 1.0, 1.0);
    ASSERT_EQ(forward->AddTransform(k, a), 1);
    ASSERT_EQ(reverse->AddTransform(n - 1 - k, b), 1);
  }
  vtkNew<vtkMatrix4x4> x, y;
  for (int i = 0; i <= 10 * (n - 1); ++i)
  {
    ASSERT_EQ(forward->InterpolateTransform(i / 10.0, x), 1);
    ASSERT_EQ(reverse->InterpolateTransform(i / 10.0, y), 1);
    for (int e = 0; e < 16; ++e)
    {
      ASSERT_EQ(x->GetElement(e / 4, e % 4), y->GetElement(e / 4, e % 4)) << i;
    }
  }
  // Removing and re-adding in the middle, and replacing, keep it consistent too.
  vtkNew<vtkTransform> middle;
  middle->RotateZ(7.0 * 100);
  middle->Translate(100, 0.1 * 100 * 100, 0);
  middle->Scale(2.0, 1.0, 1.0);
  reverse->RemoveTransform(100.0);
  EXPECT_EQ(reverse->GetNumberOfTransforms(), n - 1);
  reverse->AddTransform(100.0, middle);
  forward->AddTransform(100.0, middle);
  for (int i = 900; i <= 1100; ++i)
  {
    ASSERT_EQ(forward->InterpolateTransform(i / 10.0, x), 1);
    ASSERT_EQ(reverse->InterpolateTransform(i / 10.0, y), 1);
    EXPECT_EQ(x->GetElement(0, 0), y->GetElement(0, 0)) << i;
  }
}

TEST(Robustness, CameraMessagesNameTheTrueCause)
{
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> far;
  far->SetFocalPoint(0, 0, 0);
  far->SetPosition(1e200, 0, 0); // |p|^2 overflows: not "position at the focal point"
  EXPECT_EQ(path->AddCamera(0.0, far), 0);
  EXPECT_TRUE(contains(errors->Last, "exceeds 1e150")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "focal point equals")) << errors->Last;
  vtkNew<vtkCamera> up;
  up->SetPosition(0, 0, 1);
  up->SetViewUp(0, 0, 1);
  EXPECT_EQ(path->AddCamera(1e-7, up), 0);
  EXPECT_TRUE(contains(errors->Last, "t = 1e-07")) << errors->Last;
}

TEST(Robustness, CameraOvershootThatLeavesTheRangeIsAnError)
{
  // Distances 1, 1e149, 1e149, 1: Catmull-Rom's log-distance overshoot passes 1e150 (an error,
  // camera untouched); the default monotone tangents do not overshoot, so every call succeeds.
  for (const bool monotone : { false, true })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    path->SetMonotoneTangents(monotone);
    vtkNew<ErrorCounter> errors;
    path->AddObserver(vtkCommand::ErrorEvent, errors);
    const double distance[4] = { 1.0, 1e149, 1e149, 1.0 };
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkCamera> c;
      c->SetFocalPoint(0, 0, 0);
      c->SetPosition(0, 0, distance[k]);
      c->SetClippingRange(0.1 * distance[k], 10.0 * distance[k]);
      ASSERT_EQ(path->AddCamera(k, c), 1) << errors->Last;
    }
    vtkNew<vtkCamera> out;
    int failures = 0;
    for (int i = 0; i <= 60; ++i)
    {
      if (path->InterpolateCamera(i / 20.0, out))
      {
        EXPECT_TRUE(std::isfinite(out->GetDistance()));
        EXPECT_LE(out->GetDistance(), 1e149 * (1.0 + 1e-12));
        EXPECT_LE(out->GetClippingRange()[1], 1e150);
      }
      else
      {
        ++failures;
      }
    }
    if (monotone)
    {
      EXPECT_EQ(failures, 0) << errors->Last;
    }
    else
    {
      EXPECT_GT(failures, 0);
      EXPECT_TRUE(contains(errors->Last, "exceeds 1e150")) << errors->Last;
    }
  }
}

TEST(Robustness, PathMetricRefusesClosedPathsAndNaNPoints)
{
  vtkNew<vtkCameraPathMetric> metric;
  vtkNew<ErrorCounter> errors;
  metric->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.5, 0.2, 0.1);
  points->InsertNextPoint(-0.3, 0.1, 0.4);
  metric->SetPoints(points);
  // A full orbit: every point ends where it started (it used to read 0 %).
  vtkNew<vtkCollection> orbit;
  for (int k = 0; k <= 12; ++k)
  {
    vtkNew<vtkCamera> c;
    const double a = k * 2.0 * 3.14159265358979323846 / 12.0;
    c->SetPosition(5.0 * std::sin(a), 0, 5.0 * std::cos(a));
    orbit->AddItem(c);
  }
  EXPECT_EQ(metric->EvaluateCameras(orbit), 0);
  EXPECT_TRUE(contains(errors->Last, "closed")) << errors->Last;
  points->InsertNextPoint(std::nan(""), 0, 0);
  EXPECT_EQ(metric->EvaluateCameras(orbit), 0);
  EXPECT_TRUE(contains(errors->Last, "NaN")) << errors->Last;
}

// Defects the fuzz targets found (Testing/Fuzz/README.md, the D ids), each at its regression input.

TEST(FuzzFindings, D24RemoveAtNaNRemovesNothing)
{
  // std::map takes NaN as equivalent to any key (every comparison with it is false): RemoveCamera
  // and RemoveTransform at NaN erased an arbitrary key, silently.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  vtkNew<vtkCameraInterpolatorLCT> cameras;
  vtkNew<vtkCamera> camera;
  cameras->AddCamera(3.0, camera);
  cameras->RemoveCamera(nan);
  EXPECT_EQ(cameras->GetNumberOfCameras(), 1);
  vtkNew<vtkTransformInterpolatorLCT> transforms;
  vtkNew<vtkMatrix4x4> identity;
  transforms->AddTransform(0.0, identity.Get());
  transforms->AddTransform(1.0, identity.Get());
  vtkNew<ErrorCounter> errors;
  transforms->AddObserver(vtkCommand::ErrorEvent, errors);
  transforms->RemoveTransform(nan);
  EXPECT_EQ(transforms->GetNumberOfTransforms(), 2);
}

TEST(FuzzFindings, D25InverseOfAStateWithATranslationNearDblMax)
{
  // Accepted coordinates (translation -1e308 under a stretch e^3): Inverse() refused its own
  // result, whose inverse is the state itself, as "overflows": lct::inverseAffine formed
  // A (A^-1 t) with partial sums beyond DBL_MAX before they cancel. The header promises that
  // Inverse() always succeeds.
  const double c[12] = { -3.4427884565677744e+250, -1e+308, 1, 1, 1, 0.99999994947575033, 1,
    0.999999999999997, 1, 1, 1, 0.99764093151316047 };
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(t->SetLogCoordinates(c), 1) << errors->Last;
  t->Inverse();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  EXPECT_TRUE(allFinite(t->GetMatrix()));
  t->Inverse();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  EXPECT_NEAR(t->GetMatrix()->GetElement(1, 3), -1e308, 1e294);
}

TEST(FuzzFindings, D28MatrixLogInverseOfAnIllConditionedStateWithAHugeTranslation)
{
  // A MatrixLog state of condition ~1e12 with translation ~1e304: its inverse exp(-c) is
  // representable, but the inverse of that, recomputed from its rounded matrix, overflowed, so
  // Inverse() and GetInverse() refused (GetInverse silently held the forward matrix). The inverse
  // of the inverse is the current state: Inverse() no longer recomputes it. exp(-c) itself also
  // overflowed in g(T) (Q^T u) before the products cancelled.
  const double c[12] = { 1.0619472435068445e+305, -1.0619472101725061e+305, 1.0619472252479826e+305,
    46.001245459637104, 43.946666481182774, -4.7979183238333292, -17.050276034799111,
    -23.689808041657486, 69.014164030556628, 38.967879960269144, -4.0643400724087577,
    9.0752236918192892 };
  vtkNew<vtkLogTransform> t;
  t->SetParametrisationToMatrixLog();
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(t->SetLogCoordinates(c), 1) << errors->Last;
  vtkNew<vtkMatrix4x4> forward;
  forward->DeepCopy(t->GetMatrix());
  t->Inverse();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  EXPECT_TRUE(allFinite(t->GetMatrix()));
  t->Inverse();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  for (int i = 0; i < 16; ++i)
  {
    EXPECT_EQ(t->GetMatrix()->GetElement(i / 4, i % 4), forward->GetElement(i / 4, i % 4));
  }
}

TEST(FuzzFindings, D29PolarInverseTwiceOfAnIllConditionedStateWithAHugeTranslation)
{
  // Polar, translation 1e304 under a stretch of condition ~1e12: Inverse() succeeded, but the
  // second Inverse() recomputed the inverse of the inverse from its rounded matrix, which
  // overflowed: "Inverse: the result is out of the range", though Inverse() always succeeds. The
  // inverted state is remembered, so inverting twice restores the state exactly.
  const double p = 9.4247779607693811;
  const double c[12] = { 1.0359053541755143e+304, p, p, 0, 39.477756153424501, 0, p, p, p, p, p,
    -p };
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(t->SetLogCoordinates(c), 1) << errors->Last;
  t->Inverse();
  t->Inverse();
  EXPECT_EQ(errors->Count, 0) << errors->Last;
  double back[12];
  t->GetLogCoordinates(back);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(back[i], c[i]) << i;
  }
  // GetInverse() of the inverted state (DeepCopy + Inverse on a hidden object) likewise.
  t->Inverse();
  vtkLinearTransform* inverse = t->GetLinearInverse();
  inverse->Update();
  EXPECT_TRUE(allFinite(inverse->GetMatrix()));
  EXPECT_EQ(errors->Count, 0) << errors->Last;
}

TEST(FuzzFindings, D30GetInverseOfEveryAcceptedStateSucceeds)
{
  // regression-D30-*: Polar coordinates with translation 3.3e303 are inverted and scaled by pi,
  // which gives a linear part of condition ~1e8 under a translation of 6.5e304. GetInverse()
  // (DeepCopy + Inverse() on a hidden object) reported an error on a state that had been
  // accepted; the inverse is now computed when a state is set. Session 29: that scaled state's
  // exact inverse translation is ~1e313, beyond DBL_MAX; the cofactor inverse had cancelled to a
  // finite, wrong value (this test then took it for an inverse), so the state was accepted. With
  // the inverse from exact minors Scale(pi) is refused, the state kept; Scale(1.5) is accepted
  // in both parametrisations, and GetInverse() holds its inverse.
  const double c[12] = { 3.2973891538478729e+303, 3, 3, 0, 12.506695757449304, 0, 3, 3, 3, 3, 3,
    -3 };
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(t->SetLogCoordinates(c), 1) << errors->Last;
  t->Inverse();
  double inverted[12];
  t->GetLogCoordinates(inverted);
  EXPECT_EQ(t->Scale(3.1415926535897936), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(
    contains(errors->Last, "Scale: the inverse of the resulting transform is not representable"))
    << errors->Last;
  double kept[12];
  t->GetLogCoordinates(kept);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(kept[i], inverted[i]) << i;
  }
  ASSERT_EQ(t->Scale(1.5), 1) << errors->Last;
  for (const int parametrisation : { vtkLogTransform::POLAR, vtkLogTransform::MATRIX_LOG })
  {
    ASSERT_EQ(t->SetParametrisation(parametrisation), 1) << errors->Last;
    double before[12];
    t->GetLogCoordinates(before);
    vtkNew<vtkMatrix4x4> forward;
    forward->DeepCopy(t->GetMatrix());

    // GetInverse() holds the inverse, without an error: its linear part inverts the forward one
    // to eps ||A^-1|| ||A|| (the rounding of the product itself), and it maps the forward
    // translation back to the origin (compared at unit size).
    vtkLinearTransform* inverse = t->GetLinearInverse();
    inverse->Update();
    EXPECT_EQ(errors->Count, 1) << errors->Last;
    ASSERT_TRUE(allFinite(inverse->GetMatrix()));
    const Eigen::Matrix4d m = lct_test::fromVtk(forward);
    const Eigen::Matrix4d mi = lct_test::fromVtk(inverse->GetMatrix());
    const Eigen::Matrix3d linear = mi.topLeftCorner<3, 3>();
    const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
    EXPECT_LT(
      (linear * a - Eigen::Matrix3d::Identity()).norm() / (linear.norm() * a.norm()), 1e-14);
    const double size = m.topRightCorner<3, 1>().norm();
    const Eigen::Vector3d origin =
      linear * (m.topRightCorner<3, 1>() / size) + mi.topRightCorner<3, 1>() / size;
    EXPECT_LT(origin.norm() / linear.norm(), 1e-6) << parametrisation;

    // Inverse() in place hands out the same inverse, and inverting twice restores the state
    // exactly.
    t->Inverse();
    for (int i = 0; i < 16; ++i)
    {
      EXPECT_EQ(t->GetMatrix()->GetElement(i / 4, i % 4), mi(i / 4, i % 4)) << i;
    }
    t->Inverse();
    double after[12];
    t->GetLogCoordinates(after);
    for (int i = 0; i < 12; ++i)
    {
      EXPECT_EQ(after[i], before[i]) << i;
    }
    EXPECT_EQ(errors->Count, 1) << errors->Last;
  }
}

TEST(Robustness, StatesWhoseInverseIsNotRepresentableAreRefusedWhereTheyAreSet)
{
  // The MatrixLog coordinates of the D30 state: exp(c) is representable, exp(-c), the inverse
  // Inverse() hands out, overflows. Refused by every setter that would commit it, so Inverse()
  // and GetInverse() of an accepted state never fail.
  const double c[12] = { -5.1075920722584345e+306, -2.3420892390922072e+306, 2.317310579457469e+306,
    1.8666002182014427, -28.415676084417324, -26.551045802320537, -45.609185203955938,
    8.0329358333579854, 9.3016763984169568, 1.9243244262218102, -27.367795718768143,
    -3.8797025644845782 };
  vtkNew<vtkLogTransform> t;
  t->SetParametrisationToMatrixLog();
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  EXPECT_EQ(t->SetLogCoordinates(c), 0);
  EXPECT_TRUE(contains(errors->Last,
    "SetLogCoordinates: the inverse of the resulting transform "
    "is not representable"))
    << errors->Last;
  EXPECT_TRUE(t->GetMatrix()->IsIdentity());
  // A quarter of it is accepted, with its inverse; half of it is not, so doubling the quarter is
  // refused by Scale and by a linear combination (T (+) T) alike.
  double quarter[12];
  for (int i = 0; i < 12; ++i)
  {
    quarter[i] = 0.25 * c[i];
  }
  ASSERT_EQ(t->SetLogCoordinates(quarter), 1) << errors->Last;
  EXPECT_EQ(t->Scale(2.0), 0);
  EXPECT_TRUE(contains(errors->Last, "Scale: the inverse")) << errors->Last;
  EXPECT_EQ(t->Add(t), 0);
  EXPECT_TRUE(contains(errors->Last, "Add: the inverse")) << errors->Last; // named as called
  double kept[12];
  t->GetLogCoordinates(kept);
  for (int i = 0; i < 12; ++i)
  {
    EXPECT_EQ(kept[i], quarter[i]) << i;
  }
  EXPECT_EQ(errors->Count, 3);
  vtkLinearTransform* inverse = t->GetLinearInverse();
  inverse->Update();
  EXPECT_TRUE(allFinite(inverse->GetMatrix()));
  EXPECT_EQ(errors->Count, 3) << errors->Last;
}

namespace
{
/// The keys of regression-D19-prop-track-steps-two-keys-apart.json (lct-render's cube track):
/// each within the conditioning limit (1e10, 1, 1e4) and joinable to its neighbours, but the
/// step from the first to the last, two keys apart, has condition ~1e14. (In
/// regression-D19-prop-track-missing-log.json, where D19 was found, the first key itself has
/// condition 1e14, which the interpolator refuses on its own since.)
vtkNew<vtkMatrix4x4> d19Key(int k)
{
  vtkNew<vtkTransform> t;
  switch (k)
  {
    case 0:
    {
      const double m[16] = { 1, 0, 0, 0, 0, 18854, 0, 0, 8, 0, 1e10, 0, 0, 0, 0, 1 };
      t->SetMatrix(m);
      break;
    }
    case 1:
      t->RotateWXYZ(340, 0, 1, 0);
      break;
    default:
    {
      t->RotateWXYZ(340, 0, 1, 0);
      const double shear[16] = { 1, 0.3, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
      t->Concatenate(shear);
      t->Scale(1e4, 1, 1);
      break;
    }
  }
  vtkNew<vtkMatrix4x4> m;
  m->DeepCopy(t->GetMatrix());
  return m;
}

const double kD19Times[3] = { 0.0, 2.0, 3.0 };
} // namespace

TEST(FuzzFindings, D33MatrixLogExpOfATurnWoundBeyondTheLimitIsRefused)
{
  // regression-D33-*: MatrixLog coordinates whose rotation part is (5.6e14, 1e8, 5.6e14), a turn
  // of 8e14 rad, were accepted; their exp came back with rows of norm 1.06 (the eigenvalues
  // +-8e14 i carry the angle only to ~0.1 rad), and Inverse() handed out exp(-c), which is not
  // its inverse (m m^-1 had 1.1 on the diagonal). Such a log is now refused with an error and
  // the state kept; a turn of 1e8 rad, within kMaxRotationWinding, still inverts to 1e-7.
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(t->SetParametrisationToMatrixLog(), 1);
  const double wound[12] = { -4, 1, -4, 562949953421312, 100000000, 562949953421312, 0, 0, 0, 0, 0,
    0 };
  const vtkMTimeType mtime = t->GetMTime();
  EXPECT_EQ(t->SetLogCoordinates(wound), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(contains(errors->Last, "cannot be computed accurately")) << errors->Last;
  EXPECT_EQ(t->GetMTime(), mtime);
  double kept[12];
  t->GetLogCoordinates(kept);
  for (double c : kept)
  {
    EXPECT_EQ(c, 0.0);
  }
  // The same scaled into the accepted range: exp(c) exp(-c) = I to the angle's own precision.
  const double turn = 1e8 / std::sqrt(2.0);
  const double within[12] = { -4, 1, -4, turn, 0.5, turn, 0.1, -0.2, 0.05, 0, 0, 0 };
  ASSERT_EQ(t->SetLogCoordinates(within), 1) << errors->Last;
  const Eigen::Matrix4d m = lct_test::fromVtk(t->GetMatrix());
  t->Inverse();
  const Eigen::Matrix4d mi = lct_test::fromVtk(t->GetMatrix());
  EXPECT_LT((m * mi - Eigen::Matrix4d::Identity()).norm(), 1e-6);
  EXPECT_EQ(errors->Count, 1) << errors->Last;
}

TEST(Robustness, PolarExpOfATurnWoundBeyondTheLimitIsRefused)
{
  // The Polar exp took sin and cos of any turn: Scale(1e100) of a 60-degree turn returned 1
  // with an arbitrary rotation, Scale(1e12) one off by 1e-4. Beyond kMaxRotationWinding (1e9
  // rad, the MatrixLog limit too) it is an error with the state kept; at 1e6 it is still exact
  // to the angle's precision (60e6 degrees = 240 degrees mod 360).
  vtkNew<vtkLogTransform> t;
  vtkNew<ErrorCounter> errors;
  t->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkTransform> turn;
  turn->RotateZ(60.0);
  for (const double s : { 1e12, 1e100 })
  {
    ASSERT_EQ(t->SetMatrix(turn->GetMatrix()), 1);
    const vtkMTimeType mtime = t->GetMTime();
    EXPECT_EQ(t->Scale(s), 0) << s;
    EXPECT_TRUE(contains(errors->Last, "cannot be computed accurately")) << errors->Last;
    EXPECT_EQ(t->GetMTime(), mtime);
    EXPECT_NEAR(t->GetMatrix()->GetElement(0, 0), 0.5, 1e-15);
  }
  const int before = errors->Count;
  ASSERT_EQ(t->SetMatrix(turn->GetMatrix()), 1);
  ASSERT_EQ(t->Scale(1e6), 1) << errors->Last;
  EXPECT_NEAR(t->GetMatrix()->GetElement(0, 0), -0.5, 1e-9);
  EXPECT_NEAR(t->GetMatrix()->GetElement(1, 0), -std::sqrt(0.75), 1e-9);
  EXPECT_EQ(errors->Count, before);
  // Log coordinates wound beyond the limit, as D33 for MatrixLog.
  const double wound[12] = { 0, 0, 0, 562949953421312, 100000000, 562949953421312, 0, 0, 0, 0, 0,
    0 };
  EXPECT_EQ(t->SetLogCoordinates(wound), 0);
  EXPECT_TRUE(contains(errors->Last, "cannot be computed accurately")) << errors->Last;
}

TEST(FuzzFindings, D19KeysWhoseCurveNeedsAMissingLogAreRefused)
{
  // lct-render accepted the cube track and stopped mid-render ("interpolating props.cube at
  // t = 0.909 failed"): AddTransform checked only the steps to the neighbours, but a Spline point
  // on the first segment combines the last key about the first. Now the key that completes such
  // a stencil is refused, naming both keys, in any order of the keys; a Linear track takes the
  // keys, and then refuses to become a Spline or to lose the middle key.
  for (int order = 0; order < 2; ++order)
  {
    vtkNew<vtkTransformInterpolatorLCT> path;
    vtkNew<ErrorCounter> errors;
    path->AddObserver(vtkCommand::ErrorEvent, errors);
    int accepted = 0;
    for (int j = 0; j < 3; ++j)
    {
      const int k = order == 0 ? j : 2 - j;
      accepted += path->AddTransform(kD19Times[k], d19Key(k));
    }
    EXPECT_EQ(accepted, 2);
    EXPECT_EQ(errors->Count, 1);
    EXPECT_TRUE(contains(errors->Last,
      "the Spline curve combines the key at t = 3 with the key "
      "at t = 0 as its reference"))
      << errors->Last;
    EXPECT_TRUE(contains(errors->Last, "has no Polar logarithm")) << errors->Last;
    EXPECT_TRUE(contains(errors->Last, "ill-conditioned")) << errors->Last;
    EXPECT_TRUE(contains(errors->Last, "key rejected")) << errors->Last;
    EXPECT_FALSE(contains(errors->Last, "MatrixLog")) << errors->Last;
    EXPECT_FALSE(contains(errors->Last, "use the")) << errors->Last;
    // What was accepted interpolates everywhere.
    vtkNew<vtkMatrix4x4> out;
    for (int i = 0; i <= 60; ++i)
    {
      const double t = path->GetMinimumT() + (path->GetMaximumT() - path->GetMinimumT()) * i / 60.0;
      EXPECT_EQ(path->InterpolateTransform(t, out), 1) << t << ": " << errors->Last;
      EXPECT_TRUE(allFinite(out));
    }
    EXPECT_EQ(errors->Count, 1) << errors->Last;
  }

  vtkNew<vtkTransformInterpolatorLCT> linear;
  linear->SetInterpolationTypeToLinear();
  vtkNew<ErrorCounter> errors;
  linear->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int k = 0; k < 3; ++k)
  {
    ASSERT_EQ(linear->AddTransform(kD19Times[k], d19Key(k)), 1) << errors->Last;
  }
  const vtkMTimeType mtime = linear->GetMTime();
  EXPECT_EQ(linear->SetInterpolationTypeToSpline(), 0);
  EXPECT_TRUE(contains(errors->Last, "SetInterpolationType(Spline): the Spline curve combines"))
    << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "; unchanged.")) << errors->Last;
  EXPECT_EQ(linear->GetInterpolationType(), vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR);
  EXPECT_EQ(linear->RemoveTransform(2.0), 0);
  EXPECT_TRUE(contains(errors->Last,
    "RemoveTransform(2): without this key, the Linear curve "
    "combines the key at t = 3 with the key at t = 0"))
    << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "not removed")) << errors->Last;
  EXPECT_EQ(linear->GetNumberOfTransforms(), 3);
  EXPECT_EQ(linear->GetMTime(), mtime);
  EXPECT_EQ(errors->Count, 2);
  vtkNew<vtkMatrix4x4> out;
  for (int i = 0; i <= 30; ++i)
  {
    EXPECT_EQ(linear->InterpolateTransform(i / 10.0, out), 1) << i << ": " << errors->Last;
  }
  // The end key can go: nothing is joined by its removal.
  EXPECT_EQ(linear->RemoveTransform(3.0), 1);
  EXPECT_EQ(errors->Count, 2) << errors->Last;
}

TEST(Robustness, CurveMessagesNameTheKeysAndTheParametrisationInUse)
{
  // MatrixLog: keys turning 60 degrees apiece with a non-uniform scale; keys 0 and 3 are a half
  // turn apart, which has no real matrix log, and a Subdivision point combines them (a Spline
  // point does not: its stencil is 4 keys, about the middle two). Only there is switching to
  // Polar advised.
  auto turn = [](int k) {
    vtkNew<vtkTransform> t;
    t->RotateZ(60.0 * k);
    t->Scale(2, 1, 1);
    vtkNew<vtkMatrix4x4> m;
    m->DeepCopy(t->GetMatrix());
    return m;
  };
  vtkNew<vtkTransformInterpolatorLCT> path;
  path->SetParametrisationToMatrixLog();
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int k = 0; k < 4; ++k)
  {
    ASSERT_EQ(path->AddTransform(k, turn(k)), 1) << errors->Last;
  }
  EXPECT_EQ(path->SetInterpolationTypeToSubdivision(), 0);
  EXPECT_TRUE(contains(errors->Last,
    "the Subdivision curve combines the key at t = 3 with the key "
    "at t = 0 as its reference, but the step from the key at "
    "t = 0 to the key at t = 3 has no MatrixLog logarithm"))
    << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "no real matrix logarithm")) << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "SetParametrisationToPolar")) << errors->Last;
  // In Polar the same keys are fine for every type.
  ASSERT_EQ(path->SetParametrisationToPolar(), 1) << errors->Last;
  ASSERT_EQ(path->SetInterpolationTypeToSubdivision(), 1) << errors->Last;
  // And back to MatrixLog is refused for the same pair, named as such.
  EXPECT_EQ(path->SetParametrisationToMatrixLog(), 0);
  EXPECT_TRUE(contains(errors->Last, "SetParametrisation(MatrixLog): the Subdivision curve"))
    << errors->Last;
  EXPECT_EQ(path->GetParametrisation(), vtkTransformInterpolatorLCT::POLAR);

  // ConsistentRotation needs Polar's rotation branches: in MatrixLog it was accepted and turned
  // a spin back the short way (principal logs). Refused both ways round.
  vtkNew<vtkTransformInterpolatorLCT> spin;
  spin->SetParametrisationToMatrixLog();
  spin->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int k = 0; k < 4; ++k)
  {
    ASSERT_EQ(spin->AddTransform(k, turn(k)), 1) << errors->Last;
  }
  EXPECT_EQ(spin->ConsistentRotationOn(), 0);
  EXPECT_TRUE(contains(errors->Last,
    "SetConsistentRotation(on): ConsistentRotation continues each key's rotation on the branch"))
    << errors->Last;
  EXPECT_FALSE(spin->GetConsistentRotation());
  ASSERT_EQ(spin->SetParametrisationToPolar(), 1) << errors->Last;
  ASSERT_EQ(spin->ConsistentRotationOn(), 1) << errors->Last;
  EXPECT_EQ(spin->SetParametrisationToMatrixLog(), 0);
  EXPECT_TRUE(contains(errors->Last, "SetParametrisation(MatrixLog): ConsistentRotation"))
    << errors->Last;
  EXPECT_EQ(spin->GetParametrisation(), vtkTransformInterpolatorLCT::POLAR);

  // Polar: a step beyond the conditioning limit, no advice to switch to what is in use.
  vtkNew<vtkTransformInterpolatorLCT> polar;
  polar->SetInterpolationTypeToSubdivision();
  polar->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(polar->AddTransform(kD19Times[0], d19Key(0)), 1);
  ASSERT_EQ(polar->AddTransform(kD19Times[1], d19Key(1)), 1);
  EXPECT_EQ(polar->AddTransform(kD19Times[2], d19Key(2)), 0);
  EXPECT_TRUE(contains(errors->Last, "AddTransform at t = 3: the Subdivision curve"))
    << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "has no Polar logarithm")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "MatrixLog")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "real matrix logarithm")) << errors->Last;
  EXPECT_FALSE(contains(errors->Last, "SetParametrisation")) << errors->Last;
}

TEST(Robustness, EveryAcceptedKeySetInterpolatesEverywhere)
{
  // For every type, both parametrisations and both ConsistentRotation settings: keys drawn from
  // moderate maps and from extreme ones (stretches up to 1e6.5, turns of a half turn with scale),
  // added at random times in random order, removed, and with controls for Bezier. Whatever the
  // interpolator accepts must interpolate at every t in its range: a failure may only be the
  // in-between itself out of range, beyond the conditioning limit (a spline overshoot) or refused
  // as inaccurate between ill-conditioned keys, never a missing logarithm.
  lct_test::RandomTransforms random(1919);
  int refusals = 0;
  int evaluations = 0;
  int failures = 0;
  for (int type = 0; type <= vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER; ++type)
  {
    for (int parametrisation = 0; parametrisation < 2; ++parametrisation)
    {
      for (int consistent = 0; consistent < 2; ++consistent)
      {
        for (int trial = 0; trial < 6; ++trial)
        {
          SCOPED_TRACE(::testing::Message()
            << "type " << type << ", parametrisation " << parametrisation << ", ConsistentRotation "
            << consistent << ", trial " << trial);
          vtkNew<vtkTransformInterpolatorLCT> path;
          vtkNew<ErrorCounter> errors;
          path->AddObserver(vtkCommand::ErrorEvent, errors);
          ASSERT_EQ(path->SetInterpolationType(type), 1);
          ASSERT_EQ(path->SetParametrisation(parametrisation), 1);
          if (consistent && parametrisation == vtkTransformInterpolatorLCT::MATRIX_LOG)
          {
            EXPECT_EQ(path->SetConsistentRotation(consistent), 0); // Polar only
            continue;
          }
          ASSERT_EQ(path->SetConsistentRotation(consistent), 1);
          for (int k = 0; k < 14; ++k)
          {
            const Eigen::Matrix4d m = random.HardKey(true);
            vtkNew<vtkMatrix4x4> key;
            lct_test::toVtk(m, key);
            const double t = std::floor(random.Uniform(0.0, 40.0)) / 4.0;
            refusals += path->AddTransform(t, key) == 0;
            if (random.Uniform(0.0, 1.0) < 0.15)
            {
              refusals += path->RemoveTransform(std::floor(random.Uniform(0.0, 40.0)) / 4.0) == 0;
            }
            if (type == vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER &&
              random.Uniform(0.0, 1.0) < 0.2)
            {
              vtkNew<vtkMatrix4x4> control;
              lct_test::toVtk(m * random.Affine(lct_test::TransformClass::Similarity), control);
              path->SetBezierControls(t, control, nullptr); // refused where no key is at t
            }
          }
          const int before = errors->Count;
          vtkNew<vtkMatrix4x4> out;
          for (int i = 0; i <= 200 && path->GetNumberOfTransforms() > 0; ++i)
          {
            const double t =
              path->GetMinimumT() + (path->GetMaximumT() - path->GetMinimumT()) * i / 200.0;
            ++evaluations;
            if (!path->InterpolateTransform(t, out))
            {
              EXPECT_TRUE(contains(errors->Last, "the combination of the keys failed") ||
                contains(errors->Last, "the absolute logarithms (ConsistentRotation) failed"))
                << errors->Last;
              EXPECT_FALSE(contains(errors->Last, "defect")) << errors->Last;
              EXPECT_FALSE(contains(errors->Last, "logarithm:")) << errors->Last;
            }
            else
            {
              EXPECT_TRUE(allFinite(out));
            }
          }
          failures += errors->Count - before;
        }
      }
    }
  }
  // The draws do reach refusals (the checks are exercised), and most calls interpolate: the
  // in-betweens refused involve the keys of condition up to 1e13 (a quarter of the draws), whose
  // relative steps lose the smallest stretch (InaccurateResult, lct/KeyLogs.h).
  EXPECT_GT(refusals, 50);
  EXPECT_GT(evaluations, 15000); // three of the four parametrisation x ConsistentRotation pairs
  EXPECT_LT(failures, evaluations / 4);
}

// A4 (Testing/Fuzz/README.md): FuzzAnalysis found Factor(Reconstruct(x)) 4.8e-6 away from x on
// an explicit basis of Gram condition 1. The input below is the regression input
// FuzzAnalysis/regression-A4-round-trip-of-a-near-identity-basis decoded as the target decodes
// it: one Polar basis transform I + ~1e-12 noise (the fuzzer's "I + 10^-k" linear part) and the
// coefficient 0.0799. Measured against a long double oracle: the basis log, exp and log are
// accurate (the log of the reconstruction to 5.8e-20 of the exact log of that double matrix),
// but the reconstruction 1 + 3.1e-14 on the diagonal holds its stretch only to 1.1e-16 (1.6e-16
// in the log norm), and the basis's singular value 1.66e-12 turns that into 3.5e-6 in the
// coefficient: the conditioning of factoring near the identity, which the error bound states.
TEST(FuzzFindings, A4FactorOfANearIdentityBasisIsRefusedWhereDoublesCannotHoldIt)
{
  const double rows[16] = { 0x1.00000000006e2p+0, 0x1.c4e5b91135274p-42, -0x1.ce0f79644f868p-42,
    0.0, -0x1.f0fe14579ae1p-41, 0x1.0000000000162p+0, 0x1.f17ef0a1528f5p-42, 0.0,
    -0x1.7e5b6cedc240ap-41, -0x1.dfd6d58fa4c35p-41, 0x1.ffffffffff45ap-1, 0.0, 0.0, -0.0, 0.0,
    1.0 };
  const double coefficient = 0x1.4773f7d9a4dabp-4; // 0.0799445802352269
  vtkNew<vtkMatrix4x4> b;
  b->DeepCopy(rows);
  vtkNew<vtkTransformBasisLCT> basis;
  vtkNew<ErrorCounter> errors;
  basis->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(basis->AddBasisTransform(b), 1);
  ASSERT_EQ(basis->GetRank(), 1);
  EXPECT_LT(basis->GetConditionNumber(), 1e4); // what the fuzz check asked of the basis
  vtkNew<vtkDoubleArray> sigma;
  basis->GetSingularValues(sigma);
  EXPECT_LT(sigma->GetValue(0), 1e-11);

  vtkNew<vtkDoubleArray> x;
  x->InsertNextValue(coefficient);
  vtkNew<vtkMatrix4x4> t;
  ASSERT_EQ(basis->Reconstruct(x, t), 1);

  // Refused, with the cause, the coefficients untouched.
  vtkNew<vtkDoubleArray> back;
  back->InsertNextValue(42.0);
  EXPECT_EQ(basis->Factor(t, back), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(contains(errors->Last, "cannot be computed accurately")) << errors->Last;
  EXPECT_TRUE(contains(errors->Last, "smallest singular value")) << errors->Last;
  ASSERT_EQ(back->GetNumberOfTuples(), 1);
  EXPECT_EQ(back->GetValue(0), 42.0);

  // Accepting any bound gives the miss the fuzzer saw, within the stated bound, and beyond what
  // the default tolerance accepts.
  EXPECT_EQ(basis->SetCoefficientTolerance(std::numeric_limits<double>::infinity()), 1);
  ASSERT_EQ(basis->Factor(t, back), 1);
  const double miss = std::abs(back->GetValue(0) - coefficient);
  const double bound = basis->GetCoefficientErrorBound();
  EXPECT_GT(miss, 1e-6 * (1.0 + coefficient));
  EXPECT_LE(miss, bound);
  EXPECT_GT(bound, 1e-6 * (1.0 + std::abs(back->GetValue(0))));

  // The same transform on a basis further from the identity (exp(1e9 log B)) factors within the
  // default tolerance: the basis's size, not its Gram condition, was the cause. (Its coefficient
  // 8e-11 is still known only to ~1e-3 of itself: T's rounding is in T, whatever the basis.)
  EXPECT_EQ(basis->SetCoefficientTolerance(1e-6), 1);
  vtkNew<vtkDoubleArray> far;
  far->InsertNextValue(1e9);
  vtkNew<vtkMatrix4x4> farTransform;
  ASSERT_EQ(basis->Reconstruct(far, farTransform), 1);
  vtkNew<vtkTransformBasisLCT> scaled;
  ASSERT_EQ(scaled->AddBasisTransform(farTransform), 1);
  ASSERT_EQ(scaled->Factor(t, back), 1);
  EXPECT_NEAR(back->GetValue(0) * 1e9, coefficient, 1e-2 * coefficient);
  EXPECT_LE(scaled->GetCoefficientErrorBound(), 1e-6 * (1.0 + std::abs(back->GetValue(0))));

  // Bad tolerances are refused and change nothing.
  const int before = errors->Count;
  EXPECT_EQ(basis->SetCoefficientTolerance(0.0), 0);
  EXPECT_EQ(basis->SetCoefficientTolerance(-1.0), 0);
  EXPECT_EQ(basis->SetCoefficientTolerance(std::numeric_limits<double>::quiet_NaN()), 0);
  EXPECT_EQ(errors->Count, before + 3);
  EXPECT_EQ(basis->GetCoefficientTolerance(), 1e-6);
}

namespace
{
/// Every value in `bad` is refused by set (0, one error naming the setter, the setting and the
/// modification time unchanged); `good` is then accepted.
template <typename Object, typename Value, typename Get>
void expectRefusedOutsideRange(Object* object, int (Object::*set)(Value), Get get,
  std::initializer_list<Value> bad, Value good, const char* setter)
{
  vtkNew<ErrorCounter> errors;
  const unsigned long observer = object->AddObserver(vtkCommand::ErrorEvent, errors);
  for (const Value value : bad)
  {
    const Value before = (object->*get)();
    const vtkMTimeType mtime = object->GetMTime();
    const int count = errors->Count;
    EXPECT_EQ((object->*set)(value), 0) << setter << "(" << value << ")";
    EXPECT_EQ(errors->Count, count + 1) << setter << "(" << value << ")";
    EXPECT_TRUE(contains(errors->Last, setter)) << errors->Last;
    EXPECT_EQ((object->*get)(), before) << setter << "(" << value << ")";
    EXPECT_EQ(object->GetMTime(), mtime) << setter << "(" << value << ")";
  }
  EXPECT_EQ((object->*set)(good), 1) << setter << "(" << good << ")";
  EXPECT_EQ((object->*get)(), good) << setter;
  object->RemoveObserver(observer);
}
} // namespace

TEST(Robustness, SettersRefuseValuesOutOfRangeInsteadOfClampingThem)
{
  // vtkSetClampMacro clamped these silently (SetConstantSpeedMeasure(7) set the focal point,
  // SetAspect(NaN) stored NaN); each is now refused with an error and changes nothing.
  const double nan = std::nan("");
  vtkNew<vtkCameraInterpolatorLCT> camera;
  expectRefusedOutsideRange(camera.Get(), &vtkCameraInterpolatorLCT::SetConstantSpeedMeasure,
    &vtkCameraInterpolatorLCT::GetConstantSpeedMeasure, { -1, 3, 7 },
    static_cast<int>(vtkCameraInterpolatorLCT::CONSTANT_SPEED_EYE), "SetConstantSpeedMeasure");
  expectRefusedOutsideRange(camera.Get(), &vtkCameraInterpolatorLCT::SetInterpolationType,
    &vtkCameraInterpolatorLCT::GetInterpolationType, { -1, 4 }, 0, "SetInterpolationType");
  vtkNew<vtkTransformInterpolatorLCT> path;
  expectRefusedOutsideRange(path.Get(), &vtkTransformInterpolatorLCT::SetInterpolationType,
    &vtkTransformInterpolatorLCT::GetInterpolationType, { -1, 5 }, 0, "SetInterpolationType");
  vtkNew<vtkCameraPathMetric> metric;
  expectRefusedOutsideRange(metric.Get(), &vtkCameraPathMetric::SetAspect,
    &vtkCameraPathMetric::GetAspect,
    { nan, 0.0, -1.0, 1e7, std::numeric_limits<double>::infinity() }, 2.0, "SetAspect");
  expectRefusedOutsideRange(metric.Get(), &vtkCameraPathMetric::SetNumberOfSamples,
    &vtkCameraPathMetric::GetNumberOfSamples, { 1, -5, 100001 }, 10, "SetNumberOfSamples");
  expectRefusedOutsideRange(metric.Get(), &vtkCameraPathMetric::SetSamplesPerSegment,
    &vtkCameraPathMetric::GetSamplesPerSegment, { 1, 1001 }, 20, "SetSamplesPerSegment");
  vtkNew<vtkInterpolatorCueLCT> cue;
  expectRefusedOutsideRange(cue.Get(), &vtkInterpolatorCueLCT::SetKeyTimeMapping,
    &vtkInterpolatorCueLCT::GetKeyTimeMapping, { -1, 2 },
    static_cast<int>(vtkInterpolatorCueLCT::KEY_TIME_MAPPING_CUE_TIME), "SetKeyTimeMapping");
  vtkNew<vtkProbeDeformerLCT> deformer;
  expectRefusedOutsideRange(deformer.Get(), &vtkProbeDeformerLCT::SetBlendMode,
    &vtkProbeDeformerLCT::GetBlendMode, { -1, 4 },
    static_cast<int>(vtkProbeDeformerLCT::DUAL_QUATERNION), "SetBlendMode");
  expectRefusedOutsideRange(deformer.Get(), &vtkProbeDeformerLCT::SetWeightMode,
    &vtkProbeDeformerLCT::GetWeightMode, { -1, 3 }, static_cast<int>(vtkProbeDeformerLCT::CUTOFF),
    "SetWeightMode");
  expectRefusedOutsideRange(deformer.Get(), &vtkProbeDeformerLCT::SetNormalization,
    &vtkProbeDeformerLCT::GetNormalization, { -1, 3 },
    static_cast<int>(vtkProbeDeformerLCT::NORMALIZE_NONE), "SetNormalization");
  expectRefusedOutsideRange(deformer.Get(), &vtkProbeDeformerLCT::SetSerialThreshold,
    &vtkProbeDeformerLCT::GetSerialThreshold, { vtkIdType(-1) }, vtkIdType(5),
    "SetSerialThreshold");
  vtkNew<vtkShapeBlenderLCT> blender;
  expectRefusedOutsideRange(blender.Get(), &vtkShapeBlenderLCT::SetSerialThreshold,
    &vtkShapeBlenderLCT::GetSerialThreshold, { vtkIdType(-3) }, vtkIdType(0), "SetSerialThreshold");
  vtkNew<vtkTransformBasisLCT> basis;
  expectRefusedOutsideRange(basis.Get(), &vtkTransformBasisLCT::SetMaximumRank,
    &vtkTransformBasisLCT::GetMaximumRank, { -1, 13 }, 3, "SetMaximumRank");
  vtkNew<vtkTransformSequencePCA> pca;
  expectRefusedOutsideRange(pca.Get(), &vtkTransformSequencePCA::SetParametrisation,
    &vtkTransformSequencePCA::GetParametrisation, { -1, 2 },
    static_cast<int>(vtkTransformSequencePCA::MATRIX_LOG), "SetParametrisation");
  expectRefusedOutsideRange(pca.Get(), &vtkTransformSequencePCA::SetMaximumNumberOfComponents,
    &vtkTransformSequencePCA::GetMaximumNumberOfComponents, { -1 }, 4,
    "SetMaximumNumberOfComponents");
}

TEST(Robustness, LinearCombinationWithANullArgumentIsAnError)
{
  // It was a warning (vtkGenericWarningMacro), which error observers and scripts that watch
  // for errors missed.
  vtkNew<vtkLogTransform> result;
  vtkNew<ErrorCounter> errors;
  result->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCollection> transforms;
  vtkNew<vtkDoubleArray> weights;
  const vtkMTimeType mtime = result->GetMTime();
  EXPECT_EQ(vtkLogTransform::LinearCombination(transforms, nullptr, result), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_TRUE(contains(errors->Last, "null weights")) << errors->Last;
  EXPECT_EQ(vtkLogTransform::LinearCombination(nullptr, weights, result), 0);
  EXPECT_TRUE(contains(errors->Last, "null transforms")) << errors->Last;
  EXPECT_EQ(result->GetMTime(), mtime);
}

// Audit (session 29): vtkTransformSequencePCA::RemoveAllFrames kept the root channel its header
// says goes with the frames, so the next sequence had a channel silently factored out.
TEST(Robustness, SequencePCARemoveAllFramesForgetsTheRootChannel)
{
  vtkNew<vtkTransformSequencePCA> pca;
  for (int f = 0; f < 5; ++f)
  {
    vtkNew<vtkCollection> frame;
    for (int c = 0; c < 3; ++c)
    {
      vtkNew<vtkTransform> t;
      t->RotateWXYZ((10.0 + c) * f, c == 0, c == 1, c == 2);
      frame->AddItem(t);
    }
    ASSERT_EQ(pca->AddFrame(frame), 1);
  }
  pca->SetRootChannel(2);
  ASSERT_EQ(pca->Compute(), 1);
  pca->RemoveAllFrames();
  EXPECT_EQ(pca->GetRootChannel(), -1);
}
