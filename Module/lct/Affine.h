/**
 * @file Affine.h
 * @brief 4x4 homogeneous affine matrices: validation, assembly and inverse.
 *
 * The domain of both parametrisations is Aff+(3): finite 4x4 matrices with bottom row
 * (0, 0, 0, 1) and a linear part of positive determinant.
 */
#ifndef lct_Affine_h
#define lct_Affine_h

#include "vtkLCTModule.h"

#include "lct/Status.h"

#include <Eigen/Core>

namespace lct
{

/// Ok, NonFinite, NotAffine (bottom row not (0,0,0,1)), NegativeDeterminant or Singular
/// (det = 0). Conditioning is checked by the logarithms, not here.
VTKLCT_EXPORT Status validateAffine(const Eigen::Matrix4d& m);

/// [linear translation; 0 0 0 1]
inline Eigen::Matrix4d makeAffine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& translation)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = translation;
  return m;
}

/// The inverse of an affine matrix, using its block structure (no 4x4 inversion), at any
/// magnitude. Entries overflow to Inf when the inverse is out of range (callers check).
VTKLCT_EXPORT Eigen::Matrix4d inverseAffine(const Eigen::Matrix4d& m);

/// R^-1 M, the step from key R to key M of the relative form. For an ill-conditioned R the plain
/// product is off by eps cond(R) relative; there the step is formed from exact minors
/// (lct/AccurateMinors.h). Entries overflow to Inf when the step is out of range.
VTKLCT_EXPORT Eigen::Matrix4d relativeStep(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& m);

/// The step from key R to key M in world axes, [L_m L_r^-1, t_m - t_r]: the Polar relative
/// form's (lct/KeyLogs.h), where M = [E L_r, t_r + d] for the step [E, d] (applyWorldStep). Its
/// linear part acts after the reference's, in world axes, so a stretch of the step is never
/// turned by the reference's own rotation (the step in R's frame, R^-1 M, is: blending a
/// squashed key with a turned one through it inflates the in-between beyond both keys, by a
/// factor that grows with the squash). Exact minors for an ill-conditioned R, as relativeStep.
VTKLCT_EXPORT Eigen::Matrix4d worldStep(const Eigen::Matrix4d& reference, const Eigen::Matrix4d& m);

/// [E L_r, t_r + d] for a step [E, d] in world axes (worldStep), with compensated dot products
/// when `accurate` (needsAccurateProducts(R)).
VTKLCT_EXPORT Eigen::Matrix4d applyWorldStep(
  const Eigen::Matrix4d& reference, const Eigen::Matrix4d& step, bool accurate);

/// sigma_max / sigma_min of the linear part, at unit scale so that only their ratio counts (Inf
/// for a singular one; a reflection has one too). The module inverts a linear part only when it
/// is at most kMaxConditionNumber.
VTKLCT_EXPORT double linearConditionNumber(const Eigen::Matrix4d& m);

/// Whether the plain products with this map lose digits: ||A||_F^3 / det A > 1e3 (an upper bound
/// of cond(A)^2 times 5.2, and at least cond(A)). relativeStep and the relative form use exact
/// minors and compensated products then.
VTKLCT_EXPORT bool needsAccurateProducts(const Eigen::Matrix4d& m);

/// log |det A| of the linear part to a few ulps at any magnitude and condition (exact minors).
VTKLCT_EXPORT double accurateLogDeterminant(const Eigen::Matrix4d& m);

/// Whether log |det A| of a computed result is `expected` within 1e-9 plus what rounding its
/// entries to double can move it (2 eps sum_ij |cofactor_ij a_ij| / |det A|, first order). The
/// relative form between ill-conditioned keys can lose the result's smallest stretch in its
/// intermediates (steps of condition cond(K_r) cond(K_i)); its determinant, prod det(K_i)^(w_i)
/// for every scheme, shows it.
VTKLCT_EXPORT bool determinantMatches(const Eigen::Matrix4d& result, double expectedLogDeterminant);

/// R X, with compensated dot products when needsAccurateProducts(R) (lct/AccurateMinors.h).
VTKLCT_EXPORT Eigen::Matrix4d productWith(
  const Eigen::Matrix4d& r, const Eigen::Matrix4d& x, bool accurate);

} // namespace lct

#endif
