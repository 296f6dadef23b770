// Regression-image test of vtkShapeBlenderLCT (issue #11 §3, §5): a striped bar and a target
// twisted by 180 degrees, blended at w = 0, 0.5, 0.8, 1, 1.5 (top row, left to right), against the
// linear blend of the points at the same weights (bottom row), which pinches the bar to a line at
// w = 0.5 where the log blend keeps its cross-section. Baseline:
// Testing/Data/Baseline/TestShapeBlenderTwist.png.
#include "../Unit/ShapeMeshes.h"
#include "RegressionImage.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellData.h"
#include "vtkLookupTable.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkShapeBlenderLCT.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

namespace
{
constexpr int kRings = 41;
constexpr int kAround = 8;
constexpr double kLength = 6.0;

void addBar(vtkRenderer* renderer, vtkPolyData* mesh, double x, double y)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->SetScalarModeToUseCellData();
  mapper->SetColorModeToMapScalars();
  mapper->SetScalarRange(0, 1);
  vtkNew<vtkLookupTable> lut;
  lut->SetNumberOfTableValues(2);
  lut->SetTableValue(0, 0.85, 0.55, 0.2);
  lut->SetTableValue(1, 0.25, 0.45, 0.8);
  lut->Build();
  mapper->SetLookupTable(lut);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetInterpolationToFlat();
  actor->SetPosition(x, y, 0.0);
  actor->RotateX(-90.0); // the bar's z axis up the screen
  renderer->AddActor(actor);
}
} // namespace

int TestShapeBlenderTwist(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestShapeBlenderTwist"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  const lct_test::Mesh rest = lct_test::tube(kRings, kAround, 1.0, kLength);
  const std::vector<Eigen::Vector3d> target =
    lct_test::twisted(rest.points, 3.14159265358979323846, kLength);
  auto restPd = lct_test::toPolyData(rest.points, rest.triangles);
  // Stripes: the side faces alternate colours around the bar; the caps take the first.
  vtkNew<vtkUnsignedCharArray> stripes;
  stripes->SetName("stripes");
  for (std::size_t j = 0; j < rest.triangles.size(); ++j)
  {
    const std::size_t side = static_cast<std::size_t>(kRings - 1) * kAround * 2;
    stripes->InsertNextValue(j < side ? static_cast<unsigned char>((j / 2) % kAround % 2) : 0);
  }
  restPd->GetCellData()->SetScalars(stripes);

  vtkNew<vtkShapeBlenderLCT> blender;
  blender->SetInputData(restPd);
  blender->AddTarget(lct_test::toPolyData(target, rest.triangles));
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  const double weights[] = { 0.0, 0.5, 0.8, 1.0, 1.5 };
  for (int i = 0; i < 5; ++i)
  {
    const double w = weights[i];
    blender->SetWeight(0, w);
    blender->Update();
    if (blender->GetOutput()->GetNumberOfPoints() != static_cast<vtkIdType>(rest.points.size()))
    {
      return EXIT_FAILURE;
    }
    vtkNew<vtkPolyData> ours;
    ours->DeepCopy(blender->GetOutput());
    addBar(renderer, ours, 3.5 * i, 4.0);
    std::vector<Eigen::Vector3d> linear;
    for (std::size_t k = 0; k < rest.points.size(); ++k)
    {
      linear.push_back((1.0 - w) * rest.points[k] + w * target[k]);
    }
    auto lbs = lct_test::toPolyData(linear, rest.triangles);
    lbs->GetCellData()->SetScalars(stripes);
    addBar(renderer, lbs, 3.5 * i, -4.0);
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(6.0, 3.0, 0.0);
  camera->SetPosition(6.0, 10.0, 30.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  camera->Zoom(1.3);

  vtkNew<vtkRenderWindow> renWin;
  renWin->SetMultiSamples(0);
  renWin->SetSize(600, 500);
  renWin->AddRenderer(renderer);
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
