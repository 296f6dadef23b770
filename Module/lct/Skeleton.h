/**
 * @file Skeleton.h
 * @brief A skeletal animation as data: a joint hierarchy, one local transform per joint per
 *        frame, and its forward kinematics.
 *
 * The joints are in an order in which every parent precedes its children (the depth-first
 * order of a BVH file), so forward kinematics is one pass: world_j = world_parent(j) local_j,
 * with world_root = local_root. A joint's local transform maps its own frame into its parent's;
 * its translation column is where the joint sits in the parent (the BVH OFFSET plus any
 * position channels), its linear part the joint's rotation (and, for formats that have it,
 * scale). End sites are joints without motion of their own (a constant local transform); they
 * carry the tips of the last bones.
 *
 * This is what vtkSkeletonAnimationReader fills from a file (through assimp) and what the
 * analysis classes (vtkTransformSequencePCA) and the interpolators take, one channel per joint.
 */
#ifndef lct_Skeleton_h
#define lct_Skeleton_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace lct
{

struct SkeletonJoint
{
  std::string name;
  int parent = -1;      ///< index of the parent joint, -1 for a root
  bool endSite = false; ///< no motion of its own: the tip of a bone
};

struct SkeletalAnimation
{
  std::vector<SkeletonJoint> joints; ///< parents precede their children
  int frames = 0;
  double frameTime = 0.0; ///< seconds between frames (> 0)
  /// Local transforms, frame-major: locals[f * joints.size() + j].
  std::vector<Eigen::Matrix4d> locals;

  int jointCount() const noexcept { return static_cast<int>(this->joints.size()); }
  const Eigen::Matrix4d& local(int frame, int joint) const
  {
    return this->locals[static_cast<std::size_t>(frame) * this->joints.size() +
      static_cast<std::size_t>(joint)];
  }
  /// The depth of a joint (0 for a root).
  int depth(int joint) const;
};

/// The world transforms of every joint at `frame` (world.size() becomes jointCount()).
VTKLCT_EXPORT void worldTransforms(
  const SkeletalAnimation& animation, int frame, std::vector<Eigen::Matrix4d>& world);

/// Whether the hierarchy is well formed: every parent index precedes its child, and the
/// transform count is frames x joints. `why` names the first problem.
VTKLCT_EXPORT bool isConsistent(const SkeletalAnimation& animation, std::string* why = nullptr);

} // namespace lct

#endif
