// The camera-flight figure, shared by Examples/CameraFlight.cxx and the regression tests
// Testing/Cxx/TestCameraFlightLCT.cxx and TestCameraFlightVTK.cxx.
//
// A small scene (the Wuson mesh of Examples/SceneModel.h on a pedestal, a red sphere, a blue cube
// and a green cone around it, on a grey floor) and a camera path of three keys: a 130-degree turn
// about the scene, a zoom (view angle 40 -> 28 -> 22 degrees) and a shift of the centre of
// projection (window centre (0, 0) -> (0.35, 0.15) -> (-0.2, 0.3)). The figure shows the path at
// t = 0.25, 0.5 and 0.75 of the flight side by side, through vtkCameraInterpolatorLCT or, for
// comparison, VTK's vtkCameraInterpolator (its default spline; it ignores the window centre).
//
// Header-only: everything is `inline`. Needs LCT::LCT, VTK::IOPLY, VTK::IOGeometry,
// VTK::FiltersSources, VTK::RenderingCore and an OpenGL2 render window.
#ifndef CameraFlightScene_h
#define CameraFlightScene_h

#include "SceneModel.h"
#include "vtkCameraInterpolatorLCT.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCameraInterpolator.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkCylinderSource.h"
#include "vtkNew.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"

#include <cmath>
#include <string>
#include <vector>

namespace CameraFlightScene
{

/// Times of the three panels, as fractions of the flight.
constexpr double PanelTimes[3] = { 0.25, 0.5, 0.75 };

/// Key k (0, 1, 2 at t = 0, 1, 2) of the flight.
inline void MakeKey(int k, vtkCamera* camera)
{
  const double turn[3] = { -40.0, 30.0, 90.0 }; // azimuth in degrees: 130 in all
  const double angle[3] = { 40.0, 28.0, 22.0 };
  const double center[3][2] = { { 0.0, 0.0 }, { 0.35, 0.15 }, { -0.2, 0.3 } };
  const double a = turn[k] * 3.14159265358979323846 / 180.0;
  const double distance = 7.0 - 1.0 * k;
  camera->SetFocalPoint(0.0, 0.4, 0.0);
  camera->SetPosition(distance * std::sin(a), 2.5 + 0.5 * k, distance * std::cos(a));
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(angle[k]);
  camera->SetWindowCenter(center[k][0], center[k][1]);
  camera->SetClippingRange(0.5, 30.0);
}

inline vtkSmartPointer<vtkActor> MakeActor(vtkPolyDataAlgorithm* source, const double color[3])
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(source->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  return actor;
}

/// The actors of the scene (shared by the panels).
inline std::vector<vtkSmartPointer<vtkActor>> MakeActors(std::string* source)
{
  std::vector<vtkSmartPointer<vtkActor>> actors;
  vtkNew<vtkCubeSource> floor;
  floor->SetBounds(-3.0, 3.0, -0.05, 0.0, -3.0, 3.0);
  const double grey[3] = { 0.75, 0.75, 0.72 };
  actors.push_back(MakeActor(floor, grey));

  vtkNew<vtkCylinderSource> pedestal;
  pedestal->SetResolution(48);
  pedestal->SetHeight(0.3);
  pedestal->SetRadius(0.8);
  pedestal->SetCenter(0.0, 0.15, 0.0);
  const double stone[3] = { 0.55, 0.5, 0.45 };
  actors.push_back(MakeActor(pedestal, stone));

  vtkNew<vtkTransform> pose;
  SceneModel::MakePose(SceneModel::LoadModel(source), pose);
  auto model = vtkSmartPointer<vtkPolyData>::New();
  model->DeepCopy(SceneModel::LoadModel());
  vtkNew<vtkPolyDataMapper> modelMapper;
  modelMapper->SetInputData(model);
  auto wuson = vtkSmartPointer<vtkActor>::New();
  wuson->SetMapper(modelMapper);
  vtkNew<vtkTransform> placement;
  placement->PostMultiply();
  placement->Concatenate(pose);
  placement->Scale(1.4, 1.4, 1.4);
  placement->Translate(0.0, 0.85, 0.0);
  wuson->SetUserTransform(placement);
  wuson->GetProperty()->SetColor(0.85, 0.65, 0.35);
  actors.push_back(wuson);

  vtkNew<vtkSphereSource> sphere;
  sphere->SetCenter(1.8, 0.45, 1.2);
  sphere->SetRadius(0.45);
  sphere->SetThetaResolution(36);
  sphere->SetPhiResolution(24);
  const double red[3] = { 0.8, 0.2, 0.15 };
  actors.push_back(MakeActor(sphere, red));

  vtkNew<vtkCubeSource> cube;
  cube->SetBounds(-2.2, -1.4, 0.0, 0.8, -1.6, -0.8);
  const double blue[3] = { 0.2, 0.4, 0.8 };
  actors.push_back(MakeActor(cube, blue));

  vtkNew<vtkConeSource> cone;
  cone->SetCenter(-1.2, 0.6, 1.9);
  cone->SetDirection(0.0, 1.0, 0.0);
  cone->SetHeight(1.2);
  cone->SetRadius(0.45);
  cone->SetResolution(48);
  const double green[3] = { 0.25, 0.65, 0.3 };
  actors.push_back(MakeActor(cone, green));
  return actors;
}

/**
 * Fill `window` with three viewports showing the flight at PanelTimes through the LCT
 * interpolator (`lct` true) or VTK's. Returns false (after printing why) on failure.
 */
inline bool Build(vtkRenderWindow* window, bool lct, std::string* source = nullptr)
{
  vtkNew<vtkCameraInterpolatorLCT> ours;
  vtkNew<vtkCameraInterpolator> theirs;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkCamera> key;
    MakeKey(k, key);
    if (!ours->AddCamera(k, key))
    {
      return false;
    }
    theirs->AddCamera(k, key);
  }
  const auto actors = MakeActors(source);
  for (int panel = 0; panel < 3; ++panel)
  {
    vtkNew<vtkRenderer> renderer;
    renderer->SetViewport(panel / 3.0, 0.0, (panel + 1) / 3.0, 1.0);
    renderer->SetBackground(0.96, 0.95, 0.92);
    for (const auto& actor : actors)
    {
      renderer->AddActor(actor);
    }
    const double t = 2.0 * PanelTimes[panel];
    if (lct)
    {
      if (!ours->InterpolateCamera(t, renderer->GetActiveCamera()))
      {
        return false;
      }
    }
    else
    {
      theirs->InterpolateCamera(t, renderer->GetActiveCamera());
    }
    window->AddRenderer(renderer);
  }
  return true;
}

} // namespace CameraFlightScene

#endif
