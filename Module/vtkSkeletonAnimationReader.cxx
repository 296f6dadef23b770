#include "vtkSkeletonAnimationReader.h"

#include "lct/BVHWriter.h"
#include "lct/Skeleton.h"

#include "vtkCellArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkStringArray.h"

#include "AssimpSampling.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSkeletonAnimationReader);

namespace
{
/// Bounds on what a file can make the reader allocate (3 10^7 transforms are 3.8 GB).
constexpr std::size_t kMaxJoints = 10000;
constexpr std::size_t kMaxTransforms = 30000000;

using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

struct Node
{
  const aiNode* node;
  int parent;
};

/// The skeleton of `animation` in `scene`, depth first: each tree of animated nodes from its
/// top-most animated node down, with every descendant.
std::vector<Node> skeletonNodes(
  const aiNode* root, const std::map<std::string, const aiNodeAnim*>& channels)
{
  std::vector<Node> nodes;
  // Iterative depth-first walk (a hostile file can nest deeply): (node, skeleton parent, inside).
  struct Visit
  {
    const aiNode* node;
    int parent;
    bool inside;
  };
  std::vector<Visit> stack{ { root, -1, false } };
  while (!stack.empty() && nodes.size() <= kMaxJoints)
  {
    const Visit v = stack.back();
    stack.pop_back();
    const bool animated = channels.count(v.node->mName.C_Str()) > 0;
    int index = v.parent;
    bool inside = v.inside;
    if (inside || animated)
    {
      nodes.push_back({ v.node, v.parent });
      index = static_cast<int>(nodes.size()) - 1;
      inside = true;
    }
    // Children pushed in reverse so that they come out in file order.
    for (unsigned c = v.node->mNumChildren; c-- > 0;)
    {
      if (v.node->mChildren[c])
      {
        stack.push_back({ v.node->mChildren[c], inside ? index : -1, inside });
      }
    }
  }
  return nodes;
}

/// The MOTION section of a BVH file (its first word HIERARCHY): the count its `Frames:` line
/// declares (as written) and the number of data rows after `Frame Time:`. False for another
/// file, or a BVH file without those lines (assimp reports that itself).
bool bvhMotionRows(const std::string& file, std::string& declared, long& rows)
{
  std::ifstream in(file);
  std::string word;
  if (!(in >> word) || word != "HIERARCHY")
  {
    return false;
  }
  std::string line;
  while (std::getline(in, line) && line.find("MOTION") == std::string::npos)
  {
  }
  bool timeLine = false;
  declared.clear();
  while (!timeLine && std::getline(in, line))
  {
    const std::size_t frames = line.find("Frames:");
    if (frames != std::string::npos)
    {
      std::istringstream(line.substr(frames + 7)) >> declared;
    }
    timeLine = line.find("Frame Time:") != std::string::npos;
  }
  if (!timeLine || declared.empty())
  {
    return false;
  }
  rows = 0;
  while (std::getline(in, line))
  {
    rows += line.find_first_not_of(" \t\r") != std::string::npos ? 1 : 0;
  }
  return true;
}
} // namespace

struct vtkSkeletonAnimationReader::Internals
{
  bool Loaded = false;
  std::string LoadedFile;
  vtkMTimeType LoadedMTime = 0;
  lct::SkeletalAnimation Animation;
  double StartTime = 0.0;
  std::vector<double> Times;
};

//------------------------------------------------------------------------------
vtkSkeletonAnimationReader::vtkSkeletonAnimationReader()
  : Internal(new Internals)
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkSkeletonAnimationReader::~vtkSkeletonAnimationReader()
{
  this->SetFileName(nullptr);
  delete this->Internal;
}

//------------------------------------------------------------------------------
bool vtkSkeletonAnimationReader::Load()
{
  Internals& in = *this->Internal;
  if (in.Loaded && in.LoadedMTime == this->GetMTime())
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
  Assimp::Importer importer;
  // No post-processing: the node hierarchy and the keys as the file has them.
  const aiScene* scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
  if (!scene || !scene->mRootNode)
  {
    vtkErrorMacro(<< file << ": not readable as an animation file: " << importer.GetErrorString());
    return false;
  }
  if (scene->mNumAnimations == 0 || !scene->mAnimations[0] ||
    scene->mAnimations[0]->mNumChannels == 0)
  {
    vtkErrorMacro(<< file << ": the file has no skeletal animation.");
    return false;
  }
  const aiAnimation& animation = *scene->mAnimations[0];
  std::map<std::string, const aiNodeAnim*> channels;
  unsigned frames = 0;
  const aiNodeAnim* longest = nullptr;
  for (unsigned c = 0; c < animation.mNumChannels; ++c)
  {
    const aiNodeAnim* channel = animation.mChannels[c];
    if (!channel)
    {
      continue;
    }
    channels[channel->mNodeName.C_Str()] = channel;
    const unsigned keys =
      std::max({ channel->mNumPositionKeys, channel->mNumRotationKeys, channel->mNumScalingKeys });
    if (keys > frames)
    {
      frames = keys;
      longest = channel;
    }
  }
  const std::vector<Node> nodes = skeletonNodes(scene->mRootNode, channels);
  if (nodes.empty() || frames == 0)
  {
    vtkErrorMacro(<< file << ": the animation's channels name no node of the file.");
    return false;
  }
  if (nodes.size() > kMaxJoints || static_cast<std::size_t>(frames) * nodes.size() > kMaxTransforms)
  {
    vtkErrorMacro(<< file << ": " << frames << " frames of " << nodes.size()
                  << " joints exceed the reader's limit (10000 joints, 3e7 transforms).");
    return false;
  }
  // Frame times: the key times of the channel with the most keys, in seconds. assimp gives 0
  // ticks per second for a format that has none (then 25, assimp's own default), but a BVH file
  // states its Frame Time (assimp: 1 / Frame Time ticks per second): one that is not positive
  // and finite (0, negative, NaN, beyond float) is an error, not 1/25 s.
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool statesFrameTime = extension == ".bvh";
  if (statesFrameTime &&
    !(animation.mTicksPerSecond > 0.0 && std::isfinite(animation.mTicksPerSecond)))
  {
    vtkErrorMacro(<< file << ": the Frame Time is not a positive number (assimp read "
                  << animation.mTicksPerSecond << " frames per second).");
    return false;
  }
  const double ticksPerSecond = animation.mTicksPerSecond > 0.0 ? animation.mTicksPerSecond : 25.0;
  std::vector<double> ticks(frames);
  for (unsigned f = 0; f < frames; ++f)
  {
    const double t = longest->mNumRotationKeys == frames ? longest->mRotationKeys[f].mTime
      : longest->mNumPositionKeys == frames              ? longest->mPositionKeys[f].mTime
                                                         : longest->mScalingKeys[f].mTime;
    ticks[f] = t;
  }
  for (unsigned f = 1; f < frames; ++f)
  {
    if (!(ticks[f] > ticks[f - 1]) || !std::isfinite(ticks[f]))
    {
      vtkErrorMacro(<< file << ": the key times are not increasing at key " << f << ".");
      return false;
    }
  }
  // BVH: the Frames: line gives the frame count (the format's rule, which assimp follows for
  // counts above 0). Rows after them are not read (some exporters write one more: Boxing_Toes)
  // and said so; a count the frames read do not match (Frames: 0 and a row, which assimp reads
  // as one frame) is an error rather than an animation the header denies.
  std::string declared;
  long rows = 0;
  if (bvhMotionRows(file, declared, rows))
  {
    if (std::strtod(declared.c_str(), nullptr) != static_cast<double>(frames))
    {
      vtkErrorMacro(<< file << ": its Frames: line says " << declared
                    << " but its MOTION section holds " << rows
                    << (rows == 1 ? " data row" : " data rows")
                    << ": the header is wrong; fix the Frames: line");
      in = Internals();
      return false;
    }
    if (rows > static_cast<long>(frames))
    {
      vtkWarningMacro(<< file << ": " << rows - static_cast<long>(frames)
                      << " data row(s) after the " << frames
                      << " its Frames: line declares are not read.");
    }
  }
  lct::SkeletalAnimation& a = in.Animation;
  a.frames = static_cast<int>(frames);
  a.frameTime = frames > 1 ? (ticks.back() - ticks.front()) / (frames - 1) / ticksPerSecond
                           : 1.0 / ticksPerSecond;
  if (!(a.frameTime > 0.0) || !std::isfinite(a.frameTime))
  {
    vtkErrorMacro(<< file << ": the frame time " << a.frameTime << " s is not positive and finite ("
                  << ticksPerSecond << " ticks per second).");
    in = Internals();
    return false;
  }
  for (const Node& n : nodes)
  {
    const bool animated = channels.count(n.node->mName.C_Str()) > 0;
    a.joints.push_back({ n.node->mName.C_Str(), n.parent, !animated && n.node->mNumChildren == 0 });
  }
  a.locals.resize(static_cast<std::size_t>(frames) * nodes.size());
  for (std::size_t j = 0; j < nodes.size(); ++j)
  {
    const Eigen::Matrix4d rest = lct_assimp::toEigen(nodes[j].node->mTransformation);
    const auto found = channels.find(nodes[j].node->mName.C_Str());
    const aiNodeAnim* channel = found == channels.end() ? nullptr : found->second;
    for (unsigned f = 0; f < frames; ++f)
    {
      Eigen::Matrix4d& local = a.locals[static_cast<std::size_t>(f) * nodes.size() + j];
      local = lct_assimp::sampleLocal(channel, rest, ticks[f]);
      if (!local.allFinite())
      {
        vtkErrorMacro(<< file << ": joint " << a.joints[j].name
                      << " has a non-finite value at frame " << f << ".");
        in = Internals();
        return false;
      }
    }
  }
  in.StartTime = ticks.front() / ticksPerSecond;
  in.Times.resize(frames);
  for (unsigned f = 0; f < frames; ++f)
  {
    in.Times[f] = ticks[f] / ticksPerSecond;
  }
  in.Loaded = true;
  in.LoadedFile = file;
  in.LoadedMTime = this->GetMTime();
  return true;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->Load())
  {
    return 0;
  }
  const std::vector<double>& times = this->Internal->Times;
  vtkInformation* info = outputVector->GetInformationObject(0);
  info->Set(
    vtkStreamingDemandDrivenPipeline::TIME_STEPS(), times.data(), static_cast<int>(times.size()));
  const double range[2] = { times.front(), times.back() };
  info->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  if (!this->Load())
  {
    return 0;
  }
  const Internals& in = *this->Internal;
  const lct::SkeletalAnimation& a = in.Animation;
  vtkInformation* info = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(info);
  int frame = 0;
  if (info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    const double t = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    if (std::isfinite(t))
    {
      const auto after = std::lower_bound(in.Times.begin(), in.Times.end(), t);
      frame = static_cast<int>(after - in.Times.begin());
      if (frame >= a.frames || (frame > 0 && t - in.Times[frame - 1] < in.Times[frame] - t))
      {
        frame = std::max(0, frame - 1);
      }
    }
  }
  std::vector<Eigen::Matrix4d> world;
  lct::worldTransforms(a, frame, world);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(a.jointCount());
  vtkNew<vtkCellArray> bones;
  vtkNew<vtkStringArray> names;
  names->SetName("JointName");
  vtkNew<vtkIntArray> ids, parents, depths;
  ids->SetName("JointId");
  parents->SetName("Parent");
  depths->SetName("Depth");
  for (int j = 0; j < a.jointCount(); ++j)
  {
    const Eigen::Vector3d p = world[static_cast<std::size_t>(j)].topRightCorner<3, 1>();
    points->SetPoint(j, p.data());
    const int parent = a.joints[static_cast<std::size_t>(j)].parent;
    if (parent >= 0)
    {
      const vtkIdType line[2] = { parent, j };
      bones->InsertNextCell(2, line);
    }
    names->InsertNextValue(a.joints[static_cast<std::size_t>(j)].name);
    ids->InsertNextValue(j);
    parents->InsertNextValue(parent);
    depths->InsertNextValue(a.depth(j));
  }
  output->SetPoints(points);
  output->SetLines(bones);
  output->GetPointData()->AddArray(names);
  output->GetPointData()->AddArray(ids);
  output->GetPointData()->AddArray(parents);
  output->GetPointData()->AddArray(depths);
  vtkNew<vtkIntArray> frameArray;
  frameArray->SetName("Frame");
  frameArray->InsertNextValue(frame);
  output->GetFieldData()->AddArray(frameArray);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), in.Times[frame]);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkSkeletonAnimationReader::Valid(int joint, int frame, const char* caller)
{
  const Internals& in = *this->Internal;
  if (!in.Loaded)
  {
    vtkErrorMacro(<< caller << ": no animation read (UpdateInformation() first).");
    return false;
  }
  if (joint < 0 || joint >= in.Animation.jointCount() || frame < 0 || frame >= in.Animation.frames)
  {
    vtkErrorMacro(<< caller << ": joint " << joint << ", frame " << frame << " is outside the "
                  << in.Animation.jointCount() << " joints x " << in.Animation.frames
                  << " frames.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::GetNumberOfJoints()
{
  return this->Internal->Loaded ? this->Internal->Animation.jointCount() : 0;
}

//------------------------------------------------------------------------------
const char* vtkSkeletonAnimationReader::GetJointName(int joint)
{
  return this->Valid(joint, 0, "GetJointName")
    ? this->Internal->Animation.joints[static_cast<std::size_t>(joint)].name.c_str()
    : nullptr;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::GetJointParent(int joint)
{
  return this->Valid(joint, 0, "GetJointParent")
    ? this->Internal->Animation.joints[static_cast<std::size_t>(joint)].parent
    : -1;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::IsEndSite(int joint)
{
  return this->Valid(joint, 0, "IsEndSite") &&
    this->Internal->Animation.joints[static_cast<std::size_t>(joint)].endSite;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::GetNumberOfFrames()
{
  return this->Internal->Loaded ? this->Internal->Animation.frames : 0;
}

//------------------------------------------------------------------------------
double vtkSkeletonAnimationReader::GetFrameTime()
{
  return this->Internal->Loaded ? this->Internal->Animation.frameTime : 0.0;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::GetLocalTransform(int joint, int frame, vtkMatrix4x4* result)
{
  if (!result)
  {
    vtkErrorMacro(<< "GetLocalTransform: null result matrix.");
    return 0;
  }
  if (!this->Valid(joint, frame, "GetLocalTransform"))
  {
    return 0;
  }
  const RowMajor4 rows = this->Internal->Animation.local(frame, joint);
  result->DeepCopy(rows.data());
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::GetWorldTransform(int joint, int frame, vtkMatrix4x4* result)
{
  if (!result)
  {
    vtkErrorMacro(<< "GetWorldTransform: null result matrix.");
    return 0;
  }
  if (!this->Valid(joint, frame, "GetWorldTransform"))
  {
    return 0;
  }
  const lct::SkeletalAnimation& a = this->Internal->Animation;
  Eigen::Matrix4d world = a.local(frame, joint);
  for (int p = a.joints[static_cast<std::size_t>(joint)].parent; p >= 0;
       p = a.joints[static_cast<std::size_t>(p)].parent)
  {
    world = a.local(frame, p) * world;
  }
  const RowMajor4 rows = world;
  result->DeepCopy(rows.data());
  return 1;
}

//------------------------------------------------------------------------------
int vtkSkeletonAnimationReader::WriteBVH(const char* fileName, const char* rotationOrder)
{
  if (!fileName || !*fileName || !rotationOrder)
  {
    vtkErrorMacro(<< "WriteBVH: " << (rotationOrder ? "no file name" : "no rotation order")
                  << "; nothing written.");
    return 0;
  }
  if (!this->Internal->Loaded)
  {
    vtkErrorMacro(<< "WriteBVH: no animation read (UpdateInformation() first); nothing written.");
    return 0;
  }
  const std::string target = fileName;
  const std::string temporary = target + ".part";
  std::string why;
  bool written = false;
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    written = out && lct::writeBVH(this->Internal->Animation, rotationOrder, out, &why);
    out.close();
    written = written && !out.fail();
    if (why.empty() && !written)
    {
      why = "cannot write " + temporary;
    }
  }
  if (!written || std::rename(temporary.c_str(), target.c_str()) != 0)
  {
    std::remove(temporary.c_str());
    vtkErrorMacro(<< "WriteBVH: " << target << ": "
                  << (written ? "cannot rename the temporary file into place" : why)
                  << "; nothing written.");
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
const lct::SkeletalAnimation* vtkSkeletonAnimationReader::GetAnimation()
{
  return this->Internal->Loaded ? &this->Internal->Animation : nullptr;
}

//------------------------------------------------------------------------------
void vtkSkeletonAnimationReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "Joints: " << this->GetNumberOfJoints() << "\n";
  os << indent << "Frames: " << this->GetNumberOfFrames() << "\n";
  os << indent << "FrameTime: " << this->GetFrameTime() << "\n";
}
