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
#include "FuzzMatrixLogGuards.h"

#include "lct/Affine.h"
#include "lct/Combination.h"
#include "lct/Curves.h"
#include "lct/Eigenvalues3.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarDecomposition.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <complex>
#include <vector>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;

Eigen::Vector3d SingularValues(const Eigen::Matrix3d& a)
{
  return Eigen::JacobiSVD<Eigen::Matrix3d>(a).singularValues();
}

/// A finite matrix with det > 0 whose singular values lie in [1e-30, 1e30] and span at most
/// `condition`: such input has digits to spare, and refusing it would be a defect.
bool Comfortable(const Eigen::Matrix3d& a, double condition)
{
  if (!AllFinite(a) || !(a.determinant() > 0.0))
  {
    return false;
  }
  const Eigen::Vector3d s = SingularValues(a);
  return s[2] >= 1e-30 && s[0] <= 1e30 && s[0] <= condition * s[2];
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

// KNOWN: D6 (Testing/Fuzz/README.md). symmetricEigenvalues forms r = det(B) / (2 p2 p) with
// p2 = tr(B^2) / 6 of the traceless part B; when ||B|| is tiny but not zero (about 1e-104 ..
// 1e-162 in absolute terms) p2 p underflows to 0 and r = 0/0: all three eigenvalues are NaN, and
// logSPD / sqrtSPD refuse a perfectly good SPD matrix as NonFinite (so does the Polar log, e.g. of
// 2 I + 1e-110 (e_xy + e_yx)). The same 0/0 hits generalEigenvalues' three-real-roots branch
// (D1). Skipped where the trigger holds.
bool KnownTinyAnisotropy(const Eigen::Matrix3d& s)
{
  const double shift = s.trace() / 3.0;
  const double b00 = s(0, 0) - shift, b11 = s(1, 1) - shift, b22 = s(2, 2) - shift;
  const double p2 = (b00 * b00 + b11 * b11 + b22 * b22 +
                      2.0 * (s(0, 1) * s(0, 1) + s(0, 2) * s(0, 2) + s(1, 2) * s(1, 2))) /
    6.0;
  return lct_fuzz::Known("D6", p2 > 0.0 && !(p2 * std::sqrt(p2) > 0.0));
}

// KNOWN: D9 (Testing/Fuzz/README.md). symmetricEigenvalues finds a double eigenvalue only to
// ~sqrt(eps) ||B|| (r = +-1, where acos has an infinite slope), not to eps ||A|| as its header
// says. Harmless for the matrix functions of well-conditioned input, but when the two smallest
// eigenvalues are both small against the largest (a near-double root as far as the cubic can
// tell), the error exceeds the smallest: logSPD, sqrtSPD and the Polar log refuse a valid SPD
// matrix as Singular (eigenvalues 522, 1e-8, 1e-8 come out as 522, 2.1e-6, -2.1e-6; 1e-3, 1e-8,
// 1.8e-15 (cond 5.6e11, threshold 5.6e14) as 1e-3, 1e-8, -6.4e-16). Skipped where the trigger
// holds (both below 1e-4 of the largest).
bool KnownDoubleSmallEigenvalue(const Eigen::Matrix3d& s, lct::Status status)
{
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues();
  return lct_fuzz::Known("D9", status == lct::Status::Singular && l[1] <= 1e-4 * l[2]);
}

// KNOWN: D3 (see FuzzCoreLogExp.cxx): the clustered-eigenvalue series of the log overflows for
// a stretch far from 1, and logSPD says Ok with Inf/NaN.
bool KnownClusteredLogSeries(const Eigen::Matrix3d& s, const Eigen::Matrix3d& result)
{
  if (AllFinite(result))
  {
    return false;
  }
  const Eigen::Vector3d l = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues();
  const double mean = l.sum() / 3.0;
  return lct_fuzz::Known("D3", l[2] - l[0] <= 0.3 * std::abs(mean));
}

// KNOWN: D1, D2: see FuzzMatrixLogGuards.h (lct_fuzz::KnownCubic).
using lct_fuzz::KnownCubic;

void PolarDecompose(lct_fuzz::Input& in)
{
  const Eigen::Matrix3d a = in.Linear();
  const auto polar = lct::polarDecompose(a);
  if (!polar)
  {
    LCT_FUZZ_CHECK(polar.status == lct::Status::NonFinite ||
        polar.status == lct::Status::NegativeDeterminant ||
        polar.status == lct::Status::Singular || polar.status == lct::Status::IllConditioned,
      "polarDecompose failed with an undocumented status " << lct::describe(polar.status));
    // D12 (below): near rank one the Newton iterates can also overflow, and a good matrix is
    // refused as NonFinite (all entries 1 +- 5e-8).
    const Eigen::Vector3d sv = SingularValues(a);
    if (Comfortable(a, 1e12) && lct_fuzz::Known("D12", sv[1] <= 1e-4 * sv[0]))
    {
      return;
    }
    LCT_FUZZ_CHECK(!Comfortable(a, 1e12),
      "polarDecompose refused a well-conditioned matrix (" << lct::describe(polar.status) << "):\n"
                                                           << Show(a));
    return;
  }
  const Eigen::Matrix3d& u = polar.value.rotation;
  const Eigen::Matrix3d& s = polar.value.unitStretch;
  LCT_FUZZ_CHECK(AllFinite(u) && AllFinite(s),
    "polarDecompose: Ok with non-finite factors\n"
      << Show(a));
  // KNOWN: D13 (Testing/Fuzz/README.md). The singularity guard (det <= eps^3 ||A||^3) is far
  // below the rounding error of the computed determinant itself (~eps ||A||^3), so numerically
  // singular input of either orientation passes; Newton then converges to the orthogonal factor
  // of the orientation the rounding chose, and a reflection (det -1) is returned Ok as the
  // "rotation" (e.g. singular values 25.4, 0.31, 3.2e-16 with computed det +5.3e-15). The Polar
  // log still refuses such input (its stretch has a negative eigenvalue), polarDecompose does not.
  const Eigen::Vector3d singular = SingularValues(a);
  // D12 (below) also ends in a reflection when two singular values are small.
  if (u.determinant() < 0.0 &&
    (lct_fuzz::Known("D13", singular[2] <= 1e-13 * singular[0]) ||
      lct_fuzz::Known("D12", singular[1] <= 1e-4 * singular[0])))
  {
    return;
  }
  LCT_FUZZ_CHECK(
    (u.transpose() * u - Eigen::Matrix3d::Identity()).norm() <= 1e-10 && u.determinant() > 0.0,
    "polarDecompose: the rotation factor is not a rotation\na =\n"
      << Show(a) << "\nU =\n"
      << Show(u));
  LCT_FUZZ_CHECK(s == s.transpose(), "polarDecompose: the stretch is not symmetric");
  if (Comfortable(a, 1e12))
  {
    // A backward-stable polar decomposition reproduces A to a modest multiple of eps.
    const double backward = (u * s - a).norm() / a.norm();
    // KNOWN: D12 (Testing/Fuzz/README.md). For maps near rank one (two small singular values)
    // the scaled Newton iteration with cofactor inverses is not backward stable: the backward
    // error grows like 0.1 eps sigma1/sigma2 (1.7e-11 at 1e6, 1.7e-5 at 1e12), and from
    // sigma1/sigma2 ~ 1e8 the rotation factor can be off by a half turn, returned Ok (e.g.
    // singular values 16, 2e-9, 2.8e-11: ||U - U_svd|| = 2.83). One small singular value is fine.
    const Eigen::Vector3d sv = SingularValues(a);
    if (lct_fuzz::Known("D12", backward > 1e-12 && sv[1] <= 1e-4 * sv[0]))
    {
      return;
    }
    LCT_FUZZ_CHECK(backward <= 1e-12,
      "polarDecompose: U S != A\na =\n"
        << Show(a) << "\nU S =\n"
        << Show(u * s));
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
      if (spd && Comfortable(s, 1e12) &&
        (KnownTinyAnisotropy(s) || KnownDoubleSmallEigenvalue(s, f.status)))
      {
        continue;
      }
      LCT_FUZZ_CHECK(!(spd && Comfortable(s, 1e12)),
        name << " refused a well-conditioned SPD matrix (" << lct::describe(f.status) << "):\n"
             << Show(s));
      continue;
    }
    if (log && KnownClusteredLogSeries(s, f.value))
    {
      continue;
    }
    // KNOWN: D7: below ~1e-100 the eigenvalues are wrong (a singular matrix looks SPD), and the
    // Newton form then overflows: Ok with NaN, e.g. logSPD(diag(1e-320, 0, 0)).
    if (!AllFinite(f.value) && lct_fuzz::Known("D7", s.cwiseAbs().maxCoeff() < 1e-100))
    {
      continue;
    }
    LCT_FUZZ_CHECK(AllFinite(f.value),
      name << ": Ok with a non-finite result\ns =\n"
           << Show(s) << "\nresult =\n"
           << Show(f.value));
    LCT_FUZZ_CHECK(f.value == f.value.transpose(), name << ": the result is not symmetric");
    if (spd && Comfortable(s, 1e6))
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
  const Eigen::Matrix3d s = Symmetric(in);
  if (AllFinite(s) && s.cwiseAbs().maxCoeff() <= 1e100)
  {
    const Eigen::Vector3d l = lct::symmetricEigenvalues(s);
    if (!KnownTinyAnisotropy(s))
    {
      LCT_FUZZ_CHECK(AllFinite(l) && l[0] >= l[1] && l[1] >= l[2],
        "symmetricEigenvalues: not finite and descending: " << Show(l.transpose()) << " for\n"
                                                            << Show(s));
      const Eigen::Vector3d reference =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(s).eigenvalues().reverse();
      // KNOWN: D7 (Testing/Fuzz/README.md). No prior scaling: for matrices below ~1e-100 the
      // cube p2 p (and det B) leave the normal range, for ~1e-154 the squares too, so their
      // eigenvalues lose relative accuracy (1e-3 at 1e-107) or all of it (diag(1e-320, 0, 0) ->
      // a triple 3.3e-321; diag(2e-160, 1e-160, 1e-160) -> a triple 1.3e-160).
      // At a double eigenvalue r = +-1 and acos turns an eps error into sqrt(eps) (diag(2, 1, 1)
      // -> 1 +- 4e-9, though the header says eps ||A||; the matrix functions do not suffer, as
      // the Newton form is second-order in a split double node). So: sqrt(eps)-level here.
      const bool accurate = (l - reference).cwiseAbs().maxCoeff() <= 1e-7 * s.norm();
      if (!accurate && lct_fuzz::Known("D7", s.cwiseAbs().maxCoeff() < 1e-100))
      {
        return;
      }
      LCT_FUZZ_CHECK(accurate,
        "symmetricEigenvalues is inaccurate: " << Show(l.transpose()) << " vs Eigen's "
                                               << Show(reference.transpose()));
    }
  }
  const Eigen::Matrix3d a = in.Linear();
  // D7 again: no scaling, so below ~1e-100 the shifted entries and their products lose their
  // digits (the trace / 3 of a denormal matrix is already rounded).
  if (AllFinite(a) && a.cwiseAbs().maxCoeff() <= 1e40 && !KnownCubic(a) &&
    !lct_fuzz::Known("D7", a.cwiseAbs().maxCoeff() < 1e-100))
  {
    const lct::GeneralEigenvalues e = lct::generalEigenvalues(a);
    std::complex<double> sum = 0.0;
    for (const auto& v : e.values)
    {
      sum += v;
    }
    // The trace is the sum of the eigenvalues, which the shifted cubic keeps to round-off.
    LCT_FUZZ_CHECK(std::abs(sum - a.trace()) <= 1e-8 * (a.norm() + std::abs(a.trace())),
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
  if (lct::validateAffine(m) == lct::Status::Ok)
  {
    Eigen::Matrix4d e = m;
    e.diagonal().array() -= 1.0;
    if (e.norm() >= 0.25 && KnownCubic(m.topLeftCorner<3, 3>()))
    {
      return;
    }
    if (e.norm() >= 0.25)
    {
      const auto l = lct::matrixLog(m);
      if (l && std::isfinite(s) && KnownCubic(lct::logLinearPart(s * l.value)))
      {
        return;
      }
    }
  }
  const auto p = lct::matrixPower(m, s);
  // KNOWN: D8 (Testing/Fuzz/README.md). Near the identity (||M - I|| < 1/4) matrixPower sums the
  // binomial series without checking the result: for large |s| the coefficients overflow and it
  // returns Ok with NaN, even for M = I (inf * 0). The interpolators only use s in [0, 1/2].
  Eigen::Matrix4d offset = m;
  offset.diagonal().array() -= 1.0;
  if (p && !AllFinite(p.value) && lct_fuzz::Known("D8", offset.norm() < 0.25))
  {
    return;
  }
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
  if (p == lct::Parametrisation::MatrixLog)
  {
    // Mirror what combine() will hand to the MatrixLog functions and skip D1/D2 triggers.
    const bool relative =
      reference < keys.size() && lct::validateAffine(keys[reference]) == lct::Status::Ok;
    for (const bool rel : { false, true })
    {
      if (rel && !relative)
      {
        continue;
      }
      const Eigen::Matrix4d left =
        rel ? lct::inverseAffine(keys[reference]) : Eigen::Matrix4d::Identity();
      lct::LogCoords sum = lct::LogCoords::Zero();
      for (int i = 0; i < count; ++i)
      {
        if (weights[i] == 0.0)
        {
          continue;
        }
        const Eigen::Matrix4d x = left * keys[i];
        if (lct::validateAffine(x) != lct::Status::Ok)
        {
          break;
        }
        if (KnownCubic(x.topLeftCorner<3, 3>()))
        {
          return;
        }
        const auto l = lct::matrixLog(x);
        if (!l)
        {
          break;
        }
        sum += weights[i] * l.value;
      }
      if (KnownCubic(lct::logLinearPart(sum)))
      {
        return;
      }
    }
  }
  const auto absolute = lct::combine(weights.data(), keys.data(), keys.size(), p);
  if (absolute)
  {
    LCT_FUZZ_CHECK(AllFinite(absolute.value), "combine: Ok with a non-finite result");
  }
  const auto relative =
    lct::combineRelative(weights.data(), keys.data(), keys.size(), reference, p);
  if (relative && !AllFinite(relative.value))
  {
    // KNOWN: D10 (Testing/Fuzz/README.md). combineRelative multiplies the reference key back
    // onto a finite exp(sum_i w_i log(R^-1 T_i)) and returns the product unchecked: Ok with Inf
    // when it overflows (e.g. R a translation by -1.39e308, T the identity, weights -0.67, -1:
    // -1.39e308 - 1.39e308). lct::KeyLogs does the same (combineAbout, and the hand-over).
    std::vector<Eigen::Matrix4d> products;
    const Eigen::Matrix4d inverse = lct::inverseAffine(keys[reference]);
    for (const Eigen::Matrix4d& key : keys)
    {
      products.push_back(inverse * key);
    }
    const auto inner = lct::combine(weights.data(), products.data(), products.size(), p);
    if (lct_fuzz::Known("D10", inner && AllFinite(inner.value)))
    {
      return;
    }
  }
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
  const int n = in.Int(1, 12);
  std::vector<double> times;
  for (int i = 0; i < n; ++i)
  {
    times.push_back(in.Finite());
  }
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  const int keys = static_cast<int>(times.size());
  double t = in.Double();
  if (std::isnan(t))
  {
    t = 0.0; // callers reject NaN before asking for weights
  }
  const lct::CurveScheme scheme = static_cast<lct::CurveScheme>(in.Int(0, 4));
  // KNOWN: D11 (Testing/Fuzz/README.md). Key times whose differences overflow (e.g. -1.08e308 and
  // 1e308, both finite) make segmentOf's u = (t - t_i) / (t_i+1 - t_i) = Inf / Inf = NaN: NaN
  // weights for every scheme, and for Subdivision the float-cast-overflow (UB)
  // static_cast<int>(NaN) in fundamental() (Curves.cxx:138). The interpolators accept such keys.
  if (lct_fuzz::Known("D11", !std::isfinite(times.back() - times.front())))
  {
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
