// Regression image of a camera flight through vtkCameraInterpolatorLCT: a 130-degree turn, a zoom
// and a shift of the centre of projection, shown at t = 0.25, 0.5, 0.75
// (Examples/CameraFlightScene.h). TestCameraFlightVTK shows the same keys through
// vtkCameraInterpolator, to document the difference.
#include "../../Examples/CameraFlightScene.h"
#include "RegressionImage.h"

int TestCameraFlightLCT(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestCameraFlightLCT"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(600, 200);
  if (!CameraFlightScene::Build(renWin, true))
  {
    return EXIT_FAILURE;
  }
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
