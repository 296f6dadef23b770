#include "lct/BSplineFit.h"


#include <algorithm>
#include <cmath>
#include <iterator>

namespace lct
{
namespace
{

constexpr int kMaxDegree = 3;
constexpr double kSmoothingShare = 1e-10;

/// The clamped knot vector: degree + 1 copies of each end around the interior knots.
std::vector<double> knotVector(const BSplineCurve& curve)
{
  const int p = curve.degree;
  std::vector<double> knots;
  knots.reserve(curve.interiorKnots.size() + 2 * static_cast<std::size_t>(p) + 2);
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, 0.0);
  for (int k : curve.interiorKnots)
  {
    knots.push_back(static_cast<double>(k));
  }
  knots.insert(knots.end(), static_cast<std::size_t>(p) + 1, static_cast<double>(curve.samples - 1));
  return knots;
}

/// Walks the integer parameters 0 .. N-1 in order, giving for each the index of its first
/// non-zero basis function and the p + 1 values (Piegl & Tiller A2.2).
class BasisWalker
{
public:
  explicit BasisWalker(const BSplineCurve& curve)
    : Knots(knotVector(curve))
    , Degree(curve.degree)
    , Last(curve.controlPointCount() - 1)
    , Span(curve.degree)
  {
  }

  /// Fills `values` (degree + 1 entries) at u and returns the index of the first one.
  int At(double u, double* values)
  {
    const int p = this->Degree;
    while (this->Span < this->Last && u >= this->Knots[static_cast<std::size_t>(this->Span) + 1])
    {
      ++this->Span;
    }
    const int k = this->Span;
    double left[kMaxDegree + 1];
    double right[kMaxDegree + 1];
    values[0] = 1.0;
    for (int j = 1; j <= p; ++j)
    {
      left[j] = u - this->Knots[static_cast<std::size_t>(k + 1 - j)];
      right[j] = this->Knots[static_cast<std::size_t>(k + j)] - u;
      double saved = 0.0;
      for (int r = 0; r < j; ++r)
      {
        const double temp = values[r] / (right[r + 1] + left[j - r]);
        values[r] = saved + right[r + 1] * temp;
        saved = left[j - r] * temp;
      }
      values[j] = saved;
    }
    return k - p;
  }

private:
  std::vector<double> Knots;
  int Degree;
  int Last;
  int Span;
};

bool knotsValid(const std::vector<int>& knots, int samples)
{
  int previous = 0;
  for (int k : knots)
  {
    if (k <= previous || k >= samples - 1)
    {
      return false;
    }
    previous = k;
  }
  return true;
}

/// Solves S x = b in place for the columns of `rhs` (one per system, transposed: rhs is
/// d x n), S symmetric positive definite and banded, stored as band(r, i) = S(i + r, i) for
/// r = 0 .. w. Band Cholesky S = L L^T (Golub & Van Loan, Matrix Computations, Alg. 4.3.5):
/// O(n w^2), no fill-in outside the band. Returns false if a pivot is not positive.
bool bandCholeskySolve(Eigen::MatrixXd& band, Eigen::MatrixXd& rhs)
{
  const int w = static_cast<int>(band.rows()) - 1;
  const int n = static_cast<int>(band.cols());
  for (int j = 0; j < n; ++j)
  {
    for (int k = std::max(0, j - w); k < j; ++k)
    {
      // Subtract L(j..j+w-(j-k), k) L(j, k) from column j.
      const double ljk = band(j - k, k);
      for (int i = j; i <= std::min(n - 1, k + w); ++i)
      {
        band(i - j, j) -= band(i - k, k) * ljk;
      }
    }
    const double pivot = band(0, j);
    if (!(pivot > 0.0))
    {
      return false;
    }
    const double root = std::sqrt(pivot);
    for (int r = 0; r <= w && j + r < n; ++r)
    {
      band(r, j) /= root;
    }
  }
  // L y = b, then L^T x = y.
  for (int j = 0; j < n; ++j)
  {
    rhs.col(j) /= band(0, j);
    for (int r = 1; r <= w && j + r < n; ++r)
    {
      rhs.col(j + r) -= band(r, j) * rhs.col(j);
    }
  }
  for (int j = n - 1; j >= 0; --j)
  {
    for (int r = 1; r <= w && j + r < n; ++r)
    {
      rhs.col(j) -= band(r, j) * rhs.col(j + r);
    }
    rhs.col(j) /= band(0, j);
  }
  return true;
}

/// Per-sample error of the curve.
Eigen::VectorXd sampleErrors(
  const Eigen::MatrixXd& samples, const BSplineCurve& curve, const SampleError& error)
{
  const Eigen::MatrixXd values = evaluateAtSamples(curve);
  if (!error)
  {
    return (samples - values).colwise().norm().transpose();
  }
  Eigen::VectorXd errors(values.cols());
  Eigen::VectorXd value(values.rows());
  for (Eigen::Index f = 0; f < values.cols(); ++f)
  {
    value = values.col(f);
    errors(f) = error(static_cast<int>(f), value);
  }
  return errors;
}

} // namespace

Eigen::MatrixXd evaluateAtSamples(const BSplineCurve& curve)
{
  const int d = static_cast<int>(curve.controlPoints.rows());
  Eigen::MatrixXd out(d, curve.samples);
  BasisWalker walker(curve);
  double basis[kMaxDegree + 1];
  for (int f = 0; f < curve.samples; ++f)
  {
    const int first = walker.At(static_cast<double>(f), basis);
    // Plain loops: d is 3 or 6, too small for Eigen's dynamic-size expressions to pay.
    double* column = out.data() + static_cast<std::ptrdiff_t>(f) * d;
    const double* points = curve.controlPoints.data() + static_cast<std::ptrdiff_t>(first) * d;
    for (int r = 0; r < d; ++r)
    {
      column[r] = basis[0] * points[r];
    }
    for (int i = 1; i <= curve.degree; ++i)
    {
      for (int r = 0; r < d; ++r)
      {
        column[r] += basis[i] * points[i * d + r];
      }
    }
  }
  return out;
}

bool isWellFormed(const BSplineCurve& curve, const char** why)
{
  auto fail = [why](const char* reason) {
    if (why)
    {
      *why = reason;
    }
    return false;
  };
  if (curve.samples < 1)
  {
    return fail("a curve without samples");
  }
  if (curve.degree < 0 || curve.degree > kMaxDegree || curve.degree > curve.samples - 1)
  {
    return fail("a curve degree outside 0..3 or above its sample count - 1");
  }
  if (!knotsValid(curve.interiorKnots, curve.samples))
  {
    return fail("curve knots that are not increasing integers inside the frame range");
  }
  if (curve.controlPoints.cols() != curve.controlPointCount() || curve.controlPoints.rows() < 1)
  {
    return fail("a control point count that does not match the knots");
  }
  if (!curve.controlPoints.allFinite())
  {
    return fail("a control point that is not finite");
  }
  return true;
}

Result<BSplineCurve> fitLeastSquares(
  const Eigen::MatrixXd& samples, int degree, const std::vector<int>& interiorKnots)
{
  using Out = Result<BSplineCurve>;
  const int n = static_cast<int>(samples.cols());
  if (n < 1 || samples.rows() < 1 || degree < 0 || degree > kMaxDegree ||
    !knotsValid(interiorKnots, n))
  {
    return Out::failure(Status::InvalidArgument);
  }
  if (!samples.allFinite())
  {
    return Out::failure(Status::NonFinite);
  }
  Out out;
  BSplineCurve& curve = out.value;
  curve.degree = std::min(degree, n - 1);
  curve.samples = n;
  curve.interiorKnots = interiorKnots;
  const int p = curve.degree;
  const int count = curve.controlPointCount();
  if (p == 0)
  {
    curve.controlPoints = samples.rowwise().mean();
    return out;
  }

  // Normal equations (A^T A + lambda D^T D) c = A^T y, banded with half-width w = max(p, 2):
  // band(r, i) = entry (i + r, i). D holds the second differences c_i - 2 c_{i+1} + c_{i+2},
  // zero on lines, so the penalty never pulls a well-determined fit, only fixes the free
  // directions.
  const int w = std::max(p, 2);
  const int d = static_cast<int>(samples.rows());
  Eigen::MatrixXd band = Eigen::MatrixXd::Zero(w + 1, count);
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(samples.rows(), count);
  BasisWalker walker(curve);
  double basis[kMaxDegree + 1];
  for (int f = 0; f < n; ++f)
  {
    const int first = walker.At(static_cast<double>(f), basis);
    const double* y = samples.data() + static_cast<std::ptrdiff_t>(f) * d;
    for (int a = 0; a <= p; ++a)
    {
      double* r = rhs.data() + static_cast<std::ptrdiff_t>(first + a) * d;
      for (int i = 0; i < d; ++i)
      {
        r[i] += basis[a] * y[i];
      }
      for (int b = a; b <= p; ++b)
      {
        band(b - a, first + a) += basis[a] * basis[b];
      }
    }
  }
  const double lambda = kSmoothingShare * band.row(0).sum() / count;
  const double stencil[3] = { 1.0, -2.0, 1.0 };
  for (int i = 0; i + 2 < count; ++i)
  {
    for (int a = 0; a < 3; ++a)
    {
      for (int b = a; b < 3; ++b)
      {
        band(b - a, i + a) += lambda * stencil[a] * stencil[b];
      }
    }
  }
  if (!bandCholeskySolve(band, rhs))
  {
    return Out::failure(Status::NumericalFailure);
  }
  curve.controlPoints = std::move(rhs);
  if (!curve.controlPoints.allFinite())
  {
    return Out::failure(Status::NumericalFailure);
  }
  return out;
}

Result<BSplineCurve> fitWithinTolerance(
  const Eigen::MatrixXd& samples, int degree, const ToleranceFit& options)
{
  using Out = Result<BSplineCurve>;
  const int n = static_cast<int>(samples.cols());
  if (n < 1)
  {
    return Out::failure(Status::InvalidArgument);
  }
  Eigen::VectorXd tolerance = options.sampleTolerances;
  if (tolerance.size() == 0)
  {
    tolerance.setConstant(n, options.tolerance);
  }
  if (tolerance.size() != n || !tolerance.allFinite() || !(tolerance.minCoeff() > 0.0))
  {
    return Out::failure(Status::InvalidArgument);
  }
  std::vector<int> knots;
  for (;;)
  {
    Out fit = fitLeastSquares(samples, degree, knots);
    if (!fit)
    {
      return fit;
    }
    if (options.adjust)
    {
      options.adjust(fit.value);
    }
    const Eigen::VectorXd errors = sampleErrors(samples, fit.value, options.error);
    // Span s runs from bounds[s] to bounds[s + 1]; each sample belongs to the span it starts.
    std::vector<int> bounds;
    bounds.reserve(knots.size() + 2);
    bounds.push_back(0);
    bounds.insert(bounds.end(), knots.begin(), knots.end());
    bounds.push_back(n - 1);
    std::vector<int> added;
    for (std::size_t s = 0; s + 1 < bounds.size(); ++s)
    {
      const int a = bounds[s];
      const int b = bounds[s + 1];
      const int end = s + 2 == bounds.size() ? b : b - 1;
      // The worst sample relative to its tolerance.
      int worst = a;
      double worstShare = errors(a) / tolerance(a);
      for (int f = a + 1; f <= end; ++f)
      {
        const double share = errors(f) / tolerance(f);
        if (share > worstShare || std::isnan(share))
        {
          worst = f;
          worstShare = std::isnan(share) ? HUGE_VAL : share;
        }
      }
      if (worstShare <= 1.0)
      {
        continue;
      }
      if (b - a >= 2)
      {
        const int quarter = (b - a) / 4;
        const bool central = worst - a >= std::max(1, quarter) && b - worst >= std::max(1, quarter);
        added.push_back(central ? worst : a + (b - a) / 2);
        continue;
      }
      // A span of one step cannot be split, but its control points are shared with the spans
      // either side, whose samples pull them: a knot next to it in each frees them.
      if (s > 0 && a - bounds[s - 1] >= 2)
      {
        added.push_back(a - 1);
      }
      if (s + 2 < bounds.size() && bounds[s + 2] - b >= 2)
      {
        added.push_back(b + 1);
      }
    }
    std::sort(added.begin(), added.end());
    added.erase(std::unique(added.begin(), added.end()), added.end());
    if (added.empty())
    {
      return fit;
    }
    std::vector<int> merged;
    merged.reserve(knots.size() + added.size());
    std::merge(knots.begin(), knots.end(), added.begin(), added.end(), std::back_inserter(merged));
    knots.swap(merged);
  }
}

} // namespace lct
