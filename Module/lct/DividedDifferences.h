/**
 * @file DividedDifferences.h
 * @brief Accurate divided differences of exp, log and sqrt at up to four (complex) nodes.
 *
 * Every matrix function of the core is a Hermite interpolation polynomial in Newton form,
 * f(A) = f[z0] I + f[z0,z1] (A - z0) + f[z0,z1,z2] (A - z0)(A - z1)
 * (Kaji & Ochiai App. B; Higham, "Functions of Matrices", §1.2), evaluated at the eigenvalues
 * from the cubic formula. Its accuracy is the accuracy of the divided differences. The
 * textbook recursion `(f[..] - f[..]) / (zk - z0)` cancels when nodes nearly coincide (it
 * loses about six digits in Kaji & Ochiai's eq. 7), so a subset whose nodes lie within a
 * small disc is summed instead from the Taylor series of f about the disc's centre:
 *
 *   f[x0..xm] = sum_{k >= m} f^(k)(c) / k! * h_{k-m}(x0 - c, ..., xm - c),
 *
 * with h_j the complete homogeneous symmetric polynomials. A subset that is spread out is
 * split at its two farthest nodes, so every division is by a large difference. Coincident
 * nodes are therefore handled exactly (confluent divided differences are derivatives).
 */
#ifndef lct_DividedDifferences_h
#define lct_DividedDifferences_h

#include "vtkLCTModule.h"

#include <cmath>
#include <complex>

namespace lct
{

/// The scalar functions whose matrix versions the core needs.
enum class ScalarFunction
{
  Exp,
  Log, ///< principal branch; nodes must not lie on the closed negative real axis
  Sqrt ///< principal branch; same domain as Log
};

/// f(z) on its principal branch.
template <typename Scalar>
Scalar evaluate(ScalarFunction f, const Scalar& z)
{
  switch (f)
  {
    case ScalarFunction::Exp:
      return std::exp(z);
    case ScalarFunction::Log:
      return std::log(z);
    case ScalarFunction::Sqrt:
      return std::sqrt(z);
  }
  return z;
}

/// All divided differences of f over the subsets of `count` (<= 4) nodes.
/// `table[mask]` is f[ nodes whose bit is set in mask ], for mask in 1 .. 2^count - 1.
template <typename Scalar>
struct DividedDifferenceTable
{
  Scalar table[16];
  const Scalar& operator[](unsigned mask) const { return table[mask]; }
};

/// Fills the table of divided differences of `f` at `nodes[0..count)`, count in 1..4.
VTKLCT_EXPORT DividedDifferenceTable<double> dividedDifferences(
  ScalarFunction f, const double* nodes, int count);
VTKLCT_EXPORT DividedDifferenceTable<std::complex<double>> dividedDifferences(
  ScalarFunction f, const std::complex<double>* nodes, int count);

/// The Newton coefficients f[x0], f[x0,x1], f[x0,x1,x2] at three real nodes: the fast path of
/// the symmetric functions. Pairs use closed forms without cancellation
/// (e^b expm1(a-b)/(a-b), log1p((a-b)/b)/(a-b), 1/(sqrt a + sqrt b)); the triple uses the
/// Taylor series only when all three nodes cluster. Log and Sqrt need positive nodes.
struct NewtonCoefficients3
{
  double c0; ///< f[x0]
  double c1; ///< f[x0, x1]
  double c2; ///< f[x0, x1, x2]
};
VTKLCT_EXPORT NewtonCoefficients3 newtonCoefficients(
  ScalarFunction f, double x0, double x1, double x2);

} // namespace lct

#endif
