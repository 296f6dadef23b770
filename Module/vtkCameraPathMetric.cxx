#include "vtkCameraPathMetric.h"

#include "lct/PathMetric.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"

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
int vtkCameraPathMetric::Measure(const std::vector<vtkCamera*>& cameras)
{
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "no points to measure; results unchanged.");
    return 0;
  }
  std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>> views, projections;
  for (vtkCamera* camera : cameras)
  {
    views.push_back(toEigen(camera->GetViewTransformMatrix()));
    projections.push_back(
      toEigen(camera->GetCompositeProjectionTransformMatrix(this->Aspect, -1.0, 1.0)));
  }
  std::vector<Eigen::Vector3d> points(this->Points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < this->Points->GetNumberOfPoints(); ++i)
  {
    this->Points->GetPoint(i, points[i].data());
  }
  const lct::PathMetricResult r = lct::measurePath(views, projections, points);
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
  std::vector<vtkSmartPointer<vtkCamera>> owned;
  std::vector<vtkCamera*> cameras;
  for (int k = 0; k < this->NumberOfSamples; ++k)
  {
    owned.push_back(vtkSmartPointer<vtkCamera>::New());
    const double t = t0 + (t1 - t0) * k / (this->NumberOfSamples - 1);
    if (!path->InterpolateCamera(t, owned.back()))
    {
      vtkErrorMacro(<< "EvaluateInterpolator: the path failed at t = " << t
                    << "; results unchanged.");
      return 0;
    }
    cameras.push_back(owned.back());
  }
  return this->Measure(cameras);
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateCameras(vtkCollection* collection)
{
  std::vector<vtkCamera*> cameras;
  if (collection)
  {
    for (int i = 0; i < collection->GetNumberOfItems(); ++i)
    {
      vtkCamera* camera = vtkCamera::SafeDownCast(collection->GetItemAsObject(i));
      if (!camera)
      {
        vtkErrorMacro(<< "EvaluateCameras: item " << i << " is not a vtkCamera; results "
                      << "unchanged.");
        return 0;
      }
      cameras.push_back(camera);
    }
  }
  if (cameras.size() < 2)
  {
    vtkErrorMacro(<< "EvaluateCameras: at least two cameras are needed; results unchanged.");
    return 0;
  }
  return this->Measure(cameras);
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
