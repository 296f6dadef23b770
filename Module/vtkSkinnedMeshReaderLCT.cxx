#include "vtkSkinnedMeshReaderLCT.h"

#include "AssimpSampling.h"

#include "lct/Affine.h"
#include "lct/Conditioning.h"
#include "lct/Format.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkSmartPointer.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/SVD>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkSkinnedMeshReaderLCT);

namespace
{
// Bounds on what a file can make the reader allocate.
constexpr std::size_t kMaxVertices = 10000000;
constexpr std::size_t kMaxBones = 65536;
constexpr std::size_t kMaxInfluences = 32;

/// An assimp matrix as an affine map: files store the bottom row in float (X files write it out),
/// so one within float round-off of (0, 0, 0, 1) is taken as exactly that; false otherwise.
bool affineOf(const aiMatrix4x4& a, Eigen::Matrix4d& m)
{
  m = lct_assimp::toEigen(a);
  const Eigen::RowVector4d bottom = m.row(3);
  if ((bottom - Eigen::RowVector4d(0, 0, 0, 1)).cwiseAbs().maxCoeff() > 1e-5 || !m.allFinite())
  {
    return false;
  }
  m.row(3) = Eigen::RowVector4d(0, 0, 0, 1);
  return true;
}

/// Whether the linear part of an affine map can be inverted to working accuracy: its singular
/// values (at unit scale, so that only their ratio counts) within lct::kMaxConditionNumber of each
/// other, the limit the module puts on every linear part it inverts. A zero scale fails, and so
/// does a flattening too thin for double precision to undo; a reflection passes. `condition` is
/// sigma_max / sigma_min (Inf for a singular map).
bool invertible(const Eigen::Matrix4d& m, double& condition)
{
  condition = lct::linearConditionNumber(m);
  return condition <= lct::kMaxConditionNumber;
}

/// Why an affine map cannot be inverted (invertible() false), for an error message.
std::string notInvertible(double condition)
{
  std::ostringstream why;
  why << "is singular or too ill-conditioned to invert (condition number " << condition
      << ", the limit " << lct::kMaxConditionNumber << ")";
  return why.str();
}

/// Writes an affine map (the bottom row stored as exactly (0, 0, 0, 1): products of float-born
/// matrices can round it by an ulp).
void toVtk(const Eigen::Matrix4d& m, vtkMatrix4x4* out)
{
  out->Identity();
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      out->SetElement(i, j, m(i, j));
    }
  }
}

/// Why the keys of an animation channel cannot be sampled, or "": a value or time that is not
/// finite (it makes the node, and every bone below it, NaN about that key), or a zero quaternion
/// (it stands for no rotation at all; sampled, it silently came out as the identity).
std::string keyProblem(const aiNodeAnim& channel)
{
  const auto describe = [](const char* kind, unsigned k, double tick, const char* what) {
    return std::string(kind) + " key " + std::to_string(k) + " (tick " + lct::formatNumber(tick) +
      ") " + what;
  };
  const auto vectorProblem = [&describe](
                               const char* kind, const aiVectorKey* keys, unsigned count) {
    for (unsigned k = 0; k < count; ++k)
    {
      const aiVector3D& v = keys[k].mValue;
      if (!std::isfinite(keys[k].mTime) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
        !std::isfinite(v.z))
      {
        return describe(kind, k, keys[k].mTime, "is not finite");
      }
    }
    return std::string();
  };
  std::string problem = vectorProblem("position", channel.mPositionKeys, channel.mNumPositionKeys);
  for (unsigned k = 0; k < channel.mNumRotationKeys && problem.empty(); ++k)
  {
    const aiQuatKey& key = channel.mRotationKeys[k];
    const aiQuaternion& q = key.mValue;
    if (!std::isfinite(key.mTime) || !std::isfinite(q.w) || !std::isfinite(q.x) ||
      !std::isfinite(q.y) || !std::isfinite(q.z))
    {
      problem = describe("rotation", k, key.mTime, "is not finite");
    }
    else if (q.w == 0 && q.x == 0 && q.y == 0 && q.z == 0)
    {
      problem = describe("rotation", k, key.mTime, "is the zero quaternion, which is no rotation");
    }
  }
  return problem.empty() ? vectorProblem("scale", channel.mScalingKeys, channel.mNumScalingKeys)
                         : problem;
}

std::string lowerCase(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

} // namespace

struct vtkSkinnedMeshReaderLCT::Internals
{
  std::unique_ptr<Assimp::Importer> Importer;
  const aiScene* Scene = nullptr;
  std::string LoadedFile;
  vtkMTimeType LoadedMTime = 0;
  /// Every node in depth-first order with its parent's index (parents first).
  std::vector<std::pair<const aiNode*, int>> Nodes;
  std::map<std::string, const aiNodeAnim*> Channels;
  double TicksPerSecond = 25.0;
  double StartTime = 0.0, EndTime = 0.0;
  struct Bone
  {
    std::string Name;
    int Node = -1;
    Eigen::Matrix4d Rest;
  };
  std::vector<Bone> Bones;
  int Influences = 0;
  vtkSmartPointer<vtkPolyData> Mesh;
  /// Node world transforms at CachedTime.
  double CachedTime = -1.0;
  std::vector<Eigen::Matrix4d> CachedWorld;

  /// World transforms of every node with the animation sampled at `seconds` (or the nodes'
  /// own transforms, the bind pose, for a negative time).
  const std::vector<Eigen::Matrix4d>& World(double seconds)
  {
    if (!this->CachedWorld.empty() && seconds == this->CachedTime)
    {
      return this->CachedWorld;
    }
    this->CachedWorld.resize(this->Nodes.size());
    const double tick = seconds * this->TicksPerSecond;
    for (std::size_t i = 0; i < this->Nodes.size(); ++i)
    {
      const aiNode* node = this->Nodes[i].first;
      Eigen::Matrix4d rest;
      affineOf(node->mTransformation, rest); // validated by Load
      const auto found = this->Channels.find(node->mName.C_Str());
      const Eigen::Matrix4d local = (seconds < 0.0 || found == this->Channels.end())
        ? rest
        : lct_assimp::sampleLocal(found->second, rest, tick);
      const int parent = this->Nodes[i].second;
      this->CachedWorld[i] =
        parent < 0 ? local : Eigen::Matrix4d(this->CachedWorld[parent] * local);
    }
    this->CachedTime = seconds;
    return this->CachedWorld;
  }

  /// A bone's world matrix at `seconds` (clamped to the animation's range); false if it is not
  /// finite. Load checks every key, but finite keys at extreme magnitudes can still overflow when
  /// interpolated or multiplied down the node tree.
  bool Pose(int bone, double seconds, Eigen::Matrix4d& matrix)
  {
    const double t = std::min(std::max(seconds, this->StartTime), this->EndTime);
    const Bone& b = this->Bones[bone];
    matrix = b.Node < 0 ? b.Rest : this->World(t)[b.Node];
    return matrix.allFinite();
  }

  /// Why Pose() failed, for an error message.
  std::string NotFinite(int bone, double seconds) const
  {
    return "the matrix of bone " + std::to_string(bone) + " ('" + this->Bones[bone].Name +
      "') at time " + lct::formatNumber(seconds) +
      " is not finite (the animation's keys overflow when interpolated or multiplied down the "
      "node tree)";
  }
};

vtkSkinnedMeshReaderLCT::vtkSkinnedMeshReaderLCT()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
}

vtkSkinnedMeshReaderLCT::~vtkSkinnedMeshReaderLCT()
{
  this->SetFileName(nullptr);
}

std::string vtkSkinnedMeshReaderLCT::GetFileExtensions()
{
  std::string list; // "*.3ds;*.ac;..."
  Assimp::Importer().GetExtensionList(list);
  std::string out;
  std::size_t begin = 0;
  while (begin < list.size())
  {
    std::size_t end = list.find(';', begin);
    end = end == std::string::npos ? list.size() : end;
    std::string pattern = list.substr(begin, end - begin);
    if (pattern.compare(0, 1, "*") == 0)
    {
      pattern.erase(0, 1);
    }
    pattern = lowerCase(pattern);
    if (pattern.size() > 1 && pattern[0] == '.')
    {
      out += (out.empty() ? "" : " ") + pattern;
    }
    begin = end + 1;
  }
  return out;
}

bool vtkSkinnedMeshReaderLCT::IsExtensionSupported(const char* extension)
{
  if (!extension || !*extension)
  {
    return false;
  }
  const std::string wanted =
    lowerCase(extension[0] == '.' ? extension : std::string(".") + extension);
  const std::string all = " " + GetFileExtensions() + " ";
  return all.find(" " + wanted + " ") != std::string::npos;
}

bool vtkSkinnedMeshReaderLCT::Load()
{
  Internals& in = *this->Internal;
  if (in.Scene && in.LoadedMTime == this->GetMTime())
  {
    return true;
  }
  in = Internals();
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro(<< "no file name.");
    return false;
  }
  const std::string file = this->FileName;
  const std::string declared = lct_assimp::declaredCountProblem(file);
  if (!declared.empty())
  {
    vtkErrorMacro(<< file << ": not readable as a mesh file: " << declared);
    return false;
  }
  in.Importer.reset(new Assimp::Importer);
  const aiScene* scene =
    in.Importer->ReadFile(file, aiProcess_ValidateDataStructure | aiProcess_Triangulate);
  const auto fail = [&](const std::string& why) {
    vtkErrorMacro(<< file << ": " << why);
    in = Internals();
    return false;
  };
  if (!scene || !scene->mRootNode)
  {
    return fail(std::string("not readable as a mesh file: ") + in.Importer->GetErrorString());
  }
  if (scene->mNumMeshes == 0)
  {
    return fail("the file has no mesh.");
  }
  // The node tree, parents first (iterative: a hostile file can nest deeply).
  std::map<std::string, int> nodeByName;
  std::vector<std::pair<const aiNode*, int>> stack{ { scene->mRootNode, -1 } };
  std::vector<int> meshNode(scene->mNumMeshes, -1);
  while (!stack.empty())
  {
    const auto [node, parent] = stack.back();
    stack.pop_back();
    const int index = static_cast<int>(in.Nodes.size());
    Eigen::Matrix4d local;
    if (!affineOf(node->mTransformation, local))
    {
      return fail("node '" + std::string(node->mName.C_Str()) +
        "' has a transform that is not affine or not finite.");
    }
    // A zero scale flattens everything below the node: its normals need the inverse (NaN
    // otherwise), and a bone node's matrix would be singular.
    double condition = 0.0;
    if (!invertible(local, condition))
    {
      return fail("node '" + std::string(node->mName.C_Str()) + "' has a transform that " +
        notInvertible(condition) + ".");
    }
    in.Nodes.emplace_back(node, parent);
    nodeByName.emplace(node->mName.C_Str(), index);
    for (unsigned m = 0; m < node->mNumMeshes; ++m)
    {
      if (node->mMeshes[m] < scene->mNumMeshes && meshNode[node->mMeshes[m]] < 0)
      {
        meshNode[node->mMeshes[m]] = index;
      }
    }
    for (unsigned c = node->mNumChildren; c-- > 0;)
    {
      if (node->mChildren[c])
      {
        stack.emplace_back(node->mChildren[c], index);
      }
    }
    if (in.Nodes.size() > kMaxBones)
    {
      return fail("more than 65536 nodes.");
    }
  }
  if (scene->mNumAnimations > 0 && scene->mAnimations[0])
  {
    const aiAnimation& a = *scene->mAnimations[0];
    in.TicksPerSecond = a.mTicksPerSecond > 0.0 ? a.mTicksPerSecond : 25.0;
    for (unsigned c = 0; c < a.mNumChannels; ++c)
    {
      if (!a.mChannels[c])
      {
        continue;
      }
      const std::string problem = keyProblem(*a.mChannels[c]);
      if (!problem.empty())
      {
        return fail("the animation of node '" + std::string(a.mChannels[c]->mNodeName.C_Str()) +
          "': " + problem + "; nothing read.");
      }
      in.Channels[a.mChannels[c]->mNodeName.C_Str()] = a.mChannels[c];
    }
    in.EndTime =
      std::isfinite(a.mDuration) && a.mDuration > 0 ? a.mDuration / in.TicksPerSecond : 0.0;
  }
  const std::vector<Eigen::Matrix4d> bind = in.World(-1.0);

  // Meshes, placed by their nodes, and their bones.
  std::size_t vertices = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
  {
    vertices += scene->mMeshes[m] ? scene->mMeshes[m]->mNumVertices : 0;
  }
  if (vertices == 0 || vertices > kMaxVertices)
  {
    return fail(vertices ? "more than 10^7 vertices." : "the meshes have no vertices.");
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  bool allHaveNormals = true;
  std::vector<std::vector<std::pair<int, float>>> influences(vertices);
  vtkIdType offset = 0;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m)
  {
    const aiMesh* mesh = scene->mMeshes[m];
    if (!mesh || mesh->mNumVertices == 0)
    {
      continue;
    }
    const Eigen::Matrix4d place =
      meshNode[m] >= 0 ? bind[meshNode[m]] : Eigen::Matrix4d::Identity();
    const Eigen::Matrix3d normalMap = place.topLeftCorner<3, 3>().inverse().transpose();
    allHaveNormals = allHaveNormals && mesh->mNormals;
    for (unsigned v = 0; v < mesh->mNumVertices; ++v)
    {
      const Eigen::Vector4d p = place *
        Eigen::Vector4d(mesh->mVertices[v].x, mesh->mVertices[v].y, mesh->mVertices[v].z, 1.0);
      if (!p.allFinite())
      {
        return fail(
          "mesh " + std::to_string(m) + " vertex " + std::to_string(v) + " is not finite.");
      }
      points->InsertNextPoint(p[0], p[1], p[2]);
      if (mesh->mNormals)
      {
        const Eigen::Vector3d n = (normalMap *
          Eigen::Vector3d(mesh->mNormals[v].x, mesh->mNormals[v].y, mesh->mNormals[v].z))
                                    .normalized();
        normals->InsertNextTuple3(n[0], n[1], n[2]);
      }
    }
    for (unsigned f = 0; f < mesh->mNumFaces; ++f)
    {
      const aiFace& face = mesh->mFaces[f];
      if (face.mNumIndices != 3)
      {
        continue; // points and lines of a mesh: not part of the surface
      }
      vtkIdType ids[3];
      bool valid = true;
      for (int k = 0; k < 3; ++k)
      {
        valid = valid && face.mIndices[k] < mesh->mNumVertices;
        ids[k] = offset + face.mIndices[k];
      }
      if (!valid)
      {
        return fail("mesh " + std::to_string(m) + " face " + std::to_string(f) +
          " refers to a vertex it does not have.");
      }
      triangles->InsertNextCell(3, ids);
    }
    const auto addBone = [&](const std::string& name, int node, const Eigen::Matrix4d& rest) {
      in.Bones.push_back({ name, node, rest });
      return static_cast<int>(in.Bones.size()) - 1;
    };
    if (mesh->mNumBones == 0)
    {
      // A rigid mesh follows its node: one more bone of weight 1.
      const int node = meshNode[m] >= 0 ? meshNode[m] : 0;
      const int bone = addBone(in.Nodes[node].first->mName.C_Str(), node, place);
      for (unsigned v = 0; v < mesh->mNumVertices; ++v)
      {
        influences[offset + v].emplace_back(bone, 1.0f);
      }
    }
    for (unsigned b = 0; b < mesh->mNumBones; ++b)
    {
      const aiBone* bone = mesh->mBones[b];
      const auto node = bone ? nodeByName.find(bone->mName.C_Str()) : nodeByName.end();
      if (!bone)
      {
        return fail("mesh " + std::to_string(m) + " bone " + std::to_string(b) + " is missing.");
      }
      if (node == nodeByName.end())
      {
        // Nothing animates such a bone (anim_test.x has one): it keeps its vertices in place.
        vtkWarningMacro(<< file << ": bone '" << bone->mName.C_Str() << "' of mesh " << m
                        << " names no node of the file; its vertices stay in the bind pose.");
      }
      // The bone at bind time: the mesh's placement times the inverse of the offset matrix (which
      // maps mesh space to bone space in the bind pose).
      // The same checks as for node transforms: a projective offset matrix lost its bottom row
      // when written out as the bone's (affine) rest matrix.
      Eigen::Matrix4d offsetMatrix;
      if (!affineOf(bone->mOffsetMatrix, offsetMatrix))
      {
        const aiMatrix4x4& o = bone->mOffsetMatrix;
        std::ostringstream why;
        why << "the offset (inverse bind) matrix of bone '" << bone->mName.C_Str()
            << "' is not affine (bottom row " << o.d1 << " " << o.d2 << " " << o.d3 << " " << o.d4
            << ", not 0 0 0 1) or not finite.";
        return fail(why.str());
      }
      double condition = 0.0;
      if (!invertible(offsetMatrix, condition))
      {
        return fail("the offset (inverse bind) matrix of bone '" +
          std::string(bone->mName.C_Str()) + "' " + notInvertible(condition) + ".");
      }
      const Eigen::Matrix4d rest = place * lct::inverseAffine(offsetMatrix);
      if (!rest.allFinite())
      {
        return fail("the rest matrix of bone '" + std::string(bone->mName.C_Str()) +
          "' (its mesh's placement times the inverse of its offset matrix) is not finite.");
      }
      const int index =
        addBone(bone->mName.C_Str(), node == nodeByName.end() ? -1 : node->second, rest);
      for (unsigned w = 0; w < bone->mNumWeights; ++w)
      {
        const aiVertexWeight& vw = bone->mWeights[w];
        if (vw.mVertexId >= mesh->mNumVertices || !std::isfinite(vw.mWeight))
        {
          return fail("bone '" + std::string(bone->mName.C_Str()) + "' has a weight for vertex " +
            std::to_string(vw.mVertexId) + " that is out of range or not finite.");
        }
        if (vw.mWeight != 0.0f)
        {
          influences[offset + vw.mVertexId].emplace_back(index, vw.mWeight);
        }
      }
    }
    if (in.Bones.size() > kMaxBones)
    {
      return fail("more than 65536 bones.");
    }
    offset += mesh->mNumVertices;
  }
  std::size_t k = 1;
  for (const auto& row : influences)
  {
    k = std::max(k, row.size());
  }
  if (k > kMaxInfluences)
  {
    return fail("a vertex with more than 32 bones.");
  }
  in.Influences = static_cast<int>(k);
  vtkNew<vtkFloatArray> weights;
  weights->SetName("BoneWeights");
  weights->SetNumberOfComponents(in.Influences);
  weights->SetNumberOfTuples(static_cast<vtkIdType>(vertices));
  vtkNew<vtkIntArray> indices;
  indices->SetName("BoneIndices");
  indices->SetNumberOfComponents(in.Influences);
  indices->SetNumberOfTuples(static_cast<vtkIdType>(vertices));
  for (std::size_t v = 0; v < vertices; ++v)
  {
    for (std::size_t s = 0; s < k; ++s)
    {
      const bool used = s < influences[v].size();
      weights->SetTypedComponent(
        static_cast<vtkIdType>(v), static_cast<int>(s), used ? influences[v][s].second : 0.0f);
      indices->SetTypedComponent(
        static_cast<vtkIdType>(v), static_cast<int>(s), used ? influences[v][s].first : 0);
    }
  }
  in.Mesh = vtkSmartPointer<vtkPolyData>::New();
  in.Mesh->SetPoints(points);
  in.Mesh->SetPolys(triangles);
  in.Mesh->GetPointData()->AddArray(weights);
  in.Mesh->GetPointData()->AddArray(indices);
  if (allHaveNormals)
  {
    in.Mesh->GetPointData()->SetNormals(normals);
  }
  in.Scene = scene;
  in.LoadedFile = file;
  in.LoadedMTime = this->GetMTime();
  return true;
}

int vtkSkinnedMeshReaderLCT::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!this->Load())
  {
    output->Initialize();
    return 0;
  }
  output->ShallowCopy(this->Internal->Mesh);
  return 1;
}

bool vtkSkinnedMeshReaderLCT::Ready(const char* caller)
{
  if (!this->Internal->Scene)
  {
    vtkErrorMacro(<< caller << ": nothing read yet (Update() first)");
    return false;
  }
  return true;
}

int vtkSkinnedMeshReaderLCT::GetNumberOfBones()
{
  return static_cast<int>(this->Internal->Bones.size());
}

const char* vtkSkinnedMeshReaderLCT::GetBoneName(int bone)
{
  return (bone >= 0 && bone < this->GetNumberOfBones()) ? this->Internal->Bones[bone].Name.c_str()
                                                        : nullptr;
}

int vtkSkinnedMeshReaderLCT::GetMaximumInfluences()
{
  return this->Internal->Influences;
}

double vtkSkinnedMeshReaderLCT::GetStartTime()
{
  return this->Internal->StartTime;
}

double vtkSkinnedMeshReaderLCT::GetEndTime()
{
  return this->Internal->EndTime;
}

int vtkSkinnedMeshReaderLCT::GetBoneRestMatrix(int bone, vtkMatrix4x4* result)
{
  if (!this->Ready("GetBoneRestMatrix"))
  {
    return 0;
  }
  if (!result)
  {
    vtkErrorMacro(<< "GetBoneRestMatrix: the result matrix is null; nothing written.");
    return 0;
  }
  if (bone < 0 || bone >= this->GetNumberOfBones())
  {
    vtkErrorMacro(<< "GetBoneRestMatrix: bone " << bone << " is outside [0, "
                  << this->GetNumberOfBones() << "); result unchanged.");
    return 0;
  }
  toVtk(this->Internal->Bones[bone].Rest, result);
  return 1;
}

int vtkSkinnedMeshReaderLCT::GetBoneMatrix(int bone, double time, vtkMatrix4x4* result)
{
  if (!this->Ready("GetBoneMatrix"))
  {
    return 0;
  }
  if (!result)
  {
    vtkErrorMacro(<< "GetBoneMatrix: the result matrix is null; nothing written.");
    return 0;
  }
  if (bone < 0 || bone >= this->GetNumberOfBones())
  {
    vtkErrorMacro(<< "GetBoneMatrix: bone " << bone << " is outside [0, "
                  << this->GetNumberOfBones() << "); result unchanged.");
    return 0;
  }
  if (!std::isfinite(time))
  {
    vtkErrorMacro(<< "GetBoneMatrix: the time " << lct::formatNumber(time)
                  << " is not finite; result unchanged.");
    return 0;
  }
  Eigen::Matrix4d matrix;
  if (!this->Internal->Pose(bone, time, matrix))
  {
    vtkErrorMacro(<< "GetBoneMatrix: " << this->Internal->NotFinite(bone, time)
                  << "; result unchanged.");
    return 0;
  }
  toVtk(matrix, result);
  return 1;
}

int vtkSkinnedMeshReaderLCT::ConfigureDeformer(vtkProbeDeformerLCT* deformer, double time)
{
  if (!deformer)
  {
    vtkErrorMacro(<< "ConfigureDeformer: the deformer is null; nothing configured.");
    return 0;
  }
  if (!this->Ready("ConfigureDeformer"))
  {
    return 0;
  }
  if (!std::isfinite(time))
  {
    vtkErrorMacro(<< "ConfigureDeformer: the time " << lct::formatNumber(time)
                  << " is not finite; the deformer is unchanged.");
    return 0;
  }
  const int n = this->GetNumberOfBones();
  // Every bone posed before the deformer is touched: one that cannot be leaves it as it was.
  std::vector<Eigen::Matrix4d> poses(static_cast<std::size_t>(n));
  for (int b = 0; b < n; ++b)
  {
    if (!this->Internal->Pose(b, time, poses[b]))
    {
      vtkErrorMacro(<< "ConfigureDeformer: " << this->Internal->NotFinite(b, time)
                    << "; the deformer is unchanged.");
      return 0;
    }
  }
  const bool same = deformer->GetNumberOfProbes() == n;
  if (!same)
  {
    deformer->RemoveAllProbes();
  }
  for (int b = 0; b < n; ++b)
  {
    // Matrices of this deformer's own: one set kept by the reader and handed to every deformer
    // made configuring a second deformer at another time move the first one too.
    vtkNew<vtkMatrix4x4> current;
    vtkNew<vtkMatrix4x4> rest;
    toVtk(poses[b], current);
    this->GetBoneRestMatrix(b, rest);
    if (same)
    {
      deformer->SetProbe(b, current, rest);
    }
    else
    {
      deformer->AddProbe(current, rest);
    }
  }
  deformer->SetWeightModeToPointData();
  deformer->SetWeightArrayName("BoneWeights");
  deformer->SetTransformIndexArrayName("BoneIndices");
  deformer->SetNormalizationToLinear();
  return 1;
}

void vtkSkinnedMeshReaderLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "NumberOfBones: " << this->GetNumberOfBones() << "\n";
  os << indent << "MaximumInfluences: " << this->Internal->Influences << "\n";
  os << indent << "TimeRange: " << this->Internal->StartTime << " .. " << this->Internal->EndTime
     << "\n";
}
