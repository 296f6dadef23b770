/**
 * @file    vtkLCTCameraParameters.h
 * @brief   (private to the module) a vtkCamera's parameters as lct::CameraParameters and back,
 *          so that every class judges a camera by the same lct::toCameraKey checks
 */
#ifndef vtkLCTCameraParameters_h
#define vtkLCTCameraParameters_h

#include "lct/CameraKey.h"

#include "vtkCamera.h"
#include "vtkLCTModule.h"

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

/**
 * Writes `c` into `camera`: the state vtkCamera's setters leave (SetFocalPoint, SetPosition,
 * SetViewUp, then the projection's), with the view transform, distance and camera-light
 * transform rebuilt once instead of once per frame setter (each rebuild was ~25 % of an
 * InterpolateCamera), and one ModifiedEvent for the frame.
 */
VTKLCT_EXPORT void ToVtk(const lct::CameraParameters& c, vtkCamera* camera);

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
