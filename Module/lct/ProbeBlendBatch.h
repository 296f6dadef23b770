/**
 * @file ProbeBlendBatch.h
 * @brief The probe blends of lct/ProbeBlend.h for a block of points at once, each point in one
 *        lane of a SIMD vector: 4 lanes (AVX2 + FMA where the CPU has them, chosen at load time)
 *        or, on CPUs with AVX-512, 8 lanes (chosen at run time).
 *
 * deformBatch is deformPoints' fast path for distance weights and for weights taken straight
 * from the point's slots (slot k = probe k): one pass per block of points reads the weights and
 * the points, normalises, blends, applies and stores, with every intermediate in registers (no
 * per-point call, no allocation, no aliasing through memory). Blends: Polar (Kaji & Ochiai's
 * phi(sum w psi(A)), about the point's centre c(p) = sum |w| c / sum |w|), Linear (LBS) and
 * DualQuaternion (Kavan's DLB with the hemisphere check, dual parts formed once per probe; with
 * stretch, "Polar+DQ" in Kavan et al.'s two phases: the stretches about their probes' centres
 * blended linearly, then the rigid parts).
 *
 * The exps are evaluated in lanes: the rotation's by the half-angle form of
 * lct::expSO3MinusIdentity with sin(phi) / phi and cos(phi) as Taylor polynomials in phi^2 (a
 * turn of up to 2 pi, both truncated below 1e-17; Estrin's scheme); the stretch's in the form
 * E = exp(Y) - I, so a small stretch keeps its relative accuracy: Taylor of degree 12 on Y / 2^s
 * with ||Y / 2^s||_F <= 1/4 (truncation below 1e-17 relative; Paterson-Stockmeyer), then s
 * squarings E <- 2E + E^2, s chosen per lane (a lane's result never depends on the other lanes,
 * so a threaded run equals a serial one bit for bit). A lane whose blended turn exceeds 2 pi, or
 * whose stretch log exceeds 16 in norm (Polar), takes lct::blendAtPoint itself. A point with one
 * weight of exactly 1 takes that probe's matrix (no exp) and one with all weights 0 stays put, as
 * in lct::blendAtPoint, so the guarantees of lct/ProbeBlend.h (exactness at rest, rigidity of a
 * single rigid probe) hold. Needs GCC or Clang (vector extensions).
 */
#ifndef lct_ProbeBlendBatch_h
#define lct_ProbeBlendBatch_h

#include "vtkLCTModule.h"

#include "lct/ProbeBlend.h"

namespace lct
{

/// Points per block (the lanes of one vector of doubles).
constexpr int kProbeBatch = 4;

/// The most probes (slots) a batch takes.
constexpr int kProbeBatchMaxProbes = 8;

/// Probe data laid out for the lanes, prepared once per call.
struct ProbeBatchSet
{
  int probes = 0;
  BlendMode mode = BlendMode::Polar;
  bool allRigid = true;
  double rotation[3][kProbeBatchMaxProbes];             ///< Polar: rotation part of psi(A_k)
  double stretch[6][kProbeBatchMaxProbes];              ///< Polar: log S_k as a SymmetricVector
  double stretchMinusIdentity[6][kProbeBatchMaxProbes]; ///< DualQuaternion: S_k - I, the same
  double linearMinusIdentity[9][kProbeBatchMaxProbes];  ///< row-major L_k - I
  double translation[3][kProbeBatchMaxProbes];
  double centre[3][kProbeBatchMaxProbes];
  /// DualQuaternion: (w, x, y, z), the sign of probe 0's side (q and -q are the same turn)
  double quaternion[4][kProbeBatchMaxProbes];
  double dual[4][kProbeBatchMaxProbes]; ///< DualQuaternion: (0, t_k') q_k (BlendProbe::dual)
  double stretchShift[3][kProbeBatchMaxProbes]; ///< DualQuaternion: (S_k - I) c_k
  /// DualQuaternion: -1 where probe k's rotation is in the other hemisphere than probe p's
  /// (Kavan's check, against the point's heaviest probe p), else 1: [k][p].
  double hemisphere[kProbeBatchMaxProbes][kProbeBatchMaxProbes];
  /// DualQuaternion: every entry of `hemisphere` is 1 (every two probes turn by less than pi
  /// relative to each other, as the bones of a character usually do), so the check cannot flip
  /// a probe and the lanes skip finding the heaviest probe.
  bool oneHemisphere = false;
};

/// Whether `set` can be blended in lanes (Polar, Linear or DualQuaternion, at most
/// kProbeBatchMaxProbes probes), and if so its layout.
VTKLCT_EXPORT bool prepareProbeBatch(const ProbeBlendSet& set, ProbeBatchSet& batch);

/// Deforms points [begin, end) as lct::deformPoints does for distance weights, or for slot
/// weights with slot k = probe k, `source.slots` == the number of probes and float or double
/// weights: the same maps to a few ulps, the same checks and the same first failing point.
/// `in`/`out` are float or double (`doublePoints`). `lanes`: 0 for probeBatchLanes(), 4 to take
/// 4 lanes whatever the CPU (tests compare the two).
VTKLCT_EXPORT DeformFailure deformBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const WeightSource& source, const void* in, void* out, bool doublePoints,
  const CarriedVectors* carried, int carriedCount, std::int64_t begin, std::int64_t end,
  int lanes = 0);

/// The lanes deformBatch takes by default: 8 where the CPU runs AVX-512 (and the library was
/// built by GCC without sanitizers), else 4. The environment variable LCT_PROBE_LANES=4, read
/// once, keeps 4 lanes on an AVX-512 CPU (to measure the AVX2 path there).
VTKLCT_EXPORT int probeBatchLanes();

/// The weights of a block: probe k's weight at point j is weights[k][j].
using ProbeBatchWeights = double[kProbeBatchMaxProbes][kProbeBatch];

/// The maps of a block, one lane per point (lct::PointMap laid out by lane).
struct ProbeBatchMaps
{
  double d[9][kProbeBatch];
  double shift[3][kProbeBatch];
  double centre[3][kProbeBatch];

  /// Lane j as a PointMap.
  PointMap at(int j) const;
};

/// The lanes' blend on its own, for tests: the maps of `count` <= kProbeBatch points whose
/// `weights` are already normalised (`sumsToOne`; Linear mode adds (sum w - 1) I otherwise).
/// Returns the first point whose blend fails (a DualQuaternion blend whose rotations cancel, or a
/// lane beyond the lanes' range that lct::blendAtPoint refuses), or -1. Lanes past `count` are
/// left unspecified.
VTKLCT_EXPORT int blendBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& maps);

/// The lanes' weight normalisation on its own, for tests: normalises the raw weights of `count`
/// points in place as lct::normalizeWeights does, bit for bit; returns the first point it
/// cannot divide by (Linear: a sum that is not positive and finite, weights not all zero), or -1.
VTKLCT_EXPORT int normalizeBatch(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights);

} // namespace lct

#endif
