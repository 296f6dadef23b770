#include "lct/SegmentPathMetric.h"

#include <algorithm>
#include <cmath>

namespace lct
{

namespace
{
/// A chord below this fraction of the path's own scale carries no direction.
constexpr double kNegligible = 1e-9;

struct Projected
{
  Eigen::Vector3d camera;
  Eigen::Vector2d screen;
  bool inFront = false;
  bool inView = false;
};

Projected project(const Eigen::Matrix4d& view, const Eigen::Matrix4d& projection,
  const Eigen::Vector4d& p, double aspect)
{
  Projected out;
  out.camera = (view * p).head<3>();
  const Eigen::Vector4d clip = projection * p;
  // Ahead of the camera (camera space looks down -z): a parallel projection's w is 1 for points
  // behind it too, which vtkCamera's clipping range never shows.
  out.inFront = clip.w() > 0.0 && out.camera.z() < 0.0;
  const Eigen::Vector2d ndc =
    out.inFront ? Eigen::Vector2d(clip.head<2>() / clip.w()) : Eigen::Vector2d::Zero();
  out.inView = out.inFront && std::abs(ndc.x()) <= 1.0 && std::abs(ndc.y()) <= 1.0;
  // In units of half the screen height in both directions, as pixels are: NDC x spans the
  // width, so on a wide viewport it would count a horizontal motion as shorter than a vertical
  // one of the same pixels.
  out.screen = Eigen::Vector2d(aspect * ndc.x(), ndc.y());
  return out;
}

/// Adds the excess of one point to a running mean: 0 when it does not move, left out (closed)
/// when it moves but its chord is negligible. `unit` is the measure's own unit (1 on the screen,
/// whose coordinates are those of the viewport) or 0 in camera space, where `scale` (the
/// point's distance from the key cameras) sets the size: the tests stay relative to it, so that
/// a scene of size 1e-10 is measured as one of size 1 (with an absolute 1e-9 every point of it
/// read as still, and its excess as 0).
void addExcess(
  double length, double chord, double unit, double scale, double& sum, int& measured, int& closed)
{
  if (chord > kNegligible * (unit + length))
  {
    sum += 100.0 * (length - chord) / chord;
    ++measured;
  }
  else if (length <= kNegligible * (unit + scale))
  {
    ++measured;
  }
  else
  {
    ++closed;
  }
}
} // namespace

SegmentPathMetricResult measureSegments(const Matrices4d& keyViews,
  const Matrices4d& keyProjections, const Matrices4d& sampleViews,
  const Matrices4d& sampleProjections, int samplesPerSegment,
  const std::vector<Eigen::Vector3d>& points, double aspect)
{
  SegmentPathMetricResult out;
  const int keys = static_cast<int>(keyViews.size());
  const int segments = keys - 1;
  if (segments < 1 || samplesPerSegment < 2 || keyProjections.size() != keyViews.size() ||
    sampleViews.size() != static_cast<std::size_t>(segments) * samplesPerSegment ||
    sampleProjections.size() != sampleViews.size() || points.empty())
  {
    return out;
  }
  out.segments.resize(segments);
  out.keys.resize(keys);
  std::vector<double> cameraSum(segments, 0.0), screenSum(segments, 0.0);
  std::vector<double> missCamera(keys, 0.0), missScreen(keys, 0.0);
  std::vector<int> missCameraCount(keys, 0), missScreenCount(keys, 0);
  double totalCamera = 0.0, totalScreen = 0.0;
  const auto addMiss = [&](int index, const Projected& path, const Projected& truth) {
    const double distance = truth.camera.norm();
    if (distance > 0.0)
    {
      missCamera[index] += 100.0 * (path.camera - truth.camera).norm() / distance;
      ++missCameraCount[index];
    }
    if (truth.inFront && path.inFront)
    {
      missScreen[index] += 50.0 * (path.screen - truth.screen).norm();
      ++missScreenCount[index];
    }
  };
  for (const Eigen::Vector3d& point : points)
  {
    const Eigen::Vector4d p(point.x(), point.y(), point.z(), 1.0);
    double lengthCamera = 0.0, chordCamera = 0.0, lengthScreen = 0.0, chordScreen = 0.0;
    double scale = 0.0;
    bool screenValid = true, left = false;
    Projected key = project(keyViews[0], keyProjections[0], p, aspect);
    for (int k = 0; k < segments; ++k)
    {
      const Projected next = project(keyViews[k + 1], keyProjections[k + 1], p, aspect);
      SegmentExcess& segment = out.segments[k];
      double l = 0.0, ls = 0.0;
      bool screenOk = key.inFront && next.inFront, leftHere = false;
      Projected previous = key;
      for (int s = 0; s < samplesPerSegment; ++s)
      {
        const std::size_t j = static_cast<std::size_t>(k) * samplesPerSegment + s;
        const Projected q = project(sampleViews[j], sampleProjections[j], p, aspect);
        l += (q.camera - previous.camera).norm();
        ls += (q.screen - previous.screen).norm();
        screenOk = screenOk && q.inFront;
        leftHere = leftHere || !q.inView;
        // The path's own position at the keys against the true keys (key 0 on segment 0,
        // key k + 1 at the end of segment k).
        if (s == 0 && k == 0)
        {
          addMiss(0, q, key);
        }
        if (s == samplesPerSegment - 1)
        {
          addMiss(k + 1, q, next);
        }
        previous = q;
      }
      l += (next.camera - previous.camera).norm();
      ls += (next.screen - previous.screen).norm();
      const double c = (next.camera - key.camera).norm();
      const double cs = (next.screen - key.screen).norm();
      scale = std::max({ scale, key.camera.norm(), next.camera.norm() });
      addExcess(l, c, 0.0, scale, cameraSum[k], segment.measuredCamera, segment.closedCamera);
      if (screenOk)
      {
        addExcess(ls, cs, 1.0, 0.0, screenSum[k], segment.measuredScreen, segment.closedScreen);
      }
      if (key.inView && next.inView && leftHere)
      {
        ++segment.leavingView;
        left = true;
      }
      lengthCamera += l;
      chordCamera += c;
      lengthScreen += ls;
      chordScreen += cs;
      screenValid = screenValid && screenOk;
      key = next;
    }
    addExcess(lengthCamera, chordCamera, 0.0, scale, totalCamera, out.total.measuredCamera,
      out.total.closedCamera);
    if (screenValid)
    {
      addExcess(lengthScreen, chordScreen, 1.0, 0.0, totalScreen, out.total.measuredScreen,
        out.total.closedScreen);
    }
    out.total.leavingView += left ? 1 : 0;
  }
  for (int k = 0; k < segments; ++k)
  {
    SegmentExcess& segment = out.segments[k];
    segment.camera = segment.measuredCamera ? cameraSum[k] / segment.measuredCamera : 0.0;
    segment.screen = segment.measuredScreen ? screenSum[k] / segment.measuredScreen : 0.0;
  }
  out.total.camera = out.total.measuredCamera ? totalCamera / out.total.measuredCamera : 0.0;
  out.total.screen = out.total.measuredScreen ? totalScreen / out.total.measuredScreen : 0.0;
  for (int k = 0; k < keys; ++k)
  {
    out.keys[k].camera = missCameraCount[k] ? missCamera[k] / missCameraCount[k] : 0.0;
    out.keys[k].screen = missScreenCount[k] ? missScreen[k] / missScreenCount[k] : 0.0;
    out.largestMiss.camera = std::max(out.largestMiss.camera, out.keys[k].camera);
    out.largestMiss.screen = std::max(out.largestMiss.screen, out.keys[k].screen);
  }
  return out;
}

} // namespace lct
