/**
 * @file BVHWriter.h
 * @brief Write a skeletal animation as a Biovision hierarchy (BVH) file.
 *
 * The hierarchy is written as it is (joint names, parents, depth-first order; a BVH file holds
 * one hierarchy, so a skeleton with several roots is refused), every joint with a parent at its
 * OFFSET: its translation at frame 0. Roots, and joints whose translation changes over the
 * frames, get position channels (Xposition Yposition Zposition, the whole translation) at
 * OFFSET 0, where readers that add the channels to the OFFSET and readers that take them
 * instead of it (assimp 5.2 itself) agree. A name is written as one token: white space, control
 * characters and braces become '_' (readers split names there), an empty name joint_<index>;
 * names are then made unique (readers match channels to joints by name): a name already valid
 * keeps it (the first of equal ones), a changed or repeated one takes the first of token,
 * token_2, token_3, ... that no other joint uses. Every joint that is not an end site gets three
 * rotation channels in `rotationOrder` (e.g. "ZYX": R = Rz(a) Ry(b) Rx(c), the BVH convention of
 * multiplying in channel order), end sites an End Site block. The Euler angles of each frame
 * are the solution nearest to the previous frame's (of the two Tait-Bryan solutions, unwrapped
 * by whole turns), so the channels are continuous wherever the motion is, up to 10 turns either
 * way (beyond, an angle is brought back by whole turns: readers take angles of more than ~1e4
 * degrees inaccurately, assimp converting them in float32). Numbers are written
 * with 10 significant digits. Frame Time is the animation's frame time.
 *
 * BVH holds rotations and translations only: a local transform with scale or shear (linear
 * part not orthogonal to 1e-6) cannot be written and is refused.
 */
#ifndef lct_BVHWriter_h
#define lct_BVHWriter_h

#include "vtkLCTModule.h"

#include "lct/Skeleton.h"

#include <ostream>
#include <string>

namespace lct
{

/// Whether `order` is a permutation of "XYZ" (either case): a rotation order writeBVH takes.
VTKLCT_EXPORT bool isRotationOrder(const std::string& order);

/// Writes `animation` to `out`. Returns false, with the reason in `why`, for an inconsistent
/// animation, a rotation order that is not a permutation of "XYZ", or a local transform that
/// is not rigid; `out` may then hold a partial file (write to a temporary and rename).
VTKLCT_EXPORT bool writeBVH(const SkeletalAnimation& animation, const std::string& rotationOrder,
  std::ostream& out, std::string* why = nullptr);

/// The angles (radians) of R = R_order[0](a) R_order[1](b) R_order[2](c), order a permutation
/// of 0, 1, 2 (x, y, z), of the two solutions the one nearest `previous` after unwrapping each
/// angle by whole turns.
VTKLCT_EXPORT Eigen::Vector3d eulerAnglesNear(
  const Eigen::Matrix3d& rotation, const int order[3], const Eigen::Vector3d& previous);

} // namespace lct

#endif
