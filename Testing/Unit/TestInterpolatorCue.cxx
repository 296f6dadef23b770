// vtkInterpolatorCueLCT in a vtkAnimationScene (sequence mode): every tick sets the camera and
// the props to their interpolators' values at the mapped key time.
#include "vtkInterpolatorCueLCT.h"

#include "VtkTestHelpers.h"

#include "vtkActor.h"
#include "vtkAnimationScene.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkRenderer.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolatorLCT.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
struct TickRecord
{
  std::vector<double> cueTimes;
  std::vector<Eigen::Vector3d> positions;
  std::vector<Eigen::Matrix4d> propMatrices;
  vtkCamera* camera = nullptr;
  vtkActor* actor = nullptr;
};

/// A prop's geometry without a rendering backend: a unit box about the origin.
class UnitBoxMapper : public vtkMapper
{
public:
  static UnitBoxMapper* New();
  vtkTypeMacro(UnitBoxMapper, vtkMapper);
  void Render(vtkRenderer*, vtkActor*) override {}
  double* GetBounds() override { return this->Box; }
  using vtkMapper::GetBounds;

private:
  double Box[6] = { -0.5, 0.5, -0.5, 0.5, -0.5, 0.5 };
};
vtkStandardNewMacro(UnitBoxMapper);

void onTick(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* record = static_cast<TickRecord*>(clientData);
  auto* cue = static_cast<vtkAnimationCue*>(caller);
  record->cueTimes.push_back(cue->GetAnimationTime());
  const double* p = record->camera->GetPosition();
  record->positions.emplace_back(p[0], p[1], p[2]);
  record->propMatrices.push_back(lct_test::fromVtk(record->actor->GetUserMatrix()));
}
} // namespace

TEST(InterpolatorCueLCT, SequenceSceneDrivesCameraAndPropsOverTheKeyRange)
{
  vtkNew<vtkCameraInterpolatorLCT> cameraPath;
  for (int k = 0; k < 4; ++k)
  {
    vtkNew<vtkCamera> key;
    key->SetPosition(10.0 * std::cos(k), 10.0 * std::sin(k), 2.0 * k);
    key->SetViewUp(0, 0, 1);
    ASSERT_EQ(cameraPath->AddCamera(10.0 + 5.0 * k, key), 1); // keys at t = 10 .. 25
  }
  vtkNew<vtkTransformInterpolatorLCT> propPath;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkTransform> key;
    key->RotateZ(100.0 * k);
    key->Scale(1.0 + k, 1.0, 1.0);
    ASSERT_EQ(propPath->AddTransform(k, key), 1); // keys at t = 0 .. 2
  }
  vtkNew<vtkCamera> camera;
  vtkNew<vtkActor> actor;
  vtkNew<vtkInterpolatorCueLCT> cue;
  cue->SetCamera(camera);
  cue->SetCameraInterpolator(cameraPath);
  ASSERT_EQ(cue->AddProp(actor, propPath), 1);
  cue->SetTimeModeToNormalized();
  cue->SetStartTime(0.0);
  cue->SetEndTime(1.0);

  TickRecord record;
  record.camera = camera;
  record.actor = actor;
  vtkNew<vtkCallbackCommand> tick;
  tick->SetCallback(onTick);
  tick->SetClientData(&record);
  cue->AddObserver(vtkCommand::AnimationCueTickEvent, tick);

  vtkNew<vtkAnimationScene> scene;
  scene->SetModeToSequence();
  scene->SetFrameRate(10);
  scene->SetStartTime(0.0);
  scene->SetEndTime(2.0);
  scene->AddCue(cue);
  scene->Play();

  ASSERT_GE(record.cueTimes.size(), 10u);
  for (size_t i = 0; i < record.cueTimes.size(); ++i)
  {
    const double u = record.cueTimes[i];
    vtkNew<vtkCamera> expected;
    cameraPath->InterpolateCamera(10.0 + 15.0 * u, expected);
    const double* p = expected->GetPosition();
    EXPECT_LT((record.positions[i] - Eigen::Vector3d(p[0], p[1], p[2])).norm(), 1e-12) << u;
    vtkNew<vtkMatrix4x4> m;
    propPath->InterpolateTransform(2.0 * u, m);
    EXPECT_LT((record.propMatrices[i] - lct_test::fromVtk(m)).norm(), 1e-12) << u;
  }
  EXPECT_DOUBLE_EQ(record.cueTimes.front(), 0.0);
  EXPECT_NEAR(record.cueTimes.back(), 1.0, 0.051); // the scene may stop one frame short

  // Cue-time mapping: key time = cue time - start.
  cue->SetKeyTimeMappingToCueTime();
  EXPECT_DOUBLE_EQ(cue->KeyTime(0.75, 10.0, 25.0), 0.75);
  cue->SetKeyTimeMappingToRange();
  EXPECT_DOUBLE_EQ(cue->KeyTime(0.5, 10.0, 25.0), 17.5);
}

TEST(InterpolatorCueLCT, NullArgumentsAndFailingPathsAreReported)
{
  vtkNew<vtkInterpolatorCueLCT> cue;
  vtkNew<lct_test::ErrorCounter> errors;
  cue->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkActor> actor;
  EXPECT_EQ(cue->AddProp(nullptr, nullptr), 0);
  EXPECT_EQ(cue->AddProp(actor, nullptr), 0);
  EXPECT_EQ(cue->GetNumberOfProps(), 0);
  // A camera path without keys: the tick reports it and leaves the camera alone.
  vtkNew<vtkCamera> camera;
  camera->SetPosition(1, 2, 3);
  vtkNew<vtkCameraInterpolatorLCT> empty;
  empty->AddObserver(vtkCommand::ErrorEvent, errors);
  cue->SetCamera(camera);
  cue->SetCameraInterpolator(empty);
  cue->SetStartTime(0);
  cue->SetEndTime(1);
  cue->Initialize();
  cue->Tick(0.5, 0.1, 0.5);
  EXPECT_EQ(camera->GetPosition()[0], 1.0);
  EXPECT_EQ(errors->Count, 4); // two AddProp, the path's own error, the cue's
}

TEST(InterpolatorCueLCT, CueTimesAtAnyMagnitudeAndInvalidOnesReported)
{
  // A cue from -1e308 to 1e308: its duration overflows, yet its middle is the middle of the keys
  // (it mapped every tick to key time 0, and its end to NaN).
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<vtkCamera> key;
  key->SetFocalPoint(0, 0, 0);
  key->SetPosition(0, 0, 10);
  ASSERT_EQ(path->AddCamera(0.0, key), 1);
  key->SetPosition(10, 0, 10);
  ASSERT_EQ(path->AddCamera(1.0, key), 1);
  vtkNew<vtkInterpolatorCueLCT> cue;
  vtkNew<lct_test::ErrorCounter> errors;
  cue->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkCamera> camera;
  cue->SetCamera(camera);
  cue->SetCameraInterpolator(path);
  cue->SetStartTime(-1e308);
  cue->SetEndTime(1e308);
  EXPECT_EQ(cue->KeyTime(-1e308, 0.0, 1.0), 0.0);
  EXPECT_DOUBLE_EQ(cue->KeyTime(0.0, 0.0, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(cue->KeyTime(5e307, 0.0, 1.0), 0.75);
  EXPECT_EQ(cue->KeyTime(1e308, 0.0, 1.0), 1.0);
  // A key range of the same magnitude.
  EXPECT_DOUBLE_EQ(cue->KeyTime(5e307, -1e308, 1e308), 5e307);
  cue->Initialize();
  cue->Tick(0.0, 0.0, 0.0);
  EXPECT_NEAR(camera->GetPosition()[0], 5.0, 0.5);
  cue->Tick(1e308, 0.0, 1e308);
  EXPECT_NEAR(camera->GetPosition()[0], 10.0, 1e-9);
  EXPECT_EQ(errors->Count, 0);
  // A NaN start: no key time. vtkAnimationCue never starts such a cue; Initialize says so, and
  // a tick called on the cue's own TickInternal (a subclass, a cue already running) moves nothing.
  cue->SetStartTime(std::nan(""));
  EXPECT_EQ(cue->KeyTime(0.0, 2.0, 3.0), 2.0);
  cue->Initialize();
  EXPECT_EQ(errors->Count, 1);
  EXPECT_NE(errors->Last.find("cannot run"), std::string::npos) << errors->Last;
  camera->SetPosition(1, 2, 3);
  cue->Tick(0.0, 0.0, 0.0);
  EXPECT_EQ(camera->GetPosition()[0], 1.0);
  // An end before the start, with range mapping.
  cue->SetStartTime(2.0);
  cue->SetEndTime(1.0);
  cue->Initialize();
  EXPECT_EQ(errors->Count, 2);
  EXPECT_NE(errors->Last.find("an end before the start"), std::string::npos) << errors->Last;
}

TEST(InterpolatorCueLCT, RealTimeSceneDrivesTheCamera)
{
  vtkNew<vtkCameraInterpolatorLCT> cameraPath;
  for (int k = 0; k < 3; ++k)
  {
    vtkNew<vtkCamera> key;
    key->SetPosition(8.0 * std::cos(1.2 * k), 8.0 * std::sin(1.2 * k), 1.0);
    key->SetViewUp(0, 0, 1);
    ASSERT_EQ(cameraPath->AddCamera(k, key), 1);
  }
  vtkNew<vtkCamera> camera;
  vtkNew<vtkActor> unused;
  vtkNew<vtkInterpolatorCueLCT> cue;
  cue->SetCamera(camera);
  cue->SetCameraInterpolator(cameraPath);
  cue->SetTimeModeToNormalized();
  cue->SetStartTime(0.0);
  cue->SetEndTime(1.0);
  TickRecord record;
  record.camera = camera;
  record.actor = unused;
  unused->SetUserMatrix(vtkNew<vtkMatrix4x4>());
  vtkNew<vtkCallbackCommand> tick;
  tick->SetCallback(onTick);
  tick->SetClientData(&record);
  cue->AddObserver(vtkCommand::AnimationCueTickEvent, tick);

  vtkNew<vtkAnimationScene> scene;
  scene->SetModeToRealTime();
  scene->SetStartTime(0.0);
  scene->SetEndTime(0.2); // seconds of wall-clock time
  scene->AddCue(cue);
  scene->Play();

  ASSERT_GE(record.cueTimes.size(), 2u);
  for (size_t i = 0; i < record.cueTimes.size(); ++i)
  {
    vtkNew<vtkCamera> expected;
    cameraPath->InterpolateCamera(2.0 * record.cueTimes[i], expected);
    const double* p = expected->GetPosition();
    EXPECT_LT((record.positions[i] - Eigen::Vector3d(p[0], p[1], p[2])).norm(), 1e-12);
  }
}

// Audit (session 28): KeyTime extrapolated cue times outside the cue, and at large magnitudes
// returned Inf or NaN with no error (KeyTime(1e308, -1e308, -1e308) was NaN). They map to the
// range's ends now.
TEST(InterpolatorCueLCT, CueTimesOutsideTheCueMapToTheRangesEnds)
{
  vtkNew<vtkInterpolatorCueLCT> cue;
  cue->SetStartTime(0.0);
  cue->SetEndTime(2.0);
  EXPECT_EQ(cue->KeyTime(1e308, 0.5, 0.5), 0.5);
  EXPECT_EQ(cue->KeyTime(1e308, 0.0, 1e308), 1e308);
  EXPECT_EQ(cue->KeyTime(1e308, -1e308, -1e308), -1e308);
  EXPECT_EQ(cue->KeyTime(3.0, -1e308, 1e308), 1e308);
  EXPECT_EQ(cue->KeyTime(-5.0, 1.0, 4.0), 1.0);
  EXPECT_EQ(cue->KeyTime(1.0, 1.0, 4.0), 2.5);
  cue->SetStartTime(-1e308);
  cue->SetEndTime(1e308);
  cue->SetKeyTimeMappingToCueTime();
  EXPECT_EQ(cue->KeyTime(1e308, 0.0, 1.0), std::numeric_limits<double>::max());
}

// Audit (session 29): the cue refitted the clipping range right after moving the camera and
// before moving the props, so a prop moving away was clipped out of the frame (at t = 0.5 the
// range was [9.2, 11.7] with the prop 60 away); and the refit acted on the renderer's active
// camera even when the cue drove another one, which kept its stale range. A camera without a path
// (props moving in front of a still camera) had no refit at all.
TEST(InterpolatorCueLCT, ClippingRangeIsRefittedToThePropsOfThisTickOnTheCuesCamera)
{
  vtkNew<vtkCameraInterpolatorLCT> cameraPath;
  for (const double z : { 10.0, 10.5 })
  {
    vtkNew<vtkCamera> key;
    key->SetPosition(0, 0, z);
    ASSERT_EQ(cameraPath->AddCamera(z == 10.0 ? 0.0 : 1.0, key), 1);
  }
  vtkNew<vtkTransformInterpolatorLCT> propPath;
  vtkNew<vtkTransform> near, far;
  far->Translate(0, 0, -100);
  ASSERT_EQ(propPath->AddTransform(0.0, near), 1);
  ASSERT_EQ(propPath->AddTransform(1.0, far), 1);
  for (const int variant : { 0, 1, 2 })
  {
    const bool activeCamera = variant != 1;
    const bool cameraMoves = variant != 2;
    vtkNew<UnitBoxMapper> mapper;
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    vtkNew<vtkRenderer> renderer;
    renderer->AddActor(actor);
    vtkNew<vtkCamera> other;
    vtkCamera* camera = renderer->GetActiveCamera();
    if (!activeCamera)
    {
      camera = other;
    }
    const double activeRange[2] = { renderer->GetActiveCamera()->GetClippingRange()[0],
      renderer->GetActiveCamera()->GetClippingRange()[1] };
    vtkNew<vtkInterpolatorCueLCT> cue;
    cue->SetStartTime(0.0);
    cue->SetEndTime(1.0);
    cue->SetCamera(camera);
    if (cameraMoves)
    {
      cue->SetCameraInterpolator(cameraPath);
    }
    else
    {
      camera->SetClippingRange(1.0, 5.0); // fits the box at the start only
    }
    cue->SetRenderer(renderer);
    ASSERT_EQ(cue->AddProp(actor, propPath), 1);
    vtkNew<vtkAnimationScene> scene;
    scene->SetModeToSequence();
    scene->SetFrameRate(4);
    scene->SetStartTime(0.0);
    scene->SetEndTime(1.0);
    scene->AddCue(cue);
    int ticks = 0;
    vtkNew<vtkCallbackCommand> check;
    struct Context
    {
      vtkCamera* camera;
      vtkActor* actor;
      int* ticks;
    } context{ camera, actor, &ticks };
    check->SetClientData(&context);
    check->SetCallback([](vtkObject*, unsigned long, void* data, void*) {
      auto* c = static_cast<Context*>(data);
      const double* centre = c->actor->GetCenter();
      const double depth = c->camera->GetPosition()[2] - centre[2];
      const double* range = c->camera->GetClippingRange();
      EXPECT_LE(range[0], depth - 0.5);
      EXPECT_GE(range[1], depth + 0.5);
      ++*c->ticks;
    });
    cue->AddObserver(vtkCommand::AnimationCueTickEvent, check);
    scene->Play();
    EXPECT_GE(ticks, 4) << variant;
    EXPECT_EQ(renderer->GetActiveCamera() == camera, activeCamera);
    if (!activeCamera)
    {
      EXPECT_EQ(renderer->GetActiveCamera()->GetClippingRange()[0], activeRange[0]);
      EXPECT_EQ(renderer->GetActiveCamera()->GetClippingRange()[1], activeRange[1]);
    }
  }
}

// Audit (session 29): a cue given a camera path but no camera played nothing and said nothing.
TEST(InterpolatorCueLCT, ACameraPathWithoutACameraIsReportedWhenTheCueStarts)
{
  vtkNew<vtkCameraInterpolatorLCT> path;
  vtkNew<vtkCamera> key;
  ASSERT_EQ(path->AddCamera(0.0, key), 1);
  ASSERT_EQ(path->AddCamera(1.0, key), 1);
  vtkNew<vtkInterpolatorCueLCT> cue;
  vtkNew<lct_test::ErrorCounter> errors;
  cue->AddObserver(vtkCommand::ErrorEvent, errors);
  cue->SetCameraInterpolator(path);
  vtkNew<vtkAnimationScene> scene;
  scene->SetModeToSequence();
  scene->SetFrameRate(4);
  scene->SetStartTime(0.0);
  scene->SetEndTime(1.0);
  scene->AddCue(cue);
  scene->Play();
  EXPECT_EQ(errors->Count, 1); // once per run, not once per tick
  EXPECT_NE(errors->Last.find("camera interpolator but no camera"), std::string::npos)
    << errors->Last;
  // With its camera the same cue plays without a word.
  vtkNew<vtkCamera> camera;
  cue->SetCamera(camera);
  scene->Play();
  EXPECT_EQ(errors->Count, 1);
}
