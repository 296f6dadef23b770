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
#include <limits>
#include <type_traits>
#include <vector>

namespace
{
using lct_test::RandomTransforms;
using lct_test::TransformClass;

/// Probes: random rigid or affine maps, turns of up to `maxTurn` radians, each probe's rotation
/// log taken on the branch of a reference of that turn (beyond pi too).
lct::ProbeBlendSet probes(
  RandomTransforms& r, int n, bool affine, lct::BlendMode mode, double maxTurn)
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
  const lct::ProbePreparation p = lct::prepareProbes(relative, centres,
    mode == lct::BlendMode::Polar ? references : std::vector<Eigen::Vector3d>{}, mode);
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
  // DualQuaternion sets whose probes all lie on one side (the lanes skip the hemisphere check)
  // and sets where the check flips some probe.
  int oneHemisphere = 0, twoHemispheres = 0;
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
          ASSERT_TRUE(lct::prepareProbeBatch(set, batch));
          if (mode == lct::BlendMode::DualQuaternion && n > 1)
          {
            ++(batch.oneHemisphere ? oneHemisphere : twoHemispheres);
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
  EXPECT_GE(oneHemisphere, 4);
  EXPECT_GE(twoHemispheres, 4);
}

TEST(ProbeBlendBatch, LinearNormalisationMatchesThePointByPointOne)
{
  RandomTransforms r(7);
  lct::ProbeBatchWeights w;
  for (int j = 0; j < lct::kProbeBatch; ++j)
  {
    for (int k = 0; k < 4; ++k)
    {
      w[k][j] = j == 3 ? 0.0 : r.Uniform(0.0, 2.0); // lane 3: all zero
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
  ASSERT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, lct::kProbeBatch, batch), -1);
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
  batch[0][2] = -100.0;
  EXPECT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, lct::kProbeBatch, batch), 2);
  batch[0][2] = 1.0;
  batch[1][1] = INFINITY;
  EXPECT_EQ(lct::normalizeBatch(lct::WeightNormalization::Linear, 4, lct::kProbeBatch, batch), 1);
}

namespace
{
/// What lct::deformPoints' point-by-point loop gives at point i: the map's image of p.
lct::Status referencePoint(const lct::ProbeBlendSet& set, lct::WeightNormalization normalization,
  const double* raw, int n, const Eigen::Vector3d& p, Eigen::Vector3d& q, Eigen::Matrix3d& d)
{
  std::vector<double> row(raw, raw + n);
  for (double w : row)
  {
    if (!std::isfinite(w))
    {
      return lct::Status::NonFinite;
    }
  }
  if (lct::normalizeWeights(normalization, row.data(), n) != lct::Status::Ok)
  {
    return lct::Status::InvalidArgument;
  }
  lct::PointMap map;
  lct::Status s = lct::blendAtPoint(set, row.data(), nullptr, n, map);
  if (normalization == lct::WeightNormalization::None && set.mode == lct::BlendMode::Linear &&
    s == lct::Status::Ok)
  {
    // blendAtPoint blends as for normalised weights; deformPoints adds (sum w - 1) I.
    double total = 0.0;
    for (double w : row)
    {
      total += w;
    }
    int nonZero = 0;
    bool single = false;
    for (double w : row)
    {
      nonZero += w != 0.0;
      single = single || w == 1.0;
    }
    if (total != 0.0 && !(nonZero == 1 && single))
    {
      map.linearMinusIdentity.diagonal().array() += total - 1.0;
    }
  }
  q = map.apply(p);
  d = map.linearMinusIdentity;
  return s;
}

/// Raw distance weights written out from their definition (vtkProbeDeformerLCT.h): r / d^p, or
/// ((r - d) / r)^p within r; a point on a centre takes that probe alone.
void distanceWeights(const lct::ProbeBlendSet& set, lct::WeightSource::Kind kind,
  const std::vector<double>& radii, double exponent, const Eigen::Vector3d& p, double* w)
{
  const int n = static_cast<int>(set.probes.size());
  bool onCentre = false;
  for (int k = 0; k < n; ++k)
  {
    const double d = (p - set.probes[k].centre).norm();
    onCentre = onCentre || d == 0.0;
    w[k] = kind == lct::WeightSource::Kind::InverseDistance
      ? radii[k] / std::pow(d, exponent)
      : (d <= radii[k] ? std::pow((radii[k] - d) / radii[k], exponent) : 0.0);
  }
  for (int k = 0; onCentre && kind == lct::WeightSource::Kind::InverseDistance && k < n; ++k)
  {
    w[k] = (p - set.probes[k].centre).norm() == 0.0 ? 1.0 : 0.0;
  }
}

template <typename Real>
void checkDeformation(lct::BlendMode mode, bool affine, int n,
  lct::WeightNormalization normalization, RandomTransforms& r,
  lct::WeightSource::Kind weightKind = lct::WeightSource::Kind::Slots, double exponent = 1.0)
{
  const lct::ProbeBlendSet set = probes(r, n, affine, mode, 9.0);
  constexpr int kPoints = 203; // not a multiple of the block
  std::vector<Real> in(3 * kPoints), normalsIn(3 * kPoints);
  std::vector<double> weights(static_cast<std::size_t>(kPoints * n));
  const double spread = normalization == lct::WeightNormalization::None ? 12.0 : 1.0;
  for (int i = 0; i < kPoints; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      in[3 * i + c] = static_cast<Real>(r.Uniform(-10.0, 10.0));
      normalsIn[3 * i + c] = static_cast<Real>(r.Uniform(-1.0, 1.0));
    }
    for (int k = 0; k < n; ++k)
    {
      // Zeros, one weight of 1, all zeros, and (unnormalised) stretches beyond the lanes' range.
      const int kind = i % 7;
      weights[i * n + k] = kind == 0 ? (k == i % n ? 1.0 : 0.0)
        : kind == 1                  ? 0.0
        : r.Uniform(0.0, 1.0) < 0.2  ? 0.0
                                     : spread * r.Uniform(0.05, 1.0);
    }
  }
  lct::WeightSource source;
  source.kind = weightKind;
  source.normalization = normalization;
  source.weights = weights.data();
  source.slots = n;
  std::vector<double> radii(static_cast<std::size_t>(n));
  if (weightKind != lct::WeightSource::Kind::Slots)
  {
    // Weights from the distances to the probes' centres; every 9th point on a centre.
    source.weights = nullptr;
    source.slots = 0;
    source.radii = radii.data();
    source.exponent = exponent;
    for (int k = 0; k < n; ++k)
    {
      radii[k] = r.Uniform(4.0, 14.0);
    }
    for (int i = 0; i < kPoints; ++i)
    {
      if (i % 9 == 4)
      {
        const Eigen::Vector3d& c = set.probes[i % n].centre;
        for (int k = 0; k < 3; ++k)
        {
          in[3 * i + k] = static_cast<Real>(c[k]);
        }
      }
      const Eigen::Vector3d p(in[3 * i], in[3 * i + 1], in[3 * i + 2]);
      distanceWeights(set, weightKind, radii, exponent, p, &weights[i * n]);
    }
  }
  std::vector<Real> out(in.size()), normalsOut(in.size());
  lct::CarriedVectors normals;
  normals.in = normalsIn.data();
  normals.out = normalsOut.data();
  normals.isDouble = std::is_same<Real, double>::value;
  normals.isNormal = true;
  const lct::DeformFailure whole =
    lct::deformPoints(set, source, in.data(), out.data(), &normals, 1, 0, kPoints);
  // The reference's first failure, if any (DualQuaternion blends can cancel).
  std::int64_t firstFailure = -1;
  const double tolerance = std::is_same<Real, double>::value ? 1e-12 : 4e-7;
  for (int i = 0; i < kPoints && firstFailure < 0; ++i)
  {
    const Eigen::Vector3d p(in[3 * i], in[3 * i + 1], in[3 * i + 2]);
    Eigen::Vector3d q;
    Eigen::Matrix3d d;
    // A map that fails, or a point that does not fit in Real (a float output can overflow
    // where the double did not), stops deformPoints there.
    if (referencePoint(set, normalization, &weights[i * n], n, p, q, d) != lct::Status::Ok ||
      !(q.cwiseAbs().maxCoeff() <= static_cast<double>(std::numeric_limits<Real>::max())))
    {
      firstFailure = i;
      break;
    }
    const Eigen::Vector3d got(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
    EXPECT_LE((got - q).norm(), tolerance * (1.0 + q.norm()))
      << "mode " << static_cast<int>(mode) << " affine " << affine << " probes " << n << " point "
      << i;
  }
  EXPECT_EQ(whole.point, firstFailure);
  // Four lanes, as a CPU without AVX-512 runs them, give the same points to rounding.
  lct::ProbeBatchSet batch;
  ASSERT_TRUE(lct::prepareProbeBatch(set, batch));
  std::vector<Real> narrow(in.size()), narrowNormals(in.size());
  lct::CarriedVectors narrowCarried = normals;
  narrowCarried.out = narrowNormals.data();
  const lct::DeformFailure four = lct::deformBatch(set, batch, source, in.data(), narrow.data(),
    std::is_same<Real, double>::value, &narrowCarried, 1, 0, kPoints, 4);
  EXPECT_EQ(four.point, whole.point);
  EXPECT_EQ(four.status, whole.status);
  const std::int64_t compared = whole.ok() ? kPoints : whole.point;
  for (std::int64_t i = 0; i < 3 * compared; ++i)
  {
    EXPECT_LE(std::abs(static_cast<double>(narrow[i]) - static_cast<double>(out[i])),
      tolerance * (1.0 + std::abs(static_cast<double>(out[i]))))
      << "coordinate " << i;
  }
  if (!whole.ok())
  {
    return;
  }
  // Any split of the range (threads) gives the same bits.
  for (const int split : { 1, 2, 3, 5, 101, 202 })
  {
    std::vector<Real> parts(in.size()), partNormals(in.size());
    lct::CarriedVectors c = normals;
    c.out = partNormals.data();
    ASSERT_TRUE(lct::deformPoints(set, source, in.data(), parts.data(), &c, 1, 0, split).ok());
    ASSERT_TRUE(
      lct::deformPoints(set, source, in.data(), parts.data(), &c, 1, split, kPoints).ok());
    EXPECT_EQ(parts, out) << "split at " << split;
    EXPECT_EQ(partNormals, normalsOut) << "split at " << split;
  }
}
} // namespace

TEST(ProbeBlendBatch, DeformsAsThePointByPointBlendAndAnySplitGivesTheSameBits)
{
  RandomTransforms r(99);
  for (const lct::BlendMode mode :
    { lct::BlendMode::Polar, lct::BlendMode::Linear, lct::BlendMode::DualQuaternion })
  {
    for (const bool affine : { false, true })
    {
      for (const int n : { 1, 2, 3, 4, 5, 8 })
      {
        for (const auto normalization : { lct::WeightNormalization::Linear,
               lct::WeightNormalization::None, lct::WeightNormalization::Softmax })
        {
          checkDeformation<double>(mode, affine, n, normalization, r);
          checkDeformation<float>(mode, affine, n, normalization, r);
          for (const double exponent : { 1.0, 2.0, 1.5 })
          {
            for (const auto kind :
              { lct::WeightSource::Kind::InverseDistance, lct::WeightSource::Kind::Cutoff })
            {
              checkDeformation<double>(mode, affine, n, normalization, r, kind, exponent);
            }
          }
        }
      }
    }
  }
}

TEST(ProbeBlendBatch, ReportsTheFirstFailingPointWithItsCause)
{
  RandomTransforms r(5);
  const lct::ProbeBlendSet set = probes(r, 2, false, lct::BlendMode::Polar, 1.0);
  constexpr int kPoints = 40;
  std::vector<double> in(3 * kPoints, 1.0), out(3 * kPoints), weights(2 * kPoints, 0.5);
  lct::WeightSource source;
  source.kind = lct::WeightSource::Kind::Slots;
  source.weights = weights.data();
  source.slots = 2;
  const auto run = [&]() {
    return lct::deformPoints(set, source, in.data(), out.data(), nullptr, 0, 0, kPoints);
  };
  EXPECT_TRUE(run().ok());
  weights[2 * 23] = NAN;  // point 23
  weights[2 * 22] = -5.0; // point 22: a negative sum, earlier
  lct::DeformFailure f = run();
  EXPECT_EQ(f.point, 22);
  EXPECT_EQ(f.status, lct::Status::InvalidArgument);
  weights[2 * 22] = 0.5;
  f = run();
  EXPECT_EQ(f.point, 23);
  EXPECT_EQ(f.status, lct::Status::NonFinite);
  weights[2 * 23] = 0.5;
  // Point 30 overflows: unnormalised LBS scales it by the weights' sum, 3.5.
  const lct::ProbeBlendSet linear = probes(r, 2, false, lct::BlendMode::Linear, 1.0);
  source.normalization = lct::WeightNormalization::None;
  in[3 * 30] = 1e308;
  weights[2 * 30] = 3.0;
  f = lct::deformPoints(linear, source, in.data(), out.data(), nullptr, 0, 0, kPoints);
  EXPECT_EQ(f.point, 30);
  EXPECT_EQ(f.status, lct::Status::OutOfRange);
  // In float, a point that fits in double but not in float overflows too.
  std::vector<float> inFloat(3 * kPoints, 1.0f), outFloat(3 * kPoints);
  inFloat[3 * 30] = 3e38f;
  f = lct::deformPoints(linear, source, inFloat.data(), outFloat.data(), nullptr, 0, 0, kPoints);
  EXPECT_EQ(f.point, 30);
  EXPECT_EQ(f.status, lct::Status::OutOfRange);
  // DualQuaternion with stretch: unnormalised weights whose sum cancels (point 9) have no blend of
  // the stretches, as lct::blendAtPoint says; in 8 lanes and in 4.
  in[3 * 30] = 1.0;
  weights[2 * 30] = 0.5;
  const lct::ProbeBlendSet dq = probes(r, 2, true, lct::BlendMode::DualQuaternion, 1.0);
  ASSERT_FALSE(dq.allRigid);
  weights[2 * 9] = 2.0;
  weights[2 * 9 + 1] = -2.0;
  lct::PointMap map;
  EXPECT_EQ(lct::blendAtPoint(dq, &weights[2 * 9], nullptr, 2, map), lct::Status::NumericalFailure);
  lct::ProbeBatchSet batch;
  ASSERT_TRUE(lct::prepareProbeBatch(dq, batch));
  for (const int lanes : { 0, 4 })
  {
    f = lct::deformBatch(
      dq, batch, source, in.data(), out.data(), true, nullptr, 0, 0, kPoints, lanes);
    EXPECT_EQ(f.point, 9) << lanes;
    EXPECT_EQ(f.status, lct::Status::NumericalFailure) << lanes;
  }
}
