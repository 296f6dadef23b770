// ns per call of the vtkLogTransform operations that commit a new state (SetMatrix,
// SetLogCoordinates, Scale, Interpolate), of Inverse() and GetInverse(), and of
// InterpolateTransform into a vtkLogTransform output, in both parametrisations, on 1024 generic
// affine keys (turns up to 170 degrees, shear, non-uniform scale). Every commit validates the new
// state (its matrix and its inverse), so these rows show what that validation costs on the
// common path.
#include "vtkLogTransform.h"
#include "vtkTransformInterpolatorLCT.h"

#include "lct/Parametrisation.h"

#include "../Unit/RandomTransforms.h"
#include "RecordingReporter.h"

#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <Eigen/Eigenvalues>
#include <benchmark/benchmark.h>

#include <cstdio>
#include <vector>

namespace
{
constexpr int kInputs = 1024;

/// Generic affine maps that have a real matrix log too (so that both parametrisations take
/// every input), with their matrices in VTK's row-major order and their log coordinates.
struct Inputs
{
  std::vector<vtkSmartPointer<vtkMatrix4x4>> matrices;
  std::vector<lct::LogCoords> logs[2]; // Polar, MatrixLog

  Inputs()
  {
    lct_test::RandomTransforms random(2026);
    while (static_cast<int>(this->matrices.size()) < kInputs)
    {
      const Eigen::Vector3d s(
        random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0));
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m.topLeftCorner<3, 3>() =
        random.Rotation(random.Uniform(0.0, 170.0 * lct_test::kPi / 180.0)) * s.asDiagonal() *
        random.Rotation();
      m.topRightCorner<3, 1>() = random.Translation(lct_test::TransformClass::Rigid);
      const auto polar = lct::logarithm(m, lct::Parametrisation::Polar);
      const auto matrixLog = lct::logarithm(m, lct::Parametrisation::MatrixLog);
      if (!polar || !matrixLog)
      {
        continue;
      }
      auto vtk = vtkSmartPointer<vtkMatrix4x4>::New();
      for (int i = 0; i < 16; ++i)
      {
        vtk->SetElement(i / 4, i % 4, m(i / 4, i % 4));
      }
      this->matrices.push_back(vtk);
      this->logs[0].push_back(polar.value);
      this->logs[1].push_back(matrixLog.value);
    }
  }
};

const Inputs& inputs()
{
  static const Inputs data;
  return data;
}

/// state.range(0): the parametrisation (vtkLogTransform::POLAR or MATRIX_LOG).
vtkSmartPointer<vtkLogTransform> makeTransform(const benchmark::State& state)
{
  auto t = vtkSmartPointer<vtkLogTransform>::New();
  t->SetParametrisation(static_cast<int>(state.range(0)));
  return t;
}

void SetMatrix(benchmark::State& state)
{
  auto t = makeTransform(state);
  int i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(t->SetMatrix(inputs().matrices[i].Get()));
    i = (i + 1) & (kInputs - 1);
  }
}

void SetLogCoordinates(benchmark::State& state)
{
  auto t = makeTransform(state);
  const auto& logs = inputs().logs[state.range(0)];
  int i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(t->SetLogCoordinates(logs[i].data()));
    i = (i + 1) & (kInputs - 1);
  }
}

/// Scale(0.5) of a freshly set state (the set is measured too: subtract SetLogCoordinates).
void SetLogCoordinatesAndScale(benchmark::State& state)
{
  auto t = makeTransform(state);
  const auto& logs = inputs().logs[state.range(0)];
  int i = 0;
  for (auto _ : state)
  {
    t->SetLogCoordinates(logs[i].data());
    benchmark::DoNotOptimize(t->Scale(0.5));
    i = (i + 1) & (kInputs - 1);
  }
}

void Interpolate(benchmark::State& state)
{
  const auto& logs = inputs().logs[state.range(0)];
  std::vector<vtkSmartPointer<vtkLogTransform>> keys;
  for (int i = 0; i < kInputs; ++i)
  {
    keys.push_back(makeTransform(state));
    keys.back()->SetLogCoordinates(logs[i].data());
  }
  auto t = makeTransform(state);
  int i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(t->Interpolate(keys[i], keys[(i + 1) & (kInputs - 1)], 0.3));
    i = (i + 1) & (kInputs - 1);
  }
}

/// Inverse() of a freshly set state (the set is measured too: subtract SetLogCoordinates).
void SetLogCoordinatesAndInverse(benchmark::State& state)
{
  auto t = makeTransform(state);
  const auto& logs = inputs().logs[state.range(0)];
  int i = 0;
  for (auto _ : state)
  {
    t->SetLogCoordinates(logs[i].data());
    t->Inverse();
    i = (i + 1) & (kInputs - 1);
  }
}

/// GetInverse() of a freshly set state, read as a user would (VTK builds it on GetMatrix():
/// a DeepCopy, then Inverse()).
void SetLogCoordinatesAndGetInverse(benchmark::State& state)
{
  auto t = makeTransform(state);
  const auto& logs = inputs().logs[state.range(0)];
  int i = 0;
  for (auto _ : state)
  {
    t->SetLogCoordinates(logs[i].data());
    auto* inverse = static_cast<vtkLinearTransform*>(t->GetInverse());
    benchmark::DoNotOptimize(inverse->GetMatrix()->GetData()[3]);
    i = (i + 1) & (kInputs - 1);
  }
}

/// The interpolator's vtkLogTransform output: InterpolateTransform ends in its SetMatrix. Ten
/// Spline keys of a random walk (steps of up to 30 degrees and 15 % of scale, as
/// BenchInterpolators).
void InterpolateTransformIntoLogTransform(benchmark::State& state)
{
  vtkNew<vtkTransformInterpolatorLCT> path;
  path->SetParametrisation(static_cast<int>(state.range(0)));
  lct_test::RandomTransforms random(77);
  Eigen::Matrix4d key = Eigen::Matrix4d::Identity();
  for (int k = 0; k < 10; ++k)
  {
    vtkNew<vtkMatrix4x4> m;
    for (int i = 0; i < 16; ++i)
    {
      m->SetElement(i / 4, i % 4, key(i / 4, i % 4));
    }
    path->AddTransform(k, m);
    key = random.KeyframeStep() * key;
  }
  auto t = makeTransform(state);
  int i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(path->InterpolateTransform(9.0 * i / kInputs, t.Get()));
    i = (i + 1) & (kInputs - 1);
  }
}

#define LCT_BOTH_PARAMETRISATIONS(name)                                                            \
  BENCHMARK(name)->Arg(vtkLogTransform::POLAR)->Arg(vtkLogTransform::MATRIX_LOG)
LCT_BOTH_PARAMETRISATIONS(SetMatrix);
LCT_BOTH_PARAMETRISATIONS(SetLogCoordinates);
LCT_BOTH_PARAMETRISATIONS(SetLogCoordinatesAndScale);
LCT_BOTH_PARAMETRISATIONS(Interpolate);
LCT_BOTH_PARAMETRISATIONS(SetLogCoordinatesAndInverse);
LCT_BOTH_PARAMETRISATIONS(SetLogCoordinatesAndGetInverse);
LCT_BOTH_PARAMETRISATIONS(InterpolateTransformIntoLogTransform);

void printTable(const lct_bench::RecordingReporter& reporter)
{
  std::printf("\nvtkLogTransform, ns per call (medians when repeated):\n");
  std::printf("  %-38s %10s %10s\n", "operation", "Polar", "MatrixLog");
  const char* const rows[] = { "SetMatrix", "SetLogCoordinates", "SetLogCoordinatesAndScale",
    "Interpolate", "SetLogCoordinatesAndInverse", "SetLogCoordinatesAndGetInverse",
    "InterpolateTransformIntoLogTransform" };
  for (const char* row : rows)
  {
    const std::string name(row);
    std::printf(
      "  %-38s %10.1f %10.1f\n", row, reporter.Get(name + "/0"), reporter.Get(name + "/1"));
  }
}
} // namespace

int main(int argc, char** argv)
{
  benchmark::Initialize(&argc, argv);
  inputs();
  lct_bench::RecordingReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  printTable(reporter);
  benchmark::Shutdown();
  return 0;
}
