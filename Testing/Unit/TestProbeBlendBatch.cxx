// The batched probe blends (lct/ProbeBlendBatch.h) against the point-by-point ones
// (lct::blendAtPoint): the same maps to a few ulps for every supported mode, rigid and affine
// probes, random, zero, single and negative weights, turns up to and beyond 2 pi, and every
// number of probes; the special points (one weight of 1, all weights 0) exactly.
#include "lct/ProbeBlend.h"
#include "lct/ProbeBlendBatch.h"
#include "lct/SO3.h"

#include "RandomTransforms.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using lct_test::RandomTransforms;
using lct_test::TransformClass;

/// Probes: random rigid or affine maps, turns of up to `maxTurn` radians, each probe's rotation
/// log taken on the branch of a reference of that turn (beyond pi too).
lct::ProbeBlendSet probes(RandomTransforms& r, int n, bool affine, lct::BlendMode mode,
  double maxTurn)
{
  std::vector<Eigen::Matrix4d> relative;
  std::vector<Eigen::Vector3d> centres, references;
  for (int k = 0; k < n; ++k)
  {
    Eigen::Matrix4d a = r.Affine(affine ? TransformClass::GeneralAffine : TransformClass::Rigid);
    const Eigen::Vector3d axis = Eigen::Vector3d::Random().normalized();
    const double turn = r.Uniform(0.0, maxTurn);
    const Eigen::Matrix3d rotation = lct::expSO3(turn * axis);
    if (affine)
    {
      a.topLeftCorner<3, 3>() = rotation * a.topLeftCorner<3, 3>().transpose() *
        a.topLeftCorner<3, 3>(); // R S with S symmetric positive definite
    }
    else
    {
      a.topLeftCorner<3, 3>() = rotation;
    }
    relative.push_back(a);
    centres.push_back(Eigen::Vector3d::Random() * 5.0);
    references.push_back(turn * axis);
  }
  const lct::ProbePreparation p = lct::prepareProbes(
    relative, centres, mode == lct::BlendMode::Polar ? references : std::vector<Eigen::Vector3d>{},
    mode);
  EXPECT_TRUE(p.ok());
  return p.set;
}

double difference(const lct::PointMap& a, const lct::PointMap& b)
{
  const Eigen::Vector3d p(1.5, -2.0, 0.7);
  return (a.apply(p) - b.apply(p)).norm() + (a.linearMinusIdentity - b.linearMinusIdentity).norm();
}
} // namespace

TEST(ProbeBlendBatch, EqualsThePointByPointBlendForEveryModeAndProbeCount)
{
  RandomTransforms r(2024);
  int compared = 0;
  for (const lct::BlendMode mode :
    { lct::BlendMode::Polar, lct::BlendMode::Linear, lct::BlendMode::DualQuaternion })
  {
    for (const bool affine : { false, true })
    {
      for (int n = 1; n <= lct::kProbeBatchMaxProbes; ++n)
      {
        for (const double maxTurn : { 1.0, 3.1, 6.0, 9.0 })
        {
          const lct::ProbeBlendSet set = probes(r, n, affine, mode, maxTurn);
          lct::ProbeBatchSet batch;
          const bool supported = lct::prepareProbeBatch(set, batch);
          ASSERT_EQ(supported, mode != lct::BlendMode::DualQuaternion || set.allRigid);
          if (!supported)
          {
            continue;
          }
          for (int trial = 0; trial < 8; ++trial)
          {
            lct::ProbeBatchWeights w;
            const int count = 1 + trial % lct::kProbeBatch;
            for (int j = 0; j < lct::kProbeBatch; ++j)
            {
              for (int k = 0; k < n; ++k)
              {
                w[k][j] = r.Uniform(0.0, 1.0) < 0.2 ? 0.0 : r.Uniform(-0.3, 1.0);
              }
            }
            // Special lanes: one weight of exactly 1, all weights 0.
            for (int k = 0; k < n; ++k)
            {
              w[k][0] = k == n - 1 ? 1.0 : 0.0;
              w[k][1] = 0.0;
            }
            if (lct::normalizeBatch(lct::WeightNormalization::None, n, count, w) != -1)
            {
              continue;
            }
            lct::ProbeBatchMaps maps;
            // blendAtPoint blends as for normalised weights (Linear: no (sum w - 1) I term).
            const int failed = lct::blendBatch(set, batch, w, count, true, maps);
            for (int j = 0; j < count; ++j)
            {
              double row[lct::kProbeBatchMaxProbes];
              for (int k = 0; k < n; ++k)
              {
                row[k] = w[k][j];
              }
              lct::PointMap expected;
              const lct::Status s = lct::blendAtPoint(set, row, nullptr, n, expected);
              if (failed == j)
              {
                EXPECT_NE(s, lct::Status::Ok); // the DQS rotations cancel at this point
                break;
              }
              if (s != lct::Status::Ok)
              {
                continue;
              }
              const lct::PointMap got = maps.at(j);
              const double scale = 1.0 + expected.linearMinusIdentity.norm() +
                expected.shift.norm() + expected.centre.norm();
              EXPECT_LE(difference(got, expected), 1e-13 * scale)
                << "mode " << static_cast<int>(mode) << " affine " << affine << " probes " << n
                << " turn " << maxTurn << " lane " << j;
              if (j < 2)
              {
                EXPECT_EQ(got.linearMinusIdentity, expected.linearMinusIdentity);
                EXPECT_EQ(got.shift, expected.shift);
              }
              ++compared;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(ProbeBlendBatch, LinearNormalisationMatchesThePointByPointOne)
{
  RandomTransforms r(7);
  lct::ProbeBatchWeights w;
  for (int j = 0; j < lct::kProbeBatch; ++j)
  {
    for (int k = 0; k < 4; ++k)
    {
      w[k][j] = j == 3 ? 0.0 : r.Uniform(0.0, 2.0);
    }
  }
  lct::ProbeBatchWeights batch = {};
  for (int j = 0; j < lct::kProbeBatch; ++j)
  {
    for (int k = 0; k < 4; ++k)
    {
      batch[k][j] = w[k][j];
    }
  }
  ASSERT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, 8, batch), -1);
  for (int j = 0; j < lct::kProbeBatch; ++j)
  {
    double row[4] = { w[0][j], w[1][j], w[2][j], w[3][j] };
    ASSERT_EQ(lct::normalizeWeights(lct::WeightNormalization::Linear, row, 4), lct::Status::Ok);
    for (int k = 0; k < 4; ++k)
    {
      EXPECT_EQ(batch[k][j], row[k]); // bit for bit: the same division
    }
  }
  // A negative sum, and an infinite one, are refused at their point.
  batch[0][5] = -100.0;
  EXPECT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, 8, batch), 5);
  batch[0][5] = 1.0;
  batch[1][2] = INFINITY;
  EXPECT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, 8, batch), 2);
}
