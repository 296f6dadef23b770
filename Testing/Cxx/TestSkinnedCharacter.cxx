// Regression image of a skinned character (assimp-testmodels' X/BCN_Epileptic.X, 54 bones,
// 15 378 vertices) driven by its own bone weights through vtkSkinnedMeshReaderLCT and
// vtkProbeDeformerLCT, at 60 % of its animation reached frame by frame: Polar, MatrixLog,
// Linear (LBS) and DualQuaternion side by side (issue #11 §2). Skipped without the data.
#include "../../Examples/SkinnedCharacterScene.h"
#include "RegressionImage.h"

#include <fstream>

int TestSkinnedCharacter(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestSkinnedCharacter"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  const char* file = "/usr/share/assimp/models/X/BCN_Epileptic.X";
  if (!std::ifstream(file).good())
  {
    std::cerr << "TestSkinnedCharacter: " << file << " is missing (assimp-testmodels); skipped.\n";
    return VTK_SKIP_RETURN_CODE;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetSize(960, 360);
  window->SetMultiSamples(0);
  SkinnedCharacterScene::Scene scene;
  if (!SkinnedCharacterScene::Build(window, file, scene))
  {
    return EXIT_FAILURE;
  }
  const double t0 = scene.reader->GetStartTime(), t1 = scene.reader->GetEndTime();
  for (int f = 0; f <= 12; ++f)
  {
    if (!scene.SetTime(t0 + 0.6 * (t1 - t0) * f / 12.0))
    {
      return EXIT_FAILURE;
    }
  }
  scene.Frame();
  return lct_regression::CompareWithBaseline(window, argc, argv);
}
