/**
 * @file KeyLogs.h
 * @brief The logs of a sequence of keys, computed once, so that every point of a curve through
 *        them is one weighted sum and one exp (Alexa §5; Hawkins & Grimm eq. 7).
 *
 * For keys M_0 .. M_(n-1) it keeps log(M_i M_r^-1) for |i - r| <= kReach (the relative form)
 * and the absolute logs log M_i, each on the rotation branch nearest to its predecessor's
 * (Kaji & Ochiai Algorithm 1). Given curve weights w (lct/Curves.h):
 *
 * - combineRelative: exp(sum_i w_i log(M_i M_r^-1)) M_r with M_r the point of largest weight.
 *   The result depends on r (only the matrix log of two keys is reference-free), so where the
 *   two largest weights cross it would jump. Within a weight gap of kHandOver the results about
 *   both are blended along the short geodesic between them, (R_b R_a^-1)^s R_a, with a
 *   smoothstep s that is 1/2 at the crossing: no jump, and C1.
 * - combineAbsolute: exp(sum_i w_i log M_i): reference-free, keeps the winding of spins.
 */
#ifndef lct_KeyLogs_h
#define lct_KeyLogs_h

#include "vtkLCTModule.h"

#include "lct/Curves.h"
#include "lct/LogCoords.h"
#include "lct/Status.h"

#include <Eigen/Core>
#include <Eigen/StdVector>

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

  /// Computes every log of `matrices` in parametrisation p. Fails (and keeps the previous
  /// state) when a key has no log or, with `neighboursMustCombine`, two neighbours have none
  /// between them; `failed` then receives the index of the offending key.
  Status build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
    bool neighboursMustCombine, int* failed = nullptr);

  std::size_t size() const { return this->Matrices.size(); }
  const Eigen::Matrix4d& matrix(std::size_t i) const { return this->Matrices[i]; }
  Parametrisation parametrisation() const { return this->P; }

  /// log(M_i M_r^-1), or null when it does not exist or |i - r| > kReach.
  const LogCoords* relative(int i, int r) const;

  /// The relative form about the point of largest weight, with the hand-over.
  Status combineRelative(const CurveWeights& w, Eigen::Matrix4d& out) const;

  /// The absolute form exp(sum_i w_i log M_i).
  Status combineAbsolute(const CurveWeights& w, Eigen::Matrix4d& out) const;

private:
  Status combineAbout(const CurveWeights& w, int reference, Eigen::Matrix4d& out) const;

  Parametrisation P = Parametrisation::Polar;
  std::vector<Eigen::Matrix4d> Matrices;
  std::vector<LogCoords> Relative;
  std::vector<char> RelativeValid;
  std::vector<LogCoords> Absolute;
};

} // namespace lct

#endif
