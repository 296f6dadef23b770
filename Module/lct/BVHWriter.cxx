#include "lct/BVHWriter.h"

#include <Eigen/Geometry>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace lct
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegrees = 180.0 / kPi;

/// x + 2 pi k nearest to `target`.
/// Channels are unwrapped by whole turns for continuity up to this many turns either way.
constexpr double kMaxUnwrappedTurns = 10.0;

double unwrapNear(double x, double target)
{
  return x + 2.0 * kPi * std::round((target - x) / (2.0 * kPi));
}

Eigen::Vector3d unwrapNear(const Eigen::Vector3d& angles, const Eigen::Vector3d& target)
{
  return Eigen::Vector3d(unwrapNear(angles[0], target[0]), unwrapNear(angles[1], target[1]),
    unwrapNear(angles[2], target[2]));
}

std::string number(double x)
{
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", x == 0.0 ? 0.0 : x); // no "-0"
  return buffer;
}

/// `name` as one BVH token: readers split names at white space and take "{" and "}" as the
/// block's braces, so those (and control characters) become '_'; an empty name becomes
/// joint_<index>.
std::string bvhName(const std::string& name, int index)
{
  if (name.empty())
  {
    return "joint_" + std::to_string(index);
  }
  std::string token = name;
  for (char& c : token)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u <= ' ' || u == 0x7f || c == '{' || c == '}')
    {
      c = '_';
    }
  }
  return token;
}

/// The names written for the joints: bvhName, made unique (readers match channels to joints by
/// name, and "a b" and "a_b" both give "a_b"). A name that is already a valid token keeps it (the
/// first of equal ones); the others take the first free of token, token_2, token_3, ...
std::vector<std::string> uniqueBVHNames(const SkeletalAnimation& animation)
{
  const std::size_t n = animation.joints.size();
  std::vector<std::string> names(n);
  std::set<std::string> used;
  std::vector<bool> named(n, false);
  for (std::size_t j = 0; j < n; ++j)
  {
    const std::string& name = animation.joints[j].name;
    if (!animation.joints[j].endSite && bvhName(name, static_cast<int>(j)) == name &&
      used.insert(name).second)
    {
      names[j] = name;
      named[j] = true;
    }
  }
  for (std::size_t j = 0; j < n; ++j)
  {
    if (named[j] || animation.joints[j].endSite)
    {
      continue;
    }
    const std::string token = bvhName(animation.joints[j].name, static_cast<int>(j));
    std::string name = token;
    for (int k = 2; !used.insert(name).second; ++k)
    {
      name = token + "_" + std::to_string(k);
    }
    names[j] = name;
  }
  return names;
}

bool fail(std::string* why, const std::string& reason)
{
  if (why)
  {
    *why = reason;
  }
  return false;
}
} // namespace

Eigen::Vector3d eulerAnglesNear(
  const Eigen::Matrix3d& rotation, const int order[3], const Eigen::Vector3d& previous)
{
  // Eigen's solution has a in [0, pi]; the other Tait-Bryan solution is (a + pi, pi - b, c + pi)
  // (R_i(pi) R_j(pi - b) R_k(pi) = R_j(b) for distinct axes i, j, k).
  const Eigen::Vector3d first = rotation.eulerAngles(order[0], order[1], order[2]);
  const Eigen::Vector3d second(first[0] + kPi, kPi - first[1], first[2] + kPi);
  const Eigen::Vector3d a = unwrapNear(first, previous);
  const Eigen::Vector3d b = unwrapNear(second, previous);
  return (a - previous).squaredNorm() <= (b - previous).squaredNorm() ? a : b;
}

namespace
{
/// The axes (0, 1, 2 for x, y, z) of a permutation of "XYZ" (either case), or false.
bool rotationAxes(const std::string& rotationOrder, int (&order)[3])
{
  bool seen[3] = { false, false, false };
  bool valid = rotationOrder.size() == 3;
  for (int i = 0; valid && i < 3; ++i)
  {
    const char c = static_cast<char>(std::toupper(rotationOrder[static_cast<std::size_t>(i)]));
    const int axis = c == 'X' ? 0 : c == 'Y' ? 1 : c == 'Z' ? 2 : -1;
    valid = axis >= 0 && !seen[axis];
    if (valid)
    {
      seen[axis] = true;
      order[i] = axis;
    }
  }
  return valid;
}
} // namespace

bool isRotationOrder(const std::string& order)
{
  int axes[3];
  return rotationAxes(order, axes);
}

bool writeBVH(const SkeletalAnimation& animation, const std::string& rotationOrder,
  std::ostream& out, std::string* why)
{
  std::string reason;
  if (!isConsistent(animation, &reason))
  {
    return fail(why, reason);
  }
  int order[3];
  if (!rotationAxes(rotationOrder, order))
  {
    return fail(why, "the rotation order \"" + rotationOrder + "\" is not a permutation of XYZ");
  }
  if (!(animation.frameTime > 0.0) || !std::isfinite(animation.frameTime))
  {
    return fail(why, "the frame time is not positive");
  }
  const int n = animation.jointCount();
  // Which joints need position channels, and their offsets; every transform must be rigid.
  std::vector<bool> moves(static_cast<std::size_t>(n), false);
  std::vector<Eigen::Vector3d> offsets(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j)
  {
    const SkeletonJoint& joint = animation.joints[static_cast<std::size_t>(j)];
    offsets[static_cast<std::size_t>(j)] = joint.parent < 0
      ? Eigen::Vector3d::Zero()
      : Eigen::Vector3d(animation.local(0, j).topRightCorner<3, 1>());
    moves[static_cast<std::size_t>(j)] = joint.parent < 0;
    for (int f = 0; f < animation.frames; ++f)
    {
      const Eigen::Matrix4d& m = animation.local(f, j);
      const Eigen::Matrix3d r = m.topLeftCorner<3, 3>();
      if (!m.allFinite() || (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
        r.determinant() < 0.0)
      {
        return fail(why,
          "joint " + joint.name + " at frame " + std::to_string(f) +
            " is not a rotation and translation (BVH holds no scale, shear or reflection)");
      }
      // Largest entries, not norms: a norm squares them and is Inf beyond ~1.3e154, where
      // Inf > Inf dropped a translation motion of 1e300 with success.
      const Eigen::Vector3d& offset = offsets[static_cast<std::size_t>(j)];
      if ((m.topRightCorner<3, 1>() - offset).cwiseAbs().maxCoeff() >
        1e-12 * (1.0 + offset.cwiseAbs().maxCoeff()))
      {
        moves[static_cast<std::size_t>(j)] = true;
      }
      if (joint.endSite &&
        (moves[static_cast<std::size_t>(j)] || (r - Eigen::Matrix3d::Identity()).norm() > 1e-9))
      {
        return fail(
          why, "end site " + joint.name + " moves or turns (an End Site has no channels)");
      }
    }
  }
  // One hierarchy: a BVH file has one ROOT (readers stop at a second one).
  int roots = 0;
  std::string rootNames;
  for (int j = 0; j < n; ++j)
  {
    if (animation.joints[static_cast<std::size_t>(j)].parent < 0)
    {
      rootNames += (roots++ ? ", " : "") + animation.joints[static_cast<std::size_t>(j)].name;
    }
  }
  if (roots != 1)
  {
    return fail(why,
      "a BVH file holds one hierarchy (one ROOT) and this skeleton has " + std::to_string(roots) +
        " root joints (" + rootNames + ")");
  }
  // Children lists, for the nested blocks; an End Site block cannot hold others.
  std::vector<std::vector<int>> children(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j)
  {
    const int p = animation.joints[static_cast<std::size_t>(j)].parent;
    if (p >= 0)
    {
      if (animation.joints[static_cast<std::size_t>(p)].endSite)
      {
        return fail(
          why, "end site " + animation.joints[static_cast<std::size_t>(p)].name + " has children");
      }
      children[static_cast<std::size_t>(p)].push_back(j);
    }
  }
  const std::vector<std::string> names = uniqueBVHNames(animation);
  const char axisName[3] = { 'X', 'Y', 'Z' };
  out << "HIERARCHY\n";
  // Iterative, so that deep hierarchies cannot overflow the stack: (joint, open/close).
  std::vector<std::pair<int, bool>> stack;
  for (int j = n - 1; j >= 0; --j)
  {
    if (animation.joints[static_cast<std::size_t>(j)].parent < 0)
    {
      stack.push_back({ j, true });
    }
  }
  std::vector<int> fileOrder; // the joints in the order of their blocks: the channel order
  while (!stack.empty())
  {
    const auto [j, open] = stack.back();
    stack.pop_back();
    const SkeletonJoint& joint = animation.joints[static_cast<std::size_t>(j)];
    if (open)
    {
      fileOrder.push_back(j);
    }
    const std::string indent(static_cast<std::size_t>(animation.depth(j)), '\t');
    if (!open)
    {
      out << indent << "}\n";
      continue;
    }
    // A joint with position channels sits at OFFSET 0: readers that add the channels to the
    // OFFSET (the BVH text's reading, and the module's reader) and readers that take them
    // instead of it (assimp 5.2 itself) then agree.
    const Eigen::Vector3d o = moves[static_cast<std::size_t>(j)]
      ? Eigen::Vector3d::Zero()
      : offsets[static_cast<std::size_t>(j)];
    out << indent
        << (joint.endSite
               ? std::string("End Site")
               : (joint.parent < 0 ? "ROOT " : "JOINT ") + names[static_cast<std::size_t>(j)])
        << "\n"
        << indent << "{\n"
        << indent << "\tOFFSET " << number(o[0]) << " " << number(o[1]) << " " << number(o[2])
        << "\n";
    if (!joint.endSite)
    {
      const bool position = moves[static_cast<std::size_t>(j)];
      out << indent << "\tCHANNELS " << (position ? 6 : 3);
      if (position)
      {
        out << " Xposition Yposition Zposition";
      }
      for (int axis : order)
      {
        out << " " << axisName[axis] << "rotation";
      }
      out << "\n";
    }
    stack.push_back({ j, false });
    const auto& c = children[static_cast<std::size_t>(j)];
    for (auto it = c.rbegin(); it != c.rend(); ++it)
    {
      stack.push_back({ *it, true });
    }
  }
  out << "MOTION\nFrames: " << animation.frames << "\nFrame Time: " << number(animation.frameTime)
      << "\n";
  std::vector<Eigen::Vector3d> previous(static_cast<std::size_t>(n), Eigen::Vector3d::Zero());
  for (int f = 0; f < animation.frames; ++f)
  {
    std::string row;
    for (const int j : fileOrder)
    {
      if (animation.joints[static_cast<std::size_t>(j)].endSite)
      {
        continue;
      }
      const Eigen::Matrix4d& m = animation.local(f, j);
      if (moves[static_cast<std::size_t>(j)])
      {
        const Eigen::Vector3d p = m.topRightCorner<3, 1>(); // at OFFSET 0
        row += number(p[0]) + " " + number(p[1]) + " " + number(p[2]) + " ";
      }
      Eigen::Vector3d angles =
        eulerAnglesNear(m.topLeftCorner<3, 3>(), order, previous[static_cast<std::size_t>(j)]);
      // A joint spinning on would unwrap beyond what readers take accurately (assimp converts
      // degrees to radians in float32, and the module's reader refuses |angle| > 1e4 degrees):
      // an angle beyond kMaxUnwrappedTurns is brought back by whole turns (the same rotation).
      for (int a = 0; a < 3; ++a)
      {
        if (std::abs(angles[a]) > kMaxUnwrappedTurns * 2.0 * kPi)
        {
          angles[a] = std::remainder(angles[a], 2.0 * kPi);
        }
      }
      previous[static_cast<std::size_t>(j)] = angles;
      row += number(angles[0] * kDegrees) + " " + number(angles[1] * kDegrees) + " " +
        number(angles[2] * kDegrees) + " ";
    }
    row.back() = '\n';
    out << row;
  }
  return out.good() ? true : fail(why, "the stream failed while writing");
}

} // namespace lct
