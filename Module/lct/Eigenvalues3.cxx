#include "lct/Eigenvalues3.h"

#include "lct/Conditioning.h"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{

namespace
{
constexpr double kTwoPiOver3 = 2.0943951023931954923;
}

namespace
{
/// Entries beyond 2^+-300 would overflow the trace or leave the normal range in the shifted
/// matrix: such matrices are scaled by a power of two, which scales the eigenvalues exactly. (The
/// traceless part is scaled on its own below, since its cubes under- or overflow at any
/// magnitude of A: 2 I + 1e-110 E had a 0/0.)
bool needsScaling(const Eigen::Matrix3d& a, int& exponent)
{
  const double largest = a.cwiseAbs().maxCoeff();
  if (!(largest > 0x1p-300 && largest < 0x1p300) && largest > 0.0 && std::isfinite(largest))
  {
    exponent = unitScaleExponent(a);
    return true;
  }
  return false;
}
} // namespace

namespace
{
/// Beyond this |r| the two closest roots are a near-double root, where acos turns the rounding
/// of r into sqrt(eps) ||B|| (diag(2, 1, 1) gave 1 +- 4e-9).
constexpr double kNearDoubleRoot = 0.999;

/// The eigenvalues (descending) of the unit-size traceless symmetric B near a double root, to
/// eps ||B||: the isolated eigenvalue `isolated` (at a distance of at least ~1.5 p from the other
/// two) is well-conditioned, and so is its eigenvector (the largest cross product of two rows of
/// B - isolated I); the other two are those of B restricted to its orthogonal complement, a 2x2
/// problem solved without cancellation. `isolated` must be the trigonometric root itself, accurate
/// to eps p even here (its slope in r, 2 p sin(phi) / (3 sin(3 phi)), stays below p / 4): an
/// approximation such as 2 p tilts the eigenvector by its error over the gap, and the 2x2
/// eigenvalues by the square of that (2 p gave 1e-9 errors at r = 0.9995).
Eigen::Vector3d nearDoubleRoot(
  double b00, double b11, double b22, double b01, double b02, double b12, double isolated)
{
  Eigen::Matrix3d b;
  b << b00, b01, b02, b01, b11, b12, b02, b12, b22;
  Eigen::Matrix3d shifted = b;
  shifted.diagonal().array() -= isolated;
  const Eigen::Vector3d crosses[3] = { shifted.row(0).cross(shifted.row(1)),
    shifted.row(0).cross(shifted.row(2)), shifted.row(1).cross(shifted.row(2)) };
  const Eigen::Vector3d* best = &crosses[0];
  for (const Eigen::Vector3d& c : crosses)
  {
    best = c.squaredNorm() > best->squaredNorm() ? &c : best;
  }
  const Eigen::Vector3d v = best->normalized();
  // u1 orthogonal to v from v's two largest components, u2 = v x u1.
  int small = 0;
  v.cwiseAbs().minCoeff(&small);
  Eigen::Vector3d u1 = Eigen::Vector3d::Unit(small).cross(v).normalized();
  const Eigen::Vector3d u2 = v.cross(u1);
  const double mu = v.dot(b * v);
  const double a11 = u1.dot(b * u1);
  const double a22 = u2.dot(b * u2);
  const double a12 = u1.dot(b * u2);
  const double half = 0.5 * (a11 + a22);
  const double radius = std::hypot(0.5 * (a11 - a22), a12);
  Eigen::Vector3d l(mu, half + radius, half - radius);
  std::sort(l.data(), l.data() + 3, [](double x, double y) { return x > y; });
  return l;
}

} // namespace

Eigen::Vector3d symmetricEigenvalues(const Eigen::Matrix3d& a)
{
  int exponent = 0;
  if (needsScaling(a, exponent))
  {
    return scaledByPowerOfTwo(symmetricEigenvalues(scaledByPowerOfTwo(a, -exponent)), exponent);
  }
  const double shift = a.trace() / 3.0;
  // B = A - shift I at unit size (exact power of two), so that its cubes stay normal.
  const double raw[6] = { a(0, 0) - shift, a(1, 1) - shift, a(2, 2) - shift, a(0, 1), a(0, 2),
    a(1, 2) };
  double largestB = 0.0;
  for (double x : raw)
  {
    largestB = std::max(largestB, std::abs(x));
  }
  if (!(largestB > 0.0))
  {
    return Eigen::Vector3d::Constant(shift);
  }
  const int e = binaryExponent(largestB);
  const double b00 = timesPowerOfTwo(raw[0], -e);
  const double b11 = timesPowerOfTwo(raw[1], -e);
  const double b22 = timesPowerOfTwo(raw[2], -e);
  const double b01 = timesPowerOfTwo(raw[3], -e);
  const double b02 = timesPowerOfTwo(raw[4], -e);
  const double b12 = timesPowerOfTwo(raw[5], -e);
  // tr(B^2)/6, a sum of squares: no cancellation.
  const double offDiagonal = b01 * b01 + b02 * b02 + b12 * b12;
  const double p2 = (b00 * b00 + b11 * b11 + b22 * b22 + 2.0 * offDiagonal) / 6.0;
  if (p2 <= 0.0)
  {
    return Eigen::Vector3d::Constant(shift);
  }
  const double p = std::sqrt(p2);
  const double scaledP = timesPowerOfTwo(p, e); // p of the unscaled B
  // det(B / p) / 2 lies in [-1, 1]; clamp against round-off.
  const double detB =
    b00 * (b11 * b22 - b12 * b12) - b01 * (b01 * b22 - b12 * b02) + b02 * (b01 * b12 - b11 * b02);
  const double r = std::clamp(detB / (2.0 * p2 * p), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  // cos(phi -+ 2 pi/3) = -cos(phi)/2 +- sqrt(3)/2 sin(phi): one cos and one sin for all three.
  const double c = std::cos(phi);
  const double s = 0.8660254037844386468 * std::sin(phi);
  if (std::abs(r) > kNearDoubleRoot)
  {
    // The isolated root: the largest (2 p cos phi) for r near 1, the smallest near -1.
    const double isolated = r > 0.0 ? 2.0 * p * c : p * (-c - 2.0 * s);
    const Eigen::Vector3d l = nearDoubleRoot(b00, b11, b22, b01, b02, b12, isolated);
    return Eigen::Vector3d(shift + timesPowerOfTwo(l[0], e), shift + timesPowerOfTwo(l[1], e),
      shift + timesPowerOfTwo(l[2], e));
  }
  const double largest = shift + 2.0 * scaledP * c;
  const double smallest = shift + scaledP * (-c - 2.0 * s);
  const double middle = shift + scaledP * (-c + 2.0 * s);
  // phi in [0, pi/3] orders them; the clamp keeps round-off from swapping neighbours.
  return Eigen::Vector3d(largest, std::clamp(middle, smallest, largest), smallest);
}

GeneralEigenvalues generalEigenvalues(const Eigen::Matrix3d& a)
{
  int exponent = 0;
  if (needsScaling(a, exponent))
  {
    GeneralEigenvalues out = generalEigenvalues(scaledByPowerOfTwo(a, -exponent));
    for (auto& value : out.values)
    {
      value = std::complex<double>(
        std::ldexp(value.real(), exponent), std::ldexp(value.imag(), exponent));
    }
    return out;
  }
  const double shift = a.trace() / 3.0;
  Eigen::Matrix3d b = a;
  b.diagonal().array() -= shift;
  // The roots of B's characteristic polynomial at unit size, then scaled back: p (squares) and
  // q (cubes) of a tiny or huge B would leave the normal range.
  const int e = unitScaleExponent(b);
  b = scaledByPowerOfTwo(b, -e);
  // Characteristic polynomial of B: y^3 + p y + q with p = sum of principal 2x2 minors,
  // q = -det B.
  const double p = b(0, 0) * b(1, 1) - b(0, 1) * b(1, 0) + b(0, 0) * b(2, 2) - b(0, 2) * b(2, 0) +
    b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1);
  const double q = -b.determinant();
  // The roots' own scale: at unit size of B, p and q can still be far apart (one huge entry
  // paired with small ones: p ~ 1e-244, q underflowing), and then p m or the discriminant's cubes
  // under- or overflow (0/0 in r; a discriminant rounding to 0 looked like a triple root). With
  // y = scale z, z^3 + 3 P z + 2 Q = 0 has max(|P|, |Q|^(2/3)) = 1.
  const double thirdPRaw = p / 3.0;
  const double halfQRaw = 0.5 * q;
  const double scale = std::max(std::sqrt(std::abs(thirdPRaw)), std::cbrt(std::abs(halfQRaw)));

  GeneralEigenvalues out;
  if (!std::isfinite(scale))
  {
    // Only NaN input gets here (B is at unit size): say so, rather than guess a triple root.
    for (auto& value : out.values)
    {
      value = std::numeric_limits<double>::quiet_NaN();
    }
    return out;
  }
  if (!(scale > 0.0))
  {
    // p = q = 0: a triple root.
    for (auto& value : out.values)
    {
      value = shift;
    }
    return out;
  }
  const double thirdP = thirdPRaw / scale / scale;
  const double halfQ = halfQRaw / scale / scale / scale;
  const double discriminant = halfQ * halfQ + thirdP * thirdP * thirdP;
  // B's roots are scale 2^e times those of the normalised cubic.
  const auto unscale = [scale, e](double x) { return timesPowerOfTwo(x * scale, e); };
  if (discriminant > 0.0 || thirdP >= 0.0)
  {
    // One real root and a conjugate pair (Cardano). u^3 is formed without cancellation and
    // v = -p / (3u), so that u + v and u - v come from well-separated terms. (thirdP >= 0 with
    // a discriminant <= 0 cannot happen once max(|P|, |Q|^(2/3)) = 1.)
    const double sqrtD = std::sqrt(std::max(discriminant, 0.0));
    const double u = std::cbrt(-halfQ - std::copysign(sqrtD, halfQ));
    const double v = (u != 0.0) ? -thirdP / u : 0.0;
    const double real = unscale(u + v);
    const double imag = unscale(0.8660254037844386468 * std::abs(u - v)); // sqrt(3)/2
    out.complexPair = true;
    out.values[0] = std::complex<double>(shift - 0.5 * real, imag);
    out.values[1] = std::conj(out.values[0]);
    out.values[2] = std::complex<double>(shift + real, 0.0);
    return out;
  }
  // Three real roots: here |P| = 1 >= |Q|^(2/3), so r is formed from numbers of unit size.
  const double m = 2.0 * std::sqrt(-thirdP);
  const double r = std::clamp(halfQ / (thirdP * std::sqrt(-thirdP)), -1.0, 1.0);
  const double phi = std::acos(r) / 3.0;
  const double scaledM = unscale(m);
  out.values[0] = shift + scaledM * std::cos(phi);
  out.values[1] = shift + scaledM * std::cos(phi - kTwoPiOver3);
  out.values[2] = shift + scaledM * std::cos(phi + kTwoPiOver3);
  return out;
}

} // namespace lct
