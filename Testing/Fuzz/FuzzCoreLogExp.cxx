// Fuzz target: lct::logarithm / lct::exponential (Module/lct/Parametrisation.h) in both
// parametrisations, from 16 arbitrary doubles or a structured affine matrix, with and without a
// rotation reference, and exp of 12 arbitrary log coordinates.
//
// Properties: no crash or sanitizer report; a result that says Ok is finite; a matrix outside
// Aff+(3) is refused; exp of an accepted log succeeds and gives the matrix back (loosely, where
// the matrix is well conditioned, so that a silently wrong log is caught and round-off is not).
#include "FuzzInput.h"
#include "FuzzMatrixLogGuards.h"

#include "lct/Affine.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"

#include <Eigen/SVD>

#include <algorithm>
#include <complex>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;

// KNOWN: D1, D2: see FuzzMatrixLogGuards.h (lct_fuzz::KnownCubic).
using lct_fuzz::KnownCubic;

// KNOWN: D3 (Testing/Fuzz/README.md). For the log of an SPD matrix whose eigenvalues cluster
// (spread <= 1/4 of their mean) newtonCoefficients sums a Taylor series whose coefficients
// (1/c)^k and node powers (x - c)^j are formed separately: for a stretch far from 1 (mean below
// ~1e-51 with a tight cluster, nearer 1 for a wider one; or large) one of them overflows, and
// polarLog / logSPD return Ok with Inf/NaN coordinates, e.g. the Polar log of
// R_z(0.3) diag(1, 1 + 1e-7, 1 + 3e-7) * 1e-60. Skipped where the trigger holds: a non-finite
// symmetric part from a stretch whose singular values cluster (margin 0.3 for round-off).
bool KnownClusteredLogSeries(const Eigen::Matrix4d& m, const lct::LogCoords& log)
{
  if (AllFinite(lct::symmetricPart(log)))
  {
    return false;
  }
  const Eigen::Vector3d s =
    Eigen::JacobiSVD<Eigen::Matrix3d>(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).singularValues();
  const double mean = s.sum() / 3.0;
  return lct_fuzz::Known("D3", s[0] - s[2] <= 0.3 * mean);
}

// KNOWN: D5 (Testing/Fuzz/README.md). seriesDividedDifference stops after two consecutive terms
// below round-off. About the centroid of the nodes, h_1 = sum (x - c) is always 0 and
// h_2 = sum (x - c)^2 / 2 vanishes when complex nodes are placed symmetrically (three at the
// corners of an equilateral triangle, four at those of a square): the series then stops after the
// j = 2 term and drops the leading j = 3 one. MatrixLog meets this when a conjugate pair of
// eigenvalues and its extra node (0 for exp, 1 for log) form an equilateral triangle, e.g. exp of
// the log coordinates (0.099999985613770687, 0.099999985613770687, 0.10000008126820874 |
// 0.070710678118654766, -0.070710678118654766, 0 | 0.10000013814593467, 0.10000013814593467,
// 0.10000000000000009, 0.09999986185406548, 0, 0): the pair 0.15 +- 0.0866i with node 0 gives
// f[z, conj z, 0] wrong by 1.7e-5 and a translation wrong by 8.8e-8 (against Eigen's exp).
// Skipped when a round trip is inaccurate and a subset of the nodes has a
// near-zero sum of centred squares.
bool KnownSymmetricNodes(const Eigen::Matrix3d& a, double extraNode)
{
  const lct::GeneralEigenvalues e = lct::generalEigenvalues(a);
  const std::complex<double> nodes[4] = { e.values[0], e.values[1], e.values[2], extraNode };
  for (unsigned mask = 1; mask < 16; ++mask)
  {
    std::complex<double> w[4];
    int count = 0;
    std::complex<double> centre = 0.0;
    for (int i = 0; i < 4; ++i)
    {
      if (mask & (1u << i))
      {
        w[count++] = nodes[i];
        centre += nodes[i];
      }
    }
    if (count < 3)
    {
      continue;
    }
    centre /= static_cast<double>(count);
    std::complex<double> squares = 0.0;
    double size = 0.0;
    for (int i = 0; i < count; ++i)
    {
      squares += (w[i] - centre) * (w[i] - centre);
      size += std::norm(w[i] - centre);
    }
    if (size > 0.0 && std::abs(squares) <= 1e-6 * size)
    {
      return lct_fuzz::Known("D5", true);
    }
  }
  return false;
}

/// Whether exp(log m) must be computable: moderate entries and condition number.
bool RoundTripRepresentable(const Eigen::Matrix4d& m)
{
  const Eigen::Vector3d s =
    Eigen::JacobiSVD<Eigen::Matrix3d>(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).singularValues();
  return m.cwiseAbs().maxCoeff() <= 1e100 && s[2] > 0.0 && s[0] / s[2] <= 1e14;
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

void CheckLog(const Eigen::Matrix4d& m, lct::Parametrisation p, const lct::LogCoords* reference)
{
  if (p == lct::Parametrisation::MatrixLog && lct::validateAffine(m) == lct::Status::Ok &&
    KnownCubic(m.topLeftCorner<3, 3>()))
  {
    return;
  }
  const auto log = lct::logarithm(m, p, reference);
  const lct::Status valid = lct::validateAffine(m);
  if (valid != lct::Status::Ok)
  {
    LCT_FUZZ_CHECK(!log.ok(),
      lct::name(p) << " log accepted a matrix outside Aff+(3) (" << lct::describe(valid) << "):\n"
                   << Show(m));
    return;
  }
  if (!log)
  {
    return;
  }
  if (p == lct::Parametrisation::Polar && KnownClusteredLogSeries(m, log.value))
  {
    return;
  }
  // KNOWN: D4 (Testing/Fuzz/README.md). logarithm() does not validate `reference`: with a
  // non-finite rotation reference, or one so large that axis . reference overflows (|r|_1 beyond
  // DBL_MAX), nearestEquivalentRotation returns Inf/NaN and the Polar log says Ok.
  if (p == lct::Parametrisation::Polar && reference &&
    lct_fuzz::Known("D4",
      !(lct::rotationPart(*reference).cwiseAbs().sum() <= std::numeric_limits<double>::max())))
  {
    return;
  }
  LCT_FUZZ_CHECK(AllFinite(log.value),
    lct::name(p) << " log returned Ok with non-finite coordinates\nm =\n"
                 << Show(m) << "\nlog = " << Show(log.value.transpose()));
  if (p == lct::Parametrisation::MatrixLog && KnownCubic(lct::logLinearPart(log.value)))
  {
    return;
  }
  const auto back = lct::exponential(log.value, p);
  // A reference wound far from the identity (Kaji & Ochiai Algorithm 1 picks the branch nearest to
  // it) leaves a rotation vector of the reference's size, whose angle has no digits left below
  // ~|w| eps; the round trip is only expected for references of moderate size.
  if (reference && !(lct::rotationPart(*reference).norm() <= 1e6))
  {
    LCT_FUZZ_CHECK(!back.ok() || AllFinite(back.value),
      lct::name(p) << " exp returned Ok with non-finite matrix");
    return;
  }
  // The round trip may overflow (and say so) next to the overflow threshold, or for a map so
  // ill-conditioned that its log has entries whose square overflows in the closed form (MatrixLog
  // has no singularity test: cond 1e278 passes). Expected to succeed where neither applies.
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
    const bool accurate = linear <= tolerance && translation <= tolerance;
    if (!accurate && p == lct::Parametrisation::MatrixLog &&
      (KnownSymmetricNodes(m.topLeftCorner<3, 3>(), 1.0) ||
        KnownSymmetricNodes(lct::logLinearPart(log.value), 0.0)))
    {
      return;
    }
    LCT_FUZZ_CHECK(accurate,
      lct::name(p) << " exp(log m) != m: relative errors " << linear << " (linear), " << translation
                   << " (translation), tolerance " << tolerance << "\nm =\n"
                   << Show(m) << "\nexp(log m) =\n"
                   << Show(back.value) << "\nlog = " << Show(log.value.transpose()));
  }
}

void CheckExp(const lct::LogCoords& c, lct::Parametrisation p)
{
  if (p == lct::Parametrisation::MatrixLog && KnownCubic(lct::logLinearPart(c)))
  {
    return;
  }
  const auto e = lct::exponential(c, p);
  if (!AllFinite(c))
  {
    LCT_FUZZ_CHECK(!e.ok(), lct::name(p) << " exp accepted non-finite coordinates");
    return;
  }
  if (!e)
  {
    LCT_FUZZ_CHECK(e.status == lct::Status::NonFinite,
      lct::name(p) << " exp failed with " << lct::describe(e.status)
                   << " (documented: only NonFinite)");
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
