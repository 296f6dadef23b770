/**
 * @file Status.h
 * @brief Failures of the math core as values: a status code and a result carrying it.
 *
 * The core never throws and never hands out NaN. A function that can fail returns a
 * `Result<T>` whose `status` says why it failed; `value` is meaningful only when `ok()`.
 */
#ifndef lct_Status_h
#define lct_Status_h

#include "vtkLCTModule.h"

namespace lct
{

/// Why a computation of the core failed.
enum class Status
{
  Ok = 0,
  NonFinite,           ///< an input (or a result) holds NaN or Inf
  NotAffine,           ///< the bottom row of a 4x4 matrix is not (0, 0, 0, 1)
  NegativeDeterminant, ///< det < 0: a reflection, outside Aff+(3) (det = 0 is Singular)
  Singular,            ///< singular: a zero stretch (det = 0, or sigma_min = 0 in double)
  IllConditioned,      ///< sigma_max / sigma_min above kMaxConditionNumber (lct/Conditioning.h)
  NoRealLogarithm,     ///< a negative real eigenvalue (or too close to one for an accurate log)
  OutOfRange,          ///< the result overflows (or underflows to a singular map) in double
  MagnitudeOutOfRange, ///< MatrixLog only: eigenvalue magnitudes beyond 2^+-450
  InaccurateResult,    ///< the result cannot be computed accurately in double from these inputs
  NumericalFailure,    ///< an eigensolver did not converge (a defect: please report the input)
  InvalidArgument,     ///< sizes, counts or indices that make no sense
  RankDeficient        ///< a basis whose logs are linearly dependent: coefficients not unique
};

/// A one-line English description of `status`, suitable for an error message.
VTKLCT_EXPORT const char* describe(Status status) noexcept;

/// A value or the reason there is none.
template <typename T>
struct Result
{
  T value{};
  Status status = Status::Ok;

  bool ok() const noexcept { return status == Status::Ok; }
  explicit operator bool() const noexcept { return ok(); }

  static Result failure(Status why)
  {
    Result r;
    r.status = why;
    return r;
  }
};

} // namespace lct

#endif
