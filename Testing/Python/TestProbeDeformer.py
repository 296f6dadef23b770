"""vtkProbeDeformerLCT from Python, as a scripted animation drives it: probes from transforms,
matrices and actors, a twist beyond 2 pi through successive updates, skinning weights from
point-data arrays (numpy-free), every blend mode, and the errors a script sees.

Run by CTest as `/usr/bin/python3 TestProbeDeformer.py` with the build tree's package directory
on PYTHONPATH (see Testing/Python/CMakeLists.txt).
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkProbeDeformerLCT
from vtkmodules.vtkCommonCore import (VTK_DOUBLE, VTK_INT, VTK_LONG_LONG, VTK_SHORT, vtkDoubleArray,
                                      vtkFloatArray, vtkPoints, vtkUnsignedShortArray)
from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkRenderingCore import vtkActor


def column(points_per_unit=4, height=10.0):
    """Points on the z axis offset by (1, 0): a string from z = 0 to z = height."""
    pd = vtkPolyData()
    pts = vtkPoints()
    pts.SetDataTypeToDouble()
    n = int(height * points_per_unit) + 1
    for i in range(n):
        pts.InsertNextPoint(1.0, 0.0, height * i / (n - 1))
    pd.SetPoints(pts)
    return pd


def angle_of(pd, i):
    x, y, _ = pd.GetPoint(i)
    return math.atan2(y, x)


class ProbeDeformerTest(unittest.TestCase):
    def test_twist_beyond_two_pi_in_a_script(self):
        pd = column()
        bottom, top, top_rest = vtkTransform(), vtkTransform(), vtkTransform()
        top_rest.Translate(0, 0, 10)
        top.Translate(0, 0, 10)
        deformer = vtkProbeDeformerLCT()
        self.assertEqual(deformer.AddProbe(bottom), 0)
        self.assertEqual(deformer.AddProbe(top, top_rest), 1)
        deformer.SetInputData(pd)
        for _ in range(12):  # 12 x 45 degrees = 3 pi, one frame each
            top.RotateZ(45)
            deformer.Update()
        log = [0.0, 0.0, 0.0]
        self.assertEqual(deformer.GetProbeRotationLog(1, log), 1)
        self.assertAlmostEqual(log[2], 3 * math.pi, places=9)
        out = deformer.GetOutput()
        # The twist is monotone in height and reaches 3 pi w at the top point, w its
        # inverse-distance weight on the top probe (distances 1 and sqrt(101)).
        w_top = 1.0 / (1.0 + 1.0 / math.sqrt(101.0))
        unwrapped, previous = 0.0, 0.0
        for i in range(out.GetNumberOfPoints()):
            a = angle_of(out, i)
            step = math.remainder(a - previous, 2 * math.pi)
            self.assertGreaterEqual(step, -1e-12)
            unwrapped += step
            previous = a
        self.assertAlmostEqual(unwrapped, 3 * math.pi * w_top, places=9)
        self.assertGreater(unwrapped, 2 * math.pi)  # more than a full turn: the winding kept

    def test_skinning_weights_every_mode_and_probe_kind(self):
        pd = column()
        n = pd.GetNumberOfPoints()
        weights = vtkFloatArray()
        weights.SetName("skin")
        weights.SetNumberOfComponents(2)
        indices = vtkUnsignedShortArray()
        indices.SetName("bones")
        indices.SetNumberOfComponents(2)
        for i in range(n):
            z = pd.GetPoint(i)[2]
            weights.InsertNextTuple2(1.0 - z / 10.0, z / 10.0)
            indices.InsertNextTuple2(2, 0)  # slot 0 -> probe 2 (an actor), slot 1 -> probe 0
        pd.GetPointData().AddArray(weights)
        pd.GetPointData().AddArray(indices)
        moved = vtkMatrix4x4()
        moved.SetElement(0, 3, 4.0)
        actor = vtkActor()  # at rest: the identity
        deformer = vtkProbeDeformerLCT()
        deformer.AddProbe(moved)
        deformer.AddProbe(vtkTransform())
        deformer.AddProbe(actor)
        deformer.SetWeightModeToPointData()
        deformer.SetWeightArrayName("skin")
        deformer.SetTransformIndexArrayName("bones")
        deformer.SetInputData(pd)
        for mode in ("Polar", "MatrixLog", "Linear", "DualQuaternion"):
            getattr(deformer, "SetBlendModeTo" + mode)()
            deformer.Update()
            out = deformer.GetOutput()
            for i in range(n):
                z = pd.GetPoint(i)[2]
                # A pure translation blends to the weighted translation in every mode.
                self.assertAlmostEqual(out.GetPoint(i)[0], 1.0 + 4.0 * z / 10.0, places=6, msg=mode)
        # Moving the actor re-executes the pipeline (MTime follows the probes).
        actor.SetPosition(0, 2, 0)
        deformer.Update()
        self.assertAlmostEqual(deformer.GetOutput().GetPoint(0)[1], 2.0, places=9)

    def test_errors_a_script_sees(self):
        pd = column()
        deformer = vtkProbeDeformerLCT()
        errors = ErrorRecorder(deformer)
        deformer.SetInputData(pd)
        self.assertEqual(deformer.GetExecutive().Update(), 0)
        self.assertIn("no probes", errors.messages[-1])
        self.assertEqual(deformer.AddProbe(vtkPolyData()), -1)
        self.assertIn("vtkPolyData", errors.messages[-1])
        bad = vtkMatrix4x4()
        bad.SetElement(2, 2, float("nan"))
        deformer.AddProbe(bad)
        self.assertEqual(deformer.GetExecutive().Update(), 0)
        self.assertIn("probe 0: the current matrix is invalid", errors.messages[-1])
        self.assertEqual(deformer.GetOutput().GetNumberOfPoints(), 0)
        good = vtkTransform()
        self.assertEqual(deformer.SetProbe(0, good, None), 1)
        self.assertEqual(deformer.GetExecutive().Update(), 1)
        deformer.SetWeightModeToPointData()
        deformer.SetWeightArrayName("missing")
        self.assertEqual(deformer.GetExecutive().Update(), 0)
        self.assertIn("no point-data array named 'missing'", errors.messages[-1])
        # The last valid output is kept.
        self.assertEqual(deformer.GetOutput().GetNumberOfPoints(), pd.GetNumberOfPoints())
        self.assertEqual(deformer.SetProbeRadius(0, 0.0), 0)

    def test_integer_points_are_blended_as_double(self):
        # Integer points were read through a float pointer to a double copy: (10, 0, 0) under a
        # translation by (1, 2, 3) came out as (1, 4.56, 3), status OK.
        for data_type in (VTK_INT, VTK_SHORT, VTK_LONG_LONG):
            points = vtkPoints()
            points.SetDataType(data_type)
            for p in ((10, 0, 0), (5, 5, 5), (-3, 7, 1)):
                points.InsertNextPoint(p)
            mesh = vtkPolyData()
            mesh.SetPoints(points)
            move = vtkTransform()
            move.Translate(1, 2, 3)
            deformer = vtkProbeDeformerLCT()
            deformer.AddProbe(move)
            deformer.SetInputData(mesh)
            deformer.Update()
            out = deformer.GetOutput().GetPoints()
            self.assertEqual(out.GetDataType(), VTK_DOUBLE)
            for i, p in enumerate(((11, 2, 3), (6, 7, 8), (-2, 9, 4))):
                self.assertEqual(out.GetPoint(i), p)

    def test_rotation_history_survives_add_probe_and_other_modes(self):
        # A probe driven through 3 pi; AddProbe (of a probe no weight uses) and one execution in
        # Linear cleared every probe's history, and the bar snapped back from 270 to 90 degrees.
        mesh = vtkPolyData()
        points = vtkPoints()
        points.SetDataTypeToDouble()
        weights = vtkDoubleArray()
        weights.SetName("w")
        weights.SetNumberOfComponents(2)
        for k in range(11):
            points.InsertNextPoint(1, 0, k)
            weights.InsertNextTuple2(1 - k / 10, k / 10)
        mesh.SetPoints(points)
        mesh.GetPointData().AddArray(weights)
        bottom, top = vtkTransform(), vtkTransform()
        deformer = vtkProbeDeformerLCT()
        deformer.AddProbe(bottom)
        deformer.AddProbe(top)
        deformer.SetWeightModeToPointData()
        deformer.SetWeightArrayName("w")
        deformer.SetInputData(mesh)
        for degrees in range(0, 541, 30):
            top.Identity()
            top.RotateZ(degrees)
            deformer.Update()

        def middle():
            deformer.Update()
            p = deformer.GetOutput().GetPoint(5)
            return p[0], p[1]

        for a, b in zip(middle(), (0, -1)):  # half of 540 degrees
            self.assertAlmostEqual(a, b, places=9)
        deformer.AddProbe(vtkTransform())
        for a, b in zip(middle(), (0, -1)):
            self.assertAlmostEqual(a, b, places=9)
        deformer.SetBlendModeToLinear()
        deformer.Update()
        deformer.SetBlendModeToPolar()
        for a, b in zip(middle(), (0, -1)):
            self.assertAlmostEqual(a, b, places=9)

    def test_unnamed_normals_are_listed_once(self):
        mesh = vtkPolyData()
        points = vtkPoints()
        normals = vtkFloatArray()
        normals.SetNumberOfComponents(3)
        for k in range(4):
            points.InsertNextPoint(k, 0, 0)
            normals.InsertNextTuple3(0, 0, 1)
        mesh.SetPoints(points)
        mesh.GetPointData().SetNormals(normals)
        turn = vtkTransform()
        turn.RotateX(90)
        deformer = vtkProbeDeformerLCT()
        deformer.AddProbe(turn)
        deformer.SetInputData(mesh)
        deformer.Update()
        data = deformer.GetOutput().GetPointData()
        self.assertEqual(data.GetNumberOfArrays(), 1)
        n = data.GetNormals().GetTuple3(0)
        self.assertAlmostEqual(n[1], -1.0, places=6)


if __name__ == "__main__":
    unittest.main()
