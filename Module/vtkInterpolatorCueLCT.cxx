#include "vtkInterpolatorCueLCT.h"

#include "vtkLCTCheckedSet.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkProp3D.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransformInterpolatorLCT.h"

#include <vector>

vtkStandardNewMacro(vtkInterpolatorCueLCT);

struct vtkInterpolatorCueLCT::Internals
{
  vtkSmartPointer<vtkCamera> Camera;
  vtkSmartPointer<vtkCameraInterpolatorLCT> CameraPath;
  vtkSmartPointer<vtkRenderer> Renderer;
  std::vector<std::pair<vtkSmartPointer<vtkProp3D>, vtkSmartPointer<vtkTransformInterpolatorLCT>>>
    Props;
};

//------------------------------------------------------------------------------
vtkInterpolatorCueLCT::vtkInterpolatorCueLCT()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkInterpolatorCueLCT::~vtkInterpolatorCueLCT()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::SetCamera(vtkCamera* camera)
{
  if (this->Internal->Camera != camera)
  {
    this->Internal->Camera = camera;
    this->Modified();
  }
}

vtkCamera* vtkInterpolatorCueLCT::GetCamera()
{
  return this->Internal->Camera;
}

void vtkInterpolatorCueLCT::SetCameraInterpolator(vtkCameraInterpolatorLCT* path)
{
  if (this->Internal->CameraPath != path)
  {
    this->Internal->CameraPath = path;
    this->Modified();
  }
}

vtkCameraInterpolatorLCT* vtkInterpolatorCueLCT::GetCameraInterpolator()
{
  return this->Internal->CameraPath;
}

void vtkInterpolatorCueLCT::SetRenderer(vtkRenderer* renderer)
{
  if (this->Internal->Renderer != renderer)
  {
    this->Internal->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkInterpolatorCueLCT::GetRenderer()
{
  return this->Internal->Renderer;
}

//------------------------------------------------------------------------------
int vtkInterpolatorCueLCT::AddProp(vtkProp3D* prop, vtkTransformInterpolatorLCT* path)
{
  if (!prop || !path)
  {
    vtkErrorMacro(<< "AddProp: null prop or interpolator; not added.");
    return 0;
  }
  this->Internal->Props.emplace_back(prop, path);
  this->Modified();
  return 1;
}

void vtkInterpolatorCueLCT::RemoveAllProps()
{
  if (!this->Internal->Props.empty())
  {
    this->Internal->Props.clear();
    this->Modified();
  }
}

int vtkInterpolatorCueLCT::GetNumberOfProps()
{
  return static_cast<int>(this->Internal->Props.size());
}

//------------------------------------------------------------------------------
double vtkInterpolatorCueLCT::KeyTime(double cueTime, double minimumT, double maximumT)
{
  if (this->KeyTimeMapping == KEY_TIME_MAPPING_CUE_TIME)
  {
    return cueTime - this->StartTime;
  }
  const double duration = this->EndTime - this->StartTime;
  const double u = duration > 0.0 ? (cueTime - this->StartTime) / duration : 0.0;
  return minimumT + u * (maximumT - minimumT);
}

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::TickInternal(double currenttime, double deltatime, double clocktime)
{
  Internals& in = *this->Internal;
  if (in.Camera && in.CameraPath)
  {
    const double t =
      this->KeyTime(currenttime, in.CameraPath->GetMinimumT(), in.CameraPath->GetMaximumT());
    if (!in.CameraPath->InterpolateCamera(t, in.Camera))
    {
      vtkErrorMacro(<< "TickInternal: the camera path failed at key time " << t
                    << "; camera unchanged.");
    }
    else if (in.Renderer)
    {
      in.Renderer->ResetCameraClippingRange();
    }
  }
  vtkNew<vtkMatrix4x4> matrix;
  for (auto& [prop, path] : in.Props)
  {
    const double t = this->KeyTime(currenttime, path->GetMinimumT(), path->GetMaximumT());
    if (path->InterpolateTransform(t, matrix))
    {
      vtkNew<vtkMatrix4x4> copy; // each prop keeps its own matrix
      copy->DeepCopy(matrix);
      prop->SetUserMatrix(copy);
    }
    else
    {
      vtkErrorMacro(<< "TickInternal: a prop path failed at key time " << t << "; prop unchanged.");
    }
  }
  this->Superclass::TickInternal(currenttime, deltatime, clocktime);
}

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Camera: " << this->Internal->Camera.Get() << "\n";
  os << indent << "CameraInterpolator: " << this->Internal->CameraPath.Get() << "\n";
  os << indent << "Renderer: " << this->Internal->Renderer.Get() << "\n";
  os << indent << "NumberOfProps: " << this->Internal->Props.size() << "\n";
  os << indent
     << "KeyTimeMapping: " << (this->KeyTimeMapping == KEY_TIME_MAPPING_RANGE ? "Range" : "CueTime")
     << "\n";
}

//------------------------------------------------------------------------------
int vtkInterpolatorCueLCT::SetKeyTimeMapping(int value)
{
  return vtkLCTCheckedSet::Set(this, "KeyTimeMapping", this->KeyTimeMapping, value,
    static_cast<int>(KEY_TIME_MAPPING_RANGE), static_cast<int>(KEY_TIME_MAPPING_CUE_TIME));
}
