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

#include <algorithm>
#include <cmath>
#include <limits>
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
bool vtkInterpolatorCueLCT::HasValidTimes(double cueTime) const
{
  return std::isfinite(cueTime) && std::isfinite(this->StartTime) && std::isfinite(this->EndTime) &&
    (this->KeyTimeMapping == KEY_TIME_MAPPING_CUE_TIME || this->EndTime >= this->StartTime);
}

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::Initialize()
{
  if (!this->HasValidTimes(this->StartTime))
  {
    vtkErrorMacro(<< "Initialize: a cue from " << this->StartTime << " to " << this->EndTime
                  << " cannot run (NaN or infinite times, or an end before the start): no tick "
                     "will move the camera or the props.");
  }
  this->Superclass::Initialize();
}

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::StartCueInternal()
{
  if (this->Internal->CameraPath && !this->Internal->Camera)
  {
    vtkErrorMacro(<< "StartCueInternal: the cue has a camera interpolator but no camera "
                     "(SetCamera, e.g. the renderer's active camera): the camera path is not "
                     "played.");
  }
  this->Superclass::StartCueInternal();
}

//------------------------------------------------------------------------------
double vtkInterpolatorCueLCT::KeyTime(double cueTime, double minimumT, double maximumT)
{
  if (!this->HasValidTimes(cueTime))
  {
    return minimumT;
  }
  if (this->KeyTimeMapping == KEY_TIME_MAPPING_CUE_TIME)
  {
    // Beyond the double range (a cue from -1e308 at 1e308) the largest finite time, not Inf.
    return std::clamp(cueTime - this->StartTime, std::numeric_limits<double>::lowest(),
      std::numeric_limits<double>::max());
  }
  double duration = this->EndTime - this->StartTime;
  double elapsed = cueTime - this->StartTime;
  if (!std::isfinite(duration) || !std::isfinite(elapsed))
  {
    // Halves of finite doubles never overflow when subtracted (a cue from -1e308 to 1e308).
    duration = 0.5 * this->EndTime - 0.5 * this->StartTime;
    elapsed = 0.5 * cueTime - 0.5 * this->StartTime;
  }
  // Cue times outside the cue map to its ends (the interpolators clamp there anyway): beyond
  // them u would extrapolate, and (1 - u) minimumT + u maximumT overflow to Inf or NaN.
  const double u = duration > 0.0 ? std::clamp(elapsed / duration, 0.0, 1.0) : 0.0;
  // Exactly minimumT and maximumT at the cue's ends, and no overflow of maximumT - minimumT.
  return (1.0 - u) * minimumT + u * maximumT;
}

namespace
{
/// vtkRenderer::ResetCameraClippingRange fits the renderer's ACTIVE camera, which need not be
/// the camera the cue drives: that one is made active for the fit (VTK's own rule, not a copy of
/// it), and the renderer's own camera, if it had one, is put back.
void RefitClippingRange(vtkRenderer* renderer, vtkCamera* camera)
{
  vtkSmartPointer<vtkCamera> active =
    renderer->IsActiveCameraCreated() ? renderer->GetActiveCamera() : nullptr;
  if (active == camera)
  {
    renderer->ResetCameraClippingRange();
    return;
  }
  renderer->SetActiveCamera(camera);
  renderer->ResetCameraClippingRange();
  renderer->SetActiveCamera(active);
}
} // namespace

//------------------------------------------------------------------------------
void vtkInterpolatorCueLCT::TickInternal(double currenttime, double deltatime, double clocktime)
{
  Internals& in = *this->Internal;
  if (!this->HasValidTimes(currenttime))
  {
    vtkErrorMacro(<< "TickInternal: cue time " << currenttime << " of a cue from "
                  << this->StartTime << " to " << this->EndTime
                  << " maps to no key time (NaN or infinite times, or an end before the start); "
                     "nothing moved.");
    this->Superclass::TickInternal(currenttime, deltatime, clocktime);
    return;
  }
  // Props first: the camera's clipping range is refitted to where this tick puts them.
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
      RefitClippingRange(in.Renderer, in.Camera);
    }
  }
  else if (in.Camera && in.Renderer && !in.Props.empty())
  {
    // A still camera watching moving props: its clipping range follows them all the same.
    RefitClippingRange(in.Renderer, in.Camera);
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
