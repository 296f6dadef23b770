#include "vtkCameraPathMetric.h"

#include "lct/PathMetric.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>

vtkStandardNewMacro(vtkCameraPathMetric);

namespace
{
Eigen::Matrix4d toEigen(vtkMatrix4x4* m)
{
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m->GetData());
}
} // namespace

//------------------------------------------------------------------------------
vtkCameraPathMetric::vtkCameraPathMetric() = default;
vtkCameraPathMetric::~vtkCameraPathMetric() = default;

//------------------------------------------------------------------------------
void vtkCameraPathMetric::SetPoints(vtkPoints* points)
{
  if (this->Points != points)
  {
    this->Points = points;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPoints* vtkCameraPathMetric::GetPoints()
{
  return this->Points;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::Sample(vtkCamera* camera)
{
  this->Views.push_back(toEigen(camera->GetViewTransformMatrix()));
  this->Projections.push_back(
    toEigen(camera->GetCompositeProjectionTransformMatrix(this->Aspect, -1.0, 1.0)));
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::Measure()
{
  std::vector<Eigen::Vector3d> points(this->Points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < this->Points->GetNumberOfPoints(); ++i)
  {
    this->Points->GetPoint(i, points[i].data());
    if (!points[i].allFinite())
    {
      vtkErrorMacro(<< "point " << i << " is NaN or Inf; results unchanged.");
      return 0;
    }
  }
  for (size_t s = 0; s < this->Views.size(); ++s)
  {
    if (!this->Views[s].allFinite() || !this->Projections[s].allFinite())
    {
      vtkErrorMacro(<< "camera sample " << s << " has a NaN or Inf matrix; results unchanged.");
      return 0;
    }
  }
  const lct::PathMetricResult r = lct::measurePath(this->Views, this->Projections, points);
  if (r.closedCamera > 0 || r.closedScreen > 0)
  {
    vtkErrorMacro(<< "the path is closed for " << std::max(r.closedCamera, r.closedScreen) << " of "
                  << points.size() << " points: they move but end where they started "
                  << (r.closedCamera > 0 ? "in camera space" : "on the screen")
                  << " (e.g. a full orbit), so their excess over a zero chord is unbounded; "
                  << "measure an open part of the path. Results unchanged.");
    return 0;
  }
  if (r.pointsMeasuredScreen == 0)
  {
    vtkErrorMacro(<< "no point stays in front of the camera over the whole path: the screen-space "
                  << "excess is undefined. Results unchanged.");
    return 0;
  }
  if (!std::isfinite(r.cameraSpaceExcess) || !std::isfinite(r.screenSpaceExcess))
  {
    vtkErrorMacro(<< "the path gives non-finite path lengths; results unchanged.");
    return 0;
  }
  this->CameraSpaceExcess = r.cameraSpaceExcess;
  this->ScreenSpaceExcess = r.screenSpaceExcess;
  this->LeftView = r.leftView;
  this->NumberOfPointsLeavingView = 0;
  for (char left : this->LeftView)
  {
    this->NumberOfPointsLeavingView += left ? 1 : 0;
  }
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateInterpolator(vtkCameraInterpolatorLCT* path, double t0, double t1)
{
  if (!path || !std::isfinite(t0) || !std::isfinite(t1))
  {
    vtkErrorMacro(<< "EvaluateInterpolator: null path or non-finite times; results unchanged.");
    return 0;
  }
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "EvaluateInterpolator: no points to measure; results unchanged.");
    return 0;
  }
  this->Views.clear();
  this->Projections.clear();
  vtkNew<vtkCamera> camera; // one camera, re-used: memory does not grow with the samples
  for (int k = 0; k < this->NumberOfSamples; ++k)
  {
    const double t = t0 + (t1 - t0) * k / (this->NumberOfSamples - 1);
    if (!path->InterpolateCamera(t, camera))
    {
      vtkErrorMacro(<< "EvaluateInterpolator: the path failed at t = " << t
                    << "; results unchanged.");
      return 0;
    }
    this->Sample(camera);
  }
  return this->Measure();
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateCameras(vtkCollection* collection)
{
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "EvaluateCameras: no points to measure; results unchanged.");
    return 0;
  }
  const int count = collection ? collection->GetNumberOfItems() : 0;
  if (count < 2 || count > 100000)
  {
    vtkErrorMacro(<< "EvaluateCameras: " << count
                  << " cameras; 2 to 100000 are needed; results unchanged.");
    return 0;
  }
  this->Views.clear();
  this->Projections.clear();
  for (int i = 0; i < count; ++i)
  {
    vtkCamera* camera = vtkCamera::SafeDownCast(collection->GetItemAsObject(i));
    if (!camera)
    {
      vtkErrorMacro(<< "EvaluateCameras: item " << i << " is not a vtkCamera; results "
                    << "unchanged.");
      return 0;
    }
    this->Sample(camera);
  }
  return this->Measure();
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::GetPointLeftView(vtkIdType i)
{
  return (i >= 0 && i < static_cast<vtkIdType>(this->LeftView.size()) && this->LeftView[i]) ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Points: " << this->Points.Get() << "\n";
  os << indent << "Aspect: " << this->Aspect << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "CameraSpaceExcess: " << this->CameraSpaceExcess << " %\n";
  os << indent << "ScreenSpaceExcess: " << this->ScreenSpaceExcess << " %\n";
  os << indent << "NumberOfPointsLeavingView: " << this->NumberOfPointsLeavingView << "\n";
}
