// Shared by FuzzRenderKeysJson.cxx and FuzzRenderKeysPvcc.cxx: what Examples/lct-render.cxx does
// with the keys its readers (Examples/RenderKeys.h) return, up to the first frame that needs a
// display. lct-render.cxx keeps this in main(), so it is restated here, following that file:
// the camera keys go into a vtkCameraInterpolatorLCT and each prop track into a
// vtkTransformInterpolatorLCT (a refused key is a clean input error), the path metric is taken
// over [tmin, tmax], and frame i of N is interpolated at tmin + (tmax - tmin) i / (N - 1).
//
// Property: keys the reader accepted and the interpolators accepted render: every frame
// interpolates (lct-render would stop with "interpolating ... failed" after writing frames) and
// every interpolated camera parameter and prop matrix is finite.
#ifndef lct_fuzz_FuzzRenderKeys_h
#define lct_fuzz_FuzzRenderKeys_h

#include "FuzzInput.h"
#include "RenderKeys.h"

#include "vtkCameraInterpolatorLCT.h"
#include "vtkCameraPathMetric.h"
#include "vtkLCTCameraParameters.h" // the parameters AddCamera reads
#include "vtkTransformInterpolatorLCT.h"

#include "lct/CameraKey.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <streambuf>
#include <string>
#include <vector>

#include <unistd.h>

namespace lct_fuzz
{

/// RenderKeys' readers may print notes on std::cerr (a .pvsm camera track's mode); keep them
/// out of the fuzzer's log.
inline void SilenceStdErr()
{
  struct NullBuffer : std::streambuf
  {
    int overflow(int c) override { return c; }
  };
  static NullBuffer null;
  static std::streambuf* const previous = std::cerr.rdbuf(&null);
  (void)previous;
}

/// The readers of ParaView files take a file name: the input's bytes in a temporary file (one
/// per process, `stem` naming it, removed at exit), whose name is returned.
inline const std::string& InputAsFile(const char* stem, const uint8_t* data, size_t size)
{
  static const std::string name = [stem] {
    const char* dir = std::getenv("TMPDIR");
    std::string pattern = std::string(dir && *dir ? dir : "/tmp") + "/" + stem + "-XXXXXX";
    const int fd = mkstemp(&pattern[0]);
    if (fd < 0)
    {
      std::perror("mkstemp");
      std::abort();
    }
    close(fd);
    static const std::string removeAtExit = pattern;
    std::atexit([] { std::remove(removeAtExit.c_str()); });
    return pattern;
  }();
  FILE* f = std::fopen(name.c_str(), "wb");
  if (!f || std::fwrite(data, 1, size, f) != size || std::fclose(f) != 0)
  {
    std::perror(name.c_str());
    std::abort();
  }
  return name;
}

/// lct-render's name -> interpolation type (its CameraType()).
inline int InterpolationType(const std::string& name)
{
  if (name == "linear")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR;
  }
  if (name == "bspline")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE;
  }
  if (name == "subdivision")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION;
  }
  return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE;
}

/// The checks on what a reader returned, then lct-render's use of it.
inline void RenderKeysLikeLctRender(const RenderKeys::Keys& keys)
{
  // What the reader promises.
  LCT_FUZZ_CHECK(
    keys.Camera.size() >= 2, "the reader returned " << keys.Camera.size() << " camera keys");
  LCT_FUZZ_CHECK(RenderKeys::IsInterpolationName(keys.Interpolation),
    "the reader returned interpolation \"" << keys.Interpolation << "\"");
  for (const auto& key : keys.Camera)
  {
    LCT_FUZZ_CHECK(std::isfinite(key.Time) && key.Camera, "a camera key without finite time");
  }
  for (const auto& [name, track] : keys.Props)
  {
    LCT_FUZZ_CHECK(!track.Keys.empty(), "props." << name << " has no keys");
    LCT_FUZZ_CHECK(
      track.Interpolation.empty() || RenderKeys::IsInterpolationName(track.Interpolation),
      "props." << name << " interpolation \"" << track.Interpolation << "\"");
    for (const auto& key : track.Keys)
    {
      LCT_FUZZ_CHECK(std::isfinite(key.Time) && AllFinite(key.Matrix.data(), 16) &&
          key.Matrix[12] == 0.0 && key.Matrix[13] == 0.0 && key.Matrix[14] == 0.0 &&
          key.Matrix[15] == 1.0,
        key.Path << ": the reader returned a non-finite or non-affine matrix "
                 << Show(key.Matrix.data(), 16));
    }
  }

  ErrorObserver errors;
  vtkNew<vtkCameraInterpolatorLCT> cameraPath;
  errors.Observe(cameraPath);
  cameraPath->SetInterpolationType(InterpolationType(keys.Interpolation));
  cameraPath->SetConsistentRotation(keys.ConsistentRotation);
  double tmin = keys.Camera.front().Time, tmax = tmin;
  for (const auto& key : keys.Camera)
  {
    tmin = std::min(tmin, key.Time);
    tmax = std::max(tmax, key.Time);
    if (!cameraPath->AddCamera(key.Time, key.Camera))
    {
      return; // lct-render: "... is degenerate (rejected by vtkCameraInterpolatorLCT: ...)"
    }
  }
  struct Track
  {
    std::string Name;
    vtkSmartPointer<vtkTransformInterpolatorLCT> Path;
  };
  std::vector<Track> tracks;
  for (const auto& [name, track] : keys.Props)
  {
    Track t;
    t.Name = name;
    t.Path = vtkSmartPointer<vtkTransformInterpolatorLCT>::New();
    errors.Observe(t.Path);
    const std::string scheme =
      !track.Interpolation.empty() ? track.Interpolation : keys.Interpolation;
    t.Path->SetInterpolationType(InterpolationType(scheme)); // same enum values 0..3
    t.Path->SetConsistentRotation(track.ConsistentRotation);
    double lo = track.Keys.front().Time, hi = lo;
    for (const auto& key : track.Keys)
    {
      lo = std::min(lo, key.Time);
      hi = std::max(hi, key.Time);
      vtkNew<vtkMatrix4x4> m;
      m->DeepCopy(key.Matrix.data());
      if (!t.Path->AddTransform(key.Time, m))
      {
        return; // lct-render: "... is not a usable transform (rejected by ...)"
      }
    }
    tracks.push_back(t);
  }

  // The path metric over a few scene points (lct-render uses the scene's mesh points).
  {
    vtkNew<vtkPoints> points;
    for (int i = 0; i < 8; ++i)
    {
      points->InsertNextPoint((i & 1) - 0.5, ((i >> 1) & 1) * 0.8, ((i >> 2) & 1) - 0.5);
    }
    vtkNew<vtkCameraPathMetric> metric;
    metric->SetPoints(points);
    metric->SetNumberOfSamples(12);
    if (metric->EvaluateInterpolator(cameraPath, tmin, tmax))
    {
      LCT_FUZZ_CHECK(std::isfinite(metric->GetCameraSpaceExcess()) &&
          std::isfinite(metric->GetScreenSpaceExcess()),
        "vtkCameraPathMetric returned 1 with a non-finite excess");
    }
  }

  constexpr int N = 12;
  auto frameTime = [&](int i) { return N > 1 ? tmin + (tmax - tmin) * i / (N - 1) : tmin; };
  for (int i = 0; i < N; ++i)
  {
    const double t = frameTime(i);
    for (const Track& track : tracks)
    {
      vtkNew<vtkMatrix4x4> k;
      // Accepted keys interpolate at every frame (D19: the interpolator refuses keys whose curve
      // would combine a log that does not exist), unless the in-between itself is out of range
      // or too ill-conditioned.
      if (!track.Path->InterpolateTransform(t, k) && ExplainedRefusal(errors.Last))
      {
        continue;
      }
      LCT_FUZZ_CHECK(track.Path->InterpolateTransform(t, k),
        "interpolating props." << track.Name << " at t = " << t << " failed: " << errors.Last);
      LCT_FUZZ_CHECK(AllFinite(k->GetData(), 16),
        "props." << track.Name << " at t = " << t << " is not finite: " << Show(k->GetData(), 16));
    }
    vtkNew<vtkCamera> camera;
    // vtkCameraInterpolatorLCT.h: refused (never non-finite) where a spline overshoots out of
    // vtkCamera's range; the convex schemes (Linear, BSpline) stay within the keys.
    const int type = cameraPath->GetInterpolationType();
    const bool overshoot = type == vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE ||
      type == vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION;
    if (!cameraPath->InterpolateCamera(t, camera))
    {
      LCT_FUZZ_CHECK(overshoot && errors.Last.find("overshoot") != std::string::npos,
        "interpolating the camera at t = " << t << " failed: " << errors.Last);
      continue;
    }
    const lct::CameraParameters c = vtkLCTCamera::FromVtk(camera);
    const bool finite = AllFinite(c.position) && AllFinite(c.focalPoint) && AllFinite(c.viewUp) &&
      std::isfinite(c.viewAngle) && std::isfinite(c.parallelScale) && AllFinite(c.windowCenter) &&
      AllFinite(c.viewShear) && AllFinite(c.clippingRange);
    LCT_FUZZ_CHECK(finite,
      "the camera at t = " << t << " is not finite: position " << Show(c.position.transpose())
                           << ", clipping " << Show(c.clippingRange.transpose()));
  }
}

} // namespace lct_fuzz

#endif
