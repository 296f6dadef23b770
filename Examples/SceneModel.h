// The mesh the example scenes draw, and the pose that normalises it. Shared by
// Examples/TransformSpaceScene.h and Examples/InterpolatorTrailScene.h (and through them by the
// examples and the regression-image tests in Testing/Cxx/).
//
// Header-only: everything is `inline`. Needs VTK::IOPLY, VTK::IOGeometry, VTK::FiltersSources
// and VTK::CommonTransforms.
#ifndef SceneModel_h
#define SceneModel_h

#include "vtkArrowSource.h"
#include "vtkNew.h"
#include "vtkPLYReader.h"
#include "vtkPolyData.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <algorithm>
#include <fstream>
#include <iostream>
#include <string>

namespace SceneModel
{

/// Mesh files tried in order (Debian package assimp-testmodels).
inline const char* const* ModelFiles()
{
  static const char* const files[] = { "/usr/share/assimp/models/PLY/Wuson.ply",
    "/usr/share/assimp/models/STL/Wuson.stl", nullptr };
  return files;
}

inline bool FileReadable(const std::string& name)
{
  std::ifstream f(name, std::ios::binary);
  return f.good();
}

/**
 * The model: the Wuson mesh from assimp-testmodels, or, when it is not installed, an arrow
 * (which still shows orientation; images then differ from the test baselines).
 * `source` receives a description of what was loaded.
 */
inline vtkSmartPointer<vtkPolyData> LoadModel(std::string* source = nullptr)
{
  for (const char* const* f = ModelFiles(); *f; ++f)
  {
    const std::string name = *f;
    if (!FileReadable(name))
    {
      continue;
    }
    vtkSmartPointer<vtkPolyData> mesh;
    if (name.size() > 4 && name.compare(name.size() - 4, 4, ".ply") == 0)
    {
      vtkNew<vtkPLYReader> reader;
      reader->SetFileName(name.c_str());
      reader->Update();
      mesh = reader->GetOutput();
    }
    else
    {
      vtkNew<vtkSTLReader> reader;
      reader->SetFileName(name.c_str());
      reader->Update();
      mesh = reader->GetOutput();
    }
    if (mesh && mesh->GetNumberOfCells() > 0)
    {
      if (source)
      {
        *source = name;
      }
      return mesh;
    }
  }
  std::cerr << "SceneModel: no model file found (install assimp-testmodels for " << ModelFiles()[0]
            << "); using an arrow instead.\n";
  vtkNew<vtkArrowSource> arrow;
  arrow->SetTipResolution(24);
  arrow->SetShaftResolution(24);
  arrow->Update();
  if (source)
  {
    *source = "vtkArrowSource (fallback)";
  }
  return arrow->GetOutput();
}

/**
 * A pose to apply to the model before the transforms a scene shows: centre the bounding box at
 * the origin, scale its longest side to 1 and turn it to a three-quarter view.
 */
inline void MakePose(vtkPolyData* model, vtkTransform* pose)
{
  double b[6];
  model->GetBounds(b);
  const double size = std::max({ b[1] - b[0], b[3] - b[2], b[5] - b[4], 1e-12 });
  pose->Identity();
  pose->PostMultiply();
  pose->Translate(-0.5 * (b[0] + b[1]), -0.5 * (b[2] + b[3]), -0.5 * (b[4] + b[5]));
  pose->Scale(1.0 / size, 1.0 / size, 1.0 / size);
  pose->RotateY(-65.0); // the Wuson's long axis (z) towards +x, seen three-quarter
  pose->RotateX(15.0);  // and a little from above
}

} // namespace SceneModel

#endif
