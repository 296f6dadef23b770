#include "lct/MonotoneTangents.h"

#include <algorithm>
#include <cmath>

namespace lct
{

KeyTangent monotoneTangentOfParts(const double* partBefore, const double* partAfter, int partCount,
  double roundOff, double hPrevious, double hNext)
{
  const double span = hPrevious + hNext;
  const KeyTangent catmullRom{ hPrevious / span, hNext / span };
  if (!(hPrevious > 0.0 && hNext > 0.0 && std::isfinite(span)))
  {
    return catmullRom;
  }
  // The speed of each part before and after the key, made unit-free by the part's own scale. A
  // part whose steps are at round-off level for the steps is left out: unit-free, the 1e-16 a
  // MatrixLog leaves in the translation of a pure turn, or a 1e-15 translation, would weigh as
  // much as the turn. (A path of translations alone keeps them at any size.)
  double before2 = 0.0, after2 = 0.0;
  for (int g = 0; g < partCount; ++g)
  {
    if (!(std::isfinite(partBefore[g]) && std::isfinite(partAfter[g])))
    {
      return catmullRom;
    }
    if (!(std::max(partBefore[g], partAfter[g]) > roundOff))
    {
      continue;
    }
    const double before = partBefore[g] / hPrevious;
    const double after = partAfter[g] / hNext;
    const double scale = before + after;
    if (scale > 0.0)
    {
      before2 += (before / scale) * (before / scale);
      after2 += (after / scale) * (after / scale);
    }
  }
  const double before = std::sqrt(before2), after = std::sqrt(after2);
  if (!(before + after > 0.0))
  {
    return catmullRom; // the neighbours are the key: every tangent is 0
  }
  if (before == 0.0 || after == 0.0)
  {
    // The harmonic mean with a still side is 0. Weighting the still secant by 1 would give the
    // same tangent, but as large opposite weights of two keys very close in time.
    return { 0.0, 0.0 };
  }
  // Fritsch & Butland: each secant weighted by the other's speed.
  return { after / (before + after), before / (before + after) };
}

KeyTangent monotoneTangent(
  const LogCoords& previous, const LogCoords& next, double hPrevious, double hNext)
{
  if (!previous.allFinite() || !next.allFinite())
  {
    const double span = hPrevious + hNext;
    return { hPrevious / span, hNext / span };
  }
  // The parts are the translation (a length) and the linear part, rotation and stretch together
  // (both logs, without units: a 1e-6 stretch beside a turn of a radian is negligible, as it is
  // to the eye); stableNorm, so that steps near the double range do not overflow.
  const double before[] = { previous.head<3>().stableNorm(), previous.tail<9>().stableNorm() };
  const double after[] = { next.head<3>().stableNorm(), next.tail<9>().stableNorm() };
  const double roundOff =
    kRoundOffPart * std::max(previous.cwiseAbs().maxCoeff(), next.cwiseAbs().maxCoeff());
  return monotoneTangentOfParts(before, after, 2, roundOff, hPrevious, hNext);
}

int cameraChannelGroup(int channel)
{
  using C = CameraKey;
  switch (channel)
  {
    case C::LogDistance:
      return 0;
    case C::LogTanHalfAngle:
      return 1;
    case C::LogParallelScale:
      return 2;
    case C::WindowCenterX:
    case C::WindowCenterY:
      return 3;
    case C::ShearX:
    case C::ShearY:
    case C::ShearCenter:
      return 4;
    default:
      return 5; // LogNear, LogFar
  }
}

CameraTangents monotoneCameraTangents(const CameraKey& previous, const CameraKey& key,
  const CameraKey& next, const Eigen::Vector3d& rotationBefore,
  const Eigen::Vector3d& rotationAfter, double hPrevious, double hNext)
{
  CameraTangents tangents;
  {
    const Eigen::Vector3d focalBefore =
      previous.focalFrame.topRightCorner<3, 1>() - key.focalFrame.topRightCorner<3, 1>();
    const Eigen::Vector3d focalAfter =
      next.focalFrame.topRightCorner<3, 1>() - key.focalFrame.topRightCorner<3, 1>();
    const double before[] = { focalBefore.stableNorm(), rotationBefore.stableNorm() };
    const double after[] = { focalAfter.stableNorm(), rotationAfter.stableNorm() };
    const double largest =
      std::max({ focalBefore.cwiseAbs().maxCoeff(), focalAfter.cwiseAbs().maxCoeff(),
        rotationBefore.cwiseAbs().maxCoeff(), rotationAfter.cwiseAbs().maxCoeff() });
    tangents.frame =
      monotoneTangentOfParts(before, after, 2, kRoundOffPart * largest, hPrevious, hNext);
  }
  const CameraKey::Channels stepBefore = previous.channels - key.channels;
  const CameraKey::Channels stepAfter = next.channels - key.channels;
  for (int g = 0; g < kCameraChannelGroupCount; ++g)
  {
    double largest = 0.0;
    for (int c = 0; c < CameraKey::ChannelCount; ++c)
    {
      if (cameraChannelGroup(c) == g)
      {
        largest = std::max({ largest, std::abs(stepBefore[c]), std::abs(stepAfter[c]) });
      }
    }
    // The group's norms, scaled by its largest step so that window centres near the double
    // range do not overflow; a group that does not move gets Catmull-Rom's weights (its tangent
    // is 0 whatever they are).
    double before2 = 0.0, after2 = 0.0;
    for (int c = 0; c < CameraKey::ChannelCount && largest > 0.0; ++c)
    {
      if (cameraChannelGroup(c) == g)
      {
        before2 += (stepBefore[c] / largest) * (stepBefore[c] / largest);
        after2 += (stepAfter[c] / largest) * (stepAfter[c] / largest);
      }
    }
    const double before = largest * std::sqrt(before2), after = largest * std::sqrt(after2);
    tangents.channels[g] = monotoneTangentOfParts(&before, &after, 1, 0.0, hPrevious, hNext);
  }
  return tangents;
}

} // namespace lct
