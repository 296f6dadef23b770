// TransformSpace <out.png>: render the "space of transformations" figure (Alexa 2002, Fig. 1)
// offscreen at 800x800 and write it as a PNG. The scene is Examples/TransformSpaceScene.h, the
// same one Testing/Cxx/TestTransformSpace.cxx compares against its baseline.
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 written, 1 error, 2 usage, 125 no DISPLAY.
#include "TransformSpaceScene.h"

#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: " << (argc > 0 ? argv[0] : "TransformSpace") << " <out.png>\n"
              << "Renders the space of transformations a (.) A (+) b (.) B (Alexa 2002, Fig. 1) "
                 "to a PNG (run under xvfb-run -a without a display).\n";
    return 2;
  }
  const std::string out = argv[1];

  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << "TransformSpace: DISPLAY is not set; this VTK renders through X only. "
                 "Run it as: xvfb-run -a "
              << argv[0] << " " << out << "\n";
    return 125;
  }

  // Fail early, and clearly, if the output cannot be written (vtkPNGWriter only warns).
  {
    const bool existed = std::ifstream(out).good();
    std::ofstream probe(out, std::ios::binary | std::ios::app);
    if (!probe)
    {
      std::cerr << "TransformSpace: cannot write " << out << "\n";
      return 1;
    }
    probe.close();
    if (!existed)
    {
      std::remove(out.c_str()); // leave nothing behind if rendering fails
    }
  }

  vtkNew<vtkRenderer> renderer;
  std::string source;
  if (!TransformSpaceScene::Build(renderer, &source))
  {
    return 1;
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(8);
  window->SetSize(800, 800);
  window->AddRenderer(renderer);
  window->Render();

  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(out.c_str());
  writer->SetInputConnection(grab->GetOutputPort());
  writer->Write();
  if (writer->GetErrorCode() != 0)
  {
    std::cerr << "TransformSpace: writing " << out << " failed (error code "
              << writer->GetErrorCode() << ")\n";
    std::remove(out.c_str());
    return 1;
  }
  std::cout << "TransformSpace: model " << source << "; wrote " << out << " (800x800)\n";
  return 0;
}
