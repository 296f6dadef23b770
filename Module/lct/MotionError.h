/**
 * @file MotionError.h
 * @brief How far one skeletal animation is from another where it shows: the world positions of
 *        the joints, the measure of animation-compression libraries (ACL, Unreal).
 *
 * The error of a frame at a joint is the distance between the joint's world positions (the
 * translation of its forward-kinematics transform, lct/Skeleton.h) in the two animations; end
 * sites count like any joint, and so does every frame, the first included. The statistics are
 * over all joints and frames.
 *
 * The skeleton height H (the unit of relative tolerances) is the Y extent, max - min, of the
 * joint and end-site positions in the rest pose: every local rotation the identity, every
 * joint at its frame-0 translation except the roots, which sit at the origin (the pose of a
 * BVH file with every channel 0, whose joints other than the root have no position channels).
 *
 * Pure functions: safe to call concurrently.
 */
#ifndef lct_MotionError_h
#define lct_MotionError_h

#include "vtkLCTModule.h"

#include "lct/Skeleton.h"

#include <vector>

namespace lct
{

struct PositionErrorStatistics
{
  double max = 0.0;
  double p99 = 0.0; ///< the 99th percentile (nearest rank) over joints x frames
  double mean = 0.0;
  int worstFrame = 0;
  int worstJoint = 0;
};

/// The world positions of every joint at every frame: 3 x joints per frame, frame-major.
VTKLCT_EXPORT std::vector<double> worldPositions(const SkeletalAnimation& animation);

/// Errors of `approximation` against the positions `reference` from worldPositions (same
/// hierarchy and frame count: callers check). A non-finite position counts as an infinite error.
VTKLCT_EXPORT PositionErrorStatistics positionErrors(
  const std::vector<double>& reference, const SkeletalAnimation& approximation);

/// How far world positions computed from float32 values (assimp's reading of a BVH file) can be
/// from those of the values the file's text holds, estimated at every frame and joint as
/// kFloat32ChainFactor 2^-24 (1 + depth) sum |t_i| over the joint's chain (t_i the local
/// translations: each rounds by ~2^-24 relative, and each rotation above the joint by ~2^-24
/// radians, which moves what hangs below it), maximised over frames and joints. On the three
/// assimp-testmodels clips the largest deviation measured against a double evaluation of the
/// text is 1/4 to 1/8 of it (Unit.SkeletonReader). A position tolerance below it cannot be
/// verified against the file's text by a float32 reader.
VTKLCT_EXPORT double float32PositionResolution(const SkeletalAnimation& animation);

/// The factor of float32PositionResolution (rounding is not all in one direction: the worst
/// case of the sum would be ~8 times looser than what files show).
constexpr double kFloat32ChainFactor = 2.0;

/// H, as above (0 for a skeleton without extent in Y).
VTKLCT_EXPORT double restPoseHeight(const SkeletalAnimation& animation);

} // namespace lct

#endif
