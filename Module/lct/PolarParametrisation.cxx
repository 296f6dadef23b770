#include "lct/PolarParametrisation.h"

#include "lct/Affine.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <limits>

namespace lct
{

Result<LogCoords> polarLog(const Eigen::Matrix4d& m, const Eigen::Vector3d* rotationReference)
{
  using R = Result<LogCoords>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  const auto polar = polarDecompose(m.topLeftCorner<3, 3>());
  if (!polar)
  {
    return R::failure(polar.status);
  }
  R out;
  // A rigid map's stretch is I up to round-off: its log is 0 exactly, so that blends of rigid
  // maps are exactly rigid and take the rotation-only path of polarExp.
  Eigen::Matrix3d stretchOffset = polar.value.stretch;
  stretchOffset.diagonal().array() -= 1.0;
  const bool rigid =
    stretchOffset.cwiseAbs().maxCoeff() <= 8.0 * std::numeric_limits<double>::epsilon();
  const auto logStretch = rigid ? Result<Eigen::Matrix3d>{ Eigen::Matrix3d::Zero(), Status::Ok }
                                : logSPD(polar.value.stretch);
  if (!logStretch)
  {
    return R::failure(logStretch.status);
  }
  translationPart(out.value) = m.topRightCorner<3, 1>();
  rotationPart(out.value) = rotationReference
    ? logSO3Nearest(polar.value.rotation, *rotationReference)
    : logSO3(polar.value.rotation);
  symmetricPart(out.value) = toSymmetricVector(logStretch.value);
  return out;
}

Result<Eigen::Matrix4d> polarExp(const LogCoords& c)
{
  using R = Result<Eigen::Matrix4d>;
  if (!c.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  // Rigid maps (Y = 0, the common case of cameras and skeletons) skip the stretch entirely.
  const Eigen::Matrix3d linear = symmetricPart(c).isZero(0.0)
    ? expSO3(rotationPart(c))
    : Eigen::Matrix3d(expSO3(rotationPart(c)) * expSym(fromSymmetricVector(symmetricPart(c))));
  R out{ makeAffine(linear, translationPart(c)), Status::Ok };
  if (!out.value.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  return out;
}

} // namespace lct
