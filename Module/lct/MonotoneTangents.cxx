#include "lct/MonotoneTangents.h"

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
  // The speed of each part (translation, rotation, stretch) before and after the key, made
  // unit-free by the part's own scale (stableNorm: steps near the double range do not overflow).
  constexpr int kStart[] = { 0, 3, 6 };
  constexpr int kSize[] = { 3, 3, 6 };
  double before2 = 0.0, after2 = 0.0;
  for (int g = 0; g < 3; ++g)
  {
    const double before = previous.segment(kStart[g], kSize[g]).stableNorm() / hPrevious;
    const double after = next.segment(kStart[g], kSize[g]).stableNorm() / hNext;
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
