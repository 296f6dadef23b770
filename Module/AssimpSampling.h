// Sampling assimp's node animations (private to the module's readers, not installed): keys
// bracketed by time, positions and scales interpolated linearly, rotations by slerp, as assimp's
// own viewer does; a channel's missing keys fall back on the node's rest transform.
#ifndef lct_AssimpSampling_h
#define lct_AssimpSampling_h

#include <assimp/anim.h>
#include <assimp/matrix4x4.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace lct_assimp
{

inline Eigen::Matrix4d toEigen(const aiMatrix4x4& m)
{
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
    m.d4;
  return out;
}

/// The index of the last key at or before `time` (0 before the first), and the fraction of
/// the way to the next one.
template <typename Key>
inline std::pair<unsigned, double> bracket(const Key* keys, unsigned count, double time)
{
  const Key* after =
    std::upper_bound(keys, keys + count, time, [](double t, const Key& k) { return t < k.mTime; });
  if (after == keys)
  {
    return { 0u, 0.0 };
  }
  const unsigned i = static_cast<unsigned>(after - keys) - 1;
  if (i + 1 >= count || !(keys[i + 1].mTime > keys[i].mTime))
  {
    return { i, 0.0 };
  }
  return { i, (time - keys[i].mTime) / (keys[i + 1].mTime - keys[i].mTime) };
}

inline Eigen::Vector3d sampleVector(
  const aiVectorKey* keys, unsigned count, double time, const Eigen::Vector3d& fallback)
{
  if (count == 0)
  {
    return fallback;
  }
  const auto [i, s] = bracket(keys, count, time);
  const Eigen::Vector3d a(keys[i].mValue.x, keys[i].mValue.y, keys[i].mValue.z);
  if (s == 0.0)
  {
    return a;
  }
  const Eigen::Vector3d b(keys[i + 1].mValue.x, keys[i + 1].mValue.y, keys[i + 1].mValue.z);
  return (1.0 - s) * a + s * b;
}

inline Eigen::Quaterniond sampleRotation(
  const aiQuatKey* keys, unsigned count, double time, const Eigen::Quaterniond& fallback)
{
  if (count == 0)
  {
    return fallback;
  }
  const auto [i, s] = bracket(keys, count, time);
  const aiQuaternion& qa = keys[i].mValue;
  const Eigen::Quaterniond a(qa.w, qa.x, qa.y, qa.z);
  if (s == 0.0)
  {
    return a;
  }
  const aiQuaternion& qb = keys[i + 1].mValue;
  return a.slerp(s, Eigen::Quaterniond(qb.w, qb.x, qb.y, qb.z));
}

/// The local transform of a node at `tick` (the animation's time unit): its channel sampled, or
/// `rest` (the node's own transform) without a channel or for the channel's missing keys.
inline Eigen::Matrix4d sampleLocal(
  const aiNodeAnim* channel, const Eigen::Matrix4d& rest, double tick)
{
  if (!channel)
  {
    return rest;
  }
  const Eigen::Vector3d restTranslation = rest.topRightCorner<3, 1>();
  const Eigen::Matrix3d restLinear = rest.topLeftCorner<3, 3>();
  const Eigen::Vector3d restScale = restLinear.colwise().norm();
  const Eigen::Quaterniond restRotation(
    Eigen::Matrix3d(restLinear * restScale.cwiseInverse().asDiagonal()));
  const Eigen::Vector3d position =
    sampleVector(channel->mPositionKeys, channel->mNumPositionKeys, tick, restTranslation);
  const Eigen::Vector3d scale =
    sampleVector(channel->mScalingKeys, channel->mNumScalingKeys, tick, restScale);
  const Eigen::Quaterniond rotation =
    sampleRotation(channel->mRotationKeys, channel->mNumRotationKeys, tick, restRotation);
  Eigen::Matrix4d local = Eigen::Matrix4d::Identity();
  local.topLeftCorner<3, 3>() = rotation.normalized().toRotationMatrix() * scale.asDiagonal();
  local.topRightCorner<3, 1>() = position;
  return local;
}

/// Why a file must not be handed to assimp, or "": a PLY header declaring more elements than
/// the file has bytes (each element takes at least one). assimp allocates for the declared
/// count before it reads a value: a 189-byte PLY declaring 2e9 vertices grew both readers to
/// several GB without returning. Other formats are left to assimp (see the README's limits).
inline std::string declaredCountProblem(const std::string& file)
{
  std::string extension = std::filesystem::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  std::error_code error;
  const auto bytes = std::filesystem::file_size(file, error);
  if (extension != ".ply" || error)
  {
    return "";
  }
  std::ifstream in(file, std::ios::binary);
  std::string line;
  for (int lines = 0; lines < 10000 && std::getline(in, line); ++lines)
  {
    std::istringstream words(line);
    std::string keyword, name, count;
    words >> keyword;
    if (keyword == "end_header")
    {
      break;
    }
    if (keyword == "element" && words >> name >> count)
    {
      const double declared = std::strtod(count.c_str(), nullptr);
      if (declared > static_cast<double>(bytes))
      {
        return "its PLY header declares " + count + " " + name + " elements but the file has " +
          std::to_string(bytes) +
          " bytes (each element takes at least one): truncated or corrupted";
      }
    }
  }
  return "";
}

} // namespace lct_assimp

#endif
