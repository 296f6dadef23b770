#include "lct/Parametrisation.h"

#include "lct/MatrixLogParametrisation.h"
#include "lct/PolarParametrisation.h"

namespace lct
{

Result<LogCoords> logarithm(const Eigen::Matrix4d& m, Parametrisation p, const LogCoords* reference)
{
  if (p == Parametrisation::MatrixLog)
  {
    return matrixLog(m);
  }
  if (reference)
  {
    const Eigen::Vector3d rotationReference = rotationPart(*reference);
    return polarLog(m, &rotationReference);
  }
  return polarLog(m);
}

Result<Eigen::Matrix4d> exponential(const LogCoords& c, Parametrisation p)
{
  return p == Parametrisation::MatrixLog ? matrixExp(c) : polarExp(c);
}

const char* adviceFor(Status status, Parametrisation p) noexcept
{
  const bool polarWouldWork =
    status == Status::NoRealLogarithm || status == Status::MagnitudeOutOfRange;
  return p == Parametrisation::MatrixLog && polarWouldWork
    ? " (the Polar parametrisation, SetParametrisationToPolar(), has a logarithm for every "
      "orientation-preserving map of any magnitude)"
    : "";
}

const char* name(Parametrisation p) noexcept
{
  return p == Parametrisation::MatrixLog ? "MatrixLog" : "Polar";
}

} // namespace lct
