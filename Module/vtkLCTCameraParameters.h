/**
 * @file    vtkLCTCameraParameters.h
 * @brief   (private to the module) a vtkCamera's parameters as lct::CameraParameters and back,
 *          so that every class judges a camera by the same lct::toCameraKey checks
 */
#ifndef vtkLCTCameraParameters_h
#define vtkLCTCameraParameters_h

#include "lct/CameraKey.h"

#include "vtkCamera.h"

#include <string>

namespace vtkLCTCamera
{

/// Everything lct::toCameraKey judges and the interpolators interpolate.
inline lct::CameraParameters FromVtk(vtkCamera* camera)
{
  lct::CameraParameters c;
  camera->GetPosition(c.position.data());
  camera->GetFocalPoint(c.focalPoint.data());
  camera->GetViewUp(c.viewUp.data());
  c.parallelProjection = camera->GetParallelProjection() != 0;
  c.horizontalViewAngle = camera->GetUseHorizontalViewAngle() != 0;
  c.viewAngle = camera->GetViewAngle();
  c.parallelScale = camera->GetParallelScale();
  camera->GetWindowCenter(c.windowCenter.data());
  camera->GetViewShear(c.viewShear.data());
  camera->GetClippingRange(c.clippingRange.data());
  return c;
}

inline void ToVtk(const lct::CameraParameters& c, vtkCamera* camera)
{
  const Eigen::Vector3d back = c.position - c.focalPoint;
  if (back.norm() < 2.0 * lct::kMinCameraDistance)
  {
    // vtkCamera recomputes the distance from the coordinates and clamps it to 1e-20 along its
    // PREVIOUS direction of projection (ComputeDistance): near that minimum, an ulp below it
    // turned the camera to wherever it looked before. Look the right way first (positions this
    // close are within 2e-8 of the origin, so a step of 1e-10 is exact enough and not clamped).
    camera->SetPosition(c.position.data());
    const Eigen::Vector3d ahead = c.position - 1e-10 * back.normalized();
    camera->SetFocalPoint(ahead.data());
  }
  camera->SetFocalPoint(c.focalPoint.data());
  camera->SetPosition(c.position.data());
  // SetFocalPoint measured its distance from the camera's PREVIOUS position, and was clamped
  // (moved by 1e-20) where that position is the new focal point. From the new position the
  // distance is at least kMinCameraDistance, so setting it again is exact. (Only then: each
  // setter rebuilds the view transform, ~15 % of an InterpolateCamera.)
  if (Eigen::Map<const Eigen::Vector3d>(camera->GetFocalPoint()) != c.focalPoint)
  {
    camera->SetFocalPoint(c.focalPoint.data());
  }
  camera->SetViewUp(c.viewUp.data());
  camera->SetParallelProjection(c.parallelProjection);
  camera->SetUseHorizontalViewAngle(c.horizontalViewAngle);
  camera->SetParallelScale(c.parallelScale);
  camera->SetViewAngle(c.viewAngle);
  camera->SetWindowCenter(c.windowCenter[0], c.windowCenter[1]);
  camera->SetViewShear(c.viewShear[0], c.viewShear[1], c.viewShear[2]);
  camera->SetClippingRange(c.clippingRange[0], c.clippingRange[1]);
}

/// Why a key camera of these kinds cannot join keys of the other kinds, or "": a parallel
/// key with perspective ones, or view angles measured horizontally with vertical ones. Every
/// sample of a path takes one projection and one kind of angle (vtkCameraInterpolator sets
/// neither), and the two angles measure different things (a horizontal 60 degrees is a vertical
/// 32 at aspect 2), so neither key's view would be reproduced or measured.
inline std::string KindMismatch(
  bool parallel, bool horizontal, bool otherParallel, bool otherHorizontal)
{
  if (parallel != otherParallel)
  {
    return std::string("a ") + (parallel ? "parallel" : "perspective") +
      " key cannot be mixed with " + (otherParallel ? "parallel" : "perspective") + " keys";
  }
  if (horizontal != otherHorizontal)
  {
    return std::string("a key whose view angle is ") + (horizontal ? "horizontal" : "vertical") +
      " (UseHorizontalViewAngle " + (horizontal ? "on" : "off") +
      ") cannot be mixed with keys whose view angle is " +
      (otherHorizontal ? "horizontal" : "vertical");
  }
  return "";
}

} // namespace vtkLCTCamera

#endif
