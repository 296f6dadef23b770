// Regression-image test of the transform interpolators: one mesh carried through five keys
// (260 degrees of rotation about a tilted axis, shear and non-uniform scale at the middle keys),
// drawn as a ghost trail of 20 in-betweens per scheme with the keys solid in front, one row per
// scheme, top to bottom: LCT Linear, LCT Spline, LCT BSpline, LCT Subdivision
// (vtkTransformInterpolatorLCT), VTK Linear, VTK Spline (vtkTransformInterpolator, its default).
// The scene is shared with Examples/InterpolatorTrail.cxx. Baseline:
// Testing/Data/Baseline/TestTransformInterpolatorTrail.png (made with the Wuson mesh of
// assimp-testmodels; without it the scene falls back to an arrow and the image test fails).
#include "../../Examples/InterpolatorTrailScene.h"
#include "RegressionImage.h"

int TestTransformInterpolatorTrail(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestTransformInterpolatorTrail"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  constexpr int size = 600;
  vtkNew<vtkRenderer> renderer;
  if (!InterpolatorTrailScene::Build(renderer, size))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(size, size);
  renWin->AddRenderer(renderer);
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
