// vtkSkinnedMeshReaderLCT on the skinned characters of assimp-testmodels, driving
// vtkProbeDeformerLCT in every blend mode (issue #11 §2). Skipped without the data.
#include "VtkTestHelpers.h"

#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkSkinnedMeshReaderLCT.h"

#include <Eigen/Dense>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

namespace
{
const std::string kModels = "/usr/share/assimp/models/";

bool have(const std::string& file)
{
  return std::ifstream(kModels + file).good();
}

double diagonal(vtkPolyData* pd)
{
  double b[6];
  pd->GetBounds(b);
  return std::sqrt(std::pow(b[1] - b[0], 2) + std::pow(b[3] - b[2], 2) + std::pow(b[5] - b[4], 2));
}
} // namespace

class SkinnedCharacters : public ::testing::TestWithParam<const char*>
{
};

TEST_P(SkinnedCharacters, WeightsBonesAndEveryBlendModeThroughTheAnimation)
{
  const std::string file = GetParam();
  if (!have(file))
  {
    GTEST_SKIP() << kModels + file << " is missing (assimp-testmodels)";
  }
  vtkNew<vtkSkinnedMeshReaderLCT> reader;
  reader->SetFileName((kModels + file).c_str());
  ASSERT_EQ(reader->GetExecutive()->Update(), 1);
  vtkPolyData* rest = reader->GetOutput();
  ASSERT_GT(rest->GetNumberOfPoints(), 0);
  ASSERT_GT(reader->GetNumberOfBones(), 1);
  ASSERT_GT(reader->GetEndTime(), reader->GetStartTime());
  vtkDataArray* w = rest->GetPointData()->GetArray("BoneWeights");
  vtkDataArray* idx = rest->GetPointData()->GetArray("BoneIndices");
  ASSERT_TRUE(w && idx);
  ASSERT_EQ(w->GetNumberOfComponents(), reader->GetMaximumInfluences());
  // The file's weights: every vertex bound with a positive sum (the deformer normalises;
  // animation_with_skeleton.fbx has sums up to 1.2).
  for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
  {
    double sum = 0.0;
    for (int k = 0; k < w->GetNumberOfComponents(); ++k)
    {
      sum += w->GetComponent(i, k);
      ASSERT_LT(idx->GetComponent(i, k), reader->GetNumberOfBones());
    }
    ASSERT_GT(sum, 0.0) << i;
  }
  const double size = diagonal(rest);
  const double t = 0.5 * (reader->GetStartTime() + reader->GetEndTime());
  // The oracle of the wiring: LBS written out with the reader's matrices,
  // sum_k w_k (current_k rest_k^-1) v.
  std::vector<Eigen::Matrix4d> relative;
  for (int b = 0; b < reader->GetNumberOfBones(); ++b)
  {
    vtkNew<vtkMatrix4x4> current, restMatrix;
    ASSERT_EQ(reader->GetBoneMatrix(b, t, current), 1);
    ASSERT_EQ(reader->GetBoneRestMatrix(b, restMatrix), 1);
    relative.push_back(lct_test::fromVtk(current) * lct_test::fromVtk(restMatrix).inverse());
  }
  vtkSmartPointer<vtkPolyData> linear;
  for (int mode = vtkProbeDeformerLCT::POLAR; mode <= vtkProbeDeformerLCT::DUAL_QUATERNION; ++mode)
  {
    vtkNew<vtkProbeDeformerLCT> deformer;
    deformer->SetInputConnection(reader->GetOutputPort());
    deformer->SetBlendMode(mode);
    // Through the animation frame by frame (ConsistentRotation follows each bone).
    const int frames = 12;
    for (int f = 0; f <= frames; ++f)
    {
      const double time =
        reader->GetStartTime() + (t - reader->GetStartTime()) * f / static_cast<double>(frames);
      ASSERT_EQ(reader->ConfigureDeformer(deformer, time), 1);
      ASSERT_EQ(deformer->GetExecutive()->Update(), 1)
        << file << " mode " << mode << " frame " << f;
    }
    vtkPolyData* out = vtkPolyData::SafeDownCast(deformer->GetOutputDataObject(0));
    ASSERT_EQ(out->GetNumberOfPoints(), rest->GetNumberOfPoints());
    if (mode == vtkProbeDeformerLCT::LINEAR)
    {
      for (vtkIdType i = 0; i < rest->GetNumberOfPoints(); ++i)
      {
        double p[3], q[3];
        rest->GetPoint(i, p);
        out->GetPoint(i, q);
        Eigen::Vector4d expected = Eigen::Vector4d::Zero();
        double sum = 0.0;
        for (int k = 0; k < w->GetNumberOfComponents(); ++k)
        {
          sum += w->GetComponent(i, k);
          expected += w->GetComponent(i, k) *
            (relative[static_cast<int>(idx->GetComponent(i, k))] *
              Eigen::Vector4d(p[0], p[1], p[2], 1));
        }
        expected /= sum;
        ASSERT_LT((expected.head<3>() - Eigen::Vector3d(q[0], q[1], q[2])).norm(), 1e-5 * size)
          << i;
      }
      linear = vtkSmartPointer<vtkPolyData>::New();
      linear->DeepCopy(out);
    }
    else if (linear)
    {
      // DQS against LBS: the same skin, apart where LBS loses volume at the joints.
      double mean = 0.0;
      for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      {
        double a[3], b[3];
        out->GetPoint(i, a);
        linear->GetPoint(i, b);
        mean += std::sqrt(vtkMath::Distance2BetweenPoints(a, b));
      }
      mean /= out->GetNumberOfPoints();
      EXPECT_LT(mean, 0.05 * size) << file << " mode " << mode;
    }
    EXPECT_LT(diagonal(out), 3.0 * size);
    EXPECT_GT(diagonal(out), size / 3.0);
  }
}

INSTANTIATE_TEST_SUITE_P(AssimpTestModels, SkinnedCharacters,
  ::testing::Values("X/BCN_Epileptic.X", "FBX/animation_with_skeleton.fbx", "X/anim_test.x"));

TEST(SkinnedMeshReader, UnreadableFilesAreErrorsWithoutOutput)
{
  vtkNew<vtkSkinnedMeshReaderLCT> reader;
  vtkNew<lct_test::ErrorCounter> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<lct_test::ErrorCounter> executive;
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executive);
  reader->SetFileName("/nonexistent/character.fbx");
  EXPECT_EQ(reader->GetExecutive()->Update(), 0);
  EXPECT_NE(errors->Last.find("not readable"), std::string::npos) << errors->Last;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  const std::string junk = std::string(LCT_BINARY_DIR) + "/Testing/Temporary/not-a-mesh.obj";
  std::ofstream(junk) << "# an OBJ file without any vertex\n";
  reader->SetFileName(junk.c_str());
  EXPECT_EQ(reader->GetExecutive()->Update(), 0);
  EXPECT_NE(errors->Last.find("not-a-mesh.obj"), std::string::npos) << errors->Last;
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  // A face without indices (assimp-testmodels' invalid/OutOfMemory.off): assimp's triangulation
  // asserted and aborted the process; its structure check now refuses the file first.
  const std::string invalid = "/usr/share/assimp/models/invalid/OutOfMemory.off";
  if (std::ifstream(invalid).good())
  {
    reader->SetFileName(invalid.c_str());
    EXPECT_EQ(reader->GetExecutive()->Update(), 0);
    EXPECT_NE(errors->Last.find("Validation failed"), std::string::npos) << errors->Last;
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(reader->GetBoneMatrix(0, 0.0, m), 0);
  vtkNew<vtkProbeDeformerLCT> d;
  EXPECT_EQ(reader->ConfigureDeformer(d, 0.0), 0);
}

// The extension list lct-render uses to pick the reader: assimp's, lower case, with the dot.
TEST(SkinnedMeshReader, FileExtensionsAreAssimpsInLowerCase)
{
  const std::string list = vtkSkinnedMeshReaderLCT::GetFileExtensions();
  for (const char* ext : { ".fbx", ".dae", ".x", ".3ds", ".off", ".obj", ".bvh" })
  {
    EXPECT_NE((" " + list + " ").find(std::string(" ") + ext + " "), std::string::npos) << ext;
    EXPECT_TRUE(vtkSkinnedMeshReaderLCT::IsExtensionSupported(ext)) << ext;
  }
  for (char c : list)
  {
    EXPECT_FALSE(c >= 'A' && c <= 'Z') << list;
  }
  EXPECT_TRUE(vtkSkinnedMeshReaderLCT::IsExtensionSupported("FBX"));
  EXPECT_TRUE(vtkSkinnedMeshReaderLCT::IsExtensionSupported(".Dae"));
  for (const char* ext : { ".json", ".vtp", "", ".", "fb", ".fbxx" })
  {
    EXPECT_FALSE(vtkSkinnedMeshReaderLCT::IsExtensionSupported(ext)) << ext;
  }
  EXPECT_FALSE(vtkSkinnedMeshReaderLCT::IsExtensionSupported(nullptr));
}
