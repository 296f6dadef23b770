#include "vtkCameraInterpolatorLCT.h"

#include "lct/CameraKey.h"
#include "lct/Curves.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"

#include "vtkCamera.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkCameraInterpolatorLCT);

namespace
{
lct::CurveScheme toScheme(int type)
{
  switch (type)
  {
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR:
      return lct::CurveScheme::Linear;
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE:
      return lct::CurveScheme::BSpline;
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION:
      return lct::CurveScheme::Subdivision;
    default:
      return lct::CurveScheme::CatmullRom;
  }
}

lct::CameraParameters fromVtk(vtkCamera* camera)
{
  lct::CameraParameters c;
  camera->GetPosition(c.position.data());
  camera->GetFocalPoint(c.focalPoint.data());
  camera->GetViewUp(c.viewUp.data());
  c.parallelProjection = camera->GetParallelProjection() != 0;
  c.viewAngle = camera->GetViewAngle();
  c.parallelScale = camera->GetParallelScale();
  camera->GetWindowCenter(c.windowCenter.data());
  camera->GetViewShear(c.viewShear.data());
  camera->GetClippingRange(c.clippingRange.data());
  return c;
}

void toVtk(const lct::CameraParameters& c, vtkCamera* camera)
{
  camera->SetFocalPoint(c.focalPoint.data());
  camera->SetPosition(c.position.data());
  camera->SetViewUp(c.viewUp.data());
  camera->SetParallelProjection(c.parallelProjection);
  camera->SetParallelScale(c.parallelScale);
  camera->SetViewAngle(c.viewAngle);
  camera->SetWindowCenter(c.windowCenter[0], c.windowCenter[1]);
  camera->SetViewShear(c.viewShear[0], c.viewShear[1], c.viewShear[2]);
  camera->SetClippingRange(c.clippingRange[0], c.clippingRange[1]);
}

struct Key
{
  double Time;
  lct::CameraKey Camera;
  Eigen::Matrix4d CameraMatrix; ///< Hawkins & Grimm's P_b S V, for METHOD_CAMERA_MATRIX
};
} // namespace

/// The keys and the logs of their orientations, updated together whenever the keys change.
/// Only the orientation of the focal frame goes through the key logs: its translation, the focal
/// point, is interpolated linearly (combining whole rigid frames in Polar coordinates would move a
/// focal point that the keys share). Rotations always have logs, so updates cannot fail.
struct vtkCameraInterpolatorLCT::Internals
{
  lct::Keyframes<Key> Keys;
  lct::KeyLogs Orientations;
  /// Logs of the camera matrices (MatrixLog), built on the first CameraMatrix evaluation after a
  /// change, and why they are missing if they are.
  bool CameraMatricesCurrent = false;
  lct::KeyLogs CameraMatrices{ lct::Parametrisation::MatrixLog };
  lct::Status CameraMatricesStatus = lct::Status::Ok;

  const lct::KeyLogs& CameraMatrixLogs()
  {
    if (!this->CameraMatricesCurrent)
    {
      std::vector<Eigen::Matrix4d> matrices;
      for (size_t i = 0; i < this->Keys.size(); ++i)
      {
        matrices.push_back(this->Keys[i].CameraMatrix);
      }
      this->CameraMatricesStatus =
        this->CameraMatrices.build(matrices, lct::Parametrisation::MatrixLog, true);
      this->CameraMatricesCurrent = true;
    }
    return this->CameraMatrices;
  }

  static Eigen::Matrix4d Orientation(const Key& key)
  {
    Eigen::Matrix4d m = key.Camera.focalFrame;
    m.topRightCorner<3, 1>().setZero();
    return m;
  }

  void KeysChanged() { this->CameraMatricesCurrent = false; }

  void Add(const Key& key)
  {
    const int index = this->Keys.position(key.Time);
    if (this->Keys.find(key.Time) == index)
    {
      this->Orientations.replace(index, Orientation(key), false);
      this->Keys.replace(index, key);
    }
    else
    {
      this->Orientations.insert(index, Orientation(key), false);
      this->Keys.insert(index, key);
    }
    this->KeysChanged();
  }

  void Remove(int index)
  {
    this->Orientations.erase(index, false);
    this->Keys.erase(index);
    this->KeysChanged();
  }
};

//------------------------------------------------------------------------------
vtkCameraInterpolatorLCT::vtkCameraInterpolatorLCT()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCameraInterpolatorLCT::~vtkCameraInterpolatorLCT()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::GetNumberOfCameras()
{
  return static_cast<int>(this->Internal->Keys.size());
}

//------------------------------------------------------------------------------
double vtkCameraInterpolatorLCT::GetMinimumT()
{
  return this->Internal->Keys.minimumTime();
}

//------------------------------------------------------------------------------
double vtkCameraInterpolatorLCT::GetMaximumT()
{
  return this->Internal->Keys.maximumTime();
}

//------------------------------------------------------------------------------
void vtkCameraInterpolatorLCT::Initialize()
{
  this->Internal->Keys.clear();
  this->Internal->Orientations = lct::KeyLogs();
  this->Internal->KeysChanged();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::AddCamera(double t, vtkCamera* camera)
{
  if (!camera)
  {
    vtkErrorMacro(<< "AddCamera: null camera; key rejected.");
    return 0;
  }
  if (!std::isfinite(t))
  {
    vtkErrorMacro(<< "AddCamera: the key time " << t << " is not finite; key rejected.");
    return 0;
  }
  const auto key = lct::toCameraKey(fromVtk(camera));
  if (!key)
  {
    vtkErrorMacro(<< "AddCamera at t = " << t << ": "
                  << (key.status == lct::Status::NonFinite
                         ? "the camera has NaN or Inf parameters"
                         : "degenerate camera (position at the focal point, view-up parallel to "
                           "the view direction, view angle outside (0, 180), parallel scale <= 0 "
                           "or clipping range not 0 < near < far)")
                  << "; key rejected.");
    return 0;
  }
  for (size_t i = 0; i < this->Internal->Keys.size(); ++i)
  {
    const Key& other = this->Internal->Keys[i];
    if (other.Time != t && other.Camera.parallelProjection != key.value.parallelProjection)
    {
      vtkErrorMacro(<< "AddCamera at t = " << t << ": a "
                    << (key.value.parallelProjection ? "parallel" : "perspective")
                    << " key cannot be mixed with "
                    << (other.Camera.parallelProjection ? "parallel" : "perspective")
                    << " keys; key rejected.");
      return 0;
    }
  }
  this->Internal->Add(Key{ t, key.value, lct::cameraMatrix(lct::fromCameraKey(key.value)) });
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkCameraInterpolatorLCT::RemoveCamera(double t)
{
  const int index = this->Internal->Keys.find(t);
  if (index < 0)
  {
    return;
  }
  this->Internal->Remove(index);
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::InterpolateCamera(double t, vtkCamera* camera)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (!camera || n == 0 || std::isnan(t))
  {
    vtkErrorMacro(<< "InterpolateCamera: "
                  << (!camera     ? "null camera"
                         : n == 0 ? "no keys"
                                  : "t is NaN")
                  << "; camera unchanged.");
    return 0;
  }
  const lct::CurveWeights w =
    lct::curveWeights(toScheme(this->InterpolationType), in.Keys.times().data(), n, t);
  lct::CameraKey key;
  const lct::Status status = this->ConsistentRotation
    ? in.Orientations.combineAbsolute(w, key.focalFrame)
    : in.Orientations.combineRelative(w, key.focalFrame);
  if (status != lct::Status::Ok)
  {
    vtkErrorMacro(<< "InterpolateCamera(" << t << "): " << lct::describe(status)
                  << "; camera unchanged.");
    return 0;
  }
  key.channels.setZero();
  Eigen::Vector3d focalPoint = Eigen::Vector3d::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    const lct::CameraKey& k = in.Keys[w.key[j]].Camera;
    key.channels += w.weight[j] * k.channels;
    focalPoint += w.weight[j] * k.focalFrame.topRightCorner<3, 1>();
  }
  key.focalFrame.topRightCorner<3, 1>() = focalPoint;
  key.parallelProjection = in.Keys[0].Camera.parallelProjection;
  lct::CameraParameters result = lct::fromCameraKey(key);
  if (this->Method == METHOD_CAMERA_MATRIX)
  {
    const lct::KeyLogs& logs = in.CameraMatrixLogs();
    Eigen::Matrix4d matrix;
    lct::Status matrixStatus = in.CameraMatricesStatus;
    if (matrixStatus == lct::Status::Ok)
    {
      matrixStatus = logs.combineRelative(w, matrix);
    }
    const auto fromMatrix = matrixStatus == lct::Status::Ok
      ? lct::fromCameraMatrix(matrix, result)
      : lct::Result<lct::CameraParameters>::failure(matrixStatus);
    if (!fromMatrix)
    {
      vtkErrorMacro(<< "InterpolateCamera(" << t << "), CameraMatrix method: "
                    << lct::describe(fromMatrix.status) << "; camera unchanged.");
      return 0;
    }
    result = fromMatrix.value;
  }
  toVtk(result, camera);
  return 1;
}

//------------------------------------------------------------------------------
void vtkCameraInterpolatorLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const types[] = { "Linear", "Spline", "BSpline", "Subdivision" };
  os << indent << "InterpolationType: " << types[this->InterpolationType] << "\n";
  os << indent << "ConsistentRotation: " << (this->ConsistentRotation ? "On" : "Off") << "\n";
  os << indent << "Method: " << (this->Method == METHOD_FOCAL_FRAME ? "FocalFrame" : "CameraMatrix")
     << "\n";
  os << indent << "NumberOfCameras: " << this->GetNumberOfCameras() << "\n";
  if (!this->Internal->Keys.empty())
  {
    os << indent << "Time range: [" << this->GetMinimumT() << ", " << this->GetMaximumT() << "]\n";
  }
}
