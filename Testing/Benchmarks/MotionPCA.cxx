// Alexa 2002 §6.3 on real motion capture: PCA of an animation's joint transforms in log space,
// with his accounting beside the floats actually needed and the forward-kinematics error.
//
// For each CMU / boxing BVH file (assimp-testmodels) and r in {5, 10, 20, 40} components, two
// schemes are compared:
//  - Alexa: the principal MatrixLog 4x4 logs of every joint's local transform (root included)
//    as one row per frame, uncentred SVD (his §6.3), truncated to r;
//  - LCT: vtkLCT's lct::sequencePCA: Polar logs continuous in time (each taken against the
//    previous frame's), centred at each joint's mean log (tangent PCA), the root joint factored
//    out and kept exactly.
// The clips are read by the module's vtkSkeletonAnimationReader (assimp). Every data row is
// rebuilt, forward kinematics (lct::worldPositions) gives the world positions of every joint
// and End Site, and the error is their distance to the recorded ones: mean, 99th percentile and
// max, in % of the skeleton height H (the y extent of the rest pose, every channel 0).
//
// Accounting. Alexa's: F J 16 scalars against F r + J 16 r (he counts 16 per 4x4 log). Honest:
// the file's own F C values (C channels per row) against what the scheme must store as float32:
// the r scores per frame, the non-zero entries of the r components (log coordinates that vary
// in the data; 6 of a joint's 16 at most), the means of those coordinates (LCT), and the root's
// 6 values per frame (LCT). The factor is the ratio; neither counts entropy coding.
//
// Plain program: prints markdown. Usage: BenchMotionPCA [--check] [BVH directory]. --check exits
// 1 unless LCT with every component reproduces every file to 1e-6 % of H (ctest runs it) and 77
// without the data; --benchmark_* flags (scripts/bench passes them) are ignored.
#include "vtkSkeletonAnimationReader.h"

#include <vtkNew.h>

#include "lct/MotionError.h"

#include "lct/LogBasis.h"
#include "lct/Parametrisation.h"
#include "lct/SequencePCA.h"

#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
constexpr int kSkipped = 77;
const int kComponents[] = { 5, 10, 20, 40 };

using Matrix4 = Eigen::Matrix4d;

const Eigen::Matrix4d& toEigen(const Matrix4& m)
{
  return m;
}

struct Clip
{
  std::string name;
  lct::SkeletalAnimation animation; ///< as vtkSkeletonAnimationReader reads it
  int channels = 0;                 ///< per data row, from the file's CHANNELS lines
  std::vector<int> animated;        ///< joints with motion (End Sites have none)
  int root = 0;                     ///< index into animated of the ROOT (the first)
  std::vector<std::vector<Matrix4>> locals; ///< [frame][joint] for every joint
  std::vector<double> reference;            ///< lct::worldPositions of the recording
  double height = 0.0;
};

/// Channels per data row from the CHANNELS lines (the reader keeps only the motion).
int channelCount(const std::string& path)
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

bool load(const std::string& path, Clip& clip)
{
  vtkNew<vtkSkeletonAnimationReader> reader;
  reader->SetFileName(path.c_str());
  reader->UpdateInformation();
  if (!reader->GetAnimation())
  {
    std::fprintf(stderr, "%s: not readable\n", path.c_str());
    return false;
  }
  clip.name = std::filesystem::path(path).filename().string();
  clip.animation = *reader->GetAnimation();
  clip.channels = channelCount(path);
  const lct::SkeletalAnimation& a = clip.animation;
  for (int j = 0; j < a.jointCount(); ++j)
  {
    if (!a.joints[static_cast<std::size_t>(j)].endSite)
    {
      clip.animated.push_back(j);
    }
  }
  clip.height = lct::restPoseHeight(a);
  clip.reference = lct::worldPositions(a);
  for (int f = 0; f < a.frames; ++f)
  {
    std::vector<Matrix4> locals;
    for (int j = 0; j < a.jointCount(); ++j)
    {
      locals.push_back(a.local(f, j));
    }
    clip.locals.push_back(std::move(locals));
  }
  return true;
}

struct Error
{
  double mean = 0.0, p99 = 0.0, max = 0.0; ///< % of H
};

/// FK error of rebuilt local transforms of the animated joints ([frame][animated joint]).
Error fkError(const Clip& clip, const std::vector<std::vector<Eigen::Matrix4d>>& rebuilt)
{
  lct::SkeletalAnimation approximation = clip.animation;
  for (int f = 0; f < approximation.frames; ++f)
  {
    for (std::size_t a = 0; a < clip.animated.size(); ++a)
    {
      approximation.locals[static_cast<std::size_t>(f) * approximation.joints.size() +
        static_cast<std::size_t>(clip.animated[a])] = rebuilt[static_cast<std::size_t>(f)][a];
    }
  }
  const lct::PositionErrorStatistics e = lct::positionErrors(clip.reference, approximation);
  const double scale = 100.0 / clip.height;
  return { e.mean * scale, e.p99 * scale, e.max * scale };
}

/// Log coordinates (over all frames and the given channels) whose value is not constant.
int varyingCoordinates(const std::vector<lct::LogCoords>& logs, int frames, int channels,
  std::vector<bool>* varying = nullptr)
{
  int count = 0;
  std::vector<bool> v(static_cast<std::size_t>(12 * channels), false);
  for (int c = 0; c < channels; ++c)
  {
    for (int k = 0; k < 12; ++k)
    {
      const double first = logs[static_cast<std::size_t>(c)][k];
      for (int f = 1; f < frames; ++f)
      {
        if (std::abs(logs[static_cast<std::size_t>(f * channels + c)][k] - first) >
          1e-12 * (1.0 + std::abs(first)))
        {
          v[static_cast<std::size_t>(12 * c + k)] = true;
          ++count;
          break;
        }
      }
    }
  }
  if (varying)
  {
    *varying = v;
  }
  return count;
}

struct Row
{
  int r;
  Error error;
  double alexaFactor, honestFactor;
  double seconds;
};

/// Alexa's scheme: uncentred SVD of the principal MatrixLog logs of every animated joint.
std::vector<Row> alexa(const Clip& clip, bool& ok)
{
  const int frames = clip.animation.frames;
  const int joints = static_cast<int>(clip.animated.size());
  std::vector<lct::LogCoords> logs;
  ok = true;
  for (int f = 0; f < frames; ++f)
  {
    for (int j : clip.animated)
    {
      const auto c = lct::logarithm(
        toEigen(clip.locals[f][static_cast<std::size_t>(j)]), lct::Parametrisation::MatrixLog);
      if (!c)
      {
        std::printf(
          "  (Alexa: frame %d joint %d has no real log: %s)\n", f, j, lct::describe(c.status));
        ok = false;
        return {};
      }
      logs.push_back(c.value);
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  Eigen::MatrixXd rows(frames, 12 * joints);
  for (int f = 0; f < frames; ++f)
  {
    for (int a = 0; a < joints; ++a)
    {
      rows.block<1, 12>(f, 12 * a) = logs[static_cast<std::size_t>(f * joints + a)]
                                       .cwiseProduct(lct::logMetricRoot())
                                       .transpose();
    }
  }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(rows, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Uncentred, the constant non-zero coordinates (the bone offsets) are stored too.
  std::vector<bool> varying;
  varyingCoordinates(logs, frames, joints, &varying);
  int stored = 0;
  for (int k = 0; k < 12 * joints; ++k)
  {
    stored +=
      varying[static_cast<std::size_t>(k)] || logs[static_cast<std::size_t>(k / 12)][k % 12] != 0.0;
  }
  std::vector<Row> out;
  for (int r : kComponents)
  {
    const int k = std::min<int>(r, static_cast<int>(svd.singularValues().size()));
    const Eigen::MatrixXd approx = svd.matrixU().leftCols(k) *
      svd.singularValues().head(k).asDiagonal() * svd.matrixV().leftCols(k).transpose();
    std::vector<std::vector<Eigen::Matrix4d>> rebuilt(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f)
    {
      for (int a = 0; a < joints; ++a)
      {
        const lct::LogCoords c =
          approx.block<1, 12>(f, 12 * a).transpose().cwiseQuotient(lct::logMetricRoot());
        const auto m = lct::exponential(c, lct::Parametrisation::MatrixLog);
        rebuilt[f].push_back(m ? m.value : Eigen::Matrix4d::Identity());
      }
    }
    const double alexaFactor =
      double(frames) * joints * 16 / (double(frames) * k + joints * 16.0 * k);
    const double honest =
      double(frames) * clip.channels / (double(frames) * k + double(stored) * k);
    out.push_back({ r, fkError(clip, rebuilt), alexaFactor, honest, seconds });
  }
  return out;
}

/// vtkLCT's scheme: Polar logs continuous in time, centred, root factored out.
std::vector<Row> lctScheme(const Clip& clip, bool allComponents, Error* full)
{
  const int frames = clip.animation.frames;
  const int joints = static_cast<int>(clip.animated.size()) - 1; // without the root
  std::vector<int> analysed;
  for (std::size_t a = 0; a < clip.animated.size(); ++a)
  {
    if (static_cast<int>(a) != clip.root)
    {
      analysed.push_back(clip.animated[a]);
    }
  }
  std::vector<lct::LogCoords> logs(static_cast<std::size_t>(frames * joints));
  for (int f = 0; f < frames; ++f)
  {
    for (int a = 0; a < joints; ++a)
    {
      const lct::LogCoords* previous =
        f > 0 ? &logs[static_cast<std::size_t>((f - 1) * joints + a)] : nullptr;
      logs[static_cast<std::size_t>(f * joints + a)] =
        lct::logarithm(toEigen(clip.locals[f][static_cast<std::size_t>(analysed[a])]),
          lct::Parametrisation::Polar, previous)
          .value;
    }
  }
  const auto t0 = std::chrono::steady_clock::now();
  const auto pca = lct::sequencePCA(logs.data(), frames, joints);
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int varying = varyingCoordinates(logs, frames, joints);
  std::vector<Row> out;
  auto rebuild = [&](int k) {
    std::vector<std::vector<Eigen::Matrix4d>> rebuilt(static_cast<std::size_t>(frames));
    for (int f = 0; f < frames; ++f)
    {
      for (std::size_t a = 0; a < clip.animated.size(); ++a)
      {
        if (static_cast<int>(a) == clip.root)
        {
          rebuilt[f].push_back(toEigen(clip.locals[f][static_cast<std::size_t>(clip.animated[a])]));
          continue;
        }
        const int s = static_cast<int>(a) - (static_cast<int>(a) > clip.root ? 1 : 0);
        const auto c = lct::reconstructLog(pca.value, f, s, k);
        rebuilt[f].push_back(lct::exponential(c.value, lct::Parametrisation::Polar).value);
      }
    }
    return fkError(clip, rebuilt);
  };
  if (allComponents && full)
  {
    *full = rebuild(pca.value.size());
  }
  for (int r : kComponents)
  {
    const int k = std::min(r, pca.value.size());
    const double alexaFactor =
      double(frames) * (joints + 1) * 16 / (double(frames) * k + (joints + 1) * 16.0 * k);
    const double honest = double(frames) * clip.channels /
      (double(frames) * (k + 6) + double(varying) * (k + 1));
    out.push_back({ r, rebuild(k), alexaFactor, honest, seconds });
  }
  return out;
}

void print(const char* scheme, const std::vector<Row>& rows)
{
  for (const Row& row : rows)
  {
    std::printf("| %s | %d | %.2f | %.2f | %.2f | %.1fx | %.1fx | %.0f |\n", scheme, row.r,
      row.error.mean, row.error.p99, row.error.max, row.alexaFactor, row.honestFactor,
      row.seconds * 1e3);
  }
}
} // namespace

int main(int argc, char* argv[])
{
  bool check = false;
  std::string directory = "/usr/share/assimp/models/BVH";
  for (int i = 1; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--check")
    {
      check = true;
    }
    else if (arg.rfind("--benchmark", 0) == 0)
    {
      continue;
    }
    else if (arg == "--help")
    {
      std::printf("usage: %s [--check] [BVH directory]\n", argv[0]);
      return 0;
    }
    else
    {
      directory = arg;
    }
  }
  const char* files[] = { "01_01.bvh", "01_03.bvh", "Boxing_Toes.bvh" };
  int status = 0;
  bool any = false;
  std::printf("## Alexa §6.3: PCA of joint transforms in log space\n\n");
  std::printf("| scheme | components | mean %%H | p99 %%H | max %%H | Alexa's factor | "
              "honest factor | SVD ms |\n|---|---|---|---|---|---|---|---|\n");
  for (const char* file : files)
  {
    const std::string path = directory + "/" + file;
    if (!std::filesystem::exists(path))
    {
      continue;
    }
    Clip clip;
    if (!load(path, clip))
    {
      return 1;
    }
    any = true;
    std::printf("| **%s** | %d frames, %zu joints, %d channels, H = %.2f | | | | | | |\n",
      clip.name.c_str(), clip.animation.frames, clip.animated.size(), clip.channels,
      clip.height);
    bool alexaOk = false;
    const auto a = alexa(clip, alexaOk);
    if (alexaOk)
    {
      print("Alexa", a);
    }
    Error full;
    print("LCT", lctScheme(clip, true, &full));
    std::printf("| LCT, every component | | %.1e | | %.1e | | | |\n", full.mean, full.max);
    if (check && !(full.max <= 1e-6))
    {
      std::fprintf(
        stderr, "%s: every component reproduces to %.3g %% of H, not 1e-6\n", file, full.max);
      status = 1;
    }
  }
  if (!any)
  {
    std::printf(
      "skipped: no BVH files in %s (Debian package assimp-testmodels)\n", directory.c_str());
    return check ? kSkipped : 0;
  }
  return status;
}
