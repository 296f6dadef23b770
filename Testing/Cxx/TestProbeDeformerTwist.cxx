// Regression image of vtkProbeDeformerLCT (issue #11 §5, Kaji & Ochiai Fig. 2): columns Polar,
// Linear (LBS, what vtkWeightedTransformFilter does) and DualQuaternion. Top row: four strings
// between a fixed bottom probe and a top probe driven step by step through 3 pi (Polar twists
// them 1.5 turns; LBS and DQS see the principal pi). Bottom row: a bar twisted by 180 degrees
// (LBS collapses it to a line at mid-height, |cos 90| = 0; Polar and DQS keep its radius).
#include "RegressionImage.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"
#include "vtkTubeFilter.h"

#include <algorithm>
#include <cmath>

namespace
{
/// Four polylines of 200 points from z = 0 to z = 10 at (+-0.8, +-0.8).
vtkSmartPointer<vtkPolyData> makeStrings()
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  const double corners[4][2] = { { 0.8, 0.8 }, { -0.8, 0.8 }, { -0.8, -0.8 }, { 0.8, -0.8 } };
  for (const auto& c : corners)
  {
    lines->InsertNextCell(200);
    for (int i = 0; i < 200; ++i)
    {
      lines->InsertCellPoint(pts->InsertNextPoint(c[0], c[1], 10.0 * i / 199.0));
    }
  }
  pd->SetPoints(pts);
  pd->SetLines(lines);
  return pd;
}

/// A closed tube of radius 1 from z = 0 to z = 10: 80 rings of 48 points, quads.
vtkSmartPointer<vtkPolyData> makeBar()
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> quads;
  const int rings = 80, around = 48;
  for (int r = 0; r < rings; ++r)
  {
    for (int a = 0; a < around; ++a)
    {
      const double t = 2.0 * 3.14159265358979 * a / around;
      // A square-ish section (superellipse) makes the twist readable.
      const double c = std::cos(t), s = std::sin(t);
      const double x = std::copysign(std::pow(std::abs(c), 0.5), c);
      const double y = std::copysign(std::pow(std::abs(s), 0.5), s);
      pts->InsertNextPoint(x, 0.6 * y, 10.0 * r / (rings - 1));
    }
  }
  for (int r = 0; r + 1 < rings; ++r)
  {
    for (int a = 0; a < around; ++a)
    {
      const vtkIdType q[4] = { r * around + a, r * around + (a + 1) % around,
        (r + 1) * around + (a + 1) % around, (r + 1) * around + a };
      quads->InsertNextCell(4, q);
    }
  }
  pd->SetPoints(pts);
  pd->SetPolys(quads);
  return pd;
}

/// The deformed input: bottom probe fixed, top probe at z = 10 turned to `degrees` in steps of
/// 45 degrees (so ConsistentRotation follows the winding).
vtkSmartPointer<vtkProbeDeformerLCT> deform(vtkPolyData* input, int mode, double degrees)
{
  auto f = vtkSmartPointer<vtkProbeDeformerLCT>::New();
  vtkNew<vtkTransform> bottom, top, topRest;
  topRest->Translate(0, 0, 10);
  top->Translate(0, 0, 10);
  f->AddProbe(bottom);
  f->AddProbe(top, topRest);
  f->SetBlendMode(mode);
  f->SetInputData(input);
  for (double turned = 0.0; turned < degrees;)
  {
    const double step = std::min(45.0, degrees - turned);
    top->RotateZ(step);
    turned += step;
    f->Update();
  }
  return f;
}

void addColumn(vtkRenderWindow* win, int column, int mode, vtkPolyData* strings, vtkPolyData* bar)
{
  const double colours[3][3] = { { 0.85, 0.45, 0.2 }, { 0.3, 0.55, 0.85 }, { 0.4, 0.7, 0.35 } };
  for (int row = 0; row < 2; ++row)
  {
    vtkNew<vtkRenderer> ren;
    ren->SetViewport(column / 3.0, row == 0 ? 0.5 : 0.0, (column + 1) / 3.0, row == 0 ? 1.0 : 0.5);
    ren->SetBackground(0.12, 0.12, 0.14);
    vtkNew<vtkPolyDataMapper> mapper;
    vtkSmartPointer<vtkProbeDeformerLCT> f =
      deform(row == 0 ? strings : bar, mode, row == 0 ? 540.0 : 180.0);
    if (row == 0)
    {
      vtkNew<vtkTubeFilter> tubes;
      tubes->SetInputConnection(f->GetOutputPort());
      tubes->SetRadius(0.12);
      tubes->SetNumberOfSides(12);
      mapper->SetInputConnection(tubes->GetOutputPort());
    }
    else
    {
      vtkNew<vtkPolyDataNormals> normals;
      normals->SetInputConnection(f->GetOutputPort());
      mapper->SetInputConnection(normals->GetOutputPort());
    }
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colours[column][0], colours[column][1], colours[column][2]);
    ren->AddActor(actor);
    ren->GetActiveCamera()->SetPosition(14, -14, 8);
    ren->GetActiveCamera()->SetFocalPoint(0, 0, 5);
    ren->GetActiveCamera()->SetViewUp(0, 0, 1);
    ren->ResetCameraClippingRange();
    ren->GetActiveCamera()->SetViewAngle(38);
    win->AddRenderer(ren);
  }
}
} // namespace

int TestProbeDeformerTwist(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestProbeDeformerTwist"))
  {
    return VTK_SKIP_RETURN_CODE;
  }
  vtkSmartPointer<vtkPolyData> strings = makeStrings();
  vtkSmartPointer<vtkPolyData> bar = makeBar();
  vtkNew<vtkRenderWindow> win;
  win->SetSize(720, 560);
  win->SetMultiSamples(0);
  addColumn(win, 0, vtkProbeDeformerLCT::POLAR, strings, bar);
  addColumn(win, 1, vtkProbeDeformerLCT::LINEAR, strings, bar);
  addColumn(win, 2, vtkProbeDeformerLCT::DUAL_QUATERNION, strings, bar);
  return lct_regression::CompareWithBaseline(win, argc, argv);
}
