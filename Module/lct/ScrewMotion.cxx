#include "lct/ScrewMotion.h"

#include <Eigen/Geometry>

#include <cmath>

namespace lct
{

Eigen::Vector3d screwTranslation(const Eigen::Vector3d& w, const Eigen::Vector3d& v)
{
  const double th2 = w.squaredNorm();
  const double th = std::sqrt(th2);
  double a, b; // (1 - cos th) / th^2 and (th - sin th) / th^3
  if (th < 1e-4)
  {
    a = 0.5 - th2 / 24.0;
    b = 1.0 / 6.0 - th2 / 120.0;
  }
  else
  {
    const double s = std::sin(0.5 * th);
    a = 2.0 * s * s / th2; // half-angle form: no cancellation
    b = (th - std::sin(th)) / (th2 * th);
  }
  const Eigen::Vector3d wv = w.cross(v);
  return v + a * wv + b * w.cross(wv);
}

Eigen::Vector3d screwTwist(const Eigen::Vector3d& w, const Eigen::Vector3d& t)
{
  const double th2 = w.squaredNorm();
  const double th = std::sqrt(th2);
  // (1 - (th / 2) cot(th / 2)) / th^2, 1/12 + th^2 / 720 near 0.
  const double c = th < 1e-4 ? 1.0 / 12.0 + th2 / 720.0
                             : (1.0 - 0.5 * th * std::cos(0.5 * th) / std::sin(0.5 * th)) / th2;
  const Eigen::Vector3d wt = w.cross(t);
  return t - 0.5 * wt + c * w.cross(wt);
}

} // namespace lct
