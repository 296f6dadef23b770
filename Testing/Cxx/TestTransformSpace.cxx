// Regression-image test of the "space of transformations" figure (Alexa 2002, Fig. 1): a 5x5
// grid of copies of a mesh placed by a (.) A (+) b (.) B, each through a vtkLogTransform
// concatenated in a vtkTransform used as the actor's UserTransform. The scene is shared with
// Examples/TransformSpace.cxx. Baseline: Testing/Data/Baseline/TestTransformSpace.png (made
// with the Wuson mesh of assimp-testmodels; without it the scene falls back to an arrow and
// the image test fails).
#include "../../Examples/TransformSpaceScene.h"
#include "RegressionImage.h"

int TestTransformSpace(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestTransformSpace"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderer> renderer;
  if (!TransformSpaceScene::Build(renderer))
  {
    return EXIT_FAILURE;
  }
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(400, 400);
  renWin->AddRenderer(renderer);
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
