/**
 * @file ProbeBlendBatch.h
 * @brief The probe blends of lct/ProbeBlend.h for kProbeBatch points at once, in a layout the
 *        compiler vectorises across points (structure of arrays, no branch or call per point
 *        in the hot loops; AVX2 + FMA where the CPU has them, by function multiversioning).
 *
 * The batch computes the same maps as lct::blendAtPoint, for weights taken straight from the
 * point's slots (slot k = probe k): Polar (Kaji & Ochiai's phi(sum w psi(A)), about the
 * point's centre c(p) = sum |w| c / sum |w|), Linear (LBS) and DualQuaternion on rigid probes
 * (Kavan's DLB, whose dual parts are formed once per probe). The rotation exp of the Polar
 * blend uses the half-angle form of lct::expSO3MinusIdentity with sin(phi) / phi and
 * cos(phi) as Taylor polynomials in phi^2 for a turn of up to 2 pi (phi <= pi: both truncated
 * below 1e-17, so within a few ulps of std::sin / std::cos there); a point whose blended turn
 * exceeds 2 pi takes lct::expSO3MinusIdentity itself. The stretch exp of affine probes, a
 * point with one weight of exactly 1 (that probe's matrix, no exp) and all-zero weights are
 * handled per point as lct::blendAtPoint does, so the guarantees of lct/ProbeBlend.h
 * (exactness at rest, rigidity of a single rigid probe) hold unchanged.
 */
#ifndef lct_ProbeBlendBatch_h
#define lct_ProbeBlendBatch_h

#include "vtkLCTModule.h"

#include "lct/ProbeBlend.h"

namespace lct
{

/// Points per batch.
constexpr int kProbeBatch = 8;

/// The most probes (slots) a batch takes.
constexpr int kProbeBatchMaxProbes = 8;

/// Probe data laid out for the batch, prepared once per execution.
struct ProbeBatchSet
{
  int probes = 0;
  BlendMode mode = BlendMode::Polar;
  bool allRigid = true;
  double rotation[3][kProbeBatchMaxProbes];            ///< Polar: rotation part of psi(A_k)
  double linearMinusIdentity[9][kProbeBatchMaxProbes]; ///< row-major L_k - I
  double translation[3][kProbeBatchMaxProbes];
  double centre[3][kProbeBatchMaxProbes];
  double quaternion[4][kProbeBatchMaxProbes]; ///< DualQuaternion: (w, x, y, z)
  double dual[4][kProbeBatchMaxProbes];       ///< DualQuaternion: (0, t_k) q_k
  /// DualQuaternion: -1 where probe k's rotation is in the other hemisphere than probe p's
  /// (Kavan's check, against the point's heaviest probe p), else 1: [k][p].
  double hemisphere[kProbeBatchMaxProbes][kProbeBatchMaxProbes];
};

/// Whether `set` can be blended in batches (Polar, Linear, or DualQuaternion on rigid probes;
/// at most kProbeBatchMaxProbes probes), and if so its batch layout.
VTKLCT_EXPORT bool prepareProbeBatch(const ProbeBlendSet& set, ProbeBatchSet& batch);

/// The weights of a batch: probe k's weight at point j is weights[k][j] (normalised or raw).
using ProbeBatchWeights = double[kProbeBatchMaxProbes][kProbeBatch];

/// The blended maps of a batch, one lane per point: p' = p + d (p - centre) + shift with d
/// row-major (lct::PointMap, laid out by lane).
struct ProbeBatchMaps
{
  double d[9][kProbeBatch];
  double shift[3][kProbeBatch];
  double centre[3][kProbeBatch];
  double halfAngle2[kProbeBatch]; ///< Polar: (theta / 2)^2 of the blended turn
  double total[kProbeBatch];      ///< the weights' sum (DualQuaternion: -1 where they cancel)
  int pivot[kProbeBatch];         ///< DualQuaternion: the heaviest probe

  /// Lane j as a PointMap.
  PointMap at(int j) const;
};

/// Normalises the raw weights of `count` points in place as lct::normalizeWeights does each
/// point's; returns the first point whose weights it cannot divide by (Linear: a sum that is
/// not positive and finite, with weights not all zero), or -1.
VTKLCT_EXPORT int normalizeBatch(
  WeightNormalization normalization, int probes, int count, ProbeBatchWeights& weights);

/// The maps of `count` <= kProbeBatch points with normalised `weights`: the maps
/// lct::blendAtPoint gives, to rounding. `sumsToOne`: the weights were normalised (Linear mode
/// adds (sum w - 1) I otherwise). Returns the first point whose blend fails (a DualQuaternion
/// blend whose rotations cancel), or -1. Lanes past `count` are left unspecified.
VTKLCT_EXPORT int blendBatch(const ProbeBlendSet& set, const ProbeBatchSet& batch,
  const ProbeBatchWeights& weights, int count, bool sumsToOne, ProbeBatchMaps& maps);

/// q = p + d (p - centre) + shift in every lane.
VTKLCT_EXPORT void applyBatch(
  const ProbeBatchMaps& maps, const double (&p)[3][kProbeBatch], double (&q)[3][kProbeBatch]);

} // namespace lct

#endif
