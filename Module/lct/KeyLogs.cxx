#include "lct/KeyLogs.h"

#include "lct/Affine.h"
#include "lct/Combination.h"
#include "lct/MatrixLogParametrisation.h"
#include "lct/Parametrisation.h"
#include "lct/SO3.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

namespace
{
/// log(||L||_F^3 / det L), an upper bound of log cond(L)^2 + log 5.2 and at least log cond(L)
/// (lct::needsAccurateProducts' measure), free of overflow.
double logIllConditioning(const Eigen::Matrix4d& m, double logDeterminant)
{
  const Eigen::Matrix3d linear = m.topLeftCorner<3, 3>();
  const double largest = linear.cwiseAbs().maxCoeff();
  return 3.0 * (std::log(largest) + std::log((linear / largest).norm())) - logDeterminant;
}
} // namespace

namespace lct
{

namespace
{
/// The number of keys of `points` curve points (Bezier: the keys of a key-and-control sequence
/// of 3 (n - 1) + 1 points).
int curveKeys(CurveScheme scheme, int points)
{
  return scheme == CurveScheme::Bezier ? (points + 2) / 3 : points;
}

/// The segments whose curve points may combine a log that an edit at point `index` adds.
void segmentsNear(CurveScheme scheme, int index, int& first, int& last)
{
  if (scheme == CurveScheme::Bezier)
  {
    first = (index - 1) / 3 - 1;
    last = index / 3 + 1;
    return;
  }
  first = index - KeyLogs::kStencilReach - 1;
  last = index + KeyLogs::kStencilReach;
}

/// Calls visit(j) for every point that a curve point on segments first..last combines.
template <typename Visit>
bool forEachCombinedPoint(CurveScheme scheme, int keyCount, int first, int last, Visit&& visit)
{
  const int segments = curveSegments(keyCount);
  for (int s = std::max(first, 0); s <= last && s < segments; ++s)
  {
    const CurveStencil stencil = curveStencil(scheme, keyCount, s);
    for (int j = stencil.first; j <= stencil.last; ++j)
    {
      if (!visit(j))
      {
        return false;
      }
    }
  }
  return true;
}
} // namespace

void KeyLogs::commitWindows(int first, const std::vector<Window>& scratch)
{
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
    const LogCoords* previous =
      (i > 0 && this->AbsoluteStatus[i - 1] == Status::Ok) ? &this->Absolute[i - 1] : nullptr;
    auto a = logarithm(this->Matrices[i], this->P, previous);
    if (!a && previous)
    {
      // A chain wound beyond kMaxRotationWinding (Polar) starts again from the principal branch
      // rather than leaving this key without an absolute log: so every key whose principal log
      // exists has an absolute one, which is what a CurveNeeds check of absolute logs asks.
      a = logarithm(this->Matrices[i], this->P);
    }
    const bool unchanged =
      i > index && this->AbsoluteStatus[i] == a.status && (!a.ok() || a.value == this->Absolute[i]);
    this->AbsoluteStatus[i] = a.status;
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
  // Appending in order computes each relative log once.
  KeyLogs next(p);
  for (std::size_t i = 0; i < matrices.size(); ++i)
  {
    const Status status = next.edit(
      Edit::Insert, static_cast<int>(i), &matrices[i], neighboursMustCombine, nullptr, nullptr);
    if (status != Status::Ok)
    {
      if (failed)
      {
        *failed = static_cast<int>(i);
      }
      return status;
    }
  }
  *this = std::move(next);
  return Status::Ok;
}

Status KeyLogs::build(const std::vector<Eigen::Matrix4d>& matrices, Parametrisation p,
  bool neighboursMustCombine, const CurveNeeds& needs, MissingLog* missing)
{
  // Each append checks the logs of the segments near it, which are all the logs the appended key
  // adds: the appends check every log the curve points need.
  KeyLogs next(p);
  for (std::size_t i = 0; i < matrices.size(); ++i)
  {
    const Status status = next.edit(
      Edit::Insert, static_cast<int>(i), &matrices[i], neighboursMustCombine, &needs, missing);
    if (status != Status::Ok)
    {
      return status;
    }
  }
  *this = std::move(next);
  return Status::Ok;
}

Status KeyLogs::edit(Edit kind, int index, const Eigen::Matrix4d* m, bool neighboursMustCombine,
  const CurveNeeds* needs, MissingLog* missing)
{
  MissingLog ignored;
  MissingLog& found = missing ? *missing : ignored;
  found = MissingLog();
  const int n = static_cast<int>(this->Matrices.size());
  const int size = n + (kind == Edit::Insert ? 1 : 0) - (kind == Edit::Erase ? 1 : 0);
  // The position in the old sequence of the key at position i of the edited one (-1 for an
  // inserted key), and that key.
  auto original = [&](int i) {
    if (kind == Edit::Insert)
    {
      return i < index ? i : (i == index ? -1 : i - 1);
    }
    return (kind == Edit::Erase && i >= index) ? i + 1 : i;
  };
  auto edited = [&](int i) -> const Eigen::Matrix4d& {
    return (kind != Edit::Erase && i == index) ? *m : this->Matrices[original(i)];
  };
  // Only the windows within reach of the edit change, and in them only the entries that pair
  // the edited key, or keys that were out of each other's reach before (erase); the others are
  // the old logs, moved.
  const int first = std::max(0, index - kReach);
  const int last = std::min(size - 1, index + kReach - (kind == Edit::Erase ? 1 : 0));
  std::vector<Window> scratch;
  for (int r = first; r <= last; ++r)
  {
    Window w;
    for (int slot = 0; slot <= 2 * kReach; ++slot)
    {
      const int i = r + slot - kReach;
      w.status[slot] = Status::InvalidArgument;
      if (i < 0 || i >= size)
      {
        continue;
      }
      const int oldR = original(r);
      const int oldI = original(i);
      const bool pairsEdited = kind != Edit::Erase && (r == index || i == index);
      if (!pairsEdited && std::abs(oldI - oldR) <= kReach)
      {
        const Window& old = this->Windows[oldR];
        w.status[slot] = old.status[oldI - oldR + kReach];
        w.logs[slot] = old.logs[oldI - oldR + kReach];
        continue;
      }
      if (i == r)
      {
        // log(M^-1 M) = 0 exactly: keys are reproduced at their times however ill-conditioned
        // (the computed M^-1 M is I only to eps cond(M)).
        w.logs[slot].setZero();
        w.status[slot] = Status::Ok;
        continue;
      }
      const auto l = relativeLog(edited(r), edited(i), this->P);
      w.status[slot] = l.status;
      if (l)
      {
        w.logs[slot] = l.value;
      }
    }
    // Fatal between neighbours when asked (no curve could join them).
    if (neighboursMustCombine && r + 1 < size && w.status[kReach + 1] != Status::Ok)
    {
      found = MissingLog{ w.status[kReach + 1], r + 1, r };
      return found.status;
    }
    scratch.push_back(w);
  }
  if (needs && size > 0)
  {
    // Every log the curve points near the edit combine, before anything changes: the relative
    // ones are in the recomputed windows (their references are within kStencilReach + 1 of the
    // edit, the windows within kReach), an absolute one is the principal log of the new key
    // (updateAbsoluteFrom falls back to it).
    const int keys = curveKeys(needs->scheme, size);
    int firstSegment = 0;
    int lastSegment = 0;
    segmentsNear(needs->scheme, index, firstSegment, lastSegment);
    if (needs->absolute)
    {
      if (kind != Edit::Erase)
      {
        const Status own = logarithm(*m, this->P).status;
        if (own != Status::Ok)
        {
          found = MissingLog{ own, index, index };
          return own;
        }
      }
    }
    else
    {
      forEachCombinedPair(needs->scheme, keys, firstSegment, lastSegment, [&](int i, int r) {
        const Status status = scratch[r - first].status[i - r + kReach];
        if (status != Status::Ok)
        {
          found = MissingLog{ status, i, r };
          return false;
        }
        return true;
      });
      if (found.missing())
      {
        return found.status;
      }
    }
  }
  switch (kind)
  {
    case Edit::Insert:
      this->Matrices.insert(this->Matrices.begin() + index, *m);
      this->Windows.insert(this->Windows.begin() + index, Window());
      this->Absolute.insert(this->Absolute.begin() + index, LogCoords::Zero());
      this->AbsoluteStatus.insert(this->AbsoluteStatus.begin() + index, Status::InvalidArgument);
      this->Accurate.insert(this->Accurate.begin() + index, needsAccurateProducts(*m));
      this->LogDeterminant.insert(this->LogDeterminant.begin() + index, accurateLogDeterminant(*m));
      break;
    case Edit::Replace:
      this->Matrices[index] = *m;
      this->Accurate[index] = needsAccurateProducts(*m);
      this->LogDeterminant[index] = accurateLogDeterminant(*m);
      break;
    case Edit::Erase:
      this->Matrices.erase(this->Matrices.begin() + index);
      this->Windows.erase(this->Windows.begin() + index);
      this->Absolute.erase(this->Absolute.begin() + index);
      this->AbsoluteStatus.erase(this->AbsoluteStatus.begin() + index);
      this->Accurate.erase(this->Accurate.begin() + index);
      this->LogDeterminant.erase(this->LogDeterminant.begin() + index);
      break;
  }
  this->commitWindows(first, scratch);
  this->updateAbsoluteFrom(index);
  return Status::Ok;
}

Status KeyLogs::insert(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine)
{
  return this->edit(Edit::Insert, index, &m, neighboursMustCombine, nullptr, nullptr);
}

Status KeyLogs::replace(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine)
{
  return this->edit(Edit::Replace, index, &m, neighboursMustCombine, nullptr, nullptr);
}

Status KeyLogs::erase(int index, bool neighboursMustCombine)
{
  return this->edit(Edit::Erase, index, nullptr, neighboursMustCombine, nullptr, nullptr);
}

Status KeyLogs::insert(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine,
  const CurveNeeds& needs, MissingLog* missing)
{
  return this->edit(Edit::Insert, index, &m, neighboursMustCombine, &needs, missing);
}

Status KeyLogs::replace(int index, const Eigen::Matrix4d& m, bool neighboursMustCombine,
  const CurveNeeds& needs, MissingLog* missing)
{
  return this->edit(Edit::Replace, index, &m, neighboursMustCombine, &needs, missing);
}

Status KeyLogs::erase(
  int index, bool neighboursMustCombine, const CurveNeeds& needs, MissingLog* missing)
{
  return this->edit(Edit::Erase, index, nullptr, neighboursMustCombine, &needs, missing);
}

MissingLog KeyLogs::missingLog(const CurveNeeds& needs, int firstSegment, int lastSegment) const
{
  MissingLog out;
  const int keys = curveKeys(needs.scheme, static_cast<int>(this->size()));
  if (keys == 0)
  {
    return out;
  }
  if (needs.absolute)
  {
    forEachCombinedPoint(needs.scheme, keys, firstSegment, lastSegment, [&](int j) {
      if (this->AbsoluteStatus[j] != Status::Ok)
      {
        out = MissingLog{ this->AbsoluteStatus[j], j, j };
        return false;
      }
      return true;
    });
    return out;
  }
  forEachCombinedPair(needs.scheme, keys, firstSegment, lastSegment, [&](int i, int r) {
    const Status status = this->relativeStatus(i, r);
    if (status != Status::Ok)
    {
      out = MissingLog{ status, i, r };
      return false;
    }
    return true;
  });
  return out;
}

MissingLog KeyLogs::missingLog(const std::vector<Eigen::Matrix4d>& points, int offset, int keyCount,
  Parametrisation p, const CurveNeeds& needs, int firstSegment, int lastSegment, int involving,
  int across)
{
  MissingLog out;
  if (keyCount == 0)
  {
    return out;
  }
  auto point = [&](int j) -> const Eigen::Matrix4d& { return points[j - offset]; };
  // Neighbouring segments share most of their logs: each is computed once.
  std::vector<std::pair<int, int>> checked;
  auto once = [&](int i, int r) {
    if (std::find(checked.begin(), checked.end(), std::make_pair(i, r)) != checked.end())
    {
      return false;
    }
    checked.emplace_back(i, r);
    return true;
  };
  if (needs.absolute)
  {
    forEachCombinedPoint(needs.scheme, keyCount, firstSegment, lastSegment, [&](int j) {
      if ((involving >= 0 && j != involving) || !once(j, j))
      {
        return true;
      }
      const Status status = logarithm(point(j), p).status;
      if (status != Status::Ok)
      {
        out = MissingLog{ status, j, j };
        return false;
      }
      return true;
    });
    return out;
  }
  forEachCombinedPair(needs.scheme, keyCount, firstSegment, lastSegment, [&](int i, int r) {
    const bool wanted = (involving < 0 || i == involving || r == involving) &&
      (across < 0 || (std::min(i, r) < across && std::max(i, r) >= across));
    if (!wanted || !once(i, r))
    {
      return true;
    }
    const Status status = relativeLog(point(r), point(i), p).status;
    if (status != Status::Ok)
    {
      out = MissingLog{ status, i, r };
      return false;
    }
    return true;
  });
  return out;
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
  return w.status[slot] == Status::Ok ? &w.logs[slot] : nullptr;
}

Status KeyLogs::relativeStatus(int i, int r) const
{
  const int n = static_cast<int>(this->size());
  if (std::abs(i - r) > kReach || r < 0 || r >= n || i < 0 || i >= n)
  {
    return Status::InvalidArgument;
  }
  return this->Windows[r].status[i - r + kReach];
}

Status KeyLogs::combineAbout(
  const CurveWeights& w, int reference, Eigen::Matrix4d& out, MissingLog* missing) const
{
  LogCoords sum = LogCoords::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    const LogCoords* l = this->relative(w.key[j], reference);
    if (!l)
    {
      const Status status = this->relativeStatus(w.key[j], reference);
      if (missing)
      {
        *missing = MissingLog{ status, w.key[j], reference };
      }
      return status;
    }
    sum += w.weight[j] *
      (std::abs(w.key[j] - reference) >= 2 ? this->continuedRelative(w.key[j], reference, *l) : *l);
  }
  const auto m = exponential(sum, this->P);
  if (!m)
  {
    return m.status;
  }
  const Eigen::Matrix4d result =
    applyRelativeStep(this->Matrices[reference], m.value, this->P, this->Accurate[reference]);
  if (!result.allFinite())
  {
    return Status::OutOfRange;
  }
  out = result;
  return Status::Ok;
}

LogCoords KeyLogs::continuedRelative(int i, int r, const LogCoords& principal) const
{
  if (this->P != Parametrisation::Polar)
  {
    return principal; // principal matrix logs only
  }
  const int step = i > r ? 1 : -1;
  Eigen::Vector3d previous = Eigen::Vector3d::Zero(); // key r's own step is 0
  for (int k = r + step; k != i; k += step)
  {
    const LogCoords* between = this->relative(k, r);
    if (!between)
    {
      return principal;
    }
    previous = nearestEquivalentRotation(rotationPart(*between), previous);
  }
  LogCoords continued = principal;
  rotationPart(continued) = nearestEquivalentRotation(rotationPart(principal), previous);
  return continued;
}

Status KeyLogs::checkResult(const CurveWeights& w, const Eigen::Matrix4d& out) const
{
  bool involved = false;
  double expected = 0.0;
  for (int j = 0; j < w.count; ++j)
  {
    involved = involved || this->Accurate[w.key[j]];
    expected += w.weight[j] * this->LogDeterminant[w.key[j]];
  }
  return !involved || determinantMatches(out, expected) ? Status::Ok : Status::InaccurateResult;
}

Status KeyLogs::combineRelative(
  const CurveWeights& w, Eigen::Matrix4d& result, MissingLog* missing) const
{
  // A key at its own time (every other weight 0) is that key, exactly: no exp, no product and
  // nothing to check (the determinant check refused, at its own time, the camera matrix of a
  // scene at 1e-100 whose determinant double cannot form).
  int only = -1;
  for (int j = 0; j < w.count; ++j)
  {
    if (w.weight[j] != 0.0)
    {
      only = only == -1 && w.weight[j] == 1.0 ? j : -2;
    }
  }
  if (only >= 0)
  {
    result = this->Matrices[w.key[only]];
    return Status::Ok;
  }
  Eigen::Matrix4d out;
  const Status status = this->combineRelativeUnchecked(w, out, missing);
  if (status != Status::Ok)
  {
    return status;
  }
  const Status check = this->checkResult(w, out);
  if (check == Status::Ok)
  {
    result = out;
  }
  return check;
}

Status KeyLogs::combineTwoIllConditioned(
  const CurveWeights& w, int p, int q, Eigen::Matrix4d& out, MissingLog* missing) const
{
  // About an ill-conditioned key the step's rounding is amplified by its condition even where
  // the result is far better conditioned (keys I and a stretch of condition 1e12: the largest
  // stretch 1e-6 off at t = 0.9, which the determinant check cannot see, with status OK); about
  // the better-conditioned key it is not. But near an ill-conditioned key, its smallest stretch
  // is kept only by the step from it, a product with a near-identity: then the result about it
  // is taken if it passes the determinant check and agrees with the other to kAgreement.
  const bool qBetter =
    logIllConditioning(this->Matrices[w.key[q]], this->LogDeterminant[w.key[q]]) <
    logIllConditioning(this->Matrices[w.key[p]], this->LogDeterminant[w.key[p]]);
  const int better = qBetter ? q : p, worse = qBetter ? p : q;
  Eigen::Matrix4d first;
  const Status status = this->combineAbout(w, w.key[better], first, missing);
  if (status != Status::Ok)
  {
    return status;
  }
  if (this->checkResult(w, first) == Status::Ok)
  {
    out = first;
    return Status::Ok;
  }
  Eigen::Matrix4d second;
  if (this->combineAbout(w, w.key[worse], second, nullptr) == Status::Ok &&
    this->checkResult(w, second) == Status::Ok)
  {
    const double scale = first.topLeftCorner<3, 3>().cwiseAbs().maxCoeff();
    const double difference =
      (first.topLeftCorner<3, 3>() - second.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff();
    if (difference <= kAgreement * scale)
    {
      out = second;
      return Status::Ok;
    }
  }
  out = first; // refused by the caller's check
  return Status::Ok;
}

KeyLogs::HandOver KeyLogs::handOver(const CurveWeights& w)
{
  HandOver h;
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
  h.first = std::max(a, 0);
  h.second = b;
  const double gap = b < 0 ? kHandOver : w.weight[a] - w.weight[b];
  if (gap < kHandOver)
  {
    const double x = gap / kHandOver;
    h.share = 0.5 * (1.0 - x * x * (3.0 - 2.0 * x));
  }
  return h;
}

Status KeyLogs::combineRelativeUnchecked(
  const CurveWeights& w, Eigen::Matrix4d& out, MissingLog* missing) const
{
  // Two keys (the Linear type, or wherever only two weights are not zero): the result is the same
  // about either of them (Polar: U^t S^t L_a = (U^t S^(t-1) U^T) U S L_a about b, the polar
  // factors of the inverse step being U^T and U S^-1 U^T; MatrixLog: A (A^-1 B)^t =
  // B (B^-1 A)^(1-t)), so there is nothing to hand over: about the key of larger weight.
  int p = -1, q = -1, nonzero = 0;
  for (int j = 0; j < w.count; ++j)
  {
    if (w.weight[j] != 0.0)
    {
      (p < 0 ? p : q) = j;
      ++nonzero;
    }
  }
  if (nonzero == 2)
  {
    if (!this->Accurate[w.key[p]] && !this->Accurate[w.key[q]])
    {
      return this->combineAbout(w, w.key[w.weight[q] > w.weight[p] ? q : p], out, missing);
    }
    return this->combineTwoIllConditioned(w, p, q, out, missing);
  }
  const HandOver h = handOver(w);
  const int a = h.first, b = h.second;
  const Status status = this->combineAbout(w, w.key[a], out, missing);
  if (status != Status::Ok || h.share == 0.0)
  {
    return status;
  }
  Eigen::Matrix4d other;
  if (this->combineAbout(w, w.key[b], other, nullptr) != Status::Ok)
  {
    return status; // no result about b: keep the one about a
  }
  // s times the step from the result about a to the one about b, taken as every step of the
  // relative form (lct::relativeLog): at s = 1/2 the same point from either side. (The matrix
  // power of the step in the result's own frame, a far-from-normal matrix between stretched
  // keys, failed there, and the curve snapped to the result about a: jumps of 45 sample steps
  // for keys of condition 1e4.)
  const bool accurate = this->Accurate[w.key[a]] || this->Accurate[w.key[b]];
  const auto step = relativeLog(out, other, this->P);
  const auto power = step ? exponential(h.share * step.value, this->P)
                          : Result<Eigen::Matrix4d>::failure(step.status);
  if (power)
  {
    const Eigen::Matrix4d blended = applyRelativeStep(out, power.value, this->P, accurate);
    if (blended.allFinite())
    {
      out = blended;
    }
  }
  return status;
}

Status KeyLogs::combineAbsolute(
  const CurveWeights& w, Eigen::Matrix4d& out, MissingLog* missing) const
{
  LogCoords sum = LogCoords::Zero();
  for (int j = 0; j < w.count; ++j)
  {
    if (this->AbsoluteStatus[w.key[j]] != Status::Ok)
    {
      if (missing)
      {
        *missing = MissingLog{ this->AbsoluteStatus[w.key[j]], w.key[j], w.key[j] };
      }
      return this->AbsoluteStatus[w.key[j]];
    }
    sum += w.weight[j] * this->Absolute[w.key[j]];
  }
  const auto m = exponential(sum, this->P);
  if (!m)
  {
    return m.status;
  }
  const Status check = this->checkResult(w, m.value);
  if (check == Status::Ok)
  {
    out = m.value;
  }
  return check;
}

} // namespace lct
