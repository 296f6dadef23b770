// Stress over the hard input classes (robustness issue, part 2): N random inputs per class (10^6
// by default), each through log -> exp in both parametrisations and through a 2-key and a 5-key
// vtkTransformInterpolatorLCT (Spline). Per class and parametrisation it reports the largest
// round-trip error, how many inputs were refused with an error, how many failed silently
// (status Ok but a wrong or non-finite result: must be 0), and the slowest single call.
//
// A silent failure is any of: a non-finite output with status Ok; a round trip exp(log A) off by
// more than 1e-10 relative (linear and translation blocks separately, the translation relative to
// max(1, |t|) |A|); a key not reproduced at its time to 1e-10; an in-between whose determinant is
// not det(K0)^(1-t) det(K1)^t to 1e-8 (a property of both parametrisations' relative form, so a
// lost small stretch shows). Determinants are computed exactly in __float128 from the stored
// doubles, so the check does not share the code it checks.
//
// Usage: BenchStress [--count N] [--interpolations M] [--seed S]: N inputs per class through
// log -> exp, M interpolator runs per class (default N / 20: a run costs about 20 logs). Exits 1
// if any silent failure is found.
#include "lct/Parametrisation.h"

#include "vtkCommand.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransformInterpolatorLCT.h"

#include "../Unit/RandomTransforms.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include <time.h>

namespace
{
using lct::Parametrisation;
using lct_test::kPi;
using lct_test::RandomTransforms;

/// Silences the errors the classes report (they are counted through return values).
class Silence : public vtkCommand
{
public:
  static Silence* New() { return new Silence; }
  void Execute(vtkObject*, unsigned long, void*) override {}
};

double logAbsDeterminantExact(const Eigen::Matrix4d& m)
{
  using Q = __float128;
  auto q = [&](int i, int j) { return static_cast<Q>(m(i, j)); };
  Q det = 0;
  for (int j = 0; j < 3; ++j)
  {
    det +=
      q(0, j) * (q(1, (j + 1) % 3) * q(2, (j + 2) % 3) - q(1, (j + 2) % 3) * q(2, (j + 1) % 3));
  }
  // log of a __float128 without libquadmath: split off the binary exponent.
  if (det <= 0)
  {
    return -std::numeric_limits<double>::infinity();
  }
  int e = 0;
  while (det > static_cast<Q>(1e300))
  {
    det /= static_cast<Q>(1e300);
    e += 300;
  }
  while (det < static_cast<Q>(1e-300))
  {
    det *= static_cast<Q>(1e300);
    e -= 300;
  }
  return std::log(static_cast<double>(det)) + e * std::log(10.0);
}

double blockError(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b)
{
  const double scale = b.topLeftCorner<3, 3>().cwiseAbs().maxCoeff();
  const double linear =
    (a.topLeftCorner<3, 3>() - b.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff() / scale;
  const double translation =
    (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).cwiseAbs().maxCoeff() /
    std::max(1.0, b.topRightCorner<3, 1>().cwiseAbs().maxCoeff()) / std::max(1.0, scale);
  return std::max(linear, translation);
}

struct Tally
{
  long inputs = 0;
  long refused = 0;
  long silent = 0;
  double worstRoundTrip = 0.0;
  double worstKey = 0.0;
  double worstDeterminant = 0.0;
  double slowest = 0.0; // seconds
  std::string firstSilent;

  void silentFailure(const std::string& what)
  {
    if (this->silent++ == 0)
    {
      this->firstSilent = what;
    }
  }
};

/// This thread's CPU time in seconds: unlike a wall clock it does not count the time the thread
/// was preempted, so "slowest call" measures the call and not the machine's load.
double threadSeconds()
{
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

template <typename F>
auto timed(Tally& tally, F&& f)
{
  const double t0 = threadSeconds();
  auto result = f();
  tally.slowest = std::max(tally.slowest, threadSeconds() - t0);
  return result;
}

void roundTrip(const Eigen::Matrix4d& m, Parametrisation p, Tally& tally)
{
  ++tally.inputs;
  const auto log = timed(tally, [&] { return lct::logarithm(m, p); });
  if (!log)
  {
    ++tally.refused;
    return;
  }
  if (!log.value.allFinite())
  {
    tally.silentFailure("non-finite log coordinates");
    return;
  }
  const auto back = timed(tally, [&] { return lct::exponential(log.value, p); });
  if (!back)
  {
    ++tally.refused;
    return;
  }
  const double error = blockError(back.value, m);
  tally.worstRoundTrip = std::max(tally.worstRoundTrip, error);
  if (!back.value.allFinite() || !(error <= 1e-10))
  {
    char text[64];
    std::snprintf(text, sizeof(text), "round trip error %.3g", error);
    tally.silentFailure(text);
  }
}

/// The relative change of det A that rounding its entries to double can cause, to first order:
/// 4 sum_ij |cofactor_ij| ulp(a_ij) / |det A| (ulp of subnormal entries included).
double representableDeterminantError(const Eigen::Matrix4d& m)
{
  using Q = __float128;
  auto q = [&](int i, int j) { return static_cast<Q>(m(i, j)); };
  Q det = 0, bound = 0;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const int r0 = (i + 1) % 3, r1 = (i + 2) % 3, c0 = (j + 1) % 3, c1 = (j + 2) % 3;
      const Q cofactor = q(r0, c0) * q(r1, c1) - q(r0, c1) * q(r1, c0);
      if (i == 0)
      {
        det += q(0, j) * cofactor;
      }
      const double x = m(i, j);
      const double ulp =
        std::nextafter(std::abs(x), std::numeric_limits<double>::infinity()) - std::abs(x);
      bound += (cofactor < 0 ? -cofactor : cofactor) * static_cast<Q>(ulp);
    }
  }
  if (det < 0)
  {
    det = -det;
  }
  return det > 0 ? static_cast<double>(4 * bound / det) : std::numeric_limits<double>::infinity();
}

Eigen::Matrix4d toEigen(vtkMatrix4x4* m)
{
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m->GetData());
}

void toVtk(const Eigen::Matrix4d& m, vtkMatrix4x4* out)
{
  Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(out->GetData()) = m;
  out->Modified();
}

/// Keys at times 0 .. n-1 through a Spline interpolator: keys reproduced, in-betweens finite with
/// the geometric determinant between their neighbours (Linear type for that check).
void interpolation(const std::vector<Eigen::Matrix4d>& keys, Parametrisation p,
  vtkTransformInterpolatorLCT* path, Tally& tally)
{
  ++tally.inputs;
  path->Initialize();
  path->SetParametrisation(p == Parametrisation::Polar ? vtkTransformInterpolatorLCT::POLAR
                                                       : vtkTransformInterpolatorLCT::MATRIX_LOG);
  vtkNew<vtkMatrix4x4> m;
  for (size_t k = 0; k < keys.size(); ++k)
  {
    toVtk(keys[k], m);
    if (!timed(tally, [&] { return path->AddTransform(static_cast<double>(k), m); }))
    {
      ++tally.refused;
      return;
    }
  }
  for (int type : { vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE,
         vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR })
  {
    path->SetInterpolationType(type);
    const int samples = 4 * static_cast<int>(keys.size() - 1);
    for (int i = 0; i <= samples; ++i)
    {
      const double t = static_cast<double>(i) / 4.0;
      if (!timed(tally, [&] { return path->InterpolateTransform(t, m); }))
      {
        ++tally.refused;
        return;
      }
      const Eigen::Matrix4d r = toEigen(m);
      if (!r.allFinite())
      {
        tally.silentFailure("non-finite in-between");
        return;
      }
      if (i % 4 == 0)
      {
        const double error = blockError(r, keys[i / 4]);
        tally.worstKey = std::max(tally.worstKey, error);
        if (!(error <= 1e-10))
        {
          char text[64];
          std::snprintf(text, sizeof(text), "key %d off by %.3g", i / 4, error);
          tally.silentFailure(text);
        }
      }
      else if (type == vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR)
      {
        const int k = i / 4;
        const double u = (i % 4) / 4.0;
        const double expected =
          (1 - u) * logAbsDeterminantExact(keys[k]) + u * logAbsDeterminantExact(keys[k + 1]);
        const double got = logAbsDeterminantExact(r);
        const double error = std::abs(got - expected) / (1.0 + std::abs(expected));
        tally.worstDeterminant = std::max(tally.worstDeterminant, error);
        // Storing the in-between in double (subnormal entries included) moves its determinant
        // by up to the first-order bound below: that much is allowed on top of 1e-8.
        if (!(error <= 1e-8 + representableDeterminantError(r)))
        {
          char text[64];
          std::snprintf(text, sizeof(text), "in-between determinant off by %.3g", error);
          tally.silentFailure(text);
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The classes.

Eigen::Matrix3d stretch(RandomTransforms& r, bool uniform, double lo, double hi)
{
  if (uniform)
  {
    return r.LogUniform(lo, hi) * Eigen::Matrix3d::Identity();
  }
  const Eigen::Matrix3d q = r.Rotation();
  const Eigen::Vector3d s(r.LogUniform(lo, hi), r.LogUniform(lo, hi), r.LogUniform(lo, hi));
  return q * s.asDiagonal() * q.transpose();
}

Eigen::Matrix4d affine(const Eigen::Matrix3d& linear, const Eigen::Vector3d& t)
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.topLeftCorner<3, 3>() = linear;
  m.topRightCorner<3, 1>() = t;
  return m;
}

struct InputClass
{
  const char* name;
  std::function<Eigen::Matrix4d(RandomTransforms&)> make;
};

std::vector<InputClass> inputClasses()
{
  auto translation = [](RandomTransforms& r, double size) {
    return Eigen::Vector3d(size * r.Normal(), size * r.Normal(), size * r.Normal());
  };
  return {
    { "rotation exactly pi, uniform scale",
      [=](RandomTransforms& r) {
        return affine(r.Rotation(kPi) * stretch(r, true, 0.1, 10), translation(r, 10));
      } },
    { "rotation exactly pi, non-uniform scale",
      [=](RandomTransforms& r) {
        return affine(r.Rotation(kPi) * stretch(r, false, 0.2, 5), translation(r, 10));
      } },
    { "rotation pi - [1e-15, 1e-8]",
      [=](RandomTransforms& r) {
        const double delta = r.LogUniform(1e-15, 1e-8);
        return affine(
          r.Rotation(kPi - delta) * stretch(r, r.Uniform(0, 1) < 0.5, 0.2, 5), translation(r, 10));
      } },
    { "near identity (+-1e-15)",
      [=](RandomTransforms& r) {
        Eigen::Matrix3d a = Eigen::Matrix3d::Identity();
        for (int i = 0; i < 9; ++i)
        {
          a(i) += 1e-15 * r.Uniform(-1, 1);
        }
        return affine(a, translation(r, 1e-15));
      } },
    { "repeated stretch eigenvalues",
      [=](RandomTransforms& r) {
        const Eigen::Matrix3d q = r.Rotation();
        const double a = r.LogUniform(0.2, 5);
        const Eigen::Vector3d s(a, a, r.Uniform(0, 1) < 0.3 ? a : r.LogUniform(0.2, 5));
        return affine(r.Rotation() * q * s.asDiagonal() * q.transpose(), translation(r, 10));
      } },
    { "nearly repeated (1e-12 apart)",
      [=](RandomTransforms& r) {
        const Eigen::Matrix3d q = r.Rotation();
        const double a = r.LogUniform(0.2, 5);
        const Eigen::Vector3d s(
          a, a * (1 + 1e-12 * r.Uniform(-1, 1)), a * (1 + 1e-12 * r.Uniform(-1, 1)));
        return affine(r.Rotation() * q * s.asDiagonal() * q.transpose(), translation(r, 10));
      } },
    { "near-singular (det 1e-12 .. 1e-3)",
      [=](RandomTransforms& r) {
        const double det = r.LogUniform(1e-12, 1e-3);
        const double mid = r.LogUniform(std::sqrt(det), 1.0);
        const Eigen::Vector3d s(1.0, mid, det / mid);
        return affine(r.Rotation() * s.asDiagonal() * r.Rotation(), translation(r, 10));
      } },
    { "scale 1e-150",
      [=](RandomTransforms& r) {
        return affine(1e-150 * r.Rotation() * stretch(r, false, 0.5, 2), translation(r, 1e-150));
      } },
    { "scale 1e150",
      [=](RandomTransforms& r) {
        return affine(1e150 * r.Rotation() * stretch(r, false, 0.5, 2), translation(r, 1e150));
      } },
    { "translation 1e300",
      [=](RandomTransforms& r) {
        return affine(r.Rotation() * stretch(r, false, 0.5, 2), translation(r, 1e300));
      } },
    { "denormal entries",
      [=](RandomTransforms& r) {
        Eigen::Matrix3d a = r.Rotation(r.Uniform(0, 1) < 0.5 ? 1e-310 : r.Uniform(0, kPi));
        for (int i = 0; i < 9; ++i)
        {
          if (r.Uniform(0, 1) < 0.3)
          {
            a(i) = 1e-310 * r.Uniform(-1, 1); // subnormal
          }
        }
        if (r.Uniform(0, 1) < 0.3)
        {
          a *= 1e-305; // everything near the subnormal range
        }
        return affine(a, translation(r, r.Uniform(0, 1) < 0.5 ? 1e-310 : 1.0));
      } },
  };
}

void printRow(const char* name, const char* what, const Tally& t)
{
  std::printf("| %-38s | %-27s | %9ld | %8ld | %6ld | %9.2e | %9.2e | %9.2e | %8.1f |\n", name,
    what, t.inputs, t.refused, t.silent, t.worstRoundTrip, t.worstKey, t.worstDeterminant,
    1e6 * t.slowest);
  if (t.silent)
  {
    std::printf("|   first silent failure: %s\n", t.firstSilent.c_str());
  }
}
} // namespace

int main(int argc, char* argv[])
{
  long count = 1000000;
  long interpolations = 0; // 0: count / 20
  unsigned long seed = 2026;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--count") && i + 1 < argc)
    {
      count = std::atol(argv[++i]);
    }
    else if (!std::strcmp(argv[i], "--interpolations") && i + 1 < argc)
    {
      interpolations = std::atol(argv[++i]);
      if (interpolations < 1)
      {
        std::fprintf(stderr, "--interpolations must be at least 1\n");
        return 2;
      }
    }
    else if (!std::strcmp(argv[i], "--seed") && i + 1 < argc)
    {
      seed = std::strtoul(argv[++i], nullptr, 10);
    }
    else
    {
      std::fprintf(stderr, "usage: %s [--count N] [--interpolations M] [--seed S]\n", argv[0]);
      return 2;
    }
  }
  if (count < 1)
  {
    std::fprintf(stderr, "--count must be at least 1\n");
    return 2;
  }
  vtkNew<vtkTransformInterpolatorLCT> path;
  vtkNew<Silence> silence;
  path->AddObserver(vtkCommand::ErrorEvent, silence);
  path->AddObserver(vtkCommand::WarningEvent, silence);

  std::printf(
    "Stress over the hard input classes: %ld inputs per class (seed %lu)\n\n", count, seed);
  std::printf("| %-38s | %-27s | %9s | %8s | %6s | %9s | %9s | %9s | %8s |\n", "class", "run",
    "inputs", "refused", "silent", "round trip", "key", "det", "slowest");
  std::printf("|%s|%s|%s|%s|%s|%s|%s|%s|%s|\n", std::string(40, '-').c_str(),
    std::string(29, '-').c_str(), std::string(11, '-').c_str(), std::string(10, '-').c_str(),
    std::string(8, '-').c_str(), std::string(11, '-').c_str(), std::string(11, '-').c_str(),
    std::string(11, '-').c_str(), std::string(10, '-').c_str());
  long silentTotal = 0;
  if (interpolations == 0)
  {
    interpolations = std::max(1L, count / 20); // an interpolator run costs ~20 logs
  }
  for (const InputClass& c : inputClasses())
  {
    for (Parametrisation p : { Parametrisation::Polar, Parametrisation::MatrixLog })
    {
      RandomTransforms random(seed);
      Tally logExp, two, five, piApart;
      for (long n = 0; n < count; ++n)
      {
        roundTrip(c.make(random), p, logExp);
      }
      for (long n = 0; n < interpolations; ++n)
      {
        interpolation(
          { random.Affine(lct_test::TransformClass::GeneralAffine), c.make(random) }, p, path, two);
        std::vector<Eigen::Matrix4d> keys;
        for (int k = 0; k < 5; ++k)
        {
          keys.push_back(c.make(random));
        }
        interpolation(keys, p, path, five);
        // Keys exactly pi apart: K1 = K0 R(pi) on top of the class's own key.
        const Eigen::Matrix4d k0 = c.make(random);
        interpolation(
          { k0, k0 * affine(random.Rotation(kPi), Eigen::Vector3d::Zero()) }, p, path, piApart);
      }
      const std::string tag = std::string(" (") + lct::name(p) + ")";
      printRow(c.name, ("log -> exp" + tag).c_str(), logExp);
      printRow(c.name, ("2 keys" + tag).c_str(), two);
      printRow(c.name, ("5 keys" + tag).c_str(), five);
      printRow(c.name, ("2 keys pi apart" + tag).c_str(), piApart);
      silentTotal += logExp.silent + two.silent + five.silent + piApart.silent;
    }
  }
  std::printf("\nround trip: max blockwise relative error of exp(log A) over the accepted inputs; "
              "key: max error of a key at its time; det: max relative error of log det of a "
              "Linear in-between against (1-u) log det K0 + u log det K1; slowest: one call, "
              "microseconds of thread CPU time. Interpolator runs: %ld per class (2-key, 5-key, pi apart).\n",
    interpolations);
  std::printf("silent failures: %ld\n", silentTotal);
  return silentTotal == 0 ? 0 : 1;
}
