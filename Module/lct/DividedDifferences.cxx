#include "lct/DividedDifferences.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{

namespace
{

using Complex = std::complex<double>;

inline double realPart(double x)
{
  return x;
}
inline double realPart(const Complex& z)
{
  return z.real();
}

inline double magnitude(double x)
{
  return std::abs(x);
}
// |z| without the overflow guards of std::abs: our nodes are far from overflow.
inline double magnitude(const Complex& z)
{
  return std::sqrt(z.real() * z.real() + z.imag() * z.imag());
}

/// Whether the nodes of a subset, of diameter `diameter` about `centre`, are close enough for
/// the Taylor series: within radius 1 for exp (terms fall like 1/k!), within a quarter of
/// |centre| for log and sqrt (terms fall like 4^-k). Log and sqrt also need the centre in the
/// right half plane, or the disc could straddle the branch cut.
template <typename Scalar>
bool useSeries(ScalarFunction f, const Scalar& centre, double diameter)
{
  if (f == ScalarFunction::Exp)
  {
    return diameter <= 1.0;
  }
  return realPart(centre) > 0.0 && diameter <= 0.25 * magnitude(centre);
}

/// Products without the NaN/Inf recovery of the C99 complex multiply (__muldc3): the nodes
/// here are finite by construction, and this is the inner loop of the series.
inline double multiply(double a, double b)
{
  return a * b;
}
inline Complex multiply(const Complex& a, const Complex& b)
{
  return Complex(
    a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real());
}

/// f[nodes in mask] from the Taylor series of f about the centroid c of those nodes:
/// sum_{k >= order} a_k h_{k - order}(x - c), a_k = f^(k)(c) / k!. The complete homogeneous
/// polynomials h_j are built one degree at a time (h_j(x_1..x_v) = h_j(x_1..x_{v-1}) +
/// x_v h_{j-1}(x_1..x_v)), so the work stops as soon as the terms fall below round-off.
template <typename Scalar>
Scalar seriesDividedDifference(
  ScalarFunction f, const Scalar* nodes, int count, unsigned mask, int order)
{
  constexpr int kMaxDegree = 80;
  Scalar w[4];
  int m = 0;
  Scalar centre(0.0);
  for (int i = 0; i < count; ++i)
  {
    if (mask & (1u << i))
    {
      w[m++] = nodes[i];
      centre += nodes[i];
    }
  }
  centre /= static_cast<double>(m);
  for (int v = 0; v < m; ++v)
  {
    w[v] -= centre;
  }

  // Log and sqrt: with u = w / c, a_k h_j(w) = b_k c^(-order) h_j(u) (log: a_k = (-1)^(k+1) c^-k /
  // k) or b_k c^(1/2 - order) h_j(u) (sqrt: a_k = binom(1/2, k) c^(1/2 - k)), since h_j is
  // homogeneous of degree j = k - order. The powers of 1/c are never formed, so a cluster of
  // nodes far from 1 (a stretch of 1e-60) does not overflow them.
  const bool scaled = f != ScalarFunction::Exp;
  Scalar scale(1.0);
  if (scaled)
  {
    const Scalar inverseCentre = Scalar(1.0) / centre;
    for (int v = 0; v < m; ++v)
    {
      w[v] = multiply(w[v], inverseCentre);
    }
    for (int k = 0; k < order; ++k)
    {
      scale = multiply(scale, inverseCentre);
    }
    if (f == ScalarFunction::Sqrt)
    {
      scale = multiply(scale, std::sqrt(centre));
    }
  }
  // b_k by recurrence in k: exp e^c / k!, log (-1)^(k+1) / k (b_0 = log c, with scale 1), sqrt
  // binom(1/2, k).
  Scalar a = f == ScalarFunction::Exp
    ? evaluate(f, centre)
    : (f == ScalarFunction::Log ? evaluate(f, centre) : Scalar(1.0));
  auto advance = [&](int k) {
    switch (f)
    {
      case ScalarFunction::Exp:
        a /= static_cast<double>(k);
        break;
      case ScalarFunction::Log:
        a = Scalar(((k % 2) ? 1.0 : -1.0) / static_cast<double>(k));
        break;
      case ScalarFunction::Sqrt:
        a *= (1.5 - k) / static_cast<double>(k);
        break;
    }
  };
  for (int k = 1; k <= order; ++k)
  {
    advance(k);
  }
  // The largest |u| (or |w|): |h_j| <= C(j + m - 1, m - 1) r^j bounds every later term, so the
  // sum stops on a bound, not on a term that happens to vanish (h_1 = 0 about the centroid, and
  // h_2 = 0 for nodes symmetric about it: an equilateral triangle stopped the series before its
  // leading term).
  double r = 0.0;
  for (int v = 0; v < m; ++v)
  {
    r = std::max(r, magnitude(w[v]));
  }

  // hv[v] = h_j(w_0 .. w_v) for the current degree j.
  Scalar hv[4];
  for (int v = 0; v < m; ++v)
  {
    hv[v] = Scalar(1.0);
  }
  Scalar sum = a; // j = 0: h_0 = 1
  double rPower = 1.0;
  int negligible = 0;
  for (int j = 1; j <= kMaxDegree; ++j)
  {
    Scalar previous(0.0); // h_j of the first v variables, v = 0
    for (int v = 0; v < m; ++v)
    {
      hv[v] = previous + multiply(w[v], hv[v]);
      previous = hv[v];
    }
    advance(order + j);
    sum += multiply(a, hv[m - 1]);
    rPower *= r;
    double count = 1.0; // C(j + m - 1, m - 1)
    for (int i = 1; i < m; ++i)
    {
      count = count * (j + i) / i;
    }
    const double bound = magnitude(a) * count * rPower;
    // Stop after two consecutive bounds below round-off of the sum.
    if (bound <= 0.25 * std::numeric_limits<double>::epsilon() * magnitude(sum))
    {
      if (++negligible == 2)
      {
        break;
      }
    }
    else
    {
      negligible = 0;
    }
  }
  return scaled ? multiply(sum, scale) : sum;
}

template <typename Scalar>
DividedDifferenceTable<Scalar> computeTable(ScalarFunction f, const Scalar* nodes, int count)
{
  DividedDifferenceTable<Scalar> out;
  const unsigned full = (1u << count) - 1u;
  // Removing bits from a mask makes it smaller, so in increasing mask order every proper
  // subset is ready before the subsets that contain it.
  for (unsigned mask = 1; mask <= full; ++mask)
  {
    int m = 0;
    int first = -1;
    for (int i = 0; i < count; ++i)
    {
      if (mask & (1u << i))
      {
        if (first < 0)
        {
          first = i;
        }
        ++m;
      }
    }
    if (m == 1)
    {
      out.table[mask] = evaluate(f, nodes[first]);
      continue;
    }
    // The two farthest nodes of the subset.
    int ia = -1;
    int ib = -1;
    double diameter = -1.0;
    Scalar centre(0.0);
    for (int i = 0; i < count; ++i)
    {
      if (!(mask & (1u << i)))
      {
        continue;
      }
      centre += nodes[i];
      for (int j = i + 1; j < count; ++j)
      {
        if (mask & (1u << j))
        {
          const double d = magnitude(nodes[i] - nodes[j]);
          if (d > diameter)
          {
            diameter = d;
            ia = i;
            ib = j;
          }
        }
      }
    }
    centre /= static_cast<double>(m);
    if (useSeries(f, centre, diameter))
    {
      out.table[mask] = seriesDividedDifference(f, nodes, count, mask, m - 1);
    }
    else
    {
      // f[S] = (f[S \ a] - f[S \ b]) / (b - a), |b - a| = diameter, never small here.
      const unsigned withoutA = mask & ~(1u << ia);
      const unsigned withoutB = mask & ~(1u << ib);
      out.table[mask] = (out.table[withoutA] - out.table[withoutB]) / (nodes[ib] - nodes[ia]);
    }
  }
  return out;
}

/// f[a, b] from f(a) = fa and f(b) = fb without cancellation.
double pairDifference(ScalarFunction f, double a, double fa, double b, double fb)
{
  const double d = a - b;
  switch (f)
  {
    case ScalarFunction::Exp:
      return d == 0.0 ? fb : fb * (std::expm1(d) / d);
    case ScalarFunction::Log:
      if (d == 0.0)
      {
        return 1.0 / b;
      }
      // Beyond a ratio of 1.5 the logs differ by > 0.4 and their difference is accurate.
      return std::abs(d) <= 0.5 * b ? std::log1p(d / b) / d : (fa - fb) / d;
    case ScalarFunction::Sqrt:
      return 1.0 / (fa + fb);
  }
  return 0.0;
}

} // namespace

NewtonCoefficients3 newtonCoefficients(ScalarFunction f, double x0, double x1, double x2)
{
  NewtonCoefficients3 out;
  if (f == ScalarFunction::Exp)
  {
    // e^x1 = e^x0 (1 + expm1(x1 - x0)): the expm1 values serve both f(x1) and f[x0, x1].
    const double e0 = std::exp(x0);
    const double d1 = x1 - x0;
    const double d2 = x2 - x0;
    const double m1 = std::expm1(d1);
    const double m2 = std::expm1(d2);
    out.c0 = e0;
    out.c1 = d1 == 0.0 ? e0 : e0 * (m1 / d1);
    const double c02 = d2 == 0.0 ? e0 : e0 * (m2 / d2);
    if (std::max(x0, std::max(x1, x2)) - std::min(x0, std::min(x1, x2)) <= 0.25)
    {
      const double nodes[3] = { x0, x1, x2 };
      out.c2 = seriesDividedDifference(f, nodes, 3, 0b111u, 2);
    }
    else
    {
      // f[x0,x1,x2] = (f[x0,x1] - f[x0,x2]) / (x1 - x2), and x1, x2 are the extreme nodes
      // here or the difference is at least a third of the spread.
      out.c2 = (out.c1 - c02) / (x1 - x2);
      if (std::abs(x1 - x2) < std::max(std::abs(d1), std::abs(d2)))
      {
        const double e1 = e0 + e0 * m1;
        const double e2 = e0 + e0 * m2;
        out.c2 = std::abs(d1) >= std::abs(d2) ? (pairDifference(f, x1, e1, x2, e2) - c02) / d1
                                              : (pairDifference(f, x1, e1, x2, e2) - out.c1) / d2;
      }
    }
    return out;
  }
  const double f0 = evaluate(f, x0);
  const double f1 = evaluate(f, x1);
  const double f2 = evaluate(f, x2);
  out.c0 = f0;
  out.c1 = pairDifference(f, x0, f0, x1, f1);
  if (f == ScalarFunction::Sqrt)
  {
    // -1 / ((sqrt a + sqrt b)(sqrt b + sqrt c)(sqrt a + sqrt c)): exact, no cancellation.
    out.c2 = -1.0 / ((f0 + f1) * (f1 + f2) * (f0 + f2));
    return out;
  }
  // (f[x0,x1] - f[x0,x2]) / (x1 - x2), unless the nodes cluster and the difference cancels.
  const double lo = std::min({ x0, x1, x2 });
  const double hi = std::max({ x0, x1, x2 });
  const double centre = (x0 + x1 + x2) / 3.0;
  const bool clustered =
    f == ScalarFunction::Exp ? hi - lo <= 0.25 : hi - lo <= 0.25 * std::abs(centre);
  if (clustered)
  {
    const double nodes[3] = { x0, x1, x2 };
    out.c2 = seriesDividedDifference(f, nodes, 3, 0b111u, 2);
    return out;
  }
  // Divide by the largest difference: split at the two extreme nodes.
  if (std::abs(x1 - x2) >= std::abs(x0 - x2) && std::abs(x1 - x2) >= std::abs(x0 - x1))
  {
    out.c2 = (out.c1 - pairDifference(f, x0, f0, x2, f2)) / (x1 - x2);
  }
  else if (std::abs(x0 - x2) >= std::abs(x0 - x1))
  {
    out.c2 = (pairDifference(f, x1, f1, x2, f2) - out.c1) / (x2 - x0);
  }
  else
  {
    out.c2 = (pairDifference(f, x1, f1, x2, f2) - pairDifference(f, x0, f0, x2, f2)) / (x1 - x0);
  }
  return out;
}

DividedDifferenceTable<double> dividedDifferences(ScalarFunction f, const double* nodes, int count)
{
  return computeTable(f, nodes, count);
}

DividedDifferenceTable<Complex> dividedDifferences(
  ScalarFunction f, const Complex* nodes, int count)
{
  return computeTable(f, nodes, count);
}

} // namespace lct
