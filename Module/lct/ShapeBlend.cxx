#include "lct/ShapeBlend.h"

#include "lct/Conditioning.h"
#include "lct/PolarParametrisation.h"
#include "lct/SO3.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <mutex>
#include <numeric>
#include <utility>

namespace lct
{

namespace
{
using Index = std::int64_t;

void runParallel(
  const ParallelFor& parallel, Index n, const std::function<void(std::int64_t, std::int64_t)>& body)
{
  if (parallel)
  {
    parallel(n, body);
  }
  else
  {
    body(0, n);
  }
}

/// The lowest-numbered failure seen by any thread.
class FirstFailure
{
public:
  void record(const ShapeBlendIssue& issue)
  {
    const std::lock_guard<std::mutex> guard(this->Lock);
    if (this->Issue.ok() || issue.face < this->Issue.face)
    {
      this->Issue = issue;
    }
  }
  ShapeBlendIssue get() const { return this->Issue; }

private:
  std::mutex Lock;
  ShapeBlendIssue Issue;
};

/// [b - a, c - a, ghost - a]: the edge matrix of Sumner & Popović with Kaji's ghost vertex.
Eigen::Matrix3d edgeMatrix(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  Eigen::Matrix3d e;
  e.col(0) = b - a;
  e.col(1) = c - a;
  e.col(2) = ghostVertex(a, b, c) - a;
  return e;
}

/// Union-find over points, for the vertex-connected pieces.
Index findRoot(std::vector<Index>& parent, Index v)
{
  while (parent[v] != v)
  {
    parent[v] = parent[parent[v]];
    v = parent[v];
  }
  return v;
}

/// The exact sum of doubles as non-overlapping partials of increasing magnitude (Shewchuk's
/// grow-expansion, as Python's math.fsum), rounded once at the end.
class ExactSum
{
public:
  void add(double x)
  {
    std::size_t kept = 0;
    for (double y : this->Partials)
    {
      if (std::abs(x) < std::abs(y))
      {
        std::swap(x, y);
      }
      const double hi = x + y;
      const double lo = y - (hi - x); // exact: x + y = hi + lo
      if (lo != 0.0)
      {
        this->Partials[kept++] = lo;
      }
      x = hi;
    }
    this->Partials.resize(kept);
    this->Partials.push_back(x);
  }
  double value() const
  {
    double sum = 0.0;
    for (auto p = this->Partials.rbegin(); p != this->Partials.rend(); ++p)
    {
      sum += *p;
    }
    return sum;
  }

private:
  std::vector<double> Partials;
};

/// Per piece, the centroid of `points` (pieceOf maps points to pieces). Summed exactly: the
/// centroid becomes a translation of the blend, whose pieces can be far smaller than the meshes
/// (halfway between a mesh and its copy scaled by S, sqrt S). A plain sum is off by ~eps S for
/// points of size S even when their centroid is 0, which moved that blend by eps sqrt S times its
/// size (433 sizes at S = 1e40; at S = 1e80 every point rounded to the same one).
std::vector<Eigen::Vector3d> pieceCentroids(const std::vector<Eigen::Vector3d>& points,
  const std::vector<Index>& pieceOf, const std::vector<Index>& pieceSize)
{
  std::vector<std::array<ExactSum, 3>> sums(pieceSize.size());
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    for (int i = 0; i < 3; ++i)
    {
      sums[pieceOf[v]][i].add(points[v][i]);
    }
  }
  std::vector<Eigen::Vector3d> c(pieceSize.size());
  for (std::size_t p = 0; p < c.size(); ++p)
  {
    for (int i = 0; i < 3; ++i)
    {
      c[p][i] = sums[p][i].value() / static_cast<double>(pieceSize[p]);
    }
  }
  return c;
}
} // namespace

Eigen::Vector3d ghostVertex(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d n = (b - a).cross(c - a);
  return (a + b + c) / 3.0 + n / std::sqrt(n.stableNorm());
}

namespace
{
/// A triangle's squared longest edge and |n|, twice its area.
struct TriangleMeasure
{
  double longest;
  double n;
};

TriangleMeasure measureTriangle(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return { std::max({ (b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm() }),
    (b - a).cross(c - a).stableNorm() }; // |n| up to 2^961 (kTriangleScaleExponent)
}
} // namespace

bool isDegenerateTriangle(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const TriangleMeasure m = measureTriangle(a, b, c);
  // Written so that NaN (and a zero longest edge) counts as degenerate.
  return !(m.n > kDegenerateTriangleRatio * m.longest) || !std::isfinite(m.n) ||
    !std::isfinite(m.longest);
}

double triangleThinness(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const TriangleMeasure m = measureTriangle(a, b, c);
  return m.n / m.longest;
}

double triangleSize(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  return std::max({ (b - a).cwiseAbs().maxCoeff(), (c - a).cwiseAbs().maxCoeff(),
    (c - b).cwiseAbs().maxCoeff() });
}

bool isTriangleScaleInRange(
  const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const double largest = triangleSize(a, b, c);
  return largest == 0.0 ||
    (largest <= std::ldexp(1.0, kTriangleScaleExponent) &&
      largest >= std::ldexp(1.0, -kTriangleScaleExponent));
}

struct ShapeBlender::Data
{
  bool HasRest = false;
  Index Points = 0;
  std::vector<Triangle> Triangles;
  /// Per face: the inverse of the rest edge matrix, E_0^-1 (A = E E_0^-1).
  std::vector<Eigen::Matrix3d> RestInverse;
  /// Per face: H = G_0 (I - g g^T / |g|^2), the ghost-eliminated operator: rows are the face's
  /// three points, J_j = X^T H for X the 3x3 matrix of their positions (one per row).
  std::vector<Eigen::Matrix3d> H;
  /// Face adjacency across edges (CSR).
  std::vector<Index> AdjacencyStart;
  std::vector<Index> Adjacency;
  /// Pieces: per point its piece; per piece its size and its pinned (lowest) point.
  std::vector<Index> PieceOf;
  std::vector<Index> PieceSize;
  /// Per point its unknown, or -1 for a pinned point.
  std::vector<Index> Unknown;
  Index Unknowns = 0;
  std::vector<Eigen::Vector3d> RestCentroids;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> Solver;
  /// Per target: per-face logs and per-piece centroids.
  std::vector<std::vector<LogCoords>> Logs;
  std::vector<std::vector<Eigen::Vector3d>> TargetCentroids;
};

ShapeBlender::ShapeBlender()
  : D(new Data)
{
}

ShapeBlender::~ShapeBlender() = default;

bool ShapeBlender::hasRest() const noexcept
{
  return this->D->HasRest;
}

std::int64_t ShapeBlender::numberOfPoints() const noexcept
{
  return this->D->Points;
}

std::int64_t ShapeBlender::numberOfFaces() const noexcept
{
  return static_cast<Index>(this->D->Triangles.size());
}

int ShapeBlender::numberOfTargets() const noexcept
{
  return static_cast<int>(this->D->Logs.size());
}

std::int64_t ShapeBlender::numberOfPieces() const noexcept
{
  return static_cast<Index>(this->D->PieceSize.size());
}

std::int64_t ShapeBlender::numberOfUnknowns() const noexcept
{
  return this->D->Unknowns;
}

const LogCoords& ShapeBlender::faceLog(int target, std::int64_t face) const
{
  return this->D->Logs[target][face];
}

ShapeBlendIssue ShapeBlender::setRest(const std::vector<Eigen::Vector3d>& points,
  const std::vector<Triangle>& triangles, const ParallelFor& parallel)
{
  Data& d = *this->D;
  d.HasRest = false;
  d.Logs.clear();
  d.TargetCentroids.clear();
  const Index n = static_cast<Index>(points.size());
  const Index m = static_cast<Index>(triangles.size());
  if (m == 0)
  {
    return { Status::InvalidArgument };
  }
  for (Index v = 0; v < n; ++v)
  {
    if (!points[v].allFinite())
    {
      return { Status::NonFinite, -1, -1, v };
    }
  }
  for (Index j = 0; j < m; ++j)
  {
    for (const Index v : triangles[j])
    {
      if (v < 0 || v >= n)
      {
        return { Status::InvalidArgument, -1, j };
      }
    }
  }

  // Per face: E_0^-1 and H, in parallel; the lowest degenerate face is reported.
  d.RestInverse.resize(m);
  d.H.resize(m);
  FirstFailure failure;
  runParallel(parallel, m, [&](Index begin, Index end) {
    Eigen::Matrix<double, 4, 3> difference; // the rows of [x1 x2 x3 g] -> edge-matrix columns
    difference << -1, -1, -1, 1, 0, 0, 0, 1, 0, 0, 0, 1;
    for (Index j = begin; j < end; ++j)
    {
      const Triangle& t = triangles[j];
      const Eigen::Vector3d &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
      if (!isTriangleScaleInRange(a, b, c))
      {
        failure.record({ Status::OutOfRange, -1, j });
        return;
      }
      if (isDegenerateTriangle(a, b, c))
      {
        failure.record({ Status::Singular, -1, j });
        return;
      }
      // E_0 is inverted at unit size (2^-e E_0 is exact): its determinant |n|^(3/2) grows as the
      // cube of the triangle and leaves double's range beyond ~2^+-340, well inside
      // kTriangleScaleExponent, where a plain inverse holds Inf/NaN (small) or 0 (large).
      const Eigen::Matrix3d e0 = edgeMatrix(a, b, c);
      const int e = unitScaleExponent(e0);
      d.RestInverse[j] =
        scaledByPowerOfTwo(Eigen::Matrix3d(scaledByPowerOfTwo(e0, -e).inverse()), -e);
      // J = [x1 x2 x3 g] G with G = difference E_0^-1; the ghost row g3 of G is solved out.
      const Eigen::Matrix<double, 4, 3> g = difference * d.RestInverse[j];
      const Eigen::RowVector3d g3 = g.row(3);
      const Eigen::Matrix3d projector =
        Eigen::Matrix3d::Identity() - g3.transpose() * g3 / g3.squaredNorm();
      d.H[j] = g.topRows<3>() * projector;
      // H H^T scales as 1 / (size^2 sine): a tiny, thin triangle can still overflow it, and NaN
      // would pass the factorisation unnoticed.
      if (!(d.H[j] * d.H[j].transpose()).allFinite())
      {
        failure.record({ Status::OutOfRange, -1, j });
        return;
      }
    }
  });
  if (!failure.get().ok())
  {
    return failure.get();
  }

  // Face adjacency across shared edges.
  std::vector<std::pair<std::pair<Index, Index>, Index>> edges;
  edges.reserve(3 * m);
  for (Index j = 0; j < m; ++j)
  {
    for (int e = 0; e < 3; ++e)
    {
      const Index a = triangles[j][e], b = triangles[j][(e + 1) % 3];
      edges.push_back({ { std::min(a, b), std::max(a, b) }, j });
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<Index, Index>> links;
  for (std::size_t i = 0; i < edges.size();)
  {
    std::size_t k = i;
    while (k < edges.size() && edges[k].first == edges[i].first)
    {
      ++k;
    }
    for (std::size_t p = i; p < k; ++p)
    {
      for (std::size_t q = p + 1; q < k; ++q)
      {
        if (edges[p].second != edges[q].second)
        {
          links.push_back({ edges[p].second, edges[q].second });
          links.push_back({ edges[q].second, edges[p].second });
        }
      }
    }
    i = k;
  }
  std::sort(links.begin(), links.end());
  links.erase(std::unique(links.begin(), links.end()), links.end());
  d.AdjacencyStart.assign(m + 1, 0);
  d.Adjacency.resize(links.size());
  for (std::size_t i = 0; i < links.size(); ++i)
  {
    ++d.AdjacencyStart[links[i].first + 1];
    d.Adjacency[i] = links[i].second;
  }
  std::partial_sum(d.AdjacencyStart.begin(), d.AdjacencyStart.end(), d.AdjacencyStart.begin());

  // Vertex-connected pieces; the lowest point of each is pinned.
  std::vector<Index> parent(n);
  std::iota(parent.begin(), parent.end(), Index{ 0 });
  for (const Triangle& t : triangles)
  {
    for (int e = 1; e < 3; ++e)
    {
      const Index ra = findRoot(parent, t[0]), rb = findRoot(parent, t[e]);
      if (ra != rb)
      {
        parent[std::max(ra, rb)] = std::min(ra, rb);
      }
    }
  }
  d.PieceOf.assign(n, -1);
  d.PieceSize.clear();
  d.Unknown.assign(n, -1);
  std::vector<Index> pieceOfRoot(n, -1);
  d.Unknowns = 0;
  for (Index v = 0; v < n; ++v)
  {
    const Index r = findRoot(parent, v);
    if (pieceOfRoot[r] < 0)
    {
      // v is the lowest point of its piece (roots are the minima): pinned.
      pieceOfRoot[r] = static_cast<Index>(d.PieceSize.size());
      d.PieceSize.push_back(0);
    }
    else
    {
      d.Unknown[v] = d.Unknowns++;
    }
    d.PieceOf[v] = pieceOfRoot[r];
    ++d.PieceSize[d.PieceOf[v]];
  }
  d.RestCentroids = pieceCentroids(points, d.PieceOf, d.PieceSize);

  // The normal equations sum_j S_j^T H_j H_j^T S_j over the free points, factorised once.
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(9 * m);
  for (Index j = 0; j < m; ++j)
  {
    const Eigen::Matrix3d local = d.H[j] * d.H[j].transpose();
    for (int r = 0; r < 3; ++r)
    {
      const Index ur = d.Unknown[triangles[j][r]];
      for (int c = 0; c < 3 && ur >= 0; ++c)
      {
        const Index uc = d.Unknown[triangles[j][c]];
        if (uc >= 0)
        {
          entries.emplace_back(ur, uc, local(r, c));
        }
      }
    }
  }
  Eigen::SparseMatrix<double> normal(d.Unknowns, d.Unknowns);
  normal.setFromTriplets(entries.begin(), entries.end());
  d.Solver.compute(normal);
  if (d.Solver.info() != Eigen::Success)
  {
    return { Status::NumericalFailure };
  }
  d.Triangles = triangles;
  d.Points = n;
  d.HasRest = true;
  return {};
}

ShapeBlendIssue ShapeBlender::setTargets(
  const std::vector<std::vector<Eigen::Vector3d>>& targets, const ParallelFor& parallel)
{
  Data& d = *this->D;
  if (!d.HasRest)
  {
    return { Status::InvalidArgument };
  }
  const Index m = static_cast<Index>(d.Triangles.size());
  std::vector<std::vector<LogCoords>> logs(targets.size());
  std::vector<std::vector<Eigen::Vector3d>> centroids(targets.size());
  for (std::size_t i = 0; i < targets.size(); ++i)
  {
    const int target = static_cast<int>(i);
    const std::vector<Eigen::Vector3d>& points = targets[i];
    if (static_cast<Index>(points.size()) != d.Points)
    {
      return { Status::InvalidArgument, target };
    }
    for (Index v = 0; v < d.Points; ++v)
    {
      if (!points[v].allFinite())
      {
        return { Status::NonFinite, target, -1, v };
      }
    }
    // Principal logs per face, in parallel.
    std::vector<LogCoords>& faceLogs = logs[i];
    faceLogs.resize(m);
    FirstFailure failure;
    runParallel(parallel, m, [&](Index begin, Index end) {
      for (Index j = begin; j < end; ++j)
      {
        const Triangle& t = d.Triangles[j];
        const Eigen::Vector3d &a = points[t[0]], &b = points[t[1]], &c = points[t[2]];
        if (!isTriangleScaleInRange(a, b, c))
        {
          failure.record({ Status::OutOfRange, target, j });
          return;
        }
        if (isDegenerateTriangle(a, b, c))
        {
          failure.record({ Status::Singular, target, j });
          return;
        }
        Eigen::Matrix4d map = Eigen::Matrix4d::Identity();
        map.topLeftCorner<3, 3>() = edgeMatrix(a, b, c) * d.RestInverse[j];
        const Result<LogCoords> log = polarLog(map);
        if (!log.ok())
        {
          failure.record({ log.status, target, j });
          return;
        }
        faceLogs[j] = log.value;
      }
    });
    if (!failure.get().ok())
    {
      return failure.get();
    }
    // Consistent rotation branches: per edge-connected piece, a breadth-first walk from the face
    // that turned least, each face's rotation log nearest its parent's (Alg. 1).
    std::vector<Index> byAngle(m);
    std::iota(byAngle.begin(), byAngle.end(), Index{ 0 });
    std::stable_sort(byAngle.begin(), byAngle.end(), [&](Index p, Index q) {
      return rotationPart(faceLogs[p]).squaredNorm() < rotationPart(faceLogs[q]).squaredNorm();
    });
    std::vector<char> visited(m, 0);
    std::vector<Index> queue;
    queue.reserve(m);
    for (const Index root : byAngle)
    {
      if (visited[root])
      {
        continue;
      }
      visited[root] = 1;
      queue.clear();
      queue.push_back(root);
      for (std::size_t head = 0; head < queue.size(); ++head)
      {
        const Index f = queue[head];
        for (Index k = d.AdjacencyStart[f]; k < d.AdjacencyStart[f + 1]; ++k)
        {
          const Index g = d.Adjacency[k];
          if (!visited[g])
          {
            visited[g] = 1;
            rotationPart(faceLogs[g]) =
              nearestEquivalentRotation(rotationPart(faceLogs[g]), rotationPart(faceLogs[f]));
            queue.push_back(g);
          }
        }
      }
    }
    centroids[i] = pieceCentroids(points, d.PieceOf, d.PieceSize);
  }
  d.Logs = std::move(logs);
  d.TargetCentroids = std::move(centroids);
  return {};
}

ShapeBlendIssue ShapeBlender::blend(const std::vector<double>& weights,
  std::vector<Eigen::Vector3d>& out, const ParallelFor& parallel) const
{
  const Data& d = *this->D;
  if (!d.HasRest || weights.size() != d.Logs.size())
  {
    return { Status::InvalidArgument };
  }
  for (std::size_t i = 0; i < weights.size(); ++i)
  {
    if (!std::isfinite(weights[i]))
    {
      return { Status::NonFinite, static_cast<int>(i) };
    }
  }
  const Index m = static_cast<Index>(d.Triangles.size());
  const std::size_t k = weights.size();
  // Per face: B_j = phi(sum_i w_i psi(A_ij)), then its right-hand side H_j B_j^T.
  std::vector<Eigen::Matrix3d> local(m);
  FirstFailure failure;
  runParallel(parallel, m, [&](Index begin, Index end) {
    for (Index j = begin; j < end; ++j)
    {
      LogCoords c = LogCoords::Zero();
      for (std::size_t i = 0; i < k; ++i)
      {
        c += weights[i] * d.Logs[i][j];
      }
      const Result<Eigen::Matrix4d> map = polarExp(c);
      if (!map.ok())
      {
        failure.record({ map.status, -1, j });
        return;
      }
      local[j] = map.value.topLeftCorner<3, 3>();
    }
  });
  if (!failure.get().ok())
  {
    return failure.get();
  }
  // The right-hand side at the unit size of the largest B_j, the solution scaled back (exact
  // powers of two): H ~ 1 / (rest size) and B ~ (blend size) / (rest size), so for meshes more
  // than ~2^540 apart in size (both inside kTriangleScaleExponent) the plain products H B^T
  // overflow, or underflow to a silently wrong blend, though the blend itself is in range.
  int scale = std::numeric_limits<int>::min();
  for (const Eigen::Matrix3d& b : local)
  {
    scale = std::max(scale, unitScaleExponent(b));
  }
  runParallel(parallel, m, [&](Index begin, Index end) {
    for (Index j = begin; j < end; ++j)
    {
      local[j] = d.H[j] * scaledByPowerOfTwo(local[j], -scale).transpose();
    }
  });
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(d.Unknowns, 3);
  for (Index j = 0; j < m; ++j)
  {
    for (int r = 0; r < 3; ++r)
    {
      const Index u = d.Unknown[d.Triangles[j][r]];
      if (u >= 0)
      {
        rhs.row(u) += local[j].row(r);
      }
    }
  }
  const Eigen::MatrixXd unitX = d.Solver.solve(rhs);
  if (d.Solver.info() != Eigen::Success)
  {
    return { Status::NumericalFailure };
  }
  const Eigen::MatrixXd x = scaledByPowerOfTwo(unitX, scale);
  if (!x.allFinite())
  {
    return { Status::OutOfRange }; // the right-hand side or the solve overflowed
  }
  // Pinned points at 0; then each piece moves so its centroid is the blend of the centroids.
  std::vector<Eigen::Vector3d> result(d.Points, Eigen::Vector3d::Zero());
  for (Index v = 0; v < d.Points; ++v)
  {
    if (d.Unknown[v] >= 0)
    {
      result[v] = x.row(d.Unknown[v]).transpose();
    }
  }
  std::vector<Eigen::Vector3d> centroids = pieceCentroids(result, d.PieceOf, d.PieceSize);
  double restWeight = 1.0;
  for (const double w : weights)
  {
    restWeight -= w;
  }
  for (std::size_t p = 0; p < centroids.size(); ++p)
  {
    Eigen::Vector3d wanted = restWeight * d.RestCentroids[p];
    for (std::size_t i = 0; i < k; ++i)
    {
      wanted += weights[i] * d.TargetCentroids[i][p];
    }
    centroids[p] = wanted - centroids[p];
  }
  for (Index v = 0; v < d.Points; ++v)
  {
    result[v] += centroids[d.PieceOf[v]];
  }
  for (const Eigen::Vector3d& p : result)
  {
    if (!p.allFinite())
    {
      return { Status::OutOfRange };
    }
  }
  out = std::move(result);
  return {};
}

} // namespace lct
