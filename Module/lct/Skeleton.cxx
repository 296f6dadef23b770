#include "lct/Skeleton.h"

namespace lct
{

int SkeletalAnimation::depth(int joint) const
{
  int d = 0;
  for (int p = this->joints[static_cast<std::size_t>(joint)].parent; p >= 0;
       p = this->joints[static_cast<std::size_t>(p)].parent)
  {
    ++d;
  }
  return d;
}

void worldTransforms(
  const SkeletalAnimation& animation, int frame, std::vector<Eigen::Matrix4d>& world)
{
  const int n = animation.jointCount();
  world.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j)
  {
    const int p = animation.joints[static_cast<std::size_t>(j)].parent;
    world[static_cast<std::size_t>(j)] = p < 0
      ? animation.local(frame, j)
      : world[static_cast<std::size_t>(p)] * animation.local(frame, j);
  }
}

bool isConsistent(const SkeletalAnimation& animation, std::string* why)
{
  auto fail = [why](const std::string& reason) {
    if (why)
    {
      *why = reason;
    }
    return false;
  };
  if (animation.joints.empty() || animation.frames <= 0)
  {
    return fail("no joints or no frames");
  }
  for (std::size_t j = 0; j < animation.joints.size(); ++j)
  {
    const int p = animation.joints[j].parent;
    if (p < -1 || p >= static_cast<int>(j))
    {
      return fail("joint " + std::to_string(j) + " has parent " + std::to_string(p) +
        ", which does not precede it");
    }
  }
  if (animation.locals.size() !=
    static_cast<std::size_t>(animation.frames) * animation.joints.size())
  {
    return fail("the transform count is not frames x joints");
  }
  return true;
}

} // namespace lct
