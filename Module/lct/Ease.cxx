#include "lct/Ease.h"

#include <algorithm>

namespace lct
{

double easeSegment(double u, double leaving, double arriving)
{
  u = std::clamp(u, 0.0, 1.0);
  if (leaving == 0.0 && arriving == 0.0)
  {
    return u; // exactly: no ease must not move a curve point by rounding
  }
  const double u2 = u * u, u3 = u2 * u;
  const double e =
    (1.0 - leaving) * (u3 - 2.0 * u2 + u) + (3.0 * u2 - 2.0 * u3) + (1.0 - arriving) * (u3 - u2);
  return std::clamp(e, 0.0, 1.0);
}

double inverseEaseSegment(double e, double leaving, double arriving)
{
  e = std::clamp(e, 0.0, 1.0);
  if ((leaving == 0.0 && arriving == 0.0) || e == 0.0 || e == 1.0)
  {
    return e;
  }
  double lo = 0.0, hi = 1.0;
  for (int iteration = 0; iteration < 64 && lo < hi; ++iteration)
  {
    const double middle = 0.5 * (lo + hi);
    if (middle <= lo || middle >= hi)
    {
      break;
    }
    (easeSegment(middle, leaving, arriving) < e ? lo : hi) = middle;
  }
  return 0.5 * (lo + hi);
}

} // namespace lct
