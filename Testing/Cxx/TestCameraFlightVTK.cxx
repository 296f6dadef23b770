// Regression image of the camera flight of TestCameraFlightLCT (a 130-degree turn, a zoom and a
// shift of the centre of projection, at t = 0.25, 0.5, 0.75; Examples/CameraFlightScene.h) through
// VTK's vtkCameraInterpolator, whose default spline ignores the window centre. It documents the
// difference; it is not a target.
#include "../../Examples/CameraFlightScene.h"
#include "RegressionImage.h"

int TestCameraFlightVTK(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestCameraFlightVTK"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(600, 200);
  if (!CameraFlightScene::Build(renWin, false))
  {
    return EXIT_FAILURE;
  }
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
