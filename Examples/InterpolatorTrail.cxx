// InterpolatorTrail <out.png>: render the interpolator ghost trail figure (one row per scheme:
// LCT Linear, Spline, BSpline, Subdivision, VTK Linear, Spline on the same five keys with
// rotation, shear and non-uniform scale) offscreen at 1200x1200 and write it as a PNG. The scene
// is Examples/InterpolatorTrailScene.h, the same one
// Testing/Cxx/TestTransformInterpolatorTrail.cxx compares against its baseline (at 600x600).
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 written, 1 error, 2 usage, 125 no DISPLAY.
#include "FigureProgram.h"
#include "InterpolatorTrailScene.h"

int main(int argc, char* argv[])
{
  return FigureProgram::Run(argc, argv, "InterpolatorTrail",
    "Renders the ghost trails of vtkTransformInterpolatorLCT and vtkTransformInterpolator on the "
    "same keys to a PNG",
    1200, 1200, [](vtkRenderWindow* window, int size, std::string* source) {
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      return InterpolatorTrailScene::Build(renderer, size, source);
    });
}
