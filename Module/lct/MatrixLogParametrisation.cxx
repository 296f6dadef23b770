#include "lct/MatrixLogParametrisation.h"

#include "lct/AccurateMinors.h"
#include "lct/Affine.h"
#include "lct/AffineExp.h"
#include "lct/Conditioning.h"
#include "lct/DividedDifferences.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"
#include "lct/SVD3.h"
#include "lct/Sym3.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{

namespace
{

using Complex = std::complex<double>;

/// f(A) and f[A, x] t for the 4x4 block matrix [A t; 0 x] (x = 1 for log, 0 for exp): its
/// f is [f(A), g(A) t; 0, f(x)] with g(z) = f[z, x].
struct BlockFunction
{
  Eigen::Matrix3d linear;
  Eigen::Vector3d translation;
  Status status = Status::Ok;
  /// The eigenvalue closest to the negative real axis, by the ratio |Im| / -Re (infinite when
  /// every eigenvalue has a positive real part): where the log is ill-conditioned.
  double nearestToNegativeAxis = std::numeric_limits<double>::infinity();
};

/// f(B) for a 2x2 block B with eigenvalues mu0, mu1 from divided differences c0 = f[mu0],
/// c1 = f[mu0, mu1]: f(B) = c0 I + c1 (B - mu0 I), real for a real B (imaginary parts cancel).
Eigen::Matrix2d newtonForm2(const Eigen::Matrix2d& b, Complex c0, Complex c1, Complex mu0)
{
  Eigen::Matrix2d out = c1.real() * b;
  out.diagonal().array() += (c0 - c1 * mu0).real();
  return out;
}

/// The eigenvalues of a 2x2 block (a conjugate pair, or two real ones).
void blockEigenvalues(const Eigen::Matrix2d& b, Complex& mu0, Complex& mu1)
{
  const double half = 0.5 * (b(0, 0) + b(1, 1));
  const double d = 0.5 * (b(0, 0) - b(1, 1));
  const double discriminant = d * d + b(0, 1) * b(1, 0);
  if (discriminant < 0.0)
  {
    mu0 = Complex(half, std::sqrt(-discriminant));
    mu1 = std::conj(mu0);
  }
  else
  {
    const double r = std::sqrt(discriminant);
    mu0 = half + r;
    mu1 = half - r;
  }
}

/// f of [A t; 0 x] through the real Schur form A = Q T Q^T (Eigen's RealSchur): on a
/// quasi-triangular T every entry of f(T) is a sum of products of T's entries with divided
/// differences of f at T's eigenvalues (Higham, "Functions of Matrices", Thm 4.11; for a 2x2
/// block B above a 1x1 block y, f(T)_(B,y) = f[., y](B) T_(B,y), the solution of the Sylvester
/// equation). The divided differences are accurate for close and coincident nodes
/// (lct/DividedDifferences.h), and nothing is formed in the original basis, so spread spectra
/// (1e-6, 1, 1e6) keep all their digits, which the quadratic polynomial in A does not.
BlockFunction blockFunction(
  ScalarFunction f, const Eigen::Matrix3d& a, const Eigen::Vector3d& t, double extraNode)
{
  BlockFunction out;
  // The Schur form of A 2^-e is Q (T 2^-e) Q^T, exactly: Eigen's iteration forms norms and
  // squares of the entries, which overflow for entries near the end of the double range (exp
  // of coordinates ~1e308 did not converge), so it runs on the unit-size matrix.
  const int e = unitScaleExponent(a);
  const Eigen::RealSchur<Eigen::Matrix3d> schur(scaledByPowerOfTwo(a, -e));
  if (schur.info() != Eigen::Success)
  {
    out.status = Status::NumericalFailure;
    return out;
  }
  const Eigen::Matrix3d tm = scaledByPowerOfTwo(schur.matrixT(), e);
  const Eigen::Matrix3d& q = schur.matrixU();
  // Block structure: a 2x2 block at the top (rows 0-1), at the bottom (rows 1-2), or none.
  const bool blockTop = tm(1, 0) != 0.0;
  const bool blockBottom = !blockTop && tm(2, 1) != 0.0;
  Complex nodes[4];
  if (blockTop)
  {
    blockEigenvalues(tm.topLeftCorner<2, 2>(), nodes[0], nodes[1]);
    nodes[2] = tm(2, 2);
  }
  else if (blockBottom)
  {
    nodes[0] = tm(0, 0);
    blockEigenvalues(tm.bottomRightCorner<2, 2>(), nodes[1], nodes[2]);
  }
  else
  {
    for (int i = 0; i < 3; ++i)
    {
      nodes[i] = tm(i, i);
    }
  }
  nodes[3] = extraNode;
  // Eigenvalues beyond 2^500 (or overflowing in the 2x2 block's discriminant) only come from
  // exp of huge coordinates: a real part beyond 710 overflows anyway, an imaginary one is an
  // angle with no digits left below a turn, and their divided differences would leave the range.
  constexpr double kLargestNode = 3.27e150; // ~2^500
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::abs(nodes[i]) <= kLargestNode))
    {
      out.status = Status::OutOfRange;
      return out;
    }
  }
  if (f == ScalarFunction::Exp)
  {
    for (int i = 0; i < 3; ++i)
    {
      // A turn wound beyond kMaxRotationWinding: the eigenvalues carry the angle to ~eps theta,
      // and the result would come back neither orthogonal nor the inverse of exp(-L) (found by
      // FuzzLogTransform: theta = 8e14 gave a "rotation" with rows of norm 1.06).
      if (std::abs(nodes[i].imag()) > kMaxRotationWinding)
      {
        out.status = Status::InaccurateResult;
        return out;
      }
    }
  }
  if (f != ScalarFunction::Exp)
  {
    for (int i = 0; i < 3; ++i)
    {
      if (nodes[i].imag() == 0.0 && nodes[i].real() <= 0.0)
      {
        out.status = Status::NoRealLogarithm;
        return out;
      }
      if (nodes[i].real() < 0.0)
      {
        out.nearestToNegativeAxis =
          std::min(out.nearestToNegativeAxis, std::abs(nodes[i].imag()) / -nodes[i].real());
      }
    }
  }
  const auto dd = dividedDifferences(f, nodes, 4);
  // F = f(T) and G = g(T), g(z) = f[z, x]: g's divided differences are f's with x appended
  // (mask bit 3).
  Eigen::Matrix3d fT = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d gT = Eigen::Matrix3d::Zero();
  for (int pass = 0; pass < 2; ++pass)
  {
    const unsigned x = pass == 0 ? 0u : 8u;
    Eigen::Matrix3d& m = pass == 0 ? fT : gT;
    if (blockTop)
    {
      const Eigen::Matrix2d b = tm.topLeftCorner<2, 2>();
      m.topLeftCorner<2, 2>() = newtonForm2(b, dd[1 | x], dd[3 | x], nodes[0]);
      m(2, 2) = dd[4 | x].real();
      // f[., y](B) T_(B,y) with y = T22.
      m.topRightCorner<2, 1>() =
        newtonForm2(b, dd[5 | x], dd[7 | x], nodes[0]) * tm.topRightCorner<2, 1>();
    }
    else if (blockBottom)
    {
      const Eigen::Matrix2d b = tm.bottomRightCorner<2, 2>();
      m(0, 0) = dd[1 | x].real();
      m.bottomRightCorner<2, 2>() = newtonForm2(b, dd[2 | x], dd[6 | x], nodes[1]);
      // T_(y,B) f[y, .](B) with y = T00.
      m.block<1, 2>(0, 1) = tm.block<1, 2>(0, 1) * newtonForm2(b, dd[3 | x], dd[7 | x], nodes[1]);
    }
    else
    {
      m(0, 0) = dd[1 | x].real();
      m(1, 1) = dd[2 | x].real();
      m(2, 2) = dd[4 | x].real();
      m(0, 1) = tm(0, 1) * dd[3 | x].real();
      m(1, 2) = tm(1, 2) * dd[6 | x].real();
      // Paths 0 -> 2 and 0 -> 1 -> 2; (T01 T12) f[...] is grouped to keep within range.
      m(0, 2) = tm(0, 2) * dd[5 | x].real() + tm(0, 1) * (tm(1, 2) * dd[7 | x].real());
    }
  }
  out.linear = q * fT * q.transpose();
  // g(T) (Q^T t) at the unit size of t: for t near DBL_MAX the products overflow before they
  // cancel (exp of -log M, the inverse of a map whose inverse vtkLogTransform checked finite).
  const int k = unitScaleExponent(t);
  const Eigen::Vector3d unitT = scaledByPowerOfTwo(t, -k);
  out.translation = scaledByPowerOfTwo(Eigen::Vector3d(q * (gT * (q.transpose() * unitT))), k);
  if (!out.linear.allFinite() || !out.translation.allFinite())
  {
    out.status = Status::OutOfRange;
  }
  return out;
}

/// Pairs with |Im| / -Re below this (turns beyond 135 degrees) are checked a posteriori.
constexpr double kCheckedPairSlope = 1.0;

/// Pairs with |Im| / -Re below this (turns within ~1e-6 rad of a half turn) are refused: there
/// the log's forward error, ~eps pi / slope, exceeds 1e-9, and the a posteriori round trip cannot
/// see it (exp maps the whole family of logs of a block near -I close to it). A rotation 2e-15
/// short of a half turn came back with a stretch of 0.33 in its log and passed the round trip.
constexpr double kRefusedPairSlope = 1e-6;

/// exp(log M) == M to 1e-12, relative, block by block (a large translation must not hide an
/// error in the linear part).
bool accurateRoundTrip(const Eigen::Matrix4d& back, const Eigen::Matrix4d& m)
{
  constexpr double kTolerance = 1e-12;
  const double linear = (back.topLeftCorner<3, 3>() - m.topLeftCorner<3, 3>()).norm();
  const double translation = (back.topRightCorner<3, 1>() - m.topRightCorner<3, 1>()).norm();
  return linear <= kTolerance * m.topLeftCorner<3, 3>().norm() &&
    translation <= kTolerance * std::max(1.0, m.topRightCorner<3, 1>().norm()) *
      std::max(1.0, m.topLeftCorner<3, 3>().norm());
}

LogCoords packLog(const Eigen::Matrix3d& logLinear, const Eigen::Vector3d& u)
{
  LogCoords c;
  translationPart(c) = u;
  rotationPart(c) = vee(logLinear);
  symmetricPart(c) = toSymmetricVector(logLinear);
  return c;
}

/// Eigenvalue magnitudes (geometric mean |det A|^(1/3)) up to 2^+-kLogMagnitudeLimit: the
/// divided differences of log at such nodes (up to |lambda|^-2) and their products with Schur
/// entries stay in the double range.
constexpr double kMagnitudeLimitExponent = 450.0;
/// Above 2^64 the translation block is solved for instead (see matrixLog).
constexpr double kLargeMagnitudeExponent = 64.0;
constexpr double kLn2 = 0.69314718055994530942;

/// log det A without underflow or overflow: the determinant of A 2^-e plus 3 e log 2.
double logDeterminant(const Eigen::Matrix3d& a)
{
  const int e = unitScaleExponent(a);
  const double det = unitScaleDeterminant(scaledByPowerOfTwo(a, -e));
  if (det != 0.0)
  {
    return std::log(std::abs(det)) + 3.0 * e * kLn2;
  }
  // Underflowed at unit scale (diag(1e-110, 1, 1e110), determinant 1, read as out of range).
  int exponent = 0;
  return std::log(std::abs(unitScaleDeterminant(equilibrated(a, exponent)))) + exponent * kLn2;
}

/// The magnitudes this parametrisation handles (see kMagnitudeLimitExponent) and a condition
/// number up to kMaxConditionNumber. `logDet` is log det A.
Status checkRange(const Eigen::Matrix3d& a, double logDet)
{
  if (!std::isfinite(logDet) || std::abs(logDet) > 3.0 * kMagnitudeLimitExponent * kLn2)
  {
    return Status::MagnitudeOutOfRange;
  }
  const int e = unitScaleExponent(a);
  // ||A||_F^3 / det A >= cond(A); only then is the condition number computed.
  const double logBound = 3.0 * (std::log(scaledByPowerOfTwo(a, -e).norm()) + e * kLn2) - logDet;
  if (!std::isfinite(logBound))
  {
    return Status::OutOfRange;
  }
  if (logBound > std::log(kMaxConditionNumber))
  {
    const SingularValueDecomposition3 svd = singularValueDecomposition3(scaledByPowerOfTwo(a, -e));
    if (!(svd.sigma[2] > 0.0))
    {
      // The smallest stretch underflowed at unit scale (callers map it: logDet is finite, so the
      // determinant is not 0).
      return Status::Singular;
    }
    if (svd.sigma[0] > kMaxConditionNumber * svd.sigma[2])
    {
      return Status::IllConditioned;
    }
  }
  return Status::Ok;
}

} // namespace

Eigen::Matrix3d logLinearPart(const LogCoords& c)
{
  return hat(rotationPart(c)) + fromSymmetricVector(symmetricPart(c));
}

Result<Eigen::Matrix4d> matrixExp(const LogCoords& c)
{
  using R = Result<Eigen::Matrix4d>;
  if (!c.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Matrix3d l = logLinearPart(c);
  // Skew plus symmetric part can overflow for coordinates near DBL_MAX: no exp in range then.
  if (!l.allFinite())
  {
    return R::failure(Status::OutOfRange);
  }
  // Logs of moderate size (turns up to 5.6 rad, stretches up to e^8) by scaling and squaring:
  // 4-10x faster than the Schur form and at least as accurate there (lct/AffineExp.h).
  Eigen::Matrix3d linear;
  Eigen::Vector3d translation;
  if (affineExpBySquaring(l, translationPart(c), linear, translation))
  {
    if (!linear.allFinite() || !translation.allFinite())
    {
      return R::failure(Status::OutOfRange); // a translation near the end of the double range
    }
  }
  else
  {
    const BlockFunction block = blockFunction(ScalarFunction::Exp, l, translationPart(c), 0.0);
    if (block.status != Status::Ok)
    {
      return R::failure(block.status);
    }
    linear = block.linear;
    translation = block.translation;
  }
  // det exp(L) = e^tr(L): a result below the normal range, or one too ill-conditioned to hold
  // its smallest stretch, is refused like the same matrix given to matrixLog. exp(L) is never
  // singular: a smallest singular value that rounded to 0 is an underflow, OutOfRange.
  Status range = checkRange(linear, l.trace());
  if (range == Status::MagnitudeOutOfRange)
  {
    // A representable result beyond the parametrisation's 1e+-135 (e^320 I = 1e139 I) is
    // refused for that reason, which Polar does not share, not as out of double's range.
    const bool representable = linear.allFinite() && std::abs(l.trace()) <= 3.0 * 700.0;
    range = representable ? Status::MagnitudeOutOfRange : Status::OutOfRange;
  }
  range = range == Status::Singular ? Status::OutOfRange : range;
  if (range != Status::Ok)
  {
    return R::failure(range);
  }
  return { makeAffine(linear, translation), Status::Ok };
}

Result<Eigen::Matrix4d> matrixPower(const Eigen::Matrix4d& m, double s)
{
  using R = Result<Eigen::Matrix4d>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  if (!std::isfinite(s))
  {
    return R::failure(Status::NonFinite);
  }
  Eigen::Matrix4d e = m;
  e.diagonal().array() -= 1.0;
  const double norm = e.norm();
  // The series only where its terms fall geometrically from the start (|s| <= 2, ||E|| < 1/4:
  // ratio (|s| + k) / k ||E|| <= 1/2); a huge |s| would overflow binom(s, k) first.
  if (norm >= 0.25 || std::abs(s) > 2.0)
  {
    const auto l = matrixLog(m);
    if (!l)
    {
      return R::failure(l.status);
    }
    return matrixExp(s * l.value);
  }
  // (I + E)^s = sum_k binom(s, k) E^k with |binom(s, k)| <= (k + 1)^2 / 2 here and ||E^k|| <= 4^-k.
  // E has a zero bottom row, so only the top 3x4 block of the powers is formed.
  Eigen::Matrix<double, 3, 4> power = e.topRows<3>();
  Eigen::Matrix<double, 3, 4> sum = s * power;
  double coefficient = s;
  constexpr int kMaxTerms = 200;
  for (int k = 2; k <= kMaxTerms; ++k)
  {
    // E^k = E^(k-1) E, with E's bottom row zero: [P q] [A t; 0 0] = [P A, P t].
    Eigen::Matrix<double, 3, 4> next;
    next.leftCols<3>() = power.leftCols<3>() * e.topLeftCorner<3, 3>();
    next.col(3) = power.leftCols<3>() * e.topRightCorner<3, 1>();
    power = next;
    coefficient *= (s - (k - 1)) / k;
    const Eigen::Matrix<double, 3, 4> term = coefficient * power;
    sum += term;
    if (term.norm() <= 0.25 * std::numeric_limits<double>::epsilon() * (1.0 + sum.norm()))
    {
      break;
    }
  }
  Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
  out.topRows<3>() += sum;
  return { out, Status::Ok };
}

Result<LogCoords> matrixLog(const Eigen::Matrix4d& m)
{
  using R = Result<LogCoords>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const double logDet = logDeterminant(a);
  const Status range = checkRange(a, logDet);
  if (range != Status::Ok)
  {
    // A determinant that validateAffine found positive: a smallest stretch that underflowed at
    // unit scale is a condition far beyond kMaxConditionNumber, not a zero determinant.
    return R::failure(range == Status::Singular ? Status::IllConditioned : range);
  }
  BlockFunction block = blockFunction(ScalarFunction::Log, a, m.topRightCorner<3, 1>(), 1.0);
  if (block.status != Status::Ok)
  {
    return R::failure(block.status);
  }
  // For large eigenvalues the divided differences with the node 1 fall like |lambda|^-3 and
  // underflow; there A - I is as well conditioned as A, so u = (A - I)^-1 log(A) t directly.
  if (logDet > 3.0 * kLargeMagnitudeExponent * kLn2)
  {
    Eigen::Matrix3d shifted = a;
    shifted.diagonal().array() -= 1.0;
    block.translation =
      shifted.partialPivLu().solve(Eigen::Vector3d(block.linear * m.topRightCorner<3, 1>()));
    if (!block.translation.allFinite())
    {
      return R::failure(Status::OutOfRange);
    }
  }
  if (block.nearestToNegativeAxis < kRefusedPairSlope)
  {
    return R::failure(Status::NoRealLogarithm);
  }
  R out{ packLog(block.linear, block.translation), Status::Ok };
  // A conjugate pair close to the negative real axis (turns beyond 135 degrees): there the
  // log is ill-conditioned (its divided differences grow like 1 / Im), so the result may have
  // lost digits. Check it and refuse it rather than return an inaccurate logarithm. The pair is
  // the Schur form's own, the one the log was computed from.
  // Likewise for condition numbers beyond 1e4, where the Schur-Parlett sums of a non-normal T
  // may cancel (measured: backward errors up to 2e-10 at 1e12).
  const bool illConditioned = 3.0 * std::log(a.norm() / std::exp(logDet / 3.0)) > std::log(1e4);
  if (block.nearestToNegativeAxis < kCheckedPairSlope || illConditioned)
  {
    const auto back = matrixExp(out.value);
    if (!back || !accurateRoundTrip(back.value, m))
    {
      return R::failure(Status::NoRealLogarithm);
    }
  }
  return out;
}

} // namespace lct
