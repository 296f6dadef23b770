// vtkShapeBlenderLCT and lct/ShapeBlend (Kaji & Ochiai §5.3): exactness at the rest mesh and
// the targets, twists beyond 180 degrees without collapse, extrapolation, rigid targets, labelling
// independence, the caching of the factorisation and the logs, and every bad input.
#include "ShapeMeshes.h"
#include "VtkTestHelpers.h"

#include "lct/ShapeBlend.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkShapeBlenderLCT.h"
#include "vtkSmartPointer.h"

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

namespace
{
using lct_test::Mesh;

constexpr double kPi = 3.14159265358979323846;
constexpr int kRings = 41;
constexpr int kAround = 24;
constexpr double kRadius = 1.0;
constexpr double kLength = 10.0;

Mesh bar()
{
  return lct_test::tube(kRings, kAround, kRadius, kLength);
}

double maxDistance(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b)
{
  EXPECT_EQ(a.size(), b.size());
  double d = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
  {
    d = std::max(d, (a[i] - b[i]).norm());
  }
  return d;
}

Eigen::Vector3d centroid(const std::vector<Eigen::Vector3d>& p)
{
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const auto& x : p)
  {
    c += x;
  }
  return c / static_cast<double>(p.size());
}

/// The blend through the VTK class; empty (with a test failure) when it fails.
std::vector<Eigen::Vector3d> blendWithFilter(const Mesh& rest,
  const std::vector<std::vector<Eigen::Vector3d>>& targets, const std::vector<double>& weights)
{
  vtkNew<vtkShapeBlenderLCT> blender;
  blender->SetInputData(lct_test::toPolyData(rest.points, rest.triangles));
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    const int index = blender->AddTarget(lct_test::toPolyData(targets[i], rest.triangles));
    EXPECT_EQ(index, static_cast<int>(i));
    EXPECT_EQ(blender->SetWeight(index, weights[i]), 1);
  }
  blender->Update();
  EXPECT_EQ(blender->GetOutput()->GetNumberOfPoints(), static_cast<vtkIdType>(rest.points.size()));
  return lct_test::pointsOf(blender->GetOutput());
}

/// Per ring of the bar: its mean radius about its own centre, and its turn (radians, in
/// (-pi, pi]) about z relative to the rest ring.
struct RingMeasure
{
  std::vector<double> minRadius, maxRadius, turn;
};

RingMeasure measureRings(
  const std::vector<Eigen::Vector3d>& rest, const std::vector<Eigen::Vector3d>& out)
{
  RingMeasure m;
  for (int i = 0; i < kRings; ++i)
  {
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    for (int j = 0; j < kAround; ++j)
    {
      c += out[i * kAround + j];
    }
    c /= kAround;
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0, cross = 0.0, dot = 0.0;
    for (int j = 0; j < kAround; ++j)
    {
      const Eigen::Vector3d q = out[i * kAround + j] - c;
      const Eigen::Vector3d p = rest[i * kAround + j];
      const double r = std::hypot(q.x(), q.y());
      lo = std::min(lo, r);
      hi = std::max(hi, r);
      cross += p.x() * q.y() - p.y() * q.x();
      dot += p.x() * q.x() + p.y() * q.y();
    }
    m.minRadius.push_back(lo);
    m.maxRadius.push_back(hi);
    m.turn.push_back(std::atan2(cross, dot));
  }
  return m;
}

/// The difference of two angles, wrapped into (-pi, pi].
double angleDifference(double a, double b)
{
  return std::remainder(a - b, 2.0 * kPi);
}

/// Checks the output is a bar twisted by `angle` at the top (ring by ring, to `turnTolerance`
/// rad) with its radius kept (to `radiusTolerance` relative); returns the worst relative radius
/// error.
double expectTwistedBar(const std::vector<Eigen::Vector3d>& rest,
  const std::vector<Eigen::Vector3d>& out, double angle, double turnTolerance,
  double radiusTolerance)
{
  const RingMeasure m = measureRings(rest, out);
  double worst = 0.0, worstTurn = 0.0;
  for (int i = 0; i < kRings; ++i)
  {
    const double expected = angle * i / (kRings - 1);
    EXPECT_NEAR(angleDifference(m.turn[i], expected), 0.0, turnTolerance) << "ring " << i;
    worstTurn = std::max(worstTurn, std::abs(angleDifference(m.turn[i], expected)));
    worst =
      std::max({ worst, std::abs(m.minRadius[i] - kRadius), std::abs(m.maxRadius[i] - kRadius) });
  }
  EXPECT_LT(worst / kRadius, radiusTolerance);
  std::cout << "  twisted by " << angle * 180 / kPi << " deg: worst turn error " << worstTurn
            << " rad, worst relative radius error " << worst / kRadius << "\n";
  return worst / kRadius;
}

/// A non-rigid target: stretched along x, sheared, bulging along the bar.
std::vector<Eigen::Vector3d> bulged(const std::vector<Eigen::Vector3d>& points)
{
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : points)
  {
    const double s = 1.0 + 0.3 * std::sin(kPi * p.z() / kLength);
    out.emplace_back(1.4 * s * p.x() + 0.2 * p.z(), s * p.y(), 0.9 * p.z());
  }
  return out;
}
} // namespace

TEST(ShapeBlendCore, GhostVertexIsAtCentroidPlusNormalOverRootNorm)
{
  const Eigen::Vector3d a(0.1, 0.2, 0.3), b(2.0, 0.5, -0.2), c(0.4, 1.7, 0.9);
  const Eigen::Vector3d g = lct::ghostVertex(a, b, c);
  const Eigen::Vector3d offset = g - (a + b + c) / 3.0;
  const Eigen::Vector3d n = (b - a).cross(c - a);
  EXPECT_NEAR(offset.norm(), std::sqrt(n.norm()), 1e-14);
  EXPECT_NEAR(offset.normalized().dot(n.normalized()), 1.0, 1e-14);
  EXPECT_FALSE(lct::isDegenerateTriangle(a, b, c));
  EXPECT_TRUE(lct::isDegenerateTriangle(a, b, a));
  EXPECT_TRUE(lct::isDegenerateTriangle(a, b, 0.5 * (a + b)));
  EXPECT_TRUE(lct::isDegenerateTriangle(a, a, a));
  EXPECT_TRUE(lct::isDegenerateTriangle(
    a, b, Eigen::Vector3d(std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0)));
}

TEST(ShapeBlendCore, ExactAtRestAndAtEachTarget)
{
  const Mesh rest = bar();
  const std::vector<std::vector<Eigen::Vector3d>> targets = { lct_test::twisted(
                                                                rest.points, 0.5 * kPi, kLength),
    lct_test::twisted(rest.points, 1.5 * kPi, kLength), bulged(rest.points) };
  lct::ShapeBlender blender;
  ASSERT_TRUE(blender.setRest(rest.points, rest.triangles).ok());
  ASSERT_TRUE(blender.setTargets(targets).ok());
  EXPECT_EQ(blender.numberOfPieces(), 1);
  EXPECT_EQ(blender.numberOfUnknowns(), static_cast<std::int64_t>(rest.points.size()) - 1);
  std::vector<Eigen::Vector3d> out;
  ASSERT_TRUE(blender.blend({ 0.0, 0.0, 0.0 }, out).ok());
  const double restError = maxDistance(out, rest.points);
  EXPECT_LT(restError, 1e-9);
  for (int k = 0; k < 3; ++k)
  {
    std::vector<double> w(3, 0.0);
    w[k] = 1.0;
    ASSERT_TRUE(blender.blend(w, out).ok());
    const double targetError = maxDistance(out, targets[k]);
    EXPECT_LT(targetError, 1e-9) << "target " << k;
    std::cout << "target " << k << ": max |blend(e_k) - target| = " << targetError << "\n";
  }
  std::cout << "max |blend(0) - rest| = " << restError << "\n";
  // The same through the VTK class.
  EXPECT_LT(maxDistance(blendWithFilter(rest, targets, { 0.0, 1.0, 0.0 }), targets[1]), 1e-9);
  EXPECT_LT(maxDistance(blendWithFilter(rest, targets, { 0.0, 0.0, 0.0 }), rest.points), 1e-9);
}

TEST(ShapeBlendCore, RotationBranchesFollowTheFaceGraph)
{
  // The top cap of a bar twisted by 270 degrees turned by 270 as a whole: its principal log is
  // -90 degrees; the walk from the bottom carries the branch up to +270.
  const Mesh rest = bar();
  lct::ShapeBlender blender;
  ASSERT_TRUE(blender.setRest(rest.points, rest.triangles).ok());
  ASSERT_TRUE(blender.setTargets({ lct_test::twisted(rest.points, 1.5 * kPi, kLength) }).ok());
  const std::int64_t topCapFace = blender.numberOfFaces() - 1;
  const Eigen::Vector3d w = lct::rotationPart(blender.faceLog(0, topCapFace));
  EXPECT_NEAR(w.z(), 1.5 * kPi, 1e-9);
  EXPECT_NEAR(w.head<2>().norm(), 0.0, 1e-9);
  // And every face's rotation about z grows with its height, without a 2 pi jump.
  for (std::int64_t j = 0; j < blender.numberOfFaces(); ++j)
  {
    const lct::Triangle& t = rest.triangles[j];
    const double z = (rest.points[t[0]].z() + rest.points[t[1]].z() + rest.points[t[2]].z()) / 3;
    EXPECT_NEAR(lct::rotationPart(blender.faceLog(0, j)).z(), 1.5 * kPi * z / kLength, 0.4)
      << "face " << j;
  }
}

TEST(ShapeBlender, TwistByHalfOf180KeepsTheRadiusWhereLinearBlendCollapses)
{
  const Mesh rest = bar();
  const auto target = lct_test::twisted(rest.points, kPi, kLength);
  const auto out = blendWithFilter(rest, { target }, { 0.5 });
  const double radiusError = expectTwistedBar(rest.points, out, 0.5 * kPi, 0.02, 0.1);
  // The linear blend of the points: the top ring collapses to |cos 90°| of its radius.
  std::vector<Eigen::Vector3d> linear;
  for (std::size_t i = 0; i < rest.points.size(); ++i)
  {
    linear.push_back(0.5 * (rest.points[i] + target[i]));
  }
  const RingMeasure ours = measureRings(rest.points, out);
  const RingMeasure lbs = measureRings(rest.points, linear);
  EXPECT_GT(ours.minRadius.back(), 0.9 * kRadius);
  EXPECT_LT(lbs.maxRadius.back(), 1e-12);
  std::cout << "180 deg target at w = 0.5: top-ring radius " << ours.minRadius.back() << " .. "
            << ours.maxRadius.back() << " (linear point blend: " << lbs.maxRadius.back()
            << "), worst radius error over the bar " << radiusError << ", top turn "
            << ours.turn.back() * 180 / kPi << " deg\n";
}

TEST(ShapeBlender, TwistsOf90And270BlendSmoothly)
{
  const Mesh rest = bar();
  const auto t90 = lct_test::twisted(rest.points, 0.5 * kPi, kLength);
  const auto t270 = lct_test::twisted(rest.points, 1.5 * kPi, kLength);
  for (const double w : { 1.0 / 3.0, 0.5, 2.0 / 3.0 })
  {
    SCOPED_TRACE(w);
    expectTwistedBar(rest.points, blendWithFilter(rest, { t270 }, { w }), 1.5 * kPi * w, 0.1, 0.2);
  }
  // Half of each: 45 + 135 = 180 degrees at the top.
  const double err = expectTwistedBar(
    rest.points, blendWithFilter(rest, { t90, t270 }, { 0.5, 0.5 }), kPi, 0.1, 0.2);
  std::cout << "90 and 270 deg targets at (0.5, 0.5): worst radius error " << err << "\n";
}

TEST(ShapeBlender, ExtrapolationIsWellDefined)
{
  const Mesh rest = bar();
  const auto t180 = lct_test::twisted(rest.points, kPi, kLength);
  for (const double w : { 1.5, -0.5 })
  {
    SCOPED_TRACE(w);
    const auto out = blendWithFilter(rest, { t180 }, { w });
    for (const auto& p : out)
    {
      ASSERT_TRUE(p.allFinite());
    }
    const double err = expectTwistedBar(rest.points, out, kPi * w, 0.15, 0.1);
    std::cout << "180 deg target at w = " << w << ": worst radius error " << err << "\n";
  }
}

TEST(ShapeBlender, RigidTargetBlendsToAFractionOfItsRotation)
{
  const Mesh rest = bar();
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 2.0, -0.5).normalized();
  const double angle = 2.0 * kPi / 3.0;
  const Eigen::Vector3d shift(3.0, -1.0, 2.5);
  std::vector<Eigen::Vector3d> target;
  for (const auto& p : rest.points)
  {
    target.push_back(Eigen::AngleAxisd(angle, axis) * p + shift);
  }
  const Eigen::Vector3d c0 = centroid(rest.points), c1 = centroid(target);
  for (const double w : { 0.25, 0.5, 0.8, 1.5 })
  {
    SCOPED_TRACE(w);
    const auto out = blendWithFilter(rest, { target }, { w });
    const Eigen::Vector3d c = centroid(out);
    EXPECT_LT((c - ((1.0 - w) * c0 + w * c1)).norm(), 1e-9);
    const Eigen::Matrix3d r = Eigen::AngleAxisd(w * angle, axis).toRotationMatrix();
    double err = 0.0;
    for (std::size_t i = 0; i < out.size(); ++i)
    {
      err = std::max(err, ((out[i] - c) - r * (rest.points[i] - c0)).norm());
    }
    EXPECT_LT(err, 1e-9);
  }
}

TEST(ShapeBlender, ResultDoesNotDependOnLabelling)
{
  const Mesh rest = bar();
  const std::vector<std::vector<Eigen::Vector3d>> targets = {
    lct_test::twisted(rest.points, 1.5 * kPi, kLength), bulged(rest.points)
  };
  const std::vector<double> w = { 0.6, 0.3 };
  const auto reference = blendWithFilter(rest, targets, w);

  // Points and faces shuffled, each triangle's points rotated cyclically.
  std::mt19937 rng(11);
  const std::size_t n = rest.points.size();
  std::vector<std::int64_t> newId(n);
  std::iota(newId.begin(), newId.end(), 0);
  std::shuffle(newId.begin(), newId.end(), rng);
  Mesh shuffled;
  shuffled.points.resize(n);
  std::vector<std::vector<Eigen::Vector3d>> shuffledTargets(
    targets.size(), std::vector<Eigen::Vector3d>(n));
  for (std::size_t i = 0; i < n; ++i)
  {
    shuffled.points[newId[i]] = rest.points[i];
    for (std::size_t k = 0; k < targets.size(); ++k)
    {
      shuffledTargets[k][newId[i]] = targets[k][i];
    }
  }
  for (const lct::Triangle& t : rest.triangles)
  {
    const int r = static_cast<int>(rng() % 3);
    shuffled.triangles.push_back({ newId[t[r]], newId[t[(r + 1) % 3]], newId[t[(r + 2) % 3]] });
  }
  std::shuffle(shuffled.triangles.begin(), shuffled.triangles.end(), rng);
  const auto out = blendWithFilter(shuffled, shuffledTargets, w);
  double err = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    err = std::max(err, (out[newId[i]] - reference[i]).norm());
  }
  EXPECT_LT(err, 1e-9);
}

TEST(ShapeBlender, DisconnectedPiecesArePinnedEachByItsCentroid)
{
  // Two bars side by side and one point no triangle uses.
  const Mesh one = bar();
  Mesh two = one;
  const std::int64_t offset = static_cast<std::int64_t>(one.points.size());
  for (const auto& p : one.points)
  {
    two.points.push_back(p + Eigen::Vector3d(4.0, 0.0, 0.0));
  }
  for (const auto& t : one.triangles)
  {
    two.triangles.push_back({ t[0] + offset, t[1] + offset, t[2] + offset });
  }
  two.points.emplace_back(-3.0, 1.0, 2.0);
  // The target: the first bar twisted about its axis, the second translated and turned about
  // its own axis, the lone point moved.
  std::vector<Eigen::Vector3d> target = lct_test::twisted(two.points, kPi, kLength);
  for (std::size_t i = offset; i < two.points.size() - 1; ++i)
  {
    const Eigen::Vector3d local = two.points[i] - Eigen::Vector3d(4.0, 0.0, 0.0);
    target[i] = Eigen::AngleAxisd(0.5 * kPi, Eigen::Vector3d::UnitZ()) * local +
      Eigen::Vector3d(5.0, 2.0, 1.0);
  }
  target.back() = Eigen::Vector3d(-1.0, 3.0, 0.0);

  lct::ShapeBlender blender;
  ASSERT_TRUE(blender.setRest(two.points, two.triangles).ok());
  EXPECT_EQ(blender.numberOfPieces(), 3);
  ASSERT_TRUE(blender.setTargets({ target }).ok());
  std::vector<Eigen::Vector3d> out;
  ASSERT_TRUE(blender.blend({ 0.0 }, out).ok());
  EXPECT_LT(maxDistance(out, two.points), 1e-9);
  ASSERT_TRUE(blender.blend({ 1.0 }, out).ok());
  EXPECT_LT(maxDistance(out, target), 1e-9);
  ASSERT_TRUE(blender.blend({ 0.5 }, out).ok());
  const auto pieceCentroid = [&](const std::vector<Eigen::Vector3d>& p, std::size_t b,
                               std::size_t e) {
    return centroid(std::vector<Eigen::Vector3d>(p.begin() + b, p.begin() + e));
  };
  for (const auto& [b, e] : { std::make_pair<std::size_t, std::size_t>(0, offset),
         std::make_pair<std::size_t, std::size_t>(offset, two.points.size() - 1),
         std::make_pair<std::size_t, std::size_t>(two.points.size() - 1, two.points.size()) })
  {
    const Eigen::Vector3d wanted =
      0.5 * (pieceCentroid(two.points, b, e) + pieceCentroid(target, b, e));
    EXPECT_LT((pieceCentroid(out, b, e) - wanted).norm(), 1e-9) << "piece starting at " << b;
  }
  // The second bar turned rigidly by 45 degrees about its axis.
  const Eigen::Vector3d c0 = pieceCentroid(two.points, offset, two.points.size() - 1);
  const Eigen::Vector3d c = pieceCentroid(out, offset, two.points.size() - 1);
  const Eigen::Matrix3d r =
    Eigen::AngleAxisd(0.25 * kPi, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  for (std::size_t i = offset; i < two.points.size() - 1; ++i)
  {
    EXPECT_LT(((out[i] - c) - r * (two.points[i] - c0)).norm(), 1e-9) << "point " << i;
  }
}

TEST(ShapeBlender, WeightsAloneReuseTheFactorisationAndTheLogs)
{
  const Mesh rest = bar();
  auto restPd = lct_test::toPolyData(rest.points, rest.triangles);
  auto target = lct_test::toPolyData(lct_test::twisted(rest.points, kPi, kLength), rest.triangles);
  vtkNew<vtkShapeBlenderLCT> blender;
  blender->SetInputData(restPd);
  ASSERT_EQ(blender->AddTarget(target), 0);
  EXPECT_EQ(blender->GetNumberOfTargets(), 1);
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 1);
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 1);
  std::vector<std::vector<Eigen::Vector3d>> outputs;
  for (const double w : { 0.25, 0.5, 1.0 })
  {
    blender->SetWeight(0, w);
    EXPECT_EQ(blender->GetWeight(0), w);
    blender->Update();
    outputs.push_back(lct_test::pointsOf(blender->GetOutput()));
  }
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 1);
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 1);
  EXPECT_GT(maxDistance(outputs[0], outputs[1]), 0.1); // the weights did change the output
  EXPECT_LT(maxDistance(outputs[2], lct_test::pointsOf(target)), 1e-9);

  // Point data of the rest mesh does not touch the geometry: no recomputation.
  vtkNew<vtkDoubleArray> scalars;
  scalars->SetName("s");
  scalars->SetNumberOfTuples(restPd->GetNumberOfPoints());
  scalars->Fill(1.0);
  restPd->GetPointData()->AddArray(scalars);
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 1);
  EXPECT_NE(blender->GetOutput()->GetPointData()->GetArray("s"), nullptr);

  // A moved target: new logs, same factorisation (the target's MTime is the filter's).
  target->GetPoints()->SetPoint(0, 1.0, 0.05, 0.0);
  target->GetPoints()->Modified();
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 1);
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 2);
  EXPECT_NEAR(blender->GetOutput()->GetPoint(0)[1], 0.05, 1e-9);

  // A moved rest mesh: both.
  restPd->GetPoints()->SetPoint(0, 1.0, 0.0, 0.02);
  restPd->GetPoints()->Modified();
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 2);
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 3);

  // Points moved without touching vtkPoints' time (SetPoint does not), then the mesh's
  // Modified(), as VTK users do: the cached logs and factorisation were reused (the output was
  // 1.6 off the target at w = 1, execution OK).
  blender->SetWeight(0, 1.0);
  target->GetPoints()->SetPoint(5, 0.3, 0.9, 1.4);
  target->Modified();
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 4);
  EXPECT_LT(
    maxDistance(lct_test::pointsOf(blender->GetOutput()), lct_test::pointsOf(target)), 1e-9);
  restPd->GetPoints()->SetPoint(1, 1.0, 0.0, 0.03);
  restPd->Modified();
  blender->SetWeight(0, 0.0);
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 3);
  EXPECT_LT(
    maxDistance(lct_test::pointsOf(blender->GetOutput()), lct_test::pointsOf(restPd)), 1e-9);

  // Another target: logs only.
  blender->AddTarget(target);
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfFactorizations(), 3);
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 6);
  blender->RemoveAllTargets();
  EXPECT_EQ(blender->GetNumberOfTargets(), 0);
  blender->Update();
  EXPECT_EQ(blender->GetNumberOfLogComputations(), 7);
  // No targets: the rest mesh.
  EXPECT_LT(
    maxDistance(lct_test::pointsOf(blender->GetOutput()), lct_test::pointsOf(restPd)), 1e-9);
}

TEST(ShapeBlender, OutputKeepsTopologyAndDataButDropsNormals)
{
  const Mesh rest = bar();
  auto restPd = lct_test::toPolyData(rest.points, rest.triangles);
  vtkNew<vtkFloatArray> normals;
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(restPd->GetNumberOfPoints());
  normals->Fill(0.0);
  restPd->GetPointData()->SetNormals(normals);
  vtkNew<vtkDoubleArray> cellScalars;
  cellScalars->SetName("c");
  cellScalars->SetNumberOfTuples(restPd->GetNumberOfCells());
  cellScalars->Fill(2.0);
  restPd->GetCellData()->AddArray(cellScalars);
  vtkNew<vtkShapeBlenderLCT> blender;
  blender->SetInputData(restPd);
  blender->SetWeight(0, 1.0); // no target 0: an error, nothing stored
  blender->AddTarget(
    lct_test::toPolyData(lct_test::twisted(rest.points, kPi, kLength), rest.triangles));
  blender->SetWeight(0, 0.5);
  blender->Update();
  vtkPolyData* out = blender->GetOutput();
  EXPECT_EQ(out->GetNumberOfPolys(), restPd->GetNumberOfPolys());
  EXPECT_EQ(out->GetPointData()->GetNormals(), nullptr);
  EXPECT_NE(out->GetCellData()->GetArray("c"), nullptr);
  EXPECT_EQ(out->GetPoints()->GetDataType(), VTK_DOUBLE);
}

// ---- bad input: a clear message, RequestData returns 0, the output keeps its last result ----

namespace
{
struct BadInputFixture
{
  Mesh rest = bar();
  vtkSmartPointer<vtkPolyData> restPd = lct_test::toPolyData(rest.points, rest.triangles);
  vtkSmartPointer<vtkPolyData> target =
    lct_test::toPolyData(lct_test::twisted(rest.points, kPi, kLength), rest.triangles);
  vtkNew<vtkShapeBlenderLCT> blender;
  vtkNew<lct_test::ErrorCounter> errors;
  vtkNew<lct_test::ErrorCounter> executiveErrors; // "returned failure": counted apart
  std::vector<Eigen::Vector3d> good;

  BadInputFixture()
  {
    blender->AddObserver(vtkCommand::ErrorEvent, errors);
    blender->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
    blender->SetInputData(restPd);
    blender->AddTarget(target);
    blender->SetWeight(0, 0.5);
    blender->Update();
    good = lct_test::pointsOf(blender->GetOutput());
    EXPECT_EQ(errors->Count, 0);
  }

  /// Runs the filter, expecting failure with a message containing `needle` and the last good
  /// output; then restores nothing (each case builds its own fixture).
  void expectFailure(const std::string& needle)
  {
    const int before = errors->Count;
    blender->Modified();
    EXPECT_EQ(blender->GetExecutive()->Update(), 0);
    EXPECT_GT(errors->Count, before);
    EXPECT_NE(errors->Last.find(needle), std::string::npos) << errors->Last;
    EXPECT_EQ(maxDistance(lct_test::pointsOf(blender->GetOutput()), good), 0.0);
  }
};
} // namespace

TEST(ShapeBlendBadInput, NoInput)
{
  vtkNew<vtkShapeBlenderLCT> blender;
  vtkNew<lct_test::ErrorCounter> errors;
  blender->AddObserver(vtkCommand::ErrorEvent, errors);
  blender->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, errors);
  EXPECT_EQ(blender->GetExecutive()->Update(), 0);
  EXPECT_GT(errors->Count, 0);
  // Through the pipeline the executive refuses a missing connection before RequestData; a null
  // input object reaches RequestData.
  errors->Count = 0;
  blender->SetInputData(nullptr);
  blender->Update();
  EXPECT_GT(errors->Count, 0);
  EXPECT_EQ(blender->AddTarget(nullptr), -1);
  EXPECT_EQ(blender->GetNumberOfTargets(), 0);
}

TEST(ShapeBlendBadInput, TargetWithAnotherPointCount)
{
  BadInputFixture f;
  Mesh more = f.rest;
  more.points.emplace_back(9.0, 9.0, 9.0);
  f.blender->AddTarget(lct_test::toPolyData(more.points, more.triangles));
  f.expectFailure("target 1 has " + std::to_string(more.points.size()) +
    " points where the rest mesh has " + std::to_string(f.rest.points.size()));
}

TEST(ShapeBlendBadInput, TargetWithAnotherTriangulation)
{
  {
    BadInputFixture f;
    Mesh fewer = f.rest;
    fewer.triangles.pop_back();
    f.blender->AddTarget(lct_test::toPolyData(fewer.points, fewer.triangles));
    f.expectFailure("target 1 has " + std::to_string(fewer.triangles.size()) +
      " triangles where the rest mesh has " + std::to_string(f.rest.triangles.size()));
  }
  {
    BadInputFixture f;
    Mesh flipped = f.rest;
    std::swap(flipped.triangles[7][0], flipped.triangles[7][1]);
    f.blender->AddTarget(lct_test::toPolyData(flipped.points, flipped.triangles));
    f.expectFailure("target 1: triangle 7 (points");
  }
  {
    BadInputFixture f;
    vtkNew<vtkCellArray> quads;
    const vtkIdType quad[4] = { 0, 1, kAround + 1, kAround };
    quads->InsertNextCell(4, quad);
    auto pd = lct_test::toPolyData(f.rest.points, {});
    pd->SetPolys(quads);
    f.blender->AddTarget(pd);
    f.expectFailure("target 1: polygon 0 has 4 points: only triangles");
  }
}

TEST(ShapeBlendBadInput, RestMeshWithQuadsStripsOrNoTriangles)
{
  {
    BadInputFixture f;
    f.restPd->GetPolys()->InsertNextCell(4);
    for (vtkIdType id : { 0, 1, 2, 3 })
    {
      f.restPd->GetPolys()->InsertCellPoint(id);
    }
    f.restPd->GetPolys()->Modified();
    f.expectFailure(
      "rest mesh: polygon " + std::to_string(f.rest.triangles.size()) + " has 4 points");
  }
  {
    BadInputFixture f;
    vtkNew<vtkCellArray> strips;
    const vtkIdType strip[4] = { 0, 1, 2, 3 };
    strips->InsertNextCell(4, strip);
    f.restPd->SetStrips(strips);
    f.expectFailure("rest mesh: it has 1 triangle strips");
  }
  {
    BadInputFixture f;
    f.restPd->SetPolys(vtkNew<vtkCellArray>());
    f.expectFailure("rest mesh: it has no triangles");
  }
}

TEST(ShapeBlendBadInput, NonFinitePoints)
{
  for (const double bad :
    { std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity() })
  {
    {
      BadInputFixture f;
      f.restPd->GetPoints()->SetPoint(5, 0.0, bad, 0.0);
      f.restPd->GetPoints()->Modified();
      f.expectFailure("rest mesh: point 5 is");
    }
    {
      BadInputFixture f;
      f.target->GetPoints()->SetPoint(12, bad, 0.0, 0.0);
      f.target->GetPoints()->Modified();
      f.expectFailure("target 0: point 12 is");
    }
  }
}

TEST(ShapeBlendBadInput, DegenerateTriangles)
{
  {
    // Rest: point 1 moved onto point 0 collapses the triangles that use both.
    BadInputFixture f;
    f.restPd->GetPoints()->SetPoint(1, f.rest.points[0].data());
    f.restPd->GetPoints()->Modified();
    f.expectFailure("rest mesh: triangle 0 (points 0, 1, 25) is degenerate");
  }
  {
    // Target: point kAround + 1 moved to the midpoint of 0 and 1 + ... collinear on triangle 0.
    BadInputFixture f;
    const Eigen::Vector3d a = lct_test::pointsOf(f.target)[0];
    const Eigen::Vector3d b = lct_test::pointsOf(f.target)[1];
    const Eigen::Vector3d mid = 0.5 * (a + b);
    f.target->GetPoints()->SetPoint(kAround + 1, mid.data());
    f.target->GetPoints()->Modified();
    f.expectFailure("target 0: triangle 0 (points 0, 1, 25) is degenerate");
  }
  {
    // Rest: two triangles, one a sliver above the degenerate threshold (|n| / longest^2 = 1e-10):
    // the normal equations are indefinite in double. It was reported as an eigensolver defect
    // ("please report the matrix"); the message names the thinnest triangle and what to do.
    const std::vector<Eigen::Vector3d> points = { { 0, 0, 0 }, { 1, 0, 0 }, { 0.5, 1e-10, 0 },
      { 0.5, 1, 0 } };
    const std::vector<lct::Triangle> triangles = { { 0, 1, 2 }, { 1, 3, 2 } };
    vtkNew<vtkShapeBlenderLCT> blender;
    vtkNew<lct_test::ErrorCounter> errors;
    blender->AddObserver(vtkCommand::ErrorEvent, errors);
    blender->SetInputData(lct_test::toPolyData(points, triangles));
    EXPECT_EQ(blender->GetExecutive()->Update(), 0);
    EXPECT_NE(errors->Last.find("cannot be factorised in double precision: its thinnest triangle, "
                                "triangle 0 (points 0, 1, 2), has |n| / (longest edge)^2 = 1e-10"),
      std::string::npos)
      << errors->Last;
    EXPECT_EQ(errors->Last.find("eigensolver"), std::string::npos) << errors->Last;
  }
}

// Meshes at 1e+-200: their squared edges and areas leave double's range, and they were refused
// as "degenerate (zero or near-zero area)". They are refused as too large or too small, and a
// target 1e100 times the rest mesh (inside the range) is blended like any other.
TEST(ShapeBlendBadInput, MeshesBeyondTheScaleRange)
{
  const auto scaled = [](vtkPolyData* pd, double factor) {
    vtkPoints* points = pd->GetPoints();
    for (vtkIdType i = 0; i < points->GetNumberOfPoints(); ++i)
    {
      double p[3];
      points->GetPoint(i, p);
      points->SetPoint(i, factor * p[0], factor * p[1], factor * p[2]);
    }
    points->Modified();
  };
  {
    BadInputFixture f;
    scaled(f.restPd, 1e-200);
    f.expectFailure("rest mesh: triangle 0 (points 0, 1, 25) is too small");
  }
  {
    BadInputFixture f;
    scaled(f.target, 1e200);
    f.expectFailure("target 0: triangle 0 (points 0, 1, 25) is too large");
    EXPECT_EQ(f.errors->Last.find("degenerate"), std::string::npos) << f.errors->Last;
  }
  {
    BadInputFixture f;
    scaled(f.target, 1e100);
    f.blender->SetWeight(0, 1.0);
    f.blender->Update();
    EXPECT_EQ(f.errors->Count, 0) << f.errors->Last;
    const std::vector<Eigen::Vector3d> out = lct_test::pointsOf(f.blender->GetOutput());
    const std::vector<Eigen::Vector3d> expected = lct_test::pointsOf(f.target);
    EXPECT_LE(maxDistance(out, expected), 1e-9 * 1e100);
  }
}

TEST(ShapeBlender, AnyScaleInTheDocumentedRangeBlendsAccurately)
{
  // The bar at scale s with its copy scaled by S, weight 1/2: s sqrt S times the bar, centred
  // where the bar is (its centroid, 0 for both meshes). A plain sum of the target's points put
  // its centroid ~1e-17 S off 0, which moved the blend by 433 of its sizes at S = 1e40 and
  // collapsed it to one point at S = 1e80; the rest's edge matrix, inverted in plain double,
  // held Inf or 0 beyond ~1e+-102 (its determinant is a volume), which refused meshes at
  // 1e-130 or 1e130 with garbage ("point -1 is (3.99e252, ...)") and "degenerate" triangles.
  // A saddle on a grid of binary fractions, symmetric about 0: its centroid is exactly 0, and
  // so is that of any copy scaled by a factor (each coordinate times the same double).
  Mesh rest;
  const double grid[4] = { -0.5, -0.25, 0.25, 0.5 };
  for (const double y : grid)
  {
    for (const double x : grid)
    {
      rest.points.emplace_back(x, y, x * y);
    }
  }
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const std::int64_t v = 4 * j + i;
      rest.triangles.push_back({ v, v + 1, v + 5 });
      rest.triangles.push_back({ v, v + 5, v + 4 });
    }
  }
  const auto scaled = [](const std::vector<Eigen::Vector3d>& points, double factor) {
    std::vector<Eigen::Vector3d> out;
    for (const auto& p : points)
    {
      out.push_back(factor * p);
    }
    return out;
  };
  const std::pair<double, double> cases[] = { { 1.0, 1e10 }, { 1.0, 1e40 }, { 1.0, 1e80 },
    { 1.0, 1e100 }, { 1e-130, 1.0 }, { 1e130, 1.0 }, { 1e-140, 1.0 }, { 1e140, 1.0 },
    { 1e-100, 1e-40 }, { 1e100, 1e40 } };
  for (const auto& [s, factor] : cases)
  {
    Mesh at = rest;
    at.points = scaled(rest.points, s);
    vtkNew<vtkShapeBlenderLCT> blender;
    vtkNew<lct_test::ErrorCounter> errors;
    blender->AddObserver(vtkCommand::ErrorEvent, errors);
    blender->SetInputData(lct_test::toPolyData(at.points, at.triangles));
    const int index =
      blender->AddTarget(lct_test::toPolyData(scaled(at.points, factor), at.triangles));
    ASSERT_EQ(blender->SetWeight(index, 0.5), 1);
    ASSERT_EQ(blender->GetExecutive()->Update(), 1) << s << " " << factor << " " << errors->Last;
    EXPECT_EQ(errors->Count, 0) << errors->Last;
    const std::vector<Eigen::Vector3d> expected = scaled(at.points, std::sqrt(factor));
    const double size = s * std::sqrt(factor);
    EXPECT_LT(maxDistance(lct_test::pointsOf(blender->GetOutput()), expected) / size, 1e-12)
      << s << " " << factor;
  }
}

TEST(ShapeBlendBadInput, NonFiniteWeightsAndIndicesOutOfRange)
{
  for (const double bad :
    { std::numeric_limits<double>::quiet_NaN(), -std::numeric_limits<double>::infinity() })
  {
    BadInputFixture f;
    EXPECT_EQ(f.blender->SetWeight(0, bad), 1);
    f.expectFailure("the weight of target 0 is");
  }
  BadInputFixture f;
  const int before = f.errors->Count;
  EXPECT_EQ(f.blender->SetWeight(1, 0.5), 0);
  EXPECT_EQ(f.blender->SetWeight(-1, 0.5), 0);
  EXPECT_EQ(f.blender->GetWeight(3), 0.0);
  EXPECT_EQ(f.blender->GetTarget(1), nullptr);
  EXPECT_EQ(f.errors->Count, before + 4);
  EXPECT_NE(f.errors->Last.find("target 1 is outside [0, 1)"), std::string::npos) << f.errors->Last;
}

TEST(ShapeBlendBadInput, ExtrapolationSoFarThatTheMapsOverflow)
{
  BadInputFixture f;
  // A stretch of 1.4 per unit weight overflows at w ~ 2000.
  Mesh rest = f.rest;
  std::vector<Eigen::Vector3d> stretched;
  for (const auto& p : rest.points)
  {
    stretched.emplace_back(1.4 * p.x(), p.y(), p.z());
  }
  f.blender->RemoveAllTargets();
  f.blender->AddTarget(lct_test::toPolyData(stretched, rest.triangles));
  f.blender->SetWeight(0, 1e6);
  f.expectFailure("cannot be formed");
}

TEST(ShapeBlendBadInput, FloatPointsBlendedBeyondFloatsRangeAreAnErrorNotInf)
{
  // A 3 x 3 grid of float points, spacing s; the target scales the rest by 3, so weight w scales
  // it by 3^w: at w = 20 every coordinate but the centre's is beyond FLT_MAX (but not DBL_MAX).
  const auto grid = [](double s, int type) {
    std::vector<Eigen::Vector3d> points;
    for (int j = 0; j < 3; ++j)
    {
      for (int i = 0; i < 3; ++i)
      {
        points.emplace_back(i * s, j * s, 0.0);
      }
    }
    std::vector<lct::Triangle> triangles;
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        const std::int64_t a = 3 * j + i;
        triangles.push_back({ a, a + 1, a + 4 });
        triangles.push_back({ a, a + 4, a + 3 });
      }
    }
    vtkSmartPointer<vtkPolyData> pd = lct_test::toPolyData(points, triangles);
    vtkNew<vtkPoints> typed;
    typed->SetDataType(type);
    typed->DeepCopy(pd->GetPoints());
    pd->SetPoints(typed);
    return pd;
  };
  vtkNew<vtkShapeBlenderLCT> blender;
  vtkNew<lct_test::ErrorCounter> errors;
  blender->AddObserver(vtkCommand::ErrorEvent, errors);
  blender->SetInputData(grid(1e37, VTK_FLOAT));
  blender->AddTarget(grid(3e37, VTK_FLOAT));
  blender->SetWeight(0, 1.0);
  ASSERT_EQ(blender->GetExecutive()->Update(), 1);
  ASSERT_EQ(blender->GetOutput()->GetPoints()->GetDataType(), VTK_FLOAT);
  const std::vector<Eigen::Vector3d> good = lct_test::pointsOf(blender->GetOutput());
  EXPECT_EQ(errors->Count, 0);

  blender->SetWeight(0, 20.0);
  EXPECT_EQ(blender->GetExecutive()->Update(), 0);
  ASSERT_GT(errors->Count, 0);
  EXPECT_NE(errors->Last.find("point 0 is"), std::string::npos) << errors->Last;
  EXPECT_NE(errors->Last.find("out of the range of float"), std::string::npos) << errors->Last;
  const std::vector<Eigen::Vector3d> kept = lct_test::pointsOf(blender->GetOutput());
  EXPECT_EQ(maxDistance(kept, good), 0.0);
  for (const Eigen::Vector3d& p : kept)
  {
    EXPECT_TRUE(p.allFinite());
  }

  // The same blend of double points fits double.
  errors->Count = 0;
  blender->SetInputData(grid(1e37, VTK_DOUBLE));
  blender->RemoveAllTargets();
  blender->AddTarget(grid(3e37, VTK_DOUBLE));
  blender->SetWeight(0, 20.0);
  EXPECT_EQ(blender->GetExecutive()->Update(), 1);
  EXPECT_EQ(errors->Count, 0);
  for (const Eigen::Vector3d& p : lct_test::pointsOf(blender->GetOutput()))
  {
    EXPECT_TRUE(p.allFinite());
  }
}

TEST(ShapeBlendBadInput, RecoversAfterTheInputIsFixed)
{
  BadInputFixture f;
  f.target->GetPoints()->SetPoint(3, std::numeric_limits<double>::quiet_NaN(), 0.0, 0.0);
  f.target->GetPoints()->Modified();
  f.expectFailure("target 0: point 3");
  f.target->GetPoints()->SetPoint(3, lct_test::twisted(f.rest.points, kPi, kLength)[3].data());
  f.target->GetPoints()->Modified();
  EXPECT_EQ(f.blender->GetExecutive()->Update(), 1);
  EXPECT_LT(maxDistance(lct_test::pointsOf(f.blender->GetOutput()), f.good), 1e-12);
}
