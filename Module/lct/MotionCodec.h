/**
 * @file MotionCodec.h
 * @brief An error-bounded compressor for skeletal animation in log coordinates, and the
 *        `.lctm` file format it writes.
 *
 * Method (each step measured in the README's "Motion capture compression" section):
 *  1. Every joint's local transform becomes its Polar log coordinates (Kaji & Ochiai eq. 2:
 *     translation l, rotation vector w, stretch log Y), the rotation branch chosen nearest the
 *     previous frame's (their Algorithm 1), so w is continuous through 180 degrees and beyond.
 *     A joint is then three tracks in a vector space: l (3-D), w (3-D), Y (6-D); a track that
 *     does not change (its effect within 1e-4 of the tolerance) is stored once as a constant.
 *  2. Each track has a budget b (a world-position error, the same for every track: beta tol).
 *     A translation error moves the joint and everything below it by itself; a rotation
 *     error d of joint j moves its arms, the joints below it, by |(J_r(w) d) x arm| (J_r the
 *     right Jacobian of exp on so(3)), so a twist about a bone costs nothing on that bone.
 *  3. Compensation (no stretch anywhere): the joints are coded parents first, and each
 *     rotation track is fitted not to its input but to the rotation that puts its arms nearest
 *     their input positions *from the decoded position and orientation of its parent*
 *     (Wahba's problem, one Gauss-Newton step from the input orientation, which also pins the
 *     twist). Errors then do not accumulate along a chain: each joint corrects what its
 *     ancestors' coding left, and only the arms up to the next coded joint count for it.
 *  4. Each track is fitted by a least-squares B-spline with adaptively placed knots
 *     (lct/BSplineFit.h), degrees 1 and 3 tried on the first trial and the one with fewer
 *     coefficients kept; the control points are quantised to a step of 2 q b / (sqrt(d) R)
 *     (R the track's largest arm, q = 0.8), and knots are added until the *quantised* curve is
 *     within b at every frame.
 *  5. The streams (structure, knot gaps, control-point differences as zig-zag varints) are
 *     entropy coded with LZMA2 (liblzma, preset 9 extreme, raw stream).
 *  6. The bound is verified, not assumed: every trial is decoded by the decoder's own code and
 *     the world positions of every joint and end site at every frame compared with the input's
 *     (lct/MotionError.h). beta is searched (start 0.3, down to the safe 1 / chain depth if
 *     needed, up by 1.5, then bisection); then it climbs by 1.2 while a local repair (budgets
 *     divided by how far a point is over 0.85 of the bound, for the joints above it, within
 *     24 frames) brings the measured maximum back under the tolerance in at most two rounds.
 *     The smallest file that passed is returned; the bound holds for it by measurement.
 *
 * File layout (little-endian): bytes 0-3 "LCTM", byte 4 the format version (1), bytes 5-7
 * zero, bytes 8-11 the payload size in bytes (uint32, at most 2^30), bytes 12-15 the CRC-32
 * (ISO-HDLC, as zlib's and liblzma's) of the payload, then the payload as one raw LZMA2 stream
 * (no xz container). The payload: the metadata (rotation order, input channel count, frame
 * time, tolerance, height), frames, joints (name, parent, end-site flag), then per joint and
 * per track (translation, rotation, stretch) its kind (zero, constant, curve) and data; every
 * count is checked against the bounds of the reader (10 000 joints, 3 10^7 transforms) and
 * every curve with lct::isWellFormed before anything is allocated for it.
 *
 * Pure functions: safe to call concurrently.
 */
#ifndef lct_MotionCodec_h
#define lct_MotionCodec_h

#include "vtkLCTModule.h"

#include "lct/MotionError.h"
#include "lct/Skeleton.h"
#include "lct/Status.h"

#include <functional>
#include <string>

namespace lct
{

/// What the file keeps beside the motion, so that a decoded clip can be written back as the
/// input was and the figures of the compression can be shown again.
struct MotionMetadata
{
  std::string rotationOrder = "ZYX"; ///< BVH channel order for writing the decoded motion
  int inputChannels = 0;             ///< channels of the input file (the raw-size accounting)
  double tolerance = 0.0;            ///< the bound the file was compressed to (file units)
  double height = 0.0;               ///< skeleton height H (lct/MotionError.h)
};

struct MotionCompressionOptions
{
  double tolerance = 0.0; ///< max world-position error, in the units of the file
  /// How far the input's positions may be from the file's own values (float32 readers:
  /// lct::float32PositionResolution); a tolerance below it is refused, since it would be
  /// verified against the values read and missed against the file. 0: exact input.
  double inputResolution = 0.0;
  int degree = 0;                 ///< 0: per track the better of 1 and 3; else 1, 2 or 3
  double quantisationShare = 0.8; ///< q above, in (0, 1)
  bool searchBudget = true;       ///< false: only the first budget that passes (no search)
  int searchSteps = 4;            ///< bisection steps of the beta search
  /// 2: rotation tracks correct the decoded positions below them; 1: orientations only; 0: each
  /// track fitted to its own input (see step 3 above).
  int compensation = 2;
  int refineSteps = 5; ///< steps of the per-frame budget refinement (0: none)
  /// Called after each trial with a line of progress (may be empty).
  std::function<void(const std::string&)> progress;
};

struct MotionCompressionReport
{
  PositionErrorStatistics error; ///< of the decoded file against the input
  std::size_t bytes = 0;         ///< the file size
  std::size_t payloadBytes = 0;  ///< before LZMA2
  double budgetScale = 0.0;      ///< beta of the file written
  int trials = 0;                ///< encodings tried
  int curveTracks = 0;
  int constantTracks = 0;
  int controlPoints = 0;
  int knots = 0;
  int cubicTracks = 0;
};

/// Compresses `animation` (consistent, finite, every local transform in Aff+(3)) so that the
/// maximum world-position error is at most options.tolerance. Fails with InvalidArgument (an
/// inconsistent animation, a tolerance that is not positive and finite or is below
/// options.inputResolution, a bad option),
/// NonFinite, NotAffine, NegativeDeterminant or Singular (a local transform outside Aff+(3)),
/// or InaccurateResult (no budget met the tolerance: it is below the precision of the input).
/// `why` names the cause in words.
VTKLCT_EXPORT Result<std::string> compressMotion(const SkeletalAnimation& animation,
  const MotionMetadata& metadata, const MotionCompressionOptions& options,
  MotionCompressionReport* report = nullptr, std::string* why = nullptr);

/// Decodes a `.lctm` file's bytes. Fails with InvalidArgument and a message in `why` for
/// anything that is not a complete, intact file of a known version (wrong magic, an unknown
/// version, a truncated or corrupted stream, a checksum mismatch, counts beyond the bounds,
/// malformed curves, trailing bytes, values whose transforms are not finite).
VTKLCT_EXPORT Result<SkeletalAnimation> decompressMotion(
  const std::string& bytes, MotionMetadata* metadata = nullptr, std::string* why = nullptr);

} // namespace lct

#endif
