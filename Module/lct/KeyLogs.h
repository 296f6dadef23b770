/**
 * @file KeyLogs.h
 * @brief The logs of a sequence of keys, kept up to date as keys come and go, so that every point
 *        of a curve through them is one weighted sum and one exp (Alexa §5; Hawkins & Grimm
 *        eq. 7).
 *
 * For keys M_0 .. M_(n-1) it keeps the log of the step from M_r to M_i for |i - r| <= kReach
 * (the relative form; Polar: lct::worldStep, MatrixLog: M_r^-1 M_i) and the absolute logs log M_i,
 * each on the rotation branch nearest to its predecessor's (Kaji & Ochiai Algorithm 1). The
 * relative logs are principal; a curve point takes those of keys two or more from its reference
 * (Polar) on the rotation branch continued through the keys between, each nearest the one before
 * it, so keys turning by 100 degrees each do not wind back where two of them turn by 200. Given
 * curve weights w summing to 1 (lct/Curves.h):
 *
 * - combineRelative: the steps from M_r, the point of largest weight, combined and applied to
 *   it. MatrixLog: M_r exp(sum_i w_i log(M_r^-1 M_i)), which is also exp(sum_i w_i
 *   log(M_i M_r^-1)) M_r (the log commutes with conjugation). Polar: the step of the linear
 *   part in world axes, L_i L_r^-1 (Hawkins & Grimm's side), and the translation as the
 *   difference t_i - t_r, so the result is [exp(sum_i w_i log(L_i L_r^-1)) L_r, sum_i w_i t_i]:
 *   a translation that keys share stays put (a bone keeps its length), and the linear part stays
 *   within the keys' stretches. The step in the reference's own frame, L_r^-1 L_i, does not: its
 *   polar stretch is turned by the step's rotation before L_r squashes it, so a key squashed to
 *   1/10 blended with one turned by 90 degrees grew to 2.2 times either key in between (47 times
 *   for random keys of stretch up to e^5; session 27). The rotation part still depends on r, so
 *   where the two largest weights cross it would jump: within a weight gap of kHandOver the
 *   results about both are blended, s times the relative log of the step from one to the other
 *   applied to the first (lct::relativeLog, lct::applyRelativeStep), with a smoothstep s that
 *   is 1/2 at the crossing, where either side gives the same point: no jump, and C1.
 * - combineAbsolute: exp(sum_i w_i log M_i): reference-free, keeps the winding of spins.
 *
 * Keys are inserted, replaced and erased in O(kReach^2) logs (plus the absolute chain after the
 * change, which stops as soon as a log keeps its branch), so loading n keys in time order costs
 * O(n) logs.
 *
 * Not every pair of keys has a relative log (Polar: a step beyond the conditioning limit;
 * MatrixLog: also one without a real logarithm), nor every key an absolute one (MatrixLog). An
 * edit or a build given CurveNeeds fails, changing nothing, when a curve point of that scheme
 * would combine a log that does not exist (lct::curveStencil: every key of a segment's stencil
 * about each of its possible references, up to kStencilReach keys apart), and names it
 * (MissingLog): so an interpolator that validates its keys this way never fails for a missing log
 * when it evaluates.
 */
#ifndef lct_KeyLogs_h
#define lct_KeyLogs_h

#include "vtkLCTModule.h"

#include "lct/Combination.h"
#include "lct/Curves.h"
#include "lct/Keyframes.h"
#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <algorithm>
#include <limits>
#include <vector>

namespace lct
{

/// Which logs the curve points of a scheme combine: with `absolute`, the absolute log of every
/// key (combineAbsolute); otherwise the relative log of every key of each segment's stencil about
/// each of the segment's possible references (combineRelative; lct::curveStencil).
struct CurveNeeds
{
  CurveScheme scheme = CurveScheme::CatmullRom;
  bool absolute = false;
};

/// A log that a curve point needs and that does not exist, and why: log(M_reference^-1 M_key),
/// or the absolute log of `key` when reference == key (indices of the keys, or for Bezier of its
/// key-and-control sequence). status is Ok, and the indices -1, when none is missing.
struct MissingLog
{
  Status status = Status::Ok;
  int key = -1;
  int reference = -1;

  bool missing() const { return this->status != Status::Ok; }
};

class VTKLCT_EXPORT KeyLogs
{
public:
  /// Keys farther apart than this never share a curve point (the widest scheme touches 6
  /// neighbours plus folded end keys), so only these relative logs are kept.
  static constexpr int kReach = 7;
  /// Width of the hand-over between two reference points, in weight difference.
  static constexpr double kHandOver = 0.1;
  /// The farthest a key that a curve point combines is from its reference (Subdivision: three
  /// keys; lct::curveStencil).
  static constexpr int kStencilReach = 3;

  explicit KeyLogs(Parametrisation p = Parametrisation::Polar)
    : P(p)
  {
  }

  /// Replaces everything by `matrices` in parametrisation p. Fails (and keeps the previous
  /// state) when, with `neighboursMustCombine`, two neighbours have no relative log (the status
  /// says why); `failed` then receives the index of the later of the two.
  Status build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
    bool neighboursMustCombine, int* failed = nullptr);

  /// Inserts m before position `index` (0 .. size()). Fails like build (state unchanged).
  Status insert(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine);
  /// Replaces the key at `index`. Fails like build (state unchanged).
  Status replace(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine);
  /// Removes the key at `index`. Fails like build (state unchanged) when its two neighbours
  /// would then have no relative log.
  Status erase(int index, bool neighboursMustCombine);

  ///@{
  /// The same, failing too (state unchanged) when a curve point `needs` combines a log that the
  /// edit leaves missing; `missing` (if given) then names it, or the two neighbours without a
  /// relative log (key the later, reference the earlier), with indices after the edit.
  Status build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
    bool neighboursMustCombine, const CurveNeeds& needs, MissingLog* missing);
  Status insert(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine,
    const CurveNeeds& needs, MissingLog* missing);
  Status replace(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine,
    const CurveNeeds& needs, MissingLog* missing);
  Status erase(int index, bool neighboursMustCombine, const CurveNeeds& needs, MissingLog* missing);
  ///@}

  /// The first log that a curve point on segments firstSegment..lastSegment (all by default)
  /// needs and that does not exist; Ok when there is none.
  MissingLog missingLog(const CurveNeeds& needs, int firstSegment = 0,
    int lastSegment = std::numeric_limits<int>::max()) const;

  /// The same check for points that a caller holds outside a KeyLogs (an interpolator whose logs
  /// are rebuilt lazily, or the Bezier sequence of a few keys), computing each log it needs once:
  /// `points[j - offset]` is key j of keyCount keys (Bezier: point j of their key-and-control
  /// sequence), and the points the checked segments combine must be in the vector. With
  /// `involving` >= 0 only the logs of that key are checked (those an insertion or a replacement
  /// adds), with `across` >= 0 only the relative logs between a key before it and one from it on
  /// (those an erasure adds): the others are known to exist.
  static MissingLog missingLog(const std::vector<Eigen::Matrix4d>& points, int offset, int keyCount,
    Parametrisation p, const CurveNeeds& needs, int firstSegment, int lastSegment,
    int involving = -1, int across = -1);

  std::size_t size() const { return this->Matrices.size(); }
  const Eigen::Matrix4d& matrix(std::size_t i) const { return this->Matrices[i]; }
  Parametrisation parametrisation() const { return this->P; }

  /// The log of the step from M_r to M_i (lct::relativeLog), or null when it does not exist or
  /// |i - r| > kReach.
  const LogCoords* relative(int i, int r) const;
  /// `principal` = *relative(i, r) with its Polar rotation on the branch continued through the
  /// keys between r and i, each nearest the one before it (Kaji & Ochiai Algorithm 1), as curve
  /// points combine it: keys that turn by less than pi each keep turning the same way where two
  /// or three of them together turn by more (a Catmull-Rom stencil reaches two keys from its
  /// reference). `principal` as it is for MatrixLog, or when a log between is missing.
  LogCoords continuedRelative(int i, int r, const LogCoords& principal) const;
  /// Why relative(i, r) is null (Ok when it is not; InvalidArgument beyond reach).
  Status relativeStatus(int i, int r) const;

  /// The references of a curve point: entries `first` (largest weight) and `second` (the next,
  /// -1 with one entry) of w, and `share` in [0, 1/2], how much of the result about `second` the
  /// hand-over blends in (0 when the weights are kHandOver or more apart, 1/2 where they cross,
  /// a smoothstep in between).
  struct HandOver
  {
    int first = 0;
    int second = -1;
    double share = 0.0;
  };
  static HandOver handOver(const CurveWeights& w);

  /// The relative form about the point of largest weight, with the hand-over. Fails, leaving
  /// `out` unchanged, with the status of a missing relative log (then named in `missing`, if
  /// given) or of the exp, or with OutOfRange when the result is not finite.
  Status combineRelative(
    const CurveWeights& w, Eigen::Matrix4d& out, MissingLog* missing = nullptr) const;

  /// The absolute form exp(sum_i w_i log M_i). Fails, leaving `out` unchanged, with the status
  /// of a key without an absolute log (e.g. NoRealLogarithm, MatrixLog; named in `missing`, if
  /// given) or of the exp.
  Status combineAbsolute(
    const CurveWeights& w, Eigen::Matrix4d& out, MissingLog* missing = nullptr) const;

private:
  /// The relative logs of window r (entries i = r - kReach .. r + kReach) of `matrices`.
  struct Window
  {
    LogCoords logs[2 * kReach + 1];
    Status status[2 * kReach + 1];
  };
  enum class Edit
  {
    Insert,
    Replace,
    Erase
  };
  /// Applies an edit, recomputing only the windows within reach of it; unchanged on failure.
  Status edit(Edit kind, int index, const Eigen::Matrix4d* m, bool neighboursMustCombine,
    const CurveNeeds* needs, MissingLog* missing);
  void commitWindows(int first, const std::vector<Window>& scratch);
  void updateAbsoluteFrom(int index);
  Status combineAbout(
    const CurveWeights& w, int reference, Eigen::Matrix4d& out, MissingLog* missing) const;
  /// Two keys p, q (entries of w) of which at least one is ill-conditioned: about the better
  /// conditioned one, or about the other where only that one passes the determinant check and
  /// the two agree to kAgreement (relative, largest entry of the linear part).
  Status combineTwoIllConditioned(
    const CurveWeights& w, int p, int q, Eigen::Matrix4d& out, MissingLog* missing) const;
  static constexpr double kAgreement = 1e-8;
  Status combineRelativeUnchecked(
    const CurveWeights& w, Eigen::Matrix4d& out, MissingLog* missing) const;

  Parametrisation P;
  std::vector<Eigen::Matrix4d> Matrices;
  std::vector<Window> Windows;
  std::vector<LogCoords> Absolute;
  std::vector<Status> AbsoluteStatus;
  /// Per key: lct::needsAccurateProducts (ill-conditioned keys get compensated products, and
  /// results that involve them a check of their determinant against prod det(K_i)^(w_i)), and
  /// log |det| of the linear part.
  std::vector<char> Accurate;
  std::vector<double> LogDeterminant;
  /// OK, or InaccurateResult when a result involving ill-conditioned keys fails that check.
  Status checkResult(const CurveWeights& w, const Eigen::Matrix4d& out) const;
};

/// The keys of a lct::Keyframes around a change at time t, in time order, for the checks of an
/// edit by an interpolator whose logs are rebuilt lazily: `keys[edited]` is the inserted or
/// replacing key; for a removal, `edited` is the first key after the removed one. As a part of
/// the whole sequence, key j of the window is key offset() + j of count() keys, with phantom keys
/// on a side that does not reach the end, so that stencils near the change are clamped only
/// where the keys really end.
template <typename Key>
struct KeyWindow
{
  /// Keys on each side of a change that a check looks at: the logs an edit adds pair keys at most
  /// kStencilReach apart, and their stencils reach as far again.
  static constexpr int kSide = 2 * KeyLogs::kStencilReach;

  std::vector<const Key*> keys;
  int edited = 0;
  bool reachesFirst = true;
  bool reachesLast = true;

  int offset() const { return this->reachesFirst ? 0 : kSide; }
  int count() const
  {
    return this->offset() + static_cast<int>(this->keys.size()) + (this->reachesLast ? 0 : kSide);
  }
};

/// The window of `keyframes` around time t, with `replacement` (if any) inserted at t in place
/// of the key there. O(log n).
template <typename Key>
KeyWindow<Key> keyWindow(const Keyframes<Key>& keyframes, double t, const Key* replacement)
{
  KeyWindow<Key> w;
  std::vector<const Key*> after;
  keyframes.around(t, KeyWindow<Key>::kSide, w.keys, after);
  w.reachesFirst = static_cast<int>(w.keys.size()) < KeyWindow<Key>::kSide;
  w.reachesLast = static_cast<int>(after.size()) < KeyWindow<Key>::kSide;
  w.edited = static_cast<int>(w.keys.size());
  if (replacement)
  {
    w.keys.push_back(replacement);
  }
  w.keys.insert(w.keys.end(), after.begin(), after.end());
  return w;
}

/// The first log that the edit of a window adds (an insertion or replacement of keys[edited],
/// or with `removal` the removal before keys[edited]) and that curve points `needs` combine,
/// computed here in p on the matrices matrixOf(key); with `neighboursMustCombine` also the steps
/// from the edited key's neighbours (every curve joins them). Indices of the window's keys; Ok
/// when none is missing.
template <typename Key, typename MatrixOf>
MissingLog missingAfterEdit(const KeyWindow<Key>& w, bool removal, MatrixOf&& matrixOf,
  Parametrisation p, const CurveNeeds& needs, bool neighboursMustCombine)
{
  MissingLog missing;
  const int m = static_cast<int>(w.keys.size());
  if (m == 0 || (removal && (w.edited == 0 || w.edited == m)))
  {
    return missing; // a removal at an end joins nothing
  }
  std::vector<Eigen::Matrix4d> points;
  points.reserve(m);
  for (const Key* key : w.keys)
  {
    points.push_back(matrixOf(*key));
  }
  const int offset = w.offset();
  const int edited = offset + w.edited;
  missing =
    KeyLogs::missingLog(points, offset, w.count(), p, needs, edited - KeyLogs::kStencilReach - 1,
      edited + KeyLogs::kStencilReach, removal ? -1 : edited, removal ? edited : -1);
  for (int i = removal ? w.edited : std::max(w.edited, 1); neighboursMustCombine &&
       !missing.missing() && i <= (removal ? w.edited : std::min(w.edited + 1, m - 1));
       ++i)
  {
    const Status status = relativeLog(points[i - 1], points[i], p).status;
    if (status != Status::Ok)
    {
      missing = MissingLog{ status, offset + i, offset + i - 1 };
    }
  }
  if (missing.missing())
  {
    missing.key -= offset;
    missing.reference -= offset;
  }
  return missing;
}

} // namespace lct

#endif
