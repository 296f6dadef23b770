#include "lct/KeyLogs.h"

#include "lct/Affine.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"

#include <algorithm>
#include <cstdlib>

namespace lct
{

namespace
{
constexpr int kSlots = 2 * KeyLogs::kReach + 1;
}

Status KeyLogs::build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
  bool neighboursMustCombine, int* failed)
{
  const int n = static_cast<int>(matrices.size());
  std::vector<LogCoords> relative(static_cast<std::size_t>(n) * kSlots);
  std::vector<char> valid(relative.size(), 0);
  std::vector<LogCoords> absolute(n);
  for (int r = 0; r < n; ++r)
  {
    const auto a = logarithm(matrices[r], p, r > 0 ? &absolute[r - 1] : nullptr);
    if (!a)
    {
      if (failed)
      {
        *failed = r;
      }
      return a.status;
    }
    absolute[r] = a.value;
    const Eigen::Matrix4d inverse = inverseAffine(matrices[r]);
    for (int i = std::max(0, r - kReach); i <= std::min(n - 1, r + kReach); ++i)
    {
      const auto l = logarithm(matrices[i] * inverse, p);
      if (!l)
      {
        // MatrixLog only: a step without real log. Fatal between neighbours when asked (no
        // curve could join them); otherwise it matters only if a curve point combines the
        // two, which combineRelative reports.
        if (neighboursMustCombine && std::abs(i - r) <= 1)
        {
          if (failed)
          {
            *failed = std::max(i, r);
          }
          return l.status;
        }
        continue;
      }
      relative[r * kSlots + (i - r + kReach)] = l.value;
      valid[r * kSlots + (i - r + kReach)] = 1;
    }
  }
  this->P = p;
  this->Matrices = matrices;
  this->Relative.swap(relative);
  this->RelativeValid.swap(valid);
  this->Absolute.swap(absolute);
  return Status::Ok;
}

const LogCoords* KeyLogs::relative(int i, int r) const
{
  if (std::abs(i - r) > kReach || r < 0 || r >= static_cast<int>(this->size()) || i < 0 ||
    i >= static_cast<int>(this->size()))
  {
    return nullptr;
  }
  const std::size_t slot = r * kSlots + (i - r + kReach);
  return this->RelativeValid[slot] ? &this->Relative[slot] : nullptr;
}

Status KeyLogs::combineAbout(const CurveWeights& w, int reference, Eigen::Matrix4d& out) const
{
  LogCoords sum = LogCoords::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    const LogCoords* l = this->relative(w.key[j], reference);
    if (!l)
    {
      return Status::NoRealLogarithm;
    }
    sum += w.weight[j] * *l;
  }
  const auto m = exponential(sum, this->P);
  if (m)
  {
    out = m.value * this->Matrices[reference];
  }
  return m.status;
}

Status KeyLogs::combineRelative(const CurveWeights& w, Eigen::Matrix4d& out) const
{
  int a = -1;
  int b = -1;
  for (int j = 0; j < w.count; ++j)
  {
    if (a < 0 || w.weight[j] > w.weight[a])
    {
      b = a;
      a = j;
    }
    else if (b < 0 || w.weight[j] > w.weight[b])
    {
      b = j;
    }
  }
  const Status status = this->combineAbout(w, w.key[a], out);
  const double gap = b < 0 ? kHandOver : w.weight[a] - w.weight[b];
  if (status != Status::Ok || gap >= kHandOver)
  {
    return status;
  }
  Eigen::Matrix4d other;
  if (this->combineAbout(w, w.key[b], other) != Status::Ok)
  {
    return status; // no result about b: keep the one about a
  }
  const double x = gap / kHandOver;
  const double s = 0.5 * (1.0 - x * x * (3.0 - 2.0 * x));
  // (R_b R_a^-1)^s R_a: at s = 1/2 the same point from either side.
  const auto blend = matrixPower(other * inverseAffine(out), s);
  if (blend)
  {
    out = blend.value * out;
  }
  return status;
}

Status KeyLogs::combineAbsolute(const CurveWeights& w, Eigen::Matrix4d& out) const
{
  LogCoords sum = LogCoords::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    sum += w.weight[j] * this->Absolute[w.key[j]];
  }
  const auto m = exponential(sum, this->P);
  if (m)
  {
    out = m.value;
  }
  return m.status;
}

} // namespace lct
