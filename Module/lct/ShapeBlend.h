/**
 * @file ShapeBlend.h
 * @brief Blends of compatibly triangulated meshes by their per-face affine maps in log
 *        coordinates (Kaji & Ochiai §5.3), patched into one mesh by sparse least squares.
 *
 * Given a rest mesh U_0 (points V0, triangles F) and targets U_1 … U_k with the same triangles:
 *
 * 1. Per face j and target i, the linear map A_ij taking the rest triangle plus its ghost
 *    vertex to the target's (the fourth vertex of Sumner & Popović's deformation transfer, placed
 *    as Kaji does at centroid + n / sqrt|n|, n the unnormalised face normal):
 *    A_ij = E_ij E_0j^-1 with E = [v2 - v1, v3 - v1, ghost - v1]. det E = |n|^(3/2) > 0, so A_ij
 *    lies in GL+(3) for every pair of non-degenerate triangles.
 * 2. Its Polar log psi(A_ij) = (log U, log S) (Kaji & Ochiai eq. 3, lct::polarLog; no
 *    translation part). The rotation branch of each face is made consistent with its neighbours:
 *    per target and per edge-connected piece, a breadth-first walk over the face-adjacency graph
 *    (faces sharing an edge) starts at the face whose principal rotation angle is the smallest
 *    (the face that moved least) and takes each face's rotation log nearest its parent's (Kaji &
 *    Ochiai Alg. 1), so a bar twisted by 270 degrees keeps 270 at its far end instead of -90 and
 *    blends of large rotations do not tear.
 * 3. A blend with weights w (any reals: extrapolation below 0 and above 1 is allowed) is, per face,
 *    B_j = phi(sum_i w_i psi(A_ij)) (eq. 9; lct::polarExp).
 * 4. The points x (and the ghost vertices g) minimise sum_j |J_j(x, g) - B_j|_F^2, J_j the linear
 *    map taking the rest face j (with its ghost) to (x, g). Each ghost appears in one face only,
 *    so it is eliminated exactly per face (a Schur complement of a diagonal block): the normal
 *    equations in the points alone have the sparsity of the mesh's vertex adjacency, and are
 *    those of the full ghost-vertex form with the ghosts solved out. They are factorised once
 *    per rest mesh (Eigen's SimplicialLDLT, AMD ordering); each blend is one right-hand side with
 *    three columns and a back-substitution.
 * 5. Translation is not determined by the maps: in every vertex-connected piece (or a point that
 *    no triangle uses) the lowest-numbered point is pinned during the solve, and the piece is then
 *    translated so its point centroid is the weight blend of the meshes' centroids of that piece,
 *    (1 - sum_i w_i) c_0 + sum_i w_i c_i. So w = 0 gives the rest mesh and w = e_i target i (to
 *    round-off), each piece lands where the blend of its own positions puts it, and the result
 *    does not depend on which point was pinned or on the labelling. A point no triangle uses is
 *    its own piece: it moves by that linear blend of its positions.
 *
 * Degenerate triangles (|n| <= kDegenerateTriangleRatio (longest edge)^2: zero area, repeated or
 * collinear points) are reported with their face id and never divided by; so are triangles whose
 * size is beyond kTriangleScaleExponent (OutOfRange), whose squared edges and areas would leave
 * double's range (they would otherwise read as degenerate, or as Inf).
 */
#ifndef lct_ShapeBlend_h
#define lct_ShapeBlend_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace lct
{

/// A triangle is degenerate when |n| = 2 area <= this times its longest edge squared (the sine
/// of its largest angle is below ~1e-12): its ghost vertex and its map would be noise.
constexpr double kDegenerateTriangleRatio = 1e-12;

/// A triangle's edge coordinates (differences of its points) must be at most 2^this in
/// magnitude, and its largest one at least 2^-this (~1e+-144): squared edges, areas (2^+-960)
/// and the ghost vertex stay normal doubles. (Its edge matrix, whose determinant is a volume, is
/// inverted at unit size.)
constexpr int kTriangleScaleExponent = 480;

using Triangle = std::array<std::int64_t, 3>;

/// What went wrong, and where: `target` is -1 for the rest mesh; `face` or `point` are -1 when
/// the failure has no such place.
struct ShapeBlendIssue
{
  Status status = Status::Ok;
  int target = -1;
  std::int64_t face = -1;
  std::int64_t point = -1;
  bool ok() const noexcept { return status == Status::Ok; }
};

/// Runs body(begin, end) over [0, n) in any split (the VTK adapter passes vtkSMPTools::For);
/// empty: serially.
using ParallelFor =
  std::function<void(std::int64_t n, const std::function<void(std::int64_t, std::int64_t)>& body)>;

/// The rest mesh's per-face geometry and factorised normal equations, and the targets' per-face
/// logs. Not copyable (it owns a factorisation); reusable: setRest and setTargets may be called
/// again (setRest forgets the targets).
class VTKLCT_EXPORT ShapeBlender
{
public:
  ShapeBlender();
  ~ShapeBlender();
  ShapeBlender(const ShapeBlender&) = delete;
  ShapeBlender& operator=(const ShapeBlender&) = delete;

  /// Validates the rest mesh, builds the per-face maps and factorises the normal equations.
  /// Fails with InvalidArgument (no triangles, or a point index outside [0, points) — `face`
  /// says which), NonFinite (`point` says which), Singular (a degenerate triangle, `face`),
  /// OutOfRange (a triangle beyond kTriangleScaleExponent, or one so small and thin that its
  /// normal-equation block overflows, `face`) or NumericalFailure (the factorisation failed:
  /// please report the mesh).
  ShapeBlendIssue setRest(const std::vector<Eigen::Vector3d>& points,
    const std::vector<Triangle>& triangles, const ParallelFor& parallel = {});

  /// The targets' points (same count and triangles as the rest mesh): their per-face Polar logs
  /// with branch-consistent rotations. Fails with InvalidArgument (no rest mesh, or another point
  /// count: `target`), NonFinite (`target`, `point`), Singular (a degenerate target triangle:
  /// `target`, `face`) or IllConditioned / OutOfRange (a face map polarLog cannot take: `target`,
  /// `face`; polarLog's own NonFinite and Singular come with `face` and `point` -1). On failure
  /// the previous targets are kept.
  ShapeBlendIssue setTargets(
    const std::vector<std::vector<Eigen::Vector3d>>& targets, const ParallelFor& parallel = {});

  /// The blended points for weights w (one per target, any finite reals). Fails with
  /// InvalidArgument (no rest mesh, or weights.size() != number of targets), NonFinite (a weight:
  /// `target`), or the status of polarExp at the first face whose blended map it cannot form
  /// (OutOfRange, IllConditioned: `face`; e.g. an extrapolation so far that a stretch overflows),
  /// or OutOfRange without a face when the solve or the points overflow.
  /// `out` is left unchanged on failure.
  ShapeBlendIssue blend(const std::vector<double>& weights, std::vector<Eigen::Vector3d>& out,
    const ParallelFor& parallel = {}) const;

  bool hasRest() const noexcept;
  std::int64_t numberOfPoints() const noexcept;
  std::int64_t numberOfFaces() const noexcept;
  int numberOfTargets() const noexcept;
  /// Vertex-connected pieces (points that no triangle uses count as pieces of their own).
  std::int64_t numberOfPieces() const noexcept;
  /// Unknowns of the factorised system (points minus one pinned point per piece).
  std::int64_t numberOfUnknowns() const noexcept;

  /// The branch-consistent per-face log of target i (Polar layout, translation part 0).
  const LogCoords& faceLog(int target, std::int64_t face) const;

private:
  struct Data;
  std::unique_ptr<Data> D;
};

/// The ghost vertex of a triangle (Kaji): centroid + n / sqrt|n|, n = (b - a) x (c - a).
/// Precondition: the triangle is not degenerate.
VTKLCT_EXPORT Eigen::Vector3d ghostVertex(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Whether a triangle is degenerate by kDegenerateTriangleRatio (or not finite).
VTKLCT_EXPORT bool isDegenerateTriangle(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// |n| / (longest edge)^2, the measure isDegenerateTriangle compares with
/// kDegenerateTriangleRatio: about the smallest angle of a sliver (NaN for a point).
VTKLCT_EXPORT double triangleThinness(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// A triangle's size: the largest magnitude of its edge coordinates (differences of its points).
VTKLCT_EXPORT double triangleSize(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

/// Whether a triangle's size is within kTriangleScaleExponent (a triangle with all its points
/// equal is, and is degenerate). False when an edge is not finite.
VTKLCT_EXPORT bool isTriangleScaleInRange(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c);

} // namespace lct

#endif
