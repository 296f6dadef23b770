// vtkSkeletonAnimationReader on the CMU and boxing BVH files of assimp-testmodels: the forward
// kinematics of what it reads against a direct evaluation of the BVH text (Testing/Benchmarks/
// BVHOracle.h, an independent parser kept as the oracle of this test only), TIME_STEPS through the
// pipeline, and unreadable files.
#include "BVHOracle.h"
#include "VtkTestHelpers.h"

#include "lct/BVHWriter.h"
#include "lct/MotionError.h"
#include "lct/Skeleton.h"
#include "vtkSkeletonAnimationReader.h"

#include "vtkCommand.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace
{
const std::string kData = "/usr/share/assimp/models/BVH/";

bool haveData()
{
  return std::filesystem::exists(kData + "01_01.bvh");
}

struct Watched
{
  vtkNew<vtkSkeletonAnimationReader> reader;
  vtkNew<lct_test::ErrorCounter> errors;
  vtkNew<lct_test::ErrorCounter> pipeline; // the executive reports the failed request too
  Watched()
  {
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, pipeline);
  }
};

std::string temporaryFile(const std::string& name, const std::string& contents)
{
  const std::string path =
    (std::filesystem::temp_directory_path() / ("lct-reader-" + name)).string();
  std::ofstream(path, std::ios::binary) << contents;
  return path;
}
} // namespace

class SkeletonReaderOnClips : public ::testing::TestWithParam<const char*>
{
};

TEST_P(SkeletonReaderOnClips, ForwardKinematicsMatchesADirectEvaluationOfTheFile)
{
  if (!haveData())
  {
    GTEST_SKIP() << "assimp-testmodels not installed";
  }
  const std::string path = kData + GetParam();
  const auto direct = lct_bench::LoadBVH(path);
  ASSERT_TRUE(direct.Ok()) << direct.error;
  const lct_bench::BVHMotion& m = direct.motion;
  Watched w;
  w.reader->SetFileName(path.c_str());
  w.reader->UpdateInformation();
  ASSERT_EQ(w.errors->Count, 0) << w.errors->Last;
  const lct::SkeletalAnimation* a = w.reader->GetAnimation();
  ASSERT_NE(a, nullptr);
  ASSERT_EQ(a->jointCount(), static_cast<int>(m.joints.size()));
  // Every data row (Boxing_Toes has one more than its Frames line says, which BVHOracle.h skips).
  EXPECT_GE(a->frames, m.frameCount);
  EXPECT_LE(a->frames, m.frameCount + 1);
  EXPECT_NEAR(a->frameTime, m.frameTime, 1e-7 * m.frameTime);
  for (int j = 0; j < a->jointCount(); ++j)
  {
    EXPECT_EQ(a->joints[j].parent, m.joints[j].parent) << j;
    EXPECT_EQ(a->joints[j].endSite, m.joints[j].endSite) << j;
    if (!m.joints[j].endSite)
    {
      EXPECT_EQ(a->joints[j].name, m.joints[j].name);
    }
  }
  // World positions of every joint and End Site at every row, against the text's own FK.
  double height = 0.0, worst = 0.0;
  std::vector<Eigen::Matrix4d> world;
  std::vector<lct_bench::Matrix4> locals(m.joints.size()), directWorld;
  std::vector<double> positions;
  for (int f = 0; f < m.frameCount; ++f)
  {
    for (std::size_t j = 0; j < m.joints.size(); ++j)
    {
      locals[j] = lct_bench::LocalTransform(m, static_cast<int>(j), m.Frame(f));
    }
    lct_bench::ForwardKinematics(m, locals, directWorld, positions);
    lct::worldTransforms(*a, f, world);
    double low = 1e300, high = -1e300;
    for (std::size_t j = 0; j < m.joints.size(); ++j)
    {
      const Eigen::Vector3d expected(positions[3 * j], positions[3 * j + 1], positions[3 * j + 2]);
      worst = std::max(worst, (world[j].topRightCorner<3, 1>() - expected).norm());
      low = std::min(low, expected.y());
      high = std::max(high, expected.y());
    }
    height = std::max(height, high - low);
  }
  // assimp parses float32 values: ~1e-7 relative, accumulated along chains of up to ~10 bones.
  EXPECT_LE(worst, 1e-5 * height) << GetParam() << ": worst " << worst << ", height " << height;
  // The bound vtkMotionCodecLCT refuses tolerances below holds on real files.
  const double resolution = lct::float32PositionResolution(*a);
  EXPECT_LE(worst, resolution) << GetParam() << ": worst " << worst;
  EXPECT_LE(resolution, 1e-5 * height)
    << GetParam() << ": a bound this loose would refuse usable tolerances";
  RecordProperty("Float32ResolutionOverWorst", std::to_string(resolution / worst));
  RecordProperty("WorstPositionErrorOverHeight", std::to_string(worst / height));
}

INSTANTIATE_TEST_SUITE_P(
  CMU, SkeletonReaderOnClips, ::testing::Values("01_01.bvh", "01_03.bvh", "Boxing_Toes.bvh"));

TEST(SkeletonReader, TimeStepsDrivePipelineUpdates)
{
  if (!haveData())
  {
    GTEST_SKIP() << "assimp-testmodels not installed";
  }
  Watched w;
  w.reader->SetFileName((kData + "01_01.bvh").c_str());
  w.reader->UpdateInformation();
  vtkInformation* info = w.reader->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  const int n = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  EXPECT_EQ(n, w.reader->GetNumberOfFrames());
  const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  EXPECT_NEAR(times[1] - times[0], w.reader->GetFrameTime(), 1e-12);
  // Between frames 100 and 101, nearer 101.
  const double t = times[100] + 0.7 * (times[101] - times[100]);
  w.reader->UpdateTimeStep(t);
  vtkPolyData* skeleton = w.reader->GetOutput();
  ASSERT_EQ(skeleton->GetNumberOfPoints(), w.reader->GetNumberOfJoints());
  EXPECT_EQ(skeleton->GetNumberOfLines(), w.reader->GetNumberOfJoints() - 1); // one root
  auto* frame = vtkIntArray::SafeDownCast(skeleton->GetFieldData()->GetArray("Frame"));
  ASSERT_NE(frame, nullptr);
  EXPECT_EQ(frame->GetValue(0), 101);
  auto* names =
    vtkStringArray::SafeDownCast(skeleton->GetPointData()->GetAbstractArray("JointName"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(0), "Hips");
  ASSERT_NE(skeleton->GetPointData()->GetArray("Depth"), nullptr);
  ASSERT_NE(skeleton->GetPointData()->GetArray("Parent"), nullptr);
  // The points are the world positions of that frame.
  vtkNew<vtkMatrix4x4> world;
  const int joint = w.reader->GetNumberOfJoints() - 1;
  ASSERT_EQ(w.reader->GetWorldTransform(joint, 101, world), 1);
  double p[3];
  skeleton->GetPoint(joint, p);
  for (int i = 0; i < 3; ++i)
  {
    EXPECT_NEAR(p[i], world->GetElement(i, 3), 1e-12);
  }
  // Beyond the range: the last frame.
  w.reader->UpdateTimeStep(1e9);
  frame = vtkIntArray::SafeDownCast(w.reader->GetOutput()->GetFieldData()->GetArray("Frame"));
  EXPECT_EQ(frame->GetValue(0), w.reader->GetNumberOfFrames() - 1);
  vtkNew<vtkMatrix4x4> local;
  EXPECT_EQ(w.reader->GetLocalTransform(0, 0, local), 1);
  EXPECT_EQ(w.errors->Count, 0);
  EXPECT_EQ(w.reader->GetLocalTransform(0, w.reader->GetNumberOfFrames(), local), 0);
  EXPECT_EQ(w.reader->GetLocalTransform(-1, 0, local), 0);
  EXPECT_EQ(w.reader->GetJointName(9999), nullptr);
  EXPECT_EQ(w.errors->Count, 3);
}

TEST(SkeletonReader, UnreadableFilesAreErrorsWithoutOutput)
{
  const std::string header = "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n CHANNELS 6 Xposition "
                             "Yposition Zposition Zrotation Yrotation Xrotation\n End Site\n {\n "
                             "OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 2\nFrame Time: 0.1\n";
  const std::string files[] = {
    "/nonexistent/file.bvh",
    temporaryFile("empty.bvh", ""),
    temporaryFile("garbage.bvh", "this is not a motion file \x01\x02\x03"),
    temporaryFile("truncated.bvh", header + "0 0 0 0 0 0\n"),
    temporaryFile("words.bvh", header + "0 0 0 0 0 0\n0 0 zero 0 0 0\n"),
    temporaryFile("unbalanced.bvh", "HIERARCHY\nROOT Hips\n{\n OFFSET 0 0 0\n"),
  };
  for (const std::string& file : files)
  {
    Watched w;
    w.reader->SetFileName(file.c_str());
    w.reader->Update();
    EXPECT_EQ(w.errors->Count, 1) << file;
    EXPECT_NE(w.errors->Last.find(file), std::string::npos) << w.errors->Last;
    EXPECT_EQ(w.reader->GetOutput()->GetNumberOfPoints(), 0) << file;
    EXPECT_EQ(w.reader->GetNumberOfJoints(), 0) << file;
    EXPECT_EQ(w.reader->GetAnimation(), nullptr) << file;
  }
  // No file name at all.
  Watched w;
  w.reader->Update();
  EXPECT_EQ(w.errors->Count, 1);
  EXPECT_NE(w.errors->Last.find("no file name"), std::string::npos) << w.errors->Last;
  // A mesh file without animation.
  const std::string mesh = "/usr/share/assimp/models/PLY/cube.ply";
  if (std::filesystem::exists(mesh))
  {
    Watched m;
    m.reader->SetFileName(mesh.c_str());
    m.reader->Update();
    EXPECT_EQ(m.errors->Count, 1);
    EXPECT_NE(m.errors->Last.find("no skeletal animation"), std::string::npos) << m.errors->Last;
    EXPECT_EQ(m.reader->GetNumberOfJoints(), 0);
  }
}

// Read, write as BVH in another channel order, and read the written text with the independent
// parser: the same hierarchy and the same joint positions at every row.
TEST_P(SkeletonReaderOnClips, WrittenBVHReproducesTheMotion)
{
  if (!haveData())
  {
    GTEST_SKIP() << "assimp-testmodels not installed";
  }
  Watched w;
  w.reader->SetFileName((kData + GetParam()).c_str());
  w.reader->UpdateInformation();
  const lct::SkeletalAnimation* a = w.reader->GetAnimation();
  ASSERT_NE(a, nullptr);
  for (const char* order : { "ZXY", "XYZ" })
  {
    const std::string out = (std::filesystem::temp_directory_path() /
      (std::string("lct-written-") + order + "-" + GetParam()))
                              .string();
    ASSERT_EQ(w.reader->WriteBVH(out.c_str(), order), 1) << w.errors->Last;
    EXPECT_FALSE(std::filesystem::exists(out + ".part"));
    const auto written = lct_bench::LoadBVH(out);
    ASSERT_TRUE(written.Ok()) << written.error;
    const lct_bench::BVHMotion& m = written.motion;
    ASSERT_EQ(static_cast<int>(m.joints.size()), a->jointCount());
    ASSERT_EQ(m.frameCount, a->frames);
    EXPECT_NEAR(m.frameTime, a->frameTime, 1e-9 * a->frameTime);
    std::vector<Eigen::Matrix4d> world;
    std::vector<lct_bench::Matrix4> locals(m.joints.size()), directWorld;
    std::vector<double> positions;
    double worst = 0.0, height = 0.0, jump = 0.0;
    for (int f = 0; f < m.frameCount; ++f)
    {
      for (std::size_t j = 0; j < m.joints.size(); ++j)
      {
        EXPECT_EQ(m.joints[j].parent, a->joints[j].parent);
        locals[j] = lct_bench::LocalTransform(m, static_cast<int>(j), m.Frame(f));
      }
      lct::worldTransforms(*a, f, world);
      lct_bench::ForwardKinematics(m, locals, directWorld, positions);
      for (std::size_t j = 0; j < m.joints.size(); ++j)
      {
        const Eigen::Vector3d p(positions[3 * j], positions[3 * j + 1], positions[3 * j + 2]);
        worst = std::max(worst, (world[j].topRightCorner<3, 1>() - p).norm());
        height = std::max(height, std::abs(p.y() - positions[1]));
      }
      // Continuous channels: no rotation value jumps by half a turn between rows.
      if (f > 0)
      {
        for (int c = 0; c < m.channelCount; ++c)
        {
          jump = std::max(jump, std::abs(m.Frame(f)[c] - m.Frame(f - 1)[c]));
        }
      }
    }
    EXPECT_LE(worst, 1e-7 * height) << order;
    EXPECT_LT(jump, 180.0) << order;
    std::filesystem::remove(out);
  }
  EXPECT_EQ(w.errors->Count, 0);
}

TEST(SkeletonReader, AFrameTimeThatIsNotPositiveIsAnError)
{
  // assimp reads a BVH Frame Time as 1 / Frame Time ticks per second; the reader took a
  // non-positive rate for "unknown" and used 1/25 s (negative, NaN, beyond float), or kept
  // Frame Time 0 with every TIME_STEP 0.
  for (const char* frameTime : { "-0.03", "0", "nan", "1e300" })
  {
    const std::string text = std::string("HIERARCHY\nROOT Hips\n{\n\tOFFSET 0 0 0\n"
                                         "\tCHANNELS 6 Xposition Yposition Zposition Zrotation "
                                         "Yrotation Xrotation\n\tEnd Site\n\t{\n\t\tOFFSET 0 3 "
                                         "0\n\t}\n}\nMOTION\nFrames: 2\nFrame Time: ") +
      frameTime + "\n0 1 0 10 20 30\n0 1 0 11 21 31\n";
    const std::string path = temporaryFile("frame-time.bvh", text);
    Watched w;
    w.reader->SetFileName(path.c_str());
    w.reader->UpdateInformation();
    EXPECT_EQ(w.reader->GetAnimation(), nullptr) << frameTime;
    EXPECT_NE(w.errors->Last.find("not a positive number"), std::string::npos)
      << frameTime << ": " << w.errors->Last;
    std::filesystem::remove(path);
  }
}

TEST(SkeletonReader, WrittenJointsWithPositionChannelsReadBackByEveryConvention)
{
  // A joint below the root whose translation changes (position channels) was written as
  // "translation minus OFFSET", which the module's own reader (assimp: the channels replace the
  // OFFSET) read back off by that OFFSET: a codec round trip reported within 1 % read 77 % off.
  // Written at OFFSET 0 with the whole translation, both readings agree; a name with a space
  // is written as one token; a second root is refused.
  lct::SkeletalAnimation a;
  a.joints = { { "root", -1, false }, { "My Spine", 0, false }, { "tip", 1, true } };
  a.frames = 3;
  a.frameTime = 0.1;
  for (int f = 0; f < a.frames; ++f)
  {
    Eigen::Matrix4d root = Eigen::Matrix4d::Identity(), spine = Eigen::Matrix4d::Identity();
    root.topRightCorner<3, 1>() = Eigen::Vector3d(0.1 * f, 1.0, 0.0);
    spine.topLeftCorner<3, 3>() = Eigen::AngleAxisd(0.3 * f, Eigen::Vector3d::UnitZ()).matrix();
    spine.topRightCorner<3, 1>() = Eigen::Vector3d(0.5, -1.0 + 0.2 * f, 2.0);
    Eigen::Matrix4d tip = Eigen::Matrix4d::Identity();
    tip(1, 3) = 0.7;
    a.locals.insert(a.locals.end(), { root, spine, tip });
  }
  std::ostringstream text;
  std::string why;
  ASSERT_TRUE(lct::writeBVH(a, "ZXY", text, &why)) << why;
  EXPECT_NE(text.str().find("JOINT My_Spine"), std::string::npos) << text.str();
  const std::string path = temporaryFile("position-channels.bvh", text.str());
  // The module's reader (assimp) and the independent parser (channels added to the OFFSET).
  Watched w;
  w.reader->SetFileName(path.c_str());
  w.reader->UpdateInformation();
  const lct::SkeletalAnimation* read = w.reader->GetAnimation();
  ASSERT_NE(read, nullptr) << w.errors->Last;
  ASSERT_EQ(read->jointCount(), 3);
  ASSERT_EQ(read->frames, 3);
  const auto oracle = lct_bench::LoadBVH(path);
  ASSERT_TRUE(oracle.Ok()) << oracle.error;
  for (int f = 0; f < a.frames; ++f)
  {
    for (int j = 0; j < 3; ++j)
    {
      EXPECT_LT((read->local(f, j) - a.local(f, j)).norm(), 1e-6)
        << "frame " << f << " joint " << j;
      const lct_bench::Matrix4 l =
        lct_bench::LocalTransform(oracle.motion, j, oracle.motion.Frame(f));
      const Eigen::Matrix4d parsed =
        Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(l.data());
      EXPECT_LT((parsed - a.local(f, j)).norm(), 1e-8) << "frame " << f << " joint " << j;
    }
  }
  std::filesystem::remove(path);
  // Two roots: one file cannot hold them.
  a.joints[1].parent = -1;
  std::ostringstream twoRoots;
  EXPECT_FALSE(lct::writeBVH(a, "ZXY", twoRoots, &why));
  EXPECT_NE(why.find("one ROOT"), std::string::npos) << why;
}

TEST(SkeletonReader, WritingRefusesWhatBVHCannotHold)
{
  lct::SkeletalAnimation a;
  a.joints = { { "root", -1, false }, { "tip", 0, true } };
  a.frames = 1;
  a.frameTime = 0.1;
  a.locals = { Eigen::Matrix4d::Identity(), Eigen::Matrix4d::Identity() };
  a.locals[1](1, 3) = 2.0;
  std::ostringstream good;
  std::string why;
  ASSERT_TRUE(lct::writeBVH(a, "ZYX", good, &why)) << why;
  EXPECT_NE(good.str().find("End Site"), std::string::npos);
  EXPECT_NE(good.str().find("OFFSET 0 2 0"), std::string::npos) << good.str();
  for (const char* order : { "ZZY", "XY", "ABC", "" })
  {
    std::ostringstream out;
    EXPECT_FALSE(lct::writeBVH(a, order, out, &why)) << order;
    EXPECT_NE(why.find("XYZ"), std::string::npos) << why;
  }
  a.locals[0](0, 0) = 2.0; // a scale
  std::ostringstream scaled;
  EXPECT_FALSE(lct::writeBVH(a, "ZYX", scaled, &why));
  EXPECT_NE(why.find("no scale, shear or reflection"), std::string::npos) << why;
  a.locals[0].setIdentity();
  a.locals.pop_back(); // inconsistent
  std::ostringstream inconsistent;
  EXPECT_FALSE(lct::writeBVH(a, "ZYX", inconsistent, &why));

  Watched w;
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(w.reader->WriteBVH("/tmp/never.bvh", "ZYX"), 0); // nothing read
  if (haveData())
  {
    w.reader->SetFileName((kData + "01_01.bvh").c_str());
    w.reader->UpdateInformation();
    EXPECT_EQ(w.reader->WriteBVH("/nonexistent/dir/out.bvh", "ZYX"), 0);
    EXPECT_NE(w.errors->Last.find("nothing written"), std::string::npos) << w.errors->Last;
    EXPECT_EQ(w.reader->WriteBVH("/tmp/lct-bad-order.bvh", "ZYZ"), 0);
    EXPECT_FALSE(std::filesystem::exists("/tmp/lct-bad-order.bvh"));
    EXPECT_FALSE(std::filesystem::exists("/tmp/lct-bad-order.bvh.part"));
  }
}
