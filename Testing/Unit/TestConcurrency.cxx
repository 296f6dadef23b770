// Concurrent evaluation: once the keys stop changing, InterpolateTransform / InterpolateCamera may
// run on several threads at once (each with its own output). The interesting state is the
// module's own: the key logs and the Bezier / camera-matrix logs are rebuilt lazily by the first
// evaluation after an edit, so the threads here start on freshly edited interpolators and race
// for that rebuild. scripts/test runs this under ThreadSanitizer (build-tsan/), where a missing
// lock is a reported data race; in the normal build it checks that every thread sees the same
// results as a serial evaluation. Core functions (lct::logarithm, exponential, curveWeights, ...)
// are pure and are exercised here from every thread too.
#include "lct/Parametrisation.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolatorLCT.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <thread>
#include <vector>

namespace
{
constexpr int kThreads = 4;
constexpr int kKeys = 40;
constexpr int kSamples = 400;

double sampleTime(int i)
{
  return (kKeys - 1) * static_cast<double>(i) / (kSamples - 1);
}

vtkSmartPointer<vtkTransformInterpolatorLCT> transformPath(int type, bool consistent)
{
  auto path = vtkSmartPointer<vtkTransformInterpolatorLCT>::New();
  path->SetInterpolationType(type);
  path->SetConsistentRotation(consistent);
  // Reverse time order: every key is an insertion, so the logs are stale when the threads start.
  for (int k = kKeys - 1; k >= 0; --k)
  {
    vtkNew<vtkTransform> t;
    t->Translate(k, 0.3 * k, -0.1 * k * k);
    t->RotateWXYZ(25.0 * k, 1, 2, 3);
    t->Scale(1.0 + 0.02 * k, 1.0, 1.0 - 0.01 * k);
    path->AddTransform(k, t);
  }
  return path;
}

vtkSmartPointer<vtkCameraInterpolatorLCT> cameraPath(int method)
{
  auto path = vtkSmartPointer<vtkCameraInterpolatorLCT>::New();
  path->SetMethod(method);
  for (int k = kKeys - 1; k >= 0; --k)
  {
    vtkNew<vtkCamera> c;
    c->SetFocalPoint(0.1 * k, 0, 0);
    c->SetPosition(5.0 * std::sin(0.3 * k), 1.0, 5.0 * std::cos(0.3 * k));
    c->SetViewAngle(30.0 + k % 5);
    c->SetWindowCenter(0.01 * k, 0.0);
    path->AddCamera(k, c);
  }
  return path;
}

/// Runs `evaluate(thread, sample)` for every sample on kThreads threads at once.
template <typename Evaluate>
void onThreads(Evaluate evaluate)
{
  std::vector<std::thread> threads;
  for (int thread = 0; thread < kThreads; ++thread)
  {
    threads.emplace_back([&, thread] {
      // Each thread walks the samples from another start, so they hit the lazy rebuild and
      // different segments at the same time.
      for (int j = 0; j < kSamples; ++j)
      {
        evaluate(thread, (j + thread * kSamples / kThreads) % kSamples);
      }
    });
  }
  for (std::thread& t : threads)
  {
    t.join();
  }
}
} // namespace

TEST(Concurrency, TransformInterpolatorsEvaluatedFromSeveralThreads)
{
  for (int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER })
  {
    for (bool consistent : { false, true })
    {
      auto path = transformPath(type, consistent);
      std::vector<std::array<double, 16>> results(kSamples);
      std::vector<int> ok(kSamples, 0);
      onThreads([&](int thread, int i) {
        vtkNew<vtkMatrix4x4> out;
        const int success = path->InterpolateTransform(sampleTime(i), out);
        if (thread == 0)
        {
          ok[i] = success;
          std::copy(out->GetData(), out->GetData() + 16, results[i].begin());
        }
      });
      // The same values serially, now that the logs are built.
      auto serial = transformPath(type, consistent);
      for (int i = 0; i < kSamples; ++i)
      {
        vtkNew<vtkMatrix4x4> out;
        ASSERT_EQ(serial->InterpolateTransform(sampleTime(i), out), 1);
        ASSERT_EQ(ok[i], 1);
        for (int e = 0; e < 16; ++e)
        {
          ASSERT_EQ(results[i][e], out->GetData()[e]) << type << " " << i;
        }
      }
    }
  }
}

TEST(Concurrency, CameraInterpolatorsEvaluatedFromSeveralThreads)
{
  for (int method : { vtkCameraInterpolatorLCT::METHOD_FOCAL_FRAME,
         vtkCameraInterpolatorLCT::METHOD_CAMERA_MATRIX })
  {
    auto path = cameraPath(method);
    std::vector<std::array<double, 3>> positions(kSamples);
    onThreads([&](int thread, int i) {
      vtkNew<vtkCamera> out;
      path->InterpolateCamera(sampleTime(i), out);
      if (thread == 0)
      {
        out->GetPosition(positions[i].data());
      }
    });
    auto serial = cameraPath(method);
    for (int i = 0; i < kSamples; ++i)
    {
      vtkNew<vtkCamera> out;
      ASSERT_EQ(serial->InterpolateCamera(sampleTime(i), out), 1);
      for (int e = 0; e < 3; ++e)
      {
        ASSERT_EQ(positions[i][e], out->GetPosition()[e]) << method << " " << i;
      }
    }
  }
}

TEST(Concurrency, CoreFunctionsArePure)
{
  std::vector<double> sums(kThreads, 0.0);
  onThreads([&](int thread, int i) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(0.01 * i, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix() *
      Eigen::Vector3d(1.0 + 0.001 * i, 1e-3, 1e3).asDiagonal();
    for (lct::Parametrisation p : { lct::Parametrisation::Polar, lct::Parametrisation::MatrixLog })
    {
      const auto log = lct::logarithm(m, p);
      if (log)
      {
        sums[thread] += lct::exponential(log.value, p).value(0, 0);
      }
    }
  });
  for (int thread = 1; thread < kThreads; ++thread)
  {
    EXPECT_NEAR(sums[thread], sums[0], 1e-9 * std::abs(sums[0]));
  }
}
