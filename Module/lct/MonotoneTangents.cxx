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
  // The speed of each part before and after the key, made unit-free by the part's own scale
  // (its share of the two). A step at round-off level counts as still: unit-free, the 1e-16 a
  // MatrixLog leaves in the translation of a pure turn, or a 1e-15 translation, would weigh as
  // much as the turn, and over a time step of 1e-300 as a huge speed. (A path of translations
  // alone keeps them at any size.)
  double before2 = 0.0, after2 = 0.0;
  for (int g = 0; g < partCount; ++g)
  {
    if (!(std::isfinite(partBefore[g]) && std::isfinite(partAfter[g])))
    {
      return catmullRom;
    }
    const double stepBefore = partBefore[g] > roundOff ? partBefore[g] : 0.0;
    const double stepAfter = partAfter[g] > roundOff ? partAfter[g] : 0.0;
    if (stepBefore == 0.0 && stepAfter == 0.0)
    {
      continue;
    }
    const double before = stepBefore / hPrevious;
    const double after = stepAfter / hNext;
    const double scale = before + after;
    if (std::isfinite(scale) && scale > 0.0)
    {
      before2 += (before / scale) * (before / scale);
      after2 += (after / scale) * (after / scale);
    }
    else
    {
      // A speed overflows or both underflow (time steps near the double range): the share of
      // the speed before, 1 / (1 + after / before), from logs.
      const double share = stepBefore == 0.0 ? 0.0
        : stepAfter == 0.0                   ? 1.0
                                             : 1.0 /
          (1.0 +
            std::exp((std::log(stepAfter) - std::log(hNext)) -
              (std::log(stepBefore) - std::log(hPrevious))));
      before2 += share * share;
      after2 += (1.0 - share) * (1.0 - share);
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

namespace
{
/// The size of a step's linear part, |w| beside the Frobenius norm of its stretch (the
/// off-diagonal entries stand for two each): both unchanged when the scene turns, so the tangents
/// are too (with each off-diagonal counted once, turning every key by 45 degrees moved the curve
/// by 0.7 %).
Eigen::Matrix<double, 9, 1> linearPart(const LogCoords& step)
{
  Eigen::Matrix<double, 9, 1> parts;
  parts << rotationPart(step), symmetricPart(step).head<3>(),
    std::sqrt(2.0) * symmetricPart(step).tail<3>();
  return parts;
}

double linearPartNorm(const LogCoords& step)
{
  return linearPart(step).stableNorm();
}

/// impactWeight for one part of the four steps (vectors of one unit).
template <typename Vector>
double partImpactWeight(const Vector& outerPrevious, const Vector& previous, const Vector& next,
  const Vector& outerNext, const double* times, double roundOff)
{
  const double before = previous.stableNorm(), after = next.stableNorm();
  if (!(before > roundOff && after > roundOff))
  {
    return 0.0; // still on a side (or not finite): not a turn
  }
  // Both steps go from key k to its neighbours: the motion turns straight back where they agree.
  const double turn = (previous / before).dot(next / after);
  if (!(turn > 0.0))
  {
    return 0.0;
  }
  // min(inner speeds) / max(outer speeds), each ratio of speeds as a ratio of norms times a
  // ratio of time steps, so that no speed overflows or underflows (a still outer step: Inf).
  const double outerBefore = outerPrevious.stableNorm(), outerAfter = outerNext.stableNorm();
  const double hOuterBefore = times[1] - times[0], hBefore = times[2] - times[1],
               hAfter = times[3] - times[2], hOuterAfter = times[4] - times[3];
  const double innerOverOuter[] = { before / outerBefore * (hOuterBefore / hBefore),
    before / outerAfter * (hOuterAfter / hBefore), after / outerBefore * (hOuterBefore / hAfter),
    after / outerAfter * (hOuterAfter / hAfter) };
  double ratio = HUGE_VAL;
  for (const double r : innerOverOuter)
  {
    if (!(r >= 0.0))
    {
      return 0.0; // NaN: a still outer step (Inf) times a time ratio that underflowed
    }
    ratio = std::min(ratio, r);
  }
  const double ramp = std::clamp((ratio - kImpactOnset) / (kImpactFull - kImpactOnset), 0.0, 1.0);
  const double turn2 = std::min(turn, 1.0) * std::min(turn, 1.0);
  return turn2 * turn2 * ramp;
}
} // namespace

double impactWeight(const LogCoords& outerPrevious, const LogCoords& previous,
  const LogCoords& next, const LogCoords& outerNext, const double times[5])
{
  for (int i = 0; i < 4; ++i)
  {
    if (!(times[i + 1] > times[i] && std::isfinite(times[i + 1] - times[i])))
    {
      return 0.0;
    }
  }
  if (!(outerPrevious.allFinite() && previous.allFinite() && next.allFinite() &&
        outerNext.allFinite()))
  {
    return 0.0;
  }
  const double roundOff = kRoundOffPart *
    std::max({ outerPrevious.cwiseAbs().maxCoeff(), previous.cwiseAbs().maxCoeff(),
      next.cwiseAbs().maxCoeff(), outerNext.cwiseAbs().maxCoeff() });
  const double translation =
    partImpactWeight(Eigen::Vector3d(outerPrevious.head<3>()), Eigen::Vector3d(previous.head<3>()),
      Eigen::Vector3d(next.head<3>()), Eigen::Vector3d(outerNext.head<3>()), times, roundOff);
  const double linear = partImpactWeight(linearPart(outerPrevious), linearPart(previous),
    linearPart(next), linearPart(outerNext), times, roundOff);
  return std::max(translation, linear);
}

KeyTangent monotoneTangent(
  const LogCoords& previous, const LogCoords& next, double hPrevious, double hNext)
{
  // The parts are the translation (a length) and the linear part, rotation and stretch together
  // (both logs, without units: a 1e-6 stretch beside a turn of a radian is negligible, as it is
  // to the eye); stableNorm, so that steps near the double range do not overflow (a non-finite
  // step gives a non-finite norm, hence Catmull-Rom's tangent).
  const double before[] = { previous.head<3>().stableNorm(), linearPartNorm(previous) };
  const double after[] = { next.head<3>().stableNorm(), linearPartNorm(next) };
  const double roundOff =
    kRoundOffPart * std::max(previous.cwiseAbs().maxCoeff(), next.cwiseAbs().maxCoeff());
  return monotoneTangentOfParts(before, after, 2, roundOff, hPrevious, hNext);
}

CameraPart cameraChannelPart(int channel)
{
  using C = CameraKey;
  switch (channel)
  {
    case C::LogDistance:
      return CameraDistance;
    case C::LogTanHalfAngle:
      return CameraViewAngle;
    case C::LogParallelScale:
      return CameraParallelScale;
    case C::WindowCenterX:
    case C::WindowCenterY:
      return CameraWindowCenter;
    case C::ShearX:
    case C::ShearY:
    case C::ShearCenter:
      return CameraViewShear;
    default:
      return CameraClippingRange; // LogNear, LogFar
  }
}

CameraTangents monotoneCameraTangents(const CameraKey& previous, const CameraKey& key,
  const CameraKey& next, const Eigen::Vector3d& rotationBefore,
  const Eigen::Vector3d& rotationAfter, double hPrevious, double hNext)
{
  CameraTangents tangents;
  const auto single = [&](double before, double after, double roundOff) {
    return monotoneTangentOfParts(&before, &after, 1, roundOff, hPrevious, hNext);
  };
  // Rotation logs carry ~1e-16 rad of round-off where two keys share their orientation.
  tangents.part[CameraOrientation] =
    single(rotationBefore.stableNorm(), rotationAfter.stableNorm(), kRoundOffPart);
  {
    // In units of the key's distance, with the round-off of the coordinates.
    const Eigen::Vector3d focal = key.focalFrame.topRightCorner<3, 1>();
    const Eigen::Vector3d focalPrevious = previous.focalFrame.topRightCorner<3, 1>();
    const Eigen::Vector3d focalNext = next.focalFrame.topRightCorner<3, 1>();
    const double distance = std::exp(key.channels[CameraKey::LogDistance]);
    const double coordinates = std::max({ focal.cwiseAbs().maxCoeff(),
      focalPrevious.cwiseAbs().maxCoeff(), focalNext.cwiseAbs().maxCoeff() });
    tangents.part[CameraFocalPoint] = single((focalPrevious - focal).stableNorm() / distance,
      (focalNext - focal).stableNorm() / distance, kRoundOffPart * coordinates / distance);
  }
  // Quarter steps: the weights depend on the ratio of the two sides only, and quarters of finite
  // channels never overflow when subtracted, nor their groups' norms (window centres of 1e308
  // either way gave infinite steps, and Catmull-Rom's tangent in place of the monotone one).
  const CameraKey::Channels stepBefore = 0.25 * previous.channels - 0.25 * key.channels;
  const CameraKey::Channels stepAfter = 0.25 * next.channels - 0.25 * key.channels;
  for (int part = CameraDistance; part < CameraPartCount; ++part)
  {
    // The group's steps (at most 3 channels); stableNorm, so that window centres near the double
    // range do not overflow. A group that does not move gets Catmull-Rom's weights (its tangent
    // is 0 whatever they are).
    Eigen::Vector3d before = Eigen::Vector3d::Zero(), after = Eigen::Vector3d::Zero();
    int size = 0;
    for (int c = 0; c < CameraKey::ChannelCount; ++c)
    {
      if (cameraChannelPart(c) == part)
      {
        before[size] = stepBefore[c];
        after[size] = stepAfter[c];
        ++size;
      }
    }
    tangents.part[part] = single(before.stableNorm(), after.stableNorm(), 0.0);
  }
  return tangents;
}

} // namespace lct
