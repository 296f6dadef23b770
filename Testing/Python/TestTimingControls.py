"""Timing controls of the interpolators from Python (issue #12 §3): Kochanek-Bartels tension,
continuity and bias, per-key and path eases, constant speed, and the animation cue driving a
constant-speed camera and prop through a vtkAnimationScene, as a ParaView-style script would.

Run by CTest with /usr/bin/python3 and the build tree on PYTHONPATH. No display needed.
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import (vtkCameraInterpolatorLCT, vtkInterpolatorCueLCT,
                    vtkTransformInterpolatorLCT)
from vtkmodules.vtkCommonCore import vtkCommand, vtkDoubleArray
from vtkmodules.vtkCommonDataModel import vtkAnimationScene
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkRenderingCore import vtkActor, vtkCamera


def distance(a, b):
    return math.sqrt(sum((x - y) ** 2 for x, y in zip(a, b)))


def translation_path(xs, times):
    path = vtkTransformInterpolatorLCT()
    for t, x in zip(times, xs):
        key = vtkTransform()
        key.Translate(x, 0.0, 0.0)
        assert path.AddTransform(t, key) == 1
    return path


def x_at(path, t):
    m = vtkMatrix4x4()
    assert path.InterpolateTransform(t, m) == 1
    return m.GetElement(0, 3)


def speed_spread(points):
    """max / min of the distances between consecutive points."""
    steps = [distance(a, b) for a, b in zip(points, points[1:])]
    return max(steps) / min(steps)


class TransformTiming(unittest.TestCase):
    def test_tension_one_stops_at_the_keys_and_keys_stay_exact(self):
        times, xs = [0.0, 1.0, 3.0, 4.0], [0.0, 2.0, 5.0, 9.0]
        path = translation_path(xs, times)
        self.assertEqual(path.SetTension(1.0), 1)
        self.assertEqual(path.GetTension(), 1.0)
        for t, x in zip(times, xs):
            self.assertAlmostEqual(x_at(path, t), x, places=12)
        h = 1e-5
        self.assertLess(abs(x_at(path, 1.0 + h) - x_at(path, 1.0)) / h, 1e-3)

    def test_key_ease_arrives_at_rest(self):
        path = translation_path([0.0, 1.0, 2.0], [0.0, 1.0, 2.0])
        self.assertEqual(path.SetKeyEase(1.0, 1.0, 0.0), 1)
        h = 1e-6
        self.assertLess((x_at(path, 1.0) - x_at(path, 1.0 - h)) / h, 1e-4)
        self.assertAlmostEqual((x_at(path, 1.0 + h) - x_at(path, 1.0)) / h, 1.0, places=4)
        self.assertEqual(path.ClearKeyTiming(1.0), 1)
        self.assertAlmostEqual((x_at(path, 1.0) - x_at(path, 1.0 - h)) / h, 1.0, places=4)

    def test_constant_speed_and_arrival_times(self):
        times, xs = [0.0, 1.0, 2.0, 3.0], [0.0, 1.0, 10.0, 11.0]
        path = translation_path(xs, times)
        path.SetInterpolationTypeToLinear()
        path.ConstantSpeedOn()
        points = [(x_at(path, 3.0 * j / 110), 0, 0) for j in range(111)]
        self.assertLess(speed_spread(points), 1.0 + 1e-6)  # Linear: exactly even
        arrivals = vtkDoubleArray()
        self.assertEqual(path.GetKeyArrivalTimes(arrivals), 1)
        expected = [0.0, 3.0 / 11, 30.0 / 11, 3.0]
        for k in range(4):
            self.assertAlmostEqual(arrivals.GetValue(k), expected[k], places=9)

    def test_bad_values_are_refused_and_reported(self):
        path = translation_path([0.0, 1.0], [0.0, 1.0])
        errors = ErrorRecorder(path)
        self.assertEqual(path.SetBias(2.0), 0)
        self.assertEqual(path.SetEaseIn(float("nan")), 0)
        self.assertEqual(path.SetKeyEase(0.5, 0.1, 0.1), 0)
        self.assertEqual(path.SetConstantSpeedPoint(0.0, float("inf"), 0.0), 0)
        self.assertEqual(errors.count, 4)
        self.assertIn("[-1, 1]", errors.messages[0])
        self.assertIn("no key at t = 0.5", errors.messages[2])
        self.assertEqual(path.GetBias(), 0.0)
        self.assertEqual(path.GetEaseIn(), 0.0)


class CueWithConstantSpeed(unittest.TestCase):
    def test_scene_moves_camera_and_prop_evenly(self):
        camera_path = vtkCameraInterpolatorLCT()
        # A dolly with keys unevenly spaced in space: 1, 9 and 1 units per second.
        for t, z in [(0.0, 10.0), (1.0, 11.0), (2.0, 20.0), (3.0, 21.0)]:
            key = vtkCamera()
            key.SetFocalPoint(0.0, 0.0, 0.0)
            key.SetPosition(0.0, 0.0, z)
            self.assertEqual(camera_path.AddCamera(t, key), 1)
        camera_path.SetInterpolationTypeToLinear()
        camera_path.ConstantSpeedOn()
        camera_path.SetConstantSpeedMeasure(vtkCameraInterpolatorLCT.CONSTANT_SPEED_EYE)
        prop_path = translation_path([0.0, 1.0, 10.0, 11.0], [0.0, 1.0, 2.0, 3.0])
        prop_path.SetInterpolationTypeToLinear()
        prop_path.ConstantSpeedOn()

        camera, actor = vtkCamera(), vtkActor()
        cue = vtkInterpolatorCueLCT()
        cue.SetCamera(camera)
        cue.SetCameraInterpolator(camera_path)
        self.assertEqual(cue.AddProp(actor, prop_path), 1)
        cue.SetTimeModeToNormalized()
        cue.SetStartTime(0.0)
        cue.SetEndTime(1.0)
        eyes, props = [], []

        def on_tick(caller, event):
            eyes.append(camera.GetPosition())
            m = actor.GetUserMatrix()
            props.append((m.GetElement(0, 3), 0.0, 0.0))

        cue.AddObserver(vtkCommand.AnimationCueTickEvent, on_tick)
        scene = vtkAnimationScene()
        scene.SetModeToSequence()
        scene.SetFrameRate(22)
        scene.SetStartTime(0.0)
        scene.SetEndTime(1.0)
        scene.AddCue(cue)
        scene.Play()
        self.assertGreaterEqual(len(eyes), 20)
        # Without constant speed the steps would differ ninefold.
        self.assertLess(speed_spread(eyes), 1.0 + 1e-6)
        self.assertLess(speed_spread(props), 1.0 + 1e-6)


if __name__ == "__main__":
    unittest.main()
