// The command-line part shared by the example programs that render one figure to a PNG
// (TransformSpace, InterpolatorTrail): usage, the X display check, an early check that the output
// can be written, offscreen rendering and the PNG writing, with the exit codes
// 0 written, 1 error, 2 usage, 125 no DISPLAY (this VTK renders through X only).
//
// Header-only: everything is `inline`. Needs VTK::IOImage, VTK::RenderingCore and an OpenGL2
// render window.
#ifndef FigureProgram_h
#define FigureProgram_h

#include "vtkNew.h"
#include "vtkPNGWriter.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkWindowToImageFilter.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>

namespace FigureProgram
{

/**
 * Runs a figure program: `build(window, width, description)` fills the render window (returning
 * false after printing why if it cannot), which is then rendered offscreen at width x height and
 * written to argv[1]. `what` is a one-line description for the usage message.
 */
inline int Run(int argc, char* argv[], const char* name, const char* what, int width, int height,
  const std::function<bool(vtkRenderWindow*, int, std::string*)>& build)
{
  if (argc != 2)
  {
    std::cerr << "usage: " << (argc > 0 ? argv[0] : name) << " <out.png>\n"
              << what << " (run under xvfb-run -a without a display).\n";
    return 2;
  }
  const std::string out = argv[1];
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << name << ": DISPLAY is not set; this VTK renders through X only. Run it as: "
              << "xvfb-run -a " << argv[0] << " " << out << "\n";
    return 125;
  }
  // Fail early, and clearly, if the output cannot be written (vtkPNGWriter only warns).
  {
    const bool existed = std::ifstream(out).good();
    std::ofstream probe(out, std::ios::binary | std::ios::app);
    if (!probe)
    {
      std::cerr << name << ": cannot write " << out << "\n";
      return 1;
    }
    probe.close();
    if (!existed)
    {
      std::remove(out.c_str()); // leave nothing behind if rendering fails
    }
  }
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(8);
  window->SetSize(width, height);
  std::string source;
  if (!build(window, width, &source))
  {
    return 1;
  }
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
    std::cerr << name << ": writing " << out << " failed (error code " << writer->GetErrorCode()
              << ")\n";
    std::remove(out.c_str());
    return 1;
  }
  std::cout << name << ": model " << source << "; wrote " << out << " (" << width << "x" << height
            << ")\n";
  return 0;
}

} // namespace FigureProgram

#endif
