#include "lct/Status.h"

namespace lct
{

const char* describe(Status status) noexcept
{
  switch (status)
  {
    case Status::Ok:
      return "ok";
    case Status::NonFinite:
      return "the matrix or coordinates contain NaN or Inf";
    case Status::NotAffine:
      return "the bottom row is not (0, 0, 0, 1): a projective matrix is not an affine transform";
    case Status::NonPositiveDeterminant:
      return "the determinant of the linear part is not positive (a reflection or a singular "
             "map is outside Aff+(3))";
    case Status::Singular:
      return "the linear part is numerically singular (a stretch eigenvalue is below round-off)";
    case Status::NoRealLogarithm:
      return "the linear part has a negative real eigenvalue (or one too close to the negative "
             "real axis for an accurate result), so it has no real matrix logarithm; use the "
             "polar parametrisation";
    case Status::InvalidArgument:
      return "invalid argument (count, index or size)";
  }
  return "unknown status";
}

} // namespace lct
