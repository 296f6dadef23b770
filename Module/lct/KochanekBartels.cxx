#include "lct/KochanekBartels.h"

#include <cmath>
#include <initializer_list>

namespace lct
{

bool isValid(const TensionContinuityBias& tcb)
{
  for (const double v : { tcb.tension, tcb.continuity, tcb.bias })
  {
    if (!(v >= -1.0 && v <= 1.0)) // false for NaN
    {
      return false;
    }
  }
  return true;
}

KeyTangents kochanekBartelsTangents(
  const double* times, int keyCount, int k, const TensionContinuityBias& tcb)
{
  const double slack = 1.0 - tcb.tension;
  if (k <= 0 || k >= keyCount - 1)
  {
    // One secant: (1 - T) times it, on the side that exists.
    const KeyTangent oneSided = k <= 0 ? KeyTangent{ 0.0, slack } : KeyTangent{ slack, 0.0 };
    return { oneSided, oneSided };
  }
  const double c = tcb.continuity, b = tcb.bias;
  const double before = times[k] - times[k - 1], after = times[k + 1] - times[k];
  // Eq. 9 per unit time: 2 (a D- + b D+) / (h- + h+), with D- = h- (secant before), etc.
  const double toBefore = before / (before + after), toAfter = after / (before + after);
  const auto tangent = [&](double a, double bb) {
    return KeyTangent{ slack * a * toBefore, slack * bb * toAfter };
  };
  return { tangent((1.0 - c) * (1.0 + b), (1.0 + c) * (1.0 - b)),
    tangent((1.0 + c) * (1.0 + b), (1.0 - c) * (1.0 - b)) };
}

} // namespace lct
