// Random affine transforms of the classes the property tests sweep, with a fixed seed so that a
// failure is reproducible. Each generator documents the distribution it draws from.
#ifndef lct_test_RandomTransforms_h
#define lct_test_RandomTransforms_h

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>
#include <random>
#include <string>

namespace lct_test
{

constexpr double kPi = 3.14159265358979323846;

enum class TransformClass
{
  Rigid,          ///< rotation of any angle in [0, pi], translation ~ N(0, 10^2)
  Similarity,     ///< rigid times a uniform scale, log-uniform in [0.1, 10]
  GeneralAffine,  ///< R1 diag(s) R2 (shear and non-uniform scale), s log-uniform in [0.2, 5]
  NearSingular,   ///< singular values 1, 1e-3 and (1e-3 .. 1): det down to 1e-6
  NearHalfTurn,   ///< rotation within 1e-8 of pi (some exactly pi) times a stretch near I
  BigTranslation, ///< general affine with translation up to 1e6
  NearIdentity    ///< I + 1e-8 noise, translation 1e-8 noise
};

inline const char* className(TransformClass c)
{
  switch (c)
  {
    case TransformClass::Rigid:
      return "Rigid";
    case TransformClass::Similarity:
      return "Similarity";
    case TransformClass::GeneralAffine:
      return "GeneralAffine";
    case TransformClass::NearSingular:
      return "NearSingular";
    case TransformClass::NearHalfTurn:
      return "NearHalfTurn";
    case TransformClass::BigTranslation:
      return "BigTranslation";
    case TransformClass::NearIdentity:
      return "NearIdentity";
  }
  return "?";
}

class RandomTransforms
{
public:
  explicit RandomTransforms(std::uint64_t seed)
    : Engine(seed)
  {
  }

  double Uniform(double lo, double hi)
  {
    return std::uniform_real_distribution<double>(lo, hi)(this->Engine);
  }
  double Normal() { return std::normal_distribution<double>(0.0, 1.0)(this->Engine); }
  double LogUniform(double lo, double hi)
  {
    return std::exp(this->Uniform(std::log(lo), std::log(hi)));
  }

  Eigen::Vector3d UnitVector()
  {
    Eigen::Vector3d v(this->Normal(), this->Normal(), this->Normal());
    return v.normalized();
  }

  /// A rotation by `angle` about a uniformly random axis.
  Eigen::Matrix3d Rotation(double angle)
  {
    return Eigen::AngleAxisd(angle, this->UnitVector()).toRotationMatrix();
  }

  /// A rotation of uniformly random angle in [0, pi].
  Eigen::Matrix3d Rotation() { return this->Rotation(this->Uniform(0.0, kPi)); }

  Eigen::Matrix3d Linear(TransformClass c)
  {
    switch (c)
    {
      case TransformClass::Rigid:
        return this->Rotation();
      case TransformClass::Similarity:
        return this->LogUniform(0.1, 10.0) * this->Rotation();
      case TransformClass::GeneralAffine:
      case TransformClass::BigTranslation:
      {
        const Eigen::Vector3d s(
          this->LogUniform(0.2, 5.0), this->LogUniform(0.2, 5.0), this->LogUniform(0.2, 5.0));
        return this->Rotation() * s.asDiagonal() * this->Rotation();
      }
      case TransformClass::NearSingular:
      {
        const Eigen::Vector3d s(1.0, 1e-3, this->LogUniform(1e-3, 1.0));
        return this->Rotation() * s.asDiagonal() * this->Rotation();
      }
      case TransformClass::NearHalfTurn:
      {
        const double delta = (this->Uniform(0.0, 1.0) < 0.1) ? 0.0 : this->Uniform(0.0, 1e-8);
        Eigen::Matrix3d stretch = Eigen::Matrix3d::Identity();
        for (int i = 0; i < 3; ++i)
        {
          for (int j = i; j < 3; ++j)
          {
            stretch(i, j) += 0.1 * this->Uniform(-1.0, 1.0);
            stretch(j, i) = stretch(i, j);
          }
        }
        return this->Rotation(kPi - delta) * stretch;
      }
      case TransformClass::NearIdentity:
      {
        Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
        for (int i = 0; i < 9; ++i)
        {
          m(i) += 1e-8 * this->Normal();
        }
        return m;
      }
    }
    return Eigen::Matrix3d::Identity();
  }

  Eigen::Vector3d Translation(TransformClass c)
  {
    const Eigen::Vector3d n(this->Normal(), this->Normal(), this->Normal());
    switch (c)
    {
      case TransformClass::BigTranslation:
        return this->Uniform(0.0, 1e6) * n.normalized();
      case TransformClass::NearIdentity:
        return 1e-8 * n;
      default:
        return 10.0 * n;
    }
  }

  Eigen::Matrix4d Affine(TransformClass c)
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    m.topLeftCorner<3, 3>() = this->Linear(c);
    m.topRightCorner<3, 1>() = this->Translation(c);
    return m;
  }

  /// A key for the tests of what the interpolators refuse: a GeneralAffine linear part (60 %), a
  /// stretch diag(10^a, 1, 10^-a) with a in [4, 6.5] in random orientations (25 %: the step
  /// between two of them can exceed the 1e13 conditioning limit, so it has no log), or a half
  /// turn with a non-uniform scale (15 %: no real matrix log); translated as Rigid, or not.
  Eigen::Matrix4d HardKey(bool translated)
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
    const double kind = this->Uniform(0.0, 1.0);
    if (kind < 0.6)
    {
      m.topLeftCorner<3, 3>() = this->Linear(TransformClass::GeneralAffine);
    }
    else if (kind < 0.85)
    {
      const double a = this->Uniform(4.0, 6.5);
      m.topLeftCorner<3, 3>() = this->Rotation() *
        Eigen::Vector3d(std::pow(10.0, a), 1.0, std::pow(10.0, -a)).asDiagonal() * this->Rotation();
    }
    else
    {
      m.topLeftCorner<3, 3>() = this->Rotation(kPi) * Eigen::Vector3d(2.0, 1.0, 0.5).asDiagonal();
    }
    if (translated)
    {
      m.topRightCorner<3, 1>() = this->Translation(TransformClass::Rigid);
    }
    return m;
  }

  /// One step of a keyframed animation (the benchmarks' key walks): a rotation of up to 30
  /// degrees about a random axis, up to 15 % of non-uniform scale change, and a translation a
  /// tenth of a Rigid one.
  Eigen::Matrix4d KeyframeStep()
  {
    const Eigen::Vector3d s(
      this->LogUniform(0.87, 1.15), this->LogUniform(0.87, 1.15), this->LogUniform(0.87, 1.15));
    Eigen::Matrix4d step = Eigen::Matrix4d::Identity();
    step.topLeftCorner<3, 3>() = this->Rotation(this->Uniform(0.0, 0.52)) * s.asDiagonal();
    step.topRightCorner<3, 1>() = this->Translation(TransformClass::Rigid) / 10.0;
    return step;
  }

private:
  std::mt19937_64 Engine;
};

/// max |a - b| / max(1, max |b|), block by block: linear and translation parts separately, so
/// a 1e6 translation does not hide an error in the linear part.
inline double blockError(const Eigen::Matrix4d& a, const Eigen::Matrix4d& b)
{
  const double linear = (a.topLeftCorner<3, 3>() - b.topLeftCorner<3, 3>()).norm() /
    std::max(1.0, b.topLeftCorner<3, 3>().norm());
  const double translation = (a.topRightCorner<3, 1>() - b.topRightCorner<3, 1>()).norm() /
    std::max(1.0, b.topRightCorner<3, 1>().norm());
  return std::max(linear, translation);
}

} // namespace lct_test

#endif
