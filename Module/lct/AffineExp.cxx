#include "lct/AffineExp.h"

#include "lct/Conditioning.h"
#include "lct/InverseFactorials.h"

#include <cmath>

namespace lct
{

namespace
{
constexpr int kTaylorDegree = 16;
/// 1/k!, k = 0 .. kTaylorDegree.
constexpr auto kInverseFactorial = inverseFactorials<kTaylorDegree + 1>();
} // namespace

bool affineExpBySquaring(const Eigen::Matrix3d& l, const Eigen::Vector3d& t,
  Eigen::Matrix3d& linear, Eigen::Vector3d& translation)
{
  if (!l.allFinite() || !t.allFinite())
  {
    return false;
  }
  const double norm = l.cwiseAbs().colwise().sum().maxCoeff();
  if (!(norm <= kAffineExpNormLimit))
  {
    return false;
  }
  // The least s with norm 2^-s <= kTaylorRadius (norm / radius < 2^s).
  int s = 0;
  if (norm > kTaylorRadius)
  {
    s = binaryExponent(norm / kTaylorRadius);
  }
  // Y = [L t_unit; 0 0] 2^-s, t_unit = t 2^-k of unit size: both scalings exact.
  const int k = unitScaleExponent(t);
  Eigen::Matrix4d y = Eigen::Matrix4d::Zero();
  y.topLeftCorner<3, 3>() = powerOfTwo(-s) * l;
  y.topRightCorner<3, 1>() = scaledByPowerOfTwo(scaledByPowerOfTwo(t, -k), -s);

  // Paterson & Stockmeyer: T16(Y) = B0 + Y^4 (B1 + Y^4 (B2 + Y^4 (B3 + Y^4 c16))), with
  // B_j = c_4j I + c_4j+1 Y + c_4j+2 Y^2 + c_4j+3 Y^3 and I the 4x4 identity (the powers' bottom
  // rows are 0, so the result's is exactly [0 0 0 1]).
  const Eigen::Matrix4d y2 = y * y;
  const Eigen::Matrix4d y3 = y2 * y;
  const Eigen::Matrix4d y4 = y2 * y2;
  const auto block = [&](int j) {
    Eigen::Matrix4d b = kInverseFactorial[4 * j + 1] * y + kInverseFactorial[4 * j + 2] * y2 +
      kInverseFactorial[4 * j + 3] * y3;
    b.diagonal().array() += kInverseFactorial[4 * j];
    return b;
  };
  Eigen::Matrix4d p = kInverseFactorial[kTaylorDegree] * y4 + block(3);
  for (int j = 2; j >= 0; --j)
  {
    p = y4 * p + block(j);
  }
  for (int i = 0; i < s; ++i)
  {
    p = p * p;
  }
  linear = p.topLeftCorner<3, 3>();
  translation = scaledByPowerOfTwo(Eigen::Vector3d(p.topRightCorner<3, 1>()), k);
  return true;
}

} // namespace lct
