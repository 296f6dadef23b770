// CameraFlight <out.png>: a camera path with a centre-of-projection shift, as user code. Three key
// cameras (a 130-degree turn, a zoom and a shifted window centre, see CameraFlightScene::MakeKey)
// go into a vtkCameraInterpolatorLCT exactly as into VTK's vtkCameraInterpolator; the figure shows
// the flight at t = 0.25, 0.5, 0.75 (1200x400). The path also gets Hawkins & Grimm's quality
// metric, printed against VTK's interpolator on the same keys.
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 written, 1 error, 2 usage, 125 no DISPLAY.
#include "CameraFlightScene.h"
#include "FigureProgram.h"

#include "vtkCameraPathMetric.h"
#include "vtkCollection.h"
#include "vtkPoints.h"
#include "vtkSphereSource.h"

#include <cstdio>

int main(int argc, char* argv[])
{
  // The user code: keys in, cameras out, and the path's quality.
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<vtkCameraInterpolator> vtkPath;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkCamera> key;
    CameraFlightScene::MakeKey(k, key);
    path->AddCamera(k, key);
    vtkPath->AddCamera(k, key);
  }
  vtkNew<vtkSphereSource> sample; // points spread over the scene
  sample->SetRadius(2.0);
  sample->Update();
  vtkNew<vtkCameraPathMetric> metric;
  metric->SetPoints(sample->GetOutput()->GetPoints());
  metric->SetNumberOfSamples(21);
  if (metric->EvaluateInterpolator(path, 0.0, 2.0))
  {
    std::printf("CameraFlight: LCT path: %.1f %% excess in camera space, %.1f %% on screen\n",
      metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess());
  }
  vtkNew<vtkCollection> cameras;
  for (int s = 0; s <= 20; ++s)
  {
    vtkNew<vtkCamera> c;
    vtkPath->InterpolateCamera(0.1 * s, c);
    cameras->AddItem(c);
  }
  if (metric->EvaluateCameras(cameras))
  {
    std::printf("CameraFlight: VTK path: %.1f %% excess in camera space, %.1f %% on screen\n",
      metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess());
  }
  return FigureProgram::Run(argc, argv, "CameraFlight",
    "Renders a camera flight with a centre-of-projection shift at t = 0.25, 0.5, 0.75 to a PNG",
    1200, 400, [](vtkRenderWindow* window, int, std::string* source) {
      return CameraFlightScene::Build(window, true, source);
    });
}
