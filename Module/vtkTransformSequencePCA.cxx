#include "vtkTransformSequencePCA.h"

#include "vtkLCTCheckedSet.h"

#include "lct/Affine.h"

#include "lct/Format.h"
#include "lct/LogBasis.h"
#include "lct/Parametrisation.h"
#include "lct/SequencePCA.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkLinearTransform.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkTimeStamp.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkTransformSequencePCA);

namespace
{
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

/// Bounds on what AddFrame accepts, so that no input can make the analysis allocate without
/// limit (10^8 transforms are 12.8 GB of matrices; the SVD's working set grows with them).
constexpr int kMaxChannels = 100000;
constexpr std::size_t kMaxTransforms = 100000000;

/// A principal rotation log that moves by more than this between frames has crossed 180
/// degrees (its vector flips from ~pi a to ~-pi a); no sampled motion is that fast and useful.
constexpr double kBranchJump = 3.14159265358979323846;

lct::Parametrisation toCore(int parametrisation)
{
  return parametrisation == vtkTransformSequencePCA::MATRIX_LOG ? lct::Parametrisation::MatrixLog
                                                                : lct::Parametrisation::Polar;
}
} // namespace

struct vtkTransformSequencePCA::Internals
{
  std::vector<Eigen::Matrix4d> Transforms; // frame-major: Transforms[f * Channels + c]
  int Channels = 0;
  std::vector<double> Weights;

  bool HasAnalysis = false;
  vtkTimeStamp ComputeTime;
  lct::SequencePCA Pca;
  std::vector<int> Slot;                            // channel -> channel of Pca, or -1 for the root
  lct::LogCoords RootMean = lct::LogCoords::Zero(); // mean log of the root channel, if any

  int Frames() const
  {
    return this->Channels == 0 ? 0 : static_cast<int>(this->Transforms.size()) / this->Channels;
  }
  const Eigen::Matrix4d& At(int frame, int channel) const
  {
    return this
      ->Transforms[static_cast<std::size_t>(frame) * static_cast<std::size_t>(this->Channels) +
        static_cast<std::size_t>(channel)];
  }
};

//------------------------------------------------------------------------------
vtkTransformSequencePCA::vtkTransformSequencePCA()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkTransformSequencePCA::~vtkTransformSequencePCA()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::AddFrame(vtkCollection* transforms)
{
  Internals& in = *this->Internal;
  const int n = transforms ? transforms->GetNumberOfItems() : 0;
  if (n == 0)
  {
    vtkErrorMacro(<< "AddFrame: " << (transforms ? "empty collection" : "null collection")
                  << "; no frame added.");
    return 0;
  }
  if (in.Channels != 0 && n != in.Channels)
  {
    vtkErrorMacro(<< "AddFrame: " << n << " transforms where every frame has " << in.Channels
                  << " channels (frame " << in.Frames() << "); no frame added.");
    return 0;
  }
  if (n > kMaxChannels || in.Transforms.size() + static_cast<std::size_t>(n) > kMaxTransforms)
  {
    vtkErrorMacro(<< "AddFrame: more than " << (n > kMaxChannels ? kMaxChannels : kMaxTransforms)
                  << (n > kMaxChannels ? " channels" : " transforms in all")
                  << " (the documented limit); no frame added.");
    return 0;
  }
  std::vector<Eigen::Matrix4d> frame;
  frame.reserve(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
  {
    vtkObject* item = transforms->GetItemAsObject(i);
    vtkMatrix4x4* matrix = vtkMatrix4x4::SafeDownCast(item);
    if (auto* transform = vtkLinearTransform::SafeDownCast(item))
    {
      matrix = transform->GetMatrix();
    }
    if (!matrix)
    {
      vtkErrorMacro(<< "AddFrame: item " << i << " is " << (item ? item->GetClassName() : "null")
                    << ", not a vtkMatrix4x4 or vtkLinearTransform; no frame added.");
      return 0;
    }
    frame.push_back(RowMajor4(Eigen::Map<const RowMajor4>(matrix->GetData())));
  }
  if (in.Channels == 0)
  {
    in.Channels = n;
    in.Weights.assign(static_cast<std::size_t>(n), 1.0);
  }
  in.Transforms.insert(in.Transforms.end(), frame.begin(), frame.end());
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformSequencePCA::RemoveAllFrames()
{
  *this->Internal = Internals();
  // The header promises the root channel goes with the frames: kept, it silently factored a
  // channel of the next sequence out.
  this->RootChannel = -1;
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetNumberOfFrames()
{
  return this->Internal->Frames();
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetNumberOfChannels()
{
  return this->Internal->Channels;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::SetChannelWeight(int channel, double weight)
{
  Internals& in = *this->Internal;
  if (channel < 0 || channel >= in.Channels)
  {
    vtkErrorMacro(<< "SetChannelWeight: channel " << channel << " is outside [0, " << in.Channels
                  << ")" << (in.Channels == 0 ? " (add a frame first)" : "") << "; unchanged.");
    return 0;
  }
  if (!(std::isfinite(weight) && weight > 0.0))
  {
    vtkErrorMacro(<< "SetChannelWeight: the weight " << lct::formatNumber(weight)
                  << " is not finite and positive; unchanged.");
    return 0;
  }
  if (in.Weights[static_cast<std::size_t>(channel)] != weight)
  {
    in.Weights[static_cast<std::size_t>(channel)] = weight;
    this->Modified();
  }
  return 1;
}

//------------------------------------------------------------------------------
double vtkTransformSequencePCA::GetChannelWeight(int channel)
{
  const Internals& in = *this->Internal;
  if (channel < 0 || channel >= in.Channels)
  {
    vtkErrorMacro(<< "GetChannelWeight: channel " << channel << " is outside [0, " << in.Channels
                  << "); returning 0.");
    return 0.0;
  }
  return in.Weights[static_cast<std::size_t>(channel)];
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::Compute()
{
  Internals& in = *this->Internal;
  in.HasAnalysis = false;
  const int frames = in.Frames();
  if (frames == 0)
  {
    vtkErrorMacro(<< "Compute: no frames (AddFrame first).");
    return 0;
  }
  if (this->RootChannel < -1 || this->RootChannel >= in.Channels)
  {
    vtkErrorMacro(<< "Compute: the root channel " << this->RootChannel << " is outside [-1, "
                  << in.Channels << ").");
    return 0;
  }
  const int analysed = in.Channels - (this->RootChannel >= 0 ? 1 : 0);
  if (analysed == 0)
  {
    vtkErrorMacro(<< "Compute: the only channel is the root channel: nothing to analyse.");
    return 0;
  }
  const lct::Parametrisation p = toCore(this->Parametrisation);
  std::vector<int> slot(static_cast<std::size_t>(in.Channels), -1);
  std::vector<double> weights;
  for (int c = 0, next = 0; c < in.Channels; ++c)
  {
    if (c != this->RootChannel)
    {
      slot[static_cast<std::size_t>(c)] = next++;
      weights.push_back(in.Weights[static_cast<std::size_t>(c)]);
    }
  }
  {
    int lightest = -1, heaviest = -1;
    for (int c = 0; c < in.Channels; ++c)
    {
      const double w = in.Weights[static_cast<std::size_t>(c)];
      if (c == this->RootChannel)
      {
        continue;
      }
      lightest = lightest < 0 || w < in.Weights[static_cast<std::size_t>(lightest)] ? c : lightest;
      heaviest = heaviest < 0 || w > in.Weights[static_cast<std::size_t>(heaviest)] ? c : heaviest;
    }
    const double light = in.Weights[static_cast<std::size_t>(lightest)];
    const double heavy = in.Weights[static_cast<std::size_t>(heaviest)];
    if (heavy / lct::kMaxChannelWeightRatio > light)
    {
      vtkErrorMacro(<< "Compute: channel weights from " << lct::formatNumber(light) << " (channel "
                    << lightest << ") to " << lct::formatNumber(heavy) << " (channel " << heaviest
                    << ") span more than " << lct::formatNumber(lct::kMaxChannelWeightRatio)
                    << ": the lighter channels would fall below the SVD's resolution (their "
                       "components would be noise).");
      return 0;
    }
  }
  std::vector<lct::LogCoords> logs(static_cast<std::size_t>(frames) * analysed);
  std::vector<lct::LogCoords> channelLogs(static_cast<std::size_t>(frames));
  lct::LogCoords rootMean = lct::LogCoords::Zero();
  for (int c = 0; c < in.Channels; ++c)
  {
    // The root channel is not analysed, but its logs are taken here all the same, with the same
    // checks: GetMeanTransform returns their mean, and a root that has no log (a MatrixLog half
    // turn) or crosses 180 degrees must fail here, not after Compute reported success.
    const bool root = c == this->RootChannel;
    for (int f = 0; f < frames; ++f)
    {
      if (root)
      {
        const lct::Status valid = lct::validateAffine(in.At(f, c));
        if (valid != lct::Status::Ok)
        {
          vtkErrorMacro(<< "Compute: frame " << f << ", root channel " << c << ": "
                        << lct::describe(valid) << ".");
          return 0;
        }
      }
      lct::LogCoords* previous = f > 0 ? &channelLogs[static_cast<std::size_t>(f - 1)] : nullptr;
      const auto log =
        lct::logarithm(in.At(f, c), p, p == lct::Parametrisation::Polar ? previous : nullptr);
      if (!log)
      {
        vtkErrorMacro(<< "Compute: frame " << f << ", " << (root ? "root channel " : "channel ")
                      << c << ": " << lct::describe(log.status) << lct::adviceFor(log.status, p)
                      << ".");
        return 0;
      }
      if (p == lct::Parametrisation::MatrixLog && previous &&
        (lct::rotationPart(log.value) - lct::rotationPart(*previous)).norm() > kBranchJump)
      {
        vtkErrorMacro(<< "Compute: " << (root ? "root channel " : "channel ") << c
                      << " turns through 180 degrees between frames " << f - 1 << " and " << f
                      << ", where the principal matrix log jumps by 2 pi (use the Polar "
                         "parametrisation, which keeps the logs continuous).");
        return 0;
      }
      channelLogs[static_cast<std::size_t>(f)] = log.value;
    }
    if (root)
    {
      rootMean = lct::meanLog(channelLogs.data(), channelLogs.size());
      continue;
    }
    const int s = slot[static_cast<std::size_t>(c)];
    for (int f = 0; f < frames; ++f)
    {
      logs[static_cast<std::size_t>(f) * analysed + s] = channelLogs[static_cast<std::size_t>(f)];
    }
  }
  auto pca = lct::sequencePCA(
    logs.data(), frames, analysed, weights.data(), this->MaximumNumberOfComponents);
  if (!pca)
  {
    vtkErrorMacro(<< "Compute: " << lct::describe(pca.status) << ".");
    return 0;
  }
  in.Pca = std::move(pca.value);
  in.Slot = std::move(slot);
  in.RootMean = rootMean;
  in.HasAnalysis = true;
  in.ComputeTime.Modified();
  return 1;
}

//------------------------------------------------------------------------------
bool vtkTransformSequencePCA::Analysed(const char* caller, const void* output)
{
  if (!output)
  {
    vtkErrorMacro(<< caller << ": null output.");
    return false;
  }
  const Internals& in = *this->Internal;
  if (!in.HasAnalysis || in.ComputeTime.GetMTime() < this->GetMTime())
  {
    vtkErrorMacro(<< caller << ": "
                  << (in.HasAnalysis ? "the input changed since Compute(): call it again"
                                     : "no analysis (Compute() first)")
                  << ".");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::Output(const double log[12], vtkMatrix4x4* result, const char* caller)
{
  const auto m =
    lct::exponential(Eigen::Map<const lct::LogCoords>(log), toCore(this->Parametrisation));
  if (!m)
  {
    vtkErrorMacro(<< caller << ": the transform is not representable: " << lct::describe(m.status)
                  << "; result unchanged.");
    return 0;
  }
  const RowMajor4 rows = m.value;
  result->DeepCopy(rows.data());
  return 1;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetNumberOfComponents()
{
  return this->Internal->HasAnalysis ? this->Internal->Pca.size() : 0;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetExplainedVariance(vtkDoubleArray* fractions)
{
  if (!this->Analysed("GetExplainedVariance", fractions))
  {
    return 0;
  }
  const lct::SequencePCA& pca = this->Internal->Pca;
  fractions->SetNumberOfComponents(1);
  fractions->SetNumberOfTuples(pca.size());
  for (int i = 0; i < pca.size(); ++i)
  {
    fractions->SetValue(i, pca.varianceShare(i));
  }
  return 1;
}

//------------------------------------------------------------------------------
double vtkTransformSequencePCA::GetExplainedFraction(int components)
{
  if (components < 0)
  {
    vtkErrorMacro(<< "GetExplainedFraction: " << components
                  << " components: the count must be 0 or more.");
    return 0.0;
  }
  return this->Analysed("GetExplainedFraction", this)
    ? this->Internal->Pca.explainedFraction(components)
    : 0.0;
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetReconstructedTransform(
  int frame, int channel, int components, vtkMatrix4x4* result)
{
  const char* caller = "GetReconstructedTransform";
  if (!this->Analysed(caller, result))
  {
    return 0;
  }
  const Internals& in = *this->Internal;
  if (frame < 0 || frame >= in.Frames() || channel < 0 || channel >= in.Channels)
  {
    vtkErrorMacro(<< caller << ": frame " << frame << ", channel " << channel << " is outside the "
                  << in.Frames() << " x " << in.Channels << " input.");
    return 0;
  }
  if (components < 0)
  {
    vtkErrorMacro(<< caller << ": " << components
                  << " components: the count must be 0 or more; result unchanged.");
    return 0;
  }
  const int s = in.Slot[static_cast<std::size_t>(channel)];
  if (s < 0)
  {
    const RowMajor4 rows = in.At(frame, channel);
    result->DeepCopy(rows.data());
    return 1;
  }
  const auto log = lct::reconstructLog(in.Pca, frame, s, components);
  if (!log)
  {
    vtkErrorMacro(<< caller << ": " << lct::describe(log.status) << "; result unchanged.");
    return 0;
  }
  return this->Output(log.value.data(), result, caller);
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetEigenMotion(
  int component, int channel, double s, vtkMatrix4x4* result)
{
  const char* caller = "GetEigenMotion";
  if (!this->Analysed(caller, result))
  {
    return 0;
  }
  const Internals& in = *this->Internal;
  if (component < 0 || component >= in.Pca.size() || channel < 0 || channel >= in.Channels ||
    !std::isfinite(s))
  {
    vtkErrorMacro(<< caller << ": component " << component << " of " << in.Pca.size()
                  << ", channel " << channel << " of " << in.Channels
                  << ", s = " << lct::formatNumber(s) << ": out of range.");
    return 0;
  }
  const int slot = in.Slot[static_cast<std::size_t>(channel)];
  if (slot < 0)
  {
    return this->GetMeanTransform(channel, result);
  }
  const auto log = lct::componentLog(in.Pca, component, slot, s);
  if (!log)
  {
    vtkErrorMacro(<< caller << ": " << lct::describe(log.status) << "; result unchanged.");
    return 0;
  }
  return this->Output(log.value.data(), result, caller);
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetMeanTransform(int channel, vtkMatrix4x4* result)
{
  const char* caller = "GetMeanTransform";
  if (!this->Analysed(caller, result))
  {
    return 0;
  }
  const Internals& in = *this->Internal;
  if (channel < 0 || channel >= in.Channels)
  {
    vtkErrorMacro(<< caller << ": channel " << channel << " is outside [0, " << in.Channels
                  << ").");
    return 0;
  }
  const int slot = in.Slot[static_cast<std::size_t>(channel)];
  if (slot >= 0)
  {
    return this->Output(in.Pca.means[static_cast<std::size_t>(slot)].data(), result, caller);
  }
  // The root: the mean of its logs, taken (continuous in time) by Compute.
  return this->Output(in.RootMean.data(), result, caller);
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::GetScores(int frame, vtkDoubleArray* scores)
{
  if (!this->Analysed("GetScores", scores))
  {
    return 0;
  }
  const lct::SequencePCA& pca = this->Internal->Pca;
  if (frame < 0 || frame >= pca.frames)
  {
    vtkErrorMacro(<< "GetScores: frame " << frame << " is outside [0, " << pca.frames << ").");
    return 0;
  }
  scores->SetNumberOfComponents(1);
  scores->SetNumberOfTuples(pca.size());
  for (int i = 0; i < pca.size(); ++i)
  {
    scores->SetValue(i, pca.scores(frame, i));
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkTransformSequencePCA::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Parametrisation: " << lct::name(toCore(this->Parametrisation)) << "\n";
  os << indent << "Frames: " << this->GetNumberOfFrames() << "\n";
  os << indent << "Channels: " << this->GetNumberOfChannels() << "\n";
  os << indent << "RootChannel: " << this->RootChannel << "\n";
  os << indent << "MaximumNumberOfComponents: " << this->MaximumNumberOfComponents << "\n";
  os << indent << "NumberOfComponents: " << this->GetNumberOfComponents() << "\n";
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::SetParametrisation(int value)
{
  return vtkLCTCheckedSet::Set(this, "Parametrisation", this->Parametrisation, value,
    static_cast<int>(POLAR), static_cast<int>(MATRIX_LOG));
}

//------------------------------------------------------------------------------
int vtkTransformSequencePCA::SetMaximumNumberOfComponents(int value)
{
  return vtkLCTCheckedSet::Set(this, "MaximumNumberOfComponents", this->MaximumNumberOfComponents,
    value, static_cast<int>(0), static_cast<int>(VTK_INT_MAX));
}
