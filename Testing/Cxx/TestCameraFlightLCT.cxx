// Regression image of a camera flight through vtkCameraInterpolatorLCT: a 130-degree turn, a zoom
// and a shift of the centre of projection, shown at t = 0.25, 0.5, 0.75 (Examples/CameraFlightScene.h).
// TestCameraFlightVTK shows the same keys through vtkCameraInterpolator, to document the difference.
#include "../../Examples/CameraFlightScene.h"

#include "vtkRegressionTestImage.h"
#include "vtkRenderWindowInteractor.h"

#include <cstdlib>
#include <iostream>

int TestCameraFlightLCT(int argc, char* argv[])
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << "TestCameraFlightLCT: DISPLAY is not set (run under xvfb-run -a); skipped.\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(600, 200);
  if (!CameraFlightScene::Build(renWin, true))
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
