// vtkShapeBlenderLCT (issue #11 §4): torus grids of 20 K and 100 K triangles with 2 targets (a
// bend and a non-uniform bulge): the factorisation of the rest mesh (lct::ShapeBlender::setRest),
// the targets' per-face logs (setTargets), one blend (blend), and one blend through the VTK filter
// (a weight changed, Update, output built), on 2 threads (vtkSMPTools for the per-face work; the
// sparse factorisation and back-substitution are serial). Goals printed at the end; --check exits
// 1 when one is missed (100 K: factorisation <= 5 s and one blend <= 0.3 s; 20 K: >= 10 blends/s).
#include "../Unit/ShapeMeshes.h"
#include "RecordingReporter.h"

#include "lct/ShapeBlend.h"

#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkShapeBlenderLCT.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
struct Scene
{
  lct_test::Mesh rest;
  std::vector<std::vector<Eigen::Vector3d>> targets;
};

/// A torus of `faces` triangles (20000: 100 x 100, 100000: 250 x 200) and its two targets.
Scene makeScene(int faces)
{
  const int u = faces >= 100000 ? 250 : 100;
  const int v = faces / (2 * u);
  Scene s;
  s.rest = lct_test::torus(u, v, 3.0, 1.0);
  std::vector<Eigen::Vector3d> bend, bulge;
  for (const Eigen::Vector3d& p : s.rest.points)
  {
    // A bend about the x axis by up to 120 degrees, growing with x.
    bend.push_back(Eigen::AngleAxisd(0.5 * p.x(), Eigen::Vector3d::UnitX()) * p);
    const double a = std::atan2(p.y(), p.x());
    bulge.emplace_back(1.3 * p.x(), 0.8 * p.y(), p.z() * (1.0 + 0.3 * std::sin(3.0 * a)));
  }
  s.targets = { bend, bulge };
  return s;
}

const lct::ParallelFor kParallel = [](std::int64_t n,
                                     const std::function<void(std::int64_t, std::int64_t)>& body) {
  vtkSMPTools::For(
    0, static_cast<vtkIdType>(n), [&body](vtkIdType begin, vtkIdType end) { body(begin, end); });
};

void Factorise(benchmark::State& state)
{
  const Scene s = makeScene(static_cast<int>(state.range(0)));
  lct::ShapeBlender blender;
  for (auto _ : state)
  {
    if (!blender.setRest(s.rest.points, s.rest.triangles, kParallel).ok())
    {
      state.SkipWithError("setRest failed");
    }
  }
  state.counters["unknowns"] = static_cast<double>(blender.numberOfUnknowns());
}

void TargetLogs(benchmark::State& state)
{
  const Scene s = makeScene(static_cast<int>(state.range(0)));
  lct::ShapeBlender blender;
  blender.setRest(s.rest.points, s.rest.triangles, kParallel);
  for (auto _ : state)
  {
    if (!blender.setTargets(s.targets, kParallel).ok())
    {
      state.SkipWithError("setTargets failed");
    }
  }
}

void Blend(benchmark::State& state)
{
  const Scene s = makeScene(static_cast<int>(state.range(0)));
  lct::ShapeBlender blender;
  blender.setRest(s.rest.points, s.rest.triangles, kParallel);
  blender.setTargets(s.targets, kParallel);
  std::vector<Eigen::Vector3d> out;
  double w = 0.0;
  for (auto _ : state)
  {
    w = w > 1.0 ? 0.0 : w + 0.1;
    if (!blender.blend({ w, 1.0 - w }, out, kParallel).ok())
    {
      state.SkipWithError("blend failed");
    }
    benchmark::DoNotOptimize(out.data());
  }
}

void FilterBlend(benchmark::State& state)
{
  const Scene s = makeScene(static_cast<int>(state.range(0)));
  vtkNew<vtkShapeBlenderLCT> f;
  f->SetInputData(lct_test::toPolyData(s.rest.points, s.rest.triangles));
  for (const auto& t : s.targets)
  {
    f->AddTarget(lct_test::toPolyData(t, s.rest.triangles));
  }
  f->Update();
  double w = 0.0;
  for (auto _ : state)
  {
    w = w > 1.0 ? 0.0 : w + 0.1;
    f->SetWeight(0, w);
    f->SetWeight(1, 1.0 - w);
    f->Update();
    benchmark::DoNotOptimize(f->GetOutput()->GetPoints());
  }
  if (f->GetNumberOfFactorizations() != 1)
  {
    state.SkipWithError("the filter factorised again for a weight change");
  }
}

BENCHMARK(Factorise)->Arg(20000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(TargetLogs)->Arg(20000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(Blend)->Arg(20000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(FilterBlend)->Arg(20000)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

int printTable(const lct_bench::RecordingReporter& reporter, bool check)
{
  int missed = 0;
  std::printf("\nvtkShapeBlenderLCT on %d threads (vtkSMPTools %s):\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(), vtkSMPTools::GetBackend());
  for (const int faces : { 20000, 100000 })
  {
    const std::string arg = "/" + std::to_string(faces) + "/real_time";
    // Seconds (the benchmarks report milliseconds).
    const double factor = reporter.Get("Factorise" + arg) * 1e-3;
    const double logs = reporter.Get("TargetLogs" + arg) * 1e-3;
    const double blend = reporter.Get("Blend" + arg) * 1e-3;
    const double filter = reporter.Get("FilterBlend" + arg) * 1e-3;
    if (factor <= 0 && blend <= 0)
    {
      continue;
    }
    std::printf("  %6d faces: factorisation %.3f s, 2 targets' logs %.3f s, one blend %.4f s "
                "(%.1f blends/s), through the filter %.4f s\n",
      faces, factor, logs, blend, blend > 0 ? 1.0 / blend : 0.0, filter);
    if (faces == 100000)
    {
      const bool ok = factor > 0 && factor + logs <= 5.0 && filter > 0 && filter <= 0.3;
      missed += ok ? 0 : 1;
      std::printf(
        "    goal (factorisation + logs <= 5 s, one blend through the filter <= 0.3 s): %s\n",
        ok ? "met" : "MISSED");
    }
    else
    {
      const bool ok = filter > 0 && 1.0 / filter >= 10.0;
      missed += ok ? 0 : 1;
      std::printf("    goal (>= 10 blends/s through the filter): %s\n", ok ? "met" : "MISSED");
    }
  }
  return check && missed ? 1 : 0;
}
} // namespace

int main(int argc, char** argv)
{
  return lct_bench::runWithTable(argc, argv, printTable);
}
