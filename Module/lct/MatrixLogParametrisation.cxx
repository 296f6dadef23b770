#include "lct/MatrixLogParametrisation.h"

#include "lct/Affine.h"
#include "lct/DividedDifferences.h"
#include "lct/Eigenvalues3.h"
#include "lct/SO3.h"
#include "lct/Sym3.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace lct
{

namespace
{

using Complex = std::complex<double>;

/// f(A) = constant I + linear A + quadratic (A^2 - sum A + product I): the Newton form
/// f[z0] + f[z0,z1](A - z0) + f[z0,z1,z2](A - z0)(A - z1) regrouped with real coefficients
/// (the nodes are closed under conjugation, z0 and z1 being the pair when there is one).
struct RealNewtonForm
{
  double constant;
  double linear;
  double quadratic;

  Eigen::Matrix3d apply(const Eigen::Matrix3d& a, const Eigen::Matrix3d& quadraticFactor) const
  {
    Eigen::Matrix3d m = quadratic * quadraticFactor + linear * a;
    m.diagonal().array() += constant;
    return m;
  }
};

struct BlockFunction
{
  RealNewtonForm linearBlock;      ///< f(A)
  RealNewtonForm translationBlock; ///< f[A, extra node], applied to the translation
  Eigen::Matrix3d quadraticFactor; ///< (A - z0)(A - z1), real
};

/// The Newton forms of f(A) and of x -> f[x, extraNode] at A, from one table.
BlockFunction blockFunction(
  ScalarFunction f, const Eigen::Matrix3d& a, const GeneralEigenvalues& eig, double extraNode)
{
  Complex nodes[4];
  if (eig.complexPair)
  {
    nodes[0] = eig.values[0];
    nodes[1] = eig.values[1];
    nodes[2] = eig.values[2];
  }
  else
  {
    // Middle eigenvalue first, as for symmetric matrices (Kaji & Ochiai App. B).
    nodes[0] = eig.values[1];
    nodes[1] = eig.values[0];
    nodes[2] = eig.values[2];
  }
  nodes[3] = extraNode;
  const auto dd = dividedDifferences(f, nodes, 4);
  const double sum = (nodes[0] + nodes[1]).real();
  const double product = (nodes[0] * nodes[1]).real();

  BlockFunction out;
  out.quadraticFactor = a * a - sum * a;
  out.quadraticFactor.diagonal().array() += product;
  out.linearBlock = { (dd[0b0001] - dd[0b0011] * nodes[0]).real(), dd[0b0011].real(),
    dd[0b0111].real() };
  out.translationBlock = { (dd[0b1001] - dd[0b1011] * nodes[0]).real(), dd[0b1011].real(),
    dd[0b1111].real() };
  return out;
}

/// Pairs with |Im| / -Re below this (turns beyond 135 degrees) are checked a posteriori.
constexpr double kCheckedPairSlope = 1.0;

/// exp(log M) == M to 1e-12, relative, block by block (a large translation must not hide an
/// error in the linear part).
bool accurateRoundTrip(const Eigen::Matrix4d& back, const Eigen::Matrix4d& m)
{
  constexpr double kTolerance = 1e-12;
  const double linear = (back.topLeftCorner<3, 3>() - m.topLeftCorner<3, 3>()).norm();
  const double translation = (back.topRightCorner<3, 1>() - m.topRightCorner<3, 1>()).norm();
  return linear <= kTolerance * m.topLeftCorner<3, 3>().norm() &&
    translation <= kTolerance * std::max(1.0, m.topRightCorner<3, 1>().norm()) *
      std::max(1.0, m.topLeftCorner<3, 3>().norm());
}

LogCoords packLog(const Eigen::Matrix3d& logLinear, const Eigen::Vector3d& u)
{
  LogCoords c;
  translationPart(c) = u;
  rotationPart(c) = vee(logLinear);
  symmetricPart(c) = toSymmetricVector(logLinear);
  return c;
}

} // namespace

Eigen::Matrix3d logLinearPart(const LogCoords& c)
{
  return hat(rotationPart(c)) + fromSymmetricVector(symmetricPart(c));
}

Result<Eigen::Matrix4d> matrixExp(const LogCoords& c)
{
  using R = Result<Eigen::Matrix4d>;
  if (!c.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  const Eigen::Matrix3d l = logLinearPart(c);
  const auto block = blockFunction(ScalarFunction::Exp, l, generalEigenvalues(l), 0.0);
  R out{ makeAffine(block.linearBlock.apply(l, block.quadraticFactor),
           block.translationBlock.apply(l, block.quadraticFactor) * translationPart(c)),
    Status::Ok };
  if (!out.value.allFinite())
  {
    return R::failure(Status::NonFinite);
  }
  return out;
}

Result<Eigen::Matrix4d> matrixPower(const Eigen::Matrix4d& m, double s)
{
  using R = Result<Eigen::Matrix4d>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  if (!std::isfinite(s))
  {
    return R::failure(Status::NonFinite);
  }
  Eigen::Matrix4d e = m;
  e.diagonal().array() -= 1.0;
  const double norm = e.norm();
  if (norm >= 0.25)
  {
    const auto l = matrixLog(m);
    if (!l)
    {
      return R::failure(l.status);
    }
    return matrixExp(s * l.value);
  }
  // (I + E)^s = sum_k binom(s, k) E^k; |binom(s, k)| <= max(1, |s|)^k-ish and ||E^k|| <= 1/4^k.
  // E has a zero bottom row, so only the top 3x4 block of the powers is formed.
  Eigen::Matrix<double, 3, 4> power = e.topRows<3>();
  Eigen::Matrix<double, 3, 4> sum = s * power;
  double coefficient = s;
  constexpr int kMaxTerms = 200;
  for (int k = 2; k <= kMaxTerms; ++k)
  {
    // E^k = E^(k-1) E, with E's bottom row zero: [P q] [A t; 0 0] = [P A, P t].
    Eigen::Matrix<double, 3, 4> next;
    next.leftCols<3>() = power.leftCols<3>() * e.topLeftCorner<3, 3>();
    next.col(3) = power.leftCols<3>() * e.topRightCorner<3, 1>();
    power = next;
    coefficient *= (s - (k - 1)) / k;
    const Eigen::Matrix<double, 3, 4> term = coefficient * power;
    sum += term;
    if (term.norm() <= 0.25 * std::numeric_limits<double>::epsilon() * (1.0 + sum.norm()))
    {
      break;
    }
  }
  Eigen::Matrix4d out = Eigen::Matrix4d::Identity();
  out.topRows<3>() += sum;
  return { out, Status::Ok };
}

Result<LogCoords> matrixLog(const Eigen::Matrix4d& m)
{
  using R = Result<LogCoords>;
  const Status valid = validateAffine(m);
  if (valid != Status::Ok)
  {
    return R::failure(valid);
  }
  const Eigen::Matrix3d a = m.topLeftCorner<3, 3>();
  const GeneralEigenvalues eig = generalEigenvalues(a);
  for (const Complex& value : eig.values)
  {
    if (value.imag() == 0.0 && value.real() <= 0.0)
    {
      return R::failure(Status::NoRealLogarithm);
    }
  }
  const auto block = blockFunction(ScalarFunction::Log, a, eig, 1.0);
  const Eigen::Matrix3d logA = block.linearBlock.apply(a, block.quadraticFactor);
  const Eigen::Vector3d u =
    block.translationBlock.apply(a, block.quadraticFactor) * m.topRightCorner<3, 1>();
  R out{ packLog(logA, u), Status::Ok };
  if (!out.value.allFinite())
  {
    return R::failure(Status::NoRealLogarithm);
  }
  // A conjugate pair close to the negative real axis (turns beyond 135 degrees): there the
  // log is ill-conditioned (its divided differences grow like 1 / Im) and the cubic's roots
  // carry the round-off of the characteristic polynomial, so the closed form may lose digits.
  // Check the result and refuse it rather than return an inaccurate logarithm.
  if (eig.complexPair && eig.values[0].real() < 0.0 &&
    eig.values[0].imag() < kCheckedPairSlope * -eig.values[0].real())
  {
    const auto back = matrixExp(out.value);
    if (!back || !accurateRoundTrip(back.value, m))
    {
      return R::failure(Status::NoRealLogarithm);
    }
  }
  return out;
}

} // namespace lct
