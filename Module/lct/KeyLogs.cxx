#include "lct/KeyLogs.h"

#include "lct/Affine.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"

#include <algorithm>
#include <cstdlib>

namespace lct
{

KeyLogs::Window KeyLogs::computeWindow(const std::vector<Eigen::Matrix4d>& matrices, int r) const
{
  Window w;
  const int n = static_cast<int>(matrices.size());
  const Eigen::Matrix4d inverse = inverseAffine(matrices[r]);
  for (int slot = 0; slot <= 2 * kReach; ++slot)
  {
    const int i = r + slot - kReach;
    w.valid[slot] = false;
    if (i < 0 || i >= n)
    {
      continue;
    }
    const auto l = logarithm(inverse * matrices[i], this->P);
    if (l)
    {
      w.logs[slot] = l.value;
      w.valid[slot] = true;
    }
  }
  return w;
}

Status KeyLogs::computeWindows(const std::vector<Eigen::Matrix4d>& matrices, int first, int last,
  bool neighboursMustCombine, std::vector<Window>& scratch, int* failed) const
{
  const int n = static_cast<int>(matrices.size());
  first = std::max(first, 0);
  last = std::min(last, n - 1);
  scratch.clear();
  for (int r = first; r <= last; ++r)
  {
    scratch.push_back(this->computeWindow(matrices, r));
    // MatrixLog only: a step without real log. Fatal between neighbours when asked (no curve
    // could join them); farther apart it matters only if a curve point combines the two.
    if (neighboursMustCombine && r + 1 < n && !scratch.back().valid[kReach + 1])
    {
      if (failed)
      {
        *failed = r + 1;
      }
      return Status::NoRealLogarithm;
    }
  }
  return Status::Ok;
}

void KeyLogs::commitWindows(int first, const std::vector<Window>& scratch)
{
  first = std::max(first, 0);
  for (std::size_t k = 0; k < scratch.size(); ++k)
  {
    this->Windows[first + k] = scratch[k];
  }
}

void KeyLogs::updateAbsoluteFrom(int index)
{
  const int n = static_cast<int>(this->Matrices.size());
  for (int i = std::max(index, 0); i < n; ++i)
  {
    const LogCoords* previous = (i > 0 && this->AbsoluteValid[i - 1]) ? &this->Absolute[i - 1] : nullptr;
    const auto a = logarithm(this->Matrices[i], this->P, previous);
    const bool unchanged = i > index && this->AbsoluteValid[i] == static_cast<char>(a.ok()) &&
      (!a.ok() || a.value == this->Absolute[i]);
    this->AbsoluteValid[i] = a.ok();
    if (a)
    {
      this->Absolute[i] = a.value;
    }
    if (unchanged)
    {
      return; // the rest of the chain keeps its branches
    }
  }
}

Status KeyLogs::build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
  bool neighboursMustCombine, int* failed)
{
  KeyLogs next(p);
  std::vector<Window> scratch;
  const Status status = next.computeWindows(
    matrices, 0, static_cast<int>(matrices.size()) - 1, neighboursMustCombine, scratch, failed);
  if (status != Status::Ok)
  {
    return status;
  }
  next.Matrices = matrices;
  next.Windows = scratch;
  next.Absolute.resize(matrices.size());
  next.AbsoluteValid.assign(matrices.size(), 0);
  next.updateAbsoluteFrom(0);
  *this = std::move(next);
  return Status::Ok;
}

Status KeyLogs::insert(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine)
{
  std::vector<Eigen::Matrix4d> matrices = this->Matrices;
  matrices.insert(matrices.begin() + index, m);
  std::vector<Window> scratch;
  const Status status = this->computeWindows(
    matrices, index - kReach, index + kReach, neighboursMustCombine, scratch, nullptr);
  if (status != Status::Ok)
  {
    return status;
  }
  this->Matrices.swap(matrices);
  this->Windows.insert(this->Windows.begin() + index, Window());
  this->commitWindows(index - kReach, scratch);
  this->Absolute.insert(this->Absolute.begin() + index, LogCoords::Zero());
  this->AbsoluteValid.insert(this->AbsoluteValid.begin() + index, 0);
  this->updateAbsoluteFrom(index);
  return Status::Ok;
}

Status KeyLogs::replace(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine)
{
  std::vector<Eigen::Matrix4d> matrices = this->Matrices;
  matrices[index] = m;
  std::vector<Window> scratch;
  const Status status = this->computeWindows(
    matrices, index - kReach, index + kReach, neighboursMustCombine, scratch, nullptr);
  if (status != Status::Ok)
  {
    return status;
  }
  this->Matrices.swap(matrices);
  this->commitWindows(index - kReach, scratch);
  this->updateAbsoluteFrom(index);
  return Status::Ok;
}

Status KeyLogs::erase(int index, bool neighboursMustCombine)
{
  std::vector<Eigen::Matrix4d> matrices = this->Matrices;
  matrices.erase(matrices.begin() + index);
  std::vector<Window> scratch;
  const Status status = this->computeWindows(
    matrices, index - kReach, index + kReach - 1, neighboursMustCombine, scratch, nullptr);
  if (status != Status::Ok)
  {
    return status;
  }
  this->Matrices.swap(matrices);
  this->Windows.erase(this->Windows.begin() + index);
  this->commitWindows(index - kReach, scratch);
  this->Absolute.erase(this->Absolute.begin() + index);
  this->AbsoluteValid.erase(this->AbsoluteValid.begin() + index);
  this->updateAbsoluteFrom(index);
  return Status::Ok;
}

const LogCoords* KeyLogs::relative(int i, int r) const
{
  const int n = static_cast<int>(this->size());
  if (std::abs(i - r) > kReach || r < 0 || r >= n || i < 0 || i >= n)
  {
    return nullptr;
  }
  const Window& w = this->Windows[r];
  const int slot = i - r + kReach;
  return w.valid[slot] ? &w.logs[slot] : nullptr;
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
    out = this->Matrices[reference] * m.value;
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
  // R_a (R_a^-1 R_b)^s: at s = 1/2 the same point from either side.
  const auto blend = matrixPower(inverseAffine(out) * other, s);
  if (blend)
  {
    out = out * blend.value;
  }
  return status;
}

Status KeyLogs::combineAbsolute(const CurveWeights& w, Eigen::Matrix4d& out) const
{
  LogCoords sum = LogCoords::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    if (!this->AbsoluteValid[w.key[j]])
    {
      return Status::NoRealLogarithm;
    }
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
