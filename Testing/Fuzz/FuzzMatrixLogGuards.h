// The skips for the known MatrixLog defects D1 and D2 (Testing/Fuzz/README.md), shared by the
// targets that drive the MatrixLog parametrisation through the VTK classes. Those defects are
// undefined behaviour inside the library (D1) or a silently wrong log (D2), so a target must
// decide before the call; these functions mirror what the call will hand to lct::matrixLog /
// lct::matrixExp and say whether a trigger holds.
#ifndef lct_fuzz_FuzzMatrixLogGuards_h
#define lct_fuzz_FuzzMatrixLogGuards_h

#include "FuzzInput.h"

#include "lct/Affine.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"

#include <Eigen/LU>
#include <Eigen/SVD>

namespace lct_fuzz
{

// KNOWN: D1, D2. generalEigenvalues returns NaN/Inf eigenvalues when the characteristic
// polynomial's coefficients overflow or p m underflows (D1: matrixLog/matrixExp then shift by -1
// and read nodes[-1] in DividedDifferences.cxx:221), or a false triple root for a NaN
// discriminant (D2: a wrong log returned Ok). True where the trigger holds for `a`.
inline bool KnownCubic(const Eigen::Matrix3d& a)
{
  if (!AllFinite(a))
  {
    return false;
  }
  const lct::GeneralEigenvalues e = lct::generalEigenvalues(a);
  for (const auto& v : e.values)
  {
    if (!std::isfinite(v.real()) || !std::isfinite(v.imag()))
    {
      return Known("D1", true);
    }
  }
  Eigen::Matrix3d b = a;
  b.diagonal().array() -= a.trace() / 3.0;
  const double p = b(0, 0) * b(1, 1) - b(0, 1) * b(1, 0) + b(0, 0) * b(2, 2) - b(0, 2) * b(2, 0) +
    b(1, 1) * b(2, 2) - b(1, 2) * b(2, 1);
  const double q = -b.determinant();
  const double thirdP = p / 3.0;
  return Known("D2", !std::isfinite(0.25 * q * q + thirdP * thirdP * thirdP));
}

/// Whether a key is "tame" for the MatrixLog targets that cannot predict every matrix the library
/// derives from their keys (relative products, weighted sums of logs, the hand-over blend). D1/D2
/// need extreme linear parts: coefficients of the characteristic polynomial beyond ~1e51 or a
/// traceless part below ~1e-103. With singular values in [1e-10, 1e10], condition <= 1e8 and every
/// non-zero entry at least 1e-30 (so that two keys differ by at least ulp(1e-30) where they
/// differ), derived matrices stay far from both, and such keys cannot meet them.
inline bool Tame(const Eigen::Matrix4d& m)
{
  if (lct::validateAffine(m) != lct::Status::Ok)
  {
    return false; // (KeyLogs takes relative logs even of invalid matrices, e.g. camera matrices)
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  for (int i = 0; i < 9; ++i)
  {
    const double x = std::abs(a(i / 3, i % 3));
    if (x != 0.0 && !(x >= 1e-30))
    {
      return false;
    }
  }
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
  return s[0] <= 1e10 && s[2] >= 1e-10 && s[0] <= 1e8 * s[2];
}

/// Whether lct::matrixExp(c) would meet a D1/D2 trigger.
inline bool KnownCubicExp(const lct::LogCoords& c)
{
  return AllFinite(c) && KnownCubic(lct::logLinearPart(c));
}

/// Whether lct::matrixLog(m), or the matrixExp of its result, would meet a D1/D2 trigger.
inline bool KnownCubicLog(const Eigen::Matrix4d& m)
{
  if (lct::validateAffine(m) != lct::Status::Ok)
  {
    return false;
  }
  if (KnownCubic(m.topLeftCorner<3, 3>()))
  {
    return true;
  }
  const auto log = lct::matrixLog(m);
  return log && KnownCubicExp(log.value);
}

} // namespace lct_fuzz

#endif
