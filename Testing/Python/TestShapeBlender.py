"""vtkShapeBlenderLCT from Python: a triangulated cylinder and a target
twisted by 180 degrees; weights driven from the script: exact at w = 0 and 1, the radius kept at
w = 0.5 where the linear blend of the points collapses it, weight changes reuse the
factorisation, and the errors a script sees for bad input.

Run by CTest as `/usr/bin/python3 TestShapeBlender.py` with the build tree's package directory
on PYTHONPATH (see Testing/Python/CMakeLists.txt).
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkShapeBlenderLCT
from vtkmodules.vtkCommonCore import vtkCommand, vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData
from vtkmodules.vtkFiltersCore import vtkTriangleFilter

LENGTH = 10.0


def bar():
    """An open cylinder along y of radius 1 and height LENGTH: 41 rings of 24 points joined by
    quads, triangulated by vtkTriangleFilter as a user would."""
    rows, around = 40, 24
    points = vtkPoints()
    points.SetDataTypeToDouble()
    polys = vtkCellArray()
    for i in range(rows + 1):
        y = -LENGTH / 2 + LENGTH * i / rows
        for j in range(around):
            a = 2 * math.pi * j / around
            points.InsertNextPoint(math.cos(a), y, math.sin(a))
    for i in range(rows):
        for j in range(around):
            p0, p1 = i * around + j, i * around + (j + 1) % around
            polys.InsertNextCell(4, (p0, p0 + around, p1 + around, p1))
    quads = vtkPolyData()
    quads.SetPoints(points)
    quads.SetPolys(polys)
    triangles = vtkTriangleFilter()
    triangles.SetInputData(quads)
    triangles.Update()
    mesh = vtkPolyData()
    mesh.DeepCopy(triangles.GetOutput())
    return mesh


def twisted(mesh, angle):
    out = vtkPolyData()
    out.DeepCopy(mesh)
    pts = out.GetPoints()
    for i in range(pts.GetNumberOfPoints()):
        x, y, z = pts.GetPoint(i)
        t = angle * (y + LENGTH / 2) / LENGTH
        pts.SetPoint(i, x * math.cos(t) - z * math.sin(t), y, x * math.sin(t) + z * math.cos(t))
    return out


def max_distance(a, b):
    return max(
        math.dist(a.GetPoint(i), b.GetPoint(i)) for i in range(a.GetNumberOfPoints())
    )


def top_radii(mesh, rest):
    """Radii of the points of the rest mesh's top ring about their centre in `mesh`."""
    top = [i for i in range(rest.GetNumberOfPoints()) if rest.GetPoint(i)[1] == LENGTH / 2]
    ring = [mesh.GetPoint(i) for i in top]
    cx = sum(p[0] for p in ring) / len(ring)
    cz = sum(p[2] for p in ring) / len(ring)
    return [math.hypot(p[0] - cx, p[2] - cz) for p in ring]


class ShapeBlenderTest(unittest.TestCase):
    def setUp(self):
        self.rest = bar()
        self.target = twisted(self.rest, math.pi)
        self.blender = vtkShapeBlenderLCT()
        self.blender.SetInputData(self.rest)
        self.assertEqual(self.blender.AddTarget(self.target), 0)
        self.assertEqual(self.blender.GetNumberOfTargets(), 1)

    def blend(self, w):
        self.assertEqual(self.blender.SetWeight(0, w), 1)
        self.blender.Update()
        return self.blender.GetOutput()

    def test_exact_at_rest_and_target(self):
        self.assertLess(max_distance(self.blend(0.0), self.rest), 1e-9)
        self.assertLess(max_distance(self.blend(1.0), self.target), 1e-9)

    def test_twist_keeps_radius(self):
        radii = top_radii(self.blend(0.5), self.rest)
        self.assertGreater(min(radii), 0.9)
        self.assertLess(max(radii), 1.03)
        # The linear blend of the points: the top ring pinched to a segment through its centre.
        linear = vtkPolyData()
        linear.DeepCopy(self.rest)
        for i in range(linear.GetNumberOfPoints()):
            a, b = self.rest.GetPoint(i), self.target.GetPoint(i)
            linear.GetPoints().SetPoint(i, [0.5 * (u + v) for u, v in zip(a, b)])
        self.assertLess(max(top_radii(linear, self.rest)), 1e-9)

    def test_weights_reuse_the_factorisation(self):
        first = vtkPolyData()
        first.DeepCopy(self.blend(0.3))
        second = self.blend(0.7)
        self.assertGreater(max_distance(first, second), 0.1)
        self.assertEqual(self.blender.GetNumberOfFactorizations(), 1)
        self.assertEqual(self.blender.GetNumberOfLogComputations(), 1)
        self.blend(1.5)  # extrapolation
        self.assertEqual(self.blender.GetNumberOfFactorizations(), 1)

    def test_bad_input(self):
        errors = ErrorRecorder(self.blender)
        ErrorRecorder(self.blender.GetExecutive())
        good = vtkPolyData()
        good.DeepCopy(self.blend(0.5))
        self.assertEqual(self.blender.SetWeight(2, 0.5), 0)
        self.assertIn("target 2 is outside [0, 1)", errors.messages[-1])
        self.assertEqual(self.blender.SetWeight(0, float("nan")), 1)
        self.assertEqual(self.blender.GetExecutive().Update(), 0)
        self.assertIn("the weight of target 0 is nan", errors.messages[-1])
        self.assertEqual(max_distance(self.blender.GetOutput(), good), 0.0)
        self.blender.SetWeight(0, 0.5)
        wrong = vtkPolyData()
        wrong.DeepCopy(self.rest)
        wrong.GetPoints().InsertNextPoint(0.0, 0.0, 0.0)
        self.blender.AddTarget(wrong)
        self.assertEqual(self.blender.GetExecutive().Update(), 0)
        self.assertIn("target 1 has", errors.messages[-1])
        self.assertEqual(max_distance(self.blender.GetOutput(), good), 0.0)
        self.assertEqual(self.blender.AddTarget(None), -1)


if __name__ == "__main__":
    unittest.main()
