#include "lct/ProbeBlendBatch.h"

#include "lct/Sym3.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#if !defined(__GNUC__)
#error "lct/ProbeBlendBatch.cxx needs GCC or Clang vector extensions"
#endif

// The lanes are GCC/Clang vector types; with GCC on x86-64 the 4-lane functions are also compiled
// for x86-64-v3 (AVX2, FMA) and picked at load time where the CPU has it, and an 8-lane copy for
// x86-64-v4 (AVX-512) is picked at run time. Not under the sanitizers: the load-time choice is an
// ifunc resolver, which runs before ThreadSanitizer's runtime is up (the TSan build's unit tests
// crashed at start).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) &&                             \
  !defined(__SANITIZE_THREAD__) && !defined(__SANITIZE_ADDRESS__)
#define LCT_LANES_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#define LCT_WIDE_LANES 1
#else
#define LCT_LANES_CLONES
#define LCT_WIDE_LANES 0
#endif

// Every lane helper is inlined into the functions above, so that it runs in the chosen clone's
// instruction set (a helper left out of line would be compiled for the default target only).
#define LCT_LANE inline __attribute__((always_inline))

// The helpers pass 32- and 64-byte vectors by value; they are all inlined (no ABI between them).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace lct
{

namespace
{
constexpr int kMaxProbes = kProbeBatchMaxProbes;

// One point per lane. Every operation acts on all lanes alike, so a lane's result does not
// depend on the other lanes or on where a block starts. The lane code (lct/ProbeBlendLanes.inc)
// is compiled twice: 4 lanes of a 32-byte vector (AVX2 + FMA, or the baseline), and where GCC
// can target it, 8 lanes of a 64-byte vector for CPUs with AVX-512 (x86-64-v4), chosen at run
// time. (8 lanes on AVX2 alone measured 3-5x slower: GCC splits 64-byte vectors through memory.)
typedef double Vec4 __attribute__((vector_size(4 * sizeof(double))));
typedef std::int64_t Mask4 __attribute__((vector_size(4 * sizeof(std::int64_t))));

namespace lanes4
{
constexpr int B = 4;
static_assert(B == kProbeBatch, "the test entry points take one block of kProbeBatch lanes");
using Vec = Vec4;
using Mask = Mask4;
#define LCT_LANES_TARGET LCT_LANES_CLONES
#define LCT_LANES_OPAQUE(m)
#include "lct/ProbeBlendLanes.inc"
#undef LCT_LANES_OPAQUE
#undef LCT_LANES_TARGET

LCT_LANES_CLONES
int blendLanesForTest(const ProbeBlendSet& set, const ProbeBatchSet& p,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& maps)
{
  Vec w[kMaxProbes];
  for (int k = 0; k < p.probes; ++k)
  {
    for (int j = 0; j < B; ++j)
    {
      w[k][j] = weights[k][j];
    }
  }
  LaneFlags flags;
  LaneMaps m;
  const Mask none = splatMask(0);
  if (p.mode == BlendMode::Linear)
  {
    blendLanes<BlendMode::Linear, false>(set, p, w, sumsToOne, none, m, flags);
  }
  else if (p.mode == BlendMode::Polar)
  {
    p.allRigid ? blendLanes<BlendMode::Polar, true>(set, p, w, sumsToOne, none, m, flags)
               : blendLanes<BlendMode::Polar, false>(set, p, w, sumsToOne, none, m, flags);
  }
  else
  {
    p.allRigid ? blendLanes<BlendMode::DualQuaternion, true>(set, p, w, sumsToOne, none, m, flags)
               : blendLanes<BlendMode::DualQuaternion, false>(set, p, w, sumsToOne, none, m, flags);
  }
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
    if (flags.cancel[j] || flags.redoFailed[j])
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
    for (int j = 0; j < B; ++j)
    {
      w[k][j] = weights[k][j];
    }
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
} // namespace lanes4

#if LCT_WIDE_LANES
typedef double Vec8 __attribute__((vector_size(8 * sizeof(double))));
typedef std::int64_t Mask8 __attribute__((vector_size(8 * sizeof(std::int64_t))));

namespace lanes8
{
constexpr int B = 8;
using Vec = Vec8;
using Mask = Mask8;
#define LCT_LANES_TARGET __attribute__((target("arch=x86-64-v4")))
#define LCT_LANES_OPAQUE(m) asm("" : "+v"(m))
#include "lct/ProbeBlendLanes.inc"
#undef LCT_LANES_OPAQUE
#undef LCT_LANES_TARGET
} // namespace lanes8

/// Whether the CPU runs x86-64-v4 code (AVX-512 F, BW, CD, DQ, VL).
bool hasWideLanes()
{
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
    __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
    __builtin_cpu_supports("avx512vl");
}
#endif
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
  double side[kProbeBatchMaxProbes];
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
      batch.stretchMinusIdentity[i][k] = probe.stretchMinusIdentity[i];
    }
    // Negating a probe's q and dual part changes no blend bit: the check's sign flips with it,
    // and a blend negated as a whole gives the same rotation and translation.
    side[k] = probe.quaternion.dot(set.probes[0].quaternion) < 0.0 ? -1.0 : 1.0;
    for (int r = 0; r < 4; ++r)
    {
      batch.quaternion[r][k] = side[k] * probe.quaternion[r];
      batch.dual[r][k] = side[k] * probe.dual[r];
    }
    for (int r = 0; r < 3; ++r)
    {
      batch.stretchShift[r][k] = probe.stretchShift[r];
    }
  }
  batch.oneHemisphere = true;
  for (int k = 0; k < n; ++k)
  {
    for (int pivot = 0; pivot < n; ++pivot)
    {
      // lct::blendAtPoint's sign (a product exactly 0 counts as one side), carried over to
      // the negated quaternions, so that the lanes blend exactly what it blends.
      const double check =
        set.probes[k].quaternion.dot(set.probes[pivot].quaternion) < 0.0 ? -1.0 : 1.0;
      batch.hemisphere[k][pivot] = side[k] * side[pivot] * check;
      batch.oneHemisphere = batch.oneHemisphere && batch.hemisphere[k][pivot] > 0.0;
    }
  }
  return true;
}

DeformFailure deformBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const WeightSource& source, const void* in, void* out, bool doublePoints,
  const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end, int lanes)
{
  const bool fromSlots = source.kind == WeightSource::Kind::Slots;
  if (fromSlots
      ? (source.indices || source.slots != batch.probes || !(source.weights || source.floatWeights))
      : !source.radii)
  {
    return { Status::InvalidArgument, begin };
  }
#if !LCT_WIDE_LANES
  (void)lanes;
#else
  static const bool wide = probeBatchLanes() == 8;
  if (wide && lanes != 4)
  {
    return lanes8::deformLanes(
      set, batch, source, in, out, doublePoints, carried, carriedCount, begin, end);
  }
#endif
  return lanes4::deformLanes(
    set, batch, source, in, out, doublePoints, carried, carriedCount, begin, end);
}

int probeBatchLanes()
{
#if LCT_WIDE_LANES
  static const int lanes = [] {
    const char* chosen = std::getenv("LCT_PROBE_LANES");
    const bool narrow = chosen && std::strcmp(chosen, "4") == 0;
    return hasWideLanes() && !narrow ? 8 : 4;
  }();
  return lanes;
#else
  return 4;
#endif
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
  return lanes4::blendLanesForTest(set, batch, weights, count, sumsToOne, maps);
}

int normalizeBatch(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights)
{
  return lanes4::normalizeLanesForTest(normalization, probes, count, weights);
}

} // namespace lct
