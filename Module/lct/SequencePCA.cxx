#include "lct/SequencePCA.h"

#include "lct/Conditioning.h"
#include "lct/LogBasis.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>

namespace lct
{

double SequencePCA::varianceShare(int component) const noexcept
{
  const Eigen::Index n = this->singularValues.size();
  if (component < 0 || component >= n || !(this->singularValues[0] > 0.0))
  {
    return 0.0;
  }
  // In units of the largest singular value, so that no square overflows (sigma ~ 1e200).
  const Eigen::VectorXd unit = this->singularValues / this->singularValues[0];
  const double s = unit[component];
  return s * s / unit.squaredNorm();
}

double SequencePCA::explainedFraction(int r) const noexcept
{
  const Eigen::Index n = this->singularValues.size();
  if (n == 0 || !(this->singularValues[0] > 0.0))
  {
    return r > 0 ? 1.0 : 0.0;
  }
  // Only the kept components explain anything: with 1 kept, asking for 5 read 100 % while the
  // reconstruction from 5 uses the 1 (and was off by 1.04).
  const Eigen::Index k = std::clamp<Eigen::Index>(r, 0, std::min<Eigen::Index>(n, this->size()));
  const Eigen::VectorXd unit = this->singularValues / this->singularValues[0];
  return unit.head(k).squaredNorm() / unit.squaredNorm();
}

Result<SequencePCA> sequencePCA(
  const LogCoords* logs, int frames, int channels, const double* weights, int maximumComponents)
{
  using R = Result<SequencePCA>;
  if (!logs || frames <= 0 || channels <= 0 || maximumComponents < 0)
  {
    return R::failure(Status::InvalidArgument);
  }
  SequencePCA pca;
  pca.frames = frames;
  pca.channels = channels;
  pca.weights.assign(static_cast<std::size_t>(channels), 1.0);
  if (weights)
  {
    for (int c = 0; c < channels; ++c)
    {
      if (!(std::isfinite(weights[c]) && weights[c] > 0.0))
      {
        return R::failure(Status::InvalidArgument);
      }
      pca.weights[static_cast<std::size_t>(c)] = weights[c];
    }
    const auto range = std::minmax_element(pca.weights.begin(), pca.weights.end());
    if (*range.second / kMaxChannelWeightRatio > *range.first)
    {
      return R::failure(Status::InvalidArgument);
    }
  }
  const std::size_t count = static_cast<std::size_t>(frames) * static_cast<std::size_t>(channels);
  if (!std::all_of(logs, logs + count, [](const LogCoords& c) { return c.allFinite(); }))
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Index columns = 12 * static_cast<Eigen::Index>(channels);
  // D = diag(sqrt(w_c) W) per channel: the weighted inner product is the Euclidean one of D c.
  Eigen::VectorXd metric(columns);
  for (int c = 0; c < channels; ++c)
  {
    pca.means.push_back(
      meanLog(logs + c, static_cast<std::size_t>(frames), static_cast<std::size_t>(channels)));
    metric.segment<12>(12 * c) =
      std::sqrt(pca.weights[static_cast<std::size_t>(c)]) * logMetricRoot();
  }
  Eigen::MatrixXd rows(frames, columns);
  for (int f = 0; f < frames; ++f)
  {
    for (int c = 0; c < channels; ++c)
    {
      rows.block<1, 12>(f, 12 * c) =
        (logs[static_cast<std::size_t>(f) * static_cast<std::size_t>(channels) +
           static_cast<std::size_t>(c)] -
          pca.means[static_cast<std::size_t>(c)])
          .transpose();
    }
  }
  if (!rows.allFinite() || !std::all_of(pca.means.begin(), pca.means.end(), [](const LogCoords& m) {
        return m.allFinite();
      }))
  {
    return R::failure(Status::OutOfRange);
  }
  // Scaled by a power of two (exact) so that the SVD's squares neither overflow nor underflow.
  const int e = unitScaleExponent(rows);
  rows = scaledByPowerOfTwo(rows, -e) * metric.asDiagonal();
  // Divide and conquer: the data of a long clip (thousands of frames, hundreds of columns) is
  // where one-sided Jacobi is slow; BDCSVD falls back to Jacobi for small blocks itself.
  const Eigen::BDCSVD<Eigen::MatrixXd> svd(rows, Eigen::ComputeThinU | Eigen::ComputeThinV);
  const Eigen::VectorXd sigma = svd.singularValues();
  // Components with a non-zero singular value (to rounding: relative 1e-14 of the largest).
  Eigen::Index kept = 0;
  while (kept < sigma.size() && sigma[kept] > 1e-14 * sigma[0])
  {
    ++kept;
  }
  if (maximumComponents > 0)
  {
    kept = std::min<Eigen::Index>(kept, maximumComponents);
  }
  pca.singularValues = scaledByPowerOfTwo(sigma, e);
  pca.components = metric.cwiseInverse().asDiagonal() * svd.matrixV().leftCols(kept);
  pca.scores = scaledByPowerOfTwo(
    Eigen::MatrixXd(svd.matrixU().leftCols(kept) * sigma.head(kept).asDiagonal()), e);
  if (!pca.singularValues.allFinite() || !pca.scores.allFinite())
  {
    return R::failure(Status::OutOfRange);
  }
  return { std::move(pca), Status::Ok };
}

Result<LogCoords> reconstructLog(const SequencePCA& pca, int frame, int channel, int components)
{
  if (frame < 0 || frame >= pca.frames || channel < 0 || channel >= pca.channels)
  {
    return Result<LogCoords>::failure(Status::InvalidArgument);
  }
  const Eigen::Index r = std::clamp<Eigen::Index>(components, 0, pca.size());
  if (r == 0)
  {
    // The mean alone (and no block of an empty component matrix, whose data pointer is null:
    // FuzzAnalysis A3).
    return { pca.means[static_cast<std::size_t>(channel)], Status::Ok };
  }
  const LogCoords c = pca.means[static_cast<std::size_t>(channel)] +
    pca.components.block(12 * channel, 0, 12, r) * pca.scores.row(frame).head(r).transpose();
  if (!c.allFinite())
  {
    return Result<LogCoords>::failure(Status::OutOfRange);
  }
  return { c, Status::Ok };
}

Result<LogCoords> componentLog(const SequencePCA& pca, int component, int channel, double s)
{
  if (component < 0 || component >= pca.size() || channel < 0 || channel >= pca.channels)
  {
    return Result<LogCoords>::failure(Status::InvalidArgument);
  }
  if (!std::isfinite(s))
  {
    return Result<LogCoords>::failure(Status::NonFinite);
  }
  const double deviation = pca.singularValues[component] / std::sqrt(double(pca.frames));
  const LogCoords c = pca.means[static_cast<std::size_t>(channel)] +
    (s * deviation) * pca.components.block<12, 1>(12 * channel, component);
  if (!c.allFinite())
  {
    return Result<LogCoords>::failure(Status::OutOfRange);
  }
  return { c, Status::Ok };
}

} // namespace lct
