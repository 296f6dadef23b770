// lct::KeyLogs: incremental updates equal a full rebuild; the relative form keeps translations
// the keys share; the hand-over is symmetric.
#include "lct/Affine.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"
#include "lct/SO3.h"

#include "RandomTransforms.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using lct::Parametrisation;

namespace
{
/// Evaluates both logs at many curve points and returns the largest difference.
double maxDifference(const lct::KeyLogs& a, const lct::KeyLogs& b, const std::vector<double>& times)
{
  double worst = 0.0;
  const int n = static_cast<int>(times.size());
  for (lct::CurveScheme s :
    { lct::CurveScheme::Linear, lct::CurveScheme::CatmullRom, lct::CurveScheme::Subdivision })
  {
    for (int k = 0; k <= 50; ++k)
    {
      const double t = times.front() + (times.back() - times.front()) * k / 50.0;
      const lct::CurveWeights w = lct::curveWeights(s, times.data(), n, t);
      Eigen::Matrix4d ra, rb, aa, ab;
      EXPECT_EQ(a.combineRelative(w, ra), lct::Status::Ok);
      EXPECT_EQ(b.combineRelative(w, rb), lct::Status::Ok);
      EXPECT_EQ(a.combineAbsolute(w, aa), lct::Status::Ok);
      EXPECT_EQ(b.combineAbsolute(w, ab), lct::Status::Ok);
      worst = std::max({ worst, (ra - rb).norm(), (aa - ab).norm() });
    }
  }
  return worst;
}
} // namespace

TEST(KeyLogs, IncrementalUpdatesEqualAFullBuild)
{
  lct_test::RandomTransforms random(31);
  lct::KeyLogs incremental;
  std::vector<Eigen::Matrix4d> matrices;
  std::vector<double> times;
  for (int step = 0; step < 300; ++step)
  {
    const int n = static_cast<int>(matrices.size());
    const double action = random.Uniform(0.0, 1.0);
    const Eigen::Matrix4d m = random.Affine(lct_test::TransformClass::GeneralAffine);
    if (n < 3 || action < 0.6)
    {
      const int index = static_cast<int>(random.Uniform(0.0, n + 0.999));
      ASSERT_EQ(incremental.insert(index, m, true), lct::Status::Ok);
      matrices.insert(matrices.begin() + index, m);
    }
    else if (action < 0.8)
    {
      const int index = static_cast<int>(random.Uniform(0.0, n - 0.001));
      ASSERT_EQ(incremental.replace(index, m, true), lct::Status::Ok);
      matrices[index] = m;
    }
    else
    {
      const int index = static_cast<int>(random.Uniform(0.0, n - 0.001));
      ASSERT_EQ(incremental.erase(index, true), lct::Status::Ok);
      matrices.erase(matrices.begin() + index);
    }
  }
  lct::KeyLogs full;
  ASSERT_EQ(full.build(matrices, Parametrisation::Polar, true), lct::Status::Ok);
  ASSERT_EQ(incremental.size(), matrices.size());
  times.resize(matrices.size());
  for (size_t i = 0; i < times.size(); ++i)
  {
    times[i] = static_cast<double>(i);
    EXPECT_EQ(incremental.matrix(i), matrices[i]);
  }
  EXPECT_EQ(maxDifference(incremental, full, times), 0.0);
}

TEST(KeyLogs, RelativeFormKeepsASharedTranslation)
{
  // A bone: keys T(1, 0, 0) Rz(0, 60, 120, 180, 240) in Polar coordinates. Every curve point keeps
  // the translation (1, 0, 0) (in the world-frame relative form it swung out to 1.116).
  std::vector<Eigen::Matrix4d> keys;
  std::vector<double> times;
  for (int k = 0; k < 5; ++k)
  {
    keys.push_back(lct::makeAffine(
      lct::expSO3(Eigen::Vector3d(0, 0, k * lct_test::kPi / 3)), Eigen::Vector3d(1, 0, 0)));
    times.push_back(k);
  }
  lct::KeyLogs logs;
  ASSERT_EQ(logs.build(keys, Parametrisation::Polar, true), lct::Status::Ok);
  for (lct::CurveScheme s : { lct::CurveScheme::Linear, lct::CurveScheme::CatmullRom,
         lct::CurveScheme::BSpline, lct::CurveScheme::Subdivision })
  {
    for (int k = 0; k <= 400; ++k)
    {
      const lct::CurveWeights w = lct::curveWeights(s, times.data(), 5, k / 100.0);
      Eigen::Matrix4d m;
      ASSERT_EQ(logs.combineRelative(w, m), lct::Status::Ok);
      EXPECT_LT((m.topRightCorner<3, 1>() - Eigen::Vector3d(1, 0, 0)).norm(), 1e-14);
    }
  }
}

TEST(KeyLogs, FailedUpdatesLeaveTheLogsUnchanged)
{
  // MatrixLog: a half turn with non-uniform scale next to the identity has no real log.
  lct::KeyLogs logs(Parametrisation::MatrixLog);
  ASSERT_EQ(logs.insert(0, Eigen::Matrix4d::Identity(), true), lct::Status::Ok);
  Eigen::Matrix4d halfTurn = Eigen::Matrix4d::Identity();
  halfTurn(0, 0) = -2.0;
  halfTurn(1, 1) = -1.0;
  EXPECT_EQ(logs.insert(1, halfTurn, true), lct::Status::NoRealLogarithm);
  EXPECT_EQ(logs.size(), 1u);
  Eigen::Matrix4d quarter =
    lct::makeAffine(lct::expSO3(Eigen::Vector3d(0, 0, 1.5)), Eigen::Vector3d::Zero());
  ASSERT_EQ(logs.insert(1, quarter, true), lct::Status::Ok);
  EXPECT_EQ(logs.replace(1, halfTurn, true), lct::Status::NoRealLogarithm);
  EXPECT_EQ(logs.matrix(1), quarter);
}

TEST(KeyLogs, CurveNeedsAreCheckedAlikeInPlaceAndFromAWindow)
{
  // The interpolators check an edit either in the logs (KeyLogs::insert with CurveNeeds, when
  // they are current) or by computing the logs it adds in a window of keys (lct::
  // missingAfterEdit, when they are stale); both must accept exactly the key sets whose every
  // combined log exists, which a full check of every segment decides. Keys: HardKey (steps
  // beyond the conditioning limit, half turns without a real log), inserted at random times.
  struct TimedKey
  {
    double Time;
    Eigen::Matrix4d Matrix;
  };
  lct_test::RandomTransforms random(1920);
  int refused = 0;
  for (lct::CurveScheme scheme : { lct::CurveScheme::Linear, lct::CurveScheme::CatmullRom,
         lct::CurveScheme::BSpline, lct::CurveScheme::Subdivision })
  {
    for (Parametrisation p : { Parametrisation::Polar, Parametrisation::MatrixLog })
    {
      for (bool absolute : { false, true })
      {
        const lct::CurveNeeds needs{ scheme, absolute };
        lct::KeyLogs logs(p);
        lct::Keyframes<TimedKey> keys;
        for (int k = 0; k < 40; ++k)
        {
          const Eigen::Matrix4d m = random.HardKey(false);
          const TimedKey key{ std::floor(random.Uniform(0.0, 1000.0)), m };
          if (keys.find(key.Time))
          {
            continue;
          }
          // The window check, then the in-place one, then the whole set.
          const auto window = lct::keyWindow(keys, key.Time, &key);
          const lct::MissingLog fromWindow = lct::missingAfterEdit(
            window, false, [](const TimedKey& t) { return t.Matrix; }, p, needs, true);
          keys.flatten();
          const int index =
            static_cast<int>(std::lower_bound(keys.times().begin(), keys.times().end(), key.Time) -
              keys.times().begin());
          lct::MissingLog inPlace;
          const lct::Status status = logs.insert(index, m, true, needs, &inPlace);
          std::vector<Eigen::Matrix4d> all;
          for (size_t i = 0; i < keys.size(); ++i)
          {
            all.push_back(keys[i].Matrix);
          }
          all.insert(all.begin() + index, m);
          lct::KeyLogs full(p);
          lct::MissingLog whole;
          const lct::Status wholeStatus = full.build(all, p, true, needs, &whole);
          EXPECT_EQ(fromWindow.missing(), inPlace.missing()) << k;
          EXPECT_EQ(status == lct::Status::Ok, !inPlace.missing()) << k;
          EXPECT_EQ(wholeStatus == lct::Status::Ok, !inPlace.missing()) << k;
          if (inPlace.missing())
          {
            ++refused;
            EXPECT_EQ(logs.size(), keys.size()); // unchanged
            continue;
          }
          keys.set(key);
          ASSERT_EQ(logs.size(), keys.size());
          EXPECT_FALSE(logs.missingLog(needs).missing());
        }
      }
    }
  }
  EXPECT_GT(refused, 40);
}
