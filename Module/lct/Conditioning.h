/**
 * @file Conditioning.h
 * @brief The conditioning limits of the core, and the exact power-of-two scaling that keeps
 *        well-conditioned input of any magnitude away from overflow and underflow.
 *
 * A 3x3 linear part is accepted when sigma_max / sigma_min <= kMaxConditionNumber. The limit is
 * a property of double precision, not of the algorithms: rounding the entries of any matrix moves
 * its smallest singular value by up to eps sigma_max (Weyl), so beyond 1e13 the smallest stretch
 * of a general (rotated) matrix has fewer than 3 correct digits in its own input. The core itself
 * computes singular values to relative accuracy (lct/SVD3.h) up to that limit.
 *
 * Magnitude is handled separately from conditioning: a linear part 2^e A with A of unit size
 * has log(2^e A) = log(A) + e log 2 I (the scalar factor commutes), and multiplying by a power of
 * two is exact, so 1e300 I and 1e-300 I are as accurate as I.
 */
#ifndef lct_Conditioning_h
#define lct_Conditioning_h

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <cstring>

namespace lct
{

/// The largest accepted sigma_max / sigma_min of a linear part (see above).
constexpr double kMaxConditionNumber = 1e13;

/// The largest rotation angle (radians) of a log accepted by either parametrisation, as a
/// reference or (MatrixLog) as an eigenvalue's imaginary part: beyond it a wound angle keeps
/// fewer than 7 digits below a turn (ulp(1e9) ~ 1e-7), and the exp of a general 3x3 log with
/// eigenvalues +-i theta is only accurate to ~eps theta.
constexpr double kMaxRotationWinding = 1e9;

/// Below this condition number the closed forms in the original basis (Kaji & Ochiai App. B) are
/// accurate to ~1e-14; above it the eigen/singular-vector branches take over (measured: the
/// Newton form of log loses eps cond^2, 2.7e-13 at cond 100, 2.5e-11 at 1e3).
constexpr double kClosedFormConditionLimit = 32.0;

/// 2^e for -1022 <= e <= 1023, where it is a normal double, built from its bits. Multiplying
/// by it rounds once, exactly as std::ldexp(x, e) does, at a fraction of ldexp's cost (which
/// was two thirds of symmetricEigenvalues' instructions).
inline double powerOfTwo(int e)
{
  const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
  double value;
  std::memcpy(&value, &bits, sizeof value);
  return value;
}

/// x 2^e, rounded once: std::ldexp(x, e).
inline double timesPowerOfTwo(double x, int e)
{
  return e >= -1022 && e <= 1023 ? x * powerOfTwo(e) : std::ldexp(x, e);
}

/// e such that |x| 2^-e lies in [0.5, 1) (std::frexp's exponent); 0 for 0, Inf or NaN.
inline int binaryExponent(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int field = static_cast<int>((bits >> 52) & 0x7ff);
  if (field == 0 || field == 0x7ff)
  {
    // Subnormal (frexp normalises it), zero, Inf or NaN.
    int e = 0;
    if (x != 0.0 && std::isfinite(x))
    {
      std::frexp(x, &e);
    }
    return e;
  }
  return field - 1022;
}

/// e such that the largest |entry| of m 2^-e lies in [0.5, 1); 0 for a zero or non-finite m.
template <typename Derived>
int unitScaleExponent(const Eigen::MatrixBase<Derived>& m)
{
  const double largest = m.cwiseAbs().maxCoeff();
  if (!(largest > 0.0) || !std::isfinite(largest))
  {
    return 0;
  }
  return binaryExponent(largest);
}

/// m 2^e, exact unless entries leave the normal range.
template <typename Derived>
typename Derived::PlainObject scaledByPowerOfTwo(const Eigen::MatrixBase<Derived>& m, int e)
{
  // One multiplication by an exact power of two where 2^e itself is a normal double.
  if (e >= -1022 && e <= 1023)
  {
    return m * powerOfTwo(e);
  }
  return m.unaryExpr([e](double x) { return std::ldexp(x, e); });
}

} // namespace lct

#endif
