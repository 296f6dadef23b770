// vtkProbeDeformerLCT and lct/ProbeBlend: the guarantees of Kaji & Ochiai §5.2 as issue #11
// states them, each against an independent formula (Eigen's MatrixFunctions, Eigen's
// quaternions, vtkWeightedTransformFilter), and every bad input.
#include "RandomTransforms.h"
#include "VtkTestHelpers.h"

#include "lct/Affine.h"
#include "lct/PolarParametrisation.h"
#include "lct/ProbeBlend.h"
#include "lct/ProbeBlendBatch.h"
#include "lct/SO3.h"

#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkLongLongArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProbeDeformerLCT.h"
#include "vtkTransform.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkWeightedTransformFilter.h"

#include <unsupported/Eigen/MatrixFunctions>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
using lct_test::kPi;
using lct_test::RandomTransforms;
using lct_test::TransformClass;

Eigen::Matrix4d translation(const Eigen::Vector3d& d)
{
  Eigen::Matrix4d t = Eigen::Matrix4d::Identity();
  t.topRightCorner<3, 1>() = d;
  return t;
}

Eigen::Matrix4d rotationAbout(const Eigen::Vector3d& axis, double angle, const Eigen::Vector3d& c)
{
  Eigen::Matrix4d r = Eigen::Matrix4d::Identity();
  r.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
  return translation(c) * r * translation(-c);
}

Eigen::Vector3d apply(const Eigen::Matrix4d& m, const Eigen::Vector3d& p)
{
  return m.topLeftCorner<3, 3>() * p + m.topRightCorner<3, 1>();
}

const lct::BlendMode kModes[] = { lct::BlendMode::Polar, lct::BlendMode::MatrixLog,
  lct::BlendMode::Linear, lct::BlendMode::DualQuaternion };

const char* modeName(lct::BlendMode m)
{
  switch (m)
  {
    case lct::BlendMode::Polar:
      return "Polar";
    case lct::BlendMode::MatrixLog:
      return "MatrixLog";
    case lct::BlendMode::Linear:
      return "Linear";
    case lct::BlendMode::DualQuaternion:
      return "DualQuaternion";
  }
  return "?";
}

/// Random probes of a class with rest centres, and random normalised weights per point.
struct Scene
{
  std::vector<Eigen::Matrix4d> probes;
  std::vector<Eigen::Vector3d> centres;
  std::vector<Eigen::Vector3d> points;
  std::vector<double> weights; // points x probes
};

Scene randomScene(RandomTransforms& r, TransformClass c, int probes, int points)
{
  Scene s;
  for (int i = 0; i < probes; ++i)
  {
    // Moderate turns, so that every mode (MatrixLog: principal logs) is defined.
    Eigen::Matrix4d a = r.Affine(c);
    a.topLeftCorner<3, 3>() = r.Rotation(r.Uniform(0.0, 2.0));
    if (c == TransformClass::GeneralAffine)
    {
      Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
      for (int k = 0; k < 3; ++k)
      {
        stretch(k, k) = r.LogUniform(0.5, 2.0);
      }
      stretch(0, 1) = stretch(1, 0) = r.Uniform(-0.2, 0.2);
      a.topLeftCorner<3, 3>() *= stretch;
    }
    s.probes.push_back(a);
    s.centres.push_back(Eigen::Vector3d(r.Uniform(-5, 5), r.Uniform(-5, 5), r.Uniform(-5, 5)));
  }
  for (int p = 0; p < points; ++p)
  {
    s.points.push_back(Eigen::Vector3d(r.Uniform(-5, 5), r.Uniform(-5, 5), r.Uniform(-5, 5)));
    double sum = 0.0;
    std::vector<double> w(probes);
    for (double& x : w)
    {
      x = r.Uniform(0.0, 1.0);
      sum += x;
    }
    for (double x : w)
    {
      s.weights.push_back(x / sum);
    }
  }
  return s;
}

Eigen::Vector3d blended(const lct::ProbeBlendSet& set, const double* w, const Eigen::Vector3d& p)
{
  lct::PointMap map;
  EXPECT_EQ(
    lct::blendAtPoint(set, w, nullptr, static_cast<int>(set.probes.size()), map), lct::Status::Ok);
  return map.apply(p);
}

/// The oracle of the log blends: exp(sum w_i log(T(-c) A_i T(c))) with Eigen's MatrixFunctions
/// (MatrixLog), or phi(sum w_i psi(...)) with psi the polar decomposition by Eigen's SVD.
Eigen::Vector3d oracle(lct::BlendMode mode, const Scene& s, int point)
{
  const Eigen::Vector3d& p = s.points[point];
  const double* w = &s.weights[point * s.probes.size()];
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < s.probes.size(); ++i)
  {
    c += w[i] * s.centres[i];
  }
  if (mode == lct::BlendMode::MatrixLog)
  {
    Eigen::Matrix4d sum = Eigen::Matrix4d::Zero();
    for (std::size_t i = 0; i < s.probes.size(); ++i)
    {
      const Eigen::Matrix4d centred = translation(-c) * s.probes[i] * translation(c);
      sum += w[i] * Eigen::Matrix4d(centred.log());
    }
    return c + apply(Eigen::Matrix4d(sum.exp()), p - c);
  }
  // Polar: A = T(l) U S; sum w_i (l_i, log U_i, log S_i), then T(l) exp(W) exp(Y).
  Eigen::Vector3d l = Eigen::Vector3d::Zero();
  Eigen::Matrix3d rot = Eigen::Matrix3d::Zero(), sym = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < s.probes.size(); ++i)
  {
    const Eigen::Matrix4d centred = translation(-c) * s.probes[i] * translation(c);
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(
      centred.topLeftCorner<3, 3>(), Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d u = svd.matrixU() * svd.matrixV().transpose();
    const Eigen::Matrix3d st =
      svd.matrixV() * svd.singularValues().asDiagonal() * svd.matrixV().transpose();
    l += w[i] * centred.topRightCorner<3, 1>();
    rot += w[i] * Eigen::Matrix3d(u.log());
    sym += w[i] * Eigen::Matrix3d(st.log());
  }
  return c + l + Eigen::Matrix3d(rot.exp()) * Eigen::Matrix3d(sym.exp()) * (p - c);
}

/// Kavan's DLB of the rigid maps x -> rotations_i x + shifts_i with weights w, written with
/// Eigen's quaternions (hemisphere check against the first heaviest): x -> rotation x + shift.
struct RigidMap
{
  Eigen::Matrix3d rotation;
  Eigen::Vector3d shift;
};
RigidMap kavanBlend(const std::vector<Eigen::Quaterniond>& rotations,
  const std::vector<Eigen::Vector3d>& shifts, const double* w)
{
  std::size_t pivot = 0;
  for (std::size_t i = 0; i < rotations.size(); ++i)
  {
    pivot = w[i] > w[pivot] ? i : pivot;
  }
  Eigen::Vector4d real = Eigen::Vector4d::Zero(), dual = Eigen::Vector4d::Zero();
  for (std::size_t i = 0; i < rotations.size(); ++i)
  {
    const Eigen::Quaterniond& q = rotations[i];
    const Eigen::Vector3d& t = shifts[i];
    const Eigen::Quaterniond d = Eigen::Quaterniond(0.0, t.x(), t.y(), t.z()) * q;
    const double sign = q.dot(rotations[pivot]) < 0 ? -1.0 : 1.0;
    real += sign * w[i] * q.coeffs();
    dual += sign * w[i] * 0.5 * d.coeffs();
  }
  const double n = real.norm();
  const Eigen::Quaterniond q(real / n), d(dual / n);
  const Eigen::Quaterniond t = d * q.conjugate();
  return { q.toRotationMatrix(), 2.0 * t.vec() };
}

/// The oracle of DualQuaternion for rigid probes: kavanBlend of the probes themselves.
Eigen::Vector3d dualQuaternionOracle(const Scene& s, int point)
{
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<Eigen::Vector3d> shifts;
  for (const Eigen::Matrix4d& a : s.probes)
  {
    rotations.emplace_back(Eigen::Matrix3d(a.topLeftCorner<3, 3>()));
    shifts.push_back(a.topRightCorner<3, 1>());
  }
  const RigidMap m = kavanBlend(rotations, shifts, &s.weights[point * s.probes.size()]);
  return m.rotation * s.points[point] + m.shift;
}

vtkSmartPointer<vtkMatrix4x4> toVtk(const Eigen::Matrix4d& m)
{
  auto v = vtkSmartPointer<vtkMatrix4x4>::New();
  lct_test::toVtk(m, v);
  return v;
}

/// A poly data of the scene's points with its weights as a point-data array.
vtkSmartPointer<vtkPolyData> toPolyData(const Scene& s)
{
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (const auto& p : s.points)
  {
    pts->InsertNextPoint(p.data());
  }
  pd->SetPoints(pts);
  vtkNew<vtkDoubleArray> w;
  w->SetName("w");
  w->SetNumberOfComponents(static_cast<int>(s.probes.size()));
  w->SetNumberOfTuples(static_cast<vtkIdType>(s.points.size()));
  for (std::size_t i = 0; i < s.weights.size(); ++i)
  {
    w->SetValue(static_cast<vtkIdType>(i), s.weights[i]);
  }
  pd->GetPointData()->AddArray(w);
  return pd;
}

/// A filter over the scene: probe i is (A_i T(c_i), T(c_i)), so that A_i = current rest^-1
/// and c_i is its rest centre.
vtkSmartPointer<vtkProbeDeformerLCT> deformerFor(const Scene& s, int mode)
{
  auto f = vtkSmartPointer<vtkProbeDeformerLCT>::New();
  for (std::size_t i = 0; i < s.probes.size(); ++i)
  {
    f->AddProbe(toVtk(s.probes[i] * translation(s.centres[i])), toVtk(translation(s.centres[i])));
  }
  f->SetBlendMode(mode);
  f->SetWeightModeToPointData();
  f->SetWeightArrayName("w");
  return f;
}

Eigen::Vector3d pointOf(vtkPointSet* d, vtkIdType i)
{
  double p[3];
  d->GetPoint(i, p);
  return Eigen::Vector3d(p[0], p[1], p[2]);
}

/// Slot weights (slot k = probe k) taken as they are, without normalisation.
lct::WeightSource unnormalisedSlots(const std::vector<double>& weights, int slots)
{
  lct::WeightSource source;
  source.kind = lct::WeightSource::Kind::Slots;
  source.normalization = lct::WeightNormalization::None;
  source.weights = weights.data();
  source.slots = slots;
  return source;
}

/// InverseDistance weights r_k / d_k^exponent, Linear normalisation.
lct::WeightSource inverseDistance(const double* radii, double exponent)
{
  lct::WeightSource source;
  source.kind = lct::WeightSource::Kind::InverseDistance;
  source.radii = radii;
  source.exponent = exponent;
  return source;
}

/// Deforms the double points `in` point by point (lct::deformPoints) and, where the set runs in
/// lanes, by lct::deformBatch on the CPU's lanes and on 4, each into `out` (first filled with
/// 7) and each checked by check(path name); every run must succeed.
template <typename Check>
void deformEveryWay(const lct::ProbeBlendSet& set, const lct::WeightSource& source,
  const std::vector<double>& in, std::vector<double>& out, Check&& check)
{
  const std::int64_t count = static_cast<std::int64_t>(in.size() / 3);
  out.assign(in.size(), 7.0);
  ASSERT_TRUE(lct::deformPoints(set, source, in.data(), out.data(), nullptr, 0, 0, count).ok());
  check("point by point");
  lct::ProbeBatchSet batch;
  if (lct::prepareProbeBatch(set, batch))
  {
    for (const int lanes : { 0, 4 })
    {
      std::fill(out.begin(), out.end(), 7.0);
      ASSERT_TRUE(lct::deformBatch(
        set, batch, source, in.data(), out.data(), true, nullptr, 0, 0, count, lanes)
                    .ok());
      check(lanes == 4 ? "4 lanes" : "lanes");
    }
  }
}

} // namespace

TEST(ProbeBlend, LogBlendsMatchTheOracleOnRandomProbes)
{
  RandomTransforms r(11);
  for (TransformClass c : { TransformClass::Rigid, TransformClass::GeneralAffine })
  {
    for (lct::BlendMode mode : { lct::BlendMode::Polar, lct::BlendMode::MatrixLog })
    {
      const Scene s = randomScene(r, c, 4, 200);
      const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, mode);
      ASSERT_TRUE(prepared.ok());
      double worst = 0.0;
      for (std::size_t p = 0; p < s.points.size(); ++p)
      {
        const Eigen::Vector3d ours = blended(prepared.set, &s.weights[p * 4], s.points[p]);
        worst = std::max(
          worst, (ours - oracle(mode, s, static_cast<int>(p))).norm() / (1.0 + s.points[p].norm()));
      }
      EXPECT_LT(worst, 1e-11) << modeName(mode) << " " << lct_test::className(c);
    }
  }
}

TEST(ProbeBlend, DualQuaternionMatchesKavanWithEigenQuaternions)
{
  RandomTransforms r(12);
  const Scene s = randomScene(r, TransformClass::Rigid, 4, 300);
  const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, lct::BlendMode::DualQuaternion);
  ASSERT_TRUE(prepared.ok());
  ASSERT_TRUE(prepared.set.allRigid);
  for (std::size_t p = 0; p < s.points.size(); ++p)
  {
    const Eigen::Vector3d ours = blended(prepared.set, &s.weights[p * 4], s.points[p]);
    EXPECT_LT((ours - dualQuaternionOracle(s, static_cast<int>(p))).norm(), 1e-11) << p;
  }
}

/// "Polar+DQ" (Kaji & Ochiai Table 2) in Kavan et al.'s two phases, written out with Eigen: each
/// A_i = [U_i | t_i'] T(c_i) S_i T(-c_i) split by Eigen's SVD (t_i' = t_i + (L_i - U_i) c_i); the
/// point stretched by sum w_i (c_i + S_i (p - c_i)) / sum w_i, then moved by kavanBlend of the
/// rigid parts.
Eigen::Vector3d polarDualQuaternionOracle(const Scene& s, int point, double weightScale)
{
  const std::size_t n = s.probes.size();
  std::vector<double> w(n);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    w[i] = weightScale * s.weights[point * n + i];
    sum += w[i];
  }
  const Eigen::Vector3d& p = s.points[point];
  Eigen::Vector3d stretched = Eigen::Vector3d::Zero();
  std::vector<Eigen::Quaterniond> rotations;
  std::vector<Eigen::Vector3d> shifts;
  for (std::size_t i = 0; i < n; ++i)
  {
    const Eigen::Matrix3d l = s.probes[i].topLeftCorner<3, 3>();
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd(l, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d u = svd.matrixU() * svd.matrixV().transpose();
    const Eigen::Matrix3d stretch =
      svd.matrixV() * svd.singularValues().asDiagonal() * svd.matrixV().transpose();
    const Eigen::Vector3d& c = s.centres[i];
    stretched += w[i] / sum * (c + stretch * (p - c));
    rotations.emplace_back(u);
    shifts.push_back(s.probes[i].topRightCorner<3, 1>() + (l - u) * c);
  }
  const RigidMap m = kavanBlend(rotations, shifts, w.data());
  return m.rotation * stretched + m.shift;
}

TEST(ProbeBlend, DualQuaternionWithStretchIsKavansTwoPhaseBlend)
{
  RandomTransforms r(16);
  const Scene s = randomScene(r, TransformClass::GeneralAffine, 4, 300);
  const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, lct::BlendMode::DualQuaternion);
  ASSERT_TRUE(prepared.ok());
  ASSERT_FALSE(prepared.set.allRigid);
  // Weights summing to 2.5 blend as their normalised selves (DLB normalises the rotations; the
  // stretches are divided by the sum likewise).
  for (const double scale : { 1.0, 2.5 })
  {
    double worst = 0.0;
    for (std::size_t p = 0; p < s.points.size(); ++p)
    {
      std::vector<double> w(&s.weights[p * 4], &s.weights[p * 4] + 4);
      for (double& x : w)
      {
        x *= scale;
      }
      const Eigen::Vector3d ours = blended(prepared.set, w.data(), s.points[p]);
      const Eigen::Vector3d expected = polarDualQuaternionOracle(s, static_cast<int>(p), scale);
      worst = std::max(worst, (ours - expected).norm() / (1.0 + s.points[p].norm()));
    }
    EXPECT_LT(worst, 1e-11) << "weights scaled by " << scale;
  }
  // Weights whose sum cancels have no stretch blend: reported, not divided by zero.
  const double cancelling[4] = { 1.0, -1.0, 0.5, -0.5 };
  lct::PointMap map;
  EXPECT_EQ(
    lct::blendAtPoint(prepared.set, cancelling, nullptr, 4, map), lct::Status::NumericalFailure);
}

TEST(ProbeBlend, DualQuaternionWithAStretchThatOverflowsFailsInsteadOfMovingPointsToInfinity)
{
  // A probe stretched by 1e200 about a rest centre at 1e150: its stretch phase moves the centre
  // term (S - I) c beyond double. Both paths (lanes, and point by point with indices)
  // report the first point as out of range; none writes an infinite point.
  std::vector<Eigen::Matrix4d> relative(2, Eigen::Matrix4d::Identity());
  relative[0].topLeftCorner<3, 3>() *= 1e200;
  const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(1e150, 0, 0),
    Eigen::Vector3d(0, 0, 1) };
  const auto prepared = lct::prepareProbes(relative, centres, {}, lct::BlendMode::DualQuaternion);
  ASSERT_TRUE(prepared.ok());
  const std::vector<double> in = { 1, 2, 3, 4, 5, 6 };
  const std::vector<double> weights = { 0.5, 0.5, 0.5, 0.5 };
  const std::vector<std::int32_t> indices = { 0, 1, 0, 1 };
  lct::WeightSource source;
  source.kind = lct::WeightSource::Kind::Slots;
  source.weights = weights.data();
  source.slots = 2;
  std::vector<double> out(in.size(), 7.0);
  lct::DeformFailure f =
    lct::deformPoints(prepared.set, source, in.data(), out.data(), nullptr, 0, 0, 2);
  EXPECT_EQ(f.point, 0);
  EXPECT_EQ(f.status, lct::Status::OutOfRange);
  source.indices = indices.data();
  f = lct::deformPoints(prepared.set, source, in.data(), out.data(), nullptr, 0, 0, 2);
  EXPECT_EQ(f.point, 0);
  EXPECT_EQ(f.status, lct::Status::OutOfRange);
  for (const double x : out)
  {
    EXPECT_TRUE(std::isfinite(x));
  }
}

TEST(ProbeBlend, DualQuaternionWeightsBeyondTheSquareRootOfDoubleBlendAsTheirRatios)
{
  // Kavan's DLB divides by |sum w q|, so weights scaled by any factor blend alike. Without
  // normalisation, weights of 1e200 square beyond double in |sum w q|^2: the blend must still
  // turn the point (not leave it at rest), by the lanes and point by point.
  std::vector<Eigen::Matrix4d> relative(2, Eigen::Matrix4d::Identity());
  relative[1].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0, 0, 1.5));
  relative[1].topRightCorner<3, 1>() = Eigen::Vector3d(1, 2, 3);
  const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0) };
  const auto prepared = lct::prepareProbes(relative, centres, {}, lct::BlendMode::DualQuaternion);
  ASSERT_TRUE(prepared.ok());
  lct::PointMap unit;
  const double half[] = { 0.5, 0.5 };
  ASSERT_EQ(lct::blendAtPoint(prepared.set, half, nullptr, 2, unit), lct::Status::Ok);
  const Eigen::Vector3d p(0.3, -2.0, 1.0), expected = unit.apply(p);
  ASSERT_GT((expected - p).norm(), 0.5);
  for (const double scale : { 1e-300, 1e-160, 1e160, 1e200, 1e300 })
  {
    const double huge[] = { scale, scale };
    lct::PointMap map;
    ASSERT_EQ(lct::blendAtPoint(prepared.set, huge, nullptr, 2, map), lct::Status::Ok) << scale;
    EXPECT_LE((map.apply(p) - expected).norm(), 1e-12) << scale;
    // 9 points: a full block of 4 or 8 lanes and a partial one.
    std::vector<double> in, weights, out(27, 7.0);
    for (int i = 0; i < 9; ++i)
    {
      in.insert(in.end(), { p[0], p[1], p[2] });
      weights.insert(weights.end(), { scale, scale });
    }
    const lct::WeightSource source = unnormalisedSlots(weights, 2);
    for (const int lanes : { 0, 4 })
    {
      lct::ProbeBatchSet batch;
      ASSERT_TRUE(lct::prepareProbeBatch(prepared.set, batch));
      const lct::DeformFailure f = lct::deformBatch(
        prepared.set, batch, source, in.data(), out.data(), true, nullptr, 0, 0, 9, lanes);
      EXPECT_TRUE(f.ok()) << scale;
      for (int i = 0; i < 9; ++i)
      {
        EXPECT_LE(
          (Eigen::Vector3d(out[3 * i], out[3 * i + 1], out[3 * i + 2]) - expected).norm(), 1e-12)
          << scale << " lanes " << lanes << " point " << i;
      }
    }
    const lct::DeformFailure f =
      lct::deformPoints(prepared.set, source, in.data(), out.data(), nullptr, 0, 0, 9);
    EXPECT_TRUE(f.ok()) << scale;
    EXPECT_LE((Eigen::Vector3d(out[0], out[1], out[2]) - expected).norm(), 1e-12) << scale;
  }
}

TEST(ProbeBlend, LogBlendWeightsThatWindTheTurnBeyondDoubleAreRefused)
{
  // Without normalisation the Polar blend of two probes turning 1.5 rad is a turn of
  // 3 w radians: at w = 1e100 no digit of its sine is known (an error, not a random rotation),
  // at w = 1e300 it overflows; at w = 1e8 it is still resolved. Lanes and point by point agree.
  std::vector<Eigen::Matrix4d> relative(2, Eigen::Matrix4d::Identity());
  relative[0].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0, 0, 1.5));
  relative[1].topLeftCorner<3, 3>() = relative[0].topLeftCorner<3, 3>();
  const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0) };
  const auto prepared = lct::prepareProbes(relative, centres, {}, lct::BlendMode::Polar);
  ASSERT_TRUE(prepared.ok());
  for (const auto& [scale, expected] :
    { std::pair{ 1e8, lct::Status::Ok }, std::pair{ 1e100, lct::Status::InaccurateResult },
      std::pair{ 1e300, lct::Status::OutOfRange } })
  {
    const double weights[] = { scale, scale };
    lct::PointMap map;
    EXPECT_EQ(lct::blendAtPoint(prepared.set, weights, nullptr, 2, map), expected) << scale;
    std::vector<double> in(27, 1.0), raw, out(27, 7.0);
    for (int i = 0; i < 9; ++i)
    {
      raw.insert(raw.end(), { scale, scale });
    }
    const lct::WeightSource source = unnormalisedSlots(raw, 2);
    lct::ProbeBatchSet batch;
    ASSERT_TRUE(lct::prepareProbeBatch(prepared.set, batch));
    for (const int lanes : { 0, 4 })
    {
      const lct::DeformFailure f = lct::deformBatch(
        prepared.set, batch, source, in.data(), out.data(), true, nullptr, 0, 0, 9, lanes);
      EXPECT_EQ(f.status, expected) << scale << " lanes " << lanes;
      EXPECT_EQ(f.point, expected == lct::Status::Ok ? -1 : 0);
    }
    const lct::DeformFailure f =
      lct::deformPoints(prepared.set, source, in.data(), out.data(), nullptr, 0, 0, 9);
    EXPECT_EQ(f.status, expected) << scale;
    for (const double x : out)
    {
      EXPECT_TRUE(std::isfinite(x));
    }
  }
  // MatrixLog (point by point only): the same turns.
  const auto matrixLog = lct::prepareProbes(relative, centres, {}, lct::BlendMode::MatrixLog);
  ASSERT_TRUE(matrixLog.ok());
  for (const auto& [scale, ok] :
    { std::pair{ 1e8, true }, std::pair{ 1e100, false }, std::pair{ 1e300, false } })
  {
    const double weights[] = { scale, scale };
    lct::PointMap map;
    const lct::Status s = lct::blendAtPoint(matrixLog.set, weights, nullptr, 2, map);
    EXPECT_EQ(s == lct::Status::Ok, ok) << scale << " " << lct::describe(s);
    EXPECT_TRUE(map.linearMinusIdentity.allFinite() && map.shift.allFinite());
  }
}

TEST(ProbeBlend, InverseDistanceWeightsOfFarPointsAreTheirLimitNotZero)
{
  // r / d^p underflows far from every centre (d = 1e200, p = 2: 1e-400) and d^2 overflows from
  // 1.4e154 on: every weight was 0 and the point stayed put. Linear normalisation needs only
  // their ratios, r_k (d_min / d_k)^p, here r_k / sum r (the distances agree to 1e-200): the
  // point moves by the blend with weights 1/4, 3/4, by the lanes and point by point.
  std::vector<Eigen::Matrix4d> relative(2, Eigen::Matrix4d::Identity());
  relative[0].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0, 0, 1.0));
  relative[1].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0.5, 0, 0));
  const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0) };
  const double radii[] = { 1.0, 3.0 };
  for (const lct::BlendMode mode : { lct::BlendMode::Polar, lct::BlendMode::Linear,
         lct::BlendMode::DualQuaternion, lct::BlendMode::MatrixLog })
  {
    const auto prepared = lct::prepareProbes(relative, centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    const double quarter[] = { 0.25, 0.75 };
    lct::PointMap limit;
    ASSERT_EQ(lct::blendAtPoint(prepared.set, quarter, nullptr, 2, limit), lct::Status::Ok);
    for (const double far : { 1e20, 1e160, 1e200, 1e300 })
    {
      for (const double exponent : { 1.0, 2.0, 1.5 })
      {
        const Eigen::Vector3d p(far, 0.5 * far, -0.25 * far), expected = limit.apply(p);
        std::vector<double> in, out;
        for (int i = 0; i < 9; ++i)
        {
          in.insert(in.end(), { p[0], p[1], p[2] });
        }
        const lct::WeightSource source = inverseDistance(radii, exponent);
        const auto check = [&](const char* path) {
          for (int i = 0; i < 9; ++i)
          {
            const Eigen::Vector3d got(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
            // (stableNorm: the squares of these coordinates overflow)
            EXPECT_LE((got - expected).stableNorm(), 1e-12 * p.stableNorm())
              << path << " mode " << static_cast<int>(mode) << " at " << far << " exponent "
              << exponent << " point " << i;
          }
        };
        deformEveryWay(prepared.set, source, in, out, check);
      }
    }
  }
}

TEST(ProbeBlend, InverseDistanceWeightsNextToAndOnCoincidentCentresShareByRadius)
{
  // Two probes whose centres coincide at the origin, radii 1 and 3, a third at (1, 0, 0):
  // near the origin r_k / d^p tends to 1 : 3 : 0. At d = 1e-154 (exponent 2) the raw weights
  // 1e308 and 3e308 overflowed (the second to Inf, taken as "on the centre": probe 1 alone),
  // and at d = 0 both were Inf and shared equally: a jump from 1/4, 3/4 to 0, 1 and 1/2, 1/2.
  // Under Linear normalisation every such point now blends 1/4, 3/4, by the lanes and point by
  // point; a single centre still takes its probe alone.
  std::vector<Eigen::Matrix4d> relative(3, Eigen::Matrix4d::Identity());
  relative[0].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0, 0, 1.0));
  relative[0].topRightCorner<3, 1>() = Eigen::Vector3d(1, 0, 0); // moves the points near 0
  relative[1].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0.5, 0, 0));
  relative[1].topRightCorner<3, 1>() = Eigen::Vector3d(0, 2, 0);
  relative[2].topRightCorner<3, 1>() = Eigen::Vector3d(0, 5, 0);
  const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 0, 0),
    Eigen::Vector3d(1, 0, 0) };
  const double radii[] = { 1.0, 3.0, 1.0 };
  for (const lct::BlendMode mode : { lct::BlendMode::Polar, lct::BlendMode::Linear,
         lct::BlendMode::DualQuaternion, lct::BlendMode::MatrixLog })
  {
    const auto prepared = lct::prepareProbes(relative, centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    const double shared[] = { 0.25, 0.75, 0.0 }, alone[] = { 0.0, 0.0, 1.0 };
    lct::PointMap sharedMap, aloneMap;
    ASSERT_EQ(lct::blendAtPoint(prepared.set, shared, nullptr, 3, sharedMap), lct::Status::Ok);
    ASSERT_EQ(lct::blendAtPoint(prepared.set, alone, nullptr, 3, aloneMap), lct::Status::Ok);
    for (const double exponent : { 1.0, 2.0, 1.5 })
    {
      // Points at the origin, 1e-154 and 1e-300 from it, and on the third centre.
      const Eigen::Vector3d points[] = { Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(0, 1e-154, 0),
        Eigen::Vector3d(0, 0, 1e-300), Eigen::Vector3d(1, 0, 0) };
      std::vector<double> in, out;
      for (const Eigen::Vector3d& p : points)
      {
        in.insert(in.end(), { p[0], p[1], p[2] });
      }
      const lct::WeightSource source = inverseDistance(radii, exponent);
      const auto check = [&](const char* path) {
        for (int i = 0; i < 4; ++i)
        {
          const Eigen::Vector3d got(out[3 * i], out[3 * i + 1], out[3 * i + 2]);
          const Eigen::Vector3d expected = (i == 3 ? aloneMap : sharedMap).apply(points[i]);
          EXPECT_LE((got - expected).norm(), 1e-12)
            << path << " mode " << static_cast<int>(mode) << " exponent " << exponent << " point "
            << i << ": " << got.transpose() << " expected " << expected.transpose();
        }
      };
      deformEveryWay(prepared.set, source, in, out, check);
    }
  }
}

TEST(ProbeBlend, TranslatingTheSceneTranslatesTheOutput)
{
  RandomTransforms r(13);
  for (lct::BlendMode mode : kModes)
  {
    const Scene s = randomScene(r, TransformClass::GeneralAffine, 4, 100);
    for (double far : { 10.0, 1e3, 1e5 })
    {
      const Eigen::Vector3d d = far * r.UnitVector();
      Scene moved = s;
      for (std::size_t i = 0; i < s.probes.size(); ++i)
      {
        moved.probes[i] = translation(d) * s.probes[i] * translation(-d);
        moved.centres[i] += d;
      }
      const auto a = lct::prepareProbes(s.probes, s.centres, {}, mode);
      const auto b = lct::prepareProbes(moved.probes, moved.centres, {}, mode);
      ASSERT_TRUE(a.ok() && b.ok());
      for (std::size_t p = 0; p < s.points.size(); ++p)
      {
        const Eigen::Vector3d here = blended(a.set, &s.weights[p * 4], s.points[p]);
        const Eigen::Vector3d there = blended(b.set, &s.weights[p * 4], s.points[p] + d);
        EXPECT_LT((there - d - here).norm(), 1e-9 * (1.0 + d.norm()))
          << modeName(mode) << " |d| = " << far << " point " << p;
      }
    }
  }
}

TEST(ProbeBlend, TheOriginCentredFormIsNotEquivariantAndOursIs)
{
  // The measurement: one probe turning 90 degrees about its centre c, weight 1/2 (the
  // other weight on an identity probe at c): the paper's origin-centred Polar blend lands
  // (R(45) - I)... off by a distance that grows with |c|; ours turns the point by 45 degrees
  // about c wherever c is.
  const Eigen::Vector3d z(0, 0, 1);
  for (double far : { 0.0, 10.0, 100.0 })
  {
    const Eigen::Vector3d c(far, 0, 0);
    const std::vector<Eigen::Matrix4d> probes = { rotationAbout(z, kPi / 2, c),
      Eigen::Matrix4d::Identity() };
    const double w[2] = { 0.5, 0.5 };
    const Eigen::Vector3d p = c + Eigen::Vector3d(1, 0, 0);
    const Eigen::Vector3d expected = apply(rotationAbout(z, kPi / 4, c), p);
    const auto ours = lct::prepareProbes(probes, { c, c }, {}, lct::BlendMode::Polar);
    const auto originCentred = lct::prepareProbes(
      probes, { Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero() }, {}, lct::BlendMode::Polar);
    ASSERT_TRUE(ours.ok() && originCentred.ok());
    EXPECT_LT((blended(ours.set, w, p) - expected).norm(), 1e-12) << far;
    const double miss = (blended(originCentred.set, w, p) - expected).norm();
    if (far > 0.0)
    {
      // |l| = |(R(90) - I) c| = sqrt(2) |c| blended linearly: the paper's form misses by a
      // distance proportional to |c| (0.29 |c| here, about 2.9 at 10 and 29 at 100).
      EXPECT_NEAR(miss / far, 0.2929, 0.01) << far;
    }
  }
}

TEST(ProbeBlend, ProbesAtRestLeaveEveryPointBitForBit)
{
  RandomTransforms r(14);
  const Scene s = randomScene(r, TransformClass::Rigid, 3, 500);
  const std::vector<Eigen::Matrix4d> identity(3, Eigen::Matrix4d::Identity());
  for (lct::BlendMode mode : kModes)
  {
    const auto prepared = lct::prepareProbes(identity, s.centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    for (lct::WeightNormalization n : { lct::WeightNormalization::Linear,
           lct::WeightNormalization::Softmax, lct::WeightNormalization::None })
    {
      if (mode == lct::BlendMode::Linear && n == lct::WeightNormalization::None)
      {
        continue; // LBS with raw weights scales by their sum, as vtkWeightedTransformFilter does
      }
      std::vector<double> in, out(3 * s.points.size());
      for (const auto& p : s.points)
      {
        in.insert(in.end(), p.data(), p.data() + 3);
      }
      std::vector<float> inF(in.begin(), in.end()), outF(in.size());
      std::vector<double> radii(3, 8.0);
      lct::WeightSource src;
      src.kind = lct::WeightSource::Kind::InverseDistance;
      src.normalization = n;
      src.radii = radii.data();
      ASSERT_TRUE(lct::deformPoints(prepared.set, src, in.data(), out.data(), nullptr, 0, 0,
        static_cast<std::int64_t>(s.points.size()))
                    .ok());
      ASSERT_TRUE(lct::deformPoints(prepared.set, src, inF.data(), outF.data(), nullptr, 0, 0,
        static_cast<std::int64_t>(s.points.size()))
                    .ok());
      EXPECT_EQ(in, out) << modeName(mode);
      EXPECT_EQ(inF, outF) << modeName(mode);
    }
  }
}

TEST(ProbeBlend, AWeightOfOneOnARigidProbeMovesThePointRigidly)
{
  RandomTransforms r(15);
  for (lct::BlendMode mode : kModes)
  {
    const Scene s = randomScene(r, TransformClass::Rigid, 3, 50);
    const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    for (int i = 0; i < 3; ++i)
    {
      double w[3] = { 0, 0, 0 };
      w[i] = 1.0;
      for (const auto& p : s.points)
      {
        lct::PointMap map;
        ASSERT_EQ(lct::blendAtPoint(prepared.set, w, nullptr, 3, map), lct::Status::Ok);
        EXPECT_LT((map.apply(p) - apply(s.probes[i], p)).norm(), 1e-12) << modeName(mode);
        // The blended linear part is a rotation.
        Eigen::Matrix3d m = map.linearMinusIdentity + Eigen::Matrix3d::Identity();
        EXPECT_LT((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 1e-13);
      }
    }
  }
}

TEST(ProbeBlend, PolarAndDualQuaternionBlendsOfRigidProbesAreRigid)
{
  RandomTransforms r(16);
  const Scene s = randomScene(r, TransformClass::Rigid, 4, 200);
  for (lct::BlendMode mode : { lct::BlendMode::Polar, lct::BlendMode::DualQuaternion })
  {
    const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    for (std::size_t p = 0; p < s.points.size(); ++p)
    {
      lct::PointMap map;
      ASSERT_EQ(
        lct::blendAtPoint(prepared.set, &s.weights[4 * p], nullptr, 4, map), lct::Status::Ok);
      const Eigen::Matrix3d m = map.linearMinusIdentity + Eigen::Matrix3d::Identity();
      EXPECT_LT((m.transpose() * m - Eigen::Matrix3d::Identity()).norm(), 1e-13);
      EXPECT_NEAR(m.determinant(), 1.0, 1e-13);
    }
  }
}

TEST(ProbeBlend, TwistsBeyondTwoPiBlendByTheirWinding)
{
  // A probe turned 3 pi about z, with the reference that says so, blended half-way: 1.5 pi.
  const Eigen::Vector3d z(0, 0, 1);
  const std::vector<Eigen::Matrix4d> probes = { rotationAbout(z, 3 * kPi, Eigen::Vector3d::Zero()),
    Eigen::Matrix4d::Identity() };
  const std::vector<Eigen::Vector3d> centres(2, Eigen::Vector3d::Zero());
  const double w[2] = { 0.5, 0.5 };
  const Eigen::Vector3d p(1, 0, 0);
  const auto wound = lct::prepareProbes(
    probes, centres, { 3 * kPi * z, Eigen::Vector3d::Zero() }, lct::BlendMode::Polar);
  const auto principal = lct::prepareProbes(probes, centres, {}, lct::BlendMode::Polar);
  ASSERT_TRUE(wound.ok() && principal.ok());
  EXPECT_LT(
    (blended(wound.set, w, p) - apply(rotationAbout(z, 1.5 * kPi, centres[0]), p)).norm(), 1e-12);
  // Without the winding, pi: half of it is a quarter turn one way or the other.
  EXPECT_LT(std::abs(blended(principal.set, w, p).x()), 1e-12);
  EXPECT_NEAR(std::abs(blended(principal.set, w, p).y()), 1.0, 1e-12);
}

TEST(ProbeBlend, NormalsTransformByTheInverseTranspose)
{
  RandomTransforms r(17);
  for (lct::BlendMode mode : kModes)
  {
    const Scene s = randomScene(r, TransformClass::GeneralAffine, 3, 50);
    const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, mode);
    ASSERT_TRUE(prepared.ok());
    std::vector<double> in, out(150), normals, outNormals(150);
    for (const auto& p : s.points)
    {
      in.insert(in.end(), p.data(), p.data() + 3);
      const Eigen::Vector3d n = r.UnitVector();
      normals.insert(normals.end(), n.data(), n.data() + 3);
    }
    lct::WeightSource src;
    src.kind = lct::WeightSource::Kind::Slots;
    src.weights = s.weights.data();
    src.slots = 3;
    lct::CarriedVectors carried;
    carried.in = normals.data();
    carried.out = outNormals.data();
    carried.isDouble = true;
    ASSERT_TRUE(
      lct::deformPoints(prepared.set, src, in.data(), out.data(), &carried, 1, 0, 50).ok());
    for (int p = 0; p < 50; ++p)
    {
      lct::PointMap map;
      ASSERT_EQ(
        lct::blendAtPoint(prepared.set, &s.weights[3 * p], nullptr, 3, map), lct::Status::Ok);
      const Eigen::Matrix3d m = map.linearMinusIdentity + Eigen::Matrix3d::Identity();
      const Eigen::Vector3d expected =
        (m.inverse().transpose() * Eigen::Vector3d(&normals[3 * p])).normalized();
      EXPECT_LT((Eigen::Vector3d(&outNormals[3 * p]) - expected).norm(), 1e-12) << modeName(mode);
    }
  }
}

TEST(ProbeBlend, CarriedVectorsOfExtremeStretchesAreExactOrAnError)
{
  // A probe scaling by 1e160 at the point itself: the cofactor's entries (1e320) left double,
  // and normals came out 0 or NaN; they are the unit normals of the cofactor. A vector scaled
  // beyond double is an error at that point, not Inf in the output. (A contraction keeps the
  // digits of I + d, d = M - I: 1e-6 is the other case here.)
  for (const double scale : { 1e160, 1e-6 })
  {
    std::vector<Eigen::Matrix4d> relative(1, Eigen::Matrix4d::Identity());
    relative[0].topLeftCorner<3, 3>() = lct::expSO3(Eigen::Vector3d(0.3, 0, 0)) *
      Eigen::Vector3d(scale, 2.0 * scale, scale).asDiagonal();
    const std::vector<Eigen::Vector3d> centres = { Eigen::Vector3d(1, 2, 3) };
    for (const lct::BlendMode mode : kModes)
    {
      const auto prepared = lct::prepareProbes(relative, centres, {}, mode);
      if (!prepared.ok())
      {
        EXPECT_EQ(mode, lct::BlendMode::MatrixLog); // eigenvalues beyond 10^+-135
        continue;
      }
      const std::vector<double> in = { 1, 2, 3 }, weights = { 1.0 };
      std::vector<double> out(3, 7.0), normals = { 0.6, 0.0, 0.8 }, outNormals(3, 7.0);
      const lct::WeightSource src = unnormalisedSlots(weights, 1);
      lct::PointMap map;
      ASSERT_EQ(lct::blendAtPoint(prepared.set, weights.data(), nullptr, 1, map), lct::Status::Ok);
      Eigen::Matrix3d m = map.linearMinusIdentity + Eigen::Matrix3d::Identity();
      m /= m.cwiseAbs().maxCoeff();
      const Eigen::Vector3d expected =
        (m.inverse().transpose() * Eigen::Vector3d(0.6, 0.0, 0.8)).normalized();
      lct::CarriedVectors normal;
      normal.in = normals.data();
      normal.out = outNormals.data();
      normal.isDouble = true;
      const lct::DeformFailure f =
        lct::deformPoints(prepared.set, src, in.data(), out.data(), &normal, 1, 0, 1);
      ASSERT_TRUE(f.ok()) << scale << " " << modeName(mode);
      EXPECT_LT((Eigen::Vector3d(outNormals.data()) - expected).norm(), 1e-12)
        << scale << " " << modeName(mode);
      lct::ProbeBatchSet batch;
      const bool batchable = lct::prepareProbeBatch(prepared.set, batch);
      for (const int lanes : { 0, 4 })
      {
        std::fill(outNormals.begin(), outNormals.end(), 7.0);
        if (batchable)
        {
          ASSERT_TRUE(lct::deformBatch(
            prepared.set, batch, src, in.data(), out.data(), true, &normal, 1, 0, 1, lanes)
                        .ok());
          EXPECT_LT((Eigen::Vector3d(outNormals.data()) - expected).norm(), 1e-12)
            << scale << " " << modeName(mode) << " lanes " << lanes;
        }
      }
      // The same array as plain vectors, stretched by up to 2 scale.
      std::vector<double> vectors = { 1e300, 0.0, 1e300 }, outVectors(3, 7.0);
      lct::CarriedVectors vector = normal;
      vector.isNormal = false;
      vector.in = vectors.data();
      vector.out = outVectors.data();
      std::vector<lct::DeformFailure> failures = { lct::deformPoints(
        prepared.set, src, in.data(), out.data(), &vector, 1, 0, 1) };
      for (const int lanes : { 0, 4 })
      {
        if (batchable)
        {
          failures.push_back(lct::deformBatch(
            prepared.set, batch, src, in.data(), out.data(), true, &vector, 1, 0, 1, lanes));
        }
      }
      for (const lct::DeformFailure& g : failures)
      {
        EXPECT_EQ(g.status, scale > 1.0 ? lct::Status::OutOfRange : lct::Status::Ok)
          << scale << " " << modeName(mode);
        EXPECT_EQ(g.point, scale > 1.0 ? 0 : -1);
      }
      for (const double x : outVectors)
      {
        EXPECT_TRUE(std::isfinite(x)) << scale << " " << modeName(mode);
      }
    }
  }
}

TEST(ProbeDeformer, LinearModeMatchesVtkWeightedTransformFilter)
{
  RandomTransforms r(18);
  const Scene s = randomScene(r, TransformClass::GeneralAffine, 4, 300);
  vtkSmartPointer<vtkPolyData> pd = toPolyData(s);
  // vtkWeightedTransformFilter reads float weights correctly (issue #11: doubles it misreads).
  vtkNew<vtkFloatArray> wf;
  wf->DeepCopy(pd->GetPointData()->GetArray("w"));
  wf->SetName("wf");
  pd->GetPointData()->AddArray(wf);
  vtkNew<vtkWeightedTransformFilter> vtk;
  vtk->SetInputData(pd);
  vtk->SetNumberOfTransforms(4);
  std::vector<vtkSmartPointer<vtkTransform>> transforms;
  for (int i = 0; i < 4; ++i)
  {
    transforms.push_back(vtkSmartPointer<vtkTransform>::New());
    transforms.back()->SetMatrix(toVtk(s.probes[i]));
    vtk->SetTransform(transforms.back(), i);
  }
  vtk->SetWeightArray("wf");
  vtk->Update();
  vtkSmartPointer<vtkProbeDeformerLCT> ours = deformerFor(s, vtkProbeDeformerLCT::LINEAR);
  ours->SetWeightArrayName("wf");
  ours->SetInputData(pd);
  ours->Update();
  auto* a = vtkPointSet::SafeDownCast(vtk->GetOutputDataObject(0));
  auto* b = vtkPointSet::SafeDownCast(ours->GetOutputDataObject(0));
  ASSERT_EQ(a->GetNumberOfPoints(), b->GetNumberOfPoints());
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    EXPECT_LT((pointOf(a, i) - pointOf(b, i)).norm(), 1e-5 * (1.0 + pointOf(a, i).norm())) << i;
  }
}

TEST(ProbeDeformer, ProbesAtRestThroughTheFilterLeaveEveryPointBitForBit)
{
  // Rest matrices that turn and move (not only translations): current * rest^-1 rounded to an
  // ulp of I and moved most points by ~1e-15; a probe whose current matrix equals its rest one
  // (the same object, or an equal one) is now taken as I.
  RandomTransforms r(23);
  const Scene s = randomScene(r, TransformClass::Rigid, 3, 200);
  vtkSmartPointer<vtkPolyData> pd = toPolyData(s);
  for (int mode = vtkProbeDeformerLCT::POLAR; mode <= vtkProbeDeformerLCT::DUAL_QUATERNION; ++mode)
  {
    vtkNew<vtkProbeDeformerLCT> deformer;
    deformer->SetInputData(pd);
    ASSERT_EQ(deformer->SetBlendMode(mode), 1);
    std::vector<vtkSmartPointer<vtkMatrix4x4>> matrices;
    for (int k = 0; k < 3; ++k)
    {
      auto rest = vtkSmartPointer<vtkMatrix4x4>::New();
      const Eigen::Matrix4d m = r.Affine(TransformClass::Rigid); // turned and moved
      for (int i = 0; i < 4; ++i)
      {
        for (int j = 0; j < 4; ++j)
        {
          rest->SetElement(i, j, m(i, j));
        }
      }
      auto equal = vtkSmartPointer<vtkMatrix4x4>::New();
      equal->DeepCopy(rest);
      ASSERT_GE(deformer->AddProbe(k == 0 ? rest.Get() : equal.Get(), rest), 0);
      matrices.insert(matrices.end(), { rest, equal });
    }
    ASSERT_EQ(deformer->GetExecutive()->Update(), 1);
    auto* out = vtkPointSet::SafeDownCast(deformer->GetOutputDataObject(0))->GetPoints();
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
    {
      double a[3], b[3];
      pd->GetPoint(i, a);
      out->GetPoint(i, b);
      ASSERT_TRUE(a[0] == b[0] && a[1] == b[1] && a[2] == b[2])
        << "mode " << mode << " point " << i;
    }
  }
}

TEST(ProbeDeformer, MultithreadedResultEqualsSerialResult)
{
  RandomTransforms r(19);
  const Scene s = randomScene(r, TransformClass::GeneralAffine, 4, 50000);
  vtkSmartPointer<vtkPolyData> pd = toPolyData(s);
  for (int mode = vtkProbeDeformerLCT::POLAR; mode <= vtkProbeDeformerLCT::DUAL_QUATERNION; ++mode)
  {
    vtkSmartPointer<vtkProbeDeformerLCT> serial = deformerFor(s, mode);
    vtkSmartPointer<vtkProbeDeformerLCT> threaded = deformerFor(s, mode);
    serial->SetSerialThreshold(VTK_ID_MAX);
    threaded->SetSerialThreshold(0);
    serial->SetInputData(pd);
    threaded->SetInputData(pd);
    serial->Update();
    threaded->Update();
    auto* a = vtkPointSet::SafeDownCast(serial->GetOutputDataObject(0))->GetPoints();
    auto* b = vtkPointSet::SafeDownCast(threaded->GetOutputDataObject(0))->GetPoints();
    ASSERT_EQ(a->GetNumberOfPoints(), 50000);
    for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
    {
      double pa[3], pb[3];
      a->GetPoint(i, pa);
      b->GetPoint(i, pb);
      ASSERT_TRUE(pa[0] == pb[0] && pa[1] == pb[1] && pa[2] == pb[2]) << mode << " " << i;
    }
  }
}

// Linear normalisation is by ratios: weights whose sum overflows (1e308 each) or whose sum's
// inverse does (subnormal weights) were refused with the cause "weights do not sum to a positive
// number"; they deform exactly as the same ratios near 1 do. Inf or NaN among them still fails.
TEST(ProbeDeformer, LinearNormalisationOfHugeAndSubnormalWeights)
{
  RandomTransforms r(23);
  Scene s = randomScene(r, TransformClass::GeneralAffine, 3, 40);
  // Each point's largest weight 1, so that 1.5e308 times them overflows their sum.
  std::vector<double> unit = s.weights;
  for (std::size_t i = 0; i < s.points.size(); ++i)
  {
    const auto row = unit.begin() + static_cast<std::ptrdiff_t>(3 * i);
    const double top = *std::max_element(row, row + 3);
    std::transform(row, row + 3, row, [top](double w) { return w / top; });
  }
  const auto deformed = [&](double scale) {
    for (std::size_t i = 0; i < unit.size(); ++i)
    {
      s.weights[i] = unit[i] * scale;
    }
    vtkSmartPointer<vtkProbeDeformerLCT> f = deformerFor(s, vtkProbeDeformerLCT::POLAR);
    vtkNew<lct_test::ErrorCounter> errors;
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    f->SetInputData(toPolyData(s));
    f->Update();
    EXPECT_EQ(errors->Count, 0) << scale << ": " << errors->Last;
    std::vector<Eigen::Vector3d> out;
    auto* d = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
    for (vtkIdType i = 0; d && i < d->GetNumberOfPoints(); ++i)
    {
      out.push_back(pointOf(d, i));
    }
    return out;
  };
  const std::vector<Eigen::Vector3d> reference = deformed(1.0);
  ASSERT_EQ(unit.size(), 3 * s.points.size());
  ASSERT_EQ(reference.size(), s.points.size());
  for (const double scale : { 0x1.8p1023, 0x1p-1030, 1e-310 / 3.0 })
  {
    const std::vector<Eigen::Vector3d> out = deformed(scale);
    ASSERT_EQ(out.size(), reference.size()) << scale;
    for (std::size_t i = 0; i < out.size(); ++i)
    {
      EXPECT_LE((out[i] - reference[i]).norm(), 1e-12 * (1.0 + reference[i].norm()))
        << scale << " " << i;
    }
  }
  // The core: exact ratios, and non-finite weights refused.
  double huge[] = { 1e308, 1e308, 1e308 };
  ASSERT_EQ(lct::normalizeWeights(lct::WeightNormalization::Linear, huge, 3), lct::Status::Ok);
  for (const double w : huge)
  {
    EXPECT_EQ(w, 1.0 / 3.0);
  }
  double tiny[] = { 1e-320, 3e-320 };
  ASSERT_EQ(lct::normalizeWeights(lct::WeightNormalization::Linear, tiny, 2), lct::Status::Ok);
  EXPECT_NEAR(tiny[0], 0.25, 1e-3); // 1e-320 and 3e-320 are subnormals: ratios to ~4 digits
  EXPECT_NEAR(tiny[1], 0.75, 1e-3);
  for (const double bad :
    { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::quiet_NaN() })
  {
    double weights[] = { 1e308, 1e308, bad };
    EXPECT_EQ(lct::normalizeWeights(lct::WeightNormalization::Linear, weights, 3),
      lct::Status::InvalidArgument)
      << bad;
  }
}

TEST(ProbeDeformer, WeightAndIndexArraysOfEveryTypeGiveTheSameResult)
{
  RandomTransforms r(20);
  Scene s = randomScene(r, TransformClass::Rigid, 4, 64);
  // Two slots per point: probes (i % 4) and ((i + 1) % 4), weights 0.25 and 0.75 (exact in
  // every real type and in uchar as 64 and 192 after normalisation).
  vtkSmartPointer<vtkPolyData> pd = toPolyData(s);
  const auto fill = [&](vtkDataArray* a, const char* name, bool isIndex) {
    a->SetName(name);
    a->SetNumberOfComponents(2);
    a->SetNumberOfTuples(64);
    for (vtkIdType i = 0; i < 64; ++i)
    {
      if (isIndex)
      {
        a->SetComponent(i, 0, static_cast<double>(i % 4));
        a->SetComponent(i, 1, static_cast<double>((i + 1) % 4));
      }
      else
      {
        a->SetComponent(i, 0, 64);
        a->SetComponent(i, 1, 192);
      }
    }
    pd->GetPointData()->AddArray(a);
  };
  std::vector<vtkSmartPointer<vtkDataArray>> weightArrays = { vtkSmartPointer<vtkFloatArray>::New(),
    vtkSmartPointer<vtkDoubleArray>::New(), vtkSmartPointer<vtkIntArray>::New(),
    vtkSmartPointer<vtkUnsignedCharArray>::New() };
  std::vector<vtkSmartPointer<vtkDataArray>> indexArrays = {
    vtkSmartPointer<vtkUnsignedShortArray>::New(), vtkSmartPointer<vtkIntArray>::New(),
    vtkSmartPointer<vtkLongLongArray>::New(), vtkSmartPointer<vtkUnsignedCharArray>::New(),
    vtkSmartPointer<vtkFloatArray>::New()
  };
  for (std::size_t k = 0; k < weightArrays.size(); ++k)
  {
    fill(weightArrays[k], ("w" + std::to_string(k)).c_str(), false);
  }
  for (std::size_t k = 0; k < indexArrays.size(); ++k)
  {
    fill(indexArrays[k], ("i" + std::to_string(k)).c_str(), true);
  }
  std::vector<Eigen::Vector3d> reference;
  for (std::size_t wk = 0; wk < weightArrays.size(); ++wk)
  {
    for (std::size_t ik = 0; ik < indexArrays.size(); ++ik)
    {
      vtkSmartPointer<vtkProbeDeformerLCT> f = deformerFor(s, vtkProbeDeformerLCT::POLAR);
      f->SetWeightArrayName(("w" + std::to_string(wk)).c_str());
      f->SetTransformIndexArrayName(("i" + std::to_string(ik)).c_str());
      f->SetInputData(pd);
      ASSERT_EQ(f->GetExecutive()->Update(), 1);
      auto* out = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
      for (vtkIdType i = 0; i < 64; ++i)
      {
        if (reference.size() < 64)
        {
          // The first combination against the core directly.
          const auto prepared = lct::prepareProbes(s.probes, s.centres, {}, lct::BlendMode::Polar);
          const double w[2] = { 0.25, 0.75 };
          const std::int32_t idx[2] = { static_cast<std::int32_t>(i % 4),
            static_cast<std::int32_t>((i + 1) % 4) };
          lct::PointMap map;
          ASSERT_EQ(lct::blendAtPoint(prepared.set, w, idx, 2, map), lct::Status::Ok);
          reference.push_back(map.apply(s.points[i]));
        }
        EXPECT_LT((pointOf(out, i) - reference[i]).norm(), 1e-12) << wk << " " << ik << " " << i;
      }
    }
  }
}

TEST(ProbeDeformer, AProbeDrivenThroughThreePiTwistsByThreePi)
{
  // Two probes on the z axis: the bottom one fixed, the top one turned step by step to 3 pi.
  // A point at height 7.5 has inverse-distance weights w (top) and 1 - w and turns by 3 pi w
  // about the axis; without ConsistentRotation the principal log (pi) turns it by pi w.
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  pts->InsertNextPoint(1, 0, 7.5);
  pd->SetPoints(pts);
  const double toTop = 1.0 / std::hypot(1.0, 2.5), toBottom = 1.0 / std::hypot(1.0, 7.5);
  const double w = toTop / (toTop + toBottom);
  for (bool consistent : { true, false })
  {
    vtkNew<vtkTransform> top, topRest, bottom, bottomRest;
    topRest->Translate(0, 0, 10);
    top->Translate(0, 0, 10);
    vtkNew<vtkProbeDeformerLCT> f;
    f->AddProbe(top, topRest);
    f->AddProbe(bottom, bottomRest);
    f->SetConsistentRotation(consistent);
    f->SetInputData(pd);
    for (int step = 1; step <= 12; ++step)
    {
      top->RotateZ(45.0);
      ASSERT_EQ(f->GetExecutive()->Update(), 1) << step;
    }
    double log[3];
    ASSERT_EQ(f->GetProbeRotationLog(0, log), 1);
    const Eigen::Vector3d p = pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 0);
    const double turn = (consistent ? 3 * kPi : std::abs(log[2])) * w * (log[2] < 0 ? -1 : 1);
    EXPECT_NEAR(std::abs(log[2]), consistent ? 3 * kPi : kPi, 1e-9);
    EXPECT_NEAR(p.x(), std::cos(turn), 1e-9) << consistent;
    EXPECT_NEAR(p.y(), std::sin(turn), 1e-9) << consistent;
    EXPECT_NEAR(p.z(), 7.5, 1e-9);
  }
}

TEST(ProbeDeformer, AnExplicitRotationReferenceNeedsNoHistory)
{
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(1, 0, 0);
  pd->SetPoints(pts);
  vtkNew<vtkTransform> turned;
  turned->RotateZ(540.0);
  vtkNew<vtkTransform> fixed;
  vtkNew<vtkProbeDeformerLCT> f;
  f->AddProbe(turned);
  f->AddProbe(fixed);
  const double reference[3] = { 0, 0, 3 * kPi };
  ASSERT_EQ(f->SetProbeRotationReference(0, reference), 1);
  f->SetInputData(pd);
  ASSERT_EQ(f->GetExecutive()->Update(), 1);
  // Both centres are at the origin: inverse distance gives the point equal weights.
  double log[3];
  ASSERT_EQ(f->GetProbeRotationLog(0, log), 1);
  EXPECT_NEAR(log[2], 3 * kPi, 1e-9);
}

TEST(ProbeDeformer, MTimeFollowsTheProbesAndThePipelineReexecutes)
{
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->InsertNextPoint(1, 2, 3);
  pd->SetPoints(pts);
  vtkNew<vtkTransform> t;
  vtkNew<vtkProbeDeformerLCT> f;
  f->AddProbe(t);
  f->SetInputData(pd);
  f->Update();
  const vtkMTimeType before = f->GetMTime();
  t->Translate(1, 0, 0);
  EXPECT_GT(f->GetMTime(), before);
  f->Update();
  EXPECT_NEAR(pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 0).x(), 2.0, 1e-15);
  // A vtkMatrix4x4 and a vtkProp3D as probes.
  vtkNew<vtkMatrix4x4> m;
  m->SetElement(1, 3, 5.0);
  ASSERT_EQ(f->SetProbe(0, m, nullptr), 1);
  f->Update();
  EXPECT_NEAR(pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 0).y(), 7.0, 1e-15);
  m->SetElement(1, 3, 6.0);
  f->Update();
  EXPECT_NEAR(pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 0).y(), 8.0, 1e-15);
}

TEST(ProbeDeformer, WorksOnAnyPointSetAndCarriesVectors)
{
  vtkNew<vtkUnstructuredGrid> grid;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToFloat();
  pts->InsertNextPoint(1, 0, 0);
  pts->InsertNextPoint(0, 1, 0);
  grid->SetPoints(pts);
  vtkNew<vtkFloatArray> v;
  v->SetName("velocity");
  v->SetNumberOfComponents(3);
  v->InsertNextTuple3(1, 0, 0);
  v->InsertNextTuple3(0, 1, 0);
  grid->GetPointData()->AddArray(v);
  vtkNew<vtkTransform> t;
  t->RotateZ(90);
  vtkNew<vtkProbeDeformerLCT> f;
  f->AddProbe(t);
  f->AddVectorArrayName("velocity");
  f->SetInputData(grid);
  ASSERT_EQ(f->GetExecutive()->Update(), 1);
  auto* out = vtkUnstructuredGrid::SafeDownCast(f->GetOutputDataObject(0));
  ASSERT_NE(out, nullptr);
  EXPECT_EQ(out->GetPoints()->GetDataType(), VTK_FLOAT);
  EXPECT_LT((pointOf(out, 0) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-7);
  double vel[3];
  out->GetPointData()->GetArray("velocity")->GetTuple(0, vel);
  EXPECT_LT((Eigen::Vector3d(vel[0], vel[1], vel[2]) - Eigen::Vector3d(0, 1, 0)).norm(), 1e-7);
}

namespace
{
/// Runs f on pd, expecting failure with an error containing `needle`, and the output to be the
/// last valid one (`expectedPoints` points, first point `first`).
void expectRefused(vtkProbeDeformerLCT* f, const std::string& needle, vtkIdType expectedPoints)
{
  vtkNew<lct_test::ErrorCounter> errors;
  const unsigned long tag = f->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<lct_test::ErrorCounter> executiveErrors;
  f->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
  EXPECT_EQ(f->GetExecutive()->Update(), 0) << needle;
  EXPECT_GE(errors->Count, 1) << needle;
  EXPECT_NE(errors->Last.find(needle), std::string::npos) << errors->Last;
  auto* out = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
  EXPECT_EQ(out->GetNumberOfPoints(), expectedPoints) << needle;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    EXPECT_TRUE(pointOf(out, i).allFinite());
  }
  f->RemoveObserver(tag);
}
} // namespace

TEST(ProbeDeformer, BadInputIsRefusedAndTheLastOutputKept)
{
  RandomTransforms r(21);
  Scene s = randomScene(r, TransformClass::Rigid, 2, 10);
  vtkSmartPointer<vtkPolyData> pd = toPolyData(s);
  vtkSmartPointer<vtkProbeDeformerLCT> f = deformerFor(s, vtkProbeDeformerLCT::POLAR);
  f->SetInputData(pd);

  // Before any valid execution the output is empty.
  vtkNew<vtkProbeDeformerLCT> none;
  none->SetInputData(pd);
  expectRefused(none, "no probes", 0);
  expectRefused(none, "no probes", 0);

  ASSERT_EQ(f->GetExecutive()->Update(), 1);
  const Eigen::Vector3d good = pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 3);

  vtkNew<vtkMatrix4x4> bad;
  bad->SetElement(0, 0, std::nan(""));
  ASSERT_EQ(f->SetProbe(1, bad, nullptr), 1);
  expectRefused(f, "probe 1: the current matrix is invalid", 10);
  // Updating again without a change fails again (the pipeline would otherwise count the failed
  // execution as up to date and return 1 on the restored output).
  expectRefused(f, "probe 1: the current matrix is invalid", 10);
  bad->SetElement(0, 0, 1.0);
  bad->SetElement(3, 0, 0.5);
  expectRefused(f, "probe 1: the current matrix is invalid", 10);
  bad->SetElement(3, 0, 0.0);
  bad->SetElement(0, 0, -1.0);
  expectRefused(f, "determinant", 10);
  bad->SetElement(0, 0, 0.0);
  expectRefused(f, "probe 1", 10);
  // A MatrixLog probe without a real logarithm (a half turn); Polar takes it.
  vtkNew<vtkTransform> halfTurn;
  halfTurn->RotateZ(180.0);
  ASSERT_EQ(f->SetProbe(1, halfTurn, nullptr), 1);
  f->SetBlendModeToMatrixLog();
  expectRefused(f, "MatrixLog mode", 10);
  f->SetBlendModeToPolar();
  ASSERT_EQ(f->GetExecutive()->Update(), 1);
  ASSERT_EQ(f->SetProbe(
              1, toVtk(s.probes[1] * translation(s.centres[1])), toVtk(translation(s.centres[1]))),
    1);
  ASSERT_EQ(f->GetExecutive()->Update(), 1);
  EXPECT_EQ(pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 3), good);

  // Weight arrays.
  auto* w = vtkDoubleArray::SafeDownCast(pd->GetPointData()->GetArray("w"));
  w->SetComponent(4, 0, std::nan(""));
  pd->Modified();
  expectRefused(f, "point 4 has weights", 10);
  w->SetComponent(4, 0, 1.0);
  w->SetComponent(4, 1, -1.0);
  pd->Modified();
  expectRefused(f, "cannot divide", 10);
  w->SetComponent(4, 1, 0.5);
  pd->Modified();
  f->SetWeightArrayName("missing");
  expectRefused(f, "no point-data array named 'missing'", 10);
  f->SetWeightArrayName("w");
  vtkNew<vtkIntArray> idx;
  idx->SetName("idx");
  idx->SetNumberOfComponents(1); // the weights have 2
  idx->SetNumberOfTuples(10);
  idx->FillValue(0);
  pd->GetPointData()->AddArray(idx);
  f->SetTransformIndexArrayName("idx");
  expectRefused(f, "must match", 10);
  vtkNew<vtkIntArray> idx2;
  idx2->SetName("idx2");
  idx2->SetNumberOfComponents(2);
  idx2->SetNumberOfTuples(10);
  idx2->FillValue(1);
  idx2->SetComponent(7, 1, 2); // only probes 0 and 1 exist
  pd->GetPointData()->AddArray(idx2);
  f->SetTransformIndexArrayName("idx2");
  expectRefused(f, "point 7 slot 1 holds 2", 10);
  f->SetTransformIndexArrayName(nullptr);
  vtkNew<vtkDoubleArray> three;
  three->SetName("three");
  three->SetNumberOfComponents(3);
  three->SetNumberOfTuples(10);
  three->FillValue(1.0);
  pd->GetPointData()->AddArray(three);
  f->SetWeightArrayName("three");
  expectRefused(f, "3 components for 2 probes", 10);
  f->SetWeightArrayName("w");
  ASSERT_EQ(f->GetExecutive()->Update(), 1);

  // Distance-weight settings.
  f->SetWeightModeToInverseDistance();
  f->SetExponent(0.0);
  expectRefused(f, "exponent", 10);
  f->SetExponent(std::nan(""));
  expectRefused(f, "exponent", 10);
  f->SetExponent(1.0);
  EXPECT_EQ(f->SetProbeRadius(0, -1.0), 0);
  EXPECT_EQ(f->SetProbeRadius(0, std::numeric_limits<double>::infinity()), 0);
  EXPECT_EQ(f->SetProbeRadius(5, 1.0), 0);
  EXPECT_EQ(f->GetProbeRadius(0), 8.0);

  // Probe objects.
  vtkNew<vtkPolyData> notAProbe;
  EXPECT_EQ(f->AddProbe(notAProbe), -1);
  EXPECT_EQ(f->AddProbe(nullptr), -1);
  EXPECT_EQ(f->SetProbe(9, halfTurn, nullptr), 0);
  EXPECT_EQ(f->GetNumberOfProbes(), 2);
  const double nanReference[3] = { std::nan(""), 0, 0 };
  EXPECT_EQ(f->SetProbeRotationReference(0, nanReference), 0);

  // A result that overflows: a huge stretch on a far point.
  vtkNew<vtkTransform> huge;
  huge->Scale(1e300, 1e300, 1e300);
  ASSERT_EQ(f->SetProbe(0, huge, nullptr), 1);
  {
    vtkNew<vtkPolyData> far;
    vtkNew<vtkPoints> farPoints;
    farPoints->SetDataTypeToDouble(); // (a float point of 1e300 is Inf)
    farPoints->InsertNextPoint(1e300, 0, 0);
    far->SetPoints(farPoints);
    vtkNew<vtkProbeDeformerLCT> g;
    g->AddProbe(huge);
    g->SetInputData(far);
    expectRefused(g, "cannot be deformed", 0);
    // A NaN or Inf input point is named as such, whichever check it fails first (it read
    // "invalid argument (count, index or size)" or "out of the range of double precision").
    for (const int mode : { vtkProbeDeformerLCT::INVERSE_DISTANCE, vtkProbeDeformerLCT::CUTOFF })
    {
      ASSERT_EQ(g->SetWeightMode(mode), 1);
      farPoints->SetPoint(0, std::nan(""), 0, 0);
      farPoints->Modified();
      expectRefused(g, "point 0 is (nan, 0, 0): an input point must be finite", 0);
      farPoints->SetPoint(0, 0, std::numeric_limits<double>::infinity(), 0);
      farPoints->Modified();
      expectRefused(g, "an input point must be finite", 0);
    }
  }
  // A stretch of 1e160 at the point itself: its normal stays a unit normal, and a vector array
  // it would stretch beyond double is refused, not written as Inf.
  {
    vtkNew<vtkPolyData> one;
    vtkNew<vtkPoints> onePoint;
    onePoint->InsertNextPoint(0, 0, 0);
    one->SetPoints(onePoint);
    vtkNew<vtkDoubleArray> normal;
    normal->SetNumberOfComponents(3);
    normal->InsertNextTuple3(0.6, 0.0, 0.8);
    one->GetPointData()->SetNormals(normal);
    vtkNew<vtkTransform> stretch;
    stretch->Scale(1e160, 2e160, 1e160);
    vtkNew<vtkProbeDeformerLCT> g;
    g->AddProbe(stretch);
    g->SetInputData(one);
    ASSERT_EQ(g->GetExecutive()->Update(), 1);
    double n[3];
    vtkPolyData::SafeDownCast(g->GetOutputDataObject(0))
      ->GetPointData()
      ->GetNormals()
      ->GetTuple(0, n);
    // M^-T (0.6, 0, 0.8) is parallel to it (the cofactor's entries are 2e320 and 1e320).
    EXPECT_NEAR(n[0], 0.6, 1e-15);
    EXPECT_EQ(n[1], 0.0);
    EXPECT_NEAR(n[2], 0.8, 1e-15);
    vtkNew<vtkDoubleArray> vectors;
    vectors->SetNumberOfComponents(3);
    vectors->InsertNextTuple3(1e300, 0.0, 0.0);
    one->GetPointData()->SetVectors(vectors);
    expectRefused(g, "a vector array carried with it", 1);
  }

  // DualQuaternion with stretched probes and unnormalised weights summing to 0: no blend of the
  // stretches (sum w S / sum w); refused, the last output kept.
  {
    vtkNew<vtkPolyData> two;
    vtkNew<vtkPoints> twoPoints;
    twoPoints->InsertNextPoint(1, 2, 3);
    twoPoints->InsertNextPoint(4, 5, 6);
    two->SetPoints(twoPoints);
    vtkNew<vtkDoubleArray> w;
    w->SetName("w");
    w->SetNumberOfComponents(2);
    w->InsertNextTuple2(0.25, 0.75);
    w->InsertNextTuple2(0.25, 0.75);
    two->GetPointData()->AddArray(w);
    vtkNew<vtkTransform> stretched, turned;
    stretched->Scale(2, 1, 0.5);
    turned->RotateX(30);
    vtkNew<vtkProbeDeformerLCT> g;
    g->AddProbe(stretched);
    g->AddProbe(turned);
    g->SetInputData(two);
    g->SetBlendModeToDualQuaternion();
    g->SetWeightModeToPointData();
    g->SetWeightArrayName("w");
    g->SetNormalizationToNone();
    ASSERT_EQ(g->GetExecutive()->Update(), 1);
    w->SetTuple2(1, 2.0, -2.0);
    w->Modified();
    expectRefused(g, "weights sum to 0", 2);
    // Polar: unnormalised weights that wind the turn beyond what double resolves.
    g->SetBlendModeToPolar();
    w->SetTuple2(1, 1e100, 1e100);
    w->Modified();
    expectRefused(g, "wind the blended turn", 2);
  }
}

TEST(ProbeDeformer, AShrinkBeyondEightDigitsIsRefusedNotRoundedAway)
{
  // One probe scaling by s: every point must come out as s p. Points move as p + (A - I) p, with
  // round-off on the input's scale: s = 1e-3 keeps 13 digits; s = 1e-15 put points 4 % off and
  // s = 1e-20 at 0, with Update returning 1. Now a shrink by more than 1e8 is refused.
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  points->InsertNextPoint(0, 0, 1.1);
  points->InsertNextPoint(3, 4, 5);
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  for (const int mode : { vtkProbeDeformerLCT::LINEAR, vtkProbeDeformerLCT::POLAR,
         vtkProbeDeformerLCT::DUAL_QUATERNION })
  {
    for (const double scale : { 1e-3, 1e-7, 1e-9, 1e-15, 1e-20, 1e-300 })
    {
      vtkNew<vtkProbeDeformerLCT> f;
      f->SetBlendMode(mode);
      vtkNew<vtkMatrix4x4> m;
      for (int k = 0; k < 3; ++k)
      {
        m->SetElement(k, k, scale);
      }
      ASSERT_GE(f->AddProbe(m), 0);
      f->SetInputData(mesh);
      if (scale >= 1e-8)
      {
        ASSERT_EQ(f->GetExecutive()->Update(), 1) << mode << " " << scale;
        const Eigen::Vector3d got =
          pointOf(vtkPointSet::SafeDownCast(f->GetOutputDataObject(0)), 3);
        EXPECT_LT((got - scale * Eigen::Vector3d(3, 4, 5)).norm() / (scale * std::sqrt(50.0)), 1e-7)
          << mode << " " << scale;
      }
      else
      {
        expectRefused(f, "every probe shrinks", 0);
      }
    }
  }
}

TEST(ProbeDeformer, TheShrinkMessageBoundsTheStretchEvenWhereItsSquareUnderflows)
{
  // Audit: Scale(1e-200) was refused with "largest stretch at most 0": the bound printed was
  // ||L||_F, whose sum of squares underflows. Now it is sqrt(3) s, at least s and not 0.
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(1, 2, 3);
  mesh->SetPoints(points);
  for (const double scale : { 1e-9, 1e-200, 1e-300 })
  {
    vtkNew<vtkProbeDeformerLCT> f;
    vtkNew<vtkMatrix4x4> shrink;
    for (int k = 0; k < 3; ++k)
    {
      shrink->SetElement(k, k, scale);
    }
    ASSERT_GE(f->AddProbe(shrink), 0);
    f->SetInputData(mesh);
    vtkNew<lct_test::ErrorCounter> errors;
    f->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<lct_test::ErrorCounter> executiveErrors;
    f->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveErrors);
    EXPECT_EQ(f->GetExecutive()->Update(), 0) << scale;
    const std::string key = "largest stretch at most ";
    const std::size_t at = errors->Last.find(key);
    ASSERT_NE(at, std::string::npos) << errors->Last;
    const double bound = std::strtod(errors->Last.c_str() + at + key.size(), nullptr);
    EXPECT_GE(bound, scale) << errors->Last;
    EXPECT_LE(bound, 1.7320508075688774 * scale * (1.0 + 1e-12)) << errors->Last;
  }
}

TEST(ProbeDeformer, ATwistedCylinderKeepsItsRadiusExceptUnderLinearBlending)
{
  // A cylinder of radius 1 along z in [0, 10]; the top probe turned 180 degrees about z. At
  // mid-height the weights are 1/2 each: LBS averages R(180) and I, which collapses the section
  // to |cos 90| = 0; Polar and DQS turn it by 90 degrees and keep the radius.
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToDouble();
  for (int a = 0; a < 16; ++a)
  {
    pts->InsertNextPoint(std::cos(a * kPi / 8), std::sin(a * kPi / 8), 5.0);
  }
  pd->SetPoints(pts);
  const std::pair<int, double> expected[] = { { vtkProbeDeformerLCT::POLAR, 1.0 },
    { vtkProbeDeformerLCT::DUAL_QUATERNION, 1.0 }, { vtkProbeDeformerLCT::LINEAR, 0.0 } };
  for (const auto& [mode, radius] : expected)
  {
    vtkNew<vtkTransform> bottom, top, topRest;
    topRest->Translate(0, 0, 10);
    top->Translate(0, 0, 10);
    top->RotateZ(180);
    vtkNew<vtkProbeDeformerLCT> f;
    f->AddProbe(bottom);
    f->AddProbe(top, topRest);
    f->SetBlendMode(mode);
    f->SetInputData(pd);
    ASSERT_EQ(f->GetExecutive()->Update(), 1);
    auto* out = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
    for (vtkIdType i = 0; i < 16; ++i)
    {
      EXPECT_NEAR(pointOf(out, i).head<2>().norm(), radius, 1e-12) << mode << " " << i;
      EXPECT_NEAR(pointOf(out, i).z(), 5.0, 1e-12);
    }
  }
}

// Audit (session 28): a NaN in a carried normal was reported as "the result is out of the range
// of double precision (it overflows, or a stretch underflows to zero)".
TEST(ProbeDeformer, ANaNInACarriedNormalIsNamed)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  mesh->SetPoints(points);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->InsertNextTuple3(0, 0, 1);
  normals->InsertNextTuple3(std::nanf(""), 0, 0);
  mesh->GetPointData()->SetNormals(normals);
  vtkNew<vtkProbeDeformerLCT> deformer;
  vtkNew<lct_test::ErrorCounter> errors;
  deformer->AddObserver(vtkCommand::ErrorEvent, errors);
  deformer->SetInputData(mesh);
  vtkNew<vtkTransform> turn;
  turn->RotateZ(30);
  deformer->AddProbe(turn);
  EXPECT_EQ(deformer->GetExecutive()->Update(), 0);
  EXPECT_NE(errors->Last.find("point 1's vector in the array 'Normals' is (nan, 0, 0): a carried "
                              "normal or vector must be finite"),
    std::string::npos)
    << errors->Last;
}

// Audit (session 29): current * rest^-1 was a plain product with the rest's inverse, which
// cancels for an ill-conditioned rest (8 % off at condition 1e15, 2e-4 at 1e13, status 1), and
// rest matrices were not checked for condition. The step now comes from exact minors, and a rest
// beyond the module's condition limit (1e13) is refused.
TEST(ProbeDeformer, IllConditionedRestMatricesAreAccurateOrRefused)
{
  lct_test::RandomTransforms random(4242);
  for (const double condition : { 1e6, 1e10, 1e12, 1e15 })
  {
    const Eigen::Matrix3d r = random.Rotation(), q = random.Rotation();
    Eigen::Matrix4d rest = Eigen::Matrix4d::Identity();
    rest.topLeftCorner<3, 3>() =
      r * Eigen::Vector3d(1.0, 0.5, 1.0 / condition).asDiagonal() * q.transpose();
    rest.topRightCorner<3, 1>() = Eigen::Vector3d(0.1, 0.2, 0.3);
    Eigen::Matrix4d current = rest;
    current.topLeftCorner<3, 3>() *= 2.0; // exact: current rest^-1 = [2 I, -t]
    vtkNew<vtkMatrix4x4> restMatrix, currentMatrix;
    lct_test::toVtk(rest, restMatrix);
    lct_test::toVtk(current, currentMatrix);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->InsertNextPoint(1, 1, 1);
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(points);
    vtkNew<vtkProbeDeformerLCT> deformer;
    vtkNew<lct_test::ErrorCounter> errors;
    deformer->AddObserver(vtkCommand::ErrorEvent, errors);
    deformer->SetInputData(mesh);
    deformer->AddProbe(currentMatrix, restMatrix);
    const int ok = deformer->GetExecutive()->Update();
    if (condition > 1e13)
    {
      EXPECT_EQ(ok, 0) << condition;
      EXPECT_NE(errors->Last.find("too ill-conditioned to invert"), std::string::npos)
        << errors->Last;
      continue;
    }
    ASSERT_EQ(ok, 1) << condition << ": " << errors->Last;
    double p[3];
    deformer->GetOutput()->GetPoint(0, p);
    EXPECT_LT((Eigen::Vector3d(p[0], p[1], p[2]) - Eigen::Vector3d(1.9, 1.8, 1.7)).norm(), 1e-12)
      << condition;
  }
}

// Audit (session 30): a step current rest^-1 whose conditions compound beyond the limit, rest and
// current each within it, was reported by the blend with another cause (two random keys of
// condition 1e12: "a reflection", its computed determinant rounded negative), and a step beyond
// the double range (current 1e300 I, rest 1e-300 I, both valid) as "NaN or Inf": each now
// names the step and its cause.
TEST(ProbeDeformer, AStepBeyondTheLimitsNamesTheStep)
{
  // Refused in every blend mode, with the same cause (the text after the object's address, which
  // differs between the two filters) in each: the last mode's message is returned.
  const auto run = [](const Eigen::Matrix4d& current, const Eigen::Matrix4d& rest,
                     std::string& message) {
    vtkNew<vtkMatrix4x4> restMatrix, currentMatrix;
    lct_test::toVtk(rest, restMatrix);
    lct_test::toVtk(current, currentMatrix);
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(1, 1, 1);
    vtkNew<vtkPolyData> mesh;
    mesh->SetPoints(points);
    for (const int mode : { vtkProbeDeformerLCT::POLAR, vtkProbeDeformerLCT::LINEAR })
    {
      vtkNew<vtkProbeDeformerLCT> deformer;
      vtkNew<lct_test::ErrorCounter> errors;
      deformer->AddObserver(vtkCommand::ErrorEvent, errors);
      deformer->SetInputData(mesh);
      deformer->SetBlendMode(mode);
      deformer->AddProbe(currentMatrix, restMatrix);
      const auto cause = [](const std::string& m) { return m.substr(m.rfind("): ") + 1); };
      if (deformer->GetExecutive()->Update() != 0 ||
        errors->Last.find("): ") == std::string::npos ||
        (!message.empty() && cause(errors->Last) != cause(message)))
      {
        return false;
      }
      message = errors->Last;
    }
    return true;
  };
  std::string message;
  // rest = Ry(90 deg) diag(1, 1, 1e-10) (condition 1e10) and current = diag(1e-6, 1, 1)
  // (condition 1e6), each within the limit: their step diag(1e-6, 1, 1e10) Ry(-90 deg) has
  // condition 1e16. (Random pairs of condition 1e12 gave steps near the limit, on either side
  // of it depending on the build's rounding.)
  Eigen::Matrix4d rest = Eigen::Matrix4d::Identity(), current = Eigen::Matrix4d::Identity();
  rest.topLeftCorner<3, 3>() =
    Eigen::AngleAxisd(0.5 * M_PI, Eigen::Vector3d::UnitY()).toRotationMatrix() *
    Eigen::Vector3d(1.0, 1.0, 1e-10).asDiagonal();
  current.topLeftCorner<3, 3>() = Eigen::Vector3d(1e-6, 1.0, 1.0).asDiagonal();
  EXPECT_TRUE(run(current, rest, message));
  EXPECT_NE(message.find("current rest^-1 is too ill-conditioned to blend"), std::string::npos)
    << message;
  message.clear();
  rest = Eigen::Matrix4d::Identity();
  current = Eigen::Matrix4d::Identity();
  rest.topLeftCorner<3, 3>() *= 1e-300;
  current.topLeftCorner<3, 3>() *= 1e300;
  EXPECT_TRUE(run(current, rest, message));
  EXPECT_NE(message.find("current rest^-1 overflows the double range"), std::string::npos)
    << message;
}
