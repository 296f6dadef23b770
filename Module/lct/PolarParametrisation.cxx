#include "lct/PolarParametrisation.h"

#include "lct/Affine.h"
#include "lct/Conditioning.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <cmath>
#include <limits>

namespace lct
{

namespace
{
constexpr double kLn2 = 0.69314718055994530942;
/// log(DBL_MIN): stretches below it are subnormal or zero.
const double kLowestLogStretch = std::log(std::numeric_limits<double>::min());
const double kLogMaxConditionNumber = std::log(kMaxConditionNumber);
} // namespace

Result<LogCoords> polarLog(const Eigen::Matrix4d& m, const Eigen::Vector3d* rotationReference)
{
  using R = Result<LogCoords>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  if (rotationReference)
  {
    if (!rotationReference->allFinite())
    {
      return R::failure(Status::NonFinite);
    }
    // Wound further, the angle would keep fewer than 7 digits below a turn.
    if (rotationReference->norm() > kMaxRotationWinding)
    {
      return R::failure(Status::OutOfRange);
    }
  }
  const auto polar = polarDecompose(m.topLeftCorner<3, 3>());
  if (!polar)
  {
    return R::failure(polar.status);
  }
  const PolarFactors& f = polar.value;
  R out;
  // A rigid map's stretch is I up to round-off: its log is 0 exactly, so that blends of rigid
  // maps are exactly rigid and take the rotation-only path of polarExp.
  Eigen::Matrix3d stretchOffset = f.stretch();
  stretchOffset.diagonal().array() -= 1.0;
  const bool rigid =
    stretchOffset.cwiseAbs().maxCoeff() <= 8.0 * std::numeric_limits<double>::epsilon();
  Eigen::Matrix3d logStretch = Eigen::Matrix3d::Zero();
  if (!rigid)
  {
    if (f.hasStretchAxes)
    {
      // log S = V diag(log sigma) V^T, every sigma relatively accurate (lct/SVD3.h).
      const Eigen::Vector3d logSigma = f.unitEigenvalues.array().log();
      logStretch = f.stretchAxes * logSigma.asDiagonal() * f.stretchAxes.transpose();
      logStretch = 0.5 * (logStretch + logStretch.transpose());
    }
    else
    {
      logStretch = logSPDClosedForm(f.unitStretch, f.unitEigenvalues);
    }
    // log(2^e S_unit) = log S_unit + e log 2 I.
    logStretch.diagonal().array() += f.exponent * kLn2;
  }
  translationPart(out.value) = m.topRightCorner<3, 1>();
  rotationPart(out.value) =
    rotationReference ? logSO3Nearest(f.rotation, *rotationReference) : logSO3(f.rotation);
  symmetricPart(out.value) = toSymmetricVector(logStretch);
  // The branch nearest a reference just below kMaxRotationWinding can lie up to pi beyond it:
  // polarExp would refuse it.
  if (!out.value.allFinite() || rotationPart(out.value).norm() > kMaxRotationWinding)
  {
    return R::failure(Status::OutOfRange);
  }
  return out;
}

Result<LogCoords> polarInverse(const LogCoords& c)
{
  const auto m = polarExp(c);
  if (!m)
  {
    return Result<LogCoords>::failure(m.status);
  }
  return polarInverse(c, m.value);
}

Result<LogCoords> polarInverse(const LogCoords& c, const Eigen::Matrix4d& m)
{
  using R = Result<LogCoords>;
  const Eigen::Matrix4d inverse = inverseAffine(m);
  if (!inverse.allFinite())
  {
    return R::failure(Status::OutOfRange);
  }
  const Eigen::Matrix3d u = expSO3(rotationPart(c));
  R out;
  translationPart(out.value) = inverse.topRightCorner<3, 1>();
  rotationPart(out.value) = -rotationPart(c);
  const Eigen::Matrix3d y = u * fromSymmetricVector(symmetricPart(c)) * u.transpose();
  symmetricPart(out.value) = -toSymmetricVector(0.5 * (y + y.transpose()));
  return out;
}

Result<Eigen::Matrix4d> polarExp(const LogCoords& c)
{
  using R = Result<Eigen::Matrix4d>;
  if (!c.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Matrix3d rotation = expSO3(rotationPart(c));
  Eigen::Matrix3d linear;
  // Rigid maps (Y = 0, the common case of cameras and skeletons) skip the stretch entirely.
  if (symmetricPart(c).isZero(0.0))
  {
    linear = rotation;
  }
  else
  {
    Eigen::Vector2d bounds;
    const Eigen::Matrix3d stretch = expSym(fromSymmetricVector(symmetricPart(c)), &bounds);
    // A stretch below the normal range has lost its digits (or is 0): the map is no longer
    // representable, rather than singular.
    // (A few ulps of 708 below log(DBL_MIN) are the rounding of the log of a stretch polarLog
    // accepted, at least DBL_MIN: such a stretch keeps its 52 bits but one.)
    if (!(bounds[0] > kLowestLogStretch - 1e-12) || !stretch.allFinite())
    {
      return R::failure(Status::OutOfRange);
    }
    if (bounds[1] - bounds[0] > kLogMaxConditionNumber)
    {
      return R::failure(Status::IllConditioned);
    }
    linear = rotation * stretch;
  }
  R out{ makeAffine(linear, translationPart(c)), Status::Ok };
  if (!out.value.allFinite())
  {
    return R::failure(Status::OutOfRange);
  }
  // Wound further, the turn keeps fewer than 7 digits below a turn (sin of 1e100 radians is any
  // value): a scalar multiple or a weighted sum of logs can get there.
  if (rotationPart(c).norm() > kMaxRotationWinding)
  {
    return R::failure(Status::InaccurateResult);
  }
  return out;
}

} // namespace lct
