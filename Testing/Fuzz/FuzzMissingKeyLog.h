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
#include "lct/Parametrisation.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <vector>

namespace lct_fuzz
{

// KNOWN: D1, D2 (Testing/Fuzz/README.md). lct::generalEigenvalues solves the characteristic
// polynomial y^3 + p y + q of the shifted 3x3 matrix with no guard against overflow or underflow:
//  D1: NaN/Inf eigenvalues for finite matrices, when p^3 or q^2 overflows (entries beyond ~1e51,
//      det beyond ~1e154, e.g. [[0, 1e80, 0], [0, 0, 1], [1e80, 0, 0]]) or p m underflows to 0 in
//      the three-real-roots branch (r = 0/0, e.g. [[1, 0, 0], [0, 1, 1e-110], [0, 1e-110, 1]]).
//      matrixLog / matrixExp hand them to dividedDifferences, which finds no farthest pair of
//      nodes (ia = ib = -1): DividedDifferences.cxx:221 shifts by -1 and reads nodes[-1].
//  D2: "discriminant <= 0 and p >= 0 force p = q = 0: a triple root" holds in exact arithmetic
//      only. A NaN discriminant (det overflowing as Inf - Inf) or one that underflows to 0 while
//      p > 0 (entries below ~1e-51) takes that branch too, and matrixLog returns Ok with a wrong
//      log (6.66e118 times a 120-degree turn about (1, 1, 1); 1e-65 times a quarter turn).
// True where a trigger holds for `a`, computed as the library computes it.
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
  const double halfQ = 0.5 * q;
  const double thirdP = p / 3.0;
  const double discriminant = halfQ * halfQ + thirdP * thirdP * thirdP;
  const bool tripleBranch = !(discriminant > 0.0) && thirdP >= 0.0;
  return Known("D2", !std::isfinite(discriminant) || (tripleBranch && (p != 0.0 || q != 0.0)));
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

// KNOWN: D19 (Testing/Fuzz/README.md). The transform interpolator accepts a key when the log of
// the step to its forward neighbour exists, but a curve point needs the relative log of every
// weighted key about the reference (backward, and up to three apart), and ConsistentRotation the
// absolute log of each key. When one of those is refused (Polar: beyond the singularity threshold,
// or D6/D9), InterpolateTransform fails inside the accepted key range, with a message that names
// MatrixLog even in Polar. True when the mirror of the key logs (keys in time order, pairs
// within lct::KeyLogs::kReach = 7) finds such a missing log (the caller says Known("D19")).
inline bool MissingKeyLog(
  const std::vector<Eigen::Matrix4d>& keys, lct::Parametrisation p, bool absolute)
{
  const int n = static_cast<int>(keys.size());
  for (int r = 0; r < n; ++r)
  {
    if (absolute && !lct::logarithm(keys[r], p).ok())
    {
      return true;
    }
    const Eigen::Matrix4d inverse = lct::inverseAffine(keys[r]);
    for (int i = std::max(0, r - 7); i < std::min(n, r + 8); ++i)
    {
      if (!lct::logarithm(inverse * keys[i], p).ok())
      {
        return true;
      }
    }
  }
  return false;
}

} // namespace lct_fuzz

#endif
