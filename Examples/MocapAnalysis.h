// The parts of lct-mocap that are not argument handling: a clip with what the reader does not
// keep (the BVH channel order and count), tolerances, and `analyse`.
#ifndef lct_MocapAnalysis_h
#define lct_MocapAnalysis_h

#include "lct/MotionCodec.h"
#include "lct/MotionError.h"
#include "lct/Skeleton.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace lct_mocap
{

struct Clip
{
  lct::SkeletalAnimation animation;
  std::string rotationOrder = "ZYX"; ///< of the first joint with rotation channels (BVH)
  int channels = 0;                  ///< channels per data row of the input
  double height = 0.0;               ///< H, lct/MotionError.h
};

/// Fills the channel order and count: from a BVH file's CHANNELS lines (assimp keeps neither),
/// for other formats 3 rotation channels per animated joint plus 3 position channels for each
/// root and each joint whose translation changes.
inline void ScanBVHHeader(const std::string& path, Clip& clip)
{
  const lct::SkeletalAnimation& a = clip.animation;
  clip.height = lct::restPoseHeight(a);
  clip.channels = 0;
  std::ifstream in(path);
  std::string word;
  bool bvh = static_cast<bool>(in >> word) && word == "HIERARCHY";
  bool orderFound = false;
  while (bvh && in >> word && word != "MOTION")
  {
    if (word != "CHANNELS")
    {
      continue;
    }
    int count = 0;
    if (!(in >> count) || count < 0 || count > 64)
    {
      bvh = false;
      break;
    }
    clip.channels += count;
    std::string order;
    for (int c = 0; c < count && in >> word; ++c)
    {
      if (word.size() == 9 && word.compare(1, 8, "rotation") == 0)
      {
        order += static_cast<char>(std::toupper(static_cast<unsigned char>(word[0])));
      }
    }
    if (!orderFound && order.size() == 3)
    {
      clip.rotationOrder = order;
      orderFound = true;
    }
  }
  if (bvh && clip.channels > 0)
  {
    return;
  }
  clip.channels = 0;
  for (int j = 0; j < a.jointCount(); ++j)
  {
    if (a.joints[static_cast<std::size_t>(j)].endSite)
    {
      continue;
    }
    bool moves = a.joints[static_cast<std::size_t>(j)].parent < 0;
    for (int f = 1; f < a.frames && !moves; ++f)
    {
      moves = (a.local(f, j).block<3, 1>(0, 3) - a.local(0, j).block<3, 1>(0, 3)).norm() > 0.0;
    }
    clip.channels += moves ? 6 : 3;
  }
}

/// "1%" (of H) or a length in file units; false with a message for anything else.
inline bool ParseTolerance(const std::string& text, double height, double& tolerance,
  std::string& why)
{
  const bool relative = !text.empty() && text.back() == '%';
  const std::string number = relative ? text.substr(0, text.size() - 1) : text;
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || *end != '\0' || !(value > 0.0) || !std::isfinite(value))
  {
    why = "--tolerance " + text + ": want a positive number, optionally with %";
    return false;
  }
  if (relative && !(height > 0.0))
  {
    why = "--tolerance " + text + ": the skeleton has no height (Y extent) to take a % of";
    return false;
  }
  tolerance = relative ? value / 100.0 * height : value;
  return true;
}

/// 4 bytes x data rows x channels: the float32 size of the input's channels.
inline double RawBytes(const Clip& clip)
{
  return 4.0 * clip.animation.frames * clip.channels;
}

inline int Analyse(const Clip& clip, const std::string& directory, bool quick)
{
  (void)directory;
  const double tolerances[] = { 0.05, 0.02, 0.01, 0.005, 0.002, 0.001 };
  for (double share : tolerances)
  {
    lct::MotionMetadata metadata;
    metadata.rotationOrder = clip.rotationOrder;
    metadata.inputChannels = clip.channels;
    metadata.height = clip.height;
    lct::MotionCompressionOptions options;
    options.tolerance = share * clip.height;
    options.searchSteps = quick ? 3 : 7;
    if (const char* q = std::getenv("LCT_MOCAP_Q"))
    {
      options.quantisationShare = std::atof(q);
    }
    if (const char* c = std::getenv("LCT_MOCAP_COMP"))
    {
      options.compensation = std::atoi(c);
    }
    if (const char* d = std::getenv("LCT_MOCAP_DEGREE"))
    {
      options.degree = std::atoi(d);
    }
    lct::MotionCompressionReport report;
    std::string why;
    const lct::Result<std::string> file =
      lct::compressMotion(clip.animation, metadata, options, &report, &why);
    if (!file)
    {
      std::printf("%g %%: %s\n", 100 * share, why.c_str());
      continue;
    }
    std::printf("%6.2f %%  factor %6.1f  max %.3f %% p99 %.3f %% mean %.4f %%  cps %d knots %d "
                "cubic %d/%d beta %.3f payload %zu\n",
      100 * share, RawBytes(clip) / report.bytes, 100 * report.error.max / clip.height,
      100 * report.error.p99 / clip.height, 100 * report.error.mean / clip.height,
      report.controlPoints, report.knots, report.cubicTracks, report.curveTracks,
      report.budgetScale, report.payloadBytes);
  }
  return 0;
}

} // namespace lct_mocap

#endif
