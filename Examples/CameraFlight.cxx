// CameraFlight <out.png>: a camera path with a centre-of-projection shift, as user code. Three key
// cameras (a 130-degree turn, a zoom and a shifted window centre, see CameraFlightScene::MakeKey)
// go into a vtkCameraInterpolatorLCT exactly as into VTK's vtkCameraInterpolator; the figure shows
// the flight at t = 0.25, 0.5, 0.75 (1200x400). The path also gets Hawkins & Grimm's quality
// metric per key segment against the true keys, printed with VTK's interpolator on the same keys
// (as it is, and with the window centre lerped between the keys, a fair baseline).
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 written, 1 error, 2 usage, 125 no DISPLAY.
#include "CameraFlightScene.h"
#include "FigureProgram.h"

#include "vtkCameraPathMetric.h"
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
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkCamera> key;
    CameraFlightScene::MakeKey(k, key);
    metric->AddKeyCamera(k, key); // the true keys: every path is measured against them
  }
  // Per key segment, at the metric's own resolution, against the true key cameras; VTK's path
  // also with the window centre lerped between the keys (it ignores the window centre: the fair
  // baseline).
  std::printf("CameraFlight: path metric per key segment (cameras per segment until the excess "
              "converges, against the true keys; excess camera / screen %%, key miss camera / "
              "screen %%)\n");
  const auto print = [&](const char* name, int ok) {
    if (!ok)
    {
      std::printf("CameraFlight: %s: not measured\n", name);
      return;
    }
    std::printf("CameraFlight: %-36s segments", name);
    for (int k = 0; k < metric->GetNumberOfSegments(); ++k)
    {
      std::printf(" %.1f / %.1f", metric->GetSegmentCameraSpaceExcess(k),
        metric->GetSegmentScreenSpaceExcess(k));
    }
    std::printf("; total %.1f / %.1f; largest key miss %.2f / %.2f; %d points leave the view "
                "between keys\n",
      metric->GetTotalCameraSpaceExcess(), metric->GetTotalScreenSpaceExcess(),
      metric->GetLargestKeyMissCameraSpace(), metric->GetLargestKeyMissScreenSpace(),
      metric->GetNumberOfPointsLeavingViewBetweenKeys());
  };
  print("LCT path", metric->EvaluateSegments(path));
  print("VTK path", metric->EvaluateSegments(vtkPath, 0));
  print("VTK path, window centre lerped", metric->EvaluateSegments(vtkPath, 1));
  return FigureProgram::Run(argc, argv, "CameraFlight",
    "Renders a camera flight with a centre-of-projection shift at t = 0.25, 0.5, 0.75 to a PNG",
    1200, 400, [](vtkRenderWindow* window, int, std::string* source) {
      return CameraFlightScene::Build(window, true, source);
    });
}
