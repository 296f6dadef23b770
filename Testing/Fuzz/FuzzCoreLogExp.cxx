// Fuzz target: lct::logarithm / lct::exponential (Module/lct/Parametrisation.h) in both
// parametrisations, from 16 arbitrary doubles or a structured affine matrix, with and without a
// rotation reference, and exp of 12 arbitrary log coordinates.
//
// Properties: no crash or sanitizer report; a result that says Ok is finite; a matrix outside
// Aff+(3) is refused; exp of an accepted log succeeds and gives the matrix back (loosely, where
// the matrix is well conditioned, so that a silently wrong log is caught and round-off is not).
#include "FuzzInput.h"

#include "lct/Affine.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <complex>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;

/// Whether exp(log m) must be computable: moderate entries and condition number.
bool RoundTripRepresentable(const Eigen::Matrix4d& m)
{
  const Eigen::Vector3d s =
    Eigen::JacobiSVD<Eigen::Matrix3d>(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).singularValues();
  return m.cwiseAbs().maxCoeff() <= 1e100 && s[2] > 0.0 && s[0] / s[2] <= 1e12;
}

/// Whether exp(log m) must reproduce m to `tolerance`: finite, affine, moderate magnitudes and a
/// condition number where double precision still has digits to give.
bool WellConditioned(const Eigen::Matrix4d& m, double& tolerance)
{
  if (lct::validateAffine(m) != lct::Status::Ok)
  {
    return false;
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
  if (!(s[2] > 0.0) || !(s[0] < 1e50) || !(s[2] > 1e-50) ||
    !(m.topRightCorner<3, 1>().norm() < 1e50))
  {
    return false;
  }
  const double condition = s[0] / s[2];
  if (!(condition <= 1e6))
  {
    return false;
  }
  // Orders of magnitude above the README's measured errors (1e-13 .. 5e-12): a failure here is
  // a wrong logarithm, not round-off.
  tolerance = 1e-8 * condition;
  return true;
}

/// The statuses the headers document for a refused log (lct/PolarParametrisation.h polarLog,
/// lct/MatrixLogParametrisation.h matrixLog).
bool DocumentedLogFailure(lct::Status s, lct::Parametrisation p)
{
  using lct::Status;
  const bool both = s == Status::NonFinite || s == Status::NotAffine ||
    s == Status::NegativeDeterminant || s == Status::Singular || s == Status::IllConditioned;
  return both ||
    (p == lct::Parametrisation::Polar ? s == Status::OutOfRange
                                      : s == Status::MagnitudeOutOfRange ||
          s == Status::NoRealLogarithm || s == Status::OutOfRange);
}

/// Whether the log of m must exist: an affine map of positive determinant, condition number well
/// inside kMaxConditionNumber, and magnitudes inside the parametrisation's domain (Polar: a
/// normal smallest stretch; MatrixLog: 1e+-135, so 1e+-130 with margin, and no eigenvalue on or
/// near the negative real axis, where the log is refused or checked a posteriori).
bool LogMustExist(const Eigen::Matrix4d& m, lct::Parametrisation p)
{
  if (lct::validateAffine(m) != lct::Status::Ok || !(m.topRightCorner<3, 1>().norm() < 1e300))
  {
    return false;
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const Eigen::Vector3d s = Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
  if (!(s[2] > 0.0) || !(s[0] <= 1e12 * s[2]) || a.determinant() <= 0.0)
  {
    return false;
  }
  if (p == lct::Parametrisation::Polar)
  {
    return s[2] >= 1e-300 && s[0] <= 1e300;
  }
  // matrixLog checks its round trip a posteriori beyond ||A||_F^3 / det A = 1e4: only below
  // that, and away from the negative real axis (pairs turned by less than ~120 degrees), is a
  // refusal a defect.
  if (!(s[2] >= 1e-130 && s[0] <= 1e130 && s[0] <= 10.0 * s[2]) ||
    !(m.topRightCorner<3, 1>().norm() <= 1e100 * s[0]))
  {
    return false;
  }
  const Eigen::Vector3cd lambda = Eigen::EigenSolver<Eigen::Matrix3d>(a, false).eigenvalues();
  for (int i = 0; i < 3; ++i)
  {
    const std::complex<double> z = lambda[i];
    if (z.real() <= 0.0 && std::abs(z.imag()) < -1.7 * z.real())
    {
      return false;
    }
  }
  return true;
}

void CheckLog(const Eigen::Matrix4d& m, lct::Parametrisation p, const lct::LogCoords* reference)
{
  const auto log = lct::logarithm(m, p, reference);
  const lct::Status valid = lct::validateAffine(m);
  if (valid != lct::Status::Ok)
  {
    LCT_FUZZ_CHECK(!log.ok(),
      lct::name(p) << " log accepted a matrix outside Aff+(3) (" << lct::describe(valid) << "):\n"
                   << Show(m));
    return;
  }
  // polarLog validates its rotation reference: NonFinite, or OutOfRange beyond
  // kMaxRotationWinding (MatrixLog ignores it).
  const bool polarReference = p == lct::Parametrisation::Polar && reference;
  const Eigen::Vector3d w =
    reference ? Eigen::Vector3d(lct::rotationPart(*reference)) : Eigen::Vector3d::Zero();
  if (polarReference && !AllFinite(w))
  {
    LCT_FUZZ_CHECK(log.status == lct::Status::NonFinite,
      "Polar log with a non-finite reference: " << lct::describe(log.status) << ", not NonFinite");
    return;
  }
  if (polarReference && w.norm() > 1.01 * lct::kMaxRotationWinding)
  {
    LCT_FUZZ_CHECK(log.status == lct::Status::OutOfRange,
      "Polar log with a reference wound beyond kMaxRotationWinding (|w| = "
        << w.norm() << "): " << lct::describe(log.status) << ", not OutOfRange");
    return;
  }
  if (!log)
  {
    LCT_FUZZ_CHECK(DocumentedLogFailure(log.status, p),
      lct::name(p) << " log failed with an undocumented status " << lct::describe(log.status));
    LCT_FUZZ_CHECK(
      !LogMustExist(m, p) || (polarReference && w.norm() > 0.99 * lct::kMaxRotationWinding),
      lct::name(p) << " log refused a well-conditioned map in its domain ("
                   << lct::describe(log.status) << ")\nm =\n"
                   << Show(m));
    return;
  }
  LCT_FUZZ_CHECK(AllFinite(log.value),
    lct::name(p) << " log returned Ok with non-finite coordinates\nm =\n"
                 << Show(m) << "\nlog = " << Show(log.value.transpose()));
  const auto back = lct::exponential(log.value, p);
  // A reference wound far from the identity (Kaji & Ochiai Algorithm 1 picks the branch nearest to
  // it) leaves a rotation vector of the reference's size, whose angle has no digits left below
  // ~|w| eps; the round trip is only expected for references of moderate size.
  if (reference && !(w.norm() <= 1e6))
  {
    LCT_FUZZ_CHECK(!back.ok() || AllFinite(back.value),
      lct::name(p) << " exp returned Ok with non-finite matrix");
    return;
  }
  // The round trip may overflow (and say so) next to the overflow threshold, or be refused as
  // IllConditioned when round-off lifts the condition number past the limit. Expected to succeed
  // where neither applies.
  if (!back && !RoundTripRepresentable(m))
  {
    return;
  }
  LCT_FUZZ_CHECK(back.ok(),
    lct::name(p) << " exp of an accepted log failed (" << lct::describe(back.status) << ")\nm =\n"
                 << Show(m) << "\nlog = " << Show(log.value.transpose()));
  LCT_FUZZ_CHECK(AllFinite(back.value), lct::name(p) << " exp returned Ok with non-finite matrix");
  double tolerance = 0.0;
  if (WellConditioned(m, tolerance))
  {
    const double linear = (back.value.topLeftCorner<3, 3>() - m.topLeftCorner<3, 3>()).norm() /
      m.topLeftCorner<3, 3>().norm();
    const double translation =
      (back.value.topRightCorner<3, 1>() - m.topRightCorner<3, 1>()).norm() /
      std::max(1.0, m.topRightCorner<3, 1>().norm()) /
      std::max(1.0, m.topLeftCorner<3, 3>().norm());
    LCT_FUZZ_CHECK(linear <= tolerance && translation <= tolerance,
      lct::name(p) << " exp(log m) != m: relative errors " << linear << " (linear), " << translation
                   << " (translation), tolerance " << tolerance << "\nm =\n"
                   << Show(m) << "\nexp(log m) =\n"
                   << Show(back.value) << "\nlog = " << Show(log.value.transpose()));
  }
}

void CheckExp(const lct::LogCoords& c, lct::Parametrisation p)
{
  const auto e = lct::exponential(c, p);
  if (!AllFinite(c))
  {
    LCT_FUZZ_CHECK(e.status == lct::Status::NonFinite,
      lct::name(p) << " exp of non-finite coordinates: " << lct::describe(e.status)
                   << ", not NonFinite");
    return;
  }
  if (!e)
  {
    // lct/Parametrisation.h: NonFinite (only for non-finite c), OutOfRange, IllConditioned,
    // MagnitudeOutOfRange (MatrixLog: a representable result beyond its 1e+-135), or
    // InaccurateResult for a turn beyond kMaxRotationWinding (MatrixLog: that needs a skew part
    // of that size, Bendixson: |Im lambda| <= ||skew(L)||_2 = |w|).
    const bool woundTooFar = e.status == lct::Status::InaccurateResult &&
      lct::rotationPart(c).norm() > lct::kMaxRotationWinding;
    const bool beyondMatrixLogRange =
      p == lct::Parametrisation::MatrixLog && e.status == lct::Status::MagnitudeOutOfRange;
    LCT_FUZZ_CHECK(e.status == lct::Status::OutOfRange || e.status == lct::Status::IllConditioned ||
        woundTooFar || beyondMatrixLogRange,
      lct::name(p) << " exp failed with " << lct::describe(e.status)
                   << " (documented: OutOfRange, IllConditioned, MagnitudeOutOfRange for "
                      "MatrixLog, or InaccurateResult for a turn beyond 1e9 rad)\nc = "
                   << Show(c.transpose()));
    // Coordinates of moderate size have a representable, well-conditioned exp: with every
    // |c_i| <= 1 the log's linear part has ||L||_F <= 5, so exp(L) has condition <= e^10.
    LCT_FUZZ_CHECK(!(c.cwiseAbs().maxCoeff() <= 1.0),
      lct::name(p) << " exp refused coordinates of moderate size (" << lct::describe(e.status)
                   << ")\nc = " << Show(c.transpose()));
    return;
  }
  LCT_FUZZ_CHECK(AllFinite(e.value),
    lct::name(p) << " exp returned Ok with a non-finite matrix\nc = " << Show(c.transpose())
                 << "\nexp =\n"
                 << Show(e.value));
  LCT_FUZZ_CHECK(e.value.row(3) == Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0),
    lct::name(p) << " exp is not affine:\n"
                 << Show(e.value));
  // The log of the result is allowed to fail (e.g. a stretch too anisotropic to invert), but not
  // to return non-finite coordinates; CheckLog tests that and the round trip.
  CheckLog(e.value, p, nullptr);
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  // (a) of the issue: 16 arbitrary doubles, or a structured matrix with the special cases.
  const Eigen::Matrix4d m = in.Matrix();
  const bool withReference = in.Bool();
  const lct::LogCoords reference = in.Coordinates();
  const lct::LogCoords coordinates = in.Coordinates();
  if (lct_fuzz::Verbose())
  {
    std::fprintf(stderr, "m =\n%s\nreference (%s) = %s\ncoordinates = %s\n", Show(m).c_str(),
      withReference ? "used" : "unused", Show(reference.transpose()).c_str(),
      Show(coordinates.transpose()).c_str());
  }
  for (const lct::Parametrisation p :
    { lct::Parametrisation::Polar, lct::Parametrisation::MatrixLog })
  {
    CheckLog(m, p, withReference ? &reference : nullptr);
    CheckExp(coordinates, p);
  }
  return 0;
}
