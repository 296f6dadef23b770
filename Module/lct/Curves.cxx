#include "lct/Curves.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lct
{

void CurveWeights::add(int k, double w)
{
  for (int i = 0; i < this->count; ++i)
  {
    if (this->key[i] == k)
    {
      this->weight[i] += w;
      return;
    }
  }
  // Capacity is a property of the schemes (support <= 8 keys after folding phantoms).
  this->key[this->count] = k;
  this->weight[this->count] = w;
  ++this->count;
}

namespace
{

/// The segment i with times[i] <= t <= times[i + 1] (t already clamped), and u in [0, 1].
int segmentOf(const double* times, int n, double t, double& u)
{
  const int i = static_cast<int>(std::upper_bound(times, times + n, t) - times) - 1;
  const int segment = std::clamp(i, 0, n - 2);
  u = (t - times[segment]) / (times[segment + 1] - times[segment]);
  // Callers keep the span of the times finite; should it not be, u must still not be NaN.
  u = std::isfinite(u) ? std::clamp(u, 0.0, 1.0) : 0.0;
  return segment;
}

/// Adds weight w on the virtual key index k (any integer): indices outside [0, n) are phantom
/// keys defined by repeated linear reflection p[-j] = 2 p[-j+1] - p[-j+2] (that is, linear
/// extrapolation of the first two keys), folded onto real keys.
void addVirtual(CurveWeights& out, int k, double w, int n)
{
  if (k >= 0 && k < n)
  {
    out.add(k, w);
    return;
  }
  if (n == 1)
  {
    out.add(0, w);
    return;
  }
  // Linear extrapolation: p[k] = p[0] + k (p[1] - p[0]) for k < 0, and likewise at the end.
  if (k < 0)
  {
    out.add(0, w * (1.0 - k));
    out.add(1, w * k);
  }
  else
  {
    const int j = k - (n - 1);
    out.add(n - 1, w * (1.0 + j));
    out.add(n - 2, -w * j);
  }
}

/// The Deslauriers-Dubuc 4-point fundamental function on [-3, 3], sampled at 2^-kLevels.
constexpr int kLevels = 10;
constexpr int kPerUnit = 1 << kLevels;

const std::vector<double>& fundamentalFunction()
{
  static const std::vector<double> table = [] {
    // Subdivide the unit impulse: new odd samples (-1, 9, 9, -1)/16 of their neighbours.
    std::vector<double> values = { 0, 0, 0, 1, 0, 0, 0 }; // integer samples on [-3, 3]
    for (int level = 0; level < kLevels; ++level)
    {
      std::vector<double> next(2 * values.size() - 1);
      const int size = static_cast<int>(values.size());
      for (int i = 0; i < size; ++i)
      {
        next[2 * i] = values[i];
      }
      for (int i = 0; i + 1 < size; ++i)
      {
        const double a = i - 1 >= 0 ? values[i - 1] : 0.0;
        const double d = i + 2 < size ? values[i + 2] : 0.0;
        next[2 * i + 1] = (9.0 * (values[i] + values[i + 1]) - (a + d)) / 16.0;
      }
      values.swap(next);
    }
    return values;
  }();
  return table;
}

/// Central differences of the table: slopes (per sample) shared by neighbouring pieces.
const std::vector<double>& fundamentalSlopes()
{
  static const std::vector<double> slopes = [] {
    const std::vector<double>& v = fundamentalFunction();
    std::vector<double> d(v.size(), 0.0);
    for (size_t i = 1; i + 1 < v.size(); ++i)
    {
      d[i] = 0.5 * (v[i + 1] - v[i - 1]);
    }
    return d;
  }();
  return slopes;
}

/// phi(x) for x in [-3, 3]: cubic Hermite between the dyadic samples with central-difference
/// slopes, so the result is exactly C1, interpolates the samples (phi(k) = [k == 0]) and keeps
/// the partition of unity (shifted samples and slopes sum to 1 and 0).
double fundamental(double x)
{
  const std::vector<double>& v = fundamentalFunction();
  const std::vector<double>& d = fundamentalSlopes();
  const double position = (x + 3.0) * kPerUnit;
  // Written so that NaN is outside too: it must never reach the cast below.
  if (!(position > 0.0 && position < static_cast<double>(v.size() - 1)))
  {
    return 0.0;
  }
  const int i = static_cast<int>(position);
  const double u = position - i;
  const double u2 = u * u;
  const double u3 = u2 * u;
  return (2 * u3 - 3 * u2 + 1) * v[i] + (u3 - 2 * u2 + u) * d[i] + (-2 * u3 + 3 * u2) * v[i + 1] +
    (u3 - u2) * d[i + 1];
}

void hermite(
  CurveWeights& out, const double* times, int n, int i, double u, const SegmentTangents& tangents)
{
  // Hermite basis on segment i, h = t[i+1] - t[i]; the rational one (Curves.h) where the shape
  // asks for it. (NaN fails the test, so it keeps the cubic.)
  const double u2 = u * u;
  const double u3 = u2 * u;
  double h00 = 2 * u3 - 3 * u2 + 1;
  double h10 = u3 - 2 * u2 + u;
  double h01 = -2 * u3 + 3 * u2;
  double h11 = u3 - u2;
  const double r = tangents.shape;
  if (r > 3.0 && r < 1e300)
  {
    const double v = 1.0 - u;
    const double denominator = 1.0 + (r - 3.0) * u * v;
    h00 = (v * v * v + r * u * v * v) / denominator;
    h10 = u * v * v / denominator;
    h01 = (r * u2 * v + u3) / denominator;
    h11 = -u2 * v / denominator;
  }
  const double h = times[i + 1] - times[i];
  out.add(i, h00);
  out.add(i + 1, h01);
  // The tangent at key k: before (p[k] - p[k-1]) / h- + after (p[k+1] - p[k]) / h+, each secant
  // only where it exists.
  auto addTangent = [&](int k, const KeyTangent& tangent, double scale) {
    if (k > 0)
    {
      const double c = scale * tangent.before / (times[k] - times[k - 1]);
      out.add(k, c);
      out.add(k - 1, -c);
    }
    if (k + 1 < n)
    {
      const double c = scale * tangent.after / (times[k + 1] - times[k]);
      out.add(k + 1, c);
      out.add(k, -c);
    }
  };
  addTangent(i, tangents.start, h10 * h);
  addTangent(i + 1, tangents.end, h11 * h);
}

void bSpline(CurveWeights& out, int n, int i, double u)
{
  // Uniform cubic B-spline through the control points i-1 .. i+2 on segment [i, i+1].
  const double u2 = u * u;
  const double u3 = u2 * u;
  const double b0 = (1 - 3 * u + 3 * u2 - u3) / 6.0;
  const double b1 = (4 - 6 * u2 + 3 * u3) / 6.0;
  const double b2 = (1 + 3 * u + 3 * u2 - 3 * u3) / 6.0;
  const double b3 = u3 / 6.0;
  addVirtual(out, i - 1, b0, n);
  addVirtual(out, i, b1, n);
  addVirtual(out, i + 1, b2, n);
  addVirtual(out, i + 2, b3, n);
}

void subdivision(CurveWeights& out, int n, int i, double u)
{
  const double s = i + u;
  for (int k = i - 2; k <= i + 3; ++k)
  {
    const double w = fundamental(s - k);
    if (w != 0.0)
    {
      addVirtual(out, k, w, n);
    }
  }
}

} // namespace

KeyTangent catmullRomTangent(const double* times, int keyCount, int k)
{
  if (k <= 0)
  {
    return { 0.0, 1.0 };
  }
  if (k >= keyCount - 1)
  {
    return { 1.0, 0.0 };
  }
  const double before = times[k] - times[k - 1], after = times[k + 1] - times[k];
  return { before / (before + after), after / (before + after) };
}

CurveWeights curveWeights(CurveScheme scheme, const double* times, int keyCount, double t)
{
  if (scheme == CurveScheme::CatmullRom && keyCount > 1)
  {
    const int i = curveSegment(times, keyCount, t);
    return curveWeights(scheme, times, keyCount, t,
      SegmentTangents{
        catmullRomTangent(times, keyCount, i), catmullRomTangent(times, keyCount, i + 1) });
  }
  return curveWeights(scheme, times, keyCount, t, SegmentTangents{});
}

int curveSegment(const double* times, int keyCount, double t)
{
  if (keyCount <= 1)
  {
    return 0;
  }
  double u;
  return segmentOf(times, keyCount, std::clamp(t, times[0], times[keyCount - 1]), u);
}

CurveWeights curveWeights(
  CurveScheme scheme, const double* times, int keyCount, double t, const SegmentTangents& tangents)
{
  CurveWeights out;
  if (keyCount <= 1)
  {
    out.add(0, 1.0);
    return out;
  }
  t = std::clamp(t, times[0], times[keyCount - 1]);
  double u;
  const int i = segmentOf(times, keyCount, t, u);
  switch (scheme)
  {
    case CurveScheme::Linear:
      out.add(i, 1.0 - u);
      out.add(i + 1, u);
      break;
    case CurveScheme::CatmullRom:
      hermite(out, times, keyCount, i, u, tangents);
      break;
    case CurveScheme::BSpline:
      bSpline(out, keyCount, i, u);
      break;
    case CurveScheme::Subdivision:
      subdivision(out, keyCount, i, u);
      break;
    case CurveScheme::Bezier:
    {
      const double v = 1.0 - u;
      out.add(3 * i, v * v * v);
      out.add(3 * i + 1, 3.0 * v * v * u);
      out.add(3 * i + 2, 3.0 * v * u * u);
      out.add(3 * i + 3, u * u * u);
      break;
    }
  }
  return out;
}

CurveStencil curveStencil(CurveScheme scheme, int keyCount, int segment)
{
  CurveStencil out;
  if (keyCount <= 1)
  {
    return out;
  }
  const int last = keyCount - 1;
  auto keys = [&](int below, int above) {
    out.first = std::max(segment - below, 0);
    out.last = std::min(segment + above, last);
    out.firstReference = segment;
    out.lastReference = segment + 1;
  };
  switch (scheme)
  {
    case CurveScheme::Linear:
      keys(0, 1);
      break;
    case CurveScheme::CatmullRom:
    case CurveScheme::BSpline:
      keys(1, 2);
      break;
    case CurveScheme::Subdivision:
      keys(2, 3);
      break;
    case CurveScheme::Bezier:
      out.first = out.firstReference = 3 * segment;
      out.last = out.lastReference = 3 * segment + 3;
      break;
  }
  return out;
}

} // namespace lct
