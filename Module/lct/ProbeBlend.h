/**
 * @file ProbeBlend.h
 * @brief Per-point blends of probe transforms (Kaji & Ochiai §5.2, eq. 9), batched over points.
 *
 * A probe is a relative transform A_i = current_i rest_i^-1 with a rest centre c_i. A point p
 * with weights w_i moves by a blend of the A_i. Four blends are offered:
 *
 *   Polar          phi(sum_i w_i psi(A_i^c))       Kaji & Ochiai eq. 9, psi = (l, log U, log S)
 *   MatrixLog      exp(sum_i w_i log A_i^c)        Alexa 2002 eq. 7
 *   Linear         sum_i w_i A_i                   linear blend skinning
 *                                                  (vtkWeightedTransformFilter)
 *   DualQuaternion DLB_i([U_i | t_i']) o           "Polar+DQ" of Kaji & Ochiai Table 2, in
 *                  sum_i w_i S_i^(c_i) / sum_i w_i  Kavan et al. 2008's two phases
 *
 * For DualQuaternion A_i = [U_i | t_i'] S_i^(c_i), with S_i^(c_i) = T(c_i) S_i T(-c_i) the
 * positive definite stretch of the polar split about the probe's own centre: the stretches are
 * blended as matrices, then the rigid parts by Kavan's DLB with the hemisphere check (t_i' =
 * t_i + (L_i - U_i) c_i). Elsewhere A_i^c = T(-c) A_i T(c) is the probe seen from a centre c.
 * Eq. 9 is not
 * translation-equivariant: the log of a rotation about a far centre carries a translation
 * l = (R - I) c that is blended linearly while the rotation is blended by angle, so the same
 * scene placed elsewhere deforms differently (a probe turning 90 degrees about c, weight 1/2:
 * 2.9 off at |c| = 10, 29 off at |c| = 100). Here every point is blended about its own weighted
 * rest centre c(p) = sum_i |w_i| c_i / sum_i |w_i|, which moves with the scene, so translating
 * the mesh and every probe by d translates the output by d, and a point of weight 1 on one probe
 * moves by exactly that probe. Centring on the point itself instead would turn the Polar blend
 * into LBS (only sum_i w_i l_i would survive); c(p) keeps the log blend. Linear and
 * DualQuaternion (both its phases) are equivariant without a centre.
 *
 * Every blend is applied as  p' = p + D (p - c) + l  with D = (blended linear part) - I formed
 * without I, so probes at rest leave every point bit for bit where it was. Normals transform by
 * the cofactor matrix of I + D (the inverse transpose up to a positive factor), renormalised.
 *
 * Rotation branches (Polar): each probe's rotation log is the one nearest a reference (Kaji &
 * Ochiai Alg. 1), so a probe driven through 3 pi blends as 3 pi, not as pi. MatrixLog and
 * DualQuaternion cannot represent turns beyond pi; that is what they are compared on.
 *
 * No allocation, no virtual call and no VTK in the per-point loop; the VTK filter
 * (vtkProbeDeformerLCT) splits the points over threads and calls `deformPoints` per range.
 */
#ifndef lct_ProbeBlend_h
#define lct_ProbeBlend_h

#include "vtkLCTModule.h"

#include "lct/LogCoords.h"
#include "lct/Status.h"
#include "lct/Sym3.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace lct
{

enum class BlendMode
{
  Polar,         ///< Kaji & Ochiai's phi(sum w psi): rigid stays rigid, turns beyond 2 pi
  MatrixLog,     ///< Alexa's exp(sum w log): principal logs only
  Linear,        ///< LBS: sum w A (collapses under twist)
  DualQuaternion ///< Kavan's DLB for the rigid part, linear blend of the stretch S
};

/// How raw weights become the weights of the blend.
enum class WeightNormalization
{
  Linear,  ///< w / sum w; the sum must be positive (a point with all weights 0 stays put)
  Softmax, ///< exp(w) / sum exp(w) over the point's slots
  None     ///< as given: sum w != 1 scales the logs (Linear: scales the matrices)
};

/// A probe as every blend mode sums it, prepared once per execution.
struct BlendProbe
{
  Eigen::Matrix3d linearMinusIdentity; ///< L - I of A = [L t; 0 1]
  Eigen::Vector3d translation;         ///< t
  Eigen::Vector3d centre;              ///< the rest centre c_i
  LogCoords logs;                      ///< psi(A) (Polar, DualQuaternion) or log A (MatrixLog)
  Eigen::Vector4d quaternion;          ///< DualQuaternion: (w, x, y, z) of the rotation U of L
  /// DualQuaternion, in Kavan et al.'s two phases A = [U | t'] T(c) S T(-c): S - I of L = U S,
  /// (S - I) c (both 0 when rigid) and the dual part (0, t') q, t' = t + (L - U) c.
  SymmetricVector stretchMinusIdentity;
  Eigen::Vector3d stretchShift;
  Eigen::Vector4d dual;
  bool rigid = true; ///< no stretch (Polar, DualQuaternion: log S = 0)
};

/// The probes of one execution.
struct ProbeBlendSet
{
  BlendMode mode = BlendMode::Polar;
  std::vector<BlendProbe> probes;
  bool allRigid = true; ///< no stretch exp at all (the fast path)
};

/// Why prepareProbes failed, and which probe.
struct ProbePreparation
{
  ProbeBlendSet set;
  Status status = Status::Ok;
  int failedProbe = -1;
  bool ok() const noexcept { return status == Status::Ok; }
};

/// Prepares the probes A_i with rest centres c_i. `rotationReferences` (empty, or one per probe)
/// picks each Polar rotation log nearest the reference (Kaji & Ochiai Alg. 1); without it the
/// principal log is taken. Fails on the first A_i that is not finite, not affine, not of
/// positive determinant or (MatrixLog) has no real logarithm; the status says which.
VTKLCT_EXPORT ProbePreparation prepareProbes(const std::vector<Eigen::Matrix4d>& relative,
  const std::vector<Eigen::Vector3d>& centres,
  const std::vector<Eigen::Vector3d>& rotationReferences, BlendMode mode);

/// (0, v) (x) q for a quaternion q = (w, x, y, z): the dual part 1/2 (0, t) q of a rigid map
/// without the factor 1/2, i.e. (-v . u, w v + v x u) with u = (x, y, z).
inline Eigen::Vector4d pureTimes(const Eigen::Vector3d& v, const Eigen::Vector4d& q)
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  return Eigen::Vector4d(-(v[0] * x + v[1] * y + v[2] * z), w * v[0] + (v[1] * z - v[2] * y),
    w * v[1] + (v[2] * x - v[0] * z), w * v[2] + (v[0] * y - v[1] * x));
}

/// The blended map at one point: p' = p + linearMinusIdentity (p - centre) + shift.
struct PointMap
{
  Eigen::Matrix3d linearMinusIdentity = Eigen::Matrix3d::Zero();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  Eigen::Vector3d shift = Eigen::Vector3d::Zero();

  Eigen::Vector3d apply(const Eigen::Vector3d& p) const
  {
    return p + linearMinusIdentity * (p - centre) + shift;
  }
};

/// Weights of one point over slots: probe `indices[k]` (or probe k when indices is null) has
/// weight `weights[k]`, already normalised. A weight of 0 contributes nothing.
/// Fails with NumericalFailure (DualQuaternion: the weighted rotations cancel) or OutOfRange
/// (MatrixLog: the blend overflows).
VTKLCT_EXPORT Status blendAtPoint(const ProbeBlendSet& set, const double* weights,
  const std::int32_t* indices, int slots, PointMap& map);

/// Where the weights of a batch come from.
struct WeightSource
{
  enum class Kind
  {
    InverseDistance, ///< w_i = r_i / d_i^p (Kaji's deformer; a point on a centre takes that probe)
    Cutoff,          ///< w_i = ((r_i - d_i) / r_i)^p for d_i <= r_i, else 0
    Slots            ///< per point: `slots` weights (and probe indices) from arrays
  };
  Kind kind = Kind::InverseDistance;
  WeightNormalization normalization = WeightNormalization::Linear;
  // Distance kinds: one radius per probe, and the exponent.
  const double* radii = nullptr;
  double exponent = 1.0;
  // Slots: points x slots row-major, raw (normalised per point here), double or float.
  const double* weights = nullptr;
  const float* floatWeights = nullptr;
  const std::int32_t* indices = nullptr; ///< null: slot k is probe k
  int slots = 0;
};

/// The first point of a batch that could not be deformed, and why.
struct DeformFailure
{
  Status status = Status::Ok;
  std::int64_t point = -1;
  bool ok() const noexcept { return status == Status::Ok; }
};

/// The range of a point's largest raw InverseDistance weight taken as computed; beyond it (a
/// point about 1e145 times a probe radius from every centre, or within 1e-145 of one, with
/// exponent 2) distanceWeights takes them relative to the nearest centre under Linear
/// normalisation.
constexpr double kSmallestDistanceWeight = 0x1p-960;
constexpr double kLargestDistanceWeight = 0x1p960;

/// The raw InverseDistance or Cutoff weights of point p over every probe, as deformPoints takes
/// them: r_k / d_k^p or ((r_k - d_k) / r_k)^p within r_k. Under Linear normalisation,
/// InverseDistance weights out of that range are r_k (d_min / d_k)^p instead: the same
/// normalised weights where the raw ones would all underflow to 0 (the point would stay put)
/// or sum to infinity, and their limit on a centre: that probe alone, or the probes whose
/// centres coincide there in proportion to their radii. Otherwise a point on a centre takes
/// that probe alone (weight 1; ties share equally).
VTKLCT_EXPORT void distanceWeights(
  const ProbeBlendSet& set, const WeightSource& source, const Eigen::Vector3d& p, double* w);

/// Raw weights of a point normalised as asked. Fails with InvalidArgument when Linear
/// normalisation meets a non-positive sum of weights that are not all zero, or a weight that is
/// NaN or Inf; all-zero weights come back all zero (the point stays put). Finite weights whose
/// sum overflows (1e308 twice) or whose sum's inverse does (subnormal weights) are normalised
/// by their ratios, as any other weights.
VTKLCT_EXPORT Status normalizeWeights(
  WeightNormalization normalization, double* weights, int count);

/// One 3-component array carried along: normals (cofactor, renormalised) or vectors (linear
/// part), of float or double whatever the points are.
struct CarriedVectors
{
  const void* in = nullptr;
  void* out = nullptr;
  bool isDouble = false;
  bool isNormal = true;
};

/// Vector i of a carried array transformed by the blended linear part I + d as deformPoints
/// does: normals by the cofactor (of I + d scaled to entries of at most 1, so that stretches
/// near the ends of double keep their direction), renormalised; other vectors by I + d; a point
/// at rest (d = 0) keeps its vector bit for bit. False, with nothing written, where the result
/// is not finite in double or in the array's type (a vector stretched beyond the range).
VTKLCT_EXPORT bool carryVector(const CarriedVectors& c, const Eigen::Matrix3d& d, std::int64_t i);

/// Deforms points [begin, end) of `in` (x y z interleaved) into `out`, and the carried arrays.
/// Thread-safe for disjoint ranges. Stops at the first point that cannot be deformed: NonFinite
/// (a NaN or Inf slot weight), InvalidArgument (a probe index out of range, or weights the
/// normalisation cannot divide by), NumericalFailure or OutOfRange (its result, or one of its
/// carried vectors, in double or in the array's type, is not finite); the outputs of the range
/// are then partly written and the caller discards them. Weights are checked here, in the one
/// pass over the points, not before.
template <typename Real>
DeformFailure deformPoints(const ProbeBlendSet& set, const WeightSource& source, const Real* in,
  Real* out, const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end);

extern template VTKLCT_EXPORT DeformFailure deformPoints<float>(const ProbeBlendSet&,
  const WeightSource&, const float*, float*, const CarriedVectors*, int, std::int64_t,
  std::int64_t);
extern template VTKLCT_EXPORT DeformFailure deformPoints<double>(const ProbeBlendSet&,
  const WeightSource&, const double*, double*, const CarriedVectors*, int, std::int64_t,
  std::int64_t);

} // namespace lct

#endif
