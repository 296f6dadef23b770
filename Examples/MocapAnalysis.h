// The parts of lct-mocap that are not argument handling: a clip with what the reader does not
// keep (the BVH channel order and count), tolerances, and `analyse`.
#ifndef lct_MocapAnalysis_h
#define lct_MocapAnalysis_h

#include "lct/BVHWriter.h"
#include "lct/Curves.h"
#include "lct/LogBasis.h"
#include "lct/MotionCodec.h"
#include "lct/MotionError.h"
#include "lct/Parametrisation.h"
#include "lct/SO3.h"
#include "lct/SequencePCA.h"
#include "lct/Skeleton.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <vector>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

namespace lct_mocap
{

/// Writes `bytes` to `target` through a temporary in the same directory (lct-mocap.cxx).
bool WriteAtomically(const std::filesystem::path& target, const std::string& bytes, std::string& why);

struct Clip
{
  lct::SkeletalAnimation animation;
  std::string rotationOrder = "ZYX"; ///< of the first joint with rotation channels (BVH)
  int channels = 0;                  ///< channels per data row of the input
  double height = 0.0;               ///< H, lct/MotionError.h
  std::string name;                  ///< the file's name, for titles
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
  // A UTF-8 byte-order mark before HIERARCHY is read as BVH too (vtkSkeletonAnimationReader).
  bool bvh = static_cast<bool>(in >> word) &&
    (word == "HIERARCHY" || word == "\xEF\xBB\xBFHIERARCHY");
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

/// One point of `analyse`: a representation at one setting, its size and its error.
struct AnalysisRow
{
  std::string representation;
  std::string setting;
  double factor = 0.0;      ///< raw float32 channels / what the representation stores
  double alexaFactor = 0.0; ///< Alexa's accounting (PCA of 4x4 logs only), else 0
  lct::PositionErrorStatistics error;
  double seconds = 0.0;
};

/// The joints with motion of their own (not end sites).
inline std::vector<int> AnimatedJoints(const lct::SkeletalAnimation& a)
{
  std::vector<int> joints;
  for (int j = 0; j < a.jointCount(); ++j)
  {
    if (!a.joints[static_cast<std::size_t>(j)].endSite)
    {
      joints.push_back(j);
    }
  }
  return joints;
}

/// A copy of `a` whose animated joints' local transforms come from `local(f, index)`.
template <typename Local>
lct::SkeletalAnimation Rebuilt(const lct::SkeletalAnimation& a, const std::vector<int>& joints, Local local)
{
  lct::SkeletalAnimation out = a;
  for (int f = 0; f < a.frames; ++f)
  {
    for (std::size_t i = 0; i < joints.size(); ++i)
    {
      out.locals[static_cast<std::size_t>(f) * a.joints.size() + static_cast<std::size_t>(joints[i])] =
        local(f, static_cast<int>(i));
    }
  }
  return out;
}

/// Rows 0, k, 2k, ... and the last: the key rows of uniform subsampling.
inline std::vector<int> KeyRows(int frames, int k)
{
  std::vector<int> keys;
  for (int f = 0; f < frames; f += k)
  {
    keys.push_back(f);
  }
  if (keys.back() != frames - 1)
  {
    keys.push_back(frames - 1);
  }
  return keys;
}

/// Per animated joint and frame: a vector of `dimension` numbers (continuous in time), rebuilt
/// from uniformly subsampled rows by linear interpolation (or Catmull-Rom in log space).
inline std::vector<AnalysisRow> Subsampled(const Clip& clip, const std::vector<int>& steps,
  const std::vector<int>& joints, const std::string& name, int dimension,
  const std::function<Eigen::VectorXd(int f, int joint, const Eigen::VectorXd* previous)>& encode,
  const std::function<Eigen::Matrix4d(const Eigen::VectorXd&, int joint)>& decode, bool spline,
  const std::vector<double>& reference)
{
  const lct::SkeletalAnimation& a = clip.animation;
  const int frames = a.frames;
  std::vector<Eigen::MatrixXd> values(joints.size(), Eigen::MatrixXd(dimension, frames));
  for (std::size_t i = 0; i < joints.size(); ++i)
  {
    for (int f = 0; f < frames; ++f)
    {
      const Eigen::VectorXd previous = f > 0 ? Eigen::VectorXd(values[i].col(f - 1)) : Eigen::VectorXd();
      values[i].col(f) = encode(f, joints[i], f > 0 ? &previous : nullptr);
    }
  }
  std::vector<AnalysisRow> rows;
  for (int k : steps)
  {
    const auto start = std::chrono::steady_clock::now();
    const std::vector<int> keys = KeyRows(frames, k);
    std::vector<double> times(keys.begin(), keys.end());
    const lct::SkeletalAnimation rebuilt = Rebuilt(a, joints, [&](int f, int i) {
      Eigen::VectorXd v = Eigen::VectorXd::Zero(dimension);
      if (spline)
      {
        const lct::CurveWeights w = lct::curveWeights(
          lct::CurveScheme::CatmullRom, times.data(), static_cast<int>(times.size()), f);
        for (int n = 0; n < w.count; ++n)
        {
          v += w.weight[n] * values[static_cast<std::size_t>(i)].col(keys[static_cast<std::size_t>(w.key[n])]);
        }
      }
      else
      {
        const auto next = std::upper_bound(keys.begin(), keys.end(), f);
        const int k1 = next == keys.end() ? keys.back() : *next;
        const int k0 = next == keys.begin() ? keys.front() : *(next - 1);
        const double u = k1 > k0 ? double(f - k0) / double(k1 - k0) : 0.0;
        v = (1.0 - u) * values[static_cast<std::size_t>(i)].col(k0) +
          u * values[static_cast<std::size_t>(i)].col(k1);
      }
      return decode(v, joints[static_cast<std::size_t>(i)]);
    });
    AnalysisRow row;
    row.representation = name;
    row.setting = "every " + std::to_string(k) + " rows";
    row.factor = double(frames) / double(keys.size());
    row.error = lct::positionErrors(reference, rebuilt);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    rows.push_back(row);
  }
  return rows;
}

/// Which of the 12 log coordinates of each channel vary over the frames (what PCA must store).
inline int VaryingCoordinates(const std::vector<lct::LogCoords>& logs, int frames, int channels)
{
  int count = 0;
  for (int c = 0; c < channels; ++c)
  {
    for (int k = 0; k < 12; ++k)
    {
      bool varies = false;
      for (int f = 1; f < frames && !varies; ++f)
      {
        varies = logs[static_cast<std::size_t>(f * channels + c)](k) != logs[static_cast<std::size_t>(c)](k);
      }
      count += varies;
    }
  }
  return count;
}

/// Alexa 2002 section 6.3: the principal MatrixLog logs of every animated joint, one row per
/// frame, uncentred SVD truncated to r (his accounting: F J 16 against r (F + 16 J); honest: the
/// file's F C values against r scores per frame and the non-zero coordinates of r components).
inline std::vector<AnalysisRow> AlexaPCA(const Clip& clip, const std::vector<int>& ranks,
  const std::vector<int>& joints, const std::vector<double>& reference, std::string& note)
{
  const lct::SkeletalAnimation& a = clip.animation;
  const int frames = a.frames;
  const int n = static_cast<int>(joints.size());
  Eigen::MatrixXd rows(frames, 12 * n);
  std::vector<lct::LogCoords> logs(static_cast<std::size_t>(frames * n));
  for (int f = 0; f < frames; ++f)
  {
    for (int i = 0; i < n; ++i)
    {
      const auto c = lct::logarithm(a.local(f, joints[static_cast<std::size_t>(i)]), lct::Parametrisation::MatrixLog);
      if (!c)
      {
        note = "Alexa's 4x4 logs: frame " + std::to_string(f) + ", joint '" +
          a.joints[static_cast<std::size_t>(joints[static_cast<std::size_t>(i)])].name +
          "' has no real matrix logarithm (" + lct::describe(c.status) + "); not analysed";
        return {};
      }
      logs[static_cast<std::size_t>(f * n + i)] = c.value;
      rows.block<1, 12>(f, 12 * i) = c.value.cwiseProduct(lct::logMetricRoot()).transpose();
    }
  }
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(rows, Eigen::ComputeThinU | Eigen::ComputeThinV);
  int stored = 0;
  for (int c = 0; c < 12 * n; ++c)
  {
    stored += rows.col(c).cwiseAbs().maxCoeff() > 0.0;
  }
  std::vector<AnalysisRow> out;
  for (int r : ranks)
  {
    const auto start = std::chrono::steady_clock::now();
    const int k = std::min<int>(r, static_cast<int>(svd.singularValues().size()));
    const Eigen::MatrixXd approx = svd.matrixU().leftCols(k) *
      svd.singularValues().head(k).asDiagonal() * svd.matrixV().leftCols(k).transpose();
    const lct::SkeletalAnimation rebuilt = Rebuilt(a, joints, [&](int f, int i) {
      const lct::LogCoords c = approx.block<1, 12>(f, 12 * i).transpose().cwiseQuotient(lct::logMetricRoot());
      const auto m = lct::exponential(c, lct::Parametrisation::MatrixLog);
      return m ? m.value : Eigen::Matrix4d::Identity();
    });
    AnalysisRow row;
    row.representation = "Alexa 4x4 logs, PCA";
    row.setting = std::to_string(k) + " components";
    row.alexaFactor = double(frames) * n * 16 / (double(frames) * k + n * 16.0 * k);
    row.factor = double(frames) * clip.channels / (double(frames) * k + double(stored) * k);
    row.error = lct::positionErrors(reference, rebuilt);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.push_back(row);
  }
  return out;
}

/// lct::sequencePCA: Polar logs continuous in time, centred (tangent PCA), the roots kept
/// exactly (their values are stored per frame: counted).
inline std::vector<AnalysisRow> PolarPCA(const Clip& clip, const std::vector<int>& ranks,
  const std::vector<int>& joints, const std::vector<double>& reference)
{
  const lct::SkeletalAnimation& a = clip.animation;
  const int frames = a.frames;
  std::vector<int> analysed;
  int rootValues = 0;
  for (int j : joints)
  {
    if (a.joints[static_cast<std::size_t>(j)].parent >= 0)
    {
      analysed.push_back(j);
    }
    else
    {
      rootValues += 6;
    }
  }
  const int n = static_cast<int>(analysed.size());
  if (n == 0)
  {
    return {};
  }
  std::vector<lct::LogCoords> logs(static_cast<std::size_t>(frames * n));
  for (int f = 0; f < frames; ++f)
  {
    for (int i = 0; i < n; ++i)
    {
      const lct::LogCoords* previous = f > 0 ? &logs[static_cast<std::size_t>((f - 1) * n + i)] : nullptr;
      const auto c = lct::logarithm(a.local(f, analysed[static_cast<std::size_t>(i)]), lct::Parametrisation::Polar, previous);
      logs[static_cast<std::size_t>(f * n + i)] = c ? c.value : lct::LogCoords::Zero();
    }
  }
  const auto pca = lct::sequencePCA(logs.data(), frames, n);
  if (!pca)
  {
    return {};
  }
  const int varying = VaryingCoordinates(logs, frames, n);
  std::vector<AnalysisRow> out;
  for (int r : ranks)
  {
    const auto start = std::chrono::steady_clock::now();
    const int k = std::min(r, pca.value.size());
    const lct::SkeletalAnimation rebuilt = Rebuilt(a, analysed, [&](int f, int i) {
      const auto c = lct::reconstructLog(pca.value, f, i, k);
      const auto m = c ? lct::exponential(c.value, lct::Parametrisation::Polar) : lct::Result<Eigen::Matrix4d>();
      return c && m ? m.value : Eigen::Matrix4d::Identity();
    });
    AnalysisRow row;
    row.representation = "Polar logs, PCA";
    row.setting = std::to_string(k) + " components";
    row.factor = double(frames) * clip.channels /
      (double(frames) * (k + rootValues) + double(varying) * (k + 1));
    row.error = lct::positionErrors(reference, rebuilt);
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.push_back(row);
  }
  return out;
}

inline std::vector<AnalysisRow> Compressor(const Clip& clip, const std::vector<double>& shares)
{
  std::vector<AnalysisRow> out;
  for (double share : shares)
  {
    lct::MotionMetadata metadata;
    metadata.rotationOrder = clip.rotationOrder;
    metadata.inputChannels = clip.channels;
    metadata.height = clip.height;
    lct::MotionCompressionOptions options;
    options.tolerance = share * clip.height;
    lct::MotionCompressionReport report;
    const auto start = std::chrono::steady_clock::now();
    const lct::Result<std::string> file = lct::compressMotion(clip.animation, metadata, options, &report);
    if (!file)
    {
      continue;
    }
    AnalysisRow row;
    row.representation = "lct-mocap";
    std::ostringstream setting;
    setting << "tolerance " << 100.0 * share << " % H";
    row.setting = setting.str();
    row.factor = RawBytes(clip) / static_cast<double>(report.bytes);
    row.error = report.error;
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    out.push_back(row);
  }
  return out;
}

/// Every representation of `analyse`, in the order of the table.
inline std::vector<AnalysisRow> AnalyseClip(const Clip& clip, bool quick, std::string& note)
{
  const lct::SkeletalAnimation& a = clip.animation;
  const std::vector<double> reference = lct::worldPositions(a);
  const std::vector<int> joints = AnimatedJoints(a);
  const std::vector<int> steps = quick ? std::vector<int>{ 2, 8, 32 } : std::vector<int>{ 2, 4, 8, 16, 32 };
  const std::vector<int> ranks = quick ? std::vector<int>{ 5, 20 } : std::vector<int>{ 5, 10, 20, 40 };
  int order[3];
  for (int i = 0; i < 3; ++i)
  {
    order[i] = clip.rotationOrder[static_cast<std::size_t>(i)] - 'X';
  }
  auto translationOf = [&a](int f, int j) { return Eigen::Vector3d(a.local(f, j).block<3, 1>(0, 3)); };
  auto rigid = [](const Eigen::Matrix3d& r, const Eigen::Vector3d& t) {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.block<3, 3>(0, 0) = r;
    m.block<3, 1>(0, 3) = t;
    return m;
  };
  std::vector<AnalysisRow> all;
  auto append = [&all](std::vector<AnalysisRow> rows) { all.insert(all.end(), rows.begin(), rows.end()); };
  append(Subsampled(clip, steps, joints, "Euler channels, linear", 6,
    [&](int f, int j, const Eigen::VectorXd* previous) {
      Eigen::VectorXd v(6);
      const Eigen::Vector3d near = previous ? Eigen::Vector3d(previous->head<3>()) : Eigen::Vector3d::Zero();
      v << lct::eulerAnglesNear(a.local(f, j).block<3, 3>(0, 0), order, near), translationOf(f, j);
      return v;
    },
    [&](const Eigen::VectorXd& v, int) {
      Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
      for (int i = 0; i < 3; ++i)
      {
        r = r * Eigen::AngleAxisd(v(i), Eigen::Vector3d::Unit(order[i])).toRotationMatrix();
      }
      return rigid(r, v.tail<3>());
    },
    false, reference));
  append(Subsampled(clip, steps, joints, "rotation vectors, linear", 6,
    [&](int f, int j, const Eigen::VectorXd* previous) {
      Eigen::VectorXd v(6);
      const Eigen::Matrix3d r = a.local(f, j).block<3, 3>(0, 0);
      v << (previous ? lct::logSO3Nearest(r, previous->head<3>()) : lct::logSO3(r)), translationOf(f, j);
      return v;
    },
    [&](const Eigen::VectorXd& v, int) { return rigid(lct::expSO3(v.head<3>()), v.tail<3>()); },
    false, reference));
  append(Subsampled(clip, steps, joints, "Polar logs, Catmull-Rom keys", 12,
    [&](int f, int j, const Eigen::VectorXd* previous) {
      lct::LogCoords near;
      if (previous)
      {
        near = *previous;
      }
      const auto c = lct::logarithm(a.local(f, j), lct::Parametrisation::Polar, previous ? &near : nullptr);
      return Eigen::VectorXd(c ? c.value : lct::LogCoords::Zero());
    },
    [&](const Eigen::VectorXd& v, int) {
      const auto m = lct::exponential(lct::LogCoords(v), lct::Parametrisation::Polar);
      return m ? m.value : Eigen::Matrix4d::Identity();
    },
    true, reference));
  append(AlexaPCA(clip, ranks, joints, reference, note));
  append(PolarPCA(clip, ranks, joints, reference));
  append(Compressor(clip, quick ? std::vector<double>{ 0.01, 0.001 }
                                : std::vector<double>{ 0.05, 0.02, 0.01, 0.005, 0.002, 0.001 }));
  return all;
}

/// A log-log plot of max error (% of H) against factor, a line per representation, as a PNG
/// (lct-mocap.cxx; needs an X display).
bool PlotAnalysis(const std::vector<AnalysisRow>& rows, double height, const std::string& title,
  const std::string& png, std::string& why);

inline int Analyse(const Clip& clip, const std::string& directory, bool quick)
{
  std::string note;
  const std::vector<AnalysisRow> rows = AnalyseClip(clip, quick, note);
  std::printf("%d rows x %d channels, %d joints, H = %.4g (raw %.0f bytes)\n\n", clip.animation.frames,
    clip.channels, clip.animation.jointCount(), clip.height, RawBytes(clip));
  std::printf("| representation | setting | factor | Alexa's factor | max %%H | p99 %%H | mean %%H | s |\n");
  std::printf("|---|---|---:|---:|---:|---:|---:|---:|\n");
  std::ostringstream csv;
  csv << "representation,setting,factor,alexa_factor,max_percent_h,p99_percent_h,mean_percent_h,seconds\n";
  for (const AnalysisRow& r : rows)
  {
    const double h = 100.0 / clip.height;
    char alexa[32] = "";
    if (r.alexaFactor > 0.0)
    {
      std::snprintf(alexa, sizeof alexa, "%.1f", r.alexaFactor);
    }
    std::printf("| %s | %s | %.1f | %s | %.3g | %.3g | %.3g | %.2f |\n", r.representation.c_str(),
      r.setting.c_str(), r.factor, alexa, r.error.max * h, r.error.p99 * h, r.error.mean * h, r.seconds);
    csv << '"' << r.representation << "\",\"" << r.setting << "\"," << r.factor << ',' << r.alexaFactor
        << ',' << r.error.max * h << ',' << r.error.p99 * h << ',' << r.error.mean * h << ','
        << r.seconds << '\n';
  }
  if (!note.empty())
  {
    std::printf("\n%s\n", note.c_str());
  }
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  std::string why;
  const std::string csvPath = directory + "/analysis.csv";
  if (!WriteAtomically(csvPath, csv.str(), why))
  {
    std::fprintf(stderr, "lct-mocap: %s\n", why.c_str());
    return 1;
  }
  std::printf("\nwrote %s\n", csvPath.c_str());
  const std::string png = directory + "/analysis.png";
  if (!PlotAnalysis(rows, clip.height, clip.name + ": max error against compression factor", png, why))
  {
    std::fprintf(stderr, "lct-mocap: no plot: %s\n", why.c_str());
    return why.find("DISPLAY") != std::string::npos ? 0 : 1;
  }
  std::printf("wrote %s\n", png.c_str());
  return 0;
}

} // namespace lct_mocap

#endif
