/**
 * @file SegmentPathMetric.h
 * @brief Hawkins & Grimm's path metric (§5.1) per key segment, against the true key cameras,
 *        with how far the path misses its keys.
 *
 * Hawkins & Grimm define the excess for a key pair: a scene point's path between two keys
 * against the straight chord between its positions at the keys. Over a path through many keys
 * the chord from the first to the last sample says little (a smooth 165 degree orbit through 4
 * keys reads 133 %) and depends on the samples. Here, for keys K_0 .. K_n and the path's cameras
 * sampled at the same number of samples on every segment (both ends included, at the key times):
 *
 * - length l_k of a point on segment k: from its position in the TRUE key camera K_k, through its
 *   positions in the path's samples, to its position in K_(k+1). A path that misses a key pays
 *   the miss in its length (triangle inequality: l_k >= l0_k always), so a path cannot look
 *   better by missing its keys;
 * - chord l0_k: between its positions in K_k and K_(k+1);
 * - segment excess: 100 (l_k - l0_k) / l0_k, averaged over the points; total excess:
 *   100 (sum_k l_k - sum_k l0_k) / sum_k l0_k, i.e. against the polygon through the key
 *   positions, averaged over the points;
 * - in camera space (the view matrix times the point) and on the screen: the normalised device
 *   coordinates x, y of the composite projection, x times the viewport's aspect (width / height),
 *   so that both are in units of half the screen height and a distance is the same whichever
 *   way it points, as in pixels;
 * - key miss at key k: the mean over the points of |path(t_k) - K_k| in camera space, in % of
 *   the point's distance from the key camera, and on the screen in % of the screen height;
 * - in front of the camera: ahead of it in camera space (z < 0), for parallel projections too;
 * - points leaving the view on segment k: in front of the camera and within [-1, 1]^2 at both
 *   true keys, and not so at some sample of the segment (a point outside the view at a key is
 *   the user's framing, not the path's doing).
 *
 * A point with a negligible chord on a segment (1e-9 of its path there; in camera space relative
 * to the point's distance from the cameras, so the measure does not change with the scene's
 * size) counts as 0 when it does not move there either, and is left out of that segment's mean
 * (counted in `closedCamera` / `closedScreen`) when it moves and comes back: callers must not
 * report a segment whose every point is left out as 0 (its excess is unbounded). A
 * point behind the camera at a sample has no screen path on that segment and is left out of its
 * screen mean (and the total screen mean).
 */
#ifndef lct_SegmentPathMetric_h
#define lct_SegmentPathMetric_h

#include "vtkLCTModule.h"

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <vector>

namespace lct
{

using Matrices4d = std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>>;

struct SegmentExcess
{
  double camera = 0.0;    ///< mean excess in camera space, percent
  double screen = 0.0;    ///< mean excess on the screen, percent
  int measuredCamera = 0; ///< points averaged in camera space
  int measuredScreen = 0; ///< points averaged on the screen
  int closedCamera = 0;   ///< points left out: they move but end where they started
  int closedScreen = 0;   ///< likewise on the screen
  int leavingView = 0;    ///< in view at both keys, out of it at some sample
};

struct KeyMiss
{
  double camera = 0.0; ///< mean |path - key| in camera space, % of the point's distance
  double screen = 0.0; ///< mean |path - key| on the screen, % of the screen height
};

struct SegmentPathMetricResult
{
  std::vector<SegmentExcess> segments; ///< one per key segment
  std::vector<KeyMiss> keys;           ///< one per key
  SegmentExcess total;                 ///< over the polygon through the keys; leavingView: points
                                       ///< leaving on some segment
  KeyMiss largestMiss;                 ///< the largest key miss, each measure on its own
};

/// The metric of a path with keyViews.size() = n + 1 keys (view and composite projection
/// matrices, world to camera / clip coordinates) and samplesPerSegment samples per segment
/// (sample s of segment k at index k * samplesPerSegment + s; s = 0 at key k, the last at key
/// k + 1) and the viewport's aspect (width / height, that of the projections). Preconditions:
/// n >= 1, samplesPerSegment >= 2, the sizes consistent, every matrix finite, aspect > 0
/// (callers validate).
VTKLCT_EXPORT SegmentPathMetricResult measureSegments(const Matrices4d& keyViews,
  const Matrices4d& keyProjections, const Matrices4d& sampleViews,
  const Matrices4d& sampleProjections, int samplesPerSegment,
  const std::vector<Eigen::Vector3d>& points, double aspect = 1.0);

} // namespace lct

#endif
