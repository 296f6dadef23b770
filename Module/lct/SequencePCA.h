/**
 * @file SequencePCA.h
 * @brief Principal component analysis of a sequence of transforms in log space (Alexa 2002
 *        §6.3).
 *
 * An animation of C channels (joints, objects) over F frames is an F x 12C matrix of log
 * coordinates, one row per frame. Because log coordinates form a vector space, ordinary PCA
 * applies: Alexa writes the log matrices of each frame as a row and takes the SVD, finding that
 * 10 components reproduce a 580-frame, 17-joint walk.
 *
 * Here the analysis is tangent PCA at the per-channel mean: each channel's logs are centred at
 * their mean log (the log-space mean, which for the Polar coordinates, a Euclidean R^12 in which
 * blends are sums, is the Frechet mean of the parametrisation's metric), then the centred rows
 * are decomposed. The inner product is the one of lct/LogBasis.h (Alexa's entry-wise product of
 * log matrices) times an optional weight per channel, so the components minimise
 *
 *   sum_f sum_c w_c || log T_fc - mean_c - sum_i score_fi d_ic ||^2
 *
 * over every choice of r directions (Eckart-Young). Weights express how much a channel's error
 * matters (e.g. how far down a skeleton it travels). Rotation branches are the caller's: give
 * logs that are continuous in time (lct::logarithm with the previous frame as reference), or a
 * channel that turns through 180 degrees jumps by 2 pi and the components model the jump.
 */
#ifndef lct_SequencePCA_h
#define lct_SequencePCA_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <vector>

namespace lct
{

/// The principal components of F frames x C channels of log coordinates.
struct SequencePCA
{
  int frames = 0;
  int channels = 0;
  /// The mean log of each channel (size C).
  std::vector<LogCoords> means;
  /// The channel weights the analysis used (size C, all > 0).
  std::vector<double> weights;
  /// The principal directions d_i as columns (12C x k), in log coordinates (unweighted), in
  /// order of decreasing singular value; orthonormal in the weighted inner product.
  Eigen::MatrixXd components;
  /// All min(F, 12C) singular values of the weighted, centred data, descending: sigma_i^2 / F
  /// is the (weighted) variance along component i.
  Eigen::VectorXd singularValues;
  /// score_fi: the coordinates of frame f along component i (F x k).
  Eigen::MatrixXd scores;

  int size() const noexcept { return static_cast<int>(this->components.cols()); }

  /// The fraction of the total (weighted) variance that the first r kept components explain (r
  /// clamped to the kept ones, as the reconstruction is).
  double explainedFraction(int r) const noexcept;

  /// The fraction of the total variance along one component (0 outside [0, size of
  /// singularValues)).
  double varianceShare(int component) const noexcept;
};

/// The largest ratio between two channel weights. The data are scaled by sqrt(weight) before the
/// SVD, whose singular vectors are accurate to ~eps sigma_max: a channel weighted 1e-16 of the
/// largest keeps ~8 digits, one weighted 1e-32 would be noise, so a wider spread is refused
/// rather than losing channels silently.
constexpr double kMaxChannelWeightRatio = 1e16;

/// The PCA of `logs` (frame-major: logs[f * channels + c]), keeping at most maximumComponents
/// components (all the non-zero ones when 0). `weights` (size channels, or null for all 1) must
/// be finite and positive, within kMaxChannelWeightRatio of each other. Fails with
/// InvalidArgument (no frames or channels, a bad weight or spread of weights, a negative
/// maximumComponents), NonFinite (a non-finite log) or OutOfRange (the centred data overflow).
VTKLCT_EXPORT Result<SequencePCA> sequencePCA(const LogCoords* logs, int frames, int channels,
  const double* weights = nullptr, int maximumComponents = 0);

/// mean_c + sum_{i < r} score_fi d_ic: frame f, channel c reconstructed from the first r
/// components (r is clamped to [0, size()]). InvalidArgument for f or c out of range.
VTKLCT_EXPORT Result<LogCoords> reconstructLog(
  const SequencePCA& pca, int frame, int channel, int components);

/// mean_c + s sigma_i / sqrt(F) d_ic: channel c of the i-th "eigen-motion" at s standard
/// deviations (Alexa's Figure 5). InvalidArgument for i or c out of range; OutOfRange on overflow.
VTKLCT_EXPORT Result<LogCoords> componentLog(
  const SequencePCA& pca, int component, int channel, double s);

} // namespace lct

#endif
