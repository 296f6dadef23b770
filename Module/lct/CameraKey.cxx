#include "lct/CameraKey.h"

#include <Eigen/Geometry>
#include <Eigen/QR>

#include <algorithm>
#include <cmath>

namespace lct
{

namespace
{
constexpr double kDegreesToRadians = 3.14159265358979323846 / 180.0;
}

namespace
{
template <typename T>
Result<T> failure(Status status, const char* reason, const char** why)
{
  if (why)
  {
    *why = reason;
  }
  return Result<T>::failure(status);
}

bool withinMagnitude(const Eigen::Vector3d& v)
{
  return v.cwiseAbs().maxCoeff() <= kMaxCameraMagnitude;
}
} // namespace

Result<CameraKey> toCameraKey(const CameraParameters& c, const char** why)
{
  using K = CameraKey;
  if (!c.position.allFinite() || !c.focalPoint.allFinite() || !c.viewUp.allFinite())
  {
    return failure<K>(Status::NonFinite, "the position, focal point or view up is NaN or Inf", why);
  }
  if (!std::isfinite(c.viewAngle) || !std::isfinite(c.parallelScale) ||
    !c.windowCenter.allFinite() || !c.viewShear.allFinite() || !c.clippingRange.allFinite())
  {
    return failure<K>(Status::NonFinite,
      "the view angle, parallel scale, window centre, view shear or clipping range is NaN or Inf",
      why);
  }
  if (!withinMagnitude(c.position) || !withinMagnitude(c.focalPoint))
  {
    return failure<K>(Status::OutOfRange,
      "a coordinate of the position or focal point exceeds 1e150 (vtkCamera squares distances)",
      why);
  }
  const Eigen::Vector3d back = c.position - c.focalPoint;
  const double distance = back.stableNorm();
  // Relative to the coordinates (a scene 1e-12 across is as good as one 1e12 across), and at
  // least vtkCamera's minimum distance, below which it moves the focal point.
  const double scale =
    std::max(c.position.cwiseAbs().maxCoeff(), c.focalPoint.cwiseAbs().maxCoeff());
  // (Within round-off of it: vtkCamera's own sum of squares may differ by an ulp.)
  if (!(distance > 1e-12 * scale) || !(distance >= kMinCameraDistance * (1.0 - 1e-12)))
  {
    return failure<K>(Status::InvalidArgument,
      distance == 0.0              ? "the position equals the focal point"
        : distance > 1e-12 * scale ? "the position and the focal point are closer than 1e-20 "
                                     "(vtkCamera clamps shorter distances, moving the focal point)"
                                   : "the position and the focal point are closer than 1e-12 of "
                                     "their magnitude (no view direction)",
      why);
  }
  const Eigen::Vector3d z = back / distance;
  const double upNorm = c.viewUp.stableNorm();
  if (!(upNorm > 0.0))
  {
    return failure<K>(Status::InvalidArgument, "the view up is zero", why);
  }
  Eigen::Vector3d x = (c.viewUp / upNorm).cross(z);
  if (!(x.norm() > 1e-9))
  {
    return failure<K>(
      Status::InvalidArgument, "the view up is parallel to the view direction", why);
  }
  x.normalize();
  const Eigen::Vector3d y = z.cross(x);
  if (!(c.viewAngle > 0.0 && c.viewAngle < 180.0))
  {
    return failure<K>(Status::InvalidArgument, "the view angle is outside (0, 180) degrees", why);
  }
  if (!(c.parallelScale > 0.0) || c.parallelScale > kMaxCameraMagnitude)
  {
    return failure<K>(Status::InvalidArgument, "the parallel scale is not in (0, 1e150]", why);
  }
  if (!(c.clippingRange[0] > 0.0 && c.clippingRange[1] > c.clippingRange[0]) ||
    c.clippingRange[1] > kMaxCameraMagnitude)
  {
    return failure<K>(
      Status::InvalidArgument, "the clipping range is not 0 < near < far <= 1e150", why);
  }
  CameraKey key;
  key.focalFrame.block<3, 1>(0, 0) = x;
  key.focalFrame.block<3, 1>(0, 1) = y;
  key.focalFrame.block<3, 1>(0, 2) = z;
  key.focalFrame.block<3, 1>(0, 3) = c.focalPoint;
  key.parallelProjection = c.parallelProjection;
  key.horizontalViewAngle = c.horizontalViewAngle;
  auto& ch = key.channels;
  ch[CameraKey::LogDistance] = std::log(distance);
  ch[CameraKey::LogTanHalfAngle] = std::log(std::tan(0.5 * c.viewAngle * kDegreesToRadians));
  ch[CameraKey::LogParallelScale] = std::log(c.parallelScale);
  ch[CameraKey::WindowCenterX] = c.windowCenter[0];
  ch[CameraKey::WindowCenterY] = c.windowCenter[1];
  ch[CameraKey::ShearX] = c.viewShear[0];
  ch[CameraKey::ShearY] = c.viewShear[1];
  ch[CameraKey::ShearCenter] = c.viewShear[2];
  // log(near / distance) as a difference of logs: the ratio itself may over- or underflow.
  ch[CameraKey::LogNear] = std::log(c.clippingRange[0]) - ch[CameraKey::LogDistance];
  ch[CameraKey::LogFar] = std::log(c.clippingRange[1]) - ch[CameraKey::LogDistance];
  if (!ch.allFinite())
  {
    return failure<K>(Status::OutOfRange, "a camera parameter is out of range", why);
  }
  return { key, Status::Ok };
}

Result<CameraParameters> fromCameraKey(const CameraKey& key, const char** why)
{
  using C = CameraParameters;
  const auto& ch = key.channels;
  if (!ch.allFinite() || !key.focalFrame.allFinite())
  {
    return failure<C>(Status::NonFinite, "the interpolated camera is NaN or Inf", why);
  }
  const double logMax = std::log(kMaxCameraMagnitude);
  if (ch[CameraKey::LogDistance] > logMax ||
    ch[CameraKey::LogDistance] + std::max(ch[CameraKey::LogNear], ch[CameraKey::LogFar]) > logMax)
  {
    return failure<C>(
      Status::OutOfRange, "the interpolated distance or far clipping plane exceeds 1e150", why);
  }
  if (ch[CameraKey::LogParallelScale] > logMax)
  {
    return failure<C>(Status::OutOfRange, "the interpolated parallel scale exceeds 1e150", why);
  }
  double distance = std::exp(ch[CameraKey::LogDistance]);
  // Between keys at vtkCamera's minimum distance the exp may round just below it.
  if (distance < kMinCameraDistance && distance >= kMinCameraDistance * (1.0 - 1e-12))
  {
    distance = kMinCameraDistance;
  }
  if (!(distance >= kMinCameraDistance) && distance > 0.0)
  {
    return failure<C>(Status::OutOfRange,
      "the interpolated distance is below 1e-20, which vtkCamera cannot hold (it clamps it, "
      "moving the focal point)",
      why);
  }
  CameraParameters c;
  c.focalPoint = key.focalFrame.block<3, 1>(0, 3);
  c.position = c.focalPoint + distance * key.focalFrame.block<3, 1>(0, 2);
  c.viewUp = key.focalFrame.block<3, 1>(0, 1);
  c.parallelProjection = key.parallelProjection;
  c.horizontalViewAngle = key.horizontalViewAngle;
  c.parallelScale = std::exp(ch[CameraKey::LogParallelScale]);
  c.viewAngle = 2.0 * std::atan(std::exp(ch[CameraKey::LogTanHalfAngle])) / kDegreesToRadians;
  c.windowCenter = Eigen::Vector2d(ch[CameraKey::WindowCenterX], ch[CameraKey::WindowCenterY]);
  c.viewShear =
    Eigen::Vector3d(ch[CameraKey::ShearX], ch[CameraKey::ShearY], ch[CameraKey::ShearCenter]);
  c.clippingRange = Eigen::Vector2d(std::exp(ch[CameraKey::LogNear] + ch[CameraKey::LogDistance]),
    std::exp(ch[CameraKey::LogFar] + ch[CameraKey::LogDistance]));
  if (!withinMagnitude(c.position) || !withinMagnitude(c.focalPoint))
  {
    return failure<C>(Status::OutOfRange,
      "the interpolated position or focal point exceeds 1e150 (vtkCamera squares distances)", why);
  }
  if (!(distance > 0.0) || !(c.parallelScale > 0.0) || !(c.clippingRange[0] > 0.0) ||
    !(c.clippingRange[1] > c.clippingRange[0]))
  {
    return failure<C>(Status::OutOfRange,
      "the interpolated distance, parallel scale or clipping range underflows to 0", why);
  }
  if (!(c.viewAngle > 0.0 && c.viewAngle < 180.0))
  {
    return failure<C>(
      Status::OutOfRange, "the interpolated view angle rounds to 0 or 180 degrees", why);
  }
  return { c, Status::Ok };
}

Eigen::Matrix4d cameraMatrix(const CameraParameters& c)
{
  const Eigen::Vector3d z = (c.position - c.focalPoint).normalized();
  const Eigen::Vector3d x = c.viewUp.cross(z).normalized();
  const Eigen::Vector3d y = z.cross(x);
  Eigen::Matrix4d view = Eigen::Matrix4d::Identity();
  view.block<1, 3>(0, 0) = x.transpose();
  view.block<1, 3>(1, 0) = y.transpose();
  view.block<1, 3>(2, 0) = z.transpose();
  view.topRightCorner<3, 1>() = -(view.topLeftCorner<3, 3>() * c.position);
  const double f = 1.0 / std::tan(0.5 * c.viewAngle * kDegreesToRadians);
  Eigen::Matrix4d intrinsic = Eigen::Matrix4d::Identity();
  intrinsic(0, 0) = f;
  intrinsic(1, 1) = f;
  intrinsic(0, 2) = c.windowCenter[0];
  intrinsic(1, 2) = c.windowCenter[1];
  return intrinsic * view;
}

Result<CameraParameters> fromCameraMatrix(const Eigen::Matrix4d& m, const CameraParameters& rest)
{
  using R = Result<CameraParameters>;
  if (!m.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  if (!(a.determinant() > 0.0))
  {
    return R::failure(Status::NegativeDeterminant);
  }
  // RQ by QR of the row-reversed transpose: with J the exchange matrix, (J A)^T = Q U gives
  // A = (J U^T J)(J Q^T) with J U^T J upper triangular.
  Eigen::Matrix3d j = Eigen::Matrix3d::Zero();
  j(0, 2) = j(1, 1) = j(2, 0) = 1.0;
  const Eigen::HouseholderQR<Eigen::Matrix3d> qr((j * a).transpose());
  const Eigen::Matrix3d u = qr.matrixQR().triangularView<Eigen::Upper>();
  Eigen::Matrix3d k = j * u.transpose() * j;
  Eigen::Matrix3d rotation = j * qr.householderQ().transpose();
  // Make the diagonal of K positive (A = K R is unchanged by D K D R with D = D^-1).
  for (int i = 0; i < 3; ++i)
  {
    if (k(i, i) < 0.0)
    {
      k.col(i) = -k.col(i);
      rotation.row(i) = -rotation.row(i);
    }
  }
  k /= k(2, 2);
  CameraParameters c = rest;
  const Eigen::Vector3d position = -(rotation.transpose() * k.inverse() * m.topRightCorner<3, 1>());
  const double distance = (rest.position - rest.focalPoint).norm();
  c.position = position;
  c.focalPoint = position - distance * rotation.row(2).transpose();
  c.viewUp = rotation.row(1).transpose();
  c.viewAngle = 2.0 * std::atan(1.0 / k(1, 1)) / kDegreesToRadians;
  c.windowCenter = Eigen::Vector2d(k(0, 2), k(1, 2));
  if (!c.position.allFinite() || !c.focalPoint.allFinite() || !c.viewUp.allFinite() ||
    !c.windowCenter.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  if (!withinMagnitude(c.position) || !withinMagnitude(c.focalPoint) ||
    !(c.viewAngle > 0.0 && c.viewAngle < 180.0))
  {
    return R::failure(Status::OutOfRange);
  }
  return { c, Status::Ok };
}

} // namespace lct
