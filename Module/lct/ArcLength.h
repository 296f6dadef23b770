/**
 * @file ArcLength.h
 * @brief Constant speed: the reparametrisation of time by the arc length of a point's path,
 *        from a table of samples of the curve, refined on the curve itself at each query.
 *
 * The table holds curve times tau_0 < ... < tau_m (the keys' times and samples between them)
 * and the point's positions there; the chord of each interval stands for its arc (it misses
 * (kappa l)^2 / 24 of an interval of length l on a path of curvature kappa, so the sampler
 * makes the intervals short where the path curves: vtkLCTPathTiming.h halves an interval until
 * its chord is within 1e-5 of the sum of its half chords). Output time is spread over the
 * intervals in proportion to their chords, so the point covers equal distances in equal times;
 * within an interval the query solves |p(tau) - p(tau_j)| = d for tau (Illinois regula falsi
 * on the curve, a few evaluations), so the speed stays even where the curve's own speed varies
 * fast (near a key where it stops).
 *
 * Intervals in which the point does not move (chord <= 1e-12 of the path's length, or of the
 * largest coordinate: a turn in place, a zoom, round-off) keep their own duration, and the moving
 * intervals share the rest of the time: nothing happens in zero time. A path that does not move at
 * all keeps its times.
 */
#ifndef lct_ArcLength_h
#define lct_ArcLength_h

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace lct
{

/// `Dim`: the dimension of the measured point (3 for a point, 6 for a camera's eye and focal
/// point together).
template <int Dim>
class ArcLengthTime
{
public:
  using Point = Eigen::Matrix<double, Dim, 1>;

  /// Builds the table from curve times (strictly increasing, at least two) and the point's
  /// positions there. False (table empty) when a position is not finite, the length overflows
  /// or the times are not increasing.
  bool build(const std::vector<double>& curveTimes, const std::vector<Point>& positions);

  bool empty() const { return this->Tau.size() < 2; }
  /// The path's length (the sum of the chords).
  double length() const { return this->Length; }
  /// The output time at which the point reaches sample j (the time a key is passed, for the
  /// samples at the keys).
  double outputTime(int j) const { return this->Out[j]; }

  /// The curve time at output time t (clamped to the table's range). positionAt(tau, p) sets p
  /// to the point's position at curve time tau and returns false when it cannot.
  template <typename PositionAt>
  double curveTime(double t, PositionAt&& positionAt) const;

private:
  /// curveTime's solve: Illinois regula falsi, then bisection to a one-ulp bracket (~64 halvings
  /// of a segment at most).
  static constexpr int kIllinoisIterations = 12;
  static constexpr int kMaximumIterations = 128;

  std::vector<double> Tau;
  std::vector<double> Out;
  std::vector<double> Chord;
  std::vector<Point> P;
  std::vector<char> Moving;
  double Length = 0.0;
};

template <int Dim>
template <typename PositionAt>
double ArcLengthTime<Dim>::curveTime(double t, PositionAt&& positionAt) const
{
  if (this->empty())
  {
    return t;
  }
  t = std::clamp(t, this->Out.front(), this->Out.back());
  const int last = static_cast<int>(this->Out.size()) - 2;
  const int j = std::clamp(
    static_cast<int>(std::upper_bound(this->Out.begin(), this->Out.end(), t) - this->Out.begin()) -
      1,
    0, last);
  const double a = this->Tau[j], b = this->Tau[j + 1];
  const double span = this->Out[j + 1] - this->Out[j];
  if (!(span > 0.0))
  {
    return a;
  }
  const double fraction = std::clamp((t - this->Out[j]) / span, 0.0, 1.0);
  const double linear = a + fraction * (b - a);
  if (!this->Moving[j] || fraction == 0.0 || fraction == 1.0)
  {
    return fraction == 1.0 ? b : linear;
  }
  // Illinois regula falsi on f(tau) = |p(tau) - p_j| - d, f(a) = -d < 0 < f(b) = chord - d.
  const double d = fraction * this->Chord[j];
  double lo = a, hi = b, fLo = -d, fHi = this->Chord[j] - d;
  double tau = linear;
  int side = 0;
  Point p;
  // Illinois steps, then bisection, until |f| is at round-off or the bracket is one ulp wide:
  // stopped after 12 steps, the last iterate could lie on either side of the root, and a point
  // between keys 1e-12 apart in time moved backwards by 3e-4 of its segment.
  for (int iteration = 0; iteration < kMaximumIterations; ++iteration)
  {
    if (!positionAt(tau, p) || !p.allFinite())
    {
      return linear;
    }
    const double f = (p - this->P[j]).stableNorm() - d; // no square out of range
    if (std::abs(f) <= 1e-12 * this->Chord[j])
    {
      return tau;
    }
    if (f < 0.0)
    {
      lo = tau;
      fLo = f;
      if (side == -1)
      {
        fHi *= 0.5;
      }
      side = -1;
    }
    else
    {
      hi = tau;
      fHi = f;
      if (side == 1)
      {
        fLo *= 0.5;
      }
      side = 1;
    }
    if (!(std::nextafter(lo, hi) < hi))
    {
      // The root is between two adjacent doubles: lo, the last time short of the distance, so
      // that a later output time never maps to an earlier curve time.
      return lo;
    }
    const double next =
      iteration < kIllinoisIterations ? lo - fLo * (hi - lo) / (fHi - fLo) : lo + 0.5 * (hi - lo);
    tau = std::isfinite(next) ? std::clamp(next, lo, hi) : lo + 0.5 * (hi - lo);
  }
  return lo;
}

template <int Dim>
bool ArcLengthTime<Dim>::build(
  const std::vector<double>& curveTimes, const std::vector<Point>& positions)
{
  *this = ArcLengthTime();
  const size_t m = curveTimes.size();
  if (m < 2 || positions.size() != m)
  {
    return false;
  }
  std::vector<double> chord(m - 1);
  double length = 0.0;
  for (size_t j = 0; j + 1 < m; ++j)
  {
    if (!(curveTimes[j + 1] > curveTimes[j]) || !positions[j].allFinite() ||
      !positions[j + 1].allFinite())
    {
      return false;
    }
    chord[j] = (positions[j + 1] - positions[j]).stableNorm();
    length += chord[j];
  }
  if (!std::isfinite(length))
  {
    return false;
  }
  // Moving intervals share the time that the still ones do not keep, in proportion to length.
  // Still: below 1e-12 of the path's length, or within round-off of its coordinates (64 ulps of
  // their size: a point that does not move, e.g. an eye wobbling by 1e-15 through a zoom, is not
  // a path). 1e-12 of the size read a 1-unit path 1e12 from the origin as still, and kept its
  // times.
  double size = 0.0;
  for (const Point& p : positions)
  {
    size = std::max(size, p.cwiseAbs().maxCoeff());
  }
  const double still =
    std::max(1e-12 * length, 64.0 * std::numeric_limits<double>::epsilon() * size);
  std::vector<char> moving(m - 1);
  double stillTime = 0.0, movingLength = 0.0;
  for (size_t j = 0; j + 1 < m; ++j)
  {
    moving[j] = length > 0.0 && chord[j] > still;
    if (moving[j])
    {
      movingLength += chord[j];
    }
    else
    {
      stillTime += curveTimes[j + 1] - curveTimes[j];
    }
  }
  const double total = curveTimes.back() - curveTimes.front();
  const double movingTime = std::max(total - stillTime, 0.0);
  std::vector<double> out(m);
  out[0] = curveTimes.front();
  for (size_t j = 0; j + 1 < m; ++j)
  {
    const double step =
      moving[j] ? chord[j] / movingLength * movingTime : curveTimes[j + 1] - curveTimes[j];
    out[j + 1] = std::min(out[j] + step, curveTimes.back());
  }
  out.back() = curveTimes.back();
  this->Tau = curveTimes;
  this->Out = std::move(out);
  this->Chord = std::move(chord);
  this->P = positions;
  this->Moving = std::move(moving);
  this->Length = length;
  return true;
}

} // namespace lct

#endif
