#include "lct/SO3.h"

#include <cmath>

namespace lct
{

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
}

namespace
{
/// The coefficients of Rodrigues' formula R = I + sinc hat(w) + b hat(w)^2, with
/// cosMinusOne = cos t - 1 = -t^2 b, all without cancellation near t = 0.
struct RodriguesCoefficients
{
  double sinc;        // sin(t) / t
  double halfSincSq2; // b = (1 - cos t) / t^2 = (sin(t/2) / (t/2))^2 / 2
  double cosMinusOne; // cos t - 1 = -2 sin^2(t/2)
};

RodriguesCoefficients rodriguesCoefficients(double theta2)
{
  RodriguesCoefficients c;
  if (theta2 < 1e-8)
  {
    // Taylor series; the next terms are below 1e-24.
    c.sinc = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    c.halfSincSq2 = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
    c.cosMinusOne = -theta2 * c.halfSincSq2;
  }
  else
  {
    // One sincos of the half angle gives all three: sin t = 2 s c, 1 - cos t = 2 s^2.
    const double theta = std::sqrt(theta2);
    const double halfSin = std::sin(0.5 * theta);
    const double halfCos = std::cos(0.5 * theta);
    const double s = halfSin / (0.5 * theta);
    c.sinc = halfSin * halfCos / (0.5 * theta);
    c.halfSincSq2 = 0.5 * s * s;
    c.cosMinusOne = -2.0 * halfSin * halfSin;
  }
  return c;
}
} // namespace

Eigen::Matrix3d expSO3(const Eigen::Vector3d& w)
{
  const RodriguesCoefficients c = rodriguesCoefficients(w.squaredNorm());
  // R = cos t I + sinc hat(w) + (1 - cos t)/t^2 w w^T   (hat(w)^2 = w w^T - t^2 I)
  Eigen::Matrix3d r = c.halfSincSq2 * (w * w.transpose());
  r.diagonal().array() += 1.0 + c.cosMinusOne;
  r += c.sinc * hat(w);
  return r;
}

Eigen::Matrix3d expSO3MinusIdentity(const Eigen::Vector3d& w)
{
  // The same coefficients as expSO3, written out: the probe deformer calls this once per point.
  const double theta2 = w.squaredNorm();
  double sinc, b, cosMinusOne;
  if (theta2 < 1e-8)
  {
    sinc = 1.0 - theta2 / 6.0 + theta2 * theta2 / 120.0;
    b = 0.5 - theta2 / 24.0 + theta2 * theta2 / 720.0;
    cosMinusOne = -theta2 * b;
  }
  else
  {
    const double half = 0.5 * std::sqrt(theta2);
    const double halfSin = std::sin(half), halfCos = std::cos(half);
    const double s = halfSin / half;
    sinc = s * halfCos;
    b = 0.5 * s * s;
    cosMinusOne = -2.0 * halfSin * halfSin;
  }
  const double x = w[0], y = w[1], z = w[2];
  Eigen::Matrix3d r;
  r << b * x * x + cosMinusOne, b * x * y - sinc * z, b * x * z + sinc * y, //
    b * x * y + sinc * z, b * y * y + cosMinusOne, b * y * z - sinc * x,    //
    b * x * z - sinc * y, b * y * z + sinc * x, b * z * z + cosMinusOne;
  return r;
}

Eigen::Vector3d logSO3(const Eigen::Matrix3d& r)
{
  const double cosTheta = 0.5 * (r.trace() - 1.0);
  const Eigen::Vector3d v = vee(r); // = sin(t) n
  if (cosTheta > -0.5)
  {
    // t < 120 degrees: the skew part carries the axis to full relative accuracy.
    const double sinTheta = v.norm();
    const double theta = std::atan2(sinTheta, cosTheta);
    double ratio; // t / sin t
    if (sinTheta < 1e-5)
    {
      const double s2 = sinTheta * sinTheta;
      ratio = 1.0 + s2 / 6.0 + 3.0 * s2 * s2 / 40.0; // asin(s)/s, cos t > 0 here
    }
    else
    {
      ratio = theta / sinTheta;
    }
    return ratio * v;
  }
  // Near pi: B = sym(R) - cos t I = (1 - cos t) n n^T. Take its largest column.
  Eigen::Matrix3d b = 0.5 * (r + r.transpose());
  b.diagonal().array() -= cosTheta;
  Eigen::Index k;
  b.diagonal().maxCoeff(&k);
  Eigen::Vector3d n = b.col(k);
  n.normalize();
  double sinTheta = n.dot(v);
  if (sinTheta < 0.0)
  {
    n = -n;
    sinTheta = -sinTheta;
  }
  return std::atan2(sinTheta, cosTheta) * n;
}

Eigen::Vector3d nearestEquivalentRotation(
  const Eigen::Vector3d& w, const Eigen::Vector3d& reference)
{
  const double theta = w.norm();
  Eigen::Vector3d axis;
  if (theta > 1e-12)
  {
    axis = w / theta;
  }
  else
  {
    // The identity: every 2 pi k m is a logarithm. Pick m along the reference.
    const double refNorm = reference.norm();
    if (refNorm < kPi)
    {
      return w;
    }
    axis = reference / refNorm;
  }
  // Candidates (t + 2 pi k) axis; the closest to the reference has t + 2 pi k nearest to
  // the reference's projection on the axis.
  const double k = std::round((axis.dot(reference) - theta) / kTwoPi);
  return (theta + kTwoPi * k) * axis;
}

Eigen::Vector3d logSO3Nearest(const Eigen::Matrix3d& rotation, const Eigen::Vector3d& reference)
{
  return nearestEquivalentRotation(logSO3(rotation), reference);
}

} // namespace lct
