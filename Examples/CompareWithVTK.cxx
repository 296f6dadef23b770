// CompareWithVTK: the same keys through VTK's interpolators and through vtkLCT's, side by side.
//   1. Transform keys with shear and non-uniform scale: how far each type misses its own keys.
//   2. Rotation keys 0, 30, ..., 120 degrees about z: the angle each spline returns at the keys.
//   3. A camera flight with a 130-degree turn and a zoom: Hawkins & Grimm's path metric.
// No display needed; prints a table.
#include "vtkCamera.h"
#include "vtkCameraInterpolator.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCameraPathMetric.h"
#include "vtkCollection.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolator.h"
#include "vtkTransformInterpolatorLCT.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace
{
void shearedKey(int k, vtkTransform* t)
{
  vtkNew<vtkMatrix4x4> shear;
  shear->SetElement(0, 1, 0.3 * k);
  t->PostMultiply();
  t->Concatenate(shear);
  t->Scale(1.0 + 0.4 * k, 1.0, 1.0);
  t->RotateWXYZ(60.0 * k, 0.2, 1.0, 0.3);
}

double difference(vtkMatrix4x4* a, vtkMatrix4x4* b)
{
  double worst = 0.0;
  for (int i = 0; i < 16; ++i)
  {
    worst = std::max(worst, std::abs(a->GetElement(i / 4, i % 4) - b->GetElement(i / 4, i % 4)));
  }
  return worst;
}

double angleAt(vtkTransform* t)
{
  return std::atan2(t->GetMatrix()->GetElement(1, 0), t->GetMatrix()->GetElement(0, 0)) * 180.0 /
    3.14159265358979323846;
}
} // namespace

int main()
{
  std::printf("1. Keys with shear and non-uniform scale: largest miss at the key times\n");
  for (int type : { 0, 1 })
  {
    vtkNew<vtkTransformInterpolator> vtk;
    vtkNew<vtkTransformInterpolatorLCT> lct;
    vtk->SetInterpolationType(type);
    lct->SetInterpolationType(type);
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkTransform> key;
      shearedKey(k, key);
      vtk->AddTransform(k, key);
      lct->AddTransform(k, key);
    }
    double missVtk = 0.0;
    double missLct = 0.0;
    for (int k = 0; k < 4; ++k)
    {
      vtkNew<vtkTransform> key, a, b;
      shearedKey(k, key);
      vtk->InterpolateTransform(k, a);
      lct->InterpolateTransform(k, b);
      missVtk = std::max(missVtk, difference(a->GetMatrix(), key->GetMatrix()));
      missLct = std::max(missLct, difference(b->GetMatrix(), key->GetMatrix()));
    }
    std::printf("   %-7s vtkTransformInterpolator %.3g   vtkTransformInterpolatorLCT %.3g\n",
      type ? "Spline" : "Linear", missVtk, missLct);
  }

  std::printf("2. Rotation keys 0, 30, 60, 90, 120 degrees: angle returned at each key (spline)\n");
  vtkNew<vtkTransformInterpolator> vtkSpline;
  vtkNew<vtkTransformInterpolatorLCT> lctSpline;
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(30.0 * k);
    vtkSpline->AddTransform(k, key);
    lctSpline->AddTransform(k, key);
  }
  for (int k = 0; k < 5; ++k)
  {
    vtkNew<vtkTransform> a, b;
    vtkSpline->InterpolateTransform(k, a);
    lctSpline->InterpolateTransform(k, b);
    std::printf("   key %5.1f: VTK %7.2f   LCT %7.2f\n", 30.0 * k, angleAt(a), angleAt(b));
  }

  std::printf("3. Camera flight (130-degree turn, zoom): excess path length of scene points\n");
  vtkNew<vtkCameraInterpolator> vtkPath;
  vtkNew<vtkCameraInterpolatorLCT> lctPath;
  for (int k = 0; k < 3; ++k)
  {
    const double a = (-40.0 + 65.0 * k) * 3.14159265358979323846 / 180.0;
    vtkNew<vtkCamera> key;
    key->SetPosition(7.0 * std::sin(a), 2.5, 7.0 * std::cos(a));
    key->SetViewAngle(40.0 - 8.0 * k);
    vtkPath->AddCamera(k, key);
    lctPath->AddCamera(k, key);
  }
  vtkNew<vtkSphereSource> scene;
  scene->SetRadius(1.5);
  scene->Update();
  vtkNew<vtkCameraPathMetric> metric;
  metric->SetPoints(scene->GetOutput()->GetPoints());
  metric->SetNumberOfSamples(21);
  vtkNew<vtkCollection> cameras;
  for (int s = 0; s <= 20; ++s)
  {
    vtkNew<vtkCamera> c;
    vtkPath->InterpolateCamera(0.1 * s, c);
    cameras->AddItem(c);
  }
  if (!metric->EvaluateCameras(cameras))
  {
    return 1;
  }
  std::printf("   vtkCameraInterpolator     camera space %6.1f %%   screen %6.1f %%\n",
    metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess());
  if (!metric->EvaluateInterpolator(lctPath, 0.0, 2.0))
  {
    return 1;
  }
  std::printf("   vtkCameraInterpolatorLCT  camera space %6.1f %%   screen %6.1f %%\n",
    metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess());
  return 0;
}
