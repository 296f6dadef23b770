#include "lct/MonotoneTangents.h"

#include <algorithm>
#include <cmath>

namespace lct
{

KeyTangent monotoneTangent(
  const LogCoords& previous, const LogCoords& next, double hPrevious, double hNext)
{
  const double span = hPrevious + hNext;
  const KeyTangent catmullRom{ hPrevious / span, hNext / span };
  if (!(hPrevious > 0.0 && hNext > 0.0 && std::isfinite(span)) || !previous.allFinite() ||
    !next.allFinite())
  {
    return catmullRom;
  }
  // The speed of each part before and after the key, made unit-free by the part's own scale
  // (stableNorm: steps near the double range do not overflow). The parts are the translation
  // (a length) and the linear part, rotation and stretch together (both logs, without units: a
  // 1e-6 stretch beside a turn of a radian is negligible, as it is to the eye). A part whose steps
  // are at round-off level for the steps (1e-12 of their largest entry) is left out: unit-free,
  // the 1e-16 a MatrixLog leaves in the translation of a pure turn, or a 1e-15 translation, would
  // weigh as much as the turn. (A path of translations alone keeps them at any size.)
  constexpr int kStart[] = { 0, 3 };
  constexpr int kSize[] = { 3, 9 };
  const double roundOff =
    1e-12 * std::max(previous.cwiseAbs().maxCoeff(), next.cwiseAbs().maxCoeff());
  double before2 = 0.0, after2 = 0.0;
  for (int g = 0; g < 2; ++g)
  {
    const double stepBefore = previous.segment(kStart[g], kSize[g]).stableNorm();
    const double stepAfter = next.segment(kStart[g], kSize[g]).stableNorm();
    if (!(std::max(stepBefore, stepAfter) > roundOff))
    {
      continue;
    }
    const double before = stepBefore / hPrevious;
    const double after = stepAfter / hNext;
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
  // Fritsch & Butland: each secant weighted by the other's speed.
  return { after / (before + after), before / (before + after) };
}

} // namespace lct
