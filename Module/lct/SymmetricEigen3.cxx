#include "lct/SymmetricEigen3.h"

#include "lct/Conditioning.h"

#include <cmath>
#include <limits>
#include <utility>

namespace lct
{

namespace
{
/// Quadratic convergence reaches round-off within four sweeps on every matrix measured
/// (Testing/Unit/TestSymmetricEigen3.cxx); the bound only keeps the loop finite.
constexpr int kMaxSweeps = 12;

/// The symmetric working matrix (entries (p, q) with p <= q) and the accumulated rotations.
struct JacobiState
{
  double a[3][3];
  double v[3][3];
};

/// One Jacobi rotation in the plane (P, Q), R the third index: zeroes a(P, Q) exactly, unless it
/// is already negligible relative to the two diagonal entries it couples (Demmel & Veselić's
/// test, which keeps small eigenvalues of positive definite matrices relatively accurate).
/// Returns whether it rotated. The indices are template parameters so that every access is to a
/// fixed place (measured: 1280 instructions per call against 1820 for a loop over index triples).
template <int P, int Q, int R>
bool rotate(JacobiState& m)
{
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double apq = m.a[P][Q];
  const double app = m.a[P][P];
  const double aqq = m.a[Q][Q];
  if (std::abs(apq) <= kEps * std::sqrt(std::abs(app) * std::abs(aqq)))
  {
    m.a[P][Q] = 0.0;
    return false;
  }
  // tan of the rotation angle: the root of t^2 + 2 theta t - 1 = 0 of smaller magnitude.
  const double theta = (aqq - app) / (2.0 * apq);
  const double t = std::abs(theta) > 1e150
    ? 0.5 / theta
    : std::copysign(1.0, theta) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
  const double c = 1.0 / std::sqrt(t * t + 1.0);
  const double s = t * c;
  const double tau = s / (1.0 + c);
  m.a[P][P] = app - t * apq;
  m.a[Q][Q] = aqq + t * apq;
  m.a[P][Q] = 0.0;
  // The entries coupling R to P and Q, stored above the diagonal.
  double& arp = m.a[R < P ? R : P][R < P ? P : R];
  double& arq = m.a[R < Q ? R : Q][R < Q ? Q : R];
  const double gp = arp;
  const double gq = arq;
  arp = gp - s * (gq + tau * gp);
  arq = gq + s * (gp - tau * gq);
  for (auto& row : m.v)
  {
    const double vp = row[P];
    const double vq = row[Q];
    row[P] = vp - s * (vq + tau * vp);
    row[Q] = vq + s * (vp - tau * vq);
  }
  return true;
}
} // namespace

SymmetricEigen3 symmetricEigen3(const Eigen::Matrix3d& y)
{
  // The working copy at unit size (an exact power of two, undone on the eigenvalues), so that
  // products of entries neither overflow nor underflow.
  const Eigen::Matrix3d upper = y.triangularView<Eigen::Upper>();
  const int exponent = unitScaleExponent(upper);
  const Eigen::Matrix3d unit = scaledByPowerOfTwo(upper, -exponent);
  JacobiState m = { { { unit(0, 0), unit(0, 1), unit(0, 2) }, { 0.0, unit(1, 1), unit(1, 2) },
                      { 0.0, 0.0, unit(2, 2) } },
    { { 1.0, 0.0, 0.0 }, { 0.0, 1.0, 0.0 }, { 0.0, 0.0, 1.0 } } };
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep)
  {
    const bool first = rotate<0, 1, 2>(m);
    const bool second = rotate<0, 2, 1>(m);
    const bool third = rotate<1, 2, 0>(m);
    if (!(first || second || third))
    {
      break;
    }
  }
  const auto& a = m.a;
  // Descending order, vectors with their values.
  int order[3] = { 0, 1, 2 };
  // Three compare-exchanges, not std::sort: its comparator must be a strict weak order, which
  // NaN (from input outside the contract) would break.
  const auto exchange = [&a, &order](int i, int j) {
    if (a[order[j]][order[j]] > a[order[i]][order[i]])
    {
      std::swap(order[i], order[j]);
    }
  };
  exchange(0, 1);
  exchange(1, 2);
  exchange(0, 1);
  SymmetricEigen3 out;
  for (int k = 0; k < 3; ++k)
  {
    out.values[k] = timesPowerOfTwo(a[order[k]][order[k]], exponent);
    for (int row = 0; row < 3; ++row)
    {
      out.vectors(row, k) = m.v[row][order[k]];
    }
  }
  return out;
}

} // namespace lct
