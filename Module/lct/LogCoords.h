/**
 * @file LogCoords.h
 * @brief The 12 log coordinates shared by both parametrisations, and the choice between them.
 *
 * Both parametrisations map Aff+(3) (or the part of it they cover) to R^12, where weighted
 * sums are ordinary vector sums (Alexa eq. 7, Kaji & Ochiai eq. 9). The layout is the same:
 *
 *   [0, 3)   translation part   Polar: l;  MatrixLog: u, the top-right block of log M
 *   [3, 6)   rotation part      w with hat(w) = the skew part of the log of the linear part
 *   [6, 12)  symmetric part     (xx, yy, zz, xy, yz, xz) of the symmetric part of that log
 *
 * Polar (Kaji & Ochiai eq. 2): M = T(l) exp(hat w) exp(Y), U S the polar decomposition of the
 * linear part; rigid maps have Y = 0, similarities Y = c I. Defined on all of Aff+(3).
 * MatrixLog (Alexa 2002): M = exp([hat w + Y, u; 0 0]); only for linear parts without
 * negative real eigenvalues.
 */
#ifndef lct_LogCoords_h
#define lct_LogCoords_h

#include <Eigen/Core>

namespace lct
{

enum class Parametrisation
{
  Polar,    ///< Kaji & Ochiai 2016: surjective on Aff+(3), closed subgroups. The default.
  MatrixLog ///< Alexa 2002: log of the whole 4x4 matrix; associative scalar multiple.
};

using LogCoords = Eigen::Matrix<double, 12, 1>;

inline auto translationPart(LogCoords& c)
{
  return c.segment<3>(0);
}
inline auto translationPart(const LogCoords& c)
{
  return c.segment<3>(0);
}
inline auto rotationPart(LogCoords& c)
{
  return c.segment<3>(3);
}
inline auto rotationPart(const LogCoords& c)
{
  return c.segment<3>(3);
}
inline auto symmetricPart(LogCoords& c)
{
  return c.segment<6>(6);
}
inline auto symmetricPart(const LogCoords& c)
{
  return c.segment<6>(6);
}

} // namespace lct

#endif
