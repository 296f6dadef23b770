/**
 * @file LogBasis.h
 * @brief Factoring transformations onto a basis in log space (Alexa 2002 §6.2).
 *
 * Log coordinates form a vector space, so a transform T can be written as the "linear
 * combination" T = exp(sum_i x_i log B_i) of basis transforms B_i, and a transform outside their
 * span has a nearest transform inside it ("constraining a transform"). The coefficients x
 * minimise ||log T - o - sum_i x_i log B_i|| for an origin o (0, or the mean of the examples a
 * centred basis was built from).
 *
 * Alexa inverts the Gram matrix V_ij = <log B_i, log B_j> by SVD to learn the basis's rank and
 * condition, and maps the inner products <log T, log B_j> through V^-1. We take the SVD of the
 * basis itself instead, W B = P diag(sigma) Q^T with W the inner product's square root below:
 * the Gram matrix is B^T W^2 B, its singular values are sigma^2, and not forming it keeps twice
 * the digits (the coefficients are those of V^-1 to rounding). The rank counts the sigma_i above
 * rankTolerance sigma_1; the reported condition number is that of V, (sigma_1 / sigma_k)^2.
 *
 * Inner product: Alexa's entry-wise product of the 4x4 log matrices (eq. 8),
 * <A, B> = sum_ij a_ij b_ij. In log coordinates c = (u, w, Y) (lct/LogCoords.h) the log matrix is
 * [hat(w) + Y, u; 0 0], and since skew and symmetric parts are orthogonal,
 *
 *   <a, b> = u . u' + 2 w . w' + sum_k Y_kk Y'_kk + 2 sum_{k<l} Y_kl Y'_kl,
 *
 * i.e. W = diag(1, 1, 1, sqrt2, sqrt2, sqrt2, 1, 1, 1, sqrt2, sqrt2, sqrt2). The same formula is
 * used for the Polar coordinates (l, w, Y) (the matrix [hat(w) + Y, l; 0 0] of Kaji & Ochiai's
 * R^12). For rotations, <log R(a, theta), log R(b, phi)> = 2 theta phi (a . b): twice the dot
 * product of the rotation vectors. With Alexa's basis R_x(phi), R_y(phi), R_z(phi), the inner
 * products of R(a, theta) with the basis are therefore 2 phi theta a, and its coefficients x
 * (through the inverse Gram matrix, 2 phi^2 I) theta / phi a: the axis is x / |x| and the angle
 * phi |x| (the paper prints "(x + y + z) / phi", a misprint).
 *
 * A basis has at most 12 independent vectors (the dimension of the log space), so every size
 * here is fixed at compile time and nothing allocates.
 */
#ifndef lct_LogBasis_h
#define lct_LogBasis_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <cstddef>

namespace lct
{

/// The dimension of the log space: no basis has more independent vectors.
constexpr int kLogDimension = 12;

/// The accuracy of the logs the core computes (lct::logarithm), in units of eps in the log norm:
/// |log M computed - log M exact| <= kLogAccuracy eps (1 + |log M|) for the exact log of the
/// double matrix M (first order). The largest part near the identity is polarLog's rigid snap
/// (a stretch within 8 eps of I has log 0 exactly, |Y| up to 24 eps in the log norm); measured
/// over near-identity and general maps against a long double oracle: at most 14 eps (1 + |c|),
/// Unit.LogBasis.FactorErrorBoundHoldsForBasesNearTheIdentity. The round trip through a matrix
/// rounded to double adds the log's sensitivity to that rounding, about eps cond(A) (1 + |c|).
constexpr double kLogAccuracy = 64.0;

/// Relative singular value below which a basis direction counts as dependent: sigma_i <=
/// 1e-8 sigma_1, a Gram condition number of 1e16, where double precision keeps no digit of the
/// coefficients.
constexpr double kDefaultRankTolerance = 1e-8;

/// Coefficients: one per basis vector, at most 12.
using BasisCoefficients = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kLogDimension, 1>;

/// W, the square root of the inner product's metric: 1 on translations and diagonal stretches,
/// sqrt 2 on the rotation vector and the off-diagonal stretches (twice in the log matrix).
VTKLCT_EXPORT const LogCoords& logMetricRoot() noexcept;

/// The mean of logs[0], logs[stride], ..., logs[(count - 1) stride] (count > 0), in two passes
/// (the second recovers what the first lost to cancellation); overflows only when the exact
/// mean's terms do (|c| near the top of the double range, of both signs).
VTKLCT_EXPORT LogCoords meanLog(
  const LogCoords* logs, std::size_t count, std::size_t stride = 1) noexcept;

/// The inner product <a, b> of the log matrices of two log coordinates (see the file comment).
VTKLCT_EXPORT double logInnerProduct(const LogCoords& a, const LogCoords& b) noexcept;

/// sqrt(<a, a>), without overflow for any finite coordinates.
VTKLCT_EXPORT double logNorm(const LogCoords& a) noexcept;

/// A basis of log coordinates, analysed: the subspace origin + span(vectors).
struct LogBasis
{
  /// The basis vectors log B_i as columns (1..12 of them).
  Eigen::Matrix<double, kLogDimension, Eigen::Dynamic, 0, kLogDimension, kLogDimension> vectors;
  /// The point the span is taken about: 0 for a basis of transforms, the mean log of the
  /// examples for a centred basis from examples.
  LogCoords origin = LogCoords::Zero();
  /// Singular values of W vectors, descending (their squares are those of the Gram matrix).
  BasisCoefficients singularValues;
  /// The number of singular values above rankTolerance * singularValues[0].
  int rank = 0;
  /// The rank tolerance the basis was analysed with.
  double rankTolerance = kDefaultRankTolerance;
  /// The Gram matrix's condition number (sigma_1 / sigma_k)^2; +Inf when rank < count.
  double conditionNumber = 0.0;

  int size() const noexcept { return static_cast<int>(this->vectors.cols()); }
  bool fullRank() const noexcept { return this->rank == this->size(); }

  /// P: the first `rank` left singular vectors of W vectors, an orthonormal basis of W span,
  /// padded with zero columns to 12 (fixed-size products are several times faster).
  Eigen::Matrix<double, kLogDimension, kLogDimension> range = decltype(range)::Zero();
  /// Q diag(1 / sigma) P^T over the first `rank` singular values, padded with zero rows to 12:
  /// x = (solver W (c - origin)).head(size()) (the least-norm coefficients; the only ones when
  /// the basis has full rank).
  Eigen::Matrix<double, kLogDimension, kLogDimension> solver = decltype(solver)::Zero();
};

/// The analysed basis of `count` log vectors about `origin`. Fails with InvalidArgument (count
/// 0 or above 12, a rank tolerance outside [0, 1)) or NonFinite (a non-finite vector or
/// origin). A rank-deficient basis is a valid result (rank < count, see factorOntoBasis).
VTKLCT_EXPORT Result<LogBasis> analyseBasis(const LogCoords* vectors, std::size_t count,
  const LogCoords& origin = LogCoords::Zero(), double rankTolerance = kDefaultRankTolerance);

/// A basis found from examples, with what it leaves out.
struct ExampleBasis
{
  /// Orthonormal vectors (in <.,.>), the principal directions of the examples in order of
  /// decreasing spread; origin = their mean when centred, else 0.
  LogBasis basis;
  /// All min(count, 12) singular values of the example matrix (rows W (c_i - origin)),
  /// descending: singularValues[i]^2 / count is the mean square spread along direction i, kept
  /// or not (the kept ones are the first basis.size()).
  BasisCoefficients singularValues;
};

/// The orthonormal basis of the span of `count` example logs (Alexa §6.2: the logs written as
/// rows of a matrix and decomposed by SVD), about their mean when `centred`, keeping the
/// directions whose singular value exceeds rankTolerance times the largest, and at most
/// `maximumRank` of them when it is positive. Fails with InvalidArgument (no examples, a
/// tolerance outside [0, 1), a negative maximumRank), NonFinite (a non-finite example),
/// OutOfRange (the mean or the centred logs overflow), or RankDeficient when the examples span
/// nothing (all equal to the origin).
VTKLCT_EXPORT Result<ExampleBasis> basisFromExamples(const LogCoords* examples, std::size_t count,
  bool centred, double rankTolerance = kDefaultRankTolerance, int maximumRank = 0);

/// The factoring of c onto a basis.
struct BasisFactors
{
  BasisCoefficients coefficients; ///< x, one per basis vector
  LogCoords projection;           ///< origin + sum_i x_i vectors_i: the nearest point of the span
  double residual = 0.0;          ///< logNorm(c - projection): the distance from the span
  /// A bound on |x - x exact|_2, x exact the coefficients of the exact log of the matrix c was
  /// computed from (see coefficientErrorBound).
  double errorBound = 0.0;
};

/// The error bound of coefficients x factored from c, a log computed by lct::logarithm: an
/// error e in c moves the least-squares coefficients by at most |W e| / sigma_min, the norm of
/// the solver (Q diag(1/sigma) P^T), so
///
///   |x - x exact|_2 <= kLogAccuracy eps (1 + |c| + |origin|) / sigma_min + k eps |x|_2,
///
/// the last term the rounding of the solve. This is the conditioning of factoring, not of the
/// basis alone: the Gram condition (sigma_1 / sigma_min)^2 can be 1 while sigma_min is tiny, a
/// basis of transforms close to the identity (|log B_i| ~ 1e-12). Such a basis tells apart
/// transforms near the identity only as far as a double matrix holds them: an entry 1 + 3e-14
/// keeps its 3e-14 to 1.1e-16, so their coefficients carry eps / sigma_min (Testing/Fuzz
/// README, A4). +Inf when that overflows.
VTKLCT_EXPORT double coefficientErrorBound(
  const LogBasis& basis, const LogCoords& c, const BasisCoefficients& x) noexcept;

/// Coefficients of c (Alexa §6.2), the residual and the coefficients' error bound. Fails with
/// RankDeficient when the basis is (the coefficients are not unique; projectOntoBasis is still
/// defined), NonFinite for a non-finite c, OutOfRange when the coefficients overflow.
VTKLCT_EXPORT Result<BasisFactors> factorOntoBasis(const LogBasis& basis, const LogCoords& c);

/// The nearest point of the subspace to c, with the residual; defined for rank-deficient
/// bases too (the span of the independent directions), where `coefficients` are the ones of
/// least norm (unique when the basis has full rank). Fails with NonFinite or OutOfRange.
VTKLCT_EXPORT Result<BasisFactors> projectOntoBasis(const LogBasis& basis, const LogCoords& c);

/// origin + sum_i x_i vectors_i. Fails with InvalidArgument (a coefficient count other than the
/// basis size), NonFinite (a non-finite coefficient) or OutOfRange (overflow).
VTKLCT_EXPORT Result<LogCoords> combineBasis(
  const LogBasis& basis, const BasisCoefficients& coefficients);

} // namespace lct

#endif
