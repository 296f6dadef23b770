#include "lct/ProbeBlendBatch.h"

#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <Eigen/Geometry>

#include <cmath>

// The lane loops below are written for the auto-vectoriser; with GCC on x86-64 they are also
// compiled for x86-64-v3 (AVX2, FMA) and picked at load time where the CPU has it. Not under the
// sanitizers: the load-time choice is an ifunc resolver, which runs before ThreadSanitizer's
// runtime is up (the TSan build's unit tests crashed at start).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) &&                             \
  !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define LCT_LANES_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LCT_LANES_CLONES
#endif

namespace lct
{

namespace
{
constexpr int B = kProbeBatch;

/// Largest phi^2 = (theta / 2)^2 the polynomials cover: a turn of 2 pi.
constexpr double kMaxHalfAngle2 = 3.14159265358979323846 * 3.14159265358979323846;

using Lanes = ProbeBatchMaps;

/// sin(phi) / phi = sum (-1)^n x^n / (2n + 1)! (n <= 14) and cos(phi) = sum (-1)^n x^n / (2n)!
/// (n <= 15) for x = phi^2 <= pi^2, by Horner, one lane per point; the first omitted terms,
/// x^15 / 31! and x^16 / 32! at x = pi^2, are 1e-19 and 1e-20.
inline void sincAndCos(const double* x, double* sinc, double* cosine)
{
  static constexpr double kSin[15] = { 1.0, -0.16666666666666666, 0.008333333333333333,
    -0.0001984126984126984, 2.7557319223985893e-06, -2.505210838544172e-08, 1.6059043836821613e-10,
    -7.647163731819816e-13, 2.8114572543455206e-15, -8.22063524662433e-18, 1.9572941063391263e-20,
    -3.868170170630684e-23, 6.446950284384474e-26, -9.183689863795546e-29, 1.1309962886447716e-31 };
  static constexpr double kCos[16] = { 1.0, -0.5, 0.041666666666666664, -0.001388888888888889,
    2.48015873015873e-05, -2.755731922398589e-07, 2.08767569878681e-09, -1.1470745597729725e-11,
    4.779477332387385e-14, -1.5619206968586225e-16, 4.110317623312165e-19, -8.896791392450574e-22,
    1.6117375710961184e-24, -2.4795962632247976e-27, 3.279889237069838e-30,
    -3.7699876288159054e-33 };
  for (int j = 0; j < B; ++j)
  {
    sinc[j] = kSin[14];
    cosine[j] = kCos[15];
  }
  for (int n = 13; n >= 0; --n)
  {
    for (int j = 0; j < B; ++j)
    {
      sinc[j] = kSin[n] + x[j] * sinc[j];
    }
  }
  for (int n = 14; n >= 0; --n)
  {
    for (int j = 0; j < B; ++j)
    {
      cosine[j] = kCos[n] + x[j] * cosine[j];
    }
  }
}

/// The weights of probe k for every lane: w[k][j] (structure of arrays).
using LaneWeights = ProbeBatchWeights;

/// out[j] += w[j] * value for every lane.
inline void accumulate(double* out, const double* w, double value)
{
  for (int j = 0; j < B; ++j)
  {
    out[j] += w[j] * value;
  }
}

LCT_LANES_CLONES
void polarLanes(const ProbeBatchSet& p, const LaneWeights& w, Lanes& out)
{
  double absolute[kProbeBatchMaxProbes][B];
  for (int k = 0; k < p.probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      absolute[k][j] = std::fabs(w[k][j]);
    }
  }
  double absSum[B] = {}, cs[3][B] = {}, lin[9][B] = {}, tr[3][B] = {}, rot[3][B] = {};
  for (int k = 0; k < p.probes; ++k)
  {
    accumulate(absSum, absolute[k], 1.0);
    for (int r = 0; r < 3; ++r)
    {
      accumulate(cs[r], absolute[k], p.centre[r][k]);
      accumulate(tr[r], w[k], p.translation[r][k]);
      accumulate(rot[r], w[k], p.rotation[r][k]);
    }
    for (int e = 0; e < 9; ++e)
    {
      accumulate(lin[e], w[k], p.linearMinusIdentity[e][k]);
    }
  }
  double half2[B], clamped[B], s[B], c[B];
  for (int j = 0; j < B; ++j)
  {
    // 1 / 0 = inf for all-zero weights: fixed up per point.
    const double inverse = 1.0 / absSum[j];
    out.centre[0][j] = cs[0][j] * inverse;
    out.centre[1][j] = cs[1][j] * inverse;
    out.centre[2][j] = cs[2][j] * inverse;
    half2[j] = 0.25 * (rot[0][j] * rot[0][j] + rot[1][j] * rot[1][j] + rot[2][j] * rot[2][j]);
    clamped[j] = std::fmin(half2[j], kMaxHalfAngle2); // lanes beyond are redone per point
    out.halfAngle2[j] = half2[j];
    out.total[j] = absSum[j];
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int j = 0; j < B; ++j)
    {
      out.shift[r][j] = lin[3 * r][j] * out.centre[0][j] + lin[3 * r + 1][j] * out.centre[1][j] +
        lin[3 * r + 2][j] * out.centre[2][j] + tr[r][j];
    }
  }
  sincAndCos(clamped, s, c);
  for (int j = 0; j < B; ++j)
  {
    // R - I = sinc [w]x + b [w]x^2 in the half-angle form of lct::expSO3MinusIdentity.
    const double x = rot[0][j], y = rot[1][j], z = rot[2][j];
    const double sinc = s[j] * c[j];    // sin(theta) / theta
    const double b = 0.5 * s[j] * s[j]; // (1 - cos theta) / theta^2
    const double cosMinusOne = -2.0 * half2[j] * s[j] * s[j];
    out.d[0][j] = b * x * x + cosMinusOne;
    out.d[1][j] = b * x * y - sinc * z;
    out.d[2][j] = b * x * z + sinc * y;
    out.d[3][j] = b * x * y + sinc * z;
    out.d[4][j] = b * y * y + cosMinusOne;
    out.d[5][j] = b * y * z - sinc * x;
    out.d[6][j] = b * x * z - sinc * y;
    out.d[7][j] = b * y * z + sinc * x;
    out.d[8][j] = b * z * z + cosMinusOne;
  }
}

LCT_LANES_CLONES
void linearLanes(const ProbeBatchSet& p, const LaneWeights& w, bool sumsToOne, Lanes& out)
{
  double total[B] = {}, lin[9][B] = {}, tr[3][B] = {};
  for (int k = 0; k < p.probes; ++k)
  {
    accumulate(total, w[k], 1.0);
    for (int r = 0; r < 3; ++r)
    {
      accumulate(tr[r], w[k], p.translation[r][k]);
    }
    for (int e = 0; e < 9; ++e)
    {
      accumulate(lin[e], w[k], p.linearMinusIdentity[e][k]);
    }
  }
  for (int e = 0; e < 9; ++e)
  {
    for (int j = 0; j < B; ++j)
    {
      // sum w_i A_i p = p + sum w_i (L_i - I) p + sum w_i t_i + (sum w_i - 1) p.
      const double extra = (!sumsToOne && total[j] != 0.0) ? total[j] - 1.0 : 0.0;
      out.d[e][j] = lin[e][j] + ((e % 4 == 0) ? extra : 0.0);
    }
  }
  for (int r = 0; r < 3; ++r)
  {
    for (int j = 0; j < B; ++j)
    {
      out.shift[r][j] = tr[r][j];
      out.centre[r][j] = 0.0;
    }
  }
  for (int j = 0; j < B; ++j)
  {
    out.total[j] = total[j];
  }
}

LCT_LANES_CLONES
void dualQuaternionLanes(const ProbeBatchSet& p, const LaneWeights& w, Lanes& out)
{
  // Kavan et al.'s hemisphere check against the heaviest probe (the first of the largest |w|).
  for (int j = 0; j < B; ++j)
  {
    int pivot = -1;
    double heaviest = 0.0;
    for (int k = 0; k < p.probes; ++k)
    {
      const double a = std::fabs(w[k][j]);
      if (a > heaviest)
      {
        heaviest = a;
        pivot = k;
      }
    }
    out.pivot[j] = pivot;
  }
  double signedWeight[kProbeBatchMaxProbes][B], total[B] = {};
  for (int k = 0; k < p.probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      signedWeight[k][j] = out.pivot[j] < 0 ? 0.0 : w[k][j] * p.hemisphere[k][out.pivot[j]];
      total[j] += std::fabs(w[k][j]);
    }
  }
  double real[4][B] = {}, dual[4][B] = {};
  for (int k = 0; k < p.probes; ++k)
  {
    for (int r = 0; r < 4; ++r)
    {
      accumulate(real[r], signedWeight[k], p.quaternion[r][k]);
      accumulate(dual[r], signedWeight[k], p.dual[r][k]);
    }
  }
  for (int j = 0; j < B; ++j)
  {
    const double norm = std::sqrt(real[0][j] * real[0][j] + real[1][j] * real[1][j] +
      real[2][j] * real[2][j] + real[3][j] * real[3][j]);
    out.total[j] = norm > 1e-12 * total[j] ? total[j] : -1.0; // -1: the rotations cancel
    const double inverse = 1.0 / norm, halfInverse = 0.5 / norm;
    const double qw = real[0][j] * inverse, qx = real[1][j] * inverse, qy = real[2][j] * inverse,
                 qz = real[3][j] * inverse;
    const double ew = dual[0][j] * halfInverse, ex = dual[1][j] * halfInverse,
                 ey = dual[2][j] * halfInverse, ez = dual[3][j] * halfInverse;
    // t = 2 vec(e q*) (Kavan et al. 2008, Alg. 1).
    out.shift[0][j] = 2.0 * (qw * ex - ew * qx + (qy * ez - qz * ey));
    out.shift[1][j] = 2.0 * (qw * ey - ew * qy + (qz * ex - qx * ez));
    out.shift[2][j] = 2.0 * (qw * ez - ew * qz + (qx * ey - qy * ex));
    out.d[0][j] = -2.0 * (qy * qy + qz * qz);
    out.d[1][j] = 2.0 * (qx * qy - qw * qz);
    out.d[2][j] = 2.0 * (qx * qz + qw * qy);
    out.d[3][j] = 2.0 * (qx * qy + qw * qz);
    out.d[4][j] = -2.0 * (qx * qx + qz * qz);
    out.d[5][j] = 2.0 * (qy * qz - qw * qx);
    out.d[6][j] = 2.0 * (qx * qz - qw * qy);
    out.d[7][j] = 2.0 * (qy * qz + qw * qx);
    out.d[8][j] = -2.0 * (qx * qx + qy * qy);
    out.centre[0][j] = 0.0; // DLB commutes with rigid changes of frame
    out.centre[1][j] = 0.0;
    out.centre[2][j] = 0.0;
  }
}

/// The single probe whose weight is exactly 1 with every other 0, or -1.
int singleProbe(const double* w, int probes)
{
  int single = -1;
  for (int k = 0; k < probes; ++k)
  {
    if (w[k] != 0.0)
    {
      single = (single == -1 && w[k] == 1.0) ? k : -2;
    }
  }
  return single;
}
} // namespace

bool prepareProbeBatch(const ProbeBlendSet& set, ProbeBatchSet& batch)
{
  const int n = static_cast<int>(set.probes.size());
  const bool supported = set.mode == BlendMode::Polar || set.mode == BlendMode::Linear ||
    (set.mode == BlendMode::DualQuaternion && set.allRigid);
  if (!supported || n < 1 || n > kProbeBatchMaxProbes)
  {
    return false;
  }
  batch.probes = n;
  batch.mode = set.mode;
  batch.allRigid = set.allRigid;
  for (int k = 0; k < n; ++k)
  {
    const BlendProbe& probe = set.probes[k];
    for (int r = 0; r < 3; ++r)
    {
      batch.rotation[r][k] = rotationPart(probe.logs)[r];
      batch.translation[r][k] = probe.translation[r];
      batch.centre[r][k] = probe.centre[r];
      for (int c = 0; c < 3; ++c)
      {
        batch.linearMinusIdentity[3 * r + c][k] = probe.linearMinusIdentity(r, c);
      }
    }
    // (0, t) q: the dual part without the factor 1/2, for rigid probes about the origin.
    const Eigen::Vector4d& q = probe.quaternion;
    const Eigen::Vector3d& t = probe.translation;
    const Eigen::Vector3d u = q.tail<3>();
    const Eigen::Vector3d v = q[0] * t + t.cross(u);
    const double dual[4] = { -t.dot(u), v[0], v[1], v[2] };
    for (int r = 0; r < 4; ++r)
    {
      batch.quaternion[r][k] = q[r];
      batch.dual[r][k] = dual[r];
    }
  }
  for (int k = 0; k < n; ++k)
  {
    for (int pivot = 0; pivot < n; ++pivot)
    {
      batch.hemisphere[k][pivot] =
        set.probes[k].quaternion.dot(set.probes[pivot].quaternion) < 0.0 ? -1.0 : 1.0;
    }
  }
  return true;
}

PointMap ProbeBatchMaps::at(int j) const
{
  PointMap map;
  for (int r = 0; r < 3; ++r)
  {
    map.centre[r] = this->centre[r][j];
    map.shift[r] = this->shift[r][j];
    for (int c = 0; c < 3; ++c)
    {
      map.linearMinusIdentity(r, c) = this->d[3 * r + c][j];
    }
  }
  return map;
}

namespace
{
/// Lane j of `maps` set to `map`.
void setLane(ProbeBatchMaps& maps, int j, const PointMap& map)
{
  for (int r = 0; r < 3; ++r)
  {
    maps.centre[r][j] = map.centre[r];
    maps.shift[r][j] = map.shift[r];
    for (int c = 0; c < 3; ++c)
    {
      maps.d[3 * r + c][j] = map.linearMinusIdentity(r, c);
    }
  }
}

LCT_LANES_CLONES
void linearNormalization(int probes, double* failed, LaneWeights& w)
{
  double sum[B] = {}, nonZero[B] = {};
  for (int k = 0; k < probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      sum[j] += w[k][j];
      nonZero[j] += w[k][j] != 0.0 ? 1.0 : 0.0;
    }
  }
  double factor[B];
  for (int j = 0; j < B; ++j)
  {
    const bool any = nonZero[j] > 0.0;
    // !(sum > 0) is true for NaN; sum - sum is NaN for +-inf.
    failed[j] = any && !(sum[j] > 0.0 && sum[j] - sum[j] == 0.0) ? 1.0 : 0.0;
    // Multiplying by 1 leaves a weight bit for bit, as skipping the division does.
    factor[j] = (any && sum[j] != 1.0) ? 1.0 / sum[j] : 1.0;
  }
  for (int k = 0; k < probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      w[k][j] *= factor[j];
    }
  }
}

LCT_LANES_CLONES
void applyLanes(const ProbeBatchMaps& m, const double (&p)[3][B], double (&q)[3][B])
{
  for (int j = 0; j < B; ++j)
  {
    const double x = p[0][j] - m.centre[0][j], y = p[1][j] - m.centre[1][j],
                 z = p[2][j] - m.centre[2][j];
    q[0][j] = p[0][j] + (m.d[0][j] * x + m.d[1][j] * y + m.d[2][j] * z) + m.shift[0][j];
    q[1][j] = p[1][j] + (m.d[3][j] * x + m.d[4][j] * y + m.d[5][j] * z) + m.shift[1][j];
    q[2][j] = p[2][j] + (m.d[6][j] * x + m.d[7][j] * y + m.d[8][j] * z) + m.shift[2][j];
  }
}
} // namespace

int normalizeBatch(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights)
{
  switch (normalization)
  {
    case WeightNormalization::None:
      return -1;
    case WeightNormalization::Linear:
    {
      double failed[B];
      linearNormalization(probes, failed, weights);
      for (int j = 0; j < count; ++j)
      {
        if (failed[j] != 0.0)
        {
          return j;
        }
      }
      return -1;
    }
    case WeightNormalization::Softmax:
      break;
  }
  for (int j = 0; j < count; ++j)
  {
    double row[kProbeBatchMaxProbes];
    for (int k = 0; k < probes; ++k)
    {
      row[k] = weights[k][j];
    }
    if (normalizeWeights(normalization, row, probes) != Status::Ok)
    {
      return j;
    }
    for (int k = 0; k < probes; ++k)
    {
      weights[k][j] = row[k];
    }
  }
  return -1;
}

void applyBatch(
  const ProbeBatchMaps& maps, const double (&p)[3][kProbeBatch], double (&q)[3][kProbeBatch])
{
  applyLanes(maps, p, q);
}

int blendBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& lanes)
{
  const int n = batch.probes;
  const LaneWeights& w = weights;
  switch (batch.mode)
  {
    case BlendMode::Polar:
      polarLanes(batch, w, lanes);
      break;
    case BlendMode::Linear:
      linearLanes(batch, w, sumsToOne, lanes);
      break;
    default:
      dualQuaternionLanes(batch, w, lanes);
      break;
  }
  for (int j = 0; j < count; ++j)
  {
    double pw[kProbeBatchMaxProbes];
    for (int k = 0; k < n; ++k)
    {
      pw[k] = w[k][j];
    }
    const int single = singleProbe(pw, n);
    if (single >= 0)
    {
      // Exactly that probe (exp(psi(A)) = A), as lct::blendAtPoint takes it.
      PointMap map;
      map.linearMinusIdentity = set.probes[single].linearMinusIdentity;
      map.shift = set.probes[single].translation;
      setLane(lanes, j, map);
      continue;
    }
    if (single == -1)
    {
      setLane(lanes, j, PointMap()); // all weights 0: the point stays put
      continue;
    }
    if (batch.mode == BlendMode::DualQuaternion && lanes.total[j] < 0.0)
    {
      return j;
    }
    if (batch.mode != BlendMode::Polar || (lanes.halfAngle2[j] < kMaxHalfAngle2 && batch.allRigid))
    {
      continue;
    }
    PointMap map = lanes.at(j);
    if (!(lanes.halfAngle2[j] < kMaxHalfAngle2))
    {
      // A blended turn beyond 2 pi (or not finite): the library's own exp.
      Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
      for (int k = 0; k < n; ++k)
      {
        rotation += pw[k] * rotationPart(set.probes[k].logs);
      }
      map.linearMinusIdentity = expSO3MinusIdentity(rotation);
    }
    if (!batch.allRigid)
    {
      SymmetricVector stretch = SymmetricVector::Zero();
      for (int k = 0; k < n; ++k)
      {
        if (pw[k] != 0.0)
        {
          stretch += pw[k] * symmetricPart(set.probes[k].logs);
        }
      }
      if (!stretch.isZero(0.0))
      {
        // (R - I) S + (S - I) = R S - I.
        const Eigen::Matrix3d s = expSym(fromSymmetricVector(stretch));
        Eigen::Matrix3d d = map.linearMinusIdentity * s + s;
        d.diagonal().array() -= 1.0;
        map.linearMinusIdentity = d;
      }
    }
    setLane(lanes, j, map);
  }
  return -1;
}

} // namespace lct
