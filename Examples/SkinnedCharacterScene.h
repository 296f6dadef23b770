// A skinned character from assimp-testmodels deformed by vtkProbeDeformerLCT, one viewport per
// blend mode side by side (Polar, MatrixLog, Linear = LBS, DualQuaternion), at one time of its
// animation. Shared by Examples/SkinnedCharacter.cxx (which renders the animation to frames) and
// Testing/Cxx/TestSkinnedCharacter.cxx (which compares one frame with its baseline).
//
// Header-only: everything is `inline`.
#ifndef SkinnedCharacterScene_h
#define SkinnedCharacterScene_h

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkExecutive.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkPolyDataNormals.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkProperty.h"
#include "vtkRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkSkinnedMeshReaderLCT.h"
#include "vtkSmartPointer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace SkinnedCharacterScene
{

constexpr int kModes[4] = { vtkProbeDeformerLCT::POLAR, vtkProbeDeformerLCT::MATRIX_LOG,
  vtkProbeDeformerLCT::LINEAR, vtkProbeDeformerLCT::DUAL_QUATERNION };

/// The character, one deformer per mode and the viewports showing them.
struct Scene
{
  vtkSmartPointer<vtkSkinnedMeshReaderLCT> reader;
  std::vector<vtkSmartPointer<vtkProbeDeformerLCT>> deformers;
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;

  /// Moves every deformer's probes to `time` (seconds) and re-executes; false if any fails.
  bool SetTime(double time)
  {
    bool ok = true;
    for (auto& d : this->deformers)
    {
      ok = this->reader->ConfigureDeformer(d, time) && d->GetExecutive()->Update() && ok;
    }
    return ok;
  }

  /// Frames every viewport on the union of the deformed characters' bounds (same framing for
  /// all modes), keeping the view direction.
  void Frame()
  {
    double all[6] = { 1, -1, 1, -1, 1, -1 };
    for (auto& d : this->deformers)
    {
      double b[6];
      vtkPolyData::SafeDownCast(d->GetOutputDataObject(0))->GetBounds(b);
      for (int k = 0; k < 3; ++k)
      {
        all[2 * k] = all[2 * k] > all[2 * k + 1] ? b[2 * k] : std::min(all[2 * k], b[2 * k]);
        all[2 * k + 1] = std::max(all[2 * k + 1], b[2 * k + 1]);
      }
    }
    for (auto& r : this->renderers)
    {
      r->ResetCamera(all);
      r->GetActiveCamera()->Zoom(1.15);
      r->ResetCameraClippingRange(all);
    }
  }
};

/// Reads `file` and fills `window` with four viewports; false (after printing why) when the file
/// cannot be read.
inline bool Build(vtkRenderWindow* window, const std::string& file, Scene& scene)
{
  scene.reader = vtkSmartPointer<vtkSkinnedMeshReaderLCT>::New();
  scene.reader->SetFileName(file.c_str());
  if (!scene.reader->GetExecutive()->Update())
  {
    return false;
  }
  double bounds[6];
  scene.reader->GetOutput()->GetBounds(bounds);
  const double centre[3] = { 0.5 * (bounds[0] + bounds[1]), 0.5 * (bounds[2] + bounds[3]),
    0.5 * (bounds[4] + bounds[5]) };
  const double size = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
    std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
  const double colours[4][3] = { { 0.85, 0.45, 0.2 }, { 0.75, 0.35, 0.7 }, { 0.3, 0.55, 0.85 },
    { 0.4, 0.7, 0.35 } };
  for (int m = 0; m < 4; ++m)
  {
    auto deformer = vtkSmartPointer<vtkProbeDeformerLCT>::New();
    deformer->SetInputConnection(scene.reader->GetOutputPort());
    deformer->SetBlendMode(kModes[m]);
    scene.reader->ConfigureDeformer(deformer, scene.reader->GetStartTime());
    vtkNew<vtkPolyDataNormals> normals;
    normals->SetInputConnection(deformer->GetOutputPort());
    normals->SplittingOff();
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(normals->GetOutputPort());
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(colours[m][0], colours[m][1], colours[m][2]);
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(m / 4.0, 0.0, (m + 1) / 4.0, 1.0);
    renderer->SetBackground(0.12, 0.12, 0.14);
    renderer->AddActor(actor);
    vtkNew<vtkTextActor> label;
    label->SetInput(deformer->GetBlendModeAsString());
    label->GetTextProperty()->SetFontSize(14);
    label->SetPosition(8, 8);
    renderer->AddActor2D(label);
    vtkCamera* camera = renderer->GetActiveCamera();
    // Up along the character's longest extent, looking along its thinnest (front or back).
    int up = 0, depth = 0;
    for (int k = 1; k < 3; ++k)
    {
      up = (bounds[2 * k + 1] - bounds[2 * k]) > (bounds[2 * up + 1] - bounds[2 * up]) ? k : up;
      depth = (bounds[2 * k + 1] - bounds[2 * k]) < (bounds[2 * depth + 1] - bounds[2 * depth])
        ? k
        : depth;
    }
    const int side = 3 - up - depth;
    double position[3] = { centre[0], centre[1], centre[2] };
    position[depth] -= 1.6 * size;
    position[side] += 0.35 * size;
    position[up] += 0.15 * size;
    double viewUp[3] = { 0, 0, 0 };
    viewUp[up] = 1;
    camera->SetFocalPoint(centre);
    camera->SetPosition(position);
    camera->SetViewUp(viewUp);
    camera->SetViewAngle(30);
    renderer->ResetCameraClippingRange(bounds);
    window->AddRenderer(renderer);
    scene.deformers.push_back(deformer);
    scene.renderers.push_back(renderer);
  }
  return true;
}

} // namespace SkinnedCharacterScene

#endif
