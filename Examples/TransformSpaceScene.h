// The "space of transformations" figure (Alexa 2002, Figure 1), shared by
// Examples/TransformSpace.cxx and Testing/Cxx/TestTransformSpace.cxx.
//
// Two transforms A and B span a plane of transforms a (.) A (+) b (.) B. A 5x5 grid of copies
// of a mesh samples it: the copy in column i, row j is placed by
//
//   offset(i, j) * (a_i (.) A (+) b_j (.) B) * pose
//
// where `pose` (SceneModel::MakePose, Examples/SceneModel.h) centres, normalises and turns the
// model to a three-quarter view, the LCT transform is a vtkLogTransform and `offset` moves the
// copy to its grid cell in the view plane. The three are concatenated in a vtkTransform used as
// the actor's UserTransform. Columns (a) run left to right and are coloured by a; rows (b) run
// bottom to top. Thin grey lines mark the axes a = 0 (the column of pure b (.) B) and b = 0
// (the row of pure a (.) A): the copy where they cross (the centre) is the untransformed model,
// A is at the right end of its row, B at the top of its column, A (+) B in the top right corner
// and the inverses (-1) (.) A, (-1) (.) B at the left and bottom ends.
//
// Header-only: everything is `inline`. The scene needs VTK::IOPLY, VTK::IOGeometry,
// VTK::FiltersSources, VTK::RenderingCore (and an OpenGL2 render window to draw it).
#ifndef TransformSpaceScene_h
#define TransformSpaceScene_h

#include "SceneModel.h"
#include "vtkLogTransform.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkColorTransferFunction.h"
#include "vtkLineSource.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <algorithm>
#include <iostream>
#include <string>

namespace TransformSpaceScene
{

/// Grid size (copies per row and per column).
constexpr int GridSize = 5;
/// Distance between neighbouring copies, in units of the normalised model (longest side 1).
constexpr double CellSize = 1.7;

/// Weight of A in column i (0 .. GridSize-1, left to right): -1, -0.5, 0, 0.5, 1.
inline double WeightA(int i)
{
  return -1.0 + 0.5 * i;
}

/// Weight of B in row j (0 .. GridSize-1, bottom to top): -1, -0.5, 0, 0.5, 1.
inline double WeightB(int j)
{
  return -1.0 + 0.5 * j;
}

/**
 * The two generators. A: a quarter turn about z with a translation. B: non-uniform scale
 * (1.8, 0.6, 1) with an xy shear, followed by a rotation of 40 degrees about x.
 * Returns false (after printing why) if vtkLogTransform rejects one of them.
 */
inline bool MakeGenerators(vtkLogTransform* a, vtkLogTransform* b)
{
  vtkNew<vtkTransform> ta;
  ta->PostMultiply();
  ta->RotateZ(90.0);
  ta->Translate(0.35, 0.15, 0.0);

  vtkNew<vtkMatrix4x4> shear; // x' = x + 0.5 y
  shear->SetElement(0, 1, 0.5);
  vtkNew<vtkTransform> tb;
  tb->PostMultiply();
  tb->Concatenate(shear);
  tb->Scale(1.8, 0.6, 1.0);
  tb->RotateX(40.0);

  if (!a->SetTransform(ta) || !b->SetTransform(tb))
  {
    std::cerr << "TransformSpaceScene: vtkLogTransform rejected a generator.\n";
    return false;
  }
  return true;
}

/// Colour of column i (by a): a diverging blue - grey - orange map.
inline void ColumnColor(int i, double rgb[3])
{
  vtkNew<vtkColorTransferFunction> colors;
  colors->SetColorSpaceToDiverging();
  colors->AddRGBPoint(WeightA(0), 0.23, 0.30, 0.75);
  colors->AddRGBPoint(WeightA(GridSize - 1), 0.80, 0.25, 0.10);
  colors->GetColor(WeightA(i), rgb);
}

/// Centre of grid cell (i, j) in the view plane (z = 0).
inline void CellCenter(int i, int j, double c[3])
{
  c[0] = (i - 0.5 * (GridSize - 1)) * CellSize;
  c[1] = (j - 0.5 * (GridSize - 1)) * CellSize;
  c[2] = 0.0;
}

/**
 * Fill `renderer` with the figure: background, the axis lines, the GridSize x GridSize
 * copies, and a parallel camera along -z fitted with ResetCamera. Returns false if the
 * transforms could not be built (the renderer is then incomplete).
 */
inline bool Build(vtkRenderer* renderer, std::string* source = nullptr)
{
  vtkSmartPointer<vtkPolyData> model = SceneModel::LoadModel(source);
  vtkNew<vtkTransform> pose;
  SceneModel::MakePose(model, pose);

  vtkNew<vtkLogTransform> generatorA;
  vtkNew<vtkLogTransform> generatorB;
  if (!MakeGenerators(generatorA, generatorB))
  {
    return false;
  }
  vtkLogTransform* const generators[2] = { generatorA, generatorB };

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(model);
  mapper->ScalarVisibilityOff();

  for (int i = 0; i < GridSize; ++i)
  {
    double rgb[3];
    ColumnColor(i, rgb);
    for (int j = 0; j < GridSize; ++j)
    {
      // a (.) A (+) b (.) B
      const double weights[2] = { WeightA(i), WeightB(j) };
      vtkNew<vtkLogTransform> lct;
      if (!vtkLogTransform::LinearCombination(2, weights, generators, lct))
      {
        std::cerr << "TransformSpaceScene: LinearCombination failed at a = " << weights[0]
                  << ", b = " << weights[1] << "\n";
        return false;
      }

      // offset * lct * pose (PostMultiply: each step is applied after the previous ones).
      double c[3];
      CellCenter(i, j, c);
      vtkNew<vtkTransform> placement;
      placement->PostMultiply();
      placement->Concatenate(pose);
      placement->Concatenate(lct);
      placement->Translate(c);

      vtkNew<vtkActor> actor;
      actor->SetMapper(mapper);
      actor->SetUserTransform(placement);
      vtkProperty* p = actor->GetProperty();
      p->SetColor(rgb);
      p->SetAmbient(0.15);
      p->SetDiffuse(0.8);
      p->SetSpecular(0.25);
      p->SetSpecularPower(30.0);
      renderer->AddActor(actor);
    }
  }

  // The axes a = 0 and b = 0, behind the copies.
  double origin[3];
  CellCenter(2, 2, origin); // WeightA(2) == WeightB(2) == 0
  const double half = 0.5 * GridSize * CellSize;
  const double back = -1.5;
  const double ends[2][2][3] = {
    { { -half, origin[1], back }, { half, origin[1], back } }, // b = 0
    { { origin[0], -half, back }, { origin[0], half, back } }, // a = 0
  };
  for (const auto& e : ends)
  {
    vtkNew<vtkLineSource> line;
    line->SetPoint1(e[0]);
    line->SetPoint2(e[1]);
    vtkNew<vtkPolyDataMapper> lineMapper;
    lineMapper->SetInputConnection(line->GetOutputPort());
    vtkNew<vtkActor> lineActor;
    lineActor->SetMapper(lineMapper);
    lineActor->GetProperty()->SetColor(0.6, 0.6, 0.6);
    lineActor->GetProperty()->SetLineWidth(1.0);
    lineActor->GetProperty()->LightingOff();
    renderer->AddActor(lineActor);
  }

  renderer->SetBackground(0.97, 0.96, 0.93);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetFocalPoint(0.0, 0.0, 0.0);
  camera->SetPosition(0.0, 0.0, 10.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  renderer->ResetCamera();
  // ResetCamera fits the bounding sphere, which leaves wide margins around a flat, square
  // figure: tighten the parallel scale to the visible bounds (plus a small margin).
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double cx = 0.5 * (bounds[0] + bounds[1]);
  const double cy = 0.5 * (bounds[2] + bounds[3]);
  const double cz = camera->GetPosition()[2];
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, cz);
  camera->SetParallelScale(0.52 * std::max(bounds[1] - bounds[0], bounds[3] - bounds[2]));
  renderer->ResetCameraClippingRange();
  return true;
}

} // namespace TransformSpaceScene

#endif
