#include "lct/MotionError.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{

std::vector<double> worldPositions(const SkeletalAnimation& animation)
{
  const int joints = animation.jointCount();
  std::vector<double> positions(static_cast<std::size_t>(animation.frames) * 3 * joints);
  std::vector<Eigen::Matrix4d> world;
  for (int f = 0; f < animation.frames; ++f)
  {
    worldTransforms(animation, f, world);
    for (int j = 0; j < joints; ++j)
    {
      Eigen::Map<Eigen::Vector3d> position(
        &positions[(static_cast<std::size_t>(f) * joints + j) * 3]);
      position = world[static_cast<std::size_t>(j)].block<3, 1>(0, 3);
    }
  }
  return positions;
}

PositionErrorStatistics positionErrors(
  const std::vector<double>& reference, const SkeletalAnimation& approximation)
{
  const std::vector<double> positions = worldPositions(approximation);
  const std::size_t count = std::min(positions.size(), reference.size()) / 3;
  PositionErrorStatistics stats;
  if (count == 0)
  {
    return stats;
  }
  std::vector<double> errors(count);
  double sum = 0.0;
  for (std::size_t i = 0; i < count; ++i)
  {
    const double dx = positions[3 * i] - reference[3 * i];
    const double dy = positions[3 * i + 1] - reference[3 * i + 1];
    const double dz = positions[3 * i + 2] - reference[3 * i + 2];
    double e = std::sqrt(dx * dx + dy * dy + dz * dz);
    if (!std::isfinite(e))
    {
      e = std::numeric_limits<double>::infinity();
    }
    errors[i] = e;
    sum += e;
    if (e > stats.max || i == 0)
    {
      stats.max = e;
      stats.worstFrame = static_cast<int>(i / static_cast<std::size_t>(approximation.jointCount()));
      stats.worstJoint = static_cast<int>(i % static_cast<std::size_t>(approximation.jointCount()));
    }
  }
  stats.mean = sum / static_cast<double>(count);
  const std::size_t rank =
    static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(count))) - 1;
  std::nth_element(
    errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(rank), errors.end());
  stats.p99 = errors[rank];
  return stats;
}

double float32PositionResolution(const SkeletalAnimation& animation)
{
  const int joints = animation.jointCount();
  std::vector<double> chain(static_cast<std::size_t>(joints));
  std::vector<int> depth(static_cast<std::size_t>(joints));
  for (int j = 0; j < joints; ++j)
  {
    const int parent = animation.joints[static_cast<std::size_t>(j)].parent;
    depth[static_cast<std::size_t>(j)] =
      parent < 0 ? 0 : depth[static_cast<std::size_t>(parent)] + 1;
  }
  double worst = 0.0;
  for (int f = 0; f < animation.frames; ++f)
  {
    for (int j = 0; j < joints; ++j)
    {
      const int parent = animation.joints[static_cast<std::size_t>(j)].parent;
      const double length = animation.local(f, j).block<3, 1>(0, 3).norm();
      chain[static_cast<std::size_t>(j)] =
        (parent < 0 ? 0.0 : chain[static_cast<std::size_t>(parent)]) + length;
      worst = std::max(
        worst, (1.0 + depth[static_cast<std::size_t>(j)]) * chain[static_cast<std::size_t>(j)]);
    }
  }
  return kFloat32ChainFactor * std::ldexp(worst, -24);
}

double restPoseHeight(const SkeletalAnimation& animation)
{
  const int joints = animation.jointCount();
  if (joints == 0 || animation.frames <= 0)
  {
    return 0.0;
  }
  std::vector<Eigen::Vector3d> world(static_cast<std::size_t>(joints));
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  for (int j = 0; j < joints; ++j)
  {
    const int parent = animation.joints[static_cast<std::size_t>(j)].parent;
    world[static_cast<std::size_t>(j)] = parent < 0
      ? Eigen::Vector3d::Zero()
      : Eigen::Vector3d(
          world[static_cast<std::size_t>(parent)] + animation.local(0, j).block<3, 1>(0, 3));
    low = std::min(low, world[static_cast<std::size_t>(j)].y());
    high = std::max(high, world[static_cast<std::size_t>(j)].y());
  }
  return high - low;
}

} // namespace lct
