#include "lct/CameraKey.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace lct
{

namespace
{
constexpr double kDegreesToRadians = 3.14159265358979323846 / 180.0;
}

Result<CameraKey> toCameraKey(const CameraParameters& c)
{
  using R = Result<CameraKey>;
  if (!c.position.allFinite() || !c.focalPoint.allFinite() || !c.viewUp.allFinite() ||
    !std::isfinite(c.viewAngle) || !std::isfinite(c.parallelScale) || !c.windowCenter.allFinite() ||
    !c.viewShear.allFinite() || !c.clippingRange.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Vector3d back = c.position - c.focalPoint;
  const double distance = back.norm();
  const double scale = std::max({ 1.0, c.position.norm(), c.focalPoint.norm() });
  if (!(distance > 1e-12 * scale))
  {
    return R::failure(Status::InvalidArgument); // position at the focal point
  }
  const Eigen::Vector3d z = back / distance;
  Eigen::Vector3d x = c.viewUp.cross(z);
  // View up parallel to the view direction (or zero): no orientation.
  if (!(x.norm() > 1e-9 * c.viewUp.norm()))
  {
    return R::failure(Status::InvalidArgument);
  }
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  if (!(c.parallelScale > 0.0) || !(c.viewAngle > 0.0 && c.viewAngle < 180.0))
  {
    return R::failure(Status::InvalidArgument);
  }
  if (!(c.clippingRange[0] > 0.0 && c.clippingRange[1] > c.clippingRange[0]))
  {
    return R::failure(Status::InvalidArgument);
  }
  CameraKey key;
  key.focalFrame.block<3, 1>(0, 0) = x;
  key.focalFrame.block<3, 1>(0, 1) = y;
  key.focalFrame.block<3, 1>(0, 2) = z;
  key.focalFrame.block<3, 1>(0, 3) = c.focalPoint;
  key.parallelProjection = c.parallelProjection;
  auto& ch = key.channels;
  ch[CameraKey::LogDistance] = std::log(distance);
  ch[CameraKey::LogTanHalfAngle] = std::log(std::tan(0.5 * c.viewAngle * kDegreesToRadians));
  ch[CameraKey::LogParallelScale] = std::log(c.parallelScale);
  ch[CameraKey::WindowCenterX] = c.windowCenter[0];
  ch[CameraKey::WindowCenterY] = c.windowCenter[1];
  ch[CameraKey::ShearX] = c.viewShear[0];
  ch[CameraKey::ShearY] = c.viewShear[1];
  ch[CameraKey::ShearCenter] = c.viewShear[2];
  ch[CameraKey::LogNear] = std::log(c.clippingRange[0] / distance);
  ch[CameraKey::LogFar] = std::log(c.clippingRange[1] / distance);
  return { key, Status::Ok };
}

CameraParameters fromCameraKey(const CameraKey& key)
{
  const auto& ch = key.channels;
  const double distance = std::exp(ch[CameraKey::LogDistance]);
  CameraParameters c;
  c.focalPoint = key.focalFrame.block<3, 1>(0, 3);
  c.position = c.focalPoint + distance * key.focalFrame.block<3, 1>(0, 2);
  c.viewUp = key.focalFrame.block<3, 1>(0, 1);
  c.parallelProjection = key.parallelProjection;
  c.parallelScale = std::exp(ch[CameraKey::LogParallelScale]);
  c.viewAngle = 2.0 * std::atan(std::exp(ch[CameraKey::LogTanHalfAngle])) / kDegreesToRadians;
  c.windowCenter = Eigen::Vector2d(ch[CameraKey::WindowCenterX], ch[CameraKey::WindowCenterY]);
  c.viewShear =
    Eigen::Vector3d(ch[CameraKey::ShearX], ch[CameraKey::ShearY], ch[CameraKey::ShearCenter]);
  c.clippingRange = distance *
    Eigen::Vector2d(std::exp(ch[CameraKey::LogNear]), std::exp(ch[CameraKey::LogFar]));
  return c;
}

} // namespace lct
