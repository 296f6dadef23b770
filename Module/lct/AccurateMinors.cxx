#include "lct/AccurateMinors.h"

#include <cmath>

namespace lct
{

namespace
{

/// a + b = s + e exactly (Knuth's TwoSum).
inline void twoSum(double a, double b, double& s, double& e) noexcept
{
  s = a + b;
  const double z = s - a;
  e = (a - (s - z)) + (b - z);
}

/// The exact parts of a determinant, summed in K-fold working precision (Ogita, Rump & Oishi
/// 2005, Algorithm 4.8 SumK, K = 3): the relative error is eps + (24 eps)^3 cond, and the
/// cancellation cond = sum |terms| / |det| reaches 1e18 for a 3x3 of condition 1e12 and more,
/// beyond what the twice-the-precision Sum2 keeps (its bound there is 3e-11).
class CompensatedSum
{
public:
  void add(double x) noexcept { this->Terms[this->Count++] = x; }
  double value() noexcept
  {
    for (int pass = 0; pass < 2; ++pass)
    {
      // VecSum: the cascade of TwoSums leaves the sum in the last term and the exact errors in
      // the others, so the vector still sums exactly to the same value.
      for (int i = 1; i < this->Count; ++i)
      {
        double e;
        twoSum(this->Terms[i], this->Terms[i - 1], this->Terms[i], e);
        this->Terms[i - 1] = e;
      }
    }
    double errors = 0.0;
    for (int i = 0; i + 1 < this->Count; ++i)
    {
      errors += this->Terms[i];
    }
    return this->Terms[this->Count - 1] + errors;
  }

private:
  double Terms[24];
  int Count = 0;
};

/// Adds s a b c exactly split into four doubles: b c = p + q, then a p and a q are each split.
inline void addTripleProduct(CompensatedSum& sum, double s, double a, double b, double c) noexcept
{
  const double p = b * c;
  const double q = std::fma(b, c, -p);
  const double ap = a * p;
  const double aq = a * q;
  sum.add(s * ap);
  sum.add(s * std::fma(a, p, -ap));
  sum.add(s * aq);
  sum.add(s * std::fma(a, q, -aq));
}

} // namespace

double accurateDeterminant2(double a, double b, double c, double d) noexcept
{
  const double w = b * c;
  const double e = std::fma(-b, c, w); // w - bc exactly
  const double f = std::fma(a, d, -w); // ad - w, rounded once
  return f + e;
}

Eigen::Matrix3d accurateCofactors(const Eigen::Matrix3d& m) noexcept
{
  Eigen::Matrix3d c;
  c(0, 0) = accurateDeterminant2(m(1, 1), m(1, 2), m(2, 1), m(2, 2));
  c(0, 1) = -accurateDeterminant2(m(1, 0), m(1, 2), m(2, 0), m(2, 2));
  c(0, 2) = accurateDeterminant2(m(1, 0), m(1, 1), m(2, 0), m(2, 1));
  c(1, 0) = -accurateDeterminant2(m(0, 1), m(0, 2), m(2, 1), m(2, 2));
  c(1, 1) = accurateDeterminant2(m(0, 0), m(0, 2), m(2, 0), m(2, 2));
  c(1, 2) = -accurateDeterminant2(m(0, 0), m(0, 1), m(2, 0), m(2, 1));
  c(2, 0) = accurateDeterminant2(m(0, 1), m(0, 2), m(1, 1), m(1, 2));
  c(2, 1) = -accurateDeterminant2(m(0, 0), m(0, 2), m(1, 0), m(1, 2));
  c(2, 2) = accurateDeterminant2(m(0, 0), m(0, 1), m(1, 0), m(1, 1));
  return c;
}

double accurateDeterminant(const Eigen::Matrix3d& m) noexcept
{
  // Leibniz: the six permutations of the columns with their signs.
  CompensatedSum sum;
  addTripleProduct(sum, 1.0, m(0, 0), m(1, 1), m(2, 2));
  addTripleProduct(sum, -1.0, m(0, 0), m(1, 2), m(2, 1));
  addTripleProduct(sum, -1.0, m(0, 1), m(1, 0), m(2, 2));
  addTripleProduct(sum, 1.0, m(0, 1), m(1, 2), m(2, 0));
  addTripleProduct(sum, 1.0, m(0, 2), m(1, 0), m(2, 1));
  addTripleProduct(sum, -1.0, m(0, 2), m(1, 1), m(2, 0));
  return sum.value();
}

double unitScaleDeterminant(const Eigen::Matrix3d& a) noexcept
{
  const double det = a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) -
    a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
    a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  return std::abs(det) < 1e-6 ? accurateDeterminant(a) : det;
}

} // namespace lct
