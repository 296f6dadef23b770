// Meshes for the shape-blender tests, benchmark and regression image: a closed tube along z
// (capped by fans) that can be twisted, and a torus grid. Points and triangles as lct types, and
// their conversion to vtkPolyData.
#ifndef lct_test_ShapeMeshes_h
#define lct_test_ShapeMeshes_h

#include "lct/ShapeBlend.h"

#include "vtkCellArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Geometry>

#include <cmath>
#include <vector>

namespace lct_test
{

struct Mesh
{
  std::vector<Eigen::Vector3d> points;
  std::vector<lct::Triangle> triangles;
};

/// A closed tube of radius r, z in [0, length]: `rings` rings of `around` points, then the two
/// cap centres (bottom, top). Point (ring i, step j) is i * around + j.
inline Mesh tube(int rings, int around, double radius, double length)
{
  Mesh m;
  constexpr double twoPi = 6.28318530717958647692;
  for (int i = 0; i < rings; ++i)
  {
    const double z = length * i / (rings - 1);
    for (int j = 0; j < around; ++j)
    {
      const double a = twoPi * j / around;
      m.points.emplace_back(radius * std::cos(a), radius * std::sin(a), z);
    }
  }
  const std::int64_t bottom = static_cast<std::int64_t>(m.points.size());
  m.points.emplace_back(0.0, 0.0, 0.0);
  m.points.emplace_back(0.0, 0.0, length);
  const auto id = [around](
                    int i, int j) { return static_cast<std::int64_t>(i) * around + (j % around); };
  for (int i = 0; i + 1 < rings; ++i)
  {
    for (int j = 0; j < around; ++j)
    {
      m.triangles.push_back({ id(i, j), id(i, j + 1), id(i + 1, j + 1) });
      m.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i + 1, j) });
    }
  }
  for (int j = 0; j < around; ++j)
  {
    m.triangles.push_back({ bottom, id(0, j + 1), id(0, j) });
    m.triangles.push_back({ bottom + 1, id(rings - 1, j), id(rings - 1, j + 1) });
  }
  return m;
}

/// The points turned about the z axis by angle * z / length (a twist of `angle` at the top).
inline std::vector<Eigen::Vector3d> twisted(
  const std::vector<Eigen::Vector3d>& points, double angle, double length)
{
  std::vector<Eigen::Vector3d> out;
  out.reserve(points.size());
  for (const Eigen::Vector3d& p : points)
  {
    out.push_back(Eigen::AngleAxisd(angle * p.z() / length, Eigen::Vector3d::UnitZ()) * p);
  }
  return out;
}

/// A torus grid of 2 * u * v triangles (radii R > r), in the z = 0 plane.
inline Mesh torus(int u, int v, double major, double minor)
{
  Mesh m;
  constexpr double twoPi = 6.28318530717958647692;
  for (int i = 0; i < u; ++i)
  {
    const double a = twoPi * i / u;
    for (int j = 0; j < v; ++j)
    {
      const double b = twoPi * j / v;
      const double rho = major + minor * std::cos(b);
      m.points.emplace_back(rho * std::cos(a), rho * std::sin(a), minor * std::sin(b));
    }
  }
  const auto id = [u, v](int i, int j) { return static_cast<std::int64_t>(i % u) * v + (j % v); };
  for (int i = 0; i < u; ++i)
  {
    for (int j = 0; j < v; ++j)
    {
      m.triangles.push_back({ id(i, j), id(i + 1, j), id(i + 1, j + 1) });
      m.triangles.push_back({ id(i, j), id(i + 1, j + 1), id(i, j + 1) });
    }
  }
  return m;
}

/// The poly data of points and triangles (double points).
inline vtkSmartPointer<vtkPolyData> toPolyData(
  const std::vector<Eigen::Vector3d>& points, const std::vector<lct::Triangle>& triangles)
{
  vtkNew<vtkPoints> p;
  p->SetDataTypeToDouble();
  p->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    p->SetPoint(static_cast<vtkIdType>(i), points[i].data());
  }
  vtkNew<vtkCellArray> polys;
  for (const lct::Triangle& t : triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  auto pd = vtkSmartPointer<vtkPolyData>::New();
  pd->SetPoints(p);
  pd->SetPolys(polys);
  return pd;
}

inline std::vector<Eigen::Vector3d> pointsOf(vtkPolyData* pd)
{
  std::vector<Eigen::Vector3d> out(pd->GetNumberOfPoints());
  for (vtkIdType i = 0; i < pd->GetNumberOfPoints(); ++i)
  {
    pd->GetPoint(i, out[i].data());
  }
  return out;
}

} // namespace lct_test

#endif
