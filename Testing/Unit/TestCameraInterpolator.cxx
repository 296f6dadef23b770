// vtkCameraInterpolatorLCT: every camera parameter of a key reproduced (window centre and view
// shear included), large turns without failure, the short way and full orbits, and every bad key.
#include "vtkCameraInterpolatorLCT.h"

#include "RandomTransforms.h"
#include "VtkTestHelpers.h"
#include "lct/CameraKey.h"
#include "vtkLCTCameraParameters.h"

#include "vtkCamera.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace
{
using lct_test::ErrorCounter;

struct CameraKeySpec
{
  double t;
  Eigen::Vector3d position, focal, up;
  double angle;
  Eigen::Vector2d center;
  Eigen::Vector3d shear;
};

void apply(const CameraKeySpec& k, vtkCamera* c, bool parallel)
{
  c->SetFocalPoint(k.focal.data());
  c->SetPosition(k.position.data());
  c->SetViewUp(k.up.data());
  c->SetParallelProjection(parallel);
  c->SetViewAngle(k.angle);
  c->SetParallelScale(k.angle / 10.0);
  c->SetWindowCenter(k.center[0], k.center[1]);
  c->SetViewShear(k.shear[0], k.shear[1], k.shear[2]);
  const double d = (k.position - k.focal).norm();
  c->SetClippingRange(0.1 * d, 3.0 * d);
}

Eigen::Vector3d get3(const double* v)
{
  return Eigen::Vector3d(v[0], v[1], v[2]);
}

/// Position, focal point, view plane normal, orthogonalised up, angle/scale, centre, shear,
/// clipping.
double cameraDifference(vtkCamera* a, vtkCamera* b)
{
  double d = 0.0;
  d = std::max(d, (get3(a->GetPosition()) - get3(b->GetPosition())).norm());
  d = std::max(d, (get3(a->GetFocalPoint()) - get3(b->GetFocalPoint())).norm());
  a->OrthogonalizeViewUp();
  b->OrthogonalizeViewUp();
  d = std::max(d, (get3(a->GetViewUp()) - get3(b->GetViewUp())).norm());
  d = std::max(d, std::abs(a->GetViewAngle() - b->GetViewAngle()) / 180.0);
  d = std::max(d, std::abs(a->GetParallelScale() - b->GetParallelScale()));
  d = std::max(d, std::abs(a->GetWindowCenter()[0] - b->GetWindowCenter()[0]));
  d = std::max(d, std::abs(a->GetWindowCenter()[1] - b->GetWindowCenter()[1]));
  d = std::max(d, (get3(a->GetViewShear()) - get3(b->GetViewShear())).norm());
  d = std::max(d, std::abs(a->GetClippingRange()[0] - b->GetClippingRange()[0]));
  d = std::max(d, std::abs(a->GetClippingRange()[1] - b->GetClippingRange()[1]));
  return d;
}

std::vector<CameraKeySpec> randomKeys(int seed, int n)
{
  lct_test::RandomTransforms random(seed);
  std::vector<CameraKeySpec> keys;
  double t = 0.0;
  for (int i = 0; i < n; ++i)
  {
    CameraKeySpec k;
    k.t = t;
    k.focal = Eigen::Vector3d(random.Normal(), random.Normal(), random.Normal());
    k.position = k.focal + random.LogUniform(2.0, 20.0) * random.UnitVector();
    k.up = random.UnitVector();
    k.angle = random.Uniform(10.0, 90.0);
    k.center = Eigen::Vector2d(random.Uniform(-0.5, 0.5), random.Uniform(-0.5, 0.5));
    k.shear = Eigen::Vector3d(
      random.Uniform(-0.3, 0.3), random.Uniform(-0.3, 0.3), random.Uniform(0.5, 1.5));
    keys.push_back(k);
    t += random.Uniform(0.5, 2.0);
  }
  return keys;
}

double azimuthDegrees(vtkCamera* c)
{
  const double* p = c->GetPosition();
  return std::atan2(p[1], p[0]) * 180.0 / lct_test::kPi;
}

/// A camera on a circle of radius 5 about the origin in the xy plane, at `degrees` azimuth.
void orbitKey(double degrees, vtkCamera* c)
{
  const double a = degrees * lct_test::kPi / 180.0;
  c->SetFocalPoint(0, 0, 0);
  c->SetPosition(5 * std::cos(a), 5 * std::sin(a), 0);
  c->SetViewUp(0, 0, 1);
}

} // namespace

TEST(CameraInterpolatorLCT, ReproducesEveryParameterOfEveryKey)
{
  for (bool parallel : { false, true })
  {
    const auto keys = randomKeys(parallel ? 2 : 1, 6);
    for (int type : { 0, 1, 3 })
    {
      vtkNew<vtkCameraInterpolatorLCT> interpolator;
      interpolator->SetInterpolationType(type);
      for (const auto& k : keys)
      {
        vtkNew<vtkCamera> c;
        apply(k, c, parallel);
        ASSERT_EQ(interpolator->AddCamera(k.t, c), 1);
      }
      for (const auto& k : keys)
      {
        vtkNew<vtkCamera> expected, out;
        apply(k, expected, parallel);
        ASSERT_EQ(interpolator->InterpolateCamera(k.t, out), 1);
        EXPECT_LT(cameraDifference(out, expected), 1e-11) << "type " << type << " t " << k.t;
        EXPECT_EQ(out->GetParallelProjection(), parallel ? 1 : 0);
      }
    }
  }
}

TEST(CameraInterpolatorLCT, LargeTurnsBetweenKeysNeverFail)
{
  // The paper's iterative square root failed on turns >= 90 degrees; 1000 key pairs turning
  // 90-180 degrees about random axes through the focal point: every in-between is a valid camera
  // at the geometric mean distance halfway, looking at the focal point.
  lct_test::RandomTransforms random(3);
  int failures = 0;
  for (int i = 0; i < 1000; ++i)
  {
    const Eigen::Vector3d focal(random.Normal(), random.Normal(), random.Normal());
    const Eigen::Vector3d dir = random.UnitVector();
    const Eigen::Matrix3d turn =
      random.Rotation(random.Uniform(lct_test::kPi / 2, lct_test::kPi - 1e-6));
    const double d0 = random.LogUniform(1.0, 10.0);
    const double d1 = random.LogUniform(1.0, 10.0);
    vtkNew<vtkCamera> a, b;
    a->SetFocalPoint(focal.data());
    b->SetFocalPoint(focal.data());
    const Eigen::Vector3d pa = focal + d0 * dir;
    const Eigen::Vector3d pb = focal + d1 * (turn * dir);
    const Eigen::Vector3d upA = dir.unitOrthogonal();
    const Eigen::Vector3d upB = turn * upA;
    a->SetPosition(pa.data());
    b->SetPosition(pb.data());
    a->SetViewUp(upA.data());
    b->SetViewUp(upB.data());
    vtkNew<vtkCameraInterpolatorLCT> interpolator;
    interpolator->SetInterpolationTypeToLinear();
    if (!interpolator->AddCamera(0.0, a) || !interpolator->AddCamera(1.0, b))
    {
      ++failures;
      continue;
    }
    vtkNew<vtkCamera> mid;
    if (!interpolator->InterpolateCamera(0.5, mid))
    {
      ++failures;
      continue;
    }
    const double distance = mid->GetDistance();
    const bool ok = std::isfinite(distance) &&
      std::abs(distance - std::sqrt(d0 * d1)) < 1e-9 * distance &&
      (get3(mid->GetFocalPoint()) - focal).norm() < 1e-9;
    failures += ok ? 0 : 1;
    if (!ok && failures == 1)
    {
      ADD_FAILURE() << "distance " << distance << " expected " << std::sqrt(d0 * d1) << " focal "
                    << (get3(mid->GetFocalPoint()) - focal).norm();
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(CameraInterpolatorLCT, ShortWayOverHalfATurnAndFullOrbits)
{
  vtkNew<vtkCameraInterpolatorLCT> halfTurn;
  halfTurn->SetInterpolationTypeToLinear();
  vtkNew<vtkCamera> a, b, out;
  orbitKey(0, a);
  orbitKey(200, b);
  halfTurn->AddCamera(0, a);
  halfTurn->AddCamera(1, b);
  halfTurn->InterpolateCamera(0.5, out);
  EXPECT_NEAR(azimuthDegrees(out), -80.0, 1e-9); // 0 -> 200 the short way: -160

  // An orbit of 420 degrees in 60 degree steps: the spline passes every key and turns forward.
  vtkNew<vtkCameraInterpolatorLCT> orbit;
  for (int k = 0; k <= 7; ++k)
  {
    vtkNew<vtkCamera> key;
    orbitKey(60.0 * k, key);
    ASSERT_EQ(orbit->AddCamera(k, key), 1);
  }
  for (int i = 0; i <= 70; ++i)
  {
    const double t = i / 10.0;
    orbit->InterpolateCamera(t, out);
    EXPECT_NEAR(std::remainder(azimuthDegrees(out) - 60.0 * t, 360.0), 0.0, 1e-6) << t;
    EXPECT_NEAR(out->GetDistance(), 5.0, 1e-9);
  }
}

TEST(CameraInterpolatorLCT, OrbitsOfUpTo170DegreesPerKeyTurnEvenly)
{
  // An orbit 100-170 degrees per key: every scheme turns forward at the keys' even rate (the
  // keys are evenly timed and spaced). Combining the key two steps away the short way turned
  // 100-170 degree orbits back by up to 4 degrees and off the even rate by up to 21.
  for (const double step : { 100.0, 135.0, 170.0 })
  {
    for (const int type : { vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
           vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION })
    {
      vtkNew<vtkCameraInterpolatorLCT> orbit;
      ASSERT_EQ(orbit->SetInterpolationType(type), 1);
      for (int k = 0; k <= 5; ++k)
      {
        vtkNew<vtkCamera> key;
        orbitKey(step * k, key);
        ASSERT_EQ(orbit->AddCamera(k, key), 1);
      }
      vtkNew<vtkCamera> out;
      for (int i = 0; i <= 100; ++i)
      {
        const double t = i / 20.0;
        ASSERT_EQ(orbit->InterpolateCamera(t, out), 1);
        EXPECT_NEAR(std::remainder(azimuthDegrees(out) - step * t, 360.0), 0.0, 1e-6)
          << step << " degrees per key, type " << type << ", t = " << t;
      }
    }
  }
}

TEST(CameraInterpolatorLCT, KeysOnOneScrewMotionAreFollowedAlongIt)
{
  // A camera looking in at a focal point that climbs a helix, 60-170 degrees per key: the focal
  // frames are samples of one screw motion, which the screw-motion default reproduces between
  // the keys when it takes the rotation of a key two or three steps away as the orientations
  // do (continued through the keys between). With the principal step the Spline strayed 1.07
  // from the helix at 120 degrees per key and beyond.
  const auto helixKey = [](double degreesPerKey, double s, vtkCamera* c) {
    const double a = degreesPerKey * s * lct_test::kPi / 180.0;
    c->SetFocalPoint(3 * std::cos(a), 3 * std::sin(a), s);
    c->SetPosition(8 * std::cos(a), 8 * std::sin(a), s);
    c->SetViewUp(0, 0, 1);
  };
  for (const double step : { 60.0, 100.0, 135.0, 170.0 })
  {
    for (const int type : { vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR,
           vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
           vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION })
    {
      if (type == vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION && step > 110.0)
      {
        continue; // three steps reach 2 pi - 0.25: the screw takes the principal one there
      }
      vtkNew<vtkCameraInterpolatorLCT> path;
      ASSERT_EQ(path->SetInterpolationType(type), 1);
      for (int k = 0; k <= 5; ++k)
      {
        vtkNew<vtkCamera> key;
        helixKey(step, k, key);
        ASSERT_EQ(path->AddCamera(k, key), 1);
      }
      vtkNew<vtkCamera> out, expected;
      double worst = 0.0;
      for (int i = 0; i <= 100; ++i)
      {
        const double t = i / 20.0;
        ASSERT_EQ(path->InterpolateCamera(t, out), 1);
        helixKey(step, t, expected);
        worst =
          std::max({ worst, (get3(out->GetFocalPoint()) - get3(expected->GetFocalPoint())).norm(),
            (get3(out->GetPosition()) - get3(expected->GetPosition())).norm() });
      }
      EXPECT_LT(worst, 1e-12) << step << " degrees per key, type " << type;
    }
  }
}

// Keys are judged relative to their own magnitude: a scene 1e-12 across (position 5e-13 from the
// focal point) was refused as "closer than 1e-12 of their magnitude", which it is not.
TEST(CameraInterpolatorLCT, SmallScenesAreKeysLikeAnyOther)
{
  vtkNew<vtkCameraInterpolatorLCT> interpolator;
  vtkNew<ErrorCounter> errors;
  interpolator->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> a, b, out;
  a->SetPosition(0, 0, 5e-13);
  a->SetFocalPoint(0, 0, 0);
  a->SetClippingRange(1e-14, 1e-12);
  b->SetPosition(5e-13, 0, 0);
  b->SetFocalPoint(0, 0, 0);
  b->SetClippingRange(1e-14, 1e-12);
  ASSERT_EQ(interpolator->AddCamera(0.0, a), 1) << errors->Last;
  ASSERT_EQ(interpolator->AddCamera(1.0, b), 1) << errors->Last;
  ASSERT_EQ(interpolator->InterpolateCamera(1.0, out), 1);
  EXPECT_LE((get3(out->GetPosition()) - get3(b->GetPosition())).norm(), 1e-12 * 5e-13);
  ASSERT_EQ(interpolator->InterpolateCamera(0.5, out), 1);
  EXPECT_NEAR((get3(out->GetPosition()) - get3(out->GetFocalPoint())).norm(), 5e-13, 1e-24);
  EXPECT_EQ(errors->Count, 0);
}

// Audit (session 28): vtkCamera clamps a distance below 1e-20 along its PREVIOUS direction of
// projection. Keys exactly 1e-20 from their focal point gave in-betweens an ulp below it, and
// the output camera looked wherever it looked before (down -z, with status 1); a core key closer
// than that was accepted and then moved by vtkCamera.
TEST(CameraInterpolatorLCT, DistancesAtVtkCamerasMinimumKeepTheirDirection)
{
  vtkNew<vtkCameraInterpolatorLCT> interpolator;
  vtkNew<ErrorCounter> errors;
  interpolator->AddObserver(vtkCommand::ErrorEvent, errors);
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkCamera> key;
    key->SetFocalPoint(0, 0, 0);
    key->SetPosition(1e-20 * std::sin(0.7 * k), 0, 1e-20 * std::cos(0.7 * k));
    key->SetViewUp(0, 1, 0);
    key->SetClippingRange(1e-22, 1e-18);
    ASSERT_EQ(interpolator->AddCamera(k, key), 1) << errors->Last;
  }
  for (int s = 0; s <= 40; ++s)
  {
    const double t = 2.0 * s / 40.0;
    // Each output starts from a camera that looks elsewhere (down -z, or where it was last).
    vtkNew<vtkCamera> out;
    out->SetPosition(0, 0, 1);
    out->SetFocalPoint(0, 0, 5);
    ASSERT_EQ(interpolator->InterpolateCamera(t, out), 1) << errors->Last;
    const double* d = out->GetDirectionOfProjection();
    // The orbit turns by 0.7 rad per key: the camera looks back at the focal point from there.
    EXPECT_NEAR(d[0], -std::sin(0.7 * t), 1e-6) << t;
    EXPECT_NEAR(d[2], -std::cos(0.7 * t), 1e-6) << t;
    EXPECT_GE(out->GetDistance(), 1e-20);
    EXPECT_LE(std::abs(out->GetFocalPoint()[2]), 1e-26) << t;
  }
  lct::CameraParameters closer;
  closer.position = Eigen::Vector3d(0, 0, 9e-21);
  const char* why = "";
  EXPECT_FALSE(lct::toCameraKey(closer, &why).ok());
  EXPECT_NE(std::string(why).find("closer than 1e-20 (vtkCamera clamps"), std::string::npos) << why;
  EXPECT_EQ(errors->Count, 0);
}

// ConstantSpeed on a path whose eye and focal point stay put (a zoom, a roll): every interval is
// still, so the keys keep their times. The eye's round-off (1e-15) set the timing before.
TEST(CameraInterpolatorLCT, ConstantSpeedKeepsTheTimesOfAStillPath)
{
  vtkNew<vtkCameraInterpolatorLCT> interpolator;
  const auto key = [&](double t, double angle, double upX) {
    vtkNew<vtkCamera> c;
    c->SetPosition(0, 0, 10);
    c->SetFocalPoint(0, 0, 0);
    c->SetViewUp(upX, 1, 0);
    c->SetViewAngle(angle);
    ASSERT_EQ(interpolator->AddCamera(t, c), 1);
  };
  key(0.0, 10.0, 0.0);
  key(1.0, 60.0, 0.0);
  key(5.0, 20.0, 1.0);
  interpolator->SetConstantSpeed(1);
  vtkNew<vtkDoubleArray> arrivals;
  ASSERT_EQ(interpolator->GetKeyArrivalTimes(arrivals), 1);
  ASSERT_EQ(arrivals->GetNumberOfTuples(), 3);
  EXPECT_EQ(arrivals->GetValue(1), 1.0);
  vtkNew<vtkCamera> out;
  ASSERT_EQ(interpolator->InterpolateCamera(1.0, out), 1);
  EXPECT_NEAR(out->GetViewAngle(), 60.0, 1e-9);
}

TEST(CameraInterpolatorLCT, BadKeysAreRejectedAndLeaveTheInterpolatorUnchanged)
{
  vtkNew<vtkCameraInterpolatorLCT> interpolator;
  vtkNew<ErrorCounter> errors;
  interpolator->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> out;
  out->SetPosition(7, 7, 7);
  EXPECT_EQ(interpolator->InterpolateCamera(0.0, out), 0); // no keys
  EXPECT_EQ(errors->Count, 1);
  EXPECT_EQ(out->GetPosition()[0], 7.0);

  vtkNew<vtkCamera> good;
  ASSERT_EQ(interpolator->AddCamera(0.0, good), 1);
  const vtkMTimeType saved = interpolator->GetMTime();
  int expected = 1;
  auto reject = [&](vtkCamera* c, double t, const char* what, const char* phrase) {
    EXPECT_EQ(interpolator->AddCamera(t, c), 0) << what;
    EXPECT_EQ(errors->Count, ++expected) << what;
    EXPECT_NE(errors->Last.find(phrase), std::string::npos) << what << ": " << errors->Last;
    EXPECT_EQ(interpolator->GetNumberOfCameras(), 1) << what;
    EXPECT_EQ(interpolator->GetMTime(), saved) << what;
  };
  {
    vtkNew<vtkCamera> c; // position at the focal point
    c->SetPosition(0, 0, 0);
    c->SetFocalPoint(0, 0, 0);
    reject(c, 1.0, "position = focal point", "the position equals the focal point");
  }
  {
    vtkNew<vtkCamera> c; // view up along the view direction
    c->SetPosition(0, 0, 5);
    c->SetFocalPoint(0, 0, 0);
    c->SetViewUp(0, 0, 1);
    reject(c, 1.0, "view up parallel", "parallel to the view direction");
  }
  {
    vtkNew<vtkCamera> c;
    c->SetPosition(std::nan(""), 0, 1);
    reject(c, 1.0, "NaN position", "NaN");
  }
  {
    vtkNew<vtkCamera> c;
    c->SetWindowCenter(std::numeric_limits<double>::infinity(), 0);
    reject(c, 1.0, "Inf window centre", "NaN or Inf");
  }
  {
    vtkNew<vtkCamera> c;
    c->ParallelProjectionOn();
    reject(c, 1.0, "parallel among perspective", "cannot be mixed");
  }
  reject(good, std::nan(""), "NaN time", "not finite");
  EXPECT_EQ(interpolator->InterpolateCamera(std::nan(""), out), 0);
  EXPECT_EQ(errors->Count, ++expected);
  {
    // 1e-160 apart (vtkCamera itself keeps 1e-20, so only the core sees it): vtkCamera would
    // clamp it, moving the focal point.
    lct::CameraParameters c;
    c.position = Eigen::Vector3d(0, 0, 1e-160);
    const char* why = "";
    EXPECT_FALSE(lct::toCameraKey(c, &why).ok());
    EXPECT_NE(std::string(why).find("closer than 1e-20"), std::string::npos) << why;
  }
  // SetMethod clamped 7 to CameraMatrix and -3 to FocalFrame, returning 1.
  EXPECT_EQ(interpolator->SetMethod(7), 0);
  EXPECT_NE(errors->Last.find("SetMethod(7): outside [0, 1]"), std::string::npos) << errors->Last;
  EXPECT_EQ(interpolator->GetMethod(), vtkCameraInterpolatorLCT::METHOD_FOCAL_FRAME);
  expected += 1;
  // Replacing the only key by a parallel one is allowed (nothing to mix with).
  vtkNew<vtkCamera> parallel;
  parallel->ParallelProjectionOn();
  EXPECT_EQ(interpolator->AddCamera(0.0, parallel), 1);
  EXPECT_EQ(interpolator->GetNumberOfCameras(), 1);
}

TEST(CameraInterpolatorLCT, PaperCameraMatrixMethodReproducesKeysAndRefusesMissingLogs)
{
  const auto keys = randomKeys(7, 4);
  vtkNew<vtkCameraInterpolatorLCT> interpolator;
  interpolator->SetMethodToCameraMatrix();
  interpolator->SetInterpolationTypeToLinear();
  // Keys turning little: the matrix log exists between neighbours.
  lct_test::RandomTransforms random(8);
  double time = 0.0;
  std::vector<std::pair<double, CameraKeySpec>> used;
  CameraKeySpec k = keys[0];
  for (int i = 0; i < 4; ++i)
  {
    vtkNew<vtkCamera> c;
    apply(k, c, false);
    c->SetViewShear(0, 0, 1); // the matrix method keeps the key's shear channel, like the other
    ASSERT_EQ(interpolator->AddCamera(time, c), 1);
    used.emplace_back(time, k);
    time += 1.0;
    const Eigen::Matrix3d turn = random.Rotation(0.3);
    k.position = k.focal + turn * (k.position - k.focal);
    k.up = turn * k.up;
    k.angle = random.Uniform(20.0, 60.0);
  }
  for (const auto& [t, spec] : used)
  {
    vtkNew<vtkCamera> expected, out;
    apply(spec, expected, false);
    expected->SetViewShear(0, 0, 1);
    ASSERT_EQ(interpolator->InterpolateCamera(t, out), 1);
    EXPECT_LT(cameraDifference(out, expected), 1e-9) << t;
  }
  vtkNew<vtkCamera> mid;
  ASSERT_EQ(interpolator->InterpolateCamera(1.5, mid), 1);

  // A half turn between keys: no real matrix log. The method refuses the key that would need it
  // (it used to accept it and fail at evaluation, D19), naming the keys and the way out.
  vtkNew<vtkCameraInterpolatorLCT> halfTurn;
  halfTurn->SetMethodToCameraMatrix();
  vtkNew<ErrorCounter> errors;
  halfTurn->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> a, b;
  a->SetPosition(0, 0, 5);
  b->SetPosition(0, 0, -5);
  ASSERT_EQ(halfTurn->AddCamera(0, a), 1);
  EXPECT_EQ(halfTurn->AddCamera(1, b), 0);
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->Last.find("the key at t = 1"), std::string::npos) << errors->Last;
  EXPECT_NE(errors->Last.find("the key at t = 0"), std::string::npos) << errors->Last;
  EXPECT_NE(errors->Last.find("no MatrixLog logarithm"), std::string::npos) << errors->Last;
  EXPECT_NE(errors->Last.find("SetMethodToFocalFrame()"), std::string::npos) << errors->Last;
  EXPECT_EQ(halfTurn->GetNumberOfCameras(), 1);
  // The default method has no such limit; switching back to CameraMatrix is refused for the keys
  // it cannot interpolate, and the method kept.
  ASSERT_EQ(halfTurn->SetMethodToFocalFrame(), 1);
  ASSERT_EQ(halfTurn->AddCamera(1, b), 1);
  EXPECT_EQ(halfTurn->InterpolateCamera(0.5, mid), 1);
  EXPECT_EQ(halfTurn->SetMethodToCameraMatrix(), 0);
  EXPECT_EQ(halfTurn->GetMethod(), vtkCameraInterpolatorLCT::METHOD_FOCAL_FRAME);
  EXPECT_EQ(errors->Count, 2);
  EXPECT_NE(errors->Last.find("SetMethod(CameraMatrix)"), std::string::npos) << errors->Last;
  for (int i = 0; i <= 10; ++i)
  {
    EXPECT_EQ(halfTurn->InterpolateCamera(i / 10.0, mid), 1) << i;
  }
  EXPECT_EQ(errors->Count, 2) << errors->Last;
}

TEST(CameraInterpolatorLCT, MonotoneWindowCentresAtTheEndOfTheDoubleRange)
{
  // Window-centre keys (S, 0), (-S, 0), (S, S), (0, 0): the curve over S is the same for every
  // S. At S = 1e308 and beyond the steps between keys overflowed and the tangents silently
  // became Catmull-Rom's.
  const auto path = [](double s, std::vector<double>& out) {
    vtkNew<vtkCameraInterpolatorLCT> interpolator;
    const double centres[4][2] = { { s, 0.0 }, { -s, 0.0 }, { s, s }, { 0.0, 0.0 } };
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkCamera> key;
      key->SetPosition(0, 0, 10);
      key->SetWindowCenter(centres[k][0], centres[k][1]);
      ASSERT_EQ(interpolator->AddCamera(k, key), 1);
    }
    vtkNew<vtkCamera> camera;
    for (int i = 0; i <= 30; ++i)
    {
      ASSERT_EQ(interpolator->InterpolateCamera(i / 10.0, camera), 1);
      out.push_back(camera->GetWindowCenter()[0] / s);
      out.push_back(camera->GetWindowCenter()[1] / s);
    }
  };
  std::vector<double> unit, huge;
  path(1.7, unit);
  path(1.7e308, huge);
  ASSERT_EQ(unit.size(), huge.size());
  for (std::size_t i = 0; i < unit.size(); ++i)
  {
    EXPECT_NEAR(unit[i], huge[i], 1e-12) << i;
  }
  EXPECT_NEAR(unit[10], -0.23607, 1e-5); // t = 0.5: monotone, not Catmull-Rom's -0.25
}

TEST(CameraInterpolatorLCT, CameraMatrixMethodGivesEveryAcceptedKeyBackAtItsTime)
{
  // A window centre of 1e20 leaves Hawkins & Grimm's P_b S V without the key's digits: the key
  // was accepted and then refused at its own time ("NaN or Inf"). Now refused when added, and
  // SetMethod(CameraMatrix) refuses keys added under FocalFrame, the method kept.
  vtkNew<ErrorCounter> errors;
  vtkNew<vtkCamera> key, out;
  key->SetPosition(0, 0, 10);
  key->SetFocalPoint(0, 0, 0);
  for (const double centre : { 1e10, 1e15, 1e20, 1e100 })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    path->AddObserver(vtkCommand::ErrorEvent, errors);
    ASSERT_EQ(path->SetMethodToCameraMatrix(), 1);
    key->SetWindowCenter(centre, 0.0);
    const int before = errors->Count;
    if (path->AddCamera(0.0, key))
    {
      ASSERT_EQ(path->InterpolateCamera(0.0, out), 1) << centre;
      EXPECT_NEAR(out->GetWindowCenter()[0] / centre, 1.0, 1e-9) << centre;
    }
    else
    {
      EXPECT_GE(centre, 1e20);
      EXPECT_EQ(errors->Count, before + 1);
      EXPECT_NE(errors->Last.find("not given back by its own camera matrix"), std::string::npos)
        << errors->Last;
      ASSERT_EQ(path->SetMethodToFocalFrame(), 1);
      ASSERT_EQ(path->AddCamera(0.0, key), 1);
      EXPECT_EQ(path->SetMethodToCameraMatrix(), 0);
      EXPECT_EQ(path->GetMethod(), vtkCameraInterpolatorLCT::METHOD_FOCAL_FRAME);
      ASSERT_EQ(path->InterpolateCamera(0.0, out), 1);
      EXPECT_EQ(out->GetWindowCenter()[0], centre);
    }
  }
  // A key whose camera matrix double cannot check the determinant of (a scene at 1e-100, window
  // centre -1e300, view angle 179, clipping range from 1e-300) was refused as inaccurate at its
  // own time: a key at its time is itself.
  vtkNew<vtkCameraInterpolatorLCT> path;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  ASSERT_EQ(path->SetMethodToCameraMatrix(), 1);
  key->SetPosition(5.6565715657623136e-101, 1.3670329043305083e-100, 1.799344378782324e-101);
  key->SetFocalPoint(5.6565715657623136e-101, 1.3670329043305083e-100, -1e-20);
  key->SetViewUp(-0.4136631609789255, -0.7861606699329886, 0.45916684364121724);
  key->SetViewAngle(179.0);
  key->SetWindowCenter(-1e300, -0.4496204639521768);
  key->SetViewShear(0.0, 0.0, 0.0);
  key->SetClippingRange(1e-300, 1e-20);
  const int before = errors->Count;
  ASSERT_EQ(path->AddCamera(-3.5, key), 1) << errors->Last;
  ASSERT_EQ(path->InterpolateCamera(-3.5, out), 1) << errors->Last;
  EXPECT_NEAR(out->GetWindowCenter()[0] / -1e300, 1.0, 1e-9);
  EXPECT_NEAR(out->GetViewAngle(), 179.0, 1e-9);
  EXPECT_EQ(errors->Count, before);
}

namespace
{
/// Azimuth samples of `path` on [t0, t1], each unwrapped to within 180 degrees of the one before.
std::vector<double> azimuthSamples(vtkCameraInterpolatorLCT* path, double t0, double t1)
{
  std::vector<double> azimuths;
  vtkNew<vtkCamera> out;
  for (int s = 0; s <= 2000; ++s)
  {
    EXPECT_EQ(path->InterpolateCamera(t0 + (t1 - t0) * s / 2000.0, out), 1);
    double a = azimuthDegrees(out);
    if (!azimuths.empty())
    {
      a = azimuths.back() + std::remainder(a - azimuths.back(), 360.0);
    }
    azimuths.push_back(a);
  }
  return azimuths;
}
} // namespace

TEST(CameraInterpolatorLCT, SplineDoesNotOvershootWhereTheCameraSlowsDown)
{
  // Issue #12 §3 for cameras: azimuth keys 0, 179.9 and 180 degrees one time unit apart. The
  // default Spline (monotone tangents) turns forward only and stops at 180; Catmull-Rom's tangent
  // at the middle key (90 degrees per unit) swings past 180 before coming back.
  for (const bool monotone : { true, false })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    path->SetMonotoneTangents(monotone);
    int k = 0;
    for (const double degrees : { 0.0, 179.9, 180.0 })
    {
      vtkNew<vtkCamera> key;
      orbitKey(degrees, key);
      ASSERT_EQ(path->AddCamera(k++, key), 1);
    }
    const std::vector<double> azimuths = azimuthSamples(path, 0.0, 2.0);
    double largestDecrease = 0.0, running = -HUGE_VAL;
    for (const double a : azimuths)
    {
      largestDecrease = std::max(largestDecrease, running - a);
      running = std::max(running, a);
    }
    if (monotone)
    {
      EXPECT_LT(running, 180.0 + 1e-9);
      EXPECT_LT(largestDecrease, 1e-9);
      EXPECT_NEAR(azimuths[1000], 179.9, 1e-9); // the key
    }
    else
    {
      EXPECT_GT(running, 185.0); // Catmull-Rom's overshoot, so that the test can fail
    }
  }
}

TEST(CameraInterpolatorLCT, SplineDoesNotTurnBackBeforeATurnNorZoomAfterAZoom)
{
  // Each part of the camera has its own monotone tangent: a camera that only zooms between the
  // first two keys and only turns between the last two neither turns the wrong way while it
  // zooms nor zooms past the second key's view angle while it turns. One tangent for the whole
  // camera (or Catmull-Rom's) moves both parts on both segments.
  for (const bool monotone : { true, false })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    path->SetMonotoneTangents(monotone);
    const double azimuth[] = { 0.0, 0.0, 45.0 }, angle[] = { 40.0, 20.0, 20.0 };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkCamera> key;
      orbitKey(azimuth[k], key);
      key->SetViewAngle(angle[k]);
      ASSERT_EQ(path->AddCamera(k, key), 1);
    }
    double largestTurn = 0.0, smallestAngle = HUGE_VAL, largestAngleAfter = 0.0;
    vtkNew<vtkCamera> out;
    for (int s = 0; s <= 2000; ++s)
    {
      const double t = 2.0 * s / 2000.0;
      ASSERT_EQ(path->InterpolateCamera(t, out), 1);
      if (t <= 1.0)
      {
        largestTurn = std::max(largestTurn, std::abs(azimuthDegrees(out)));
      }
      else
      {
        largestAngleAfter = std::max(largestAngleAfter, std::abs(out->GetViewAngle() - 20.0));
      }
      smallestAngle = std::min(smallestAngle, out->GetViewAngle());
    }
    if (monotone)
    {
      EXPECT_LT(largestTurn, 1e-9);
      EXPECT_LT(largestAngleAfter, 1e-9);
      EXPECT_GT(smallestAngle, 20.0 - 1e-9);
    }
    else
    {
      EXPECT_GT(largestTurn, 1.0);
      EXPECT_LT(smallestAngle, 19.5);
    }
  }
}

TEST(CameraInterpolatorLCT, MonotoneSplineIsC1AtUnevenlySpacedRandomKeys)
{
  // Every parameter's velocity is the same on both sides of each inner key (central difference
  // quotients over 1e-6 of the time step from either side agree to ~1e-4 of the step's speed).
  const auto keys = randomKeys(7, 6);
  vtkNew<vtkCameraInterpolatorLCT> path;
  for (const auto& k : keys)
  {
    vtkNew<vtkCamera> c;
    apply(k, c, false);
    ASSERT_EQ(path->AddCamera(k.t, c), 1);
  }
  const auto parameters = [&](double t) {
    vtkNew<vtkCamera> out;
    EXPECT_EQ(path->InterpolateCamera(t, out), 1);
    out->OrthogonalizeViewUp();
    Eigen::Matrix<double, 11, 1> p;
    p << get3(out->GetPosition()), get3(out->GetFocalPoint()), get3(out->GetViewUp()),
      out->GetWindowCenter()[0], std::log(out->GetViewAngle());
    return p;
  };
  for (size_t k = 1; k + 1 < keys.size(); ++k)
  {
    const double h = 1e-6 * std::min(keys[k].t - keys[k - 1].t, keys[k + 1].t - keys[k].t);
    const double t = keys[k].t;
    const Eigen::Matrix<double, 11, 1> left = (parameters(t) - parameters(t - h)) / h;
    const Eigen::Matrix<double, 11, 1> right = (parameters(t + h) - parameters(t)) / h;
    const Eigen::Matrix<double, 11, 1> chord =
      (parameters(keys[k + 1].t) - parameters(keys[k - 1].t)) / (keys[k + 1].t - keys[k - 1].t);
    EXPECT_LT((left - right).norm(), 1e-3 * (1.0 + chord.norm())) << "key " << k;
  }
}

TEST(CameraInterpolatorLCT, TangentsFollowKeysAddedAndRemovedAfterAnEvaluation)
{
  // The monotone tangents are cached per key set: a key appended, inserted or removed after an
  // evaluation gives the curve of an interpolator built with the final keys.
  const auto keys = randomKeys(11, 5);
  const auto build = [&](vtkCameraInterpolatorLCT* path, std::initializer_list<int> which) {
    for (int i : which)
    {
      vtkNew<vtkCamera> c;
      apply(keys[i], c, false);
      ASSERT_EQ(path->AddCamera(keys[i].t, c), 1);
    }
  };
  vtkNew<vtkCameraInterpolatorLCT> edited, fresh;
  vtkNew<vtkCamera> a, b;
  build(edited, { 0, 1, 3 });
  ASSERT_EQ(edited->InterpolateCamera(keys[1].t, a), 1);
  build(edited, { 4, 2 }); // appended, then inserted
  edited->RemoveCamera(keys[0].t);
  build(fresh, { 1, 2, 3, 4 });
  for (int s = 0; s <= 40; ++s)
  {
    const double t = keys[1].t + (keys[4].t - keys[1].t) * s / 40.0;
    ASSERT_EQ(edited->InterpolateCamera(t, a), 1);
    ASSERT_EQ(fresh->InterpolateCamera(t, b), 1);
    EXPECT_LT(cameraDifference(a, b), 1e-12) << t;
  }
}

TEST(CameraInterpolatorLCT, KeysVeryCloseInTimeGiveTheirCurveNotCancellation)
{
  // Keys 1e-300 apart in time: the Spline weights of the close keys are then huge and opposite.
  // Parts are combined as steps from the key of largest weight and a still side gives a zero
  // tangent, so the curve stays between its keys (monotone data), with or without monotone
  // tangents; as absolute sums the window centre read 1e284 with status 1.
  for (const bool monotone : { true, false })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    path->SetMonotoneTangents(monotone);
    const double times[] = { 0.0, 1e-300, 2e-300, 1.0 };
    const double azimuth[] = { 0.0, 10.0, 20.0, 60.0 }, centre[] = { 0.1, 0.1, 0.1, 0.2 };
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkCamera> key;
      orbitKey(azimuth[k], key);
      key->SetWindowCenter(centre[k], 0.0);
      key->SetViewAngle(30.0 + 10.0 * k);
      ASSERT_EQ(path->AddCamera(times[k], key), 1);
    }
    vtkNew<vtkCamera> out;
    for (int s = 0; s <= 100; ++s)
    {
      const double t = s / 100.0;
      ASSERT_EQ(path->InterpolateCamera(t, out), 1) << t;
      EXPECT_GE(out->GetWindowCenter()[0], 0.1 - 1e-12) << t;
      EXPECT_LE(out->GetWindowCenter()[0], 0.2 + 1e-12) << t;
      EXPECT_NEAR(out->GetDistance(), 5.0, 1e-9) << t;
      if (monotone && s > 0) // after the close keys: 50 to 60 degrees
      {
        EXPECT_GE(out->GetViewAngle(), 50.0 - 1e-9) << t;
        EXPECT_LE(out->GetViewAngle(), 60.0 + 1e-9) << t;
      }
    }
  }
}

namespace
{
/// A camera 10 from its focal point (fx, 0, 0) after `azimuth` degrees of vtkCamera::Azimuth,
/// the whole scene scaled by s.
void scaledKey(double s, double fx, double fy, double azimuth, vtkCamera* c)
{
  c->SetFocalPoint(fx * s, fy * s, 0);
  c->SetPosition(fx * s, fy * s, 10 * s);
  c->SetViewUp(0, 1, 0);
  c->Azimuth(azimuth);
  c->SetClippingRange(0.1 * s, 100 * s);
}
} // namespace

TEST(CameraInterpolatorLCT, MonotoneSplineIsTheSamePathAtEveryScale)
{
  // Scaling the scene scales the path: the focal point's steps are measured in units of the
  // distance. (Measured against the largest coordinate, the turn counted as round-off beyond
  // 1e11 and the path at 1e20 turned 2 degrees ahead.)
  vtkNew<vtkCamera> reference, scaled;
  for (const double s : { 1e-15, 1e-8, 1e12, 1e20, 1e100 })
  {
    vtkNew<vtkCameraInterpolatorLCT> unit, big;
    const double fx[] = { 0, 1, 5, 5.5 }, azimuth[] = { 0, 60, 70, 100 }, times[] = { 0, 1, 2, 4 };
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkCamera> a, b;
      scaledKey(1.0, fx[k], 0, azimuth[k], a);
      scaledKey(s, fx[k], 0, azimuth[k], b);
      ASSERT_EQ(unit->AddCamera(times[k], a), 1);
      ASSERT_EQ(big->AddCamera(times[k], b), 1);
    }
    for (int i = 0; i <= 40; ++i)
    {
      const double t = i / 10.0;
      ASSERT_EQ(unit->InterpolateCamera(t, reference), 1);
      ASSERT_EQ(big->InterpolateCamera(t, scaled), 1);
      EXPECT_LT((get3(scaled->GetPosition()) / s - get3(reference->GetPosition())).norm(), 1e-9)
        << "scale " << s << " t " << t;
      EXPECT_LT((get3(scaled->GetViewUp()) - get3(reference->GetViewUp())).norm(), 1e-9)
        << "scale " << s << " t " << t;
    }
  }
}

TEST(CameraInterpolatorLCT, OrbitThatStopsDoesNotOvershootWhileTheFocalPointMoves)
{
  // The orientation and the focal point have their own tangents: an orbit 0 -> 60 degrees that
  // stops while the camera then pans does not swing past 60 (one tangent for the focal frame
  // swung to 64.4), and a pan that stops while the orbit goes on does not pan past its key.
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    const double fy[] = { 0, 0, 5 }, azimuth[] = { 0, 60, 60 };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkCamera> key;
      scaledKey(1.0, 0, fy[k], azimuth[k], key);
      ASSERT_EQ(path->AddCamera(k, key), 1);
    }
    vtkNew<vtkCamera> out;
    for (int i = 0; i <= 200; ++i)
    {
      ASSERT_EQ(path->InterpolateCamera(i / 100.0, out), 1);
      const Eigen::Vector3d view = get3(out->GetPosition()) - get3(out->GetFocalPoint());
      const double degrees = std::atan2(view[0], view[2]) * 180.0 / lct_test::kPi;
      EXPECT_LE(degrees, 60.0 + 1e-9) << i / 100.0;
    }
  }
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    const double fx[] = { 0, 5, 5 }, azimuth[] = { 0, 0, 30 };
    for (int k = 0; k < 3; ++k)
    {
      vtkNew<vtkCamera> key;
      scaledKey(1.0, fx[k], 0, azimuth[k], key);
      ASSERT_EQ(path->AddCamera(k, key), 1);
    }
    vtkNew<vtkCamera> out;
    for (int i = 0; i <= 200; ++i)
    {
      ASSERT_EQ(path->InterpolateCamera(i / 100.0, out), 1);
      EXPECT_LE(out->GetFocalPoint()[0], 5.0 + 1e-9) << i / 100.0;
    }
  }
}

// Audit (session 29): ToVtk set the focal point while the output camera still had its previous
// position; where that position was the new focal point, vtkCamera clamped the distance to 1e-20
// and moved the focal point, and the later SetPosition never moved it back. A key came back with
// its focal point 1e-20 off (10 % of its view distance at 1e-19), with status 1, depending on
// what the output camera had shown before.
TEST(CameraInterpolatorLCT, KeysComeBackWhateverTheOutputCameraShowedBefore)
{
  for (const double scale : { 1e-19, 1.0 })
  {
    vtkNew<vtkCameraInterpolatorLCT> path;
    vtkNew<vtkCamera> k0, k1;
    k0->SetPosition(0, 0, scale);
    k0->SetFocalPoint(0, 0, 0);
    k1->SetPosition(scale, 0, 0);
    k1->SetFocalPoint(0, 0, 0);
    path->AddCamera(0.0, k0);
    path->AddCamera(1.0, k1);
    vtkNew<vtkCamera> out;
    out->SetPosition(0, 0, 0); // where the keys' focal point is
    out->SetFocalPoint(0, 0, -1);
    ASSERT_EQ(path->InterpolateCamera(0.0, out), 1) << scale;
    const double* f = out->GetFocalPoint();
    EXPECT_EQ(f[0], 0.0) << scale;
    EXPECT_EQ(f[1], 0.0) << scale;
    EXPECT_EQ(f[2], 0.0) << scale;
    EXPECT_NEAR(out->GetPosition()[2], scale, 1e-14 * scale); // log-distance round trip
  }
}

// Audit (session 29): UseHorizontalViewAngle was not carried: a key with a horizontal 60-degree
// angle came back vertical (its field of view doubled at aspect 2), with status 1, and keys
// mixing horizontal and vertical angles were blended as if they measured the same thing.
TEST(CameraInterpolatorLCT, HorizontalViewAnglesAreReproducedAndNotMixedWithVerticalOnes)
{
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<ErrorCounter> errors;
  path->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> k0, k1, vertical;
  k0->SetPosition(0, 0, 5);
  k0->SetUseHorizontalViewAngle(1);
  k0->SetViewAngle(60);
  k1->SetPosition(5, 0, 0);
  k1->SetUseHorizontalViewAngle(1);
  k1->SetViewAngle(40);
  ASSERT_EQ(path->AddCamera(0.0, k0), 1);
  ASSERT_EQ(path->AddCamera(1.0, k1), 1);
  vtkNew<vtkCamera> out;
  for (const double t : { 0.0, 0.5, 1.0 })
  {
    ASSERT_EQ(path->InterpolateCamera(t, out), 1);
    EXPECT_EQ(out->GetUseHorizontalViewAngle(), 1) << t;
  }
  ASSERT_EQ(path->InterpolateCamera(0.0, out), 1);
  EXPECT_NEAR(out->GetProjectionTransformMatrix(2.0, -1, 1)->GetElement(1, 1),
    k0->GetProjectionTransformMatrix(2.0, -1, 1)->GetElement(1, 1), 1e-12);
  vertical->SetPosition(-5, 0, 0);
  vertical->SetViewAngle(60);
  EXPECT_EQ(path->AddCamera(2.0, vertical), 0);
  EXPECT_NE(errors->Last.find("cannot be mixed with keys whose view angle is horizontal"),
    std::string::npos)
    << errors->Last;
  EXPECT_EQ(path->GetNumberOfCameras(), 2);
}

// Audit (session 29): likewise for cameras: Initialize() reports the next clamp again.
TEST(CameraInterpolatorLCT, InitializeReportsTheNextClampAgain)
{
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<ErrorCounter> warnings;
  path->AddObserver(vtkCommand::WarningEvent, warnings);
  vtkNew<vtkCamera> key, out;
  for (int round = 1; round <= 2; ++round)
  {
    path->Initialize();
    ASSERT_EQ(path->AddCamera(0.0, key), 1);
    ASSERT_EQ(path->AddCamera(1.0, key), 1);
    ASSERT_EQ(path->InterpolateCamera(-1.0, out), 1);
    ASSERT_EQ(path->InterpolateCamera(-2.0, out), 1);
    EXPECT_EQ(warnings->Count, round) << warnings->Last;
  }
}

// Speed (session 31): the interpolated camera's frame is written with one rebuild of vtkCamera's
// view and camera-light transforms instead of one per frame setter. The state must be the one
// the public setters leave, bit for bit: every stored vector, the distance, the direction of
// projection and view plane normal (oblique views included), and every matrix a renderer asks
// for, whatever the camera showed before; and observers still hear of the change.
TEST(CameraInterpolatorLCT, CamerasAreWrittenAsTheirSettersWouldWriteThem)
{
  lct_test::RandomTransforms random(3101);
  const auto matrixOf = [](vtkMatrix4x4* m) { return lct_test::fromVtk(m); };
  for (int trial = 0; trial < 2000; ++trial)
  {
    lct::CameraParameters c;
    // (Cameras nearer to their focal point than 1e-20 are refused as keys: the clamp is
    // DistancesAtVtkCamerasMinimumKeepTheirDirection's.)
    const double scale = std::pow(10.0, random.Uniform(-15.0, 150.0));
    c.focalPoint = scale * Eigen::Vector3d(random.Normal(), random.Normal(), random.Normal());
    c.position = c.focalPoint + scale * random.LogUniform(0.01, 100.0) * random.UnitVector();
    // View up of any length (SetViewUp normalises it), not orthogonal to the view.
    c.viewUp = random.LogUniform(1e-3, 1e3) * random.UnitVector();
    c.parallelProjection = trial % 3 == 0;
    c.horizontalViewAngle = trial % 5 == 0;
    c.viewAngle = random.Uniform(1.0, 120.0);
    c.parallelScale = scale * random.LogUniform(0.1, 10.0);
    c.windowCenter = Eigen::Vector2d(random.Uniform(-1.0, 1.0), random.Uniform(-1.0, 1.0));
    c.viewShear = trial % 4 == 0 ? Eigen::Vector3d(0, 0, 1)
                                 : Eigen::Vector3d(random.Uniform(-0.5, 0.5),
                                     random.Uniform(-0.5, 0.5), random.Uniform(0.5, 1.5));
    const double d = (c.position - c.focalPoint).norm();
    c.clippingRange = Eigen::Vector2d(0.01 * d, 10.0 * d);

    vtkNew<vtkCamera> bySetters, byWriter;
    for (vtkCamera* camera : { bySetters.Get(), byWriter.Get() })
    {
      // The same earlier view for both (every fourth trial: the frame is already the new one).
      if (trial % 4 == 1)
      {
        camera->SetFocalPoint(c.focalPoint.data());
        camera->SetPosition(c.position.data());
        camera->SetViewUp(c.viewUp.data());
      }
      else
      {
        camera->SetPosition(1.0, 2.0, 3.0);
        camera->SetFocalPoint(-1.0, 0.5, 0.0);
        camera->SetViewUp(0.0, 0.0, 1.0);
      }
    }
    bySetters->SetFocalPoint(c.focalPoint.data());
    bySetters->SetPosition(c.position.data());
    bySetters->SetViewUp(c.viewUp.data());
    bySetters->SetParallelProjection(c.parallelProjection);
    bySetters->SetUseHorizontalViewAngle(c.horizontalViewAngle);
    bySetters->SetParallelScale(c.parallelScale);
    bySetters->SetViewAngle(c.viewAngle);
    bySetters->SetWindowCenter(c.windowCenter[0], c.windowCenter[1]);
    bySetters->SetViewShear(c.viewShear[0], c.viewShear[1], c.viewShear[2]);
    bySetters->SetClippingRange(c.clippingRange[0], c.clippingRange[1]);

    vtkNew<ErrorCounter> modified; // counts ModifiedEvents here
    byWriter->AddObserver(vtkCommand::ModifiedEvent, modified);
    const vtkMTimeType before = byWriter->GetMTime();
    vtkLCTCamera::ToVtk(c, byWriter);
    if (trial % 4 != 1)
    {
      EXPECT_GT(byWriter->GetMTime(), before) << trial;
      EXPECT_GE(modified->Count, 1) << trial;
    }

    for (int i = 0; i < 3; ++i)
    {
      ASSERT_EQ(byWriter->GetPosition()[i], bySetters->GetPosition()[i]) << trial;
      ASSERT_EQ(byWriter->GetFocalPoint()[i], bySetters->GetFocalPoint()[i]) << trial;
      ASSERT_EQ(byWriter->GetViewUp()[i], bySetters->GetViewUp()[i]) << trial;
      ASSERT_EQ(byWriter->GetDirectionOfProjection()[i], bySetters->GetDirectionOfProjection()[i])
        << trial;
      ASSERT_EQ(byWriter->GetViewPlaneNormal()[i], bySetters->GetViewPlaneNormal()[i]) << trial;
      ASSERT_EQ(byWriter->GetViewShear()[i], bySetters->GetViewShear()[i]) << trial;
    }
    ASSERT_EQ(byWriter->GetDistance(), bySetters->GetDistance()) << trial;
    ASSERT_EQ(byWriter->GetParallelProjection(), bySetters->GetParallelProjection());
    ASSERT_EQ(byWriter->GetUseHorizontalViewAngle(), bySetters->GetUseHorizontalViewAngle());
    ASSERT_EQ(byWriter->GetViewAngle(), bySetters->GetViewAngle());
    ASSERT_EQ(byWriter->GetParallelScale(), bySetters->GetParallelScale());
    ASSERT_EQ(byWriter->GetWindowCenter()[0], bySetters->GetWindowCenter()[0]);
    ASSERT_EQ(byWriter->GetWindowCenter()[1], bySetters->GetWindowCenter()[1]);
    ASSERT_EQ(byWriter->GetClippingRange()[0], bySetters->GetClippingRange()[0]);
    ASSERT_EQ(byWriter->GetClippingRange()[1], bySetters->GetClippingRange()[1]);
    ASSERT_EQ(byWriter->GetThickness(), bySetters->GetThickness());
    ASSERT_EQ(
      matrixOf(byWriter->GetViewTransformMatrix()), matrixOf(bySetters->GetViewTransformMatrix()))
      << trial;
    ASSERT_EQ(matrixOf(byWriter->GetCameraLightTransformMatrix()),
      matrixOf(bySetters->GetCameraLightTransformMatrix()))
      << trial;
    ASSERT_EQ(matrixOf(byWriter->GetCompositeProjectionTransformMatrix(1.5, -1.0, 1.0)),
      matrixOf(bySetters->GetCompositeProjectionTransformMatrix(1.5, -1.0, 1.0)))
      << trial;
    ASSERT_EQ(
      std::vector<double>(byWriter->GetOrientationWXYZ(), byWriter->GetOrientationWXYZ() + 4),
      std::vector<double>(bySetters->GetOrientationWXYZ(), bySetters->GetOrientationWXYZ() + 4))
      << trial;
  }
}
