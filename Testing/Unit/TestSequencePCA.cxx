// PCA of transform sequences in log space (lct/SequencePCA.h, vtkTransformSequencePCA; Alexa
// 2002 §6.3): exact reconstruction with every component, low-rank data, Eckart-Young optimality,
// weights, continuous rotation branches, the root channel, eigen-motions and bad input.
#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "lct/LogBasis.h"
#include "lct/Parametrisation.h"
#include "lct/SequencePCA.h"

#include "vtkTransformSequencePCA.h"

#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using lct::LogCoords;
using lct_test::ErrorCounter;
using lct_test::fromVtk;
using lct_test::kPi;
using lct_test::RandomTransforms;

LogCoords randomCoords(RandomTransforms& random, double size)
{
  LogCoords c;
  for (int i = 0; i < 12; ++i)
  {
    c[i] = size * random.Normal();
  }
  return c;
}

/// A smooth random animation: channel c at frame f is exp(a_c + sin(f / 7 + c) b_c + f / F e_c).
std::vector<Eigen::Matrix4d> animation(
  RandomTransforms& random, int frames, int channels, lct::Parametrisation p)
{
  std::vector<LogCoords> a, b, e;
  for (int c = 0; c < channels; ++c)
  {
    a.push_back(randomCoords(random, 0.3));
    b.push_back(randomCoords(random, 0.3));
    e.push_back(randomCoords(random, 0.3));
  }
  std::vector<Eigen::Matrix4d> out;
  for (int f = 0; f < frames; ++f)
  {
    for (int c = 0; c < channels; ++c)
    {
      const LogCoords log = a[c] + std::sin(f / 7.0 + c) * b[c] + (double(f) / frames) * e[c];
      out.push_back(lct::exponential(log, p).value);
    }
  }
  return out;
}

vtkSmartPointer<vtkCollection> frameOf(
  const std::vector<Eigen::Matrix4d>& all, int frame, int channels)
{
  auto frameItems = vtkSmartPointer<vtkCollection>::New();
  for (int c = 0; c < channels; ++c)
  {
    vtkNew<vtkMatrix4x4> m;
    lct_test::toVtk(all[static_cast<std::size_t>(frame * channels + c)], m);
    frameItems->AddItem(m);
  }
  return frameItems;
}

struct Watched
{
  vtkNew<vtkTransformSequencePCA> pca;
  vtkNew<ErrorCounter> errors;
  Watched() { pca->AddObserver(vtkCommand::ErrorEvent, errors); }
  void Load(const std::vector<Eigen::Matrix4d>& all, int frames, int channels)
  {
    for (int f = 0; f < frames; ++f)
    {
      ASSERT_EQ(this->pca->AddFrame(frameOf(all, f, channels)), 1);
    }
  }
};
} // namespace

TEST(SequencePCA, EveryComponentReproducesTheInput)
{
  RandomTransforms random(31);
  for (const int p : { vtkTransformSequencePCA::POLAR, vtkTransformSequencePCA::MATRIX_LOG })
  {
    const int frames = 60, channels = 7;
    const auto all = animation(random, frames, channels, static_cast<lct::Parametrisation>(p));
    Watched w;
    w.pca->SetParametrisation(p);
    w.Load(all, frames, channels);
    ASSERT_EQ(w.pca->Compute(), 1);
    const int k = w.pca->GetNumberOfComponents();
    EXPECT_GE(k, 3);
    EXPECT_LE(k, frames);
    EXPECT_NEAR(w.pca->GetExplainedFraction(k), 1.0, 1e-12);
    double worst = 0.0;
    vtkNew<vtkMatrix4x4> m;
    for (int f = 0; f < frames; ++f)
    {
      for (int c = 0; c < channels; ++c)
      {
        ASSERT_EQ(w.pca->GetReconstructedTransform(f, c, k, m), 1);
        worst = std::max(worst,
          (fromVtk(m) - all[static_cast<std::size_t>(f * channels + c)]).cwiseAbs().maxCoeff());
      }
    }
    EXPECT_LE(worst, 1e-10);
    EXPECT_EQ(w.errors->Count, 0);
  }
}

TEST(SequencePCA, LowRankDataHasExactlyThatManyComponents)
{
  RandomTransforms random(32);
  const int frames = 80, channels = 4;
  std::vector<LogCoords> mean, d[3];
  for (int c = 0; c < channels; ++c)
  {
    mean.push_back(randomCoords(random, 1.0));
    for (auto& direction : d)
    {
      direction.push_back(randomCoords(random, 1.0));
    }
  }
  std::vector<LogCoords> logs;
  for (int f = 0; f < frames; ++f)
  {
    const double s[3] = { random.Normal(), random.Normal(), 0.01 * random.Normal() };
    for (int c = 0; c < channels; ++c)
    {
      logs.push_back(mean[c] + s[0] * d[0][c] + s[1] * d[1][c] + s[2] * d[2][c]);
    }
  }
  const auto pca = lct::sequencePCA(logs.data(), frames, channels);
  ASSERT_TRUE(pca.ok());
  EXPECT_EQ(pca.value.size(), 3);
  EXPECT_NEAR(pca.value.explainedFraction(3), 1.0, 1e-14);
  EXPECT_LT(pca.value.explainedFraction(2), 1.0 - 1e-7);
  // The components are orthonormal in the weighted log inner product.
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      double inner = 0.0;
      for (int c = 0; c < channels; ++c)
      {
        inner += lct::logInnerProduct(pca.value.components.block<12, 1>(12 * c, i),
          pca.value.components.block<12, 1>(12 * c, j));
      }
      EXPECT_NEAR(inner, i == j ? 1.0 : 0.0, 1e-12);
    }
  }
  for (int f = 0; f < frames; ++f)
  {
    for (int c = 0; c < channels; ++c)
    {
      const auto r = lct::reconstructLog(pca.value, f, c, 3);
      ASSERT_TRUE(r.ok());
      EXPECT_LE((r.value - logs[static_cast<std::size_t>(f * channels + c)]).norm(), 1e-12);
    }
  }
}

namespace
{
/// `count` random log coordinates of size 1.
std::vector<LogCoords> randomLogs(RandomTransforms& random, int count)
{
  std::vector<LogCoords> logs;
  for (int i = 0; i < count; ++i)
  {
    logs.push_back(randomCoords(random, 1.0));
  }
  return logs;
}

/// The squared error, in the PCA's weighted inner product, of reconstructing every frame and
/// channel of `logs` from the first r components.
double reconstructionError(const lct::SequencePCA& pca, const std::vector<LogCoords>& logs, int r)
{
  double error = 0.0;
  for (int f = 0; f < pca.frames; ++f)
  {
    for (int c = 0; c < pca.channels; ++c)
    {
      const LogCoords off = lct::reconstructLog(pca, f, c, r).value -
        logs[static_cast<std::size_t>(f * pca.channels + c)];
      error += pca.weights[static_cast<std::size_t>(c)] * lct::logInnerProduct(off, off);
    }
  }
  return error;
}
} // namespace

// Eckart-Young: the squared reconstruction error with r components is the sum of the dropped
// squared singular values, and weights move the error away from the heavy channel.
TEST(SequencePCA, TruncationErrorIsTheDroppedVarianceAndWeightsSteerIt)
{
  RandomTransforms random(33);
  const int frames = 40, channels = 3;
  const std::vector<LogCoords> logs = randomLogs(random, frames * channels);
  const double weights[3] = { 1.0, 50.0, 1.0 };
  for (const bool weighted : { false, true })
  {
    const auto pca = lct::sequencePCA(logs.data(), frames, channels, weighted ? weights : nullptr);
    ASSERT_TRUE(pca.ok());
    ASSERT_EQ(pca.value.size(), 36);
    for (const int r : { 0, 1, 5, 20, 36 })
    {
      const double error = reconstructionError(pca.value, logs, r);
      const double dropped = pca.value.singularValues.tail(36 - r).squaredNorm();
      EXPECT_NEAR(error, dropped, 1e-10 * (1.0 + dropped)) << "r = " << r;
    }
  }
  // With weight 50 on channel 1, its share of the error of 12 components falls.
  auto channelError = [&](const double* w) {
    const auto pca = lct::sequencePCA(logs.data(), frames, channels, w);
    double e = 0.0;
    for (int f = 0; f < frames; ++f)
    {
      e += (lct::reconstructLog(pca.value, f, 1, 12).value -
        logs[static_cast<std::size_t>(f * channels + 1)])
             .squaredNorm();
    }
    return e;
  };
  EXPECT_LT(channelError(weights), 0.2 * channelError(nullptr));
}

// Audit (session 28): explainedFraction(r) counted components Compute had dropped: with 1 kept,
// r = 5 read 100 % while the reconstruction from "5" used the 1 and was off. It now reports what
// the reconstruction from r components leaves: 1 - explainedFraction(r) = its error's share.
TEST(SequencePCA, ExplainedFractionCountsOnlyTheKeptComponents)
{
  RandomTransforms random(34);
  const int frames = 12, channels = 2;
  const std::vector<LogCoords> logs = randomLogs(random, frames * channels);
  const auto all = lct::sequencePCA(logs.data(), frames, channels);
  ASSERT_TRUE(all.ok());
  for (const int kept : { 1, 3 })
  {
    const auto pca = lct::sequencePCA(logs.data(), frames, channels, nullptr, kept);
    ASSERT_TRUE(pca.ok());
    ASSERT_EQ(pca.value.size(), kept);
    for (const int r : { kept, kept + 1, 5, 100 })
    {
      EXPECT_EQ(pca.value.explainedFraction(r), all.value.explainedFraction(kept)) << r;
      const double error = reconstructionError(pca.value, logs, r); // weights 1
      const double total = all.value.singularValues.squaredNorm();
      EXPECT_NEAR(error / total, 1.0 - pca.value.explainedFraction(r), 1e-12) << r;
    }
    EXPECT_LT(pca.value.explainedFraction(100), 1.0 - 1e-6);
  }
}

// A joint spinning twice around z: Polar logs taken against the previous frame stay on a line
// (one component explains everything); principal MatrixLog logs jump at 180 degrees: reported.
TEST(SequencePCA, SpinBeyond180DegreesNeedsContinuousLogs)
{
  const int frames = 100; // no frame at exactly 180 degrees (no real log at all)
  std::vector<Eigen::Matrix4d> all;
  for (int f = 0; f < frames; ++f)
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(4.0 * kPi * f / (frames - 1), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    m(0, 3) = 0.01 * f;
    all.push_back(m);
  }
  Watched polar;
  polar.Load(all, frames, 1);
  ASSERT_EQ(polar.pca->Compute(), 1);
  EXPECT_EQ(polar.pca->GetNumberOfComponents(), 1);
  vtkNew<vtkMatrix4x4> m;
  ASSERT_EQ(polar.pca->GetReconstructedTransform(77, 0, 1, m), 1);
  EXPECT_LE((fromVtk(m) - all[77]).cwiseAbs().maxCoeff(), 1e-12);

  Watched matrixLog;
  matrixLog.pca->SetParametrisationToMatrixLog();
  matrixLog.Load(all, frames, 1);
  EXPECT_EQ(matrixLog.pca->Compute(), 0);
  EXPECT_NE(matrixLog.errors->Last.find("turns through 180 degrees between frames 24 and 25"),
    std::string::npos)
    << matrixLog.errors->Last;
  EXPECT_EQ(matrixLog.pca->GetNumberOfComponents(), 0);
}

// The root channel is not analysed, but its mean is a log all the same: a MatrixLog root that
// turns through 180 degrees (or sits at a half turn, which has no principal log) passed Compute
// and failed only later, in GetMeanTransform. Polar's continuous logs give the mean of a spin.
TEST(SequencePCA, RootChannelLogsAreCheckedByCompute)
{
  const int frames = 100, channels = 2;
  RandomTransforms random(36);
  std::vector<Eigen::Matrix4d> all;
  for (int f = 0; f < frames; ++f)
  {
    Eigen::Matrix4d root = Eigen::Matrix4d::Identity();
    root.topLeftCorner<3, 3>() =
      Eigen::AngleAxisd(4.0 * kPi * f / (frames - 1), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    root(0, 3) = 0.01 * f;
    all.push_back(root);
    all.push_back(random.Affine(lct_test::TransformClass::GeneralAffine));
  }
  Watched matrixLog;
  matrixLog.pca->SetParametrisationToMatrixLog();
  matrixLog.Load(all, frames, channels);
  matrixLog.pca->SetRootChannel(0);
  EXPECT_EQ(matrixLog.pca->Compute(), 0);
  EXPECT_NE(matrixLog.errors->Last.find("root channel 0 turns through 180 degrees between frames "
                                        "24 and 25"),
    std::string::npos)
    << matrixLog.errors->Last;
  vtkNew<vtkMatrix4x4> m;
  EXPECT_EQ(matrixLog.pca->GetMeanTransform(0, m), 0);

  // A root at exactly a half turn: no principal matrix log at all.
  std::vector<Eigen::Matrix4d> halfTurn(all.begin(), all.begin() + 2 * channels);
  halfTurn[static_cast<std::size_t>(channels)].topLeftCorner<3, 3>() =
    Eigen::Vector3d(-1.0, -1.0, 1.0).asDiagonal();
  Watched atHalfTurn;
  atHalfTurn.pca->SetParametrisationToMatrixLog();
  atHalfTurn.Load(halfTurn, 2, channels);
  atHalfTurn.pca->SetRootChannel(0);
  EXPECT_EQ(atHalfTurn.pca->Compute(), 0);
  EXPECT_NE(atHalfTurn.errors->Last.find("frame 1, root channel 0: "), std::string::npos)
    << atHalfTurn.errors->Last;

  // Polar: logs continuous in time, so the mean of two whole turns is the turn 2 pi (identity)
  // with the mean translation.
  Watched polar;
  polar.Load(all, frames, channels);
  polar.pca->SetRootChannel(0);
  ASSERT_EQ(polar.pca->Compute(), 1);
  ASSERT_EQ(polar.pca->GetMeanTransform(0, m), 1);
  Eigen::Matrix4d expected = Eigen::Matrix4d::Identity();
  expected(0, 3) = 0.01 * (frames - 1) / 2.0;
  EXPECT_LE((fromVtk(m) - expected).cwiseAbs().maxCoeff(), 1e-12) << fromVtk(m);
  EXPECT_EQ(polar.errors->Count, 0);
}

TEST(SequencePCA, RootChannelIsFactoredOutAndEigenMotionsAreTransforms)
{
  RandomTransforms random(34);
  const int frames = 30, channels = 4;
  auto all = animation(random, frames, channels, lct::Parametrisation::Polar);
  // A wild root motion that would dominate the analysis.
  for (int f = 0; f < frames; ++f)
  {
    Eigen::Matrix4d root = Eigen::Matrix4d::Identity();
    root.topLeftCorner<3, 3>() = random.Rotation();
    root.topRightCorner<3, 1>() = 100.0 * Eigen::Vector3d::Random();
    all[static_cast<std::size_t>(f * channels)] = root;
  }
  Watched w;
  w.Load(all, frames, channels);
  w.pca->SetRootChannel(0);
  ASSERT_EQ(w.pca->Compute(), 1);
  vtkNew<vtkMatrix4x4> m;
  for (int f = 0; f < frames; ++f)
  {
    ASSERT_EQ(w.pca->GetReconstructedTransform(f, 0, 0, m), 1);
    EXPECT_EQ(fromVtk(m), all[static_cast<std::size_t>(f * channels)]);
  }
  // About their means, the other channels move along sin(f / 7), cos(f / 7) and f: 3
  // components, which the root's wild motion would otherwise swamp.
  EXPECT_EQ(w.pca->GetNumberOfComponents(), 3);
  EXPECT_NEAR(w.pca->GetExplainedFraction(3), 1.0, 1e-12);
  vtkNew<vtkDoubleArray> fractions;
  ASSERT_EQ(w.pca->GetExplainedVariance(fractions), 1);
  ASSERT_EQ(fractions->GetNumberOfTuples(), w.pca->GetNumberOfComponents());
  EXPECT_GE(fractions->GetValue(0), 0.5);
  // Eigen-motion at s = 0 is the mean; at s it moves along the component.
  vtkNew<vtkMatrix4x4> mean, motion;
  ASSERT_EQ(w.pca->GetMeanTransform(2, mean), 1);
  ASSERT_EQ(w.pca->GetEigenMotion(0, 2, 0.0, motion), 1);
  EXPECT_LE((fromVtk(mean) - fromVtk(motion)).norm(), 1e-14);
  ASSERT_EQ(w.pca->GetEigenMotion(0, 2, 2.0, motion), 1);
  EXPECT_GT((fromVtk(mean) - fromVtk(motion)).norm(), 1e-3);
  vtkNew<vtkDoubleArray> scores;
  ASSERT_EQ(w.pca->GetScores(5, scores), 1);
  EXPECT_EQ(scores->GetNumberOfTuples(), w.pca->GetNumberOfComponents());
  EXPECT_EQ(w.errors->Count, 0);
}

TEST(SequencePCA, BadInputIsRefused)
{
  Watched w;
  int errors = 0;
  auto refused = [&](int returned, const char* fragment) {
    EXPECT_EQ(returned, 0) << fragment;
    EXPECT_EQ(w.errors->Count, ++errors) << fragment;
    EXPECT_NE(w.errors->Last.find(fragment), std::string::npos)
      << "wanted \"" << fragment << "\" in: " << w.errors->Last;
  };
  vtkNew<vtkMatrix4x4> m;
  vtkNew<vtkDoubleArray> a;
  refused(w.pca->Compute(), "no frames");
  refused(w.pca->GetReconstructedTransform(0, 0, 1, m), "Compute() first");
  refused(w.pca->GetExplainedVariance(a), "Compute() first");
  refused(w.pca->AddFrame(nullptr), "null collection");
  vtkNew<vtkCollection> frame;
  refused(w.pca->AddFrame(frame), "empty collection");
  frame->AddItem(m);
  frame->AddItem(a);
  refused(w.pca->AddFrame(frame), "item 1 is vtkDoubleArray");
  EXPECT_EQ(w.pca->GetNumberOfFrames(), 0);
  frame->RemoveAllItems();
  vtkNew<vtkMatrix4x4> m2;
  vtkNew<vtkTransform> t;
  t->RotateX(20.0);
  frame->AddItem(m);
  frame->AddItem(t);
  ASSERT_EQ(w.pca->AddFrame(frame), 1);
  ASSERT_EQ(w.pca->AddFrame(frame), 1);
  frame->AddItem(m2);
  refused(w.pca->AddFrame(frame), "3 transforms where every frame has 2 channels");
  EXPECT_EQ(w.pca->GetNumberOfFrames(), 2);
  refused(w.pca->SetChannelWeight(2, 1.0), "channel 2 is outside [0, 2)");
  refused(w.pca->SetChannelWeight(0, 0.0), "not finite and positive");
  refused(w.pca->SetChannelWeight(0, std::numeric_limits<double>::quiet_NaN()),
    "not finite and positive");
  w.pca->SetRootChannel(5);
  refused(w.pca->Compute(), "root channel 5 is outside [-1, 2)");
  w.pca->SetRootChannel(-1);
  // A NaN transform is named by frame and channel.
  vtkNew<vtkCollection> bad;
  vtkNew<vtkMatrix4x4> nan;
  nan->SetElement(1, 2, std::numeric_limits<double>::quiet_NaN());
  bad->AddItem(m);
  bad->AddItem(nan);
  ASSERT_EQ(w.pca->AddFrame(bad), 1);
  refused(w.pca->Compute(), "frame 2, channel 1: the matrix or coordinates contain NaN");
  w.pca->RemoveAllFrames();
  ASSERT_EQ(w.pca->AddFrame(frame), 1); // 3 channels now
  ASSERT_EQ(w.pca->AddFrame(frame), 1);
  ASSERT_EQ(w.pca->Compute(), 1);
  refused(w.pca->GetReconstructedTransform(2, 0, 1, m), "frame 2, channel 0 is outside");
  refused(w.pca->GetReconstructedTransform(0, 3, 1, m), "channel 3 is outside");
  // A negative count was taken as 0 (the mean), return 1.
  refused(w.pca->GetReconstructedTransform(0, 1, -3, m), "-3 components");
  EXPECT_EQ(w.pca->GetExplainedFraction(-1), 0.0);
  EXPECT_EQ(w.errors->Count, ++errors);
  EXPECT_NE(w.errors->Last.find("-1 components"), std::string::npos) << w.errors->Last;
  refused(w.pca->GetEigenMotion(0, 0, std::numeric_limits<double>::infinity(), m), "s = inf");
  refused(w.pca->GetScores(-1, a), "frame -1 is outside [0, 2)");
  // Queries after the input changed.
  ASSERT_EQ(w.pca->SetChannelWeight(1, 2.0), 1);
  refused(w.pca->GetMeanTransform(0, m), "the input changed since Compute()");
  // Weights 1e300 apart: the light channels fell below the SVD's resolution (noise), silently.
  ASSERT_EQ(w.pca->SetChannelWeight(1, 1e300), 1);
  refused(w.pca->Compute(), "channel weights from 1 (channel 0) to 1e+300 (channel 1) span more");
  ASSERT_EQ(w.pca->SetChannelWeight(1, 1e16), 1);
  EXPECT_EQ(w.pca->Compute(), 1);
  ASSERT_EQ(w.pca->SetChannelWeight(1, 1.0), 1);
  // Only the root channel.
  w.pca->RemoveAllFrames();
  vtkNew<vtkCollection> single;
  single->AddItem(t);
  ASSERT_EQ(w.pca->AddFrame(single), 1);
  w.pca->SetRootChannel(0);
  refused(w.pca->Compute(), "nothing to analyse");
  // Core: invalid arguments.
  const LogCoords logs[2] = { LogCoords::Zero(), LogCoords::Ones() };
  EXPECT_EQ(lct::sequencePCA(logs, 0, 1).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::sequencePCA(nullptr, 2, 1).status, lct::Status::InvalidArgument);
  const double negative[1] = { -1.0 };
  EXPECT_EQ(lct::sequencePCA(logs, 2, 1, negative).status, lct::Status::InvalidArgument);
  LogCoords withNaN[2] = { LogCoords::Zero(), LogCoords::Ones() };
  withNaN[1][4] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(lct::sequencePCA(withNaN, 2, 1).status, lct::Status::NonFinite);
  const auto ok = lct::sequencePCA(logs, 2, 1);
  ASSERT_TRUE(ok.ok());
  EXPECT_EQ(lct::reconstructLog(ok.value, 2, 0, 1).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::componentLog(ok.value, 1, 0, 1.0).status, lct::Status::InvalidArgument);
  EXPECT_EQ(lct::componentLog(ok.value, 0, 0, std::numeric_limits<double>::quiet_NaN()).status,
    lct::Status::NonFinite);
  const LogCoords wide[2] = { LogCoords::Constant(1.7e308), LogCoords::Constant(-1.7e308) };
  const auto w2 = lct::sequencePCA(wide, 2, 1);
  EXPECT_TRUE(w2.ok() || w2.status == lct::Status::OutOfRange);
}

// The widest spread of channel weights accepted (kMaxChannelWeightRatio) still reproduces the
// light channels from every component, to ~8 digits; beyond it they would be noise, so it is
// refused.
TEST(SequencePCA, WeightsAtTheSpreadLimitKeepTheLightChannels)
{
  RandomTransforms random(7);
  const int frames = 40, channels = 3;
  std::vector<LogCoords> logs(static_cast<std::size_t>(frames * channels));
  for (LogCoords& l : logs)
  {
    l = lct::logarithm(
      random.Affine(lct_test::TransformClass::GeneralAffine), lct::Parametrisation::Polar)
          .value;
  }
  const double limit[channels] = { 1.0, lct::kMaxChannelWeightRatio, 1.0 };
  const auto pca = lct::sequencePCA(logs.data(), frames, channels, limit);
  ASSERT_TRUE(pca.ok());
  double worst = 0.0;
  for (int f = 0; f < frames; ++f)
  {
    for (int c = 0; c < channels; ++c)
    {
      const auto back = lct::reconstructLog(pca.value, f, c, pca.value.size());
      ASSERT_TRUE(back.ok());
      worst = std::max(worst,
        (back.value - logs[static_cast<std::size_t>(f * channels + c)]).norm() /
          logs[static_cast<std::size_t>(f * channels + c)].norm());
    }
  }
  EXPECT_LE(worst, 1e-6);
  const double beyond[channels] = { 1.0, 4 * lct::kMaxChannelWeightRatio, 1.0 };
  EXPECT_EQ(
    lct::sequencePCA(logs.data(), frames, channels, beyond).status, lct::Status::InvalidArgument);
}

// FuzzAnalysis A2: singular values near 1e200 squared to Inf, and the explained fractions were
// NaN. They are formed in units of the largest singular value.
TEST(SequencePCA, ExplainedVarianceOfHugeMotionsIsFinite)
{
  RandomTransforms random(35);
  std::vector<LogCoords> logs;
  for (int f = 0; f < 10; ++f)
  {
    logs.push_back(1e200 * randomCoords(random, 1.0));
  }
  const auto pca = lct::sequencePCA(logs.data(), 10, 1);
  ASSERT_TRUE(pca.ok());
  double sum = 0.0;
  for (int i = 0; i < pca.value.size(); ++i)
  {
    ASSERT_TRUE(std::isfinite(pca.value.varianceShare(i)));
    sum += pca.value.varianceShare(i);
  }
  EXPECT_NEAR(sum, 1.0, 1e-12);
  EXPECT_NEAR(pca.value.explainedFraction(pca.value.size()), 1.0, 1e-12);
  EXPECT_GT(pca.value.explainedFraction(1), 0.0);
}

// FuzzAnalysis A3: constant data has no component; reconstructing from 0 components took a
// block of the empty component matrix (a null data pointer plus an offset: UB). It is the mean.
TEST(SequencePCA, ConstantDataHasNoComponentAndReconstructsToTheMean)
{
  RandomTransforms random(36);
  const LogCoords c = randomCoords(random, 1.0);
  const std::vector<LogCoords> logs(6, c);
  const auto pca = lct::sequencePCA(logs.data(), 3, 2);
  ASSERT_TRUE(pca.ok());
  EXPECT_EQ(pca.value.size(), 0);
  for (const int r : { 0, 1, 5 })
  {
    const auto back = lct::reconstructLog(pca.value, 2, 1, r);
    ASSERT_TRUE(back.ok());
    EXPECT_LE((back.value - c).norm(), 1e-15 * c.norm());
  }
  EXPECT_EQ(pca.value.explainedFraction(0), 0.0);
}

// FuzzAnalysis A5: the root channel is factored out and not logged, so nothing checked it: a
// projective bottom row (a denormal 1.9e-319 in the fuzz input) or a reflection was accepted and
// handed back by GetReconstructedTransform as if it were a transform.
TEST(SequencePCA, AnInvalidRootChannelIsRefused)
{
  RandomTransforms random(35);
  const int frames = 6, channels = 3;
  for (int variant = 0; variant < 3; ++variant)
  {
    auto all = animation(random, frames, channels, lct::Parametrisation::MatrixLog);
    Eigen::Matrix4d& root = all[static_cast<std::size_t>(4 * channels)];
    if (variant == 0)
    {
      root(3, 0) = 1.8665306034236453e-319;
    }
    else if (variant == 1)
    {
      root.row(0) = -root.row(0);
    }
    else
    {
      root(0, 3) = std::numeric_limits<double>::quiet_NaN();
    }
    Watched w;
    w.Load(all, frames, channels);
    w.pca->SetParametrisationToMatrixLog();
    w.pca->SetRootChannel(0);
    EXPECT_EQ(w.pca->Compute(), 0) << variant;
    EXPECT_NE(w.errors->Last.find("frame 4, root channel 0"), std::string::npos) << w.errors->Last;
    vtkNew<vtkMatrix4x4> m;
    EXPECT_EQ(w.pca->GetReconstructedTransform(4, 0, 0, m), 0);
  }
}
