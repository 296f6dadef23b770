// ns/op of the analysis in log space (Alexa §6.2-6.3), against Alexa's own recipe written with
// Eigen in the same run:
//  - factoring onto a basis: lct::factorOntoBasis (the SVD of the basis, analysed once) against
//    inverting the Gram matrix V by SVD once and mapping the inner products <log T, log B_i>
//    through V^-1 (the coefficients agree to rounding; ours keeps twice the digits);
//  - the analysis itself: lct::analyseBasis against the Gram matrix and its SVD;
//  - PCA of Alexa's animation size (580 frames x 17 joints): lct::sequencePCA against Eigen's
//    BDCSVD of the same (uncentred) matrix, i.e. what the centring, weighting and scaling cost;
//  - vtkTransformBasisLCT::Factor, the log of the transform included.
#include "vtkTransformBasisLCT.h"

#include "lct/LogBasis.h"
#include "lct/Parametrisation.h"
#include "lct/SequencePCA.h"

#include "../Unit/RandomTransforms.h"

#include <vtkDoubleArray.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <Eigen/SVD>
#include <benchmark/benchmark.h>

#include <vector>

namespace
{
using lct::LogCoords;

std::vector<LogCoords> randomLogs(int n, std::uint64_t seed)
{
  lct_test::RandomTransforms random(seed);
  std::vector<LogCoords> logs;
  while (static_cast<int>(logs.size()) < n)
  {
    const auto c = lct::logarithm(
      random.Affine(lct_test::TransformClass::GeneralAffine), lct::Parametrisation::Polar);
    if (c)
    {
      logs.push_back(c.value);
    }
  }
  return logs;
}

const std::vector<LogCoords>& targets()
{
  static const std::vector<LogCoords> t = randomLogs(256, 7);
  return t;
}

void Factor_Ours(benchmark::State& state)
{
  const int k = static_cast<int>(state.range(0));
  const auto basisLogs = randomLogs(k, 3);
  const lct::LogBasis basis = lct::analyseBasis(basisLogs.data(), basisLogs.size()).value;
  std::size_t i = 0;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(lct::factorOntoBasis(basis, targets()[i++ & 255]));
  }
}

void Factor_AlexaGramInverse(benchmark::State& state)
{
  const int k = static_cast<int>(state.range(0));
  const auto basisLogs = randomLogs(k, 3);
  Eigen::MatrixXd gram(k, k);
  for (int a = 0; a < k; ++a)
  {
    for (int b = 0; b < k; ++b)
    {
      gram(a, b) = lct::logInnerProduct(basisLogs[a], basisLogs[b]);
    }
  }
  const Eigen::MatrixXd inverse =
    Eigen::JacobiSVD<Eigen::MatrixXd>(gram, Eigen::ComputeFullU | Eigen::ComputeFullV)
      .solve(Eigen::MatrixXd::Identity(k, k));
  std::size_t i = 0;
  Eigen::VectorXd inner(k);
  for (auto _ : state)
  {
    const LogCoords& c = targets()[i++ & 255];
    for (int a = 0; a < k; ++a)
    {
      inner[a] = lct::logInnerProduct(c, basisLogs[a]);
    }
    benchmark::DoNotOptimize(Eigen::VectorXd(inverse * inner));
  }
}

void Analyse_Ours(benchmark::State& state)
{
  const int k = static_cast<int>(state.range(0));
  const auto basisLogs = randomLogs(k, 3);
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(lct::analyseBasis(basisLogs.data(), basisLogs.size()));
  }
}

void Analyse_AlexaGramSVD(benchmark::State& state)
{
  const int k = static_cast<int>(state.range(0));
  const auto basisLogs = randomLogs(k, 3);
  for (auto _ : state)
  {
    Eigen::MatrixXd gram(k, k);
    for (int a = 0; a < k; ++a)
    {
      for (int b = 0; b < k; ++b)
      {
        gram(a, b) = lct::logInnerProduct(basisLogs[a], basisLogs[b]);
      }
    }
    benchmark::DoNotOptimize(
      Eigen::JacobiSVD<Eigen::MatrixXd>(gram, Eigen::ComputeFullU | Eigen::ComputeFullV));
  }
}

// Alexa's animation: 580 frames x 17 joints.
constexpr int kFrames = 580;
constexpr int kJoints = 17;

const std::vector<LogCoords>& animation()
{
  static const std::vector<LogCoords> logs = randomLogs(kFrames * kJoints, 11);
  return logs;
}

void PCA_Ours(benchmark::State& state)
{
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(lct::sequencePCA(animation().data(), kFrames, kJoints));
  }
}

void PCA_EigenBDCSVD(benchmark::State& state)
{
  for (auto _ : state)
  {
    Eigen::MatrixXd rows(kFrames, 12 * kJoints);
    for (int f = 0; f < kFrames; ++f)
    {
      for (int j = 0; j < kJoints; ++j)
      {
        rows.block<1, 12>(f, 12 * j) = animation()[f * kJoints + j].transpose();
      }
    }
    benchmark::DoNotOptimize(
      Eigen::BDCSVD<Eigen::MatrixXd>(rows, Eigen::ComputeThinU | Eigen::ComputeThinV));
  }
}

void Factor_vtkTransformBasisLCT(benchmark::State& state)
{
  lct_test::RandomTransforms random(5);
  vtkNew<vtkTransformBasisLCT> basis;
  for (int i = 0; i < 6; ++i)
  {
    vtkNew<vtkMatrix4x4> m;
    const Eigen::Matrix4d a = random.Affine(lct_test::TransformClass::GeneralAffine);
    for (int e = 0; e < 16; ++e)
    {
      m->SetElement(e / 4, e % 4, a(e / 4, e % 4));
    }
    basis->AddBasisTransform(m);
  }
  vtkNew<vtkMatrix4x4> t;
  const Eigen::Matrix4d a = random.Affine(lct_test::TransformClass::GeneralAffine);
  for (int e = 0; e < 16; ++e)
  {
    t->SetElement(e / 4, e % 4, a(e / 4, e % 4));
  }
  vtkNew<vtkDoubleArray> x;
  for (auto _ : state)
  {
    benchmark::DoNotOptimize(basis->Factor(t, x));
  }
}
} // namespace

BENCHMARK(Factor_Ours)->Arg(3)->Arg(12);
BENCHMARK(Factor_AlexaGramInverse)->Arg(3)->Arg(12);
BENCHMARK(Analyse_Ours)->Arg(3)->Arg(12);
BENCHMARK(Analyse_AlexaGramSVD)->Arg(3)->Arg(12);
BENCHMARK(PCA_Ours)->Unit(benchmark::kMillisecond);
BENCHMARK(PCA_EigenBDCSVD)->Unit(benchmark::kMillisecond);
BENCHMARK(Factor_vtkTransformBasisLCT);

BENCHMARK_MAIN();
