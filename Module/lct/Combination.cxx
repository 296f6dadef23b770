#include "lct/Combination.h"

#include "lct/Affine.h"
#include "lct/Parametrisation.h"

namespace lct
{

LogCoords weightedSum(const double* weights, const LogCoords* coords, std::size_t count) noexcept
{
  LogCoords sum = LogCoords::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    sum += weights[i] * coords[i];
  }
  return sum;
}

std::size_t largestWeight(const double* weights, std::size_t count) noexcept
{
  std::size_t best = 0;
  for (std::size_t i = 1; i < count; ++i)
  {
    if (weights[i] > weights[best])
    {
      best = i;
    }
  }
  return best;
}

namespace
{
/// exp(sum_i w_i log(X T_i)) with X = I or R^-1.
Result<Eigen::Matrix4d> combineTimes(const double* weights, const Eigen::Matrix4d* keys,
  std::size_t count, const Eigen::Matrix4d& leftFactor, Parametrisation p)
{
  LogCoords sum = LogCoords::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    if (weights[i] == 0.0)
    {
      continue;
    }
    const auto logKey = logarithm(leftFactor * keys[i], p);
    if (!logKey)
    {
      return Result<Eigen::Matrix4d>::failure(logKey.status);
    }
    sum += weights[i] * logKey.value;
  }
  return exponential(sum, p);
}
} // namespace

Result<Eigen::Matrix4d> combine(
  const double* weights, const Eigen::Matrix4d* keys, std::size_t count, Parametrisation p)
{
  return combineTimes(weights, keys, count, Eigen::Matrix4d::Identity(), p);
}

Result<Eigen::Matrix4d> combineRelative(const double* weights, const Eigen::Matrix4d* keys,
  std::size_t count, std::size_t reference, Parametrisation p)
{
  if (reference >= count)
  {
    return Result<Eigen::Matrix4d>::failure(Status::InvalidArgument);
  }
  const Status valid = validateAffine(keys[reference]);
  if (valid != Status::Ok)
  {
    return Result<Eigen::Matrix4d>::failure(valid);
  }
  auto relative = combineTimes(weights, keys, count, inverseAffine(keys[reference]), p);
  if (relative)
  {
    relative.value = keys[reference] * relative.value;
  }
  return relative;
}

} // namespace lct
