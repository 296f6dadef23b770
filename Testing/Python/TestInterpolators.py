"""vtkTransformInterpolatorLCT and vtkCameraInterpolatorLCT from Python, as drop-ins for VTK's
interpolators: keys reproduced (including shear and the window centre), VTK's semantics (clamping,
replacement, props as keys), and bad keys reported with an ErrorEvent and a 0 return.

Run by CTest with /usr/bin/python3 and the build tree on PYTHONPATH.
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkCameraInterpolatorLCT, vtkTransformInterpolatorLCT
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkRenderingCore import vtkActor, vtkCamera, vtkTransformInterpolator

TOL = 1e-12


def elements(m):
    return [m.GetElement(i, j) for i in range(4) for j in range(4)]


def sheared_key(k):
    shear = vtkMatrix4x4()
    shear.SetElement(0, 1, 0.2 * k)
    t = vtkTransform()
    t.PostMultiply()
    t.Concatenate(shear)
    t.Scale(1.0 + 0.3 * k, 1.0, 0.8)
    t.RotateWXYZ(55.0 * k, 0.3, 1.0, 0.2)
    t.Translate(k, 0.5 * k, 0.0)
    return t


class TransformInterpolator(unittest.TestCase):
    def setUp(self):
        self.lct = vtkTransformInterpolatorLCT()
        self.vtk = vtkTransformInterpolator()
        for k in range(5):
            self.assertEqual(self.lct.AddTransform(float(k), sheared_key(k)), 1)
            self.vtk.AddTransform(float(k), sheared_key(k))

    def test_keys_are_reproduced_where_vtk_misses_them(self):
        worst_vtk = 0.0
        for kind in ("Linear", "Spline", "Subdivision", "Bezier"):
            getattr(self.lct, "SetInterpolationTypeTo" + kind)()
            for k in range(5):
                out = vtkTransform()
                self.assertEqual(self.lct.InterpolateTransform(float(k), out), 1)
                for a, b in zip(elements(out.GetMatrix()), elements(sheared_key(k).GetMatrix())):
                    self.assertAlmostEqual(a, b, delta=TOL * 10)
        for k in range(5):
            out = vtkTransform()
            self.vtk.InterpolateTransform(float(k), out)
            worst_vtk = max(worst_vtk, max(abs(a - b) for a, b in zip(
                elements(out.GetMatrix()), elements(sheared_key(k).GetMatrix()))))
        self.assertGreater(worst_vtk, 1e-2)

    def test_vtk_semantics(self):
        out = vtkMatrix4x4()
        self.assertEqual(self.lct.InterpolateTransform(-3.0, out), 1)  # clamped
        self.assertAlmostEqual(out.GetElement(0, 3), 0.0, delta=TOL)
        self.lct.AddTransform(4.0, vtkTransform())  # same time: replaces
        self.assertEqual(self.lct.GetNumberOfTransforms(), 5)
        self.lct.InterpolateTransform(9.0, out)
        self.assertEqual(elements(out), elements(vtkTransform().GetMatrix()))
        actor = vtkActor()
        actor.SetPosition(1, 2, 3)
        self.assertEqual(self.lct.AddTransform(5.0, actor), 1)
        self.lct.RemoveTransform(5.0)
        self.assertEqual(self.lct.GetMaximumT(), 4.0)

    def test_bad_keys(self):
        errors = ErrorRecorder(self.lct)
        for bad in ((0, 1, float("nan")), (2, 2, -1.0), (3, 0, 0.5)):
            m = vtkMatrix4x4()
            m.SetElement(*bad)
            self.assertEqual(self.lct.AddTransform(2.5, m), 0)
        self.assertEqual(errors.count, 3)
        self.assertEqual(self.lct.GetNumberOfTransforms(), 5)
        empty = vtkTransformInterpolatorLCT()
        empty_errors = ErrorRecorder(empty)
        self.assertEqual(empty.InterpolateTransform(0.0, vtkTransform()), 0)
        self.assertEqual(empty_errors.count, 1)


class CameraInterpolator(unittest.TestCase):
    def test_window_centre_and_turns(self):
        path = vtkCameraInterpolatorLCT()
        keys = []
        for k, (azimuth, center) in enumerate(((0, (0.0, 0.0)), (100, (0.4, -0.2)),
                                               (200, (0.1, 0.3)))):
            c = vtkCamera()
            a = math.radians(azimuth)
            c.SetPosition(6 * math.cos(a), 6 * math.sin(a), 1.0)
            c.SetViewUp(0, 0, 1)
            c.SetWindowCenter(*center)
            self.assertEqual(path.AddCamera(float(k), c), 1)
            keys.append(c)
        for k, key in enumerate(keys):
            out = vtkCamera()
            self.assertEqual(path.InterpolateCamera(float(k), out), 1)
            for a, b in zip(out.GetPosition(), key.GetPosition()):
                self.assertAlmostEqual(a, b, delta=1e-9)
            for a, b in zip(out.GetWindowCenter(), key.GetWindowCenter()):
                self.assertAlmostEqual(a, b, delta=1e-12)
        mid = vtkCamera()
        path.InterpolateCamera(0.5, mid)
        self.assertAlmostEqual(mid.GetDistance(), math.hypot(6.0, 1.0), delta=1e-9)

    def test_bad_cameras(self):
        path = vtkCameraInterpolatorLCT()
        errors = ErrorRecorder(path)
        degenerate = vtkCamera()
        degenerate.SetPosition(0, 0, 0)
        degenerate.SetFocalPoint(0, 0, 0)
        self.assertEqual(path.AddCamera(0.0, degenerate), 0)
        self.assertEqual(path.AddCamera(0.0, vtkCamera()), 1)
        parallel = vtkCamera()
        parallel.ParallelProjectionOn()
        self.assertEqual(path.AddCamera(1.0, parallel), 0)
        self.assertEqual(errors.count, 2)
        self.assertEqual(path.GetNumberOfCameras(), 1)



class Issue12(unittest.TestCase):
    def test_impact_keys_get_nearly_straight_segments(self):
        # A spike on a line: a quarter into the segment after it, near the chord (87.5) with
        # StraightenImpacts on (default), the cubic's dwell (92.1875) with it off.
        values = {}
        for straighten in (1, 0):
            path = vtkTransformInterpolatorLCT()
            self.assertEqual(path.GetStraightenImpacts(), 1)
            path.SetStraightenImpacts(straighten)
            for k, x in enumerate((0, 10, 20, 30, 100, 50, 60, 70, 80)):
                t = vtkTransform()
                t.Translate(x, 0, 0)
                self.assertEqual(path.AddTransform(k, t), 1)
            m = vtkMatrix4x4()
            self.assertEqual(path.InterpolateTransform(4.25, m), 1)
            values[straighten] = m.GetElement(0, 3)
        self.assertAlmostEqual(values[1], 87.5, delta=0.5)
        self.assertAlmostEqual(values[0], 92.1875, delta=1e-9)

    def test_monotone_tangents_do_not_swing_past_the_keys(self):
        peaks = {}
        for monotone in (1, 0):
            path = vtkTransformInterpolatorLCT()
            path.SetMonotoneTangents(monotone)
            self.assertEqual(path.GetMonotoneTangents(), monotone)
            for k, angle in enumerate((0.0, 179.9, 180.0)):
                t = vtkTransform()
                t.RotateZ(angle)
                self.assertEqual(path.AddTransform(k, t), 1)
            m = vtkMatrix4x4()
            peak = 0.0
            for s in range(2001):
                self.assertEqual(path.InterpolateTransform(2.0 * s / 2000, m), 1)
                a = math.degrees(math.atan2(m.GetElement(1, 0), m.GetElement(0, 0)))
                peak = max(peak, a + 360.0 if a < -90.0 else a)
            peaks[monotone] = peak
        self.assertLessEqual(peaks[1], 180.0 + 1e-9)
        self.assertGreater(peaks[0], 185.0)  # plain Catmull-Rom overshoots

    def test_camera_spline_does_not_zoom_past_a_key(self):
        # A zoom 40 -> 20 degrees, then a turn at 20 degrees: the default (monotone tangents for
        # each part of the camera) holds 20 degrees while it turns; Catmull-Rom zooms past it.
        lowest = {}
        for monotone in (1, 0):
            path = vtkCameraInterpolatorLCT()
            path.SetMonotoneTangents(monotone)
            self.assertEqual(path.GetMonotoneTangents(), monotone)
            for k, (azimuth, angle) in enumerate(((0, 40.0), (0, 20.0), (45, 20.0))):
                c = vtkCamera()
                a = math.radians(azimuth)
                c.SetPosition(5 * math.cos(a), 5 * math.sin(a), 0.0)
                c.SetViewUp(0, 0, 1)
                c.SetViewAngle(angle)
                self.assertEqual(path.AddCamera(float(k), c), 1)
            out = vtkCamera()
            angles = []
            for s in range(401):
                self.assertEqual(path.InterpolateCamera(2.0 * s / 400, out), 1)
                angles.append(out.GetViewAngle())
            lowest[monotone] = min(angles)
        self.assertGreaterEqual(lowest[1], 20.0 - 1e-9)
        self.assertLess(lowest[0], 19.5)

    def test_segment_metric_against_the_keys(self):
        from vtklct import vtkCameraPathMetric
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkRenderingCore import vtkCameraInterpolator

        lct, vtk, metric = vtkCameraInterpolatorLCT(), vtkCameraInterpolator(), vtkCameraPathMetric()
        for k in range(3):
            c = vtkCamera()
            c.SetPosition(8 * math.sin(0.5 * k), 1, 8 * math.cos(0.5 * k))
            c.SetWindowCenter(0.3 * (k == 1), 0.0)
            lct.AddCamera(k, c)
            vtk.AddCamera(k, c)
            self.assertEqual(metric.AddKeyCamera(k, c), 1)
        points = vtkPoints()
        for i in range(27):
            points.InsertNextPoint(i % 3 - 1, (i // 3) % 3 - 1, i // 9 - 1)
        metric.SetPoints(points)
        self.assertEqual(metric.EvaluateSegments(lct), 1)
        self.assertEqual(metric.GetNumberOfSegments(), 2)
        self.assertLess(metric.GetLargestKeyMissScreenSpace(), 1e-9)
        self.assertEqual(metric.EvaluateSegments(vtk, 0), 1)
        self.assertAlmostEqual(metric.GetKeyMissScreenSpace(1), 15.0, delta=0.5)  # 0.3 of NDC
        self.assertEqual(metric.EvaluateSegments(vtk, 1), 1)
        self.assertLess(metric.GetLargestKeyMissScreenSpace(), 1e-3)
        errors = ErrorRecorder(metric)
        self.assertEqual(metric.AddKeyCamera(float("nan"), vtkCamera()), 0)
        self.assertEqual(errors.count, 1)
        self.assertEqual(metric.GetNumberOfKeyCameras(), 3)

if __name__ == "__main__":
    unittest.main()
