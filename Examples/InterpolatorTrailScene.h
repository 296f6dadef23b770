// The interpolator "ghost trail" figure, shared by Examples/InterpolatorTrail.cxx and
// Testing/Cxx/TestTransformInterpolatorTrail.cxx.
//
// One object (the mesh of Examples/SceneModel.h) is carried through five keys K_0 .. K_4 at
// t = 0 .. 4: successive turns of 65 degrees about a tilted axis (260 degrees in all), a step
// along x, and a shear or a non-uniform scale at K_1, K_2 and K_3 (see MakeKey). Each row of the
// figure shows one interpolation scheme on the same keys, top to bottom:
//
//   LCT Linear, LCT Spline, LCT BSpline, LCT Subdivision   (vtkTransformInterpolatorLCT)
//   VTK Linear, VTK Spline (default)                      (vtkTransformInterpolator)
//
// A row draws TrailSamples in-betweens, t sampled uniformly over [tmin, tmax], in a light tint of
// the row's colour, and the five keys themselves (not interpolated) solid and darker at their
// positions, in front of the trail. An interpolating scheme passes through every key; LCT
// BSpline only through the end keys (it approximates); VTK's rows split each key into
// translation, quaternion and diagonal scale, so they miss the sheared keys K_1 and K_3 and the
// scale along rotated axes.
//
// Every copy is placed by the actor's UserTransform, a vtkTransform concatenating
//
//   row offset * M(t) * pose
//
// where `pose` (SceneModel::MakePose) normalises the model, M(t) is a key or an interpolated
// transform and the row offset (a translation in y, and in z to put the keys in front of the
// trail) is concatenated after it. The camera is parallel along -z.
//
// Header-only: everything is `inline`. Needs LCT::LCT, VTK::IOPLY, VTK::IOGeometry,
// VTK::FiltersSources, VTK::RenderingCore, VTK::RenderingFreeType (labels) and an OpenGL2 render
// window to draw it.
#ifndef InterpolatorTrailScene_h
#define InterpolatorTrailScene_h

#include "SceneModel.h"
#include "vtkTransformInterpolatorLCT.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCoordinate.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolator.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace InterpolatorTrailScene
{

/// Number of keys (at t = 0, 1, ..., NumberOfKeys - 1).
constexpr int NumberOfKeys = 5;
/// In-betweens drawn per row.
constexpr int TrailSamples = 20;
/// Step along x between neighbouring keys (the normalised model's longest side is 1).
constexpr double KeySpacing = 2.0;
/// Distance between rows.
constexpr double RowSpacing = 1.75;
/// Turn between neighbouring keys, degrees, about TurnAxis.
constexpr double TurnAngle = 65.0;
constexpr double TurnAxis[3] = { 0.35, 1.0, 0.3 };
/// The keys are drawn this much nearer the camera than the trail (no change in a parallel view).
constexpr double KeyDepth = 2.0;

/// The rows, top to bottom.
enum Scheme
{
  LCTLinear = 0,
  LCTSpline,
  LCTBSpline,
  LCTSubdivision,
  VTKLinear,
  VTKSpline,
  NumberOfSchemes
};

inline const char* SchemeLabel(int scheme)
{
  static const char* const labels[NumberOfSchemes] = { "LCT Linear", "LCT Spline", "LCT BSpline",
    "LCT Subdivision", "VTK Linear", "VTK Spline (default)" };
  return labels[scheme];
}

/// Row colour (the keys' colour; the trail is a light tint of it).
inline void SchemeColor(int scheme, double rgb[3])
{
  static const double colors[NumberOfSchemes][3] = {
    { 0.16, 0.33, 0.70 }, // LCT Linear: blue
    { 0.05, 0.45, 0.45 }, // LCT Spline: teal
    { 0.42, 0.25, 0.65 }, // LCT BSpline: purple
    { 0.18, 0.45, 0.12 }, // LCT Subdivision: green
    { 0.80, 0.38, 0.05 }, // VTK Linear: orange
    { 0.70, 0.12, 0.15 }, // VTK Spline: red
  };
  std::copy(colors[scheme], colors[scheme] + 3, rgb);
}

/// y of row `scheme` (row 0 at the top).
inline double RowY(int scheme)
{
  return (0.5 * (NumberOfSchemes - 1) - scheme) * RowSpacing;
}

/**
 * Key k (0 .. NumberOfKeys-1): M_k = T(k * KeySpacing, 0, 0) R(k * TurnAngle about TurnAxis) A_k
 * with A_0 = A_4 = identity, A_1 a shear x' = x + 0.8 y, A_2 the scale (1.5, 0.65, 1) and A_3
 * the scale (0.75, 1.4, 1) followed by a shear y' = y - 0.6 x. All with det > 0.
 */
inline void MakeKey(int k, vtkMatrix4x4* key)
{
  vtkNew<vtkMatrix4x4> shape; // A_k
  switch (k)
  {
    case 1:
      shape->SetElement(0, 1, 0.8);
      break;
    case 2:
      shape->SetElement(0, 0, 1.5);
      shape->SetElement(1, 1, 0.65);
      break;
    case 3:
    {
      vtkNew<vtkMatrix4x4> scale;
      scale->SetElement(0, 0, 0.75);
      scale->SetElement(1, 1, 1.4);
      vtkNew<vtkMatrix4x4> shear;
      shear->SetElement(1, 0, -0.6);
      vtkMatrix4x4::Multiply4x4(shear, scale, shape);
      break;
    }
    default:
      break;
  }
  vtkNew<vtkTransform> t;
  t->PostMultiply();
  t->Concatenate(shape);
  t->RotateWXYZ(k * TurnAngle, TurnAxis[0], TurnAxis[1], TurnAxis[2]);
  t->Translate(k * KeySpacing, 0.0, 0.0);
  key->DeepCopy(t->GetMatrix());
}

/**
 * The interpolation of `scheme` as a function of t, writing into a vtkTransform; false (after
 * printing why) if an interpolator rejected a key.
 */
inline bool MakeInterpolation(int scheme, std::function<bool(double, vtkTransform*)>* interpolate)
{
  if (scheme <= LCTSubdivision)
  {
    vtkSmartPointer<vtkTransformInterpolatorLCT> lct =
      vtkSmartPointer<vtkTransformInterpolatorLCT>::New();
    const int types[4] = { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR,
      vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
      vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE,
      vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION };
    lct->SetInterpolationType(types[scheme]);
    for (int k = 0; k < NumberOfKeys; ++k)
    {
      vtkNew<vtkMatrix4x4> key;
      MakeKey(k, key);
      if (!lct->AddTransform(k, key))
      {
        std::cerr << "InterpolatorTrailScene: vtkTransformInterpolatorLCT rejected key " << k
                  << "\n";
        return false;
      }
    }
    *interpolate = [lct](double t, vtkTransform* out) {
      return lct->InterpolateTransform(t, out) == 1;
    };
  }
  else
  {
    vtkSmartPointer<vtkTransformInterpolator> vtk =
      vtkSmartPointer<vtkTransformInterpolator>::New();
    if (scheme == VTKLinear)
    {
      vtk->SetInterpolationTypeToLinear();
    }
    else
    {
      vtk->SetInterpolationTypeToSpline(); // the default
    }
    for (int k = 0; k < NumberOfKeys; ++k)
    {
      vtkNew<vtkMatrix4x4> key;
      MakeKey(k, key);
      vtk->AddTransform(k, key);
    }
    if (vtk->GetNumberOfTransforms() != NumberOfKeys)
    {
      std::cerr << "InterpolatorTrailScene: vtkTransformInterpolator has "
                << vtk->GetNumberOfTransforms() << " keys, expected " << NumberOfKeys << "\n";
      return false;
    }
    *interpolate = [vtk](double t, vtkTransform* out) {
      vtk->InterpolateTransform(t, out);
      return true;
    };
  }
  return true;
}

/// One copy of the model: actor with UserTransform offset * m * pose.
inline void AddCopy(vtkRenderer* renderer, vtkPolyDataMapper* mapper, vtkTransform* pose,
  vtkLinearTransform* m, const double offset[3], const double rgb[3], bool key)
{
  vtkNew<vtkTransform> rowOffset;
  rowOffset->Translate(offset);
  vtkNew<vtkTransform> placement;
  placement->PostMultiply();
  placement->Concatenate(pose);
  placement->Concatenate(m);
  placement->Concatenate(rowOffset);

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetUserTransform(placement);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(rgb[0], rgb[1], rgb[2]);
  if (key)
  {
    p->SetAmbient(0.15);
    p->SetDiffuse(0.8);
    p->SetSpecular(0.3);
    p->SetSpecularPower(30.0);
  }
  else
  {
    p->SetAmbient(0.45);
    p->SetDiffuse(0.55);
    p->SetSpecular(0.0);
  }
  renderer->AddActor(actor);
}

/**
 * Fill `renderer` with the figure: background, one row per scheme (trail, keys, label) and a
 * parallel camera along -z fitted to it. `windowSize` (the window's height in pixels) sets the
 * label font size. Returns false if an interpolator could not be built (the renderer is then
 * incomplete).
 */
inline bool Build(vtkRenderer* renderer, int windowSize, std::string* source = nullptr)
{
  vtkSmartPointer<vtkPolyData> model = SceneModel::LoadModel(source);
  vtkNew<vtkTransform> pose;
  SceneModel::MakePose(model, pose);

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(model);
  mapper->ScalarVisibilityOff();

  const double tmin = 0.0;
  const double tmax = NumberOfKeys - 1;
  for (int scheme = 0; scheme < NumberOfSchemes; ++scheme)
  {
    std::function<bool(double, vtkTransform*)> interpolate;
    if (!MakeInterpolation(scheme, &interpolate))
    {
      return false;
    }
    double dark[3];
    SchemeColor(scheme, dark);
    double light[3];
    for (int c = 0; c < 3; ++c)
    {
      light[c] = dark[c] + 0.62 * (1.0 - dark[c]);
    }

    // The trail.
    const double trailOffset[3] = { 0.0, RowY(scheme), 0.0 };
    for (int i = 0; i < TrailSamples; ++i)
    {
      const double t = tmin + (tmax - tmin) * i / (TrailSamples - 1);
      vtkNew<vtkTransform> m;
      if (!interpolate(t, m))
      {
        std::cerr << "InterpolatorTrailScene: " << SchemeLabel(scheme)
                  << " failed to interpolate at t = " << t << "\n";
        return false;
      }
      AddCopy(renderer, mapper, pose, m, trailOffset, light, false);
    }

    // The keys themselves, in front of the trail.
    const double keyOffset[3] = { 0.0, RowY(scheme), KeyDepth };
    for (int k = 0; k < NumberOfKeys; ++k)
    {
      vtkNew<vtkMatrix4x4> key;
      MakeKey(k, key);
      vtkNew<vtkTransform> m;
      m->SetMatrix(key);
      AddCopy(renderer, mapper, pose, m, keyOffset, dark, true);
    }
  }

  // Fit a parallel camera along -z to the copies, with room above each row for its label.
  renderer->SetBackground(0.97, 0.96, 0.93);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetViewUp(0.0, 1.0, 0.0);
  double bounds[6];
  renderer->ComputeVisiblePropBounds(bounds);
  const double top = bounds[3] + 0.35 * RowSpacing; // the top row's label
  const double cx = 0.5 * (bounds[0] + bounds[1]);
  const double cy = 0.5 * (bounds[2] + top);
  camera->SetFocalPoint(cx, cy, 0.0);
  camera->SetPosition(cx, cy, 20.0);
  camera->SetParallelScale(0.53 * std::max(bounds[1] - bounds[0], top - bounds[2]));
  renderer->ResetCameraClippingRange();

  // Labels: above the left end of each row, anchored in world coordinates.
  const int fontSize = std::max(8, static_cast<int>(std::lround(0.026 * windowSize)));
  for (int scheme = 0; scheme < NumberOfSchemes; ++scheme)
  {
    double rgb[3];
    SchemeColor(scheme, rgb);
    vtkNew<vtkTextActor> label;
    label->SetInput(SchemeLabel(scheme));
    label->GetPositionCoordinate()->SetCoordinateSystemToWorld();
    label->GetPositionCoordinate()->SetValue(bounds[0], RowY(scheme) + 0.5 * RowSpacing, 0.0);
    vtkTextProperty* tp = label->GetTextProperty();
    tp->SetFontFamilyToArial();
    tp->SetFontSize(fontSize);
    tp->SetColor(rgb);
    tp->SetJustificationToLeft();
    tp->SetVerticalJustificationToTop();
    renderer->AddActor2D(label);
  }
  return true;
}

} // namespace InterpolatorTrailScene

#endif
