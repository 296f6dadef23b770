// ns per InterpolateTransform of vtkTransformInterpolatorLCT (every scheme, and the Spline with
// each timing control of issue #12 §3) against VTK's vtkTransformInterpolator (linear and its
// default spline), on the same keys and times in one run, for 2, 10 and 100 keys; and the cost
// of building the constant-speed table. Prints Google Benchmark's table and the ratios.
#include "vtkTransformInterpolatorLCT.h"

#include "../Unit/RandomTransforms.h"
#include "RecordingReporter.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkTransform.h"
#include "vtkTransformInterpolator.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <string>
#include <vector>

namespace
{
constexpr int kQueries = 1024;

/// Keys of a keyframed animation: a random walk where each key is the previous one times a step
/// of up to 30 degrees of rotation, up to 15 % of non-uniform scale change and a unit-size
/// translation; times 0 .. n-1.
void addKeys(int n, vtkTransformInterpolatorLCT* ours, vtkTransformInterpolator* vtk)
{
  lct_test::RandomTransforms random(77);
  Eigen::Matrix4d key = Eigen::Matrix4d::Identity();
  for (int k = 0; k < n; ++k)
  {
    vtkNew<vtkMatrix4x4> m;
    for (int i = 0; i < 16; ++i)
    {
      m->SetElement(i / 4, i % 4, key(i / 4, i % 4));
    }
    if (ours)
    {
      ours->AddTransform(k, m);
    }
    if (vtk)
    {
      vtk->AddTransform(k, m);
    }
    key = random.KeyframeStep() * key;
  }
}

/// Reads the result as a user would: a vtkTransform computes its matrix lazily, on GetMatrix(),
/// so that cost is counted for both interpolators.
void consume(vtkTransform* out)
{
  benchmark::DoNotOptimize(out->GetMatrix()->GetData()[3]);
}
void consume(vtkMatrix4x4* out)
{
  benchmark::DoNotOptimize(out->GetData()[3]);
}

std::vector<double> queries(int n)
{
  lct_test::RandomTransforms random(78);
  std::vector<double> t(kQueries);
  for (double& x : t)
  {
    x = random.Uniform(0.0, n - 1.0);
  }
  return t;
}

/// Ours, written into a vtkTransform (as VTK's) or a vtkMatrix4x4 (no vtkTransform bookkeeping:
/// vtkTransform::SetMatrix rebuilds its concatenation, ~140 ns here).
template <typename Output>
void Ours(benchmark::State& state, int type)
{
  const int n = static_cast<int>(state.range(0));
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  interpolator->SetInterpolationType(type);
  addKeys(n, interpolator, nullptr);
  const std::vector<double> t = queries(n);
  vtkNew<Output> out;
  int i = 0;
  for (auto _ : state)
  {
    interpolator->InterpolateTransform(t[i], out);
    consume(out);
    i = (i + 1) & (kQueries - 1);
  }
}

/// The Spline with one timing control (issue #12 §3): Kochanek-Bartels parameters on every key,
/// eases on every key, or constant speed (its table built before the loop).
enum class Timing
{
  TensionContinuityBias,
  Ease,
  ConstantSpeed
};

void OursTimed(benchmark::State& state, Timing timing)
{
  const int n = static_cast<int>(state.range(0));
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  addKeys(n, interpolator, nullptr);
  switch (timing)
  {
    case Timing::TensionContinuityBias:
      interpolator->SetTension(0.3);
      interpolator->SetContinuity(-0.2);
      interpolator->SetBias(0.1);
      break;
    case Timing::Ease:
      for (int k = 0; k < n; ++k)
      {
        interpolator->SetKeyEase(k, 0.5, 0.5);
      }
      break;
    case Timing::ConstantSpeed:
      interpolator->ConstantSpeedOn();
      break;
  }
  const std::vector<double> t = queries(n);
  vtkNew<vtkTransform> out;
  interpolator->InterpolateTransform(t[0], out); // builds the logs (and the table)
  int i = 0;
  for (auto _ : state)
  {
    interpolator->InterpolateTransform(t[i], out);
    consume(out);
    i = (i + 1) & (kQueries - 1);
  }
}

/// The first InterpolateTransform after a change with ConstantSpeed on: the table's build (about
/// 16 n curve points, more where the path curves) plus one query.
void ConstantSpeedTable(benchmark::State& state)
{
  const int n = static_cast<int>(state.range(0));
  vtkNew<vtkTransformInterpolatorLCT> interpolator;
  addKeys(n, interpolator, nullptr);
  interpolator->ConstantSpeedOn();
  vtkNew<vtkTransform> out;
  interpolator->InterpolateTransform(0.5, out); // the key logs, built once
  for (auto _ : state)
  {
    interpolator->Modified(); // stales the table only
    interpolator->InterpolateTransform(0.5, out);
    consume(out);
  }
}

void Vtk(benchmark::State& state, int type)
{
  const int n = static_cast<int>(state.range(0));
  vtkNew<vtkTransformInterpolator> interpolator;
  interpolator->SetInterpolationType(type);
  addKeys(n, nullptr, interpolator);
  const std::vector<double> t = queries(n);
  vtkNew<vtkTransform> out;
  interpolator->InterpolateTransform(t[0], out); // VTK initialises lazily on the first call
  int i = 0;
  for (auto _ : state)
  {
    interpolator->InterpolateTransform(t[i], out);
    consume(out);
    i = (i + 1) & (kQueries - 1);
  }
}

void Ours_Linear(benchmark::State& s)
{
  Ours<vtkTransform>(s, vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_LINEAR);
}
void Ours_Spline(benchmark::State& s)
{
  Ours<vtkTransform>(s, vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE);
}
void Ours_BSpline(benchmark::State& s)
{
  Ours<vtkTransform>(s, vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE);
}
void Ours_Subdivision(benchmark::State& s)
{
  Ours<vtkTransform>(s, vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION);
}
void Ours_Spline_ToMatrix(benchmark::State& s)
{
  Ours<vtkMatrix4x4>(s, vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_SPLINE);
}
void Ours_Spline_TCB(benchmark::State& s)
{
  OursTimed(s, Timing::TensionContinuityBias);
}
void Ours_Spline_Eased(benchmark::State& s)
{
  OursTimed(s, Timing::Ease);
}
void Ours_Spline_ConstantSpeed(benchmark::State& s)
{
  OursTimed(s, Timing::ConstantSpeed);
}
void Vtk_Linear(benchmark::State& s)
{
  Vtk(s, vtkTransformInterpolator::INTERPOLATION_TYPE_LINEAR);
}
void Vtk_Spline(benchmark::State& s)
{
  Vtk(s, vtkTransformInterpolator::INTERPOLATION_TYPE_SPLINE);
}

BENCHMARK(Ours_Linear)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Spline)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_BSpline)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Subdivision)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Spline_ToMatrix)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Spline_TCB)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Spline_Eased)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Ours_Spline_ConstantSpeed)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(ConstantSpeedTable)->Arg(2)->Arg(10)->Arg(100)->Unit(benchmark::kMicrosecond);
BENCHMARK(Vtk_Linear)->Arg(2)->Arg(10)->Arg(100);
BENCHMARK(Vtk_Spline)->Arg(2)->Arg(10)->Arg(100);
} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  lct_bench::RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  std::printf(
    "\nInterpolateTransform, ns per call, ours / VTK in this run (target <= 1.0x for Linear "
    "and Spline):\n");
  std::printf("  %-6s %-12s %10s %10s %8s\n", "keys", "scheme", "ours ns", "VTK ns", "ratio");
  for (int n : { 2, 10, 100 })
  {
    for (const char* scheme : { "Linear", "Spline" })
    {
      const std::string suffix = std::string(scheme) + "/" + std::to_string(n);
      const double ours = reporter.Get("Ours_" + suffix);
      const double vtk = reporter.Get("Vtk_" + suffix);
      if (ours > 0.0 && vtk > 0.0)
      {
        std::printf("  %-6d %-12s %10.1f %10.1f %7.2fx %s\n", n, scheme, ours, vtk, ours / vtk,
          ours <= vtk ? "met" : "MISSED");
      }
    }
    for (const char* scheme : { "BSpline", "Subdivision" })
    {
      const double ours = reporter.Get(std::string("Ours_") + scheme + "/" + std::to_string(n));
      if (ours > 0.0)
      {
        std::printf("  %-6d %-12s %10.1f %10s\n", n, scheme, ours, "-");
      }
    }
  }
  std::printf("\nTiming controls (issue #12 §3), Spline, ns per call, against VTK's spline in "
              "this run; constant-speed table build in us:\n");
  std::printf("  %-6s %10s %10s %10s %10s %10s %12s\n", "keys", "plain", "TCB", "eased",
    "const.sp.", "VTK", "table us");
  for (int n : { 2, 10, 100 })
  {
    const std::string k = "/" + std::to_string(n);
    const double vtk = reporter.Get("Vtk_Spline" + k);
    const auto ratio = [&](const std::string& name) {
      const double ours = reporter.Get(name + k);
      return vtk > 0.0 && ours > 0.0 ? ours / vtk : 0.0;
    };
    std::printf("  %-6d %9.2fx %9.2fx %9.2fx %9.2fx %10.1f %12.1f\n", n, ratio("Ours_Spline"),
      ratio("Ours_Spline_TCB"), ratio("Ours_Spline_Eased"), ratio("Ours_Spline_ConstantSpeed"), vtk,
      reporter.Get("ConstantSpeedTable" + k)); // in its own unit, us
  }
  benchmark::Shutdown();
  return 0;
}
