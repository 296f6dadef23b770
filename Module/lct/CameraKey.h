/**
 * @file CameraKey.h
 * @brief A camera as a rigid focal frame plus scalar intrinsics, the form in which camera keys
 *        are interpolated (after Hawkins & Grimm 2005, with the rigid factor about the focal
 *        point).
 *
 * Hawkins & Grimm interpolate the camera matrix P S R T with P = P_a P_b split so that P_b
 * (aspect, skew, centre of projection u0, v0) can be interpolated by its log, relative to a key
 * (eq. 5, 7). A vtkCamera has more structure than a general P S R T: its intrinsics are the view
 * angle (or parallel scale), the window centre (the paper's u0, v0; vtkCamera::SetWindowCenter),
 * the view shear (the paper's skew; vtkCamera::SetViewShear) and the distance to the focal point.
 * Folding them into one matrix with the rigid motion gives in-betweens with skew and anisotropy no
 * vtkCamera can represent; measured on random key pairs, interpolating each factor by its own log
 * with the rigid motion taken about the focal point moves scene points the least. So a key is:
 *
 * - the focal frame F = [x y z | focal point], x = right, y = up, z = back (towards the camera):
 *   its orientation is interpolated by the key-log machinery (lct/KeyLogs.h), its focal point
 *   linearly with the same weights (so a focal point shared by the keys stays fixed, which the
 *   Polar combination of whole rigid frames would not do);
 * - scalar channels interpolated linearly with the same curve weights: log distance,
 *   log tan(view angle / 2) (so f = cot(angle/2) is geometric), log parallel scale (both are
 *   kept whatever the projection, as vtkCamera keeps both), window
 *   centre (its unipotent matrix interpolates linearly), view shear, and the clipping range as
 *   log(near / distance), log(far / distance).
 */
#ifndef lct_CameraKey_h
#define lct_CameraKey_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// The parameters of a vtkCamera that define its view and projection.
struct CameraParameters
{
  Eigen::Vector3d position{ 0, 0, 1 };
  Eigen::Vector3d focalPoint{ 0, 0, 0 };
  Eigen::Vector3d viewUp{ 0, 1, 0 };
  bool parallelProjection = false;
  bool horizontalViewAngle = false; ///< viewAngle is horizontal (vtkCamera::UseHorizontalViewAngle)
  double viewAngle = 30.0;          ///< degrees, perspective
  double parallelScale = 1.0;       ///< parallel
  Eigen::Vector2d windowCenter{ 0, 0 };
  Eigen::Vector3d viewShear{ 0, 0, 1 }; ///< dx/dz, dy/dz, center (vtkCamera::SetViewShear)
  Eigen::Vector2d clippingRange{ 0.01, 1000.01 };
};

/// The interpolated form of a camera.
struct CameraKey
{
  /// Indices of the scalar channels.
  enum Channel
  {
    LogDistance = 0,
    LogTanHalfAngle,  ///< log tan(view angle / 2)
    LogParallelScale, ///< log parallel scale
    WindowCenterX,
    WindowCenterY,
    ShearX,
    ShearY,
    ShearCenter,
    LogNear, ///< log(near / distance)
    LogFar,  ///< log(far / distance)
    ChannelCount
  };
  using Channels = Eigen::Matrix<double, ChannelCount, 1>;

  Eigen::Matrix4d focalFrame = Eigen::Matrix4d::Identity();
  Channels channels = Channels::Zero();
  bool parallelProjection = false;
  bool horizontalViewAngle = false;
};

/// The largest coordinate, distance, parallel scale or clipping distance accepted: vtkCamera
/// squares distances (ComputeDistance, the view transform), which overflows beyond ~1e154.
constexpr double kMaxCameraMagnitude = 1e150;

/// The smallest distance between the position and the focal point: vtkCamera clamps shorter ones
/// to it (ComputeDistance), moving the focal point along its previous direction of projection.
constexpr double kMinCameraDistance = 1e-20;

/// The key of a camera. Fails with NonFinite (a NaN or Inf parameter), OutOfRange (a magnitude
/// beyond kMaxCameraMagnitude) or InvalidArgument for a degenerate camera: position at the focal
/// point or closer to it than kMinCameraDistance, view up zero or parallel to the view direction,
/// view angle outside (0, 180), parallel scale <= 0, or clipping range not 0 < near < far. `why`,
/// when given, receives a phrase naming the one condition that failed (e.g. "the position equals
/// the focal point").
VTKLCT_EXPORT Result<CameraKey> toCameraKey(
  const CameraParameters& camera, const char** why = nullptr);

/// The camera of a key (view up orthogonalised, as VTK renders it). Fails with OutOfRange when
/// the channels give a camera beyond vtkCamera's range (distance, scale or clipping range
/// overflowing or underflowing, a view angle rounding to 0 or 180), naming it in `why`.
VTKLCT_EXPORT Result<CameraParameters> fromCameraKey(
  const CameraKey& key, const char** why = nullptr);

/**
 * Hawkins & Grimm's literal formulation (eq. 5, 7), offered for comparison: the camera matrix
 * C = P_b S V with V = [R | -R c] the view transform, S = diag(f, f, 1, 1), f = cot(view angle /
 * 2), and P_b = [[1, 0, u0, 0], [0, 1, v0, 0], [0, 0, 1, 0], [0, 0, 0, 1]] holding the window
 * centre (u0, v0) (the paper's aspect and skew are 1 and 0 for a vtkCamera). The whole matrix is
 * then interpolated by its log relative to a key; in between it generally acquires skew and
 * anisotropy, which `fromCameraMatrix` drops (it keeps f_y) because a vtkCamera cannot show them.
 */
VTKLCT_EXPORT Eigen::Matrix4d cameraMatrix(const CameraParameters& camera);

/// The camera of a camera matrix (RQ decomposition of its linear part), with the distance,
/// parallel scale, view shear, clipping range and projection type taken from `rest`.
/// Fails with NonFinite or NegativeDeterminant for matrices that are no camera.
VTKLCT_EXPORT Result<CameraParameters> fromCameraMatrix(
  const Eigen::Matrix4d& matrix, const CameraParameters& rest);

} // namespace lct

#endif
