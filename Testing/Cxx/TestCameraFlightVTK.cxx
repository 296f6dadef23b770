// Regression image of the camera flight of TestCameraFlightLCT through VTK's vtkCameraInterpolator
// and a shift of the centre of projection, shown at t = 0.25, 0.5, 0.75 (Examples/CameraFlightScene.h).
// (its default spline ignores the window centre): documents the difference, not a target.
#include "../../Examples/CameraFlightScene.h"

#include "vtkRegressionTestImage.h"
#include "vtkRenderWindowInteractor.h"

#include <cstdlib>
#include <iostream>

int TestCameraFlightVTK(int argc, char* argv[])
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << "TestCameraFlightVTK: DISPLAY is not set (run under xvfb-run -a); skipped.\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(600, 200);
  if (!CameraFlightScene::Build(renWin, false))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindowInteractor> iren;
  iren->SetRenderWindow(renWin);
  renWin->Render();
  int ret = vtkRegressionTestImage(renWin);
  if (ret == vtkRegressionTester::DO_INTERACTOR)
  {
    iren->Start();
  }
  return !ret;
}
