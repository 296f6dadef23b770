/**
 * @file KeyLogs.h
 * @brief The logs of a sequence of keys, kept up to date as keys come and go, so that every point
 *        of a curve through them is one weighted sum and one exp (Alexa §5; Hawkins & Grimm
 *        eq. 7).
 *
 * For keys M_0 .. M_(n-1) it keeps log(M_r^-1 M_i) for |i - r| <= kReach (the relative form, in
 * the reference key's own frame) and the absolute logs log M_i, each on the rotation branch
 * nearest to its predecessor's (Kaji & Ochiai Algorithm 1). Given curve weights w summing to 1
 * (lct/Curves.h):
 *
 * - combineRelative: M_r exp(sum_i w_i log(M_r^-1 M_i)) with M_r the point of largest weight.
 *   Hawkins & Grimm put the reference on the other side (their matrices map world to camera);
 *   for maps to the world, the reference's own frame is the one in which the Polar translation
 *   part of M_r^-1 M_i is A_r^-1 (t_i - t_r), so the combined translation is exactly
 *   sum_i w_i t_i: a translation that keys share stays put (a bone keeps its length). For the
 *   matrix log both sides give the same result. The rotation part still depends on r, so where
 *   the two largest weights cross it would jump: within a weight gap of kHandOver the results
 *   about both are blended along the short geodesic between them, R_a (R_a^-1 R_b)^s, with a
 *   smoothstep s that is 1/2 at the crossing: no jump, and C1.
 * - combineAbsolute: exp(sum_i w_i log M_i): reference-free, keeps the winding of spins.
 *
 * Keys are inserted, replaced and erased in O(kReach^2) logs (plus the absolute chain after the
 * change, which stops as soon as a log keeps its branch), so loading n keys in time order costs
 * O(n) logs.
 */
#ifndef lct_KeyLogs_h
#define lct_KeyLogs_h

#include "vtkLCTModule.h"

#include "lct/Curves.h"
#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>

#include <vector>

namespace lct
{

class VTKLCT_EXPORT KeyLogs
{
public:
  /// Keys farther apart than this never share a curve point (the widest scheme touches 6
  /// neighbours plus folded end keys), so only these relative logs are kept.
  static constexpr int kReach = 7;
  /// Width of the hand-over between two reference points, in weight difference.
  static constexpr double kHandOver = 0.1;

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

  std::size_t size() const { return this->Matrices.size(); }
  const Eigen::Matrix4d& matrix(std::size_t i) const { return this->Matrices[i]; }
  Parametrisation parametrisation() const { return this->P; }

  /// log(M_r^-1 M_i), or null when it does not exist or |i - r| > kReach.
  const LogCoords* relative(int i, int r) const;
  /// Why relative(i, r) is null (Ok when it is not; InvalidArgument beyond reach).
  Status relativeStatus(int i, int r) const;

  /// The relative form about the point of largest weight, with the hand-over. Fails, leaving
  /// `out` unchanged, with the status of a missing relative log or of the exp, or with
  /// OutOfRange when the result is not finite.
  Status combineRelative(const CurveWeights& w, Eigen::Matrix4d& out) const;

  /// The absolute form exp(sum_i w_i log M_i). Fails, leaving `out` unchanged, with the status
  /// of a key without an absolute log (e.g. NoRealLogarithm, MatrixLog) or of the exp.
  Status combineAbsolute(const CurveWeights& w, Eigen::Matrix4d& out) const;

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
  Status edit(Edit kind, int index, const Eigen::Matrix4d* m, bool neighboursMustCombine);
  void commitWindows(int first, const std::vector<Window>& scratch);
  void updateAbsoluteFrom(int index);
  Status combineAbout(const CurveWeights& w, int reference, Eigen::Matrix4d& out) const;
  Status combineRelativeUnchecked(const CurveWeights& w, Eigen::Matrix4d& out) const;

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

} // namespace lct

#endif
