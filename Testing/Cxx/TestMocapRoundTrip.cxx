// The motion-capture codec seen: CMU 01_01 (assimp-testmodels) at four frames, the recording on
// the top row, below it the motion decoded from a 2 %-of-height .lctm file (orange) over the
// the recording (thin dark lines, drawn on top in a second layer), so where the codec spends
// its error shows. Skipped (125) without X or the data.
#include "RegressionImage.h"

#include "vtkSkeletonAnimationReader.h"

#include "lct/MotionCodec.h"
#include "lct/MotionError.h"

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkCoordinate.h"
#include "vtkCellArray.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace
{

vtkNew<vtkPolyData> SkeletonAt(const lct::SkeletalAnimation& a, int frame)
{
  std::vector<Eigen::Matrix4d> world;
  lct::worldTransforms(a, frame, world);
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> bones;
  vtkNew<vtkCellArray> joints;
  for (int j = 0; j < a.jointCount(); ++j)
  {
    const Eigen::Vector3d p = world[static_cast<std::size_t>(j)].block<3, 1>(0, 3);
    points->InsertNextPoint(p.x(), p.y(), p.z());
    const vtkIdType id = j;
    joints->InsertNextCell(1, &id);
    const int parent = a.joints[static_cast<std::size_t>(j)].parent;
    if (parent >= 0)
    {
      const vtkIdType bone[2] = { parent, j };
      bones->InsertNextCell(2, bone);
    }
  }
  vtkNew<vtkPolyData> skeleton;
  skeleton->SetPoints(points);
  skeleton->SetLines(bones);
  skeleton->SetVerts(joints);
  return skeleton;
}

void AddSkeleton(vtkRenderer* renderer, const lct::SkeletalAnimation& a, int frame,
  const double color[3], double width)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(SkeletonAt(a, frame));
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(color[0], color[1], color[2]);
  actor->GetProperty()->SetLineWidth(static_cast<float>(width));
  actor->GetProperty()->SetPointSize(static_cast<float>(2.0 * width));
  actor->GetProperty()->SetRenderLinesAsTubes(true);
  actor->GetProperty()->SetRenderPointsAsSpheres(true);
  renderer->AddActor(actor);
}

void AddLabel(vtkRenderer* renderer, const std::string& text)
{
  vtkNew<vtkTextActor> label;
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetFontSize(12);
  label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
  label->SetPosition(0.03, 0.92);
  renderer->AddViewProp(label);
}

} // namespace

int TestMocapRoundTrip(int argc, char* argv[])
{
  if (!lct_regression::DisplayAvailable("TestMocapRoundTrip"))
  {
    return 125;
  }
  const std::string path = "/usr/share/assimp/models/BVH/01_01.bvh";
  if (!std::filesystem::exists(path))
  {
    std::cerr << "TestMocapRoundTrip: " << path << " missing (assimp-testmodels); skipped.\n";
    return 125;
  }
  vtkNew<vtkSkeletonAnimationReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  const lct::SkeletalAnimation* original = reader->GetAnimation();
  if (!original)
  {
    std::cerr << "TestMocapRoundTrip: cannot read " << path << "\n";
    return 1;
  }
  const double height = lct::restPoseHeight(*original);
  lct::MotionCompressionOptions options;
  options.tolerance = 0.02 * height;
  lct::MotionCompressionReport report;
  std::string why;
  const lct::Result<std::string> file =
    lct::compressMotion(*original, lct::MotionMetadata(), options, &report, &why);
  const lct::Result<lct::SkeletalAnimation> decoded =
    file ? lct::decompressMotion(file.value, nullptr, &why) : lct::Result<lct::SkeletalAnimation>();
  if (!file || !decoded)
  {
    std::cerr << "TestMocapRoundTrip: " << why << "\n";
    return 1;
  }

  // BVH channels: 6 for the root, 3 for every other joint with motion.
  int channels = 3;
  for (const lct::SkeletonJoint& joint : original->joints)
  {
    channels += joint.endSite ? 0 : 3;
  }
  const int frames[] = { 300, 900, 1500, 2100 };
  const double dark[3] = { 0.1, 0.1, 0.15 };
  const double orange[3] = { 0.95, 0.45, 0.05 };
  const double blue[3] = { 0.15, 0.3, 0.7 };
  vtkNew<vtkRenderWindow> renWin;
  renWin->SetSize(960, 600);
  renWin->SetMultiSamples(0);
  renWin->SetNumberOfLayers(2);
  for (int column = 0; column < 4; ++column)
  {
    const int frame = frames[column];
    std::vector<Eigen::Matrix4d> world;
    lct::worldTransforms(*original, frame, world);
    const Eigen::Vector3d root = world[0].block<3, 1>(0, 3);
    for (int row = 0; row < 2; ++row)
    {
      const double viewport[4] = { 0.25 * column, row == 0 ? 0.5 : 0.0, 0.25 * (column + 1),
        row == 0 ? 1.0 : 0.5 };
      vtkNew<vtkRenderer> renderer;
      renderer->SetViewport(viewport);
      renderer->SetBackground(row == 0 ? 0.97 : 0.93, 0.96, 0.95);
      vtkCamera* camera = renderer->GetActiveCamera();
      camera->SetFocalPoint(root.x(), root.y() - 0.1 * height, root.z());
      camera->SetPosition(root.x() + 1.1 * height, root.y() + 0.1 * height, root.z() + 2.2 * height);
      camera->SetViewUp(0.0, 1.0, 0.0);
      camera->SetViewAngle(30.0);
      renWin->AddRenderer(renderer);
      if (row == 0)
      {
        AddSkeleton(renderer, *original, frame, blue, 4.0);
        AddLabel(renderer, "recorded, row " + std::to_string(frame));
        continue;
      }
      AddSkeleton(renderer, decoded.value, frame, orange, 6.0);
      char text[96];
      std::snprintf(text, sizeof text, "decoded, 2 %% of H, %.0fx",
        4.0 * original->frames * channels / static_cast<double>(report.bytes));
      AddLabel(renderer, text);
      vtkNew<vtkRenderer> overlay; // the recording, always on top of the decoded tubes
      overlay->SetLayer(1);
      overlay->SetViewport(viewport);
      overlay->SetActiveCamera(camera);
      overlay->SetInteractive(0);
      AddSkeleton(overlay, *original, frame, dark, 1.5);
      renWin->AddRenderer(overlay);
    }
  }
  return lct_regression::CompareWithBaseline(renWin, argc, argv);
}
