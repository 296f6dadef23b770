#include "lct/PathMetric.h"

#include <algorithm>
#include <cmath>

namespace lct
{

PathMetricResult measurePath(
  const std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>& views,
  const std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>& projections,
  const std::vector<Eigen::Vector3d>& points, double aspect)
{
  PathMetricResult out;
  out.leftView.assign(points.size(), 0);
  const std::size_t samples = std::min(views.size(), projections.size());
  if (samples < 2 || points.empty())
  {
    return out;
  }
  // A chord shorter than this fraction of the path's own scale carries no direction: skip it.
  constexpr double kNegligible = 1e-9;
  double cameraSum = 0.0;
  double screenSum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const Eigen::Vector4d p(points[i].x(), points[i].y(), points[i].z(), 1.0);
    double cameraLength = 0.0;
    double screenLength = 0.0;
    double distance = 0.0; // the point's largest distance from the cameras
    bool inFront = true;   // at every sample: else the point has no screen path
    Eigen::Vector3d firstCamera = Eigen::Vector3d::Zero(), lastCamera = Eigen::Vector3d::Zero();
    Eigen::Vector2d firstScreen = Eigen::Vector2d::Zero(), lastScreen = Eigen::Vector2d::Zero();
    for (std::size_t s = 0; s < samples; ++s)
    {
      const Eigen::Vector3d c = (views[s] * p).head<3>();
      const Eigen::Vector4d clip = projections[s] * p;
      // Behind the camera, x / w and y / w are finite but mirrored: no screen position.
      // In front: ahead of the camera (camera space looks down -z), which a parallel projection's
      // w = 1 does not say; for a perspective one w = -z.
      const bool front = clip.w() > 0.0 && c.z() < 0.0;
      const Eigen::Vector2d ndc =
        front ? Eigen::Vector2d(clip.head<2>() / clip.w()) : Eigen::Vector2d::Zero();
      if (!front || std::abs(ndc.x()) > 1.0 || std::abs(ndc.y()) > 1.0)
      {
        out.leftView[i] = 1;
      }
      inFront = inFront && front;
      const Eigen::Vector2d screen(aspect * ndc.x(), ndc.y());
      distance = std::max(distance, c.norm());
      if (s > 0)
      {
        cameraLength += (c - lastCamera).norm();
        screenLength += (screen - lastScreen).norm();
      }
      else
      {
        firstCamera = c;
        firstScreen = screen;
      }
      lastCamera = c;
      lastScreen = screen;
    }
    // Relative to the point's own path and distance in camera space: an absolute 1e-9 read
    // every point of a scene of size 1e-10 as still, and its excess as 0.
    const double cameraChord = (lastCamera - firstCamera).norm();
    if (cameraChord > kNegligible * cameraLength)
    {
      cameraSum += 100.0 * (cameraLength - cameraChord) / cameraChord;
      ++out.pointsMeasuredCamera;
    }
    else if (cameraLength <= kNegligible * distance)
    {
      ++out.pointsMeasuredCamera; // still: no excess
    }
    else
    {
      ++out.closedCamera;
    }
    if (!inFront || !std::isfinite(screenLength))
    {
      continue; // behind the camera at some sample: no screen path (it left the view)
    }
    const double screenChord = (lastScreen - firstScreen).norm();
    if (screenChord > kNegligible * (1.0 + screenLength))
    {
      screenSum += 100.0 * (screenLength - screenChord) / screenChord;
      ++out.pointsMeasuredScreen;
    }
    else if (screenLength <= kNegligible)
    {
      ++out.pointsMeasuredScreen;
    }
    else
    {
      ++out.closedScreen;
    }
  }
  out.cameraSpaceExcess = out.pointsMeasuredCamera ? cameraSum / out.pointsMeasuredCamera : 0.0;
  out.screenSpaceExcess = out.pointsMeasuredScreen ? screenSum / out.pointsMeasuredScreen : 0.0;
  return out;
}

} // namespace lct
