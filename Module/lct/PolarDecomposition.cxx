#include "lct/PolarDecomposition.h"

#include <Eigen/LU>

#include <cmath>
#include <limits>

namespace lct
{

Result<PolarFactors> polarDecompose(const Eigen::Matrix3d& a)
{
  using R = Result<PolarFactors>;
  if (!a.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const double det = a.determinant();
  if (!(det > 0.0))
  {
    return R::failure(Status::NonPositiveDeterminant);
  }
  // det below eps^3 * ||A||^3 (relative) carries no digits: numerically singular.
  const double norm = a.norm();
  const double eps = std::numeric_limits<double>::epsilon();
  if (det <= eps * eps * eps * norm * norm * norm)
  {
    return R::failure(Status::Singular);
  }

  constexpr int kMaxIterations = 30;
  Eigen::Matrix3d x = a;
  bool scaling = true;
  for (int iteration = 0; iteration < kMaxIterations; ++iteration)
  {
    const Eigen::Matrix3d inverseTranspose = x.inverse().transpose();
    double g = 1.0;
    if (scaling)
    {
      g = std::sqrt(std::sqrt(inverseTranspose.squaredNorm() / x.squaredNorm()));
    }
    const Eigen::Matrix3d next = 0.5 * (g * x + inverseTranspose / g);
    const double change = (next - x).squaredNorm();
    x = next;
    // Scaling only helps far from convergence; near it, it would slow the quadratic phase.
    if (change < 1e-4)
    {
      scaling = false;
    }
    // Quadratic convergence: once a step moves less than sqrt(eps), the next one is at
    // round-off, so take it and stop.
    if (change <= 1e-18)
    {
      const Eigen::Matrix3d last = 0.5 * (x + x.inverse().transpose());
      x = last;
      break;
    }
  }
  PolarFactors factors;
  factors.rotation = x;
  const Eigen::Matrix3d s = x.transpose() * a;
  factors.stretch = 0.5 * (s + s.transpose());
  if (!factors.rotation.allFinite() || !factors.stretch.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  return { factors, Status::Ok };
}

} // namespace lct
