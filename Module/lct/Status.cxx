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
    case Status::NegativeDeterminant:
      return "the determinant of the linear part is negative (a reflection is outside Aff+(3))";
    case Status::Singular:
      return "the linear part is singular (it flattens space: a zero scale or a zero determinant) "
             "and has no logarithm; to grow an object from nothing, start from a tiny positive "
             "scale such as 1e-6";
    case Status::IllConditioned:
      return "the linear part is numerically singular: too ill-conditioned (the ratio of its "
             "largest to its smallest stretch exceeds 1e13, beyond which double precision cannot "
             "represent the smallest stretch to 3 digits)";
    case Status::NoRealLogarithm:
      return "the linear part has a negative real eigenvalue (or one too close to the negative "
             "real axis for an accurate result), so it has no real matrix logarithm";
    case Status::OutOfRange:
      return "the result is out of the range of double precision (it overflows, or a stretch "
             "underflows to zero)";
    case Status::MagnitudeOutOfRange:
      return "the linear part's eigenvalue magnitudes lie outside 1e-135 .. 1e135, the range of "
             "the "
             "MatrixLog parametrisation (the Polar one takes any finite magnitude)";
    case Status::InaccurateResult:
      return "the result cannot be computed accurately in double precision from these inputs "
             "(the relative form between ill-conditioned keys loses the smallest stretch, or a "
             "turn wound beyond 1e9 rad keeps no digits below a turn); refused rather than "
             "returned inaccurate";
    case Status::NumericalFailure:
      return "an eigensolver did not converge on this input (a defect of vtkLCT: please report "
             "the matrix)";
    case Status::InvalidArgument:
      return "invalid argument (count, index or size)";
    case Status::RankDeficient:
      return "the basis is rank deficient (the logs of its transforms are linearly dependent, "
             "to the rank tolerance), so the coefficients of a transform are not unique";
  }
  return "unknown status";
}

} // namespace lct
