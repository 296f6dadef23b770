// Fuzz target: the pieces of the math core the parametrisations are built from, called directly:
// lct::polarDecompose, logSPD, sqrtSPD, expSym, expSO3 / logSO3 / logSO3Nearest, the 3x3
// eigenvalue solvers, matrixPower, combine / combineRelative and curveWeights. Each input is a
// short sequence of such calls.
//
// Properties: no crash or sanitizer report; an Ok result is finite and has the structure it
// promises (orthogonal rotation, symmetric stretch, weights that sum to 1, ...); functions
// without a status return finite values on the inputs where the exact value is representable;
// well-conditioned input is not refused; loose accuracy against independent formulas (Eigen's
// SVD and symmetric eigensolver), so that a wrong branch is caught and round-off is not.
#include "FuzzInput.h"

#include "lct/AccurateMinors.h"

#include "lct/Affine.h"
#include "lct/Combination.h"
#include "lct/Conditioning.h"
#include "lct/Curves.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"
#include "lct/SymmetricEigen3.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <vector>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;

/// A few units of the last place of the smallest subnormal: the floor of any tolerance relative
/// to a size that may itself be subnormal (there the relative one underflows to 0).
constexpr double kTiniest = 4.0 * std::numeric_limits<double>::denorm_min();

Eigen::Vector3d SingularValues(const Eigen::Matrix3d& a)
{
  return Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
}

/// A finite matrix with det > 0 whose singular values lie in [1e-290, 1e290] and span at most
/// `condition`: such input has digits to spare (the core scales every magnitude by a power of
/// two first), and refusing it would be a defect.
bool Comfortable(const Eigen::Matrix3d& a, double condition)
{
  // The sign from the accurate determinant: Eigen's rounded one can be positive for a reflection
  // whose determinant is below its rounding (D32: det -8.5e-17 of an all-ones-like matrix).
  if (!AllFinite(a) || !(lct::accurateDeterminant(a) > 0.0))
  {
    return false;
  }
  const Eigen::Vector3d s = SingularValues(a);
  return s[2] >= 1e-290 && s[0] <= 1e290 && s[0] <= condition * s[2];
}

Eigen::Matrix3d Symmetric(lct_fuzz::Input& in)
{
  switch (in.Byte() % 3)
  {
    case 0:
    {
      Eigen::Matrix3d y;
      y << in.Double(), in.Double(), in.Double(), 0, in.Double(), in.Double(), 0, 0, in.Double();
      y(1, 0) = y(0, 1);
      y(2, 0) = y(0, 2);
      y(2, 1) = y(1, 2);
      return y;
    }
    case 1:
    {
      const Eigen::Matrix3d r = in.Rotation();
      return r * in.Diagonal() * r.transpose();
    }
    default:
    {
      // c I plus a tiny symmetric perturbation: near-repeated eigenvalues.
      Eigen::Matrix3d y = in.Scale() * Eigen::Matrix3d::Identity();
      const double size = std::pow(10.0, -in.Int(0, 300));
      y(0, 1) = y(1, 0) = size * in.Provider().ConsumeFloatingPointInRange<double>(-1.0, 1.0);
      y(1, 2) = y(2, 1) = size * in.Provider().ConsumeFloatingPointInRange<double>(-1.0, 1.0);
      y(0, 0) += size * in.Provider().ConsumeFloatingPointInRange<double>(-1.0, 1.0);
      return y;
    }
  }
}

void PolarDecompose(lct_fuzz::Input& in)
{
  const Eigen::Matrix3d a = in.Linear();
  const auto polar = lct::polarDecompose(a);
  if (!polar)
  {
    LCT_FUZZ_CHECK(polar.status == lct::Status::NonFinite ||
        polar.status == lct::Status::NegativeDeterminant || polar.status == lct::Status::Singular ||
        polar.status == lct::Status::IllConditioned || polar.status == lct::Status::OutOfRange,
      "polarDecompose failed with an undocumented status " << lct::describe(polar.status));
    LCT_FUZZ_CHECK(!Comfortable(a, 1e12),
      "polarDecompose refused a well-conditioned matrix (" << lct::describe(polar.status) << "):\n"
                                                           << Show(a));
    return;
  }
  // lct/PolarDecomposition.h: A = U 2^exponent unitStretch, U a rotation, unitStretch SPD with
  // descending eigenvalues unitEigenvalues (and, on the SVD branch, stretchAxes as its basis).
  const lct::PolarFactors& f = polar.value;
  const Eigen::Matrix3d& u = f.rotation;
  const Eigen::Matrix3d& s = f.unitStretch;
  LCT_FUZZ_CHECK(AllFinite(u) && AllFinite(s) && AllFinite(f.unitEigenvalues),
    "polarDecompose: Ok with non-finite factors\n"
      << Show(a));
  LCT_FUZZ_CHECK(
    (u.transpose() * u - Eigen::Matrix3d::Identity()).norm() <= 1e-10 && u.determinant() > 0.0,
    "polarDecompose: the rotation factor is not a rotation\na =\n"
      << Show(a) << "\nU =\n"
      << Show(u));
  LCT_FUZZ_CHECK(s == s.transpose(), "polarDecompose: the stretch is not symmetric");
  const Eigen::Vector3d& l = f.unitEigenvalues;
  LCT_FUZZ_CHECK(l[0] >= l[1] && l[1] >= l[2] && l[2] > 0.0,
    "polarDecompose: unitEigenvalues not positive and descending: " << Show(l.transpose()));
  if (!Comfortable(a, 1e12))
  {
    return;
  }
  // A backward-stable polar decomposition reproduces A 2^-exponent (exact) to a modest multiple
  // of eps, and the eigenvalues of the stretch are the singular values of A.
  const Eigen::Matrix3d unit = lct::scaledByPowerOfTwo(a, -f.exponent);
  const double backward = (u * s - unit).norm() / unit.norm();
  LCT_FUZZ_CHECK(backward <= 1e-12,
    "polarDecompose: U unitStretch != 2^-exponent A (backward error "
      << backward << ", exponent " << f.exponent << ")\na =\n"
      << Show(a) << "\nU unitStretch =\n"
      << Show(u * s));
  // (Eigen's SVD of a general matrix is accurate to eps sigma_max only, so that is the test.)
  const Eigen::Vector3d sv = SingularValues(unit);
  LCT_FUZZ_CHECK((l - sv).cwiseAbs().maxCoeff() <= 1e-12 * sv[0],
    "polarDecompose: unitEigenvalues " << Show(l.transpose()) << " are not the singular values "
                                       << Show(sv.transpose()) << " of\n"
                                       << Show(unit));
  if (f.hasStretchAxes)
  {
    const Eigen::Matrix3d& v = f.stretchAxes;
    const Eigen::Matrix3d rebuilt = v * l.asDiagonal() * v.transpose();
    LCT_FUZZ_CHECK((rebuilt - s).norm() <= 1e-12 * s.norm(),
      "polarDecompose: stretchAxes diag(unitEigenvalues) stretchAxes^T != unitStretch");
  }
}

void LogAndSqrtSPD(lct_fuzz::Input& in)
{
  const Eigen::Matrix3d s = Symmetric(in);
  const bool spd = AllFinite(s) &&
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues().minCoeff() > 0.0;
  for (const bool log : { true, false })
  {
    const auto f = log ? lct::logSPD(s) : lct::sqrtSPD(s);
    const char* name = log ? "logSPD" : "sqrtSPD";
    if (!f)
    {
      // lct/Sym3.h: NonFinite, Singular, IllConditioned or OutOfRange.
      LCT_FUZZ_CHECK(f.status == lct::Status::NonFinite || f.status == lct::Status::Singular ||
          f.status == lct::Status::IllConditioned || f.status == lct::Status::OutOfRange,
        name << " failed with an undocumented status " << lct::describe(f.status));
      LCT_FUZZ_CHECK(!(spd && Comfortable(s, 1e12)),
        name << " refused a well-conditioned SPD matrix (" << lct::describe(f.status) << "):\n"
             << Show(s));
      continue;
    }
    LCT_FUZZ_CHECK(AllFinite(f.value),
      name << ": Ok with a non-finite result\ns =\n"
           << Show(s) << "\nresult =\n"
           << Show(f.value));
    LCT_FUZZ_CHECK(f.value == f.value.transpose(), name << ": the result is not symmetric");
    // (sqrt's round trip squares: magnitudes within 1e+-150.)
    if (spd && Comfortable(s, 1e6) && s.cwiseAbs().maxCoeff() <= 1e150 &&
      s.cwiseAbs().maxCoeff() >= 1e-150)
    {
      const Eigen::Matrix3d back = log ? lct::expSym(f.value) : Eigen::Matrix3d(f.value * f.value);
      LCT_FUZZ_CHECK((back - s).norm() <= 1e-9 * s.norm(),
        name << " is inaccurate: its inverse gives back\n"
             << Show(back) << "\ninstead of\n"
             << Show(s));
    }
  }
}

void ExpSym(lct_fuzz::Input& in)
{
  const Eigen::Matrix3d y = Symmetric(in);
  const Eigen::Matrix3d e = lct::expSym(y);
  if (!AllFinite(y))
  {
    return;
  }
  // The eigensolver behind the spread-spectrum branch (lct/SymmetricEigen3.h): backward stable
  // at any finite magnitude, values descending, vectors orthogonal. |eigenvalue| <= 3 max|y_ij|,
  // so the values are representable below DBL_MAX / 3 (above it they may overflow, as they must).
  const lct::SymmetricEigen3 eigen = lct::symmetricEigen3(y);
  const double size = y.cwiseAbs().maxCoeff();
  const bool representable = size <= std::numeric_limits<double>::max() / 3.0;
  LCT_FUZZ_CHECK(AllFinite(eigen.vectors) && (AllFinite(eigen.values) || !representable) &&
      eigen.values[0] >= eigen.values[1] && eigen.values[1] >= eigen.values[2],
    "symmetricEigen3: non-finite or unordered for\n"
      << Show(y));
  LCT_FUZZ_CHECK(
    (eigen.vectors.transpose() * eigen.vectors - Eigen::Matrix3d::Identity()).norm() <= 1e-13,
    "symmetricEigen3: vectors not orthogonal for\n"
      << Show(y));
  if (size > 0.0 && representable)
  {
    // Compared at unit size: the residual of a matrix near the ends of the range would overflow.
    const Eigen::Matrix3d unitY = y / size;
    const Eigen::Matrix3d rebuilt =
      eigen.vectors * (eigen.values / size).asDiagonal() * eigen.vectors.transpose();
    LCT_FUZZ_CHECK((rebuilt - unitY).norm() <= 1e-13 + kTiniest / size,
      "symmetricEigen3: V diag(l) V^T != Y for\n"
        << Show(y));
  }
  // Its eigenvalues are within +-||Y||_F, so below 700 exp(Y) is representable.
  if (y.norm() <= 700.0)
  {
    LCT_FUZZ_CHECK(AllFinite(e), "expSym is not finite for\n" << Show(y) << "\n->\n" << Show(e));
  }
  if (y.norm() <= 30.0)
  {
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(y);
    const Eigen::Matrix3d reference = eig.eigenvectors() *
      eig.eigenvalues().array().exp().matrix().asDiagonal() * eig.eigenvectors().transpose();
    LCT_FUZZ_CHECK((e - reference).norm() <= 1e-10 * reference.norm(),
      "expSym is inaccurate for\n"
        << Show(y) << "\nexpSym =\n"
        << Show(e) << "\nEigen =\n"
        << Show(reference));
  }
}

void Rotations(lct_fuzz::Input& in)
{
  Eigen::Vector3d w = in.Vector();
  if (in.Bool())
  {
    Eigen::Vector3d axis = in.Axis();
    const double n = axis.norm();
    w = (n > 0.0 && std::isfinite(n) ? Eigen::Vector3d(axis / n) : axis) * in.Angle();
  }
  const Eigen::Matrix3d r = lct::expSO3(w);
  const bool moderate = AllFinite(w) && w.norm() <= 1e15;
  if (moderate)
  {
    LCT_FUZZ_CHECK(
      AllFinite(r) && (r.transpose() * r - Eigen::Matrix3d::Identity()).norm() <= 1e-12,
      "expSO3 is not a rotation for w = " << Show(w.transpose()) << "\n"
                                          << Show(r));
  }
  Eigen::Matrix3d rotation;
  switch (in.Byte() % 3)
  {
    case 0:
      rotation = in.ExactRotation();
      break;
    case 1:
      rotation = in.Rotation();
      break;
    default:
      rotation = r;
      break;
  }
  // (Eigen's AngleAxis with a zero axis gives cos(angle) I, e.g. -I: not a rotation.)
  if (!AllFinite(rotation) ||
    !((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm() <= 1e-12) ||
    !(rotation.determinant() > 0.0))
  {
    return; // logSO3's precondition: a rotation (callers validate)
  }
  const Eigen::Vector3d v = lct::logSO3(rotation);
  LCT_FUZZ_CHECK(AllFinite(v) && v.norm() <= lct_fuzz::kPi * (1.0 + 1e-12),
    "logSO3 is not a principal log: " << Show(v.transpose()) << " for\n"
                                      << Show(rotation));
  LCT_FUZZ_CHECK((lct::expSO3(v) - rotation).norm() <= 1e-9,
    "expSO3(logSO3(R)) != R\nR =\n"
      << Show(rotation) << "\nlog = " << Show(v.transpose()));
  const Eigen::Vector3d reference = in.Vector();
  if (AllFinite(reference) && reference.norm() <= 1e6)
  {
    const Eigen::Vector3d nearest = lct::logSO3Nearest(rotation, reference);
    LCT_FUZZ_CHECK(AllFinite(nearest) && (lct::expSO3(nearest) - rotation).norm() <= 1e-6,
      "logSO3Nearest is not a log of R: " << Show(nearest.transpose()) << " for reference "
                                          << Show(reference.transpose()));
    LCT_FUZZ_CHECK((nearest - reference).norm() <= (v - reference).norm() + 1e-6,
      "logSO3Nearest is farther from the reference than the principal log: "
        << Show(nearest.transpose()) << " vs " << Show(v.transpose()) << ", reference "
        << Show(reference.transpose()));
  }
}

void Eigenvalues(lct_fuzz::Input& in)
{
  // Both solvers scale to unit size first, so every finite matrix up to ~1e300 (where ||A||
  // itself stays finite) gets finite eigenvalues, accurate relative to its largest entry.
  const Eigen::Matrix3d s = Symmetric(in);
  const double size = s.cwiseAbs().maxCoeff();
  if (AllFinite(s) && size > 0.0 && size <= 1e300)
  {
    const Eigen::Vector3d l = lct::symmetricEigenvalues(s);
    LCT_FUZZ_CHECK(AllFinite(l) && l[0] >= l[1] && l[1] >= l[2],
      "symmetricEigenvalues: not finite and descending: " << Show(l.transpose()) << " for\n"
                                                          << Show(s));
    const Eigen::Vector3d reference =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s / size).eigenvalues().reverse() * size;
    // At a double eigenvalue r = +-1 and acos turns an eps error into sqrt(eps) (the matrix
    // functions do not suffer, and refuse nothing for it since the spread-spectrum branch): so
    // sqrt(eps)-level here.
    LCT_FUZZ_CHECK((l - reference).cwiseAbs().maxCoeff() <= 3e-7 * size + kTiniest,
      "symmetricEigenvalues is inaccurate: " << Show(l.transpose()) << " vs Eigen's "
                                             << Show(reference.transpose()) << " for\n"
                                             << Show(s));
  }
  const Eigen::Matrix3d a = in.Linear();
  const double largest = a.cwiseAbs().maxCoeff();
  if (AllFinite(a) && largest <= 1e300)
  {
    const lct::GeneralEigenvalues e = lct::generalEigenvalues(a);
    std::complex<double> sum = 0.0;
    for (const auto& v : e.values)
    {
      LCT_FUZZ_CHECK(std::isfinite(v.real()) && std::isfinite(v.imag()),
        "generalEigenvalues: a non-finite eigenvalue " << v << " of\n"
                                                       << Show(a));
      sum += v;
    }
    // The trace is the sum of the eigenvalues, which the shifted cubic keeps to round-off.
    LCT_FUZZ_CHECK(std::abs(sum - a.trace()) <= 1e-8 * 3.0 * largest + kTiniest,
      "generalEigenvalues: the sum " << sum << " is not the trace " << a.trace() << " of\n"
                                     << Show(a));
    if (e.complexPair)
    {
      LCT_FUZZ_CHECK(e.values[0] == std::conj(e.values[1]) && e.values[2].imag() == 0.0,
        "generalEigenvalues: not a conjugate pair and a real root");
    }
  }
}

void MatrixPower(lct_fuzz::Input& in)
{
  const Eigen::Matrix4d m = in.Matrix();
  const double s = in.Double();
  const auto p = lct::matrixPower(m, s);
  if (p)
  {
    LCT_FUZZ_CHECK(AllFinite(p.value),
      "matrixPower: Ok with a non-finite result, s = " << s << "\nm =\n"
                                                       << Show(m) << "\nresult =\n"
                                                       << Show(p.value));
  }
}

void Combinations(lct_fuzz::Input& in)
{
  const int count = in.Int(1, 4);
  std::vector<Eigen::Matrix4d> keys;
  std::vector<double> weights;
  for (int i = 0; i < count; ++i)
  {
    keys.push_back(in.Byte() % 4 ? in.Affine() : in.Matrix());
    weights.push_back(
      in.Byte() % 2 ? in.Double() : in.Provider().ConsumeFloatingPointInRange<double>(-1.0, 2.0));
  }
  const std::size_t reference = static_cast<std::size_t>(in.Int(0, 4));
  const lct::Parametrisation p =
    in.Bool() ? lct::Parametrisation::Polar : lct::Parametrisation::MatrixLog;
  if (lct_fuzz::Verbose())
  {
    std::fprintf(stderr, "combine, %s, reference %zu\n", lct::name(p), reference);
    for (int i = 0; i < count; ++i)
    {
      std::fprintf(stderr, "weight %.17g, key\n%s\n", weights[i], Show(keys[i]).c_str());
    }
  }
  const auto absolute = lct::combine(weights.data(), keys.data(), keys.size(), p);
  if (absolute)
  {
    LCT_FUZZ_CHECK(AllFinite(absolute.value), "combine: Ok with a non-finite result");
  }
  const auto relative =
    lct::combineRelative(weights.data(), keys.data(), keys.size(), reference, p);
  if (relative)
  {
    LCT_FUZZ_CHECK(AllFinite(relative.value),
      "combineRelative: Ok with a non-finite result\n"
        << Show(relative.value));
  }
  else if (reference >= keys.size())
  {
    LCT_FUZZ_CHECK(relative.status == lct::Status::InvalidArgument,
      "combineRelative: an out-of-range reference gave " << lct::describe(relative.status));
  }
}

void Weights(lct_fuzz::Input& in)
{
  const std::vector<double> times = in.KeyTimes(1, 12);
  const int keys = static_cast<int>(times.size());
  const double t = in.QueryTime();
  const lct::CurveScheme scheme = static_cast<lct::CurveScheme>(in.Int(0, 4));
  // A finite span is a precondition (lct/Curves.h; the interpolators refuse key times that
  // break it): beyond it nothing is promised but the absence of undefined behaviour (D11: NaN
  // weights and a float-cast-overflow in the subdivision table).
  if (!std::isfinite(times.back() - times.front()))
  {
    (void)lct::curveWeights(scheme, times.data(), keys, t);
    return;
  }
  const lct::CurveWeights w = lct::curveWeights(scheme, times.data(), keys, t);
  const int points = scheme == lct::CurveScheme::Bezier ? 3 * (keys - 1) + 1 : keys;
  LCT_FUZZ_CHECK(w.count >= 1 && w.count <= lct::CurveWeights::kCapacity,
    "curveWeights: " << w.count << " weights");
  double sum = 0.0;
  for (int j = 0; j < w.count; ++j)
  {
    LCT_FUZZ_CHECK(w.key[j] >= 0 && w.key[j] < points,
      "curveWeights: key index " << w.key[j] << " outside [0, " << points << ")");
    LCT_FUZZ_CHECK(std::isfinite(w.weight[j]),
      "curveWeights: weight " << w.weight[j] << " at t = " << t << ", times "
                              << lct_fuzz::Show(times.data(), keys) << ", scheme "
                              << static_cast<int>(scheme));
    sum += w.weight[j];
  }
  LCT_FUZZ_CHECK(std::abs(sum - 1.0) <= 1e-9,
    "curveWeights: the weights sum to " << sum << " at t = " << t << ", times "
                                        << lct_fuzz::Show(times.data(), keys) << ", scheme "
                                        << static_cast<int>(scheme));
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  for (int op = 0; op < 8 && !in.Empty(); ++op)
  {
    switch (in.Byte() % 8)
    {
      case 0:
        PolarDecompose(in);
        break;
      case 1:
        LogAndSqrtSPD(in);
        break;
      case 2:
        ExpSym(in);
        break;
      case 3:
        Rotations(in);
        break;
      case 4:
        Eigenvalues(in);
        break;
      case 5:
        MatrixPower(in);
        break;
      case 6:
        Combinations(in);
        break;
      default:
        Weights(in);
        break;
    }
  }
  return 0;
}
