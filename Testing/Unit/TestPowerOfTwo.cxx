// The power-of-two helpers of lct/Conditioning.h against the C library's ldexp and frexp, which
// they replace on the hot paths: every exponent, every kind of double (subnormal, the ends of the
// range, zero, Inf and NaN).
#include "lct/Conditioning.h"

#include "RandomTransforms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace
{
/// Equal as bit patterns (so that -0 differs from 0), or both NaN.
bool sameDouble(double a, double b)
{
  if (std::isnan(a) || std::isnan(b))
  {
    return std::isnan(a) && std::isnan(b);
  }
  return std::memcmp(&a, &b, sizeof a) == 0;
}

std::vector<double> specialValues()
{
  using limits = std::numeric_limits<double>;
  return { 0.0, -0.0, limits::denorm_min(), -limits::denorm_min(), 3.0 * limits::denorm_min(),
    limits::min(), -limits::min(), limits::min() * (1.0 - limits::epsilon()), 0.5, 1.0, -1.0, 0.75,
    1.5, limits::max(), -limits::max(), limits::infinity(), -limits::infinity(),
    limits::quiet_NaN() };
}
/// The special values and `count` random ones of any magnitude, subnormals included.
std::vector<double> valuesOfEveryMagnitude(std::uint64_t seed, int count)
{
  lct_test::RandomTransforms random(seed);
  std::vector<double> values = specialValues();
  for (int i = 0; i < count; ++i)
  {
    values.push_back(
      std::ldexp(random.Uniform(-1.0, 1.0), static_cast<int>(random.Uniform(-1100.0, 1030.0))));
  }
  return values;
}
} // namespace

TEST(PowerOfTwo, IsLdexpOfOne)
{
  for (int e = -1022; e <= 1023; ++e)
  {
    ASSERT_EQ(lct::powerOfTwo(e), std::ldexp(1.0, e)) << e;
  }
}

TEST(PowerOfTwo, TimesPowerOfTwoRoundsLikeLdexp)
{
  for (const double x : valuesOfEveryMagnitude(17, 2000))
  {
    for (int e = -2200; e <= 2200; e += 7)
    {
      ASSERT_TRUE(sameDouble(lct::timesPowerOfTwo(x, e), std::ldexp(x, e))) << x << " " << e;
    }
  }
}

TEST(PowerOfTwo, BinaryExponentIsFrexpsExponent)
{
  for (const double x : valuesOfEveryMagnitude(19, 20000))
  {
    int expected = 0;
    if (std::isfinite(x))
    {
      std::frexp(x, &expected);
    }
    ASSERT_EQ(lct::binaryExponent(x), expected) << x;
  }
}
