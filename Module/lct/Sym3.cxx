#include "lct/Sym3.h"

#include "lct/Conditioning.h"
#include "lct/DividedDifferences.h"
#include "lct/Eigenvalues3.h"
#include "lct/InverseFactorials.h"
#include "lct/SymmetricEigen3.h"

#include <cmath>
#include <limits>

namespace lct
{

namespace
{

/// f(Y) by the Newton form about the middle eigenvalue (Kaji & Ochiai App. B).
Eigen::Matrix3d applySymmetric(ScalarFunction f, const Eigen::Matrix3d& y, const Eigen::Vector3d& l)
{
  // Nodes in the order middle, largest, smallest.
  const NewtonCoefficients3 c = newtonCoefficients(f, l[1], l[0], l[2]);
  Eigen::Matrix3d z = y.selfadjointView<Eigen::Upper>();
  z.diagonal().array() -= l[1];
  Eigen::Matrix3d zShifted = z;
  zShifted.diagonal().array() -= l[0] - l[1];
  Eigen::Matrix3d result = c.c2 * (z * zShifted);
  result += c.c1 * z;
  result.diagonal().array() += c.c0;
  // The exact result is symmetric; remove the round-off asymmetry of the product.
  return 0.5 * (result + result.transpose());
}

/// The Frobenius norm of the traceless part (scaled by 2^-s) up to which expSym sums a series
/// instead of solving the cubic: the spectral radius is then at most sqrt(2/3) (a traceless
/// symmetric 3x3 matrix has |l|max <= sqrt(2/3) ||Z||_F), so 18 terms leave a remainder below
/// 0.8165^18 / 18! ~ 4e-18, under half an ulp of the smallest eigenvalue e^-0.82 of exp(Z).
/// Interpolation evaluates exp on small relative logs, where this costs one exp and 17 fused
/// multiply-adds in a chain instead of the closed form's acos, sincos and three exps (measured
/// inside InterpolateTransform: about 50 ns instead of 170 ns).
constexpr double kSeriesRadius = 1.0;
/// Up to this ||Z||_F the series is summed for Z 2^-s (||Z 2^-s||_F <= kSeriesRadius) and squared
/// s <= 3 times, still on the three scalars (Z^4 = p Z^2 + q Z): no cubic, no eigenvectors. The
/// spectra stay within a spread of 2 sqrt(2/3) 4 ~ 6.5, where the error measured against a long
/// double reference is 1.0e-15 (Eigen's MatrixFunctions on the same matrices: 2.3e-14;
/// Testing/Unit/TestSym3.cxx).
constexpr double kSquaringRadius = 4.0;
/// Beyond this |eigenvalue| callers compare the bounds with the ends of exp's range (log DBL_MIN
/// ~ -708): there the series' bounds, up to 3.3 wider than the spectrum, give way to the closed
/// form's exact ones, so that polarExp does not refuse a representable stretch as below DBL_MIN.
constexpr double kExactBoundsBeyond = 690.0;
constexpr double kLn2 = 0.69314718055994530942;
/// log(kClosedFormConditionLimit): the eigenvalue spread of Y above which exp(Y) is formed from
/// eigenvectors.
const double kClosedFormLogSpread = std::log(kClosedFormConditionLimit);
constexpr int kSeriesTerms = 18;
/// 1/n!, n = 0 .. kSeriesTerms - 1.
constexpr auto kInverseFactorial = inverseFactorials<kSeriesTerms>();

/// f(Y) = V diag(f(l)) V^T: for spread spectra, where the Newton form about the middle
/// eigenvalue cancels (it builds the small eigenvalues' part from terms the size of the largest).
Eigen::Matrix3d applyEigen(ScalarFunction f, const SymmetricEigen3& e)
{
  const Eigen::Vector3d fl = e.values.unaryExpr([f](double x) { return evaluate(f, x); });
  const Eigen::Matrix3d result = e.vectors * fl.asDiagonal() * e.vectors.transpose();
  return 0.5 * (result + result.transpose());
}

Result<Eigen::Matrix3d> applyPositive(ScalarFunction f, const Eigen::Matrix3d& s)
{
  using R = Result<Eigen::Matrix3d>;
  if (!s.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  // Exact power-of-two scaling: log(2^e S) = log(S) + e log 2 I, sqrt(2^e S) = 2^(e/2) sqrt(S)
  // (e even).
  int e = unitScaleExponent(s);
  e += e & 1;
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(s, -e);
  const Eigen::Vector3d l = symmetricEigenvalues(unit);
  Eigen::Matrix3d result;
  if (l[2] > 0.0 && l[2] * kClosedFormConditionLimit >= l[0])
  {
    result = applySymmetric(f, unit, l);
  }
  else
  {
    const SymmetricEigen3 eigen = symmetricEigen3(unit);
    if (!(eigen.values[2] > 0.0))
    {
      return R::failure(Status::Singular);
    }
    if (eigen.values[0] > kMaxConditionNumber * eigen.values[2])
    {
      return R::failure(Status::IllConditioned);
    }
    result = applyEigen(f, eigen);
  }
  if (f == ScalarFunction::Log)
  {
    result.diagonal().array() += e * kLn2;
  }
  else
  {
    result = scaledByPowerOfTwo(result, e / 2);
  }
  if (!result.allFinite())
  {
    return R::failure(Status::OutOfRange);
  }
  return { result, Status::Ok };
}

} // namespace

Eigen::Matrix3d expSym(const Eigen::Matrix3d& y, Eigen::Vector2d* eigenvalueBounds)
{
  const double mean = y.trace() / 3.0;
  // Z = Y - mean I, symmetric and traceless; six numbers.
  const double z00 = y(0, 0) - mean, z11 = y(1, 1) - mean, z22 = y(2, 2) - mean;
  const double z01 = y(0, 1), z12 = y(1, 2), z02 = y(0, 2);
  const double normSq =
    z00 * z00 + z11 * z11 + z22 * z22 + 2.0 * (z01 * z01 + z12 * z12 + z02 * z02);
  // |l - mean| <= sqrt(2/3) ||Z||_F for a traceless symmetric Z.
  const double radius = 0.816496580927726 * std::sqrt(normSq);
  const bool series = normSq <= kSquaringRadius * kSquaringRadius &&
    (!eigenvalueBounds || std::abs(mean) + radius < kExactBoundsBeyond);
  if (!series)
  {
    const Eigen::Vector3d l = symmetricEigenvalues(y);
    if (l[0] - l[2] <= kClosedFormLogSpread)
    {
      if (eigenvalueBounds)
      {
        *eigenvalueBounds = Eigen::Vector2d(l[2], l[0]);
      }
      return applySymmetric(ScalarFunction::Exp, y, l);
    }
    const SymmetricEigen3 eigen = symmetricEigen3(y);
    if (eigenvalueBounds)
    {
      *eigenvalueBounds = Eigen::Vector2d(eigen.values[2], eigen.values[0]);
    }
    return applyEigen(ScalarFunction::Exp, eigen);
  }
  if (eigenvalueBounds)
  {
    *eigenvalueBounds = Eigen::Vector2d(mean - radius, mean + radius);
  }
  // W = Z 2^-s with ||W||_F <= kSeriesRadius (||Z||_F < 2^s).
  int squarings = 0;
  if (normSq > kSeriesRadius * kSeriesRadius)
  {
    squarings = binaryExponent(std::sqrt(normSq));
  }
  // squarings <= 3 (kSquaringRadius) here: 2^-squarings is normal.
  const double w = powerOfTwo(-squarings);
  // Cayley-Hamilton for traceless W: W^3 = p W + q I with p = tr(W^2)/2, q = det W, so
  //   W (alpha I + beta W + gamma W^2) = q gamma I + (alpha + p gamma) W + beta W^2,
  // and Horner's rule for sum W^n/n! runs on the three scalars (a, b, c).
  const double p = 0.5 * normSq * w * w;
  const double q = (z00 * (z11 * z22 - z12 * z12) - z01 * (z01 * z22 - z12 * z02) +
                     z02 * (z01 * z12 - z11 * z02)) *
    (w * w * w);
  double a = kInverseFactorial[kSeriesTerms - 1], b = 0.0, c = 0.0;
  for (int n = kSeriesTerms - 2; n >= 0; --n)
  {
    const double nextA = q * c + kInverseFactorial[n];
    const double nextB = a + p * c;
    c = b;
    b = nextB;
    a = nextA;
  }
  // (a I + b W + c W^2)^2 = (a^2 + 2 b c q) I + (2 a b + 2 b c p + c^2 q) W
  //                         + (b^2 + 2 a c + c^2 p) W^2,  with W^4 = p W^2 + q W.
  for (int i = 0; i < squarings; ++i)
  {
    const double nextA = a * a + 2.0 * b * c * q;
    const double nextB = 2.0 * a * b + 2.0 * b * c * p + c * c * q;
    const double nextC = b * b + 2.0 * a * c + c * c * p;
    a = nextA;
    b = nextB;
    c = nextC;
  }
  // In powers of Z: b W = (b w) Z, c W^2 = (c w^2) Z^2.
  b *= w;
  c *= w * w;
  // Z^2, symmetric by construction.
  const double s00 = z00 * z00 + z01 * z01 + z02 * z02;
  const double s11 = z01 * z01 + z11 * z11 + z12 * z12;
  const double s22 = z02 * z02 + z12 * z12 + z22 * z22;
  const double s01 = z00 * z01 + z01 * z11 + z02 * z12;
  const double s12 = z01 * z02 + z11 * z12 + z12 * z22;
  const double s02 = z00 * z02 + z01 * z12 + z02 * z22;
  const double scale = std::exp(mean);
  const double d = scale * a;
  b *= scale;
  c *= scale;
  Eigen::Matrix3d result;
  result(0, 0) = d + b * z00 + c * s00;
  result(1, 1) = d + b * z11 + c * s11;
  result(2, 2) = d + b * z22 + c * s22;
  result(0, 1) = result(1, 0) = b * z01 + c * s01;
  result(1, 2) = result(2, 1) = b * z12 + c * s12;
  result(0, 2) = result(2, 0) = b * z02 + c * s02;
  return result;
}

Result<Eigen::Matrix3d> logSPD(const Eigen::Matrix3d& s)
{
  return applyPositive(ScalarFunction::Log, s);
}

Eigen::Matrix3d logSPDClosedForm(const Eigen::Matrix3d& s, const Eigen::Vector3d& l)
{
  return applySymmetric(ScalarFunction::Log, s, l);
}

Result<Eigen::Matrix3d> sqrtSPD(const Eigen::Matrix3d& s)
{
  return applyPositive(ScalarFunction::Sqrt, s);
}

} // namespace lct
