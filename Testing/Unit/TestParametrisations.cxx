// Both parametrisations of Aff+(3), swept over every transform class (RandomTransforms.h):
// round trips exp(log A) = A and log(exp X) = X, agreement with Eigen's MatrixFunctions, the
// algebraic properties of Alexa 2002 and the subgroup closure of Kaji & Ochiai (condition V).
#include "lct/Affine.h"
#include "lct/Combination.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include "RandomTransforms.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <unsupported/Eigen/MatrixFunctions>

using lct::Parametrisation;
using lct_test::TransformClass;

namespace
{
constexpr int kSamplesPerClass = 100000;

const TransformClass kAllClasses[] = { TransformClass::Rigid, TransformClass::Similarity,
  TransformClass::GeneralAffine, TransformClass::NearSingular, TransformClass::NearHalfTurn,
  TransformClass::BigTranslation, TransformClass::NearIdentity };

/// Whether A's linear part has a real eigenvalue <= 0 or one within `margin` of the negative
/// real axis, by Eigen's iterative eigensolver (independent of our cubic formula).
bool nearNegativeRealAxis(const Eigen::Matrix4d& m, double margin)
{
  Eigen::EigenSolver<Eigen::Matrix3d> es(m.topLeftCorner<3, 3>(), false);
  for (int i = 0; i < 3; ++i)
  {
    const std::complex<double> l = es.eigenvalues()[i];
    if (l.real() <= 0.0 && std::abs(l.imag()) <= margin * std::abs(l))
    {
      return true;
    }
  }
  return false;
}

Eigen::Matrix4d logMatrix(const lct::LogCoords& c)
{
  Eigen::Matrix4d l = Eigen::Matrix4d::Zero();
  l.topLeftCorner<3, 3>() = lct::logLinearPart(c);
  l.topRightCorner<3, 1>() = lct::translationPart(c);
  return l;
}

/// Round-trip tolerance of exp(log A) = A: relative to the condition of the linear part.
double roundTripTolerance(TransformClass c)
{
  return c == TransformClass::NearSingular ? 1e-11 : 1e-13;
}
} // namespace

class EveryClass : public ::testing::TestWithParam<TransformClass>
{
};

TEST_P(EveryClass, PolarRoundTripExpOfLog)
{
  lct_test::RandomTransforms random(100 + static_cast<int>(GetParam()));
  double worst = 0.0;
  for (int i = 0; i < kSamplesPerClass; ++i)
  {
    const Eigen::Matrix4d a = random.Affine(GetParam());
    const auto c = lct::polarLog(a);
    ASSERT_TRUE(c.ok()) << lct::describe(c.status) << "\n" << a;
    const auto back = lct::polarExp(c.value);
    ASSERT_TRUE(back.ok());
    worst = std::max(worst, lct_test::blockError(back.value, a));
  }
  RecordProperty("worst", std::to_string(worst));
  EXPECT_LT(worst, roundTripTolerance(GetParam())) << lct_test::className(GetParam());
}

TEST_P(EveryClass, PolarLogMatchesEigenOnItsFactors)
{
  // Oracle: Eigen's iterative SVD for the polar factors, MatrixFunctions log for each factor.
  lct_test::RandomTransforms random(200 + static_cast<int>(GetParam()));
  double worstRotation = 0.0;
  double worstStretch = 0.0;
  for (int i = 0; i < kSamplesPerClass / 10; ++i)
  {
    const Eigen::Matrix4d a = random.Affine(GetParam());
    const Eigen::Matrix3d linear = a.topLeftCorner<3, 3>();
    Eigen::JacobiSVD<Eigen::Matrix3d> svd(linear, Eigen::ComputeFullU | Eigen::ComputeFullV);
    const Eigen::Matrix3d u = svd.matrixU() * svd.matrixV().transpose();
    const Eigen::Matrix3d s =
      svd.matrixV() * svd.singularValues().asDiagonal() * svd.matrixV().transpose();
    const auto c = lct::polarLog(a);
    ASSERT_TRUE(c.ok());
    const double cond = svd.singularValues()[0] / svd.singularValues()[2];
    worstStretch = std::max(worstStretch,
      (lct::fromSymmetricVector(lct::symmetricPart(c.value)) - s.log()).norm() /
        std::max(1.0, s.log().norm()) / cond);
    // Eigen's log drops the rotation at exactly pi, and near pi the log amplifies round-off
    // by t / sin t: compare up to 3 rad (amplification <= 21).
    if (lct::rotationPart(c.value).norm() < 3.0)
    {
      worstRotation =
        std::max(worstRotation, (lct::hat(lct::rotationPart(c.value)) - u.log()).norm() / cond);
    }
  }
  EXPECT_LT(worstRotation, 1e-13) << lct_test::className(GetParam());
  EXPECT_LT(worstStretch, 1e-13) << lct_test::className(GetParam());
}

TEST_P(EveryClass, MatrixLogRoundTripOrExplicitFailure)
{
  lct_test::RandomTransforms random(300 + static_cast<int>(GetParam()));
  double worst = 0.0;
  int refused = 0;
  int refusedWithoutReason = 0;
  for (int i = 0; i < kSamplesPerClass; ++i)
  {
    const Eigen::Matrix4d a = random.Affine(GetParam());
    const auto c = lct::matrixLog(a);
    if (!c.ok())
    {
      ASSERT_EQ(c.status, lct::Status::NoRealLogarithm);
      ++refused;
      // A refusal must be justified: an eigenvalue on the negative real axis, or within 45
      // degrees of it where the closed form is checked a posteriori.
      if (!nearNegativeRealAxis(a, std::sqrt(0.5)))
      {
        ++refusedWithoutReason;
      }
      continue;
    }
    const auto back = lct::matrixExp(c.value);
    ASSERT_TRUE(back.ok());
    worst = std::max(worst, lct_test::blockError(back.value, a));
  }
  RecordProperty("refused", refused);
  RecordProperty("worst", std::to_string(worst));
  EXPECT_EQ(refusedWithoutReason, 0);
  // What matrixLog guarantees for what it accepts (the a posteriori check near the cut).
  EXPECT_LT(worst, 5e-12) << lct_test::className(GetParam());
  if (GetParam() == TransformClass::NearIdentity)
  {
    EXPECT_EQ(refused, 0);
  }
}

TEST_P(EveryClass, MatrixLogMatchesEigen)
{
  lct_test::RandomTransforms random(400 + static_cast<int>(GetParam()));
  double worstLog = 0.0;
  double worstExp = 0.0;
  for (int i = 0; i < kSamplesPerClass / 10; ++i)
  {
    const Eigen::Matrix4d a = random.Affine(GetParam());
    // Eigen's log silently returns garbage with a negative eigenvalue and may not return
    // on singular input: only hand it matrices well inside its domain.
    // Within 45 degrees of the negative axis the log is ill-conditioned (forward errors of any
    // method grow like 1 / Im): compare there only the round trip (test above).
    if (nearNegativeRealAxis(a, std::sqrt(0.5)))
    {
      continue;
    }
    const auto c = lct::matrixLog(a);
    ASSERT_TRUE(c.ok()) << a;
    // Eigen's log loses digits on a 4x4 matrix with a 1e6 entry; conjugating by
    // D = diag(1, 1, 1, s) scales the translation block of M and of log M alike, so the
    // oracle gets a balanced matrix: log M = D^-1 log(D M D^-1) D.
    const double s = std::max(1.0, a.topRightCorner<3, 1>().norm());
    const Eigen::Vector4d d(1.0, 1.0, 1.0, s);
    const Eigen::Matrix4d balanced = d.asDiagonal() * a * d.cwiseInverse().asDiagonal();
    const Eigen::Matrix4d oracleLog =
      d.cwiseInverse().asDiagonal() * Eigen::Matrix4d(balanced.log()) * d.asDiagonal();
    worstLog = std::max(worstLog, lct_test::blockError(logMatrix(c.value), oracleLog));
    const Eigen::Matrix4d oracleExp = d.cwiseInverse().asDiagonal() *
      Eigen::Matrix4d((d.asDiagonal() * oracleLog * d.cwiseInverse().asDiagonal()).exp()) *
      d.asDiagonal();
    const auto ours = lct::matrixExp(c.value);
    worstExp = std::max(worstExp, lct_test::blockError(ours.value, oracleExp));
  }
  const double tolerance = GetParam() == TransformClass::NearSingular ? 1e-10 : 1e-12;
  EXPECT_LT(worstLog, tolerance) << lct_test::className(GetParam());
  EXPECT_LT(worstExp, tolerance) << lct_test::className(GetParam());
}

INSTANTIATE_TEST_SUITE_P(Aff3, EveryClass, ::testing::ValuesIn(kAllClasses),
  [](const ::testing::TestParamInfo<TransformClass>& info) {
    return lct_test::className(info.param);
  });

TEST(Polar, LogOfExpRoundTrip)
{
  // X = (l, w, Y) with |w| < pi (the principal branch), Y with eigenvalues in [-3, 3].
  lct_test::RandomTransforms random(500);
  double worst = 0.0;
  for (int i = 0; i < kSamplesPerClass; ++i)
  {
    lct::LogCoords x;
    for (int k = 0; k < 12; ++k)
    {
      x[k] = random.Normal();
    }
    lct::translationPart(x) *= 100.0;
    lct::rotationPart(x) = random.Uniform(0.0, 3.1) * random.UnitVector();
    lct::symmetricPart(x) *= 0.5; // stretches of condition up to ~20
    const auto m = lct::polarExp(x);
    ASSERT_TRUE(m.ok());
    const auto back = lct::polarLog(m.value);
    ASSERT_TRUE(back.ok());
    worst = std::max(worst, (back.value - x).norm() / std::max(1.0, x.norm()));
  }
  EXPECT_LT(worst, 1e-13);
}

TEST(MatrixLog, LogOfExpRoundTrip)
{
  // X with the imaginary parts of its eigenvalues below pi (principal branch).
  lct_test::RandomTransforms random(501);
  double worst = 0.0;
  for (int i = 0; i < kSamplesPerClass; ++i)
  {
    lct::LogCoords x;
    for (int k = 0; k < 12; ++k)
    {
      x[k] = 0.5 * random.Normal();
    }
    lct::rotationPart(x) = random.Uniform(0.0, 2.5) * random.UnitVector();
    const Eigen::Matrix3d l = lct::logLinearPart(x);
    Eigen::EigenSolver<Eigen::Matrix3d> es(l, false);
    if (es.eigenvalues().imag().cwiseAbs().maxCoeff() > 3.0)
    {
      continue;
    }
    const auto m = lct::matrixExp(x);
    ASSERT_TRUE(m.ok());
    const auto back = lct::matrixLog(m.value);
    ASSERT_TRUE(back.ok());
    worst = std::max(worst, (back.value - x).norm() / std::max(1.0, x.norm()));
  }
  EXPECT_LT(worst, 1e-12);
}

// ---- Alexa 2002 properties -------------------------------------------------------------------

namespace
{
Eigen::Matrix4d scalarMultiple(double s, const Eigen::Matrix4d& a, Parametrisation p)
{
  const auto c = lct::logarithm(a, p);
  EXPECT_TRUE(c.ok());
  return lct::exponential(s * c.value, p).value;
}

Eigen::Matrix4d sum(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b, Parametrisation p)
{
  const double w[2] = { 1.0, 1.0 };
  const Eigen::Matrix4d keys[2] = { a, b };
  const auto r = lct::combine(w, keys, 2, p);
  EXPECT_TRUE(r.ok());
  return r.value;
}
} // namespace

TEST(Alexa, HalfTimesHalfIsTheWhole)
{
  // (1/2 (.) T)(1/2 (.) T) = T: exact for the matrix log (associative scalar multiple).
  lct_test::RandomTransforms random(600);
  for (int i = 0; i < 10000; ++i)
  {
    const Eigen::Matrix4d t = random.Affine(TransformClass::GeneralAffine);
    if (nearNegativeRealAxis(t, std::sqrt(0.5)))
    {
      continue; // ill-conditioned there: covered by the round-trip guarantee above
    }
    const Eigen::Matrix4d half = scalarMultiple(0.5, t, Parametrisation::MatrixLog);
    ASSERT_LT(lct_test::blockError(half * half, t), 1e-13);
  }
  // Polar: holds where the factors commute (pure rotations, pure stretches); Kaji & Ochiai
  // state that it does not hold in general.
  for (int i = 0; i < 10000; ++i)
  {
    const Eigen::Matrix4d r = lct::makeAffine(random.Rotation(), Eigen::Vector3d::Zero());
    const Eigen::Matrix4d half = scalarMultiple(0.5, r, Parametrisation::Polar);
    ASSERT_LT(lct_test::blockError(half * half, r), 1e-13);
  }
}

TEST(Alexa, SumOfCommutingTransformsIsTheirProduct)
{
  lct_test::RandomTransforms random(601);
  for (int i = 0; i < 10000; ++i)
  {
    // Powers of one transform commute: A = M^a, B = M^b.
    const Eigen::Matrix4d m = random.Affine(TransformClass::GeneralAffine);
    if (nearNegativeRealAxis(m, std::sqrt(0.5)))
    {
      continue; // ill-conditioned there: covered by the round-trip guarantee above
    }
    const auto logM = lct::matrixLog(m);
    ASSERT_TRUE(logM.ok());
    const double a = random.Uniform(-0.5, 0.5);
    const double b = random.Uniform(-0.5, 0.5);
    const Eigen::Matrix4d pa = lct::matrixExp(a * logM.value).value;
    const Eigen::Matrix4d pb = lct::matrixExp(b * logM.value).value;
    ASSERT_LT(lct_test::blockError(sum(pa, pb, Parametrisation::MatrixLog), pa * pb), 1e-13);
    // Polar: coaxial rotations and coaxial stretches commute and add.
    const Eigen::Vector3d axis = random.UnitVector();
    const Eigen::Matrix4d ra =
      lct::makeAffine(lct::expSO3(a * 2.0 * axis), Eigen::Vector3d::Zero());
    const Eigen::Matrix4d rb =
      lct::makeAffine(lct::expSO3(b * 2.0 * axis), Eigen::Vector3d::Zero());
    ASSERT_LT(lct_test::blockError(sum(ra, rb, Parametrisation::Polar), ra * rb), 1e-14);
  }
}

TEST(Alexa, TransformPlusInverseIsIdentity)
{
  lct_test::RandomTransforms random(602);
  for (int i = 0; i < 10000; ++i)
  {
    const Eigen::Matrix4d a = random.Affine(TransformClass::GeneralAffine);
    if (nearNegativeRealAxis(a, std::sqrt(0.5)))
    {
      continue; // ill-conditioned there: covered by the round-trip guarantee above
    }
    const Eigen::Matrix4d inverse = lct::inverseAffine(a);
    const Eigen::Matrix4d s = sum(a, inverse, Parametrisation::MatrixLog);
    // Against the identity the error is absolute: scale it by the size of the operands.
    ASSERT_LT((s - Eigen::Matrix4d::Identity()).norm(), 1e-14 * (a.norm() + inverse.norm()));
  }
}

TEST(Alexa, DeterminantOfSumIsProductOfDeterminantsAndSumCommutes)
{
  lct_test::RandomTransforms random(603);
  for (Parametrisation p : { Parametrisation::Polar, Parametrisation::MatrixLog })
  {
    for (int i = 0; i < 10000; ++i)
    {
      // Transforms whose logs have entries ~ N(0, 0.3^2): their sum stays moderate. (The sum
      // of two generic logs can reach eigenvalues ~ +-9, where any determinant of exp is
      // only as good as eps times a condition number of ~1e8.)
      lct::LogCoords ca, cb;
      for (int k = 0; k < 12; ++k)
      {
        ca[k] = 0.3 * random.Normal();
        cb[k] = 0.3 * random.Normal();
      }
      const Eigen::Matrix4d a = lct::exponential(ca, p).value;
      const Eigen::Matrix4d b = lct::exponential(cb, p).value;
      const Eigen::Matrix4d ab = sum(a, b, p);
      const Eigen::Matrix4d ba = sum(b, a, p);
      const double expected =
        a.topLeftCorner<3, 3>().determinant() * b.topLeftCorner<3, 3>().determinant();
      ASSERT_NEAR((ab.topLeftCorner<3, 3>().determinant() / expected), 1.0, 1e-13);
      ASSERT_EQ(ab, ba);
    }
  }
}

TEST(Alexa, ZeroTimesAnythingIsIdentity)
{
  lct_test::RandomTransforms random(604);
  const Eigen::Matrix4d a = random.Affine(TransformClass::GeneralAffine);
  EXPECT_EQ(scalarMultiple(0.0, a, Parametrisation::Polar), Eigen::Matrix4d::Identity());
}

// ---- Kaji & Ochiai condition V: subgroups are linear subspaces --------------------------------

TEST(Polar, BlendsStayInTheirSubgroup)
{
  lct_test::RandomTransforms random(700);
  double rigidError = 0.0;
  double similarityError = 0.0;
  double linearError = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    const int n = 2 + i % 4;
    double w[5];
    Eigen::Matrix4d rigid[5];
    Eigen::Matrix4d similar[5];
    Eigen::Matrix4d linear[5];
    for (int k = 0; k < n; ++k)
    {
      w[k] = random.Uniform(-1.0, 2.0);
      rigid[k] = random.Affine(TransformClass::Rigid);
      similar[k] = random.Affine(TransformClass::Similarity);
      linear[k] =
        lct::makeAffine(random.Linear(TransformClass::GeneralAffine), Eigen::Vector3d::Zero());
    }
    const auto r = lct::combine(w, rigid, n, Parametrisation::Polar);
    const auto s = lct::combine(w, similar, n, Parametrisation::Polar);
    const auto l = lct::combine(w, linear, n, Parametrisation::Polar);
    ASSERT_TRUE(r.ok() && s.ok() && l.ok());
    const Eigen::Matrix3d rr = r.value.topLeftCorner<3, 3>();
    rigidError = std::max(rigidError, (rr.transpose() * rr - Eigen::Matrix3d::Identity()).norm());
    rigidError = std::max(rigidError, std::abs(rr.determinant() - 1.0));
    const Eigen::Matrix3d ss = s.value.topLeftCorner<3, 3>();
    const Eigen::Matrix3d gram = ss.transpose() * ss;
    similarityError =
      std::max(similarityError, (gram / (gram.trace() / 3.0) - Eigen::Matrix3d::Identity()).norm());
    linearError = std::max(linearError, l.value.topRightCorner<3, 1>().norm());
  }
  EXPECT_LT(rigidError, 1e-13);
  EXPECT_LT(similarityError, 1e-13);
  EXPECT_EQ(linearError, 0.0);
}

// ---- Hawkins & Grimm §3.2: their square root failed for 130 of 1000 such matrices -------------

TEST(HawkinsGrimm, LargeRotationWithNonUniformScaleNeverFails)
{
  lct_test::RandomTransforms random(800);
  int failures = 0;
  double worst = 0.0;
  for (int i = 0; i < 1000; ++i)
  {
    const Eigen::Vector3d scale(
      random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0), random.LogUniform(0.2, 5.0));
    const Eigen::Matrix3d linear =
      random.Rotation(random.Uniform(lct_test::kPi / 2, lct_test::kPi)) * scale.asDiagonal();
    const Eigen::Matrix4d key = lct::makeAffine(linear, random.Translation(TransformClass::Rigid));
    // Interpolate from the identity to the key at t = 0.5 and back to the key at t = 1.
    const Eigen::Matrix4d keys[2] = { Eigen::Matrix4d::Identity(), key };
    const double half[2] = { 0.5, 0.5 };
    const double end[2] = { 0.0, 1.0 };
    const auto mid = lct::combine(half, keys, 2, Parametrisation::Polar);
    const auto last = lct::combine(end, keys, 2, Parametrisation::Polar);
    if (!mid.ok() || !last.ok() || !mid.value.allFinite())
    {
      ++failures;
      continue;
    }
    worst = std::max(worst, lct_test::blockError(last.value, key));
  }
  EXPECT_EQ(failures, 0);
  EXPECT_LT(worst, 1e-13);
}

// ---- the relative form (Hawkins & Grimm eq. 7) -----------------------------------------------

TEST(Combination, RelativeFormReproducesTheReferenceAndTakesTheShortWay)
{
  lct_test::RandomTransforms random(900);
  for (Parametrisation p : { Parametrisation::Polar, Parametrisation::MatrixLog })
  {
    for (int i = 0; i < 2000; ++i)
    {
      const Eigen::Matrix4d keys[3] = { random.Affine(TransformClass::Similarity),
        random.Affine(TransformClass::Similarity), random.Affine(TransformClass::Similarity) };
      const double w[3] = { 0.0, 1.0, 0.0 };
      const auto r = lct::combineRelative(w, keys, 3, 1, p);
      ASSERT_TRUE(r.ok());
      ASSERT_LT(lct_test::blockError(r.value, keys[1]), 1e-13);
    }
  }
  // Keys at +170 and -170 degrees about z: the relative midpoint is the half turn (short way
  // through 180), the absolute midpoint the identity (long way through 0).
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const double angle = 170.0 * lct_test::kPi / 180.0;
  const Eigen::Matrix4d keys[2] = { lct::makeAffine(
                                      lct::expSO3(angle * z), Eigen::Vector3d::Zero()),
    lct::makeAffine(lct::expSO3(-angle * z), Eigen::Vector3d::Zero()) };
  const double half[2] = { 0.5, 0.5 };
  const auto relative = lct::combineRelative(half, keys, 2, 0, Parametrisation::Polar);
  const auto absolute = lct::combine(half, keys, 2, Parametrisation::Polar);
  ASSERT_TRUE(relative.ok() && absolute.ok());
  EXPECT_NEAR(relative.value(0, 0), -1.0, 1e-14);
  EXPECT_NEAR(absolute.value(0, 0), 1.0, 1e-14);
}

TEST(Combination, RelativeFormKeepsASharedTranslation)
{
  // In the reference's own frame the Polar translation part combines as sum w t_i.
  const Eigen::Matrix4d keys[2] = {
    lct::makeAffine(Eigen::Matrix3d::Identity(), Eigen::Vector3d(1, 0, 0)),
    lct::makeAffine(lct::expSO3(Eigen::Vector3d(0, 0, lct_test::kPi / 3)), Eigen::Vector3d(1, 0, 0))
  };
  const double half[2] = { 0.5, 0.5 };
  for (std::size_t reference : { 0u, 1u })
  {
    const auto r = lct::combineRelative(half, keys, 2, reference, Parametrisation::Polar);
    ASSERT_TRUE(r.ok());
    EXPECT_LT((r.value.topRightCorner<3, 1>() - Eigen::Vector3d(1, 0, 0)).norm(), 1e-15);
  }
}

TEST(Combination, WeightedSumAndLerp)
{
  lct::LogCoords a = lct::LogCoords::LinSpaced(1.0, 12.0);
  lct::LogCoords b = -a;
  const double w[2] = { 0.25, 0.75 };
  const lct::LogCoords c[2] = { a, b };
  EXPECT_EQ(lct::weightedSum(w, c, 2), lct::lerp(a, b, 0.75));
  EXPECT_EQ(lct::largestWeight(w, 2), 1u);
}

TEST(MatrixLog, PowerMatchesExpOfScaledLogNearAndFarFromIdentity)
{
  lct_test::RandomTransforms random(1000);
  double worst = 0.0;
  for (int i = 0; i < 20000; ++i)
  {
    // Half of them near the identity (the binomial series), half generic.
    Eigen::Matrix4d m = (i % 2)
      ? random.Affine(TransformClass::GeneralAffine)
      : lct::matrixExp(0.05 * lct::matrixLog(random.Affine(TransformClass::Similarity)).value)
          .value;
    if (nearNegativeRealAxis(m, std::sqrt(0.5)))
    {
      continue;
    }
    const double s = random.Uniform(-1.5, 1.5);
    const auto power = lct::matrixPower(m, s);
    const auto reference = lct::matrixExp(s * lct::matrixLog(m).value);
    ASSERT_TRUE(power.ok() && reference.ok());
    worst = std::max(worst, lct_test::blockError(power.value, reference.value));
  }
  EXPECT_LT(worst, 1e-13);
  EXPECT_EQ(
    lct::matrixPower(Eigen::Matrix4d::Identity(), std::nan("")).status, lct::Status::NonFinite);
}

// Audit (session 28): near a half turn the matrix log is ill-conditioned (forward error ~ eps pi
// / (pi - theta)), and exp maps the whole family of logs of a block near -I close to it, so the
// round-trip check passed a rotation 2e-15 short of a half turn whose log had a stretch of 0.33:
// its half power was visibly stretched, and the basis factoring reported wrong coefficients with
// a tiny error bound. MatrixLog now either gives the rotation's own log (skew, theta a) or
// refuses; Polar gives it always.
TEST(MatrixLog, RotationsNearAHalfTurnGiveTheirLogOrAnError)
{
  lct_test::RandomTransforms random(2800);
  int accepted = 0, refused = 0;
  for (double shortOf :
    { 1e-15, 2e-15, 5e-15, 1e-14, 2e-14, 1e-13, 1e-12, 1e-10, 1e-8, 1e-7, 3e-7, 1e-5, 1e-3 })
  {
    for (int i = 0; i < 300; ++i)
    {
      const Eigen::Vector3d axis = random.UnitVector();
      const double angle = lct_test::kPi - shortOf;
      Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
      m.topLeftCorner<3, 3>() = Eigen::AngleAxisd(angle, axis).toRotationMatrix();
      const auto log = lct::matrixLog(m);
      const auto polar = lct::polarLog(m);
      ASSERT_TRUE(polar.ok());
      EXPECT_LT(lct::symmetricPart(polar.value).norm(), 1e-15);
      if (!log.ok())
      {
        EXPECT_EQ(log.status, lct::Status::NoRealLogarithm);
        // (The round-trip check refuses turns up to ~1e-4 short, where eps / slope exceeds it.)
        EXPECT_LT(shortOf, 1e-3) << "refused a turn " << shortOf << " short of a half turn";
        ++refused;
        continue;
      }
      ++accepted;
      // The log of a rotation is skew: no stretch, and the turn angle * axis (either sign of a
      // turn this close to pi is within the tolerance of the other only at the cut).
      EXPECT_LT(lct::symmetricPart(log.value).norm(), 1e-9) << shortOf << " " << axis.transpose();
      const Eigen::Vector3d w = lct::rotationPart(log.value);
      EXPECT_LT(std::min((w - angle * axis).norm(), (w + angle * axis).norm()), 1e-9) << shortOf;
    }
  }
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, 0);
}

TEST(Polar, RigidMapsHaveAnExactlyZeroStretch)
{
  // So that blends of rigid maps are exactly rigid and take polarExp's rotation-only path.
  lct_test::RandomTransforms random(1100);
  int nonzero = 0;
  for (int i = 0; i < 10000; ++i)
  {
    const auto c = lct::polarLog(random.Affine(TransformClass::Rigid));
    ASSERT_TRUE(c.ok());
    nonzero += lct::symmetricPart(c.value).isZero(0.0) ? 0 : 1;
  }
  EXPECT_EQ(nonzero, 0);
  // ... while a stretch of 1 + 1e-14 is kept.
  Eigen::Matrix4d almost = Eigen::Matrix4d::Identity();
  almost(0, 0) = 1.0 + 1e-13;
  EXPECT_GT(lct::symmetricPart(lct::polarLog(almost).value).norm(), 0.0);
}
