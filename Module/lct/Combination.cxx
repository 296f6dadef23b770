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

Result<LogCoords> relativeLog(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& key, Parametrisation p)
{
  const Eigen::Matrix4d step =
    p == Parametrisation::Polar ? worldStep(reference, key) : relativeStep(reference, key);
  // A step that overflows is out of range, not "NaN or Inf in the input".
  if (!step.allFinite())
  {
    return Result<LogCoords>::failure(Status::OutOfRange);
  }
  const auto log = logarithm(step, p);
  // Between two maps of positive determinant the step has one too: a step whose determinant
  // rounded to 0 or below is too ill-conditioned for double, not a reflection (the message
  // read "negative determinant" for keys of determinant 1 and 2e-15).
  if ((log.status == Status::NegativeDeterminant || log.status == Status::Singular) &&
    validateAffine(reference) == Status::Ok && validateAffine(key) == Status::Ok)
  {
    return Result<LogCoords>::failure(Status::IllConditioned);
  }
  return log;
}

Eigen::Matrix4d applyRelativeStep(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& step, Parametrisation p, bool accurate)
{
  return p == Parametrisation::Polar ? applyWorldStep(reference, step, accurate)
                                     : productWith(reference, step, accurate);
}

namespace
{
/// exp(sum_i w_i log(step from R to T_i)) (Polar: worldStep, MatrixLog: R^-1 T_i), or
/// exp(sum_i w_i log T_i) without a reference R.
Result<Eigen::Matrix4d> combineTimes(const double* weights, const Eigen::Matrix4d* keys,
  std::size_t count, const Eigen::Matrix4d* reference, Parametrisation p)
{
  LogCoords sum = LogCoords::Zero();
  for (std::size_t i = 0; i < count; ++i)
  {
    if (weights[i] == 0.0 || (reference && &keys[i] == reference))
    {
      continue; // log(R^-1 R) = 0 exactly
    }
    const auto logKey = reference ? relativeLog(*reference, keys[i], p) : logarithm(keys[i], p);
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
  return combineTimes(weights, keys, count, nullptr, p);
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
  auto relative = combineTimes(weights, keys, count, &keys[reference], p);
  if (!relative)
  {
    return relative;
  }
  const bool accurate = needsAccurateProducts(keys[reference]);
  relative.value = applyRelativeStep(keys[reference], relative.value, p, accurate);
  if (!relative.value.allFinite())
  {
    return Result<Eigen::Matrix4d>::failure(Status::OutOfRange);
  }
  // Between ill-conditioned keys the intermediates may lose the smallest stretch: check the
  // determinant, prod det(K_i)^(w_i), as lct::KeyLogs does.
  bool involved = accurate;
  double expected = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    if (weights[i] != 0.0)
    {
      involved = involved || needsAccurateProducts(keys[i]);
      expected += weights[i] * accurateLogDeterminant(keys[i]);
    }
  }
  if (involved && !determinantMatches(relative.value, expected))
  {
    return Result<Eigen::Matrix4d>::failure(Status::InaccurateResult);
  }
  return relative;
}

} // namespace lct
