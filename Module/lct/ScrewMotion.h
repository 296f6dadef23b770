/**
 * @file ScrewMotion.h
 * @brief The translation part of a rigid motion's logarithm (its twist), so that rigid frames
 *        can be blended as screw motions: the rotation by its rotation vector w, the translation
 *        t through v = J(w)^-1 t, and back by t = J(w) v.
 *
 * For a rigid motion [R | t] with R = exp(hat w), the matrix logarithm is [hat w, v; 0, 0] with
 * t = J(w) v, J the left Jacobian of SO(3) (e.g. Murray, Li & Sastry, "A Mathematical
 * Introduction to Robotic Manipulation", 1994, eq. 2.36; Barfoot, "State Estimation for
 * Robotics", 2017, eq. 7.85-7.86):
 *
 *   J(w)    = I + (1 - cos th) / th^2 hat w + (th - sin th) / th^3 hat w^2,
 *   J(w)^-1 = I - hat w / 2 + (1 - (th / 2) cot(th / 2)) / th^2 hat w^2,   th = |w|,
 *
 * both finite for th < 2 pi (J(w)^-1 at th = pi too), with series near th = 0. Blending the
 * twists (w_i, v_i) linearly and mapping back moves a frame along a helix (Chasles): a point
 * fixed in all frames stays fixed; frames sharing their origin keep it.
 */
#ifndef lct_ScrewMotion_h
#define lct_ScrewMotion_h

#include "vtkLCTModule.h"

#include <Eigen/Core>

namespace lct
{

/// J(w) t: the translation of exp([hat w, t; 0, 0]).
VTKLCT_EXPORT Eigen::Vector3d screwTranslation(const Eigen::Vector3d& w, const Eigen::Vector3d& v);

/// J(w)^-1 t: the twist's v of the rigid motion [exp(hat w) | t]. Precondition |w| <= pi (a
/// principal rotation vector).
VTKLCT_EXPORT Eigen::Vector3d screwTwist(const Eigen::Vector3d& w, const Eigen::Vector3d& t);

} // namespace lct

#endif
