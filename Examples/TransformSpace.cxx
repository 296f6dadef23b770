// TransformSpace <out.png>: render the "space of transformations" figure (Alexa 2002, Fig. 1)
// offscreen at 800x800 and write it as a PNG. The scene is Examples/TransformSpaceScene.h, the
// same one Testing/Cxx/TestTransformSpace.cxx compares against its baseline.
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 written, 1 error, 2 usage, 125 no DISPLAY.
#include "FigureProgram.h"
#include "TransformSpaceScene.h"

int main(int argc, char* argv[])
{
  return FigureProgram::Run(argc, argv, "TransformSpace",
    "Renders the space of transformations a (.) A (+) b (.) B (Alexa 2002, Fig. 1) to a PNG", 800,
    800, [](vtkRenderWindow* window, int, std::string* source) {
      vtkNew<vtkRenderer> renderer;
      window->AddRenderer(renderer);
      return TransformSpaceScene::Build(renderer, source);
    });
}
