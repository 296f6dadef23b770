#include "vtkLCTCameraParameters.h"

#include <cmath>

namespace
{

/**
 * vtkCamera's frame (position, focal point, view up) written at once. Its setters each rebuild
 * the view transform, the distance and the camera-light transform (three vtkTransform updates
 * and an inverse, ~700 ns), so the three setters an interpolated camera needs cost three
 * rebuilds where one gives the same state. A class derived from vtkCamera may form pointers to
 * the protected members it inherits, and such a pointer applies to any vtkCamera (C++17
 * [class.protected]): the camera passed in keeps its own class, and the rebuild goes through
 * the same (virtual) methods the setters call. Never instantiated.
 */
class FrameWriter : public vtkCamera
{
public:
  FrameWriter() = delete;

  static void Write(vtkCamera* camera, const Eigen::Vector3d& position,
    const Eigen::Vector3d& focalPoint, const Eigen::Vector3d& viewUp)
  {
    double(&cameraPosition)[3] = camera->*(&FrameWriter::Position);
    double(&cameraFocalPoint)[3] = camera->*(&FrameWriter::FocalPoint);
    double(&cameraViewUp)[3] = camera->*(&FrameWriter::ViewUp);
    double(&direction)[3] = camera->*(&FrameWriter::DirectionOfProjection);

    // SetViewUp's normalisation, in its order of operations, so that the stored vector is the
    // one the setter would store.
    double up[3] = { viewUp[0], viewUp[1], viewUp[2] };
    const double norm = std::sqrt(up[0] * up[0] + up[1] * up[1] + up[2] * up[2]);
    if (norm != 0)
    {
      up[0] /= norm;
      up[1] /= norm;
      up[2] /= norm;
    }
    else
    {
      up[0] = 0;
      up[1] = 1;
      up[2] = 0;
    }
    bool same = true;
    for (int i = 0; i < 3; ++i)
    {
      same = same && cameraPosition[i] == position[i] && cameraFocalPoint[i] == focalPoint[i] &&
        cameraViewUp[i] == up[i];
    }
    if (same)
    {
      return; // as each setter returns when its value is unchanged
    }
    const Eigen::Vector3d ahead = focalPoint - position;
    const double distance = ahead.norm();
    for (int i = 0; i < 3; ++i)
    {
      cameraPosition[i] = position[i];
      cameraFocalPoint[i] = focalPoint[i];
      cameraViewUp[i] = up[i];
      // ComputeDistance clamps a distance below 1e-20 along the PREVIOUS direction of
      // projection and moves the focal point there: let that be the new direction, so that an
      // ulp below the clamp the camera still looks at its focal point, not where it looked
      // before (session 28's audit).
      if (distance > 0.0)
      {
        direction[i] = ahead[i] / distance;
      }
    }
    (camera->*(&FrameWriter::ComputeViewTransform))();
    (camera->*(&FrameWriter::ComputeDistance))();
    (camera->*(&FrameWriter::ComputeCameraLightTransform))();
    camera->Modified();
  }
};

} // namespace

namespace vtkLCTCamera
{

void ToVtk(const lct::CameraParameters& c, vtkCamera* camera)
{
  FrameWriter::Write(camera, c.position, c.focalPoint, c.viewUp);
  camera->SetParallelProjection(c.parallelProjection);
  camera->SetUseHorizontalViewAngle(c.horizontalViewAngle);
  camera->SetParallelScale(c.parallelScale);
  camera->SetViewAngle(c.viewAngle);
  camera->SetWindowCenter(c.windowCenter[0], c.windowCenter[1]);
  camera->SetViewShear(c.viewShear[0], c.viewShear[1], c.viewShear[2]);
  camera->SetClippingRange(c.clippingRange[0], c.clippingRange[1]);
}

} // namespace vtkLCTCamera
