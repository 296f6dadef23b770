/**
 * @file BSplineFit.h
 * @brief Least-squares B-spline curves through regularly sampled vectors, with knots placed
 *        adaptively until every sample is within a tolerance.
 *
 * A track of d-dimensional samples y_0 .. y_{N-1} at the integer parameters 0 .. N-1 (the
 * frames of an animation; here the log coordinates of one joint, which form a vector space, so
 * a curve in them is a curve of transforms: Alexa 2002 section 4, Kaji & Ochiai eq. 9) is
 * approximated by a clamped B-spline of degree p (The NURBS Book, Piegl & Tiller, section
 * 2.2; evaluation by their algorithm A2.2) whose interior knots are integers in (0, N-1). The
 * control points minimise sum_f |y_f - s(f)|^2 plus a tiny second-difference penalty
 * (1e-10 of the data term), which makes the normal equations definite even where a span holds
 * fewer samples than control points and leaves a well-determined fit unchanged to ~1e-10.
 *
 * `fitWithinTolerance` starts with no interior knot and splits, in each pass, every knot span
 * that holds a sample farther than the tolerance from the curve: at its worst sample, or at
 * its middle when the worst sample lies in the outer quarters, so spans shrink geometrically
 * and the passes are bounded by about log_{4/3} N. With a knot at every integer the fit
 * interpolates, so it converges for any tolerance above the round-off of the samples.
 *
 * Pure functions, no state: safe to call concurrently.
 */
#ifndef lct_BSplineFit_h
#define lct_BSplineFit_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

#include <functional>
#include <vector>

namespace lct
{

struct BSplineCurve
{
  int degree = 0;                 ///< 0 (constant) to 3
  int samples = 0;                ///< N: the curve covers the parameters [0, N - 1]
  std::vector<int> interiorKnots; ///< strictly increasing integers in (0, N - 1)
  /// d x (interiorKnots.size() + degree + 1) control points.
  Eigen::MatrixXd controlPoints;

  int controlPointCount() const noexcept
  {
    return static_cast<int>(this->interiorKnots.size()) + this->degree + 1;
  }
};

/// The curve at every integer parameter 0 .. samples - 1: a d x samples matrix.
VTKLCT_EXPORT Eigen::MatrixXd evaluateAtSamples(const BSplineCurve& curve);

/// Whether a curve is well formed (degree 0..3, knots strictly inside and increasing, the
/// control point count matching, every control point finite); `why`, when given, says what is
/// wrong. Decoders check this before evaluating a curve read from a file.
VTKLCT_EXPORT bool isWellFormed(const BSplineCurve& curve, const char** why = nullptr);

/// The least-squares curve of `degree` (lowered to samples - 1 for short tracks) with these
/// interior knots through the columns of `samples`. InvalidArgument for no samples, a degree
/// outside 0..3 or knots that are not strictly increasing integers in (0, N - 1); NonFinite
/// for a non-finite sample.
VTKLCT_EXPORT Result<BSplineCurve> fitLeastSquares(
  const Eigen::MatrixXd& samples, int degree, const std::vector<int>& interiorKnots);

/// How far a curve value is from sample f, in the caller's units (default: the Euclidean
/// distance to the sample).
using SampleError = std::function<double(int f, const Eigen::VectorXd& value)>;
/// Applied to each fitted curve before its errors are measured (e.g. quantising the control
/// points, so that the tolerance holds for the curve that is stored).
using CurveAdjustment = std::function<void(BSplineCurve& curve)>;

struct ToleranceFit
{
  double tolerance = 0.0; ///< positive and finite
  /// If not empty, one tolerance per sample (each positive and finite), used instead.
  Eigen::VectorXd sampleTolerances;
  SampleError error;      ///< empty: Euclidean
  CurveAdjustment adjust; ///< empty: none
};

/// The least-squares curve of `degree` with the fewest knots this file's splitting finds such
/// that error(f, s(f)) <= tolerance for every sample, s the adjusted curve. The tolerance must
/// be positive and finite (InvalidArgument); NonFinite for a non-finite sample. When even a
/// knot at every integer leaves a sample beyond the tolerance (a tolerance at the round-off
/// of the samples, or an adjustment coarser than it) the returned curve is that densest one:
/// the caller measures the error it cares about anyway.
VTKLCT_EXPORT Result<BSplineCurve> fitWithinTolerance(
  const Eigen::MatrixXd& samples, int degree, const ToleranceFit& fit);

} // namespace lct

#endif
