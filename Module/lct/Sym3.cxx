#include "lct/Sym3.h"

#include "lct/DividedDifferences.h"
#include "lct/Eigenvalues3.h"

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

Result<Eigen::Matrix3d> applyPositive(ScalarFunction f, const Eigen::Matrix3d& s)
{
  const Eigen::Vector3d l = symmetricEigenvalues(s);
  if (!l.allFinite())
  {
    return Result<Eigen::Matrix3d>::failure(Status::NonFinite);
  }
  // The smallest eigenvalue is known to about eps * largest: below that it has no digits.
  if (l[2] <= 8.0 * std::numeric_limits<double>::epsilon() * l[0])
  {
    return Result<Eigen::Matrix3d>::failure(Status::Singular);
  }
  return { applySymmetric(f, s, l), Status::Ok };
}

} // namespace

Eigen::Matrix3d expSym(const Eigen::Matrix3d& y)
{
  return applySymmetric(ScalarFunction::Exp, y, symmetricEigenvalues(y));
}

Result<Eigen::Matrix3d> logSPD(const Eigen::Matrix3d& s)
{
  return applyPositive(ScalarFunction::Log, s);
}

Result<Eigen::Matrix3d> sqrtSPD(const Eigen::Matrix3d& s)
{
  return applyPositive(ScalarFunction::Sqrt, s);
}

} // namespace lct
