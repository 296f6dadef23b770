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
