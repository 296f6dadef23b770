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

} // namespace lct
