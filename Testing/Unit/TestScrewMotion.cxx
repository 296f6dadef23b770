// Issue #12 §2: screw motion of the camera's focal frame. The twist formulas against Eigen's
// matrix exponential of the 4x4 twist (an independent oracle), and the camera path: keys hit,
// unchanged where the keys share the focal point, no jump where the reference key changes.
#include "lct/SO3.h"
#include "lct/ScrewMotion.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkNew.h"

#include <Eigen/Geometry>
#include <unsupported/Eigen/MatrixFunctions>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
vtkSmartPointer<vtkCamera> key(double angle, const Eigen::Vector3d& focal)
{
  auto c = vtkSmartPointer<vtkCamera>::New();
  c->SetFocalPoint(focal.data());
  c->SetPosition(focal.x() + 6 * std::sin(angle), focal.y() + 1, focal.z() + 6 * std::cos(angle));
  c->SetViewUp(0, 1, 0);
  return c;
}

Eigen::Vector3d focalPoint(vtkCameraInterpolatorLCT* path, double t)
{
  vtkNew<vtkCamera> c;
  EXPECT_EQ(path->InterpolateCamera(t, c), 1);
  return Eigen::Vector3d(c->GetFocalPoint());
}
} // namespace

TEST(ScrewMotion, TwistMatchesTheMatrixExponential)
{
  std::mt19937 rng(12);
  std::normal_distribution<double> g;
  for (int trial = 0; trial < 500; ++trial)
  {
    Eigen::Vector3d w(g(rng), g(rng), g(rng));
    w *= (trial % 5 == 0 ? 1e-6 : 1.0) * (trial % 7 == 0 ? 3.14159 / w.norm() : 1.0);
    if (w.norm() > 3.14159)
    {
      w *= 3.0 / w.norm();
    }
    const Eigen::Vector3d v(g(rng), g(rng), g(rng));
    Eigen::Matrix4d twist = Eigen::Matrix4d::Zero();
    twist.topLeftCorner<3, 3>() = lct::hat(w);
    twist.topRightCorner<3, 1>() = v;
    const Eigen::Matrix4d m = twist.exp();
    const Eigen::Vector3d t = lct::screwTranslation(w, v);
    EXPECT_LT((t - m.topRightCorner<3, 1>()).norm(), 1e-13 * (1 + v.norm())) << trial;
    EXPECT_LT((lct::screwTwist(w, t) - v).norm(), 1e-12 * (1 + v.norm())) << trial;
  }
}

TEST(ScrewMotion, CameraKeysAreHitAndASharedFocalPointStays)
{
  const Eigen::Vector3d shared(0.2, -0.1, 0.3);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  vtkNew<vtkCameraInterpolatorLCT> same, line, screw;
  line->ScrewMotionOff();
  ASSERT_EQ(screw->GetScrewMotion(), 1); // the default
  std::vector<Eigen::Vector3d> focals;
  for (int k = 0; k < 4; ++k)
  {
    const Eigen::Vector3d f(u(rng), u(rng), u(rng));
    focals.push_back(f);
    ASSERT_EQ(same->AddCamera(k, key(0.9 * k, shared)), 1);
    ASSERT_EQ(line->AddCamera(k, key(0.9 * k, f)), 1);
    ASSERT_EQ(screw->AddCamera(k, key(0.9 * k, f)), 1);
  }
  double differs = 0.0, largestStep = 0.0;
  Eigen::Vector3d previous = focalPoint(screw, 0.0);
  for (int s = 0; s <= 3000; ++s)
  {
    const double t = 3.0 * s / 3000;
    EXPECT_LT((focalPoint(same, t) - shared).norm(), 1e-12);
    const Eigen::Vector3d f = focalPoint(screw, t);
    differs = std::max(differs, (f - focalPoint(line, t)).norm());
    largestStep = std::max(largestStep, (f - previous).norm());
    previous = f;
    if (s % 1000 == 0)
    {
      EXPECT_LT((f - focals[s / 1000]).norm(), 1e-12); // keys hit
    }
  }
  EXPECT_GT(differs, 1e-2);     // a screw, not the curve through the focal points
  EXPECT_LT(largestStep, 2e-3); // no jump (the path is ~3 long over 3000 steps)
}
