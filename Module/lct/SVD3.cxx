#include "lct/SVD3.h"

#include "lct/AccurateMinors.h"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>

namespace lct
{

SingularValueDecomposition3 singularValueDecomposition3(const Eigen::Matrix3d& a)
{
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  SingularValueDecomposition3 out;
  out.u = svd.matrixU();
  out.v = svd.matrixV();
  // det A > 0 makes det U = det V: both -1 or both +1. Flipping the last pair keeps A.
  if (out.u.determinant() < 0.0)
  {
    out.u.col(2) = -out.u.col(2);
    out.v.col(2) = -out.v.col(2);
  }
  const double largest = svd.singularValues()[0];
  const Eigen::JacobiSVD<Eigen::Matrix3d> compound(accurateCofactors(a));
  const double largestPair = compound.singularValues()[0]; // sigma_1 sigma_2
  const double det = accurateDeterminant(a);
  out.sigma[0] = largest;
  if (!(largest > 0.0) || !(largestPair > 0.0) || !(det > 0.0))
  {
    out.sigma[1] = largestPair > 0.0 && largest > 0.0 ? largestPair / largest : 0.0;
    out.sigma[2] = 0.0;
    return out;
  }
  // Round-off must not reorder them.
  out.sigma[1] = std::min(largestPair / largest, largest);
  out.sigma[2] = std::min(det / largestPair, out.sigma[1]);
  return out;
}

} // namespace lct
