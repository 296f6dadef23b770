// Uses an installed vtkLCT: the wrapped VTK class, the export header, and Eigen (a public
// dependency, so it must come with LCT::LCT).
#include "vtkLCTModule.h"
#include "vtkLogTransform.h"

#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <Eigen/Core>

#include <cmath>
#include <cstring>
#include <iostream>

int main()
{
  vtkNew<vtkLogTransform> transform;
  if (std::strcmp(transform->GetClassName(), "vtkLogTransform") != 0 ||
    !transform->IsA("vtkLinearTransform"))
  {
    std::cerr << "unexpected class " << transform->GetClassName() << "\n";
    return 1;
  }

  vtkMatrix4x4* matrix = transform->GetMatrix();
  Eigen::Matrix4d m;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      m(i, j) = matrix->GetElement(i, j);
    }
  }
  if (!m.allFinite())
  {
    std::cerr << "non-finite matrix\n";
    return 1;
  }

  std::cout << "vtkLCT consumer OK\n";
  return 0;
}
