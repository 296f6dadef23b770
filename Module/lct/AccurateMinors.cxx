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

namespace
{
/// The exact adjugate of A: each entry a difference of two products, i.e. four doubles.
struct ExactAdjugate
{
  double parts[3][3][4];

  explicit ExactAdjugate(const Eigen::Matrix3d& m) noexcept
  {
    // adj(A)_ij = cofactor_ji = (-1)^(i+j) minor_ji; with cyclic indices the sign is built in.
    for (int i = 0; i < 3; ++i)
    {
      for (int j = 0; j < 3; ++j)
      {
        const int r0 = (j + 1) % 3, r1 = (j + 2) % 3, c0 = (i + 1) % 3, c1 = (i + 2) % 3;
        const double p = m(r0, c0) * m(r1, c1);
        const double q = m(r0, c1) * m(r1, c0);
        this->parts[i][j][0] = p;
        this->parts[i][j][1] = std::fma(m(r0, c0), m(r1, c1), -p);
        this->parts[i][j][2] = -q;
        this->parts[i][j][3] = -std::fma(m(r0, c1), m(r1, c0), -q);
      }
    }
  }

  /// (adj A x)_i exactly split into 24 doubles and summed accurately.
  template <typename Column>
  double times(int i, const Column& x) const noexcept
  {
    CompensatedSum sum;
    for (int l = 0; l < 3; ++l)
    {
      for (double part : this->parts[i][l])
      {
        const double p = part * x[l];
        sum.add(p);
        sum.add(std::fma(part, x[l], -p));
      }
    }
    return sum.value();
  }
};
} // namespace

Eigen::Matrix3d accurateInverseTimes(const Eigen::Matrix3d& a, const Eigen::Matrix3d& b) noexcept
{
  const ExactAdjugate adjugate(a);
  const double det = accurateDeterminant(a);
  Eigen::Matrix3d out;
  for (int k = 0; k < 3; ++k)
  {
    const Eigen::Vector3d column = b.col(k);
    for (int i = 0; i < 3; ++i)
    {
      out(i, k) = adjugate.times(i, column) / det;
    }
  }
  return out;
}

Eigen::Vector3d accurateInverseTimes(const Eigen::Matrix3d& a, const Eigen::Vector3d& v) noexcept
{
  const ExactAdjugate adjugate(a);
  const double det = accurateDeterminant(a);
  return Eigen::Vector3d(
    adjugate.times(0, v) / det, adjugate.times(1, v) / det, adjugate.times(2, v) / det);
}

Eigen::Matrix4d accurateProduct(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b) noexcept
{
  Eigen::Matrix4d out;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 4; ++j)
    {
      double sum = 0.0, error = 0.0;
      for (int k = 0; k < 4; ++k)
      {
        const double p = a(i, k) * b(k, j);
        const double pe = std::fma(a(i, k), b(k, j), -p);
        double se;
        twoSum(sum, p, sum, se);
        error += pe + se;
      }
      out(i, j) = sum + error;
    }
  }
  return out;
}

double unitScaleDeterminant(const Eigen::Matrix3d& a) noexcept
{
  const double det = a(0, 0) * (a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)) -
    a(0, 1) * (a(1, 0) * a(2, 2) - a(1, 2) * a(2, 0)) +
    a(0, 2) * (a(1, 0) * a(2, 1) - a(1, 1) * a(2, 0));
  return std::abs(det) < 1e-6 ? accurateDeterminant(a) : det;
}

} // namespace lct
