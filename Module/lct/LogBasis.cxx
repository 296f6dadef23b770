#include "lct/LogBasis.h"

#include "lct/Conditioning.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{
namespace
{

using LogVector = Eigen::Matrix<double, kLogDimension, 1>;
using BasisMatrix =
  Eigen::Matrix<double, kLogDimension, Eigen::Dynamic, 0, kLogDimension, kLogDimension>;

} // namespace

const LogCoords& logMetricRoot() noexcept
{
  static const LogVector w = [] {
    LogVector v;
    const double r = std::sqrt(2.0);
    v << 1, 1, 1, r, r, r, 1, 1, 1, r, r, r;
    return v;
  }();
  return w;
}

namespace
{
const LogCoords& metricRoot()
{
  return logMetricRoot();
}

bool allFinite(const LogCoords& c)
{
  return c.allFinite();
}

/// The Euclidean norm without overflow or underflow: scaled by the largest entry (Eigen's
/// stableNorm does the same in blocks, at several times the cost for 12 or 18 entries).
template <typename Derived>
double scaledNorm(const Eigen::MatrixBase<Derived>& v)
{
  const double largest = v.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return largest;
  }
  return largest * (v / largest).norm();
}

/// W d with d = c - origin; fails when the difference overflows.
Result<LogVector> weightedOffset(const LogBasis& basis, const LogCoords& c)
{
  if (!allFinite(c))
  {
    return Result<LogVector>::failure(Status::NonFinite);
  }
  const LogVector d = metricRoot().cwiseProduct(c - basis.origin);
  if (!d.allFinite())
  {
    return Result<LogVector>::failure(Status::OutOfRange);
  }
  return { d, Status::Ok };
}

/// origin + W^-1 (P P^T W d), the residual |W d - P P^T W d|, the least-norm coefficients and
/// their error bound.
Result<BasisFactors> factor(const LogBasis& basis, const LogCoords& c, const LogVector& weighted)
{
  BasisFactors f;
  const LogVector inSpan = basis.range * (basis.range.transpose() * weighted);
  f.residual = scaledNorm(weighted - inSpan);
  f.projection = basis.origin + inSpan.cwiseQuotient(metricRoot());
  f.coefficients = (basis.solver * weighted).head(basis.size());
  if (!f.coefficients.allFinite() || !f.projection.allFinite() || !std::isfinite(f.residual))
  {
    return Result<BasisFactors>::failure(Status::OutOfRange);
  }
  f.errorBound = coefficientErrorBound(basis, c, f.coefficients);
  return { f, Status::Ok };
}

} // namespace

LogCoords meanLog(const LogCoords* logs, std::size_t count, std::size_t stride) noexcept
{
  // Two passes: the mean of c_i / n (no overflow for finite input), then the mean of the
  // residuals, which recovers the digits the first pass lost to cancellation.
  const double n = static_cast<double>(count);
  LogCoords mean = LogCoords::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    mean += logs[i * stride] / n;
  }
  LogCoords correction = LogCoords::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    correction += (logs[i * stride] - mean) / n;
  }
  return mean + correction;
}

double logInnerProduct(const LogCoords& a, const LogCoords& b) noexcept
{
  return a.cwiseProduct(metricRoot()).dot(b.cwiseProduct(metricRoot()));
}

double logNorm(const LogCoords& a) noexcept
{
  // |W a| without forming sqrt(2) a (which could overflow): the entries weighted by sqrt 2 are
  // counted twice.
  Eigen::Matrix<double, 18, 1> twice;
  twice << a, rotationPart(a), a.segment<3>(9);
  return scaledNorm(twice);
}

Result<LogBasis> analyseBasis(
  const LogCoords* vectors, std::size_t count, const LogCoords& origin, double rankTolerance)
{
  if (!vectors || count == 0 || count > static_cast<std::size_t>(kLogDimension) ||
    !(rankTolerance >= 0.0 && rankTolerance < 1.0))
  {
    return Result<LogBasis>::failure(Status::InvalidArgument);
  }
  if (!allFinite(origin) || !std::all_of(vectors, vectors + count, allFinite))
  {
    return Result<LogBasis>::failure(Status::NonFinite);
  }
  const int k = static_cast<int>(count);
  LogBasis basis;
  basis.origin = origin;
  basis.rankTolerance = rankTolerance;
  basis.vectors.resize(kLogDimension, k);
  for (int i = 0; i < k; ++i)
  {
    basis.vectors.col(i) = vectors[i];
  }
  // The SVD of W B scaled by a power of two, so that no square in it overflows or underflows.
  const int e = unitScaleExponent(basis.vectors);
  const BasisMatrix weighted = metricRoot().asDiagonal() * scaledByPowerOfTwo(basis.vectors, -e);
  // A dynamic matrix for the SVD: Eigen 3.4's QR preconditioner of JacobiSVD asserts on
  // fixed-maximum-size matrices with more rows than columns (found by FuzzAnalysis; in Release,
  // where the assertion is off, it wrote past the workspace).
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(
    Eigen::MatrixXd(weighted), Eigen::ComputeThinU | Eigen::ComputeThinV);
  const BasisCoefficients sigma = svd.singularValues();
  int rank = 0;
  while (rank < k && sigma[rank] > 0.0 && sigma[rank] > rankTolerance * sigma[0])
  {
    ++rank;
  }
  basis.rank = rank;
  basis.singularValues = scaledByPowerOfTwo(sigma, e);
  basis.conditionNumber = rank == k ? (sigma[0] / sigma[k - 1]) * (sigma[0] / sigma[k - 1])
                                    : std::numeric_limits<double>::infinity();
  basis.range.leftCols(rank) = svd.matrixU().leftCols(rank);
  // The solver in the input's units: 1 / (sigma scale) may overflow for bases near the bottom
  // of the double range, which is refused rather than handed on.
  const BasisCoefficients inverse = scaledByPowerOfTwo(sigma.head(rank), e).cwiseInverse();
  basis.solver.topRows(k) =
    svd.matrixV().leftCols(rank) * inverse.asDiagonal() * svd.matrixU().leftCols(rank).transpose();
  if (!basis.singularValues.allFinite() || !basis.solver.allFinite())
  {
    return Result<LogBasis>::failure(Status::OutOfRange);
  }
  return { basis, Status::Ok };
}

Result<ExampleBasis> basisFromExamples(
  const LogCoords* examples, std::size_t count, bool centred, double rankTolerance, int maximumRank)
{
  if (!examples || count == 0 || !(rankTolerance >= 0.0 && rankTolerance < 1.0) || maximumRank < 0)
  {
    return Result<ExampleBasis>::failure(Status::InvalidArgument);
  }
  if (!std::all_of(examples, examples + count, allFinite))
  {
    return Result<ExampleBasis>::failure(Status::NonFinite);
  }
  const LogCoords origin = centred ? meanLog(examples, count) : LogCoords::Zero();
  Eigen::Matrix<double, Eigen::Dynamic, kLogDimension> rows(
    static_cast<Eigen::Index>(count), kLogDimension);
  for (std::size_t i = 0; i < count; ++i)
  {
    rows.row(static_cast<Eigen::Index>(i)) = (examples[i] - origin).transpose();
  }
  if (!origin.allFinite() || !rows.allFinite())
  {
    return Result<ExampleBasis>::failure(Status::OutOfRange);
  }
  const int e = unitScaleExponent(rows);
  rows = scaledByPowerOfTwo(rows, -e) * metricRoot().asDiagonal();
  // Column-pivoting QR first (JacobiSVD's preconditioner for tall matrices): O(count) work and
  // only the 12 x 12 right singular vectors are formed.
  const Eigen::JacobiSVD<Eigen::Matrix<double, Eigen::Dynamic, kLogDimension>,
    Eigen::ColPivHouseholderQRPreconditioner>
    svd(rows, Eigen::ComputeFullV);
  const BasisCoefficients sigma = svd.singularValues();
  const int available = static_cast<int>(sigma.size());
  const int limit = maximumRank > 0 ? std::min(maximumRank, available) : available;
  int rank = 0;
  while (rank < limit && sigma[rank] > 0.0 && sigma[rank] > rankTolerance * sigma[0])
  {
    ++rank;
  }
  if (rank == 0)
  {
    return Result<ExampleBasis>::failure(Status::RankDeficient);
  }
  LogCoords directions[kLogDimension];
  for (int i = 0; i < rank; ++i)
  {
    directions[i] = svd.matrixV().col(i).cwiseQuotient(metricRoot());
  }
  const auto basis = analyseBasis(directions, static_cast<std::size_t>(rank), origin, 0.5);
  if (!basis)
  {
    return Result<ExampleBasis>::failure(basis.status);
  }
  ExampleBasis result{ basis.value, scaledByPowerOfTwo(sigma, e) };
  result.basis.rankTolerance = rankTolerance;
  if (!result.singularValues.allFinite())
  {
    return Result<ExampleBasis>::failure(Status::OutOfRange);
  }
  return { result, Status::Ok };
}

Result<BasisFactors> factorOntoBasis(const LogBasis& basis, const LogCoords& c)
{
  const auto weighted = weightedOffset(basis, c);
  if (!weighted)
  {
    return Result<BasisFactors>::failure(weighted.status);
  }
  if (!basis.fullRank())
  {
    return Result<BasisFactors>::failure(Status::RankDeficient);
  }
  return factor(basis, c, weighted.value);
}

Result<BasisFactors> projectOntoBasis(const LogBasis& basis, const LogCoords& c)
{
  const auto weighted = weightedOffset(basis, c);
  if (!weighted)
  {
    return Result<BasisFactors>::failure(weighted.status);
  }
  return factor(basis, c, weighted.value);
}

double coefficientErrorBound(
  const LogBasis& basis, const LogCoords& c, const BasisCoefficients& x) noexcept
{
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const int k = basis.size();
  if (k == 0 || basis.rank < k || !(basis.singularValues[k - 1] > 0.0))
  {
    return std::numeric_limits<double>::infinity();
  }
  // Each term divided separately, so that nothing overflows before it must.
  const double sigmaMin = basis.singularValues[k - 1];
  const double logError = kLogAccuracy * eps * (1.0 + logNorm(c) + logNorm(basis.origin));
  const double bound = logError / sigmaMin + k * eps * scaledNorm(x) +
    // The solve's last bit, where the coefficients are subnormal.
    k * std::numeric_limits<double>::denorm_min();
  return std::isfinite(bound) ? bound : std::numeric_limits<double>::infinity();
}

Result<LogCoords> combineBasis(const LogBasis& basis, const BasisCoefficients& coefficients)
{
  if (coefficients.size() != basis.size())
  {
    return Result<LogCoords>::failure(Status::InvalidArgument);
  }
  if (!coefficients.allFinite())
  {
    return Result<LogCoords>::failure(Status::NonFinite);
  }
  const LogCoords c = basis.origin + basis.vectors * coefficients;
  if (!c.allFinite())
  {
    return Result<LogCoords>::failure(Status::OutOfRange);
  }
  return { c, Status::Ok };
}

} // namespace lct
