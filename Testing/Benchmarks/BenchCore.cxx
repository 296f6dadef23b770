// ns/op and round-trip accuracy of the core's closed-form exp/log against Eigen's
// MatrixFunctions (Pade / inverse scaling and squaring), on the same random inputs in one run.
// Prints Google Benchmark's table, then the speed ratios and the accuracy table.
#include "lct/MatrixLogParametrisation.h"
#include "lct/PolarParametrisation.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include "../Unit/RandomTransforms.h"
#include "RecordingReporter.h"

#include <Eigen/Eigenvalues>
#include <benchmark/benchmark.h>
#include <unsupported/Eigen/MatrixFunctions>

#include <algorithm>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

namespace
{
constexpr int kInputs = 1024;

/// Generic affine keys (rotation up to 170 degrees, shear, non-uniform scale, translation),
/// kept only when they have a real logarithm, so that Eigen's log is a valid reference.
struct Inputs
{
  std::vector<Eigen::Matrix4d> affine;
  std::vector<lct::LogCoords> polarLogs;
  std::vector<lct::LogCoords> matrixLogs;
  std::vector<Eigen::Matrix4d> eigenLogs;
  std::vector<Eigen::Matrix3d> spd;
  std::vector<Eigen::Matrix3d> sym;
  std::vector<Eigen::Vector3d> rotationVectors;
  std::vector<Eigen::Matrix3d> rotations;
  int rejected = 0;

  Inputs()
  {
    lct_test::RandomTransforms random(2024);
    while (static_cast<int>(affine.size()) < kInputs)
    {
      const Eigen::Vector3d s(
        random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0));
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m.topLeftCorner<3, 3>() =
        random.Rotation(random.Uniform(0.0, 170.0 * lct_test::kPi / 180.0)) * s.asDiagonal() *
        random.Rotation();
      m.topRightCorner<3, 1>() = random.Translation(lct_test::TransformClass::Rigid);
      Eigen::EigenSolver<Eigen::Matrix3d> es(m.topLeftCorner<3, 3>(), false);
      bool negative = false;
      for (int i = 0; i < 3; ++i)
      {
        const auto l = es.eigenvalues()[i];
        negative |= l.real() < 0.0 && std::abs(l.imag()) < 0.05 * std::abs(l);
      }
      if (negative)
      {
        ++rejected;
        continue;
      }
      affine.push_back(m);
      polarLogs.push_back(lct::polarLog(m).value);
      matrixLogs.push_back(lct::matrixLog(m).value);
      eigenLogs.push_back(m.log());
      const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
      spd.push_back(a.transpose() * a);
      sym.push_back(lct::fromSymmetricVector(lct::symmetricPart(polarLogs.back())));
      rotationVectors.push_back(lct::rotationPart(polarLogs.back()));
      rotations.push_back(lct::expSO3(rotationVectors.back()));
    }
  }
};

const Inputs& inputs()
{
  static const Inputs data;
  return data;
}

template <typename F>
void run(benchmark::State& state, F&& f)
{
  int i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(f(i));
    i = (i + 1) & (kInputs - 1);
  }
}

// 4x4 affine log / exp
void Log4_Polar(benchmark::State& s)
{
  run(s, [](int i) { return lct::polarLog(inputs().affine[i]).value; });
}
void Log4_MatrixLog(benchmark::State& s)
{
  run(s, [](int i) { return lct::matrixLog(inputs().affine[i]).value; });
}
void Log4_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix4d(inputs().affine[i].log()); });
}
void Exp4_Polar(benchmark::State& s)
{
  run(s, [](int i) { return lct::polarExp(inputs().polarLogs[i]).value; });
}
void Exp4_MatrixLog(benchmark::State& s)
{
  run(s, [](int i) { return lct::matrixExp(inputs().matrixLogs[i]).value; });
}
void Exp4_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix4d(inputs().eigenLogs[i].exp()); });
}
// 3x3 symmetric / SPD
void LogSPD3_Ours(benchmark::State& s)
{
  run(s, [](int i) { return lct::logSPD(inputs().spd[i]).value; });
}
void LogSPD3_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix3d(inputs().spd[i].log()); });
}
void ExpSym3_Ours(benchmark::State& s)
{
  run(s, [](int i) { return lct::expSym(inputs().sym[i]); });
}
void ExpSym3_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix3d(inputs().sym[i].exp()); });
}
// so(3)
void ExpSO3_Ours(benchmark::State& s)
{
  run(s, [](int i) { return lct::expSO3(inputs().rotationVectors[i]); });
}
void ExpSO3_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix3d(lct::hat(inputs().rotationVectors[i]).exp()); });
}
void LogSO3_Ours(benchmark::State& s)
{
  run(s, [](int i) { return lct::logSO3(inputs().rotations[i]); });
}
void LogSO3_Eigen(benchmark::State& s)
{
  run(s, [](int i) { return Eigen::Matrix3d(inputs().rotations[i].log()); });
}

BENCHMARK(Log4_Polar);
BENCHMARK(Log4_MatrixLog);
BENCHMARK(Log4_Eigen);
BENCHMARK(Exp4_Polar);
BENCHMARK(Exp4_MatrixLog);
BENCHMARK(Exp4_Eigen);
BENCHMARK(LogSPD3_Ours);
BENCHMARK(LogSPD3_Eigen);
BENCHMARK(ExpSym3_Ours);
BENCHMARK(ExpSym3_Eigen);
BENCHMARK(ExpSO3_Ours);
BENCHMARK(ExpSO3_Eigen);
BENCHMARK(LogSO3_Ours);
BENCHMARK(LogSO3_Eigen);

struct Stats
{
  double max = 0.0;
  double median = 0.0;
};

Stats stats(std::vector<double> errors)
{
  std::sort(errors.begin(), errors.end());
  return { errors.back(), errors[errors.size() / 2] };
}

void printAccuracy()
{
  const Inputs& in = inputs();
  std::vector<double> polar, matrixLog, eigen, spdOurs, spdEigen;
  for (int i = 0; i < kInputs; ++i)
  {
    const Eigen::Matrix4d& a = in.affine[i];
    polar.push_back(lct_test::blockError(lct::polarExp(in.polarLogs[i]).value, a));
    matrixLog.push_back(lct_test::blockError(lct::matrixExp(in.matrixLogs[i]).value, a));
    eigen.push_back(lct_test::blockError(Eigen::Matrix4d(in.eigenLogs[i].exp()), a));
    const Eigen::Matrix3d& s = in.spd[i];
    spdOurs.push_back((lct::expSym(lct::logSPD(s).value) - s).norm() / s.norm());
    spdEigen.push_back((Eigen::Matrix3d(Eigen::Matrix3d(s.log()).exp()) - s).norm() / s.norm());
  }
  std::printf(
    "\nRound trip exp(log A) vs A on the same %d inputs (relative, linear and translation "
    "blocks separately; %d candidates with a near-negative eigenvalue skipped so Eigen's "
    "log is valid):\n",
    kInputs, in.rejected);
  std::printf("  %-26s %12s %12s\n", "method", "max", "median");
  const std::pair<const char*, Stats> rows[] = { { "4x4 Polar (ours)", stats(polar) },
    { "4x4 MatrixLog (ours)", stats(matrixLog) }, { "4x4 Eigen log/exp", stats(eigen) },
    { "3x3 SPD log/exp (ours)", stats(spdOurs) }, { "3x3 SPD Eigen log/exp", stats(spdEigen) } };
  for (const auto& row : rows)
  {
    std::printf("  %-26s %12.3e %12.3e\n", row.first, row.second.max, row.second.median);
  }
}

void printRatios(const lct_bench::RecordingReporter& reporter)
{
  auto get = [&](const std::string& name) { return reporter.Get(name); };
  std::printf(
    "\nSpeed against Eigen in this run (Eigen time / our time; targets: log >= 20x, exp >= 5x):\n");
  std::printf("  %-22s %10s %10s %8s %8s\n", "operation", "ours ns", "Eigen ns", "ratio", "target");
  const struct
  {
    const char* label;
    const char* ours;
    const char* eigen;
    double target;
  } rows[] = { { "4x4 log, Polar", "Log4_Polar", "Log4_Eigen", 20 },
    { "4x4 log, MatrixLog", "Log4_MatrixLog", "Log4_Eigen", 20 },
    { "4x4 exp, Polar", "Exp4_Polar", "Exp4_Eigen", 5 },
    { "4x4 exp, MatrixLog", "Exp4_MatrixLog", "Exp4_Eigen", 5 },
    { "3x3 SPD log", "LogSPD3_Ours", "LogSPD3_Eigen", 20 },
    { "3x3 sym exp", "ExpSym3_Ours", "ExpSym3_Eigen", 5 },
    { "so(3) exp", "ExpSO3_Ours", "ExpSO3_Eigen", 5 },
    { "SO(3) log", "LogSO3_Ours", "LogSO3_Eigen", 20 } };
  for (const auto& row : rows)
  {
    const double ours = get(row.ours);
    const double eigen = get(row.eigen);
    if (ours > 0.0 && eigen > 0.0)
    {
      const double ratio = eigen / ours;
      std::printf("  %-22s %10.1f %10.1f %7.1fx %7.0fx %s\n", row.label, ours, eigen, ratio,
        row.target, ratio >= row.target ? "met" : "MISSED");
    }
  }
}
} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  inputs();
  lct_bench::RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printRatios(reporter);
  printAccuracy();
  benchmark::Shutdown();
  return 0;
}
