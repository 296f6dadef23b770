// lct-compare-image TEST.png BASELINE.png TEMP_DIR: compares an image lct-render wrote with a
// baseline as VTK's regression-image tests do (vtkTesting::RegressionTest: vtkImageDifference,
// threshold 10, alternates BASELINE_1.png ...; a missing or failed baseline leaves the image and
// a .diff.png in TEMP_DIR). Exit 0 when they match, 1 otherwise, 2 on usage.
#include "vtkNew.h"
#include "vtkTesting.h"

#include <iostream>

int main(int argc, char* argv[])
{
  if (argc != 4)
  {
    std::cerr << "usage: lct-compare-image TEST.png BASELINE.png TEMP_DIR\n";
    return 2;
  }
  vtkNew<vtkTesting> testing;
  for (const char* a : { static_cast<const char*>("-V"), static_cast<const char*>(argv[2]),
         static_cast<const char*>("-T"), static_cast<const char*>(argv[3]) })
  {
    testing->AddArgument(a);
  }
  const int result = testing->RegressionTest(argv[1], 10.0);
  return result == vtkTesting::PASSED ? 0 : 1;
}
