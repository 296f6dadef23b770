/**
 * @file PathMetric.h
 * @brief Hawkins & Grimm's quality metric for camera paths (§5.1): how much farther than
 *        necessary scene points travel, in camera space and on the screen.
 *
 * For each scene point, the path it follows in camera space (view matrix times point) over the
 * sampled cameras has length l; the straight segment between its first and last positions has
 * length l0. The excess is 100 (l - l0) / l0 percent (the paper prints it with the sign
 * flipped), averaged over the points; a point that does not move counts as 0, and a point that
 * moves but comes back (l0 negligible, l not) is counted as closed and left out: callers must
 * report such a path rather than average around it. Negligible means 1e-9 of the point's path,
 * and still 1e-9 of its distance from the cameras (camera space) or of the screen, so that the
 * measure does not change with the scene's size. The same on the screen uses the normalised
 * device coordinates (x, y) of the composite projection, x times the viewport's aspect (units of
 * half the screen height both ways, as pixels), for points in front of the camera at every
 * sample: a point behind it at some sample has no screen path and is left out of the screen
 * mean. A point "leaves the view" when at some sample it is behind the camera or outside
 * [-1, 1]^2 in normalised device coordinates.
 */
#ifndef lct_PathMetric_h
#define lct_PathMetric_h

#include "vtkLCTModule.h"

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <vector>

namespace lct
{

struct PathMetricResult
{
  double cameraSpaceExcess = 0.0; ///< mean excess path length in camera space, percent
  double screenSpaceExcess = 0.0; ///< mean excess path length on the screen, percent
  int pointsMeasuredCamera = 0;   ///< points with a chord, or that do not move (excess 0)
  int pointsMeasuredScreen = 0;   ///< likewise on the screen
  /// Points that move but come back to where they started (a negligible chord after a path of
  /// some length, e.g. over a full orbit): their excess is unbounded, so none is averaged in.
  int closedCamera = 0;
  int closedScreen = 0;
  std::vector<char> leftView; ///< per point: left the view at some sample
};

/// The metric over cameras given by their view matrices and composite projection matrices
/// (world to clip coordinates), sampled in order along the path (at least two samples), for a
/// viewport of the given aspect (width / height, that of the projections; > 0).
VTKLCT_EXPORT PathMetricResult measurePath(
  const std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>& views,
  const std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>& projections,
  const std::vector<Eigen::Vector3d>& points, double aspect = 1.0);

} // namespace lct

#endif
