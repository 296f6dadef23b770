#include "lct/ProbeBlend.h"

#include "lct/Affine.h"
#include "lct/Conditioning.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/PolarParametrisation.h"
#include "lct/ProbeBlendBatch.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace lct
{

namespace
{

/// A stretch log below this (largest entry) counts as none: the polar factor of a rotation
/// matrix built in double carries a stretch log of a few ulps, and skipping exp of it moves a
/// point by less than that.
constexpr double kRigidStretchTolerance = 64.0 * std::numeric_limits<double>::epsilon();

/// |q|^2 (R - I) of a quaternion q = (w, x, y, z): R - I itself for a unit one.
Eigen::Matrix3d quaternionMinusIdentity(const Eigen::Vector4d& q)
{
  const double w = q[0], x = q[1], y = q[2], z = q[3];
  Eigen::Matrix3d d;
  d << -2.0 * (y * y + z * z), 2.0 * (x * y - w * z), 2.0 * (x * z + w * y), //
    2.0 * (x * y + w * z), -2.0 * (x * x + z * z), 2.0 * (y * z - w * x),    //
    2.0 * (x * z - w * y), 2.0 * (y * z + w * x), -2.0 * (x * x + y * y);
  return d;
}

/// (R - I) S + (S - I) = R S - I for the blended rotation and the stretch S = I + E.
Eigen::Matrix3d withStretchMinusIdentity(
  const Eigen::Matrix3d& rotationMinusIdentity, const Eigen::Matrix3d& e)
{
  return rotationMinusIdentity + rotationMinusIdentity * e + e;
}

/// R S - I for the blended rotation and the stretch S = exp(Y).
Eigen::Matrix3d withStretch(const Eigen::Matrix3d& rotationMinusIdentity, const SymmetricVector& y)
{
  const Eigen::Matrix3d s = expSym(fromSymmetricVector(y));
  Eigen::Matrix3d d = rotationMinusIdentity * s + s;
  d.diagonal().array() -= 1.0;
  return d;
}

/// The point's blend centre c(p) = sum |w_i| c_i / sum |w_i|; false when every weight is 0.
bool weightedCentre(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, Eigen::Vector3d& centre)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  double total = 0.0;
  for (int k = 0; k < slots; ++k)
  {
    const double a = std::abs(weights[k]);
    if (a != 0.0)
    {
      sum += a * set.probes[indices ? indices[k] : k].centre;
      total += a;
    }
  }
  if (total == 0.0)
  {
    return false;
  }
  centre = sum / total;
  return true;
}

Status polarBlend(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, PointMap& map)
{
  // One pass over the slots gathers the centre and every sum (the per-point hot loop).
  Eigen::Vector3d centreSum = Eigen::Vector3d::Zero();
  double absoluteSum = 0.0;
  Eigen::Vector3d translationSum = Eigen::Vector3d::Zero();
  Eigen::Matrix3d linearSum = Eigen::Matrix3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
  SymmetricVector stretch = SymmetricVector::Zero();
  for (int k = 0; k < slots; ++k)
  {
    const double w = weights[k];
    if (w == 0.0)
    {
      continue;
    }
    const BlendProbe& probe = set.probes[indices ? indices[k] : k];
    const double a = std::abs(w);
    centreSum += a * probe.centre;
    absoluteSum += a;
    linearSum += w * probe.linearMinusIdentity;
    translationSum += w * probe.translation;
    rotation += w * rotationPart(probe.logs);
    if (!set.allRigid)
    {
      stretch += w * symmetricPart(probe.logs);
    }
  }
  if (absoluteSum == 0.0)
  {
    return Status::Ok;
  }
  map.centre = centreSum / absoluteSum;
  // psi(T(-c) A_i T(c)) = (A_i c - c, w_i, Y_i): only the translation depends on the centre,
  // linearly, so its blend is (sum w_i (L_i - I)) c + sum w_i t_i.
  map.shift = linearSum * map.centre + translationSum;
  // Unnormalised weights can wind the blended turn beyond what double resolves (sin of 1e100
  // radians is any value).
  const double turn = rotation.norm();
  if (!std::isfinite(turn))
  {
    return Status::OutOfRange;
  }
  if (turn > kMaxRotationWinding)
  {
    return Status::InaccurateResult;
  }
  const Eigen::Matrix3d rotationMinusIdentity = expSO3MinusIdentity(rotation);
  map.linearMinusIdentity = (set.allRigid || stretch.isZero(0.0))
    ? rotationMinusIdentity
    : withStretch(rotationMinusIdentity, stretch);
  return Status::Ok;
}

Status matrixLogBlend(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, PointMap& map)
{
  LogCoords sum = LogCoords::Zero();
  for (int k = 0; k < slots; ++k)
  {
    if (weights[k] != 0.0)
    {
      sum += weights[k] * set.probes[indices ? indices[k] : k].logs;
    }
  }
  if (sum.isZero(0.0))
  {
    return Status::Ok;
  }
  // log(T(-c) A T(c)) = T(-c) log(A) T(c) = [X, u + X c; 0 0].
  translationPart(sum) += logLinearPart(sum) * map.centre;
  const Result<Eigen::Matrix4d> m = matrixExp(sum);
  if (!m.ok())
  {
    return m.status;
  }
  map.linearMinusIdentity = m.value.topLeftCorner<3, 3>();
  map.linearMinusIdentity.diagonal().array() -= 1.0;
  map.shift = m.value.topRightCorner<3, 1>();
  return Status::Ok;
}

Status linearBlend(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, bool weightsSumToOne, PointMap& map)
{
  double total = 0.0;
  for (int k = 0; k < slots; ++k)
  {
    const double w = weights[k];
    if (w == 0.0)
    {
      continue;
    }
    const BlendProbe& probe = set.probes[indices ? indices[k] : k];
    map.linearMinusIdentity += w * probe.linearMinusIdentity;
    map.shift += w * probe.translation;
    total += w;
  }
  // sum w_i A_i p = p + sum w_i (L_i - I) p + sum w_i t_i + (sum w_i - 1) p.
  if (!weightsSumToOne && total != 0.0)
  {
    map.linearMinusIdentity.diagonal().array() += total - 1.0;
  }
  map.centre.setZero();
  return Status::Ok;
}

Status dualQuaternionBlend(const ProbeBlendSet& set, const double* weights,
  const std::int32_t* indices, int slots, PointMap& map)
{
  // Kavan et al.'s hemisphere check: every rotation on the side of the heaviest one.
  int pivot = -1;
  double heaviest = 0.0;
  for (int k = 0; k < slots; ++k)
  {
    if (std::abs(weights[k]) > heaviest)
    {
      heaviest = std::abs(weights[k]);
      pivot = indices ? indices[k] : k;
    }
  }
  if (pivot < 0)
  {
    return Status::Ok;
  }
  if (!std::isfinite(heaviest))
  {
    return Status::NonFinite;
  }
  // The blend depends on the ratios of the weights only, but |sum w q|^2 leaves double's range
  // for weights beyond 2^+-480 (possible without normalisation): those are scaled by a power of
  // two, which changes no bit of the blend.
  const int exponent = heaviest > 0x1p-480 && heaviest < 0x1p480 ? 0 : -std::ilogb(heaviest);
  // Kavan et al.'s two phases, A_k = [U_k | t'_k] T(c_k) S_k T(-c_k): the stretches about their
  // probes' centres blended linearly, then the rigid parts by DLB. Both commute with translating
  // the scene, so no per-point centre is needed.
  map.centre.setZero();
  const Eigen::Vector4d& reference = set.probes[pivot].quaternion;
  Eigen::Vector4d real = Eigen::Vector4d::Zero();
  Eigen::Vector4d dual = Eigen::Vector4d::Zero();
  SymmetricVector stretch = SymmetricVector::Zero();
  Eigen::Vector3d stretchShift = Eigen::Vector3d::Zero();
  double total = 0.0, sum = 0.0;
  for (int k = 0; k < slots; ++k)
  {
    double w = exponent == 0 ? weights[k] : std::ldexp(weights[k], exponent);
    if (w == 0.0)
    {
      continue;
    }
    total += std::abs(w);
    sum += w;
    const BlendProbe& probe = set.probes[indices ? indices[k] : k];
    if (!set.allRigid)
    {
      stretch += w * probe.stretchMinusIdentity;
      stretchShift += w * probe.stretchShift;
    }
    if (probe.quaternion.dot(reference) < 0.0)
    {
      w = -w;
    }
    real += w * probe.quaternion;
    dual += w * probe.dual;
  }
  const double norm2 = real.squaredNorm(), least = 1e-12 * total; // |real| > least, squared
  if (!(norm2 > least * least))
  {
    return Status::NumericalFailure;
  }
  // No square root: with q = real / |real| and e = dual / (2 |real|), t = 2 vec(e q*) (Kavan et
  // al. 2008, Alg. 1; the part of e along q drops out) and every entry of R - I are products of
  // two of real's and dual's components over |real|^2.
  const double inverse2 = 1.0 / norm2;
  const Eigen::Vector3d u = real.tail<3>(), v = dual.tail<3>();
  map.shift = inverse2 * (real[0] * v - dual[0] * u + u.cross(v));
  const Eigen::Matrix3d rotationMinusIdentity = quaternionMinusIdentity(real) * inverse2;
  if (set.allRigid || (stretch.isZero(0.0) && stretchShift.isZero(0.0)))
  {
    map.linearMinusIdentity = rotationMinusIdentity;
    return Status::Ok;
  }
  // The stretch phase p -> S p + g with S - I = sum w_k (S_k - I) / sum w_k and
  // g = -sum w_k (S_k - I) c_k / sum w_k, weighted as DLB weighs the rotations (a rigid blend stays
  // rigid whatever the weights sum to); a sum of weights that cancels (negative weights, no
  // normalisation) has no stretch.
  if (!(std::abs(sum) > 1e-12 * total))
  {
    return Status::NumericalFailure;
  }
  const double inverseSum = 1.0 / sum;
  const Eigen::Vector3d g = stretchShift * (-inverseSum);
  map.linearMinusIdentity =
    withStretchMinusIdentity(rotationMinusIdentity, fromSymmetricVector(stretch * inverseSum));
  map.shift += g + rotationMinusIdentity * g;
  return Status::Ok;
}

Status blend(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, bool weightsSumToOne, PointMap& map)
{
  map = PointMap();
  // A single weight of exactly 1: every blend is that probe itself (exp(psi(A)) = A), taken
  // from its matrix without an exp. Whole regions of skinned meshes are bound to one bone.
  int single = -1;
  for (int k = 0; k < slots; ++k)
  {
    if (weights[k] != 0.0)
    {
      single = (single == -1 && weights[k] == 1.0) ? k : -2;
    }
  }
  if (single >= 0)
  {
    const BlendProbe& probe = set.probes[indices ? indices[single] : single];
    map.linearMinusIdentity = probe.linearMinusIdentity;
    map.shift = probe.translation;
    return Status::Ok;
  }
  if (set.mode != BlendMode::Linear && set.mode != BlendMode::Polar &&
    !weightedCentre(set, weights, indices, slots, map.centre))
  {
    return Status::Ok;
  }
  switch (set.mode)
  {
    case BlendMode::Polar:
      return polarBlend(set, weights, indices, slots, map);
    case BlendMode::MatrixLog:
      return matrixLogBlend(set, weights, indices, slots, map);
    case BlendMode::Linear:
      return linearBlend(set, weights, indices, slots, weightsSumToOne, map);
    case BlendMode::DualQuaternion:
      return dualQuaternionBlend(set, weights, indices, slots, map);
  }
  return Status::InvalidArgument;
}

bool allFinite(const PointMap& map)
{
  return map.linearMinusIdentity.allFinite() && map.shift.allFinite() && map.centre.allFinite();
}

template <typename Real>
bool carryTyped(const Real* in, Real* out, bool isNormal, const Eigen::Matrix3d& d, std::int64_t i)
{
  const Eigen::Vector3d v(static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
    static_cast<double>(in[3 * i + 2]));
  Eigen::Vector3d r;
  if (d.isZero(0.0))
  {
    // A point at rest keeps its vectors bit for bit (renormalising would round them).
    r = v;
  }
  else if (isNormal)
  {
    // cof(M) = det(M) M^-T: rows r1 x r2, r2 x r0, r0 x r1 of M = I + D, of M scaled to
    // entries of at most 1 (cof(s M) = s^2 cof(M) points the same way; the cofactor of a
    // stretch of 1e160 would leave double and the normal come out 0 or NaN).
    Eigen::Matrix3d m = d;
    m.diagonal().array() += 1.0;
    const double largest = m.cwiseAbs().maxCoeff();
    if (largest > 0.0 && std::isfinite(largest))
    {
      m /= largest;
    }
    const Eigen::Vector3d r0 = m.row(0), r1 = m.row(1), r2 = m.row(2);
    r = Eigen::Vector3d(r1.cross(r2).dot(v), r2.cross(r0).dot(v), r0.cross(r1).dot(v));
    const double norm = r.stableNorm();
    if (norm > 0.0)
    {
      r /= norm;
    }
  }
  else
  {
    r = v + d * v;
  }
  // A vector stretched beyond double (or, for float arrays, beyond float) is not written.
  if (!r.allFinite() ||
    !(r.cwiseAbs().maxCoeff() <= static_cast<double>(std::numeric_limits<Real>::max())))
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    out[3 * i + k] = static_cast<Real>(r[k]);
  }
  return true;
}

} // namespace

bool carryVector(const CarriedVectors& c, const Eigen::Matrix3d& d, std::int64_t i)
{
  return c.isDouble
    ? carryTyped(static_cast<const double*>(c.in), static_cast<double*>(c.out), c.isNormal, d, i)
    : carryTyped(static_cast<const float*>(c.in), static_cast<float*>(c.out), c.isNormal, d, i);
}

ProbePreparation prepareProbes(const std::vector<Eigen::Matrix4d>& relative,
  const std::vector<Eigen::Vector3d>& centres,
  const std::vector<Eigen::Vector3d>& rotationReferences, BlendMode mode)
{
  ProbePreparation result;
  const auto fail = [&result](Status why, int probe) {
    result.status = why;
    result.failedProbe = probe;
    result.set.probes.clear();
    return result;
  };
  if (centres.size() != relative.size() ||
    (!rotationReferences.empty() && rotationReferences.size() != relative.size()))
  {
    return fail(Status::InvalidArgument, -1);
  }
  result.set.mode = mode;
  result.set.probes.resize(relative.size());
  for (std::size_t i = 0; i < relative.size(); ++i)
  {
    const Eigen::Matrix4d& a = relative[i];
    const int index = static_cast<int>(i);
    const Status valid = validateAffine(a);
    if (valid != Status::Ok)
    {
      return fail(valid, index);
    }
    if (!centres[i].allFinite())
    {
      return fail(Status::NonFinite, index);
    }
    BlendProbe& probe = result.set.probes[i];
    probe.linearMinusIdentity = a.topLeftCorner<3, 3>();
    probe.linearMinusIdentity.diagonal().array() -= 1.0;
    probe.translation = a.topRightCorner<3, 1>();
    probe.centre = centres[i];
    probe.logs.setZero();
    probe.stretchMinusIdentity.setZero();
    probe.stretchShift.setZero();
    probe.dual.setZero();
    switch (mode)
    {
      case BlendMode::Polar:
      case BlendMode::DualQuaternion:
      {
        const Eigen::Vector3d* reference = (mode == BlendMode::Polar && !rotationReferences.empty())
          ? &rotationReferences[i]
          : nullptr;
        const Result<LogCoords> logs = polarLog(a, reference);
        if (!logs.ok())
        {
          return fail(logs.status, index);
        }
        probe.logs = logs.value;
        if (symmetricPart(probe.logs).cwiseAbs().maxCoeff() <= kRigidStretchTolerance)
        {
          symmetricPart(probe.logs).setZero();
        }
        else
        {
          probe.rigid = false;
        }
        const Eigen::Matrix3d u = expSO3(rotationPart(probe.logs));
        const Eigen::Quaterniond q(u);
        probe.quaternion = Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
        if (mode == BlendMode::DualQuaternion)
        {
          // Kavan et al.'s two phases: A = [U | t'] T(c) S T(-c) with t' = t + (L - U) c; the
          // dual part (0, t') q (without the factor 1/2).
          Eigen::Vector3d rigidTranslation = probe.translation;
          if (!probe.rigid)
          {
            Eigen::Matrix3d e = expSym(fromSymmetricVector(symmetricPart(probe.logs)));
            e.diagonal().array() -= 1.0;
            probe.stretchMinusIdentity = toSymmetricVector(e);
            probe.stretchShift = e * probe.centre;
            rigidTranslation += (a.topLeftCorner<3, 3>() - u) * probe.centre;
          }
          probe.dual = pureTimes(rigidTranslation, probe.quaternion);
        }
        break;
      }
      case BlendMode::MatrixLog:
      {
        const Result<LogCoords> logs = matrixLog(a);
        if (!logs.ok())
        {
          return fail(logs.status, index);
        }
        probe.logs = logs.value;
        probe.rigid = false;
        break;
      }
      case BlendMode::Linear:
        probe.rigid = false;
        break;
    }
    result.set.allRigid = result.set.allRigid && probe.rigid;
  }
  return result;
}

Status blendAtPoint(const ProbeBlendSet& set, const double* weights, const std::int32_t* indices,
  int slots, PointMap& map)
{
  const Status s = blend(set, weights, indices, slots, true, map);
  if (s != Status::Ok)
  {
    return s;
  }
  return allFinite(map) ? Status::Ok : Status::OutOfRange;
}

void distanceWeights(
  const ProbeBlendSet& set, const WeightSource& source, const Eigen::Vector3d& p, double* w)
{
  const int n = static_cast<int>(set.probes.size());
  const bool squared = source.exponent == 2.0;
  const bool unit = source.exponent == 1.0;
  const bool inverse = source.kind == WeightSource::Kind::InverseDistance;
  bool onCentre = false, beyondSquares = false;
  double largest = 0.0;
  for (int i = 0; i < n; ++i)
  {
    const double d2 = (p - set.probes[i].centre).squaredNorm();
    const double r = source.radii[i];
    if (inverse)
    {
      const double dp = squared ? d2 : unit ? std::sqrt(d2) : std::pow(d2, 0.5 * source.exponent);
      w[i] = r / dp;
      onCentre = onCentre || std::isinf(w[i]);
      beyondSquares = beyondSquares || std::isinf(d2);
      largest = std::max(largest, w[i]);
    }
    else
    {
      const double d = std::sqrt(d2);
      const double x = d <= r ? (r - d) / r : 0.0;
      w[i] = squared ? x * x : unit ? x : std::pow(x, source.exponent);
    }
  }
  if (inverse && source.normalization == WeightNormalization::Linear &&
    (onCentre || beyondSquares || largest < kSmallestDistanceWeight ||
      largest > kLargestDistanceWeight))
  {
    // Linear normalisation needs only the weights' ratios, so where r / d^p leaves the double
    // range they are taken relative to the nearest centre, r (d_min / d)^p, with d measured
    // without squaring: far from every centre they would underflow to 0 (or d^2 overflow) and
    // the point stay put; next to a centre two of them would sum to infinity; on a centre the
    // limit is that probe alone, or centres that coincide there shared as r_k / sum r.
    double nearest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < n; ++i)
    {
      w[i] = (p - set.probes[i].centre).stableNorm();
      nearest = std::min(nearest, w[i]);
    }
    for (int i = 0; i < n; ++i)
    {
      const double ratio = nearest == 0.0 ? (w[i] == 0.0 ? 1.0 : 0.0) : nearest / w[i];
      w[i] = source.radii[i] *
        (squared   ? ratio * ratio
            : unit ? ratio
                   : std::pow(ratio, source.exponent));
    }
    return;
  }
  if (onCentre)
  {
    // The limit of r / d^p as the point reaches a centre: that probe alone (ties share).
    for (int i = 0; i < n; ++i)
    {
      w[i] = std::isinf(w[i]) ? 1.0 : 0.0;
    }
  }
}

Status normalizeWeights(WeightNormalization normalization, double* weights, int count)
{
  switch (normalization)
  {
    case WeightNormalization::None:
      return Status::Ok;
    case WeightNormalization::Linear:
    {
      double sum = 0.0;
      bool anyNonZero = false;
      for (int k = 0; k < count; ++k)
      {
        sum += weights[k];
        anyNonZero = anyNonZero || weights[k] != 0.0;
      }
      if (!anyNonZero)
      {
        return Status::Ok;
      }
      const double inverse = 1.0 / sum;
      if (sum > 0.0 && std::isfinite(sum) && std::isfinite(inverse))
      {
        if (sum != 1.0)
        {
          for (int k = 0; k < count; ++k)
          {
            weights[k] *= inverse;
          }
        }
        return Status::Ok;
      }
      // A sum that overflows (two weights of 1e308) or whose inverse does (subnormal weights):
      // the same ratios with the weights scaled by a power of two (exact) so the largest is
      // in [1/2, 1). NaN weights fail here too.
      double largest = 0.0;
      for (int k = 0; k < count; ++k)
      {
        largest = std::max(largest, std::abs(weights[k]));
      }
      if (!std::isfinite(largest) || std::isnan(sum))
      {
        return Status::InvalidArgument;
      }
      int exponent = 0;
      std::frexp(largest, &exponent);
      double scaledSum = 0.0;
      for (int k = 0; k < count; ++k)
      {
        scaledSum += std::ldexp(weights[k], -exponent);
      }
      if (!(scaledSum > 0.0))
      {
        return Status::InvalidArgument;
      }
      for (int k = 0; k < count; ++k)
      {
        weights[k] = std::ldexp(weights[k], -exponent) / scaledSum;
      }
      return Status::Ok;
    }
    case WeightNormalization::Softmax:
    {
      if (count == 0)
      {
        return Status::Ok;
      }
      const double top = *std::max_element(weights, weights + count);
      if (!std::isfinite(top))
      {
        return Status::InvalidArgument;
      }
      double sum = 0.0;
      for (int k = 0; k < count; ++k)
      {
        weights[k] = std::exp(weights[k] - top);
        sum += weights[k];
      }
      const double inverse = 1.0 / sum;
      for (int k = 0; k < count; ++k)
      {
        weights[k] *= inverse;
      }
      return Status::Ok;
    }
  }
  return Status::InvalidArgument;
}

namespace
{
/// q = map(p) of point i into `out`, and the carried vectors; fails (nothing more written) when
/// q is not finite in double or in Real.
template <typename Real>
bool storePoint(const PointMap& map, const Eigen::Vector3d& p, Real* out,
  const CarriedVectors* carried, int carriedCount, std::int64_t i)
{
  const Eigen::Vector3d q = map.apply(p);
  // Finite in double and in Real (a float output can overflow where the double did not).
  // A non-finite map makes q non-finite too (NaN * 0 is NaN), so q alone is checked.
  if (!q.allFinite() ||
    !(q.cwiseAbs().maxCoeff() <= static_cast<double>(std::numeric_limits<Real>::max())))
  {
    return false;
  }
  for (int k = 0; k < 3; ++k)
  {
    out[3 * i + k] = static_cast<Real>(q[k]);
  }
  for (int c = 0; c < carriedCount; ++c)
  {
    if (!carryVector(carried[c], map.linearMinusIdentity, i))
    {
      return false;
    }
  }
  return true;
}

} // namespace

template <typename Real>
DeformFailure deformPoints(const ProbeBlendSet& set, const WeightSource& source, const Real* in,
  Real* out, const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end)
{
  const bool fromSlots = source.kind == WeightSource::Kind::Slots;
  ProbeBatchSet batch;
  const bool batchable = fromSlots ? !source.indices &&
      source.slots == static_cast<int>(set.probes.size()) && (source.weights || source.floatWeights)
                                   : source.radii != nullptr;
  if (batchable && prepareProbeBatch(set, batch))
  {
    return deformBatch(set, batch, source, in, out, std::is_same<Real, double>::value, carried,
      carriedCount, begin, end);
  }
  if (fromSlots &&
    (source.slots <= 0 || !(source.weights || source.floatWeights) ||
      (!source.indices && source.slots > static_cast<int>(set.probes.size()))))
  {
    return { Status::InvalidArgument, begin };
  }
  const int slots = fromSlots ? source.slots : static_cast<int>(set.probes.size());
  const std::int32_t* noIndices = nullptr;
  // One scratch row per call (per thread range), none per point.
  std::vector<double> weights(static_cast<std::size_t>(slots));
  // Skinned meshes repeat weight rows (whole regions bound to one bone): a point whose raw
  // weights and indices equal the previous point's reuses its map, bit for bit the same.
  std::vector<double> previousRaw(static_cast<std::size_t>(slots));
  const std::int32_t* previousIndices = nullptr;
  bool havePrevious = false;
  const bool sumsToOne = source.normalization != WeightNormalization::None;
  PointMap map;
  for (std::int64_t i = begin; i < end; ++i)
  {
    const Eigen::Vector3d p(static_cast<double>(in[3 * i]), static_cast<double>(in[3 * i + 1]),
      static_cast<double>(in[3 * i + 2]));
    const std::int32_t* indices = noIndices;
    bool reuse = false;
    if (fromSlots)
    {
      bool finite = true;
      bool same = havePrevious;
      for (int k = 0; k < slots; ++k)
      {
        const double w = source.floatWeights
          ? static_cast<double>(source.floatWeights[i * slots + k])
          : source.weights[i * slots + k];
        weights[k] = w;
        finite = finite && std::isfinite(w);
        same = same && w == previousRaw[k];
      }
      if (source.indices && same)
      {
        same = std::equal(previousIndices, previousIndices + slots, source.indices + i * slots);
      }
      reuse = same;
      if (!finite)
      {
        return { Status::NonFinite, i };
      }
      if (source.indices)
      {
        indices = source.indices + i * slots;
        for (int k = 0; k < slots; ++k)
        {
          if (indices[k] < 0 || indices[k] >= static_cast<std::int32_t>(set.probes.size()))
          {
            return { Status::InvalidArgument, i };
          }
        }
      }
    }
    else
    {
      distanceWeights(set, source, p, weights.data());
    }
    if (!reuse)
    {
      if (fromSlots)
      {
        std::copy(weights.begin(), weights.end(), previousRaw.begin());
        previousIndices = indices;
        havePrevious = true;
      }
      if (normalizeWeights(source.normalization, weights.data(), slots) != Status::Ok)
      {
        return { Status::InvalidArgument, i };
      }
      const Status s = blend(set, weights.data(), indices, slots, sumsToOne, map);
      if (s != Status::Ok)
      {
        return { s, i };
      }
    }
    if (!storePoint(map, p, out, carried, carriedCount, i))
    {
      return { Status::OutOfRange, i };
    }
  }
  return {};
}

template VTKLCT_EXPORT DeformFailure deformPoints<float>(const ProbeBlendSet&, const WeightSource&,
  const float*, float*, const CarriedVectors*, int, std::int64_t, std::int64_t);
template VTKLCT_EXPORT DeformFailure deformPoints<double>(const ProbeBlendSet&, const WeightSource&,
  const double*, double*, const CarriedVectors*, int, std::int64_t, std::int64_t);

} // namespace lct
