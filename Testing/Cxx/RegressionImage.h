// The common part of the regression-image tests: skip without an X display (this VTK renders
// through X only; scripts/test runs ctest under xvfb-run), render, compare with
// Testing/Data/Baseline/<TestName>.png.
#ifndef lct_RegressionImage_h
#define lct_RegressionImage_h

#include "vtkNew.h"
#include "vtkRegressionTestImage.h"
#include "vtkRenderWindow.h"
#include "vtkRenderWindowInteractor.h"
#include "vtkTesting.h"

#include <cstdlib>
#include <iostream>

namespace lct_regression
{

/// False (after saying why) when there is no X display to render to.
inline bool DisplayAvailable(const char* test)
{
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << test << ": DISPLAY is not set (run under xvfb-run -a); skipped.\n";
    return false;
  }
  return true;
}

/// Renders `renWin` and compares it with the baseline; the test's return value.
inline int CompareWithBaseline(vtkRenderWindow* renWin, int argc, char* argv[])
{
  vtkNew<vtkRenderWindowInteractor> iren;
  iren->SetRenderWindow(renWin);
  renWin->Render();
  const int ret = vtkRegressionTestImage(renWin);
  if (ret == vtkRegressionTester::DO_INTERACTOR)
  {
    iren->Start();
  }
  return !ret;
}

} // namespace lct_regression

#endif
