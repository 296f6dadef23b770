#include "lct/ProbeBlendBatch.h"

#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#if !defined(__GNUC__)
#error "lct/ProbeBlendBatch.cxx needs GCC or Clang vector extensions"
#endif

// The lanes are GCC/Clang vector types; with GCC on x86-64 the functions below are also compiled
// for x86-64-v3 (AVX2, FMA) and picked at load time where the CPU has it. Not under the
// sanitizers: the load-time choice is an ifunc resolver, which runs before ThreadSanitizer's
// runtime is up (the TSan build's unit tests crashed at start).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) &&                             \
  !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define LCT_LANES_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define LCT_LANES_CLONES
#endif

// Every lane helper is inlined into the functions above, so that it runs in the chosen clone's
// instruction set (a helper left out of line would be compiled for the default target only).
#define LCT_LANE inline __attribute__((always_inline))

// The helpers pass 32-byte vectors by value; they are all inlined (no ABI between them).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace lct
{

namespace
{
constexpr int B = kProbeBatch;
constexpr int kMaxProbes = kProbeBatchMaxProbes;
static_assert(B == 4, "the lanes are one vector of four doubles");

// One point per lane. Every operation acts on all lanes alike, so a lane's result does not
// depend on the other lanes or on where a block starts.
typedef double Vec __attribute__((vector_size(4 * sizeof(double))));
typedef std::int64_t Mask __attribute__((vector_size(4 * sizeof(std::int64_t))));

LCT_LANE Vec splat(double x)
{
  return Vec{ x, x, x, x };
}
LCT_LANE Mask splatMask(std::int64_t x)
{
  return Mask{ x, x, x, x };
}
LCT_LANE Mask lessThan(Vec a, Vec b)
{
  return (Mask)(a < b);
}
LCT_LANE Mask lessEqual(Vec a, Vec b)
{
  return (Mask)(a <= b);
}
LCT_LANE Mask equal(Vec a, Vec b)
{
  return (Mask)(a == b);
}
LCT_LANE Vec select(Mask m, Vec a, Vec b)
{
  return (Vec)((m & (Mask)a) | (~m & (Mask)b));
}
LCT_LANE Vec absolute(Vec a)
{
  return (Vec)((Mask)a & splatMask(std::numeric_limits<std::int64_t>::max()));
}
LCT_LANE bool anyLane(Mask m)
{
  return (m[0] | m[1] | m[2] | m[3]) != 0;
}
/// Where |a| <= limit (false for NaN and for infinities beyond the limit).
LCT_LANE Mask boundedBy(Vec a, double limit)
{
  return lessEqual(absolute(a), splat(limit));
}

/// Largest phi^2 = (theta / 2)^2 the polynomials cover: a turn of 2 pi.
constexpr double kMaxHalfAngle2 = 3.14159265358979323846 * 3.14159265358979323846;

/// Largest squared Frobenius norm of a blended stretch log taken in lanes (||Y|| <= 16, a
/// stretch by up to e^16); beyond it the lane takes lct::blendAtPoint.
constexpr double kMaxStretchNorm2 = 256.0;

/// The maps of a block: p' = p + d (p - centre) + shift, d row-major.
struct LaneMaps
{
  Vec d[9];
  Vec shift[3];
  Vec centre[3];
};

/// Per-lane outcomes of a block.
struct LaneFlags
{
  Mask nonFinite = splatMask(0); ///< a NaN or Inf weight
  Mask invalid = splatMask(0);   ///< weights the normalisation cannot divide by
  Mask cancel = splatMask(0);    ///< DualQuaternion: the weighted rotations cancel
  Mask redo = splatMask(0);      ///< beyond the lanes' range: lct::blendAtPoint
};

/// sin(phi) / phi = sum (-1)^n x^n / (2n + 1)! (n <= 14) and cos(phi) = sum (-1)^n x^n / (2n)!
/// (n <= 15) for x = phi^2 <= pi^2; the first omitted terms, x^15 / 31! and x^16 / 32! at
/// x = pi^2, are 1e-19 and 1e-20. Estrin's scheme (pairs, then powers x^2, x^4, x^8): a chain of
/// four multiply-adds instead of Horner's fifteen, which the lanes would wait on.
LCT_LANE void sincAndCos(Vec x, Vec& sinc, Vec& cosine)
{
  static constexpr double kSin[16] = { 1.0, -0.16666666666666666, 0.008333333333333333,
    -0.0001984126984126984, 2.7557319223985893e-06, -2.505210838544172e-08, 1.6059043836821613e-10,
    -7.647163731819816e-13, 2.8114572543455206e-15, -8.22063524662433e-18, 1.9572941063391263e-20,
    -3.868170170630684e-23, 6.446950284384474e-26, -9.183689863795546e-29, 1.1309962886447716e-31,
    0.0 };
  static constexpr double kCos[16] = { 1.0, -0.5, 0.041666666666666664, -0.001388888888888889,
    2.48015873015873e-05, -2.755731922398589e-07, 2.08767569878681e-09, -1.1470745597729725e-11,
    4.779477332387385e-14, -1.5619206968586225e-16, 4.110317623312165e-19, -8.896791392450574e-22,
    1.6117375710961184e-24, -2.4795962632247976e-27, 3.279889237069838e-30,
    -3.7699876288159054e-33 };
  const Vec x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
  const auto estrin = [&](const double (&c)[16]) {
    Vec pair[8];
    for (int i = 0; i < 8; ++i)
    {
      pair[i] = c[2 * i] + c[2 * i + 1] * x;
    }
    Vec quad[4];
    for (int i = 0; i < 4; ++i)
    {
      quad[i] = pair[2 * i] + pair[2 * i + 1] * x2;
    }
    return (quad[0] + quad[1] * x4) + (quad[2] + quad[3] * x4) * x8;
  };
  sinc = estrin(kSin);
  cosine = estrin(kCos);
}

/// R - I of the rotation log `rot` (lct::expSO3MinusIdentity in lanes); lanes whose turn
/// exceeds 2 pi (or is not finite) are marked for redoing.
LCT_LANE void rotationMinusIdentity(const Vec (&rot)[3], Vec (&d)[9], Mask& redo)
{
  const Vec x = rot[0], y = rot[1], z = rot[2];
  const Vec half2 = 0.25 * (x * x + y * y + z * z);
  const Mask within = lessEqual(half2, splat(kMaxHalfAngle2));
  redo |= ~within;
  const Vec clamped = select(within, half2, splat(0.0));
  Vec s, c;
  sincAndCos(clamped, s, c);
  // R - I = sinc [w]x + b [w]x^2 in the half-angle form.
  const Vec sinc = s * c;     // sin(theta) / theta
  const Vec b = 0.5 * s * s;  // (1 - cos theta) / theta^2
  const Vec cosMinusOne = -2.0 * clamped * s * s;
  d[0] = b * x * x + cosMinusOne;
  d[1] = b * x * y - sinc * z;
  d[2] = b * x * z + sinc * y;
  d[3] = b * x * y + sinc * z;
  d[4] = b * y * y + cosMinusOne;
  d[5] = b * y * z - sinc * x;
  d[6] = b * x * z - sinc * y;
  d[7] = b * y * z + sinc * x;
  d[8] = b * z * z + cosMinusOne;
}

/// The upper triangle of A B for commuting symmetric A, B (so A B is symmetric), in the layout
/// of lct::SymmetricVector: (00, 11, 22, 01, 12, 02).
LCT_LANE void symmetricProduct(const Vec (&a)[6], const Vec (&b)[6], Vec (&r)[6])
{
  r[0] = a[0] * b[0] + a[3] * b[3] + a[5] * b[5];
  r[1] = a[3] * b[3] + a[1] * b[1] + a[4] * b[4];
  r[2] = a[5] * b[5] + a[4] * b[4] + a[2] * b[2];
  r[3] = a[0] * b[3] + a[3] * b[1] + a[5] * b[4];
  r[4] = a[3] * b[5] + a[1] * b[4] + a[4] * b[2];
  r[5] = a[0] * b[5] + a[3] * b[4] + a[5] * b[2];
}

/// E = exp(Y) - I of a symmetric Y, in the "minus identity" form throughout so that a small
/// stretch keeps its relative accuracy: Taylor of degree 10 on Z = Y / 2^s with ||Z||_F <= 1/8,
/// then s squarings E <- 2E + E^2, s chosen per lane. Lanes with ||Y||_F > 16 are marked.
LCT_LANE void stretchMinusIdentity(const Vec (&y)[6], Vec (&e)[6], Mask& redo)
{
  const Vec norm2 =
    y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + 2.0 * (y[3] * y[3] + y[4] * y[4] + y[5] * y[5]);
  const Mask inRange = lessEqual(norm2, splat(kMaxStretchNorm2));
  redo |= ~inRange;
  Vec scale = splat(1.0), squarings = splat(0.0);
  double threshold = 1.0 / 64.0; // (2^i / 8)^2
  for (int i = 0; i < 7; ++i, threshold *= 4.0)
  {
    const Mask more = lessThan(splat(threshold), norm2) & inRange;
    scale = select(more, 0.5 * scale, scale);
    squarings = select(more, squarings + 1.0, squarings);
  }
  Vec z[6];
  for (int i = 0; i < 6; ++i)
  {
    z[i] = select(inRange, scale * y[i], splat(0.0));
  }
  // sum_{k=1..10} Z^k / k! by Paterson and Stockmeyer: with Z^2, Z^3, Z^4,
  // (c1 Z + .. + c4 Z^4) + Z^4 (c5 Z + .. + c8 Z^4) + Z^8 (c9 Z + c10 Z^2): six products, four
  // deep, where Horner takes ten in a row (the lanes would wait on each).
  static constexpr double c[11] = { 1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 720,
    1.0 / 5040, 1.0 / 40320, 1.0 / 362880, 1.0 / 3628800 };
  Vec z2[6], z3[6], z4[6], z8[6];
  symmetricProduct(z, z, z2);
  symmetricProduct(z, z2, z3);
  symmetricProduct(z2, z2, z4);
  symmetricProduct(z4, z4, z8);
  Vec middle[6], last[6];
  for (int i = 0; i < 6; ++i)
  {
    middle[i] = c[5] * z[i] + c[6] * z2[i] + c[7] * z3[i] + c[8] * z4[i];
    last[i] = c[9] * z[i] + c[10] * z2[i];
  }
  Vec z4Middle[6], z8Last[6];
  symmetricProduct(z4, middle, z4Middle);
  symmetricProduct(z8, last, z8Last);
  for (int i = 0; i < 6; ++i)
  {
    e[i] = (z[i] + c[2] * z2[i] + c[3] * z3[i] + c[4] * z4[i]) + z4Middle[i] + z8Last[i];
  }
  const double most = std::max({ squarings[0], squarings[1], squarings[2], squarings[3] });
  for (int i = 0; i < static_cast<int>(most); ++i)
  {
    const Mask active = lessThan(splat(static_cast<double>(i)), squarings);
    Vec ee[6];
    symmetricProduct(e, e, ee);
    for (int r = 0; r < 6; ++r)
    {
      e[r] = select(active, 2.0 * e[r] + ee[r], e[r]);
    }
  }
}

/// d <- (R - I) S + (S - I) = R S - I with S = I + E, E = exp(Y) - I.
LCT_LANE void withStretch(const Vec (&y)[6], Vec (&d)[9], Mask& redo)
{
  Vec e6[6];
  stretchMinusIdentity(y, e6, redo);
  const Vec e[9] = { e6[0], e6[3], e6[5], e6[3], e6[1], e6[4], e6[5], e6[4], e6[2] };
  Vec out[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      out[3 * r + c] = d[3 * r + c] +
        (d[3 * r] * e[c] + d[3 * r + 1] * e[3 + c] + d[3 * r + 2] * e[6 + c]) + e[3 * r + c];
    }
  }
  for (int i = 0; i < 9; ++i)
  {
    d[i] = out[i];
  }
}

LCT_LANE void polarLanes(const ProbeBatchSet& p, const Vec* w, LaneMaps& m, LaneFlags& flags)
{
  const Vec zero = splat(0.0);
  Vec absSum = zero, cs[3] = { zero, zero, zero }, tr[3] = { zero, zero, zero },
      rot[3] = { zero, zero, zero };
  Vec lin[9] = { zero, zero, zero, zero, zero, zero, zero, zero, zero };
  Vec y[6] = { zero, zero, zero, zero, zero, zero };
  for (int k = 0; k < p.probes; ++k)
  {
    const Vec wk = w[k], ak = absolute(wk);
    absSum += ak;
    for (int r = 0; r < 3; ++r)
    {
      cs[r] += ak * p.centre[r][k];
      tr[r] += wk * p.translation[r][k];
      rot[r] += wk * p.rotation[r][k];
    }
    for (int e = 0; e < 9; ++e)
    {
      lin[e] += wk * p.linearMinusIdentity[e][k];
    }
    if (!p.allRigid)
    {
      for (int i = 0; i < 6; ++i)
      {
        y[i] += wk * p.stretch[i][k];
      }
    }
  }
  // All-zero lanes divide 0 by 0 here and are set afterwards.
  const Vec inverse = 1.0 / absSum;
  for (int r = 0; r < 3; ++r)
  {
    m.centre[r] = cs[r] * inverse;
  }
  // psi(T(-c) A_i T(c)) = (A_i c - c, w_i, Y_i): the blended translation is
  // (sum w_i (L_i - I)) c + sum w_i t_i.
  for (int r = 0; r < 3; ++r)
  {
    m.shift[r] = lin[3 * r] * m.centre[0] + lin[3 * r + 1] * m.centre[1] +
      lin[3 * r + 2] * m.centre[2] + tr[r];
  }
  rotationMinusIdentity(rot, m.d, flags.redo);
  if (!p.allRigid)
  {
    withStretch(y, m.d, flags.redo);
  }
}

LCT_LANE void linearLanes(const ProbeBatchSet& p, const Vec* w, bool sumsToOne, LaneMaps& m)
{
  const Vec zero = splat(0.0);
  Vec total = zero, tr[3] = { zero, zero, zero };
  Vec lin[9] = { zero, zero, zero, zero, zero, zero, zero, zero, zero };
  for (int k = 0; k < p.probes; ++k)
  {
    const Vec wk = w[k];
    total += wk;
    for (int r = 0; r < 3; ++r)
    {
      tr[r] += wk * p.translation[r][k];
    }
    for (int e = 0; e < 9; ++e)
    {
      lin[e] += wk * p.linearMinusIdentity[e][k];
    }
  }
  // sum w_i A_i p = p + sum w_i (L_i - I) p + sum w_i t_i + (sum w_i - 1) p.
  const Vec extra = sumsToOne ? zero : select(equal(total, zero), zero, total - 1.0);
  for (int e = 0; e < 9; ++e)
  {
    m.d[e] = (e % 4 == 0) ? lin[e] + extra : lin[e];
  }
  for (int r = 0; r < 3; ++r)
  {
    m.shift[r] = tr[r];
    m.centre[r] = zero;
  }
}

LCT_LANE void dualQuaternionLanes(const ProbeBatchSet& p, const Vec* w, LaneMaps& m, LaneFlags& flags)
{
  const Vec zero = splat(0.0);
  // Kavan et al.'s hemisphere check against the heaviest probe (the first of the largest |w|).
  Vec heaviest = zero, total = zero, cs[3] = { zero, zero, zero };
  Mask pivot = splatMask(0);
  for (int k = 0; k < p.probes; ++k)
  {
    const Vec a = absolute(w[k]);
    const Mask heavier = lessThan(heaviest, a);
    heaviest = select(heavier, a, heaviest);
    pivot = (heavier & splatMask(k)) | (~heavier & pivot);
    total += a;
    for (int r = 0; r < 3; ++r)
    {
      cs[r] += a * p.centre[r][k];
    }
  }
  // DLB commutes with rigid changes of frame, so rigid probes need no centre; stretches do.
  for (int r = 0; r < 3; ++r)
  {
    m.centre[r] = p.allRigid ? zero : cs[r] / total;
  }
  Vec real[4] = { zero, zero, zero, zero }, dual[4] = { zero, zero, zero, zero };
  Vec y[6] = { zero, zero, zero, zero, zero, zero };
  for (int k = 0; k < p.probes; ++k)
  {
    const double* side = p.hemisphere[k];
    const Vec sign = { side[pivot[0]], side[pivot[1]], side[pivot[2]], side[pivot[3]] };
    const Vec sw = w[k] * sign;
    for (int r = 0; r < 4; ++r)
    {
      real[r] += sw * p.quaternion[r][k];
      dual[r] += sw * p.dual[r][k];
    }
    if (!p.allRigid)
    {
      // The rigid part of T(-c) A_k T(c) translates by (L_k - I) c + t_k.
      for (int r = 0; r < 4; ++r)
      {
        dual[r] += sw *
          (p.dualPerCentre[3 * r][k] * m.centre[0] + p.dualPerCentre[3 * r + 1][k] * m.centre[1] +
            p.dualPerCentre[3 * r + 2][k] * m.centre[2]);
      }
      for (int i = 0; i < 6; ++i)
      {
        y[i] += w[k] * p.stretch[i][k];
      }
    }
  }
  const Vec norm2 =
    real[0] * real[0] + real[1] * real[1] + real[2] * real[2] + real[3] * real[3];
  Vec norm = zero;
  for (int j = 0; j < B; ++j)
  {
    norm[j] = std::sqrt(norm2[j]);
  }
  flags.cancel |= ~lessThan(1e-12 * total, norm);
  const Vec inverse = 1.0 / norm, halfInverse = 0.5 / norm;
  const Vec qw = real[0] * inverse, qx = real[1] * inverse, qy = real[2] * inverse,
            qz = real[3] * inverse;
  const Vec ew = dual[0] * halfInverse, ex = dual[1] * halfInverse, ey = dual[2] * halfInverse,
            ez = dual[3] * halfInverse;
  // t = 2 vec(e q*) (Kavan et al. 2008, Alg. 1).
  m.shift[0] = 2.0 * (qw * ex - ew * qx + (qy * ez - qz * ey));
  m.shift[1] = 2.0 * (qw * ey - ew * qy + (qz * ex - qx * ez));
  m.shift[2] = 2.0 * (qw * ez - ew * qz + (qx * ey - qy * ex));
  m.d[0] = -2.0 * (qy * qy + qz * qz);
  m.d[1] = 2.0 * (qx * qy - qw * qz);
  m.d[2] = 2.0 * (qx * qz + qw * qy);
  m.d[3] = 2.0 * (qx * qy + qw * qz);
  m.d[4] = -2.0 * (qx * qx + qz * qz);
  m.d[5] = 2.0 * (qy * qz - qw * qx);
  m.d[6] = 2.0 * (qx * qz - qw * qy);
  m.d[7] = 2.0 * (qy * qz + qw * qx);
  m.d[8] = -2.0 * (qx * qx + qy * qy);
  if (!p.allRigid)
  {
    withStretch(y, m.d, flags.redo);
  }
}

/// Lane j of `m` set to `map`.
LCT_LANE void setLane(LaneMaps& m, int j, const PointMap& map)
{
  for (int r = 0; r < 3; ++r)
  {
    m.centre[r][j] = map.centre[r];
    m.shift[r][j] = map.shift[r];
    for (int c = 0; c < 3; ++c)
    {
      m.d[3 * r + c][j] = map.linearMinusIdentity(r, c);
    }
  }
}

LCT_LANE PointMap laneMap(const LaneMaps& m, int j)
{
  PointMap map;
  for (int r = 0; r < 3; ++r)
  {
    map.centre[r] = m.centre[r][j];
    map.shift[r] = m.shift[r][j];
    for (int c = 0; c < 3; ++c)
    {
      map.linearMinusIdentity(r, c) = m.d[3 * r + c][j];
    }
  }
  return map;
}

/// The blended maps of a block of normalised weights, with lct::blendAtPoint's special points
/// (one weight of exactly 1: that probe; all weights 0: at rest) and the lanes beyond the
/// lanes' range redone by lct::blendAtPoint. Lanes already failed (`skip`) are left as they
/// come out.
LCT_LANE void blendLanes(const ProbeBlendSet& set, const ProbeBatchSet& p, const Vec* w,
  bool sumsToOne, Mask skip, LaneMaps& m, LaneFlags& flags)
{
  switch (p.mode)
  {
    case BlendMode::Polar:
      polarLanes(p, w, m, flags);
      break;
    case BlendMode::Linear:
      linearLanes(p, w, sumsToOne, m);
      break;
    default:
      dualQuaternionLanes(p, w, m, flags);
      break;
  }
  // One weight of exactly 1 with every other 0, or all 0.
  const Vec zero = splat(0.0), one = splat(1.0);
  Vec nonZero = zero, ones = zero;
  for (int k = 0; k < p.probes; ++k)
  {
    nonZero += select(equal(w[k], zero), zero, one);
    ones += select(equal(w[k], one), one, zero);
  }
  const Mask special = equal(nonZero, zero) | (equal(nonZero, one) & equal(ones, one));
  flags.cancel &= ~special;
  flags.redo &= ~(special | skip);
  if (anyLane(special))
  {
    for (int j = 0; j < B; ++j)
    {
      if (!special[j])
      {
        continue;
      }
      PointMap map;
      for (int k = 0; k < p.probes; ++k)
      {
        if (w[k][j] != 0.0)
        {
          // Exactly that probe (exp(psi(A)) = A), as lct::blendAtPoint takes it.
          map.linearMinusIdentity = set.probes[k].linearMinusIdentity;
          map.shift = set.probes[k].translation;
        }
      }
      setLane(m, j, map);
    }
  }
  if (anyLane(flags.redo))
  {
    for (int j = 0; j < B; ++j)
    {
      if (!flags.redo[j])
      {
        continue;
      }
      double row[kMaxProbes];
      for (int k = 0; k < p.probes; ++k)
      {
        row[k] = w[k][j];
      }
      PointMap map;
      if (blendAtPoint(set, row, nullptr, p.probes, map) != Status::Ok)
      {
        flags.cancel[j] = -1;
        continue;
      }
      setLane(m, j, map);
    }
  }
}

/// lct::normalizeWeights' Linear normalisation in lanes, bit for bit (the same sums in the same
/// order, the same multiplication by the inverse).
LCT_LANE void normalizeLinear(int probes, Vec* w, Mask& invalid)
{
  const Vec zero = splat(0.0), one = splat(1.0);
  Vec sum = zero;
  Mask any = splatMask(0);
  for (int k = 0; k < probes; ++k)
  {
    sum += w[k];
    any |= ~equal(w[k], zero);
  }
  invalid |= any & ~(lessThan(zero, sum) & boundedBy(sum, std::numeric_limits<double>::max()));
  const Vec factor = select(any & ~equal(sum, one), 1.0 / sum, one);
  for (int k = 0; k < probes; ++k)
  {
    w[k] *= factor;
  }
}

/// The other normalisations, lane by lane.
LCT_LANE void normalizeEach(WeightNormalization normalization, int probes, Vec* w, Mask& invalid)
{
  for (int j = 0; j < B; ++j)
  {
    double row[kMaxProbes];
    for (int k = 0; k < probes; ++k)
    {
      row[k] = w[k][j];
    }
    if (normalizeWeights(normalization, row, probes) != Status::Ok)
    {
      invalid[j] = -1;
      continue;
    }
    for (int k = 0; k < probes; ++k)
    {
      w[k][j] = row[k];
    }
  }
}

LCT_LANE void normalizeLanes(WeightNormalization normalization, int probes, Vec* w, Mask& invalid)
{
  if (normalization == WeightNormalization::Linear)
  {
    normalizeLinear(probes, w, invalid);
  }
  else if (normalization == WeightNormalization::Softmax)
  {
    normalizeEach(normalization, probes, w, invalid);
  }
}

template <typename Weight>
LCT_LANE void loadWeights(const Weight* source, int slots, const std::int64_t (&point)[B], Vec* w)
{
  for (int k = 0; k < slots; ++k)
  {
    w[k] = Vec{ static_cast<double>(source[point[0] * slots + k]),
      static_cast<double>(source[point[1] * slots + k]),
      static_cast<double>(source[point[2] * slots + k]),
      static_cast<double>(source[point[3] * slots + k]) };
  }
}

template <typename Real>
LCT_LANE void loadPoints(const Real* in, const std::int64_t (&point)[B], Vec (&p)[3])
{
  for (int r = 0; r < 3; ++r)
  {
    p[r] = Vec{ static_cast<double>(in[3 * point[0] + r]), static_cast<double>(in[3 * point[1] + r]),
      static_cast<double>(in[3 * point[2] + r]), static_cast<double>(in[3 * point[3] + r]) };
  }
}

template <typename Real>
LCT_LANE void storePoints(const Vec (&q)[3], int count, std::int64_t first, Real* out)
{
  for (int j = 0; j < count; ++j)
  {
    for (int r = 0; r < 3; ++r)
    {
      out[3 * (first + j) + r] = static_cast<Real>(q[r][j]);
    }
  }
}

LCT_LANES_CLONES
DeformFailure deformLanes(const ProbeBlendSet& set, const ProbeBatchSet& p,
  const WeightSource& source, const void* in, void* out, bool doublePoints,
  const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end)
{
  const int slots = p.probes;
  const bool sumsToOne = source.normalization != WeightNormalization::None;
  const double realMax = doublePoints ? std::numeric_limits<double>::max()
                                      : static_cast<double>(std::numeric_limits<float>::max());
  for (std::int64_t first = begin; first < end; first += B)
  {
    const int count = static_cast<int>(std::min<std::int64_t>(B, end - first));
    std::int64_t point[B]; // spare lanes repeat the last point
    for (int j = 0; j < B; ++j)
    {
      point[j] = first + std::min(j, count - 1);
    }
    Vec w[kMaxProbes];
    if (source.floatWeights)
    {
      loadWeights(source.floatWeights, slots, point, w);
    }
    else
    {
      loadWeights(source.weights, slots, point, w);
    }
    Vec pt[3] = {};
    if (doublePoints)
    {
      loadPoints(static_cast<const double*>(in), point, pt);
    }
    else
    {
      loadPoints(static_cast<const float*>(in), point, pt);
    }
    LaneFlags flags;
    for (int k = 0; k < slots; ++k)
    {
      flags.nonFinite |= ~boundedBy(w[k], std::numeric_limits<double>::max());
    }
    normalizeLanes(source.normalization, slots, w, flags.invalid);
    LaneMaps m;
    blendLanes(set, p, w, sumsToOne, flags.nonFinite | flags.invalid, m, flags);
    Vec q[3];
    Mask overflow = splatMask(0);
    for (int r = 0; r < 3; ++r)
    {
      const Vec x = pt[0] - m.centre[0], y = pt[1] - m.centre[1], z = pt[2] - m.centre[2];
      q[r] = pt[r] + (m.d[3 * r] * x + m.d[3 * r + 1] * y + m.d[3 * r + 2] * z) + m.shift[r];
      // Finite in double and in Real (a float output can overflow where the double did not);
      // a non-finite map makes q non-finite too.
      overflow |= ~boundedBy(q[r], realMax);
    }
    const Mask failed = flags.nonFinite | flags.invalid | flags.cancel | overflow;
    int stored = count;
    DeformFailure failure;
    if (anyLane(failed))
    {
      // The first failing point, with the first check it fails in lct::deformPoints' order.
      for (int j = 0; j < count; ++j)
      {
        if (failed[j])
        {
          stored = j;
          failure.point = first + j;
          failure.status = flags.nonFinite[j] ? Status::NonFinite
            : flags.invalid[j]                ? Status::InvalidArgument
            : flags.cancel[j]                 ? Status::NumericalFailure
                                              : Status::OutOfRange;
          break;
        }
      }
    }
    if (doublePoints)
    {
      storePoints(q, stored, first, static_cast<double*>(out));
    }
    else
    {
      storePoints(q, stored, first, static_cast<float*>(out));
    }
    for (int j = 0; j < stored && carriedCount > 0; ++j)
    {
      const Eigen::Matrix3d d = laneMap(m, j).linearMinusIdentity;
      for (int c = 0; c < carriedCount; ++c)
      {
        carryVector(carried[c], d, first + j);
      }
    }
    if (!failure.ok())
    {
      return failure;
    }
  }
  return {};
}

LCT_LANES_CLONES
int blendLanesForTest(const ProbeBlendSet& set, const ProbeBatchSet& p,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& maps)
{
  Vec w[kMaxProbes];
  for (int k = 0; k < p.probes; ++k)
  {
    w[k] = Vec{ weights[k][0], weights[k][1], weights[k][2], weights[k][3] };
  }
  LaneFlags flags;
  LaneMaps m;
  blendLanes(set, p, w, sumsToOne, splatMask(0), m, flags);
  for (int j = 0; j < B; ++j)
  {
    for (int i = 0; i < 9; ++i)
    {
      maps.d[i][j] = m.d[i][j];
    }
    for (int r = 0; r < 3; ++r)
    {
      maps.shift[r][j] = m.shift[r][j];
      maps.centre[r][j] = m.centre[r][j];
    }
  }
  for (int j = 0; j < count; ++j)
  {
    if (flags.cancel[j])
    {
      return j;
    }
  }
  return -1;
}

LCT_LANES_CLONES
int normalizeLanesForTest(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights)
{
  Vec w[kMaxProbes];
  for (int k = 0; k < probes; ++k)
  {
    w[k] = Vec{ weights[k][0], weights[k][1], weights[k][2], weights[k][3] };
  }
  Mask invalid = splatMask(0);
  normalizeLanes(normalization, probes, w, invalid);
  for (int k = 0; k < probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      weights[k][j] = w[k][j];
    }
  }
  for (int j = 0; j < count; ++j)
  {
    if (invalid[j])
    {
      return j;
    }
  }
  return -1;
}
} // namespace

bool prepareProbeBatch(const ProbeBlendSet& set, ProbeBatchSet& batch)
{
  const int n = static_cast<int>(set.probes.size());
  const bool supported = set.mode == BlendMode::Polar || set.mode == BlendMode::Linear ||
    set.mode == BlendMode::DualQuaternion;
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
    for (int i = 0; i < 6; ++i)
    {
      batch.stretch[i][k] = symmetricPart(probe.logs)[i];
    }
    // (0, v) q = (-v . u, q_w v + v x u) for q = (q_w, u): the dual part without the factor
    // 1/2, of the translation t_k and, column by column, of (L_k - I) c.
    const Eigen::Vector4d& q = probe.quaternion;
    const Eigen::Vector3d u = q.tail<3>();
    const auto pureTimes = [&](const Eigen::Vector3d& v) {
      const Eigen::Vector3d tail = q[0] * v + v.cross(u);
      return Eigen::Vector4d(-v.dot(u), tail[0], tail[1], tail[2]);
    };
    const Eigen::Vector4d dual = pureTimes(probe.translation);
    for (int r = 0; r < 4; ++r)
    {
      batch.quaternion[r][k] = q[r];
      batch.dual[r][k] = dual[r];
    }
    for (int c = 0; c < 3; ++c)
    {
      const Eigen::Vector4d column = pureTimes(probe.linearMinusIdentity.col(c));
      for (int r = 0; r < 4; ++r)
      {
        batch.dualPerCentre[3 * r + c][k] = column[r];
      }
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

DeformFailure deformBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const WeightSource& source, const void* in, void* out, bool doublePoints,
  const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end)
{
  if (source.kind != WeightSource::Kind::Slots || source.indices ||
    source.slots != batch.probes || !(source.weights || source.floatWeights))
  {
    return { Status::InvalidArgument, begin };
  }
  return deformLanes(set, batch, source, in, out, doublePoints, carried, carriedCount, begin, end);
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

int blendBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& maps)
{
  return blendLanesForTest(set, batch, weights, count, sumsToOne, maps);
}

int normalizeBatch(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights)
{
  return normalizeLanesForTest(normalization, probes, count, weights);
}

} // namespace lct
