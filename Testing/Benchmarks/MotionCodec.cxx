// The motion-capture codec (lct/MotionCodec.h, lct-mocap) on the CMU and boxing clips of
// assimp-testmodels, read through the module's own reader (vtkSkeletonAnimationReader):
//  - the goals: factor at 1 % and 0.1 % of the skeleton height H, the max position
//    error over every joint and End Site at every data row (measured here again by forward
//    kinematics of the decoded file), p99 and mean; compression and decompression speed in
//    multiples of real time on one core (decompression: the median of 5 decodes to transforms);
//  - what each part contributes, at 1 % on every clip: the method with one part changed
//    (no compensation, orientation-only compensation, degree 1 only, degree 3 only, no local
//    repair, a finer quantisation q = 0.35, and the payload before LZMA2).
// Factor = 4 bytes x data rows x channels of the input / bytes of the file.
//
// Plain program: prints markdown. Usage: BenchMotionCodec [--check] [--quick] [BVH directory].
// --check exits 1 when a goal is missed (factors and bound; the speed goals are reported, not
// checked: they depend on the machine) and 77 without the data (ctest's SKIP_RETURN_CODE);
// --quick skips the table of contributions; --benchmark_* flags (scripts/bench) are ignored.
#include "vtkSkeletonAnimationReader.h"

#include "lct/MotionCodec.h"
#include "lct/MotionError.h"

#include <vtkNew.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{

using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point since)
{
  return std::chrono::duration<double>(Clock::now() - since).count();
}

struct Clip
{
  std::string name;
  lct::SkeletalAnimation animation;
  int channels = 0;
  double height = 0.0;
  double goalLoose = 35.0; ///< factor goal at 1 %
  double goalTight = 10.0; ///< at 0.1 %
};

/// Channels per data row from the CHANNELS lines (assimp keeps only the motion).
int ChannelCount(const std::string& path)
{
  std::ifstream in(path);
  std::string word;
  int channels = 0;
  while (in >> word && word != "MOTION")
  {
    int n = 0;
    if (word == "CHANNELS" && in >> n)
    {
      channels += n;
    }
  }
  return channels;
}

struct Measured
{
  bool ok = false;
  std::size_t bytes = 0;
  std::size_t payload = 0;
  double factor = 0.0;
  double max = 0.0;
  double p99 = 0.0;
  double mean = 0.0;
  double compressSeconds = 0.0;
  double decodeSeconds = 0.0;
  std::string why;
};

Measured Run(const Clip& clip, double share, const lct::MotionCompressionOptions& base, bool timeDecode)
{
  Measured m;
  lct::MotionMetadata metadata;
  metadata.inputChannels = clip.channels;
  metadata.height = clip.height;
  lct::MotionCompressionOptions options = base;
  options.tolerance = share * clip.height;
  lct::MotionCompressionReport report;
  const auto start = Clock::now();
  const lct::Result<std::string> file =
    lct::compressMotion(clip.animation, metadata, options, &report, &m.why);
  m.compressSeconds = Seconds(start);
  if (!file)
  {
    return m;
  }
  std::vector<double> decodes;
  lct::Result<lct::SkeletalAnimation> decoded;
  for (int i = 0; i < (timeDecode ? 5 : 1); ++i)
  {
    const auto t = Clock::now();
    decoded = lct::decompressMotion(file.value, nullptr, &m.why);
    decodes.push_back(Seconds(t));
  }
  if (!decoded)
  {
    return m;
  }
  std::sort(decodes.begin(), decodes.end());
  m.decodeSeconds = decodes[decodes.size() / 2];
  const lct::PositionErrorStatistics e =
    lct::positionErrors(lct::worldPositions(clip.animation), decoded.value);
  m.ok = e.max <= options.tolerance;
  m.bytes = file.value.size();
  m.payload = report.payloadBytes;
  m.factor = 4.0 * clip.animation.frames * clip.channels / static_cast<double>(m.bytes);
  m.max = 100.0 * e.max / clip.height;
  m.p99 = 100.0 * e.p99 / clip.height;
  m.mean = 100.0 * e.mean / clip.height;
  if (!m.ok)
  {
    m.why = "the decoded motion misses the tolerance";
  }
  return m;
}

} // namespace

int main(int argc, char* argv[])
{
  bool check = false;
  bool quick = false;
  std::string directory = "/usr/share/assimp/models/BVH";
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--check"))
    {
      check = true;
    }
    else if (!std::strcmp(argv[i], "--quick"))
    {
      quick = true;
    }
    else if (std::strncmp(argv[i], "--benchmark", 11) != 0)
    {
      directory = argv[i];
    }
  }
  std::vector<Clip> clips;
  for (const char* name : { "01_01", "01_03", "Boxing_Toes" })
  {
    const std::string path = directory + "/" + name + ".bvh";
    if (!std::filesystem::exists(path))
    {
      continue;
    }
    vtkNew<vtkSkeletonAnimationReader> reader;
    reader->SetFileName(path.c_str());
    reader->UpdateInformation();
    if (!reader->GetAnimation())
    {
      std::printf("%s: unreadable\n", path.c_str());
      return 1;
    }
    Clip clip;
    clip.name = name;
    clip.animation = *reader->GetAnimation();
    clip.channels = ChannelCount(path);
    clip.height = lct::restPoseHeight(clip.animation);
    if (clip.name == "01_01")
    {
      clip.goalLoose = 60.0;
      clip.goalTight = 15.0;
    }
    clips.push_back(clip);
  }
  if (clips.empty())
  {
    std::printf("skipped: no BVH files in %s (Debian package assimp-testmodels)\n", directory.c_str());
    return check ? 77 : 0;
  }

  bool met = true;
  std::printf("## lct-mocap on the CMU and boxing clips\n\n");
  std::printf("| clip | rows x channels | tolerance | bytes | factor | goal | max %%H | p99 %%H | "
              "mean %%H | compress s (x real time) | decode ms (x real time) |\n");
  std::printf("|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  const lct::MotionCompressionOptions defaults;
  for (const Clip& clip : clips)
  {
    const double duration = clip.animation.frames * clip.animation.frameTime;
    for (double share : { 0.01, 0.001 })
    {
      const Measured m = Run(clip, share, defaults, true);
      const double goal = share > 0.005 ? clip.goalLoose : clip.goalTight;
      const bool pass = m.ok && m.factor >= goal;
      met = met && pass;
      std::printf("| %s | %d x %d | %g %% | %zu | %.1f | %s%.0f | %.3f | %.3f | %.4f | %.2f (%.1fx) "
                  "| %.1f (%.0fx) |\n",
        clip.name.c_str(), clip.animation.frames, clip.channels, 100.0 * share, m.bytes, m.factor,
        pass ? ">= " : "MISSED ", goal, m.max, m.p99, m.mean, m.compressSeconds,
        duration / m.compressSeconds, 1e3 * m.decodeSeconds, duration / m.decodeSeconds);
      if (!m.ok)
      {
        std::printf("\n%s at %g %%: %s\n\n", clip.name.c_str(), 100.0 * share, m.why.c_str());
      }
    }
  }

  if (!quick)
  {
    struct Variant
    {
      const char* name;
      lct::MotionCompressionOptions options;
      bool payload = false;
    };
    std::vector<Variant> variants;
    variants.push_back({ "the method (defaults)", defaults });
    Variant v{ "no compensation (each track fitted to its input)", defaults };
    v.options.compensation = 0;
    variants.push_back(v);
    v = { "orientation compensation only", defaults };
    v.options.compensation = 1;
    variants.push_back(v);
    v = { "degree 1 only (piecewise linear)", defaults };
    v.options.degree = 1;
    variants.push_back(v);
    v = { "degree 3 only (cubic)", defaults };
    v.options.degree = 3;
    variants.push_back(v);
    v = { "no local repair", defaults };
    v.options.refineSteps = 0;
    variants.push_back(v);
    v = { "finer quantisation, q = 0.35", defaults };
    v.options.quantisationShare = 0.35;
    variants.push_back(v);
    v = { "no LZMA2 (the payload's size)", defaults };
    v.payload = true;
    variants.push_back(v);
    std::printf("\n## What each part contributes (factor at 1 %% of H, the bound holding)\n\n");
    std::printf("| variant |");
    for (const Clip& clip : clips)
    {
      std::printf(" %s |", clip.name.c_str());
    }
    std::printf("\n|---|");
    for (std::size_t i = 0; i < clips.size(); ++i)
    {
      std::printf("---:|");
    }
    std::printf("\n");
    for (const Variant& variant : variants)
    {
      std::printf("| %s |", variant.name);
      for (const Clip& clip : clips)
      {
        const Measured m = Run(clip, 0.01, variant.options, false);
        const double bytes = static_cast<double>(variant.payload ? m.payload + 16 : m.bytes);
        std::printf(m.ok ? " %.1f |" : " failed |", 4.0 * clip.animation.frames * clip.channels / bytes);
        std::fflush(stdout);
      }
      std::printf("\n");
    }
  }
  std::printf("\n%s\n", met ? "All goals met." : "A goal was MISSED.");
  return check && !met ? 1 : 0;
}
