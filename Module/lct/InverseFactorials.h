/**
 * @file InverseFactorials.h
 * @brief 1/n! at compile time, the coefficients of truncated exponential series (lct/Sym3.h,
 *        lct/AffineExp.h).
 */
#ifndef lct_InverseFactorials_h
#define lct_InverseFactorials_h

#include <array>

namespace lct
{

/// 1/n! for n = 0 .. Count - 1, each the previous one divided by n (exact for n <= 2, within an
/// ulp per step after).
template <int Count>
constexpr std::array<double, Count> inverseFactorials()
{
  std::array<double, Count> f{};
  f[0] = 1.0;
  for (int n = 1; n < Count; ++n)
  {
    f[n] = f[n - 1] / n;
  }
  return f;
}

} // namespace lct

#endif
