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

const char* name(Parametrisation p) noexcept
{
  return p == Parametrisation::MatrixLog ? "MatrixLog" : "Polar";
}

} // namespace lct
