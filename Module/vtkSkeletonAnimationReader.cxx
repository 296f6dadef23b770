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
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSkeletonAnimationReader);

namespace
{
/// Bounds on what a file can make the reader allocate (3 10^7 transforms are 3.8 GB).
constexpr std::size_t kMaxJoints = 10000;
constexpr std::size_t kMaxTransforms = 30000000;
/// Key times within this fraction of a step of an even grid are evenly spaced: a key missing or
/// added moves them half a step from it, float32 key times (glTF) far less.
constexpr double kEvenKeysTolerance = 1e-2;

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

/// BVH rotation values beyond this many degrees are refused: assimp turns degrees into radians in
/// float32, which at 10^4 degrees is off by up to 1.5e-3 degrees (2.6e-5 rad), in proportion
/// beyond (2e-3 degrees at 100000.5, an arbitrary angle at 1e10).
constexpr double kMaxRotationDegrees = 1e4;

/// What the reader checks in the text of a BVH file that assimp does not.
struct BVHText
{
  struct Joint
  {
    std::string name;
    long line = 0;          ///< of its ROOT or JOINT keyword
    int channels = 0;       ///< its CHANNELS counts (assimp appends every CHANNELS line's)
    bool positions = false; ///< an Xposition, Yposition or Zposition among them
    std::vector<std::string> channelNames; ///< in order
  };
  std::vector<Joint> joints;  ///< every ROOT and JOINT in file order: assimp's channel order
  long endSites = 0;          ///< End Site blocks (joints of the skeleton too)
  long channels = 0;          ///< values per frame (the sum of the CHANNELS counts)
  std::string problem;        ///< why the MOTION section cannot be read ("": it can)
  bool byteOrderMark = false; ///< the file starts with UTF-8's EF BB BF (Windows editors)
  std::string declared;       ///< the count the Frames: line declares, as written
  std::string frameTime;      ///< the Frame Time: value, as written
  long rows = 0;              ///< data rows (lines holding values) after the Frame Time: value
  long badLine = 0;           ///< the first data row without `channels` values (0: none)
  long badValues = 0;         ///< and its number of values
  /// The first rotation value assimp reads beyond kMaxRotationDegrees (line 0: none).
  struct
  {
    long line = 0;
    long frame = 0;
    std::string joint, channel, value;
  } bigRotation;
};

/// A number as assimp's fast_atoreal_move reads it (it takes a decimal comma for a point), NaN
/// for a token that is not one.
double bvhNumber(std::string token)
{
  const std::size_t comma = token.find(',');
  if (comma != std::string::npos && comma + 1 < token.size() &&
    std::isdigit(static_cast<unsigned char>(token[comma + 1])))
  {
    token[comma] = '.';
  }
  char* end = nullptr;
  const double value = std::strtod(token.c_str(), &end);
  return !token.empty() && *end == '\0' ? value : std::numeric_limits<double>::quiet_NaN();
}

/// The tokens of a BVH file as assimp's BVHLoader::GetNextToken cuts them: white space (CR and
/// tab included) separates them, wherever the lines end, and a token starting with a brace is
/// that brace alone. Lines, for the messages, end at LF, CR LF or a lone CR.
class BVHTokens
{
public:
  explicit BVHTokens(std::istream& in)
    : Buffer(in.rdbuf())
  {
  }

  /// The next token ("" at the end of the file) and its line.
  std::string Next(long& line)
  {
    using Traits = std::streambuf::traits_type;
    std::string token;
    int c = Traits::eof();
    while (this->Buffer && (c = this->Buffer->sgetc()) != Traits::eof() && std::isspace(c))
    {
      this->Buffer->sbumpc();
      if (c == '\n' || (c == '\r' && this->Buffer->sgetc() != '\n'))
      {
        ++this->Line;
      }
    }
    line = this->Line;
    while (this->Buffer && (c = this->Buffer->sgetc()) != Traits::eof() && !std::isspace(c))
    {
      token.push_back(Traits::to_char_type(c));
      this->Buffer->sbumpc();
      if (token == "{" || token == "}")
      {
        break;
      }
    }
    return token;
  }

private:
  std::streambuf* Buffer;
  long Line = 1;
};

/// Scans a BVH file, token by token as assimp reads it: the joints' channels, the MOTION
/// section's Frames: count and Frame Time:, and the data rows (the values of each line). False
/// for another file (its first token is not HIERARCHY); for a BVH file, true, with
/// `text.problem` saying why it cannot be read when it cannot: every later check relies on the
/// scan, so a BVH file it cannot follow is refused, never taken for another format.
bool scanBVH(const std::string& file, BVHText& text)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    return false;
  }
  // A UTF-8 byte-order mark before HIERARCHY: the text is BVH all the same.
  char mark[3] = {};
  text.byteOrderMark =
    in.read(mark, 3) && mark[0] == '\xEF' && mark[1] == '\xBB' && mark[2] == '\xBF';
  in.clear();
  in.seekg(text.byteOrderMark ? 3 : 0);
  BVHTokens tokens(in);
  long line = 0;
  if (tokens.Next(line) != "HIERARCHY")
  {
    return false;
  }
  // The joint each open brace belongs to (-1: an End Site), so that a CHANNELS line after a
  // child's block still counts for its own joint, as in assimp.
  std::vector<int> open;
  int named = -1;
  std::string token;
  for (token = tokens.Next(line); !token.empty() && token != "MOTION"; token = tokens.Next(line))
  {
    if (token == "ROOT" || token == "JOINT")
    {
      const long keywordLine = line;
      BVHText::Joint joint;
      joint.name = tokens.Next(line);
      joint.line = keywordLine;
      text.joints.push_back(joint);
      named = static_cast<int>(text.joints.size()) - 1;
    }
    else if (token == "End")
    {
      ++text.endSites;
      named = -1;
    }
    else if (token == "{")
    {
      open.push_back(named);
      named = -1;
    }
    else if (token == "}")
    {
      if (!open.empty())
      {
        open.pop_back();
      }
    }
    else if (token == "CHANNELS")
    {
      // assimp reads the count as a float and truncates it.
      const double count = bvhNumber(tokens.Next(line));
      const int channels = count >= 1.0 && count < 1e6 ? static_cast<int>(count) : 0;
      BVHText::Joint* joint = !open.empty() && open.back() >= 0
        ? &text.joints[static_cast<std::size_t>(open.back())]
        : nullptr;
      text.channels += channels;
      if (joint)
      {
        joint->channels += channels;
      }
      for (int c = 0; c < channels; ++c)
      {
        const std::string channel = tokens.Next(line);
        if (channel.empty())
        {
          break;
        }
        if (joint)
        {
          joint->channelNames.push_back(channel);
          joint->positions = joint->positions || channel == "Xposition" || channel == "Yposition" ||
            channel == "Zposition";
        }
      }
    }
  }
  if (token.empty())
  {
    text.problem = "its HIERARCHY is not followed by a MOTION section (the file ends at line " +
      std::to_string(line) + ")";
    return true;
  }
  const auto quoted = [](const std::string& t) -> std::string {
    return t.empty() ? "the end of the file" : '"' + t + '"';
  };
  // assimp reads "Frames:", a count, "Frame", "Time:" and a value, in that order, as tokens.
  const long motionLine = line;
  token = tokens.Next(line);
  if (token != "Frames:")
  {
    text.problem = "its MOTION keyword (line " + std::to_string(motionLine) + ") is followed by " +
      quoted(token) + ", not by \"Frames:\" and the frame count";
    return true;
  }
  const long framesLine = line;
  text.declared = tokens.Next(line);
  if (text.declared.empty())
  {
    text.problem = "its Frames: line (line " + std::to_string(framesLine) +
      ") is followed by the end of the file";
    return true;
  }
  // assimp converts the count to unsigned and reserves memory for it before reading a row:
  // -1 and 1e12 frames ended in std::bad_alloc.
  const double count = bvhNumber(text.declared);
  const std::size_t joints = text.joints.size() + static_cast<std::size_t>(text.endSites);
  if (!(count >= 0.0 && count == std::floor(count)))
  {
    text.problem = "its Frames: line (line " + std::to_string(framesLine) + ") says " +
      text.declared + ", not a whole number of frames (0 or more)";
    return true;
  }
  if (count * static_cast<double>(std::max<std::size_t>(joints, 1)) >
    static_cast<double>(kMaxTransforms))
  {
    text.problem = "its Frames: line (line " + std::to_string(framesLine) + ") declares " +
      text.declared + " frames of " + std::to_string(joints) +
      " joints (End Sites included), beyond the reader's limit (10000 joints, 3e7 transforms)";
    return true;
  }
  const long countLine = line;
  const std::string frame = tokens.Next(line), time = tokens.Next(line);
  if (frame != "Frame" || time != "Time:")
  {
    text.problem = "its Frames: count (line " + std::to_string(countLine) + ") is followed by " +
      quoted(time.empty() ? frame : frame + " " + time) +
      ", not by \"Frame Time:\" and the frame time";
    return true;
  }
  const long timeLine = line;
  text.frameTime = tokens.Next(line);
  if (text.frameTime.empty())
  {
    text.problem =
      "its Frame Time: (line " + std::to_string(timeLine) + ") is followed by the end of the file";
    return true;
  }
  // The data rows: assimp reads count x channels values regardless of lines, frame by frame and
  // in each frame joint by joint in file order; a line is a row for the checks.
  std::vector<std::pair<std::size_t, std::size_t>> slots; // (joint, its channel) of each value
  for (std::size_t j = 0; j < text.joints.size(); ++j)
  {
    for (std::size_t c = 0; c < text.joints[j].channelNames.size(); ++c)
    {
      slots.emplace_back(j, c);
    }
  }
  const std::uint64_t channels = static_cast<std::uint64_t>(text.channels);
  const bool mapped = channels > 0 && slots.size() == channels;
  // Within the limit checked above: exact.
  const std::uint64_t read = static_cast<std::uint64_t>(count) * channels;
  const auto endRow = [&text](long rowLine, long values) {
    if (values > 0 && values != text.channels && text.badLine == 0)
    {
      text.badLine = rowLine;
      text.badValues = values;
    }
  };
  long rowLine = 0, values = 0;
  std::uint64_t index = 0; // of the value, among all
  for (token = tokens.Next(line); !token.empty(); token = tokens.Next(line), ++index)
  {
    if (line != rowLine)
    {
      endRow(rowLine, values);
      rowLine = line;
      values = 0;
      ++text.rows;
    }
    ++values;
    if (mapped && index < read && text.bigRotation.line == 0)
    {
      const auto& slot = slots[static_cast<std::size_t>(index % channels)];
      const BVHText::Joint& joint = text.joints[slot.first];
      const std::string& channel = joint.channelNames[slot.second];
      if ((channel == "Xrotation" || channel == "Yrotation" || channel == "Zrotation") &&
        std::abs(bvhNumber(token)) > kMaxRotationDegrees)
      {
        text.bigRotation.line = line;
        text.bigRotation.frame = static_cast<long>(index / channels);
        text.bigRotation.joint = joint.name;
        text.bigRotation.channel = channel;
        text.bigRotation.value = token;
      }
    }
  }
  endRow(rowLine, values);
  return true;
}

/// Whether a BVH Frame Time, as written, is a positive number outside float's normal range:
/// assimp parses it as float32 and reads 0 or Inf (or a subnormal that keeps few digits), then
/// 1 / that frames per second.
bool isBeyondFloat(const std::string& text)
{
  errno = 0;
  const double value = std::strtod(text.c_str(), nullptr);
  // 1e-400 underflows double too: strtod gives 0 with ERANGE.
  const bool positive =
    value > 0.0 || (value == 0.0 && errno == ERANGE && !text.empty() && text[0] != '-');
  return positive &&
    !(value >= static_cast<double>(std::numeric_limits<float>::min()) &&
      value <= static_cast<double>(std::numeric_limits<float>::max()));
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
  const std::string declared = lct_assimp::declaredCountProblem(file);
  if (!declared.empty())
  {
    vtkErrorMacro(<< file << ": not readable as an animation file: " << declared);
    return false;
  }
  // Before assimp, which reserves memory for a BVH file's Frames: count.
  BVHText bvh;
  const bool isBVH = scanBVH(file, bvh);
  if (isBVH && !bvh.problem.empty())
  {
    vtkErrorMacro(<< file << ": not readable as an animation file: " << bvh.problem
                  << "; nothing read.");
    return false;
  }
  Assimp::Importer importer;
  // No post-processing: the node hierarchy and the keys as the file has them. assimp's BVH
  // loader takes a byte-order mark for the first token ("Expected header string HIERARCHY"), so
  // such a file is handed over without it.
  const aiScene* scene = nullptr;
  if (isBVH && bvh.byteOrderMark)
  {
    std::ifstream in(file, std::ios::binary);
    in.seekg(3);
    const std::string text{ std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>() };
    scene =
      importer.ReadFileFromMemory(text.data(), text.size(), aiProcess_ValidateDataStructure, "bvh");
  }
  else
  {
    scene = importer.ReadFile(file, aiProcess_ValidateDataStructure);
  }
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
  // Frame times: the key times of the channel with the most keys, in seconds (extended below
  // when other channels reach beyond them). assimp gives 0 ticks per second for a format that
  // has none (then 25, assimp's own default), but a BVH file states its Frame Time (assimp:
  // 1 / Frame Time ticks per second): one that is not positive and finite (0, negative, NaN,
  // beyond float) is an error, not 1/25 s.
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  const bool statesFrameTime = extension == ".bvh";
  if (isBVH && isBeyondFloat(bvh.frameTime))
  {
    vtkErrorMacro(<< file << ": its Frame Time, " << bvh.frameTime
                  << ", is outside float's normal range (about 1.2e-38 to 3.4e+38 s), in which "
                     "assimp reads it (as 0, Inf or a subnormal that keeps few digits); nothing "
                     "read.");
    return false;
  }
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
  // BVH: what assimp 5.2 reads differently from the text. Its channels are the file's ROOT and
  // JOINT blocks in file order; a joint with 6 channels gets the position channels *instead of*
  // its OFFSET (BVH, and Testing/Unit/BVHOracle.h, add them: the OFFSET is added back below),
  // and a joint with position channels among another number of channels loses them (refused:
  // its motion cannot be recovered from what assimp read).
  std::set<const aiNodeAnim*> addOffset;
  if (isBVH)
  {
    if (bvh.joints.size() != animation.mNumChannels)
    {
      vtkErrorMacro(<< file << ": its HIERARCHY holds " << bvh.joints.size()
                    << " ROOT and JOINT blocks but assimp read " << animation.mNumChannels
                    << " animated joints: the file is not read as it is written.");
      in = Internals();
      return false;
    }
    for (unsigned c = 0; c < animation.mNumChannels; ++c)
    {
      const BVHText::Joint& joint = bvh.joints[c];
      if (joint.positions && joint.channels != 6)
      {
        vtkErrorMacro(<< file << ": joint " << joint.name << " (line " << joint.line << ") has "
                      << joint.channels
                      << " channels with position channels among them: assimp reads position "
                         "channels only on joints with 6 channels and drops these; give the "
                         "joint 6 channels (3 positions, 3 rotations).");
        in = Internals();
        return false;
      }
      if (joint.channels == 6 && animation.mChannels[c])
      {
        addOffset.insert(animation.mChannels[c]);
      }
    }
    // assimp reads values, not lines: a row with one value too many or too few shifts every
    // later frame without a word. BVH has one frame per line.
    if (bvh.badLine > 0)
    {
      vtkErrorMacro(<< file << ": line " << bvh.badLine << " of its MOTION section holds "
                    << bvh.badValues << (bvh.badValues == 1 ? " value" : " values")
                    << " but the HIERARCHY's CHANNELS give " << bvh.channels
                    << " per frame (one frame per line): the frames after it would be shifted.");
      in = Internals();
      return false;
    }
    if (bvh.bigRotation.line > 0)
    {
      vtkErrorMacro(<< file << ": joint " << bvh.bigRotation.joint << "'s "
                    << bvh.bigRotation.channel << " channel is " << bvh.bigRotation.value
                    << " degrees at frame " << bvh.bigRotation.frame << " (line "
                    << bvh.bigRotation.line << "), beyond +-" << kMaxRotationDegrees
                    << ": assimp converts degrees to radians in float32, which loses such an "
                       "angle (an arbitrary rotation at 1e10); nothing read.");
      in = Internals();
      return false;
    }
    // The Frames: line gives the frame count (the format's rule, which assimp follows for counts
    // above 0). Rows after them are not read (some exporters write one more: Boxing_Toes) and
    // said so; a count the frames read do not match (Frames: 0 and a row, which assimp reads as
    // one frame) is an error rather than an animation the header denies.
    if (bvh.rows == 0)
    {
      // assimp reads a MOTION section without rows as one frame too: compared with that frame,
      // a Frames: 0 line was blamed for the motion the file lacks.
      vtkErrorMacro(<< file << ": its MOTION section holds no data rows (its Frames: line says "
                    << bvh.declared
                    << "): the file has no motion data, and an animation needs at least one "
                       "frame; nothing read.");
      in = Internals();
      return false;
    }
    if (bvhNumber(bvh.declared) != static_cast<double>(frames))
    {
      vtkErrorMacro(<< file << ": its Frames: line says " << bvh.declared
                    << " but its MOTION section holds " << bvh.rows
                    << (bvh.rows == 1 ? " data row" : " data rows")
                    << ": the header is wrong; fix the Frames: line");
      in = Internals();
      return false;
    }
    if (bvh.rows > static_cast<long>(frames))
    {
      vtkWarningMacro(<< file << ": " << bvh.rows - static_cast<long>(frames)
                      << " data row(s) after the " << frames
                      << " its Frames: line declares are not read.");
    }
  }
  else if (frames > 1 && !statesFrameTime)
  {
    // Other formats: channels keyed at different times. The frames cover the whole animation,
    // every channel's keys and the animation's duration (a channel with few keys can span more
    // than the one with the most: it was cut at the latter's last key), at that channel's rate
    // or finer, evenly spaced. That channel's keys are no frames when unevenly spaced (1/24 s
    // to 23/24 s, then 4.2 s): the frame time would not be their spacing, and the other
    // channels' keys between them were never sampled. The whole span is then resampled at
    // their finest spacing.
    double first = ticks.front(), last = ticks.back();
    const auto span = [&first, &last](const auto* keys, unsigned count) {
      if (keys && count > 0)
      {
        first = std::min(first, keys[0].mTime);
        last = std::max(last, keys[count - 1].mTime);
      }
    };
    for (const auto& named : channels)
    {
      const aiNodeAnim* channel = named.second;
      span(channel->mPositionKeys, channel->mNumPositionKeys);
      span(channel->mRotationKeys, channel->mNumRotationKeys);
      span(channel->mScalingKeys, channel->mNumScalingKeys);
    }
    if (std::isfinite(animation.mDuration))
    {
      last = std::max(last, animation.mDuration);
    }
    double step = (ticks.back() - ticks.front()) / (frames - 1);
    const bool beyond = first < ticks.front() - 1e-6 * step || last > ticks.back() + 1e-6 * step;
    bool even = true;
    double finest = step;
    for (unsigned f = 1; f < frames; ++f)
    {
      if (ticks[f] > ticks[f - 1]) // two keys at one time have no spacing to resample at
      {
        finest = std::min(finest, ticks[f] - ticks[f - 1]);
      }
      even = even && std::abs(ticks[f] - (ticks.front() + f * step)) <= kEvenKeysTolerance * step;
    }
    if (!even)
    {
      step = finest;
    }
    if (beyond || !even)
    {
      if (!std::isfinite(first) || !std::isfinite(last))
      {
        vtkErrorMacro(<< file << ": the key times are not finite.");
        in = Internals();
        return false;
      }
      const double count = std::ceil((last - first) / step - 1e-6) + 1.0;
      if (!(count * static_cast<double>(nodes.size()) <= static_cast<double>(kMaxTransforms)))
      {
        if (even)
        {
          vtkErrorMacro(<< file << ": " << count << " frames of " << nodes.size()
                        << " joints exceed the reader's limit (10000 joints, 3e7 transforms).");
        }
        else
        {
          vtkErrorMacro(<< file << ": " << count << " frames of " << nodes.size()
                        << " joints exceed the reader's limit (10000 joints, 3e7 transforms): "
                           "its keys are unevenly spaced, and the frames resample them at "
                           "their finest spacing, "
                        << step / ticksPerSecond << " s.");
        }
        in = Internals();
        return false;
      }
      frames = static_cast<unsigned>(count);
      ticks.resize(frames);
      for (unsigned f = 0; f < frames; ++f)
      {
        ticks[f] = f + 1 == frames ? last : first + (last - first) * f / (frames - 1);
      }
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
    // A BVH joint with 6 channels: its OFFSET (assimp's node transform) plus the channels.
    const Eigen::Vector3d offset = addOffset.count(channel) > 0
      ? Eigen::Vector3d(rest.topRightCorner<3, 1>())
      : Eigen::Vector3d::Zero();
    for (unsigned f = 0; f < frames; ++f)
    {
      Eigen::Matrix4d& local = a.locals[static_cast<std::size_t>(f) * nodes.size() + j];
      local = lct_assimp::sampleLocal(channel, rest, ticks[f]);
      local.topRightCorner<3, 1>() += offset;
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
  vtkInformation* info = outputVector->GetInformationObject(0);
  if (!this->Load())
  {
    // RequestData does not run after this failure: the previous file's time steps and skeleton
    // stayed, as if still read.
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    info->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
    if (vtkPolyData* output = vtkPolyData::GetData(info))
    {
      output->Initialize();
    }
    return 0;
  }
  const std::vector<double>& times = this->Internal->Times;
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
    // +-Inf are times beyond the range like any other (the last or first frame); NaN is none.
    if (!std::isnan(t))
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
