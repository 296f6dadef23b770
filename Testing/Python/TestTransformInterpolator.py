"""vtkTransformInterpolatorLCT from Python: the interpolator's contract, scheme by scheme, and a
ParaView-style animation (a vtkAnimationScene in sequence mode whose cue moves an actor).

Checked: every interpolating scheme reproduces its keys (rotation, non-uniform scale and shear)
at the key times to 1e-12, BSpline only the end keys; t is clamped to [min, max]; AddTransform at
an existing time replaces the key; RemoveTransform; a vtkActor as a key; bad keys (NaN, Inf,
det < 0, singular, projective) return 0 with an ErrorEvent and leave the interpolator unchanged;
InterpolateTransform without keys returns 0 with an ErrorEvent.

Run by CTest as `/usr/bin/python3 TestTransformInterpolator.py` with the build tree's package
directory on PYTHONPATH (see Testing/Python/CMakeLists.txt); needs no display. unittest.main()
exits non-zero on any failure or error, including a failed `from vtklct import ...`.
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkLogTransform, vtkTransformInterpolatorLCT
from vtkmodules.vtkCommonCore import vtkAnimationCue, vtkCommand
from vtkmodules.vtkCommonDataModel import vtkAnimationScene
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkRenderingCore import vtkActor

TOL = 1e-12

# Key times (not uniform, to exercise the non-uniform Catmull-Rom and subdivision).
KEY_TIMES = (0.0, 1.0, 2.5, 3.0, 4.5)

# Schemes that pass through every key, by their setter suffix (Bezier: without control
# transforms it follows Catmull-Rom tangents and still interpolates).
INTERPOLATING = ("Linear", "Spline", "Subdivision", "Bezier")


def elements(m):
    """The 16 elements of a vtkMatrix4x4, row-major."""
    return [m.GetElement(i, j) for i in range(4) for j in range(4)]


def max_difference(a, b):
    return max(abs(x - y) for x, y in zip(a, b))


def shear_matrix(xy=0.0, xz=0.0, yz=0.0):
    """x' = x + xy*y + xz*z, y' = y + yz*z."""
    m = vtkMatrix4x4()
    m.SetElement(0, 1, xy)
    m.SetElement(0, 2, xz)
    m.SetElement(1, 2, yz)
    return m


def key_transform(k):
    """Key k: shear, non-uniform scale, a turn of 70 degrees per key about a tilted axis (280
    degrees in all) and a translation, as a vtkTransform."""
    t = vtkTransform()
    t.PostMultiply()
    t.Concatenate(shear_matrix(xy=0.5 * math.sin(k), yz=0.3 * (k % 2)))
    t.Scale(1.0 + 0.25 * k, 1.0 - 0.1 * k, 1.2)
    t.RotateWXYZ(70.0 * k, 0.3, 1.0, 0.4)
    t.Translate(1.5 * k, 0.4 * k * k, -0.2 * k)
    return t


def key_elements(k):
    return elements(key_transform(k).GetMatrix())


def make_interpolator(kind="Spline"):
    interpolator = vtkTransformInterpolatorLCT()
    getattr(interpolator, "SetInterpolationTypeTo" + kind)()
    for k, t in enumerate(KEY_TIMES):
        assert interpolator.AddTransform(t, key_transform(k)) == 1, f"key {k} rejected"
    return interpolator


def interpolate(interpolator, t):
    """The interpolated matrix at t (elements), asserting success."""
    m = vtkMatrix4x4()
    assert interpolator.InterpolateTransform(t, m) == 1, f"InterpolateTransform({t}) failed"
    return elements(m)


class InterpolatorTestCase(unittest.TestCase):
    def assertElementsClose(self, actual, expected, tol=TOL, msg=""):
        worst = max_difference(actual, expected)
        self.assertLessEqual(worst, tol, f"{msg}: max difference {worst:.3g} > {tol:g}\n"
                             f"  actual   {actual}\n  expected {expected}")


class TestKeys(InterpolatorTestCase):
    def test_defaults(self):
        interpolator = vtkTransformInterpolatorLCT()
        self.assertEqual(interpolator.GetNumberOfTransforms(), 0)
        self.assertEqual(interpolator.GetInterpolationType(),
                         vtkTransformInterpolatorLCT.INTERPOLATION_TYPE_SPLINE)
        self.assertEqual(interpolator.GetMinimumT(), 0.0)
        self.assertEqual(interpolator.GetMaximumT(), 0.0)

    def test_keys_have_shear_and_positive_determinant(self):
        for k in range(len(KEY_TIMES)):
            m = key_transform(k).GetMatrix()
            self.assertGreater(m.Determinant(), 0.0)
        # The 3x3 part of key 1 is not a rotation times a diagonal scale: M^T M is not diagonal
        # in the rotated frame, i.e. the columns are not orthogonal.
        m = key_transform(1).GetMatrix()
        cols = [[m.GetElement(r, c) for r in range(3)] for c in range(3)]
        self.assertGreater(abs(sum(a * b for a, b in zip(cols[0], cols[1]))), 0.1)

    def test_interpolating_schemes_reproduce_every_key(self):
        for kind in INTERPOLATING:
            interpolator = make_interpolator(kind)
            self.assertEqual(interpolator.GetNumberOfTransforms(), len(KEY_TIMES))
            self.assertEqual(interpolator.GetMinimumT(), KEY_TIMES[0])
            self.assertEqual(interpolator.GetMaximumT(), KEY_TIMES[-1])
            for k, t in enumerate(KEY_TIMES):
                with self.subTest(scheme=kind, key=k):
                    self.assertElementsClose(interpolate(interpolator, t), key_elements(k),
                                             TOL, f"{kind} at key {k}")

    def test_all_output_types_agree(self):
        interpolator = make_interpolator("Spline")
        for t in (0.0, 0.7, 2.5, 3.9):
            expected = interpolate(interpolator, t)
            xform = vtkTransform()
            self.assertEqual(interpolator.InterpolateTransform(t, xform), 1)
            self.assertElementsClose(elements(xform.GetMatrix()), expected, 0.0, "vtkTransform")
            log = vtkLogTransform()
            self.assertEqual(interpolator.InterpolateTransform(t, log), 1)
            self.assertElementsClose(elements(log.GetMatrix()), expected, 1e-12, "vtkLogTransform")

    def test_bspline_reproduces_only_the_end_keys(self):
        interpolator = make_interpolator("BSpline")
        last = len(KEY_TIMES) - 1
        for k in (0, last):
            self.assertElementsClose(interpolate(interpolator, KEY_TIMES[k]), key_elements(k),
                                     TOL, f"BSpline at end key {k}")
        # It approximates: the interior keys are not on the curve.
        for k in range(1, last):
            self.assertGreater(max_difference(interpolate(interpolator, KEY_TIMES[k]),
                                              key_elements(k)), 1e-3, f"BSpline at key {k}")

    def test_in_betweens_differ_from_the_keys(self):
        # Not a constant or a step: halfway between keys 0 and 1 is neither key.
        for kind in INTERPOLATING + ("BSpline",):
            interpolator = make_interpolator(kind)
            mid = interpolate(interpolator, 0.5)
            for k in (0, 1):
                self.assertGreater(max_difference(mid, key_elements(k)), 1e-2, kind)

    def test_clamped_outside_the_key_range(self):
        for kind in INTERPOLATING + ("BSpline",):
            interpolator = make_interpolator(kind)
            first = interpolate(interpolator, KEY_TIMES[0])
            last = interpolate(interpolator, KEY_TIMES[-1])
            warnings = ErrorRecorder(interpolator, vtkCommand.WarningEvent)
            for t in (KEY_TIMES[0] - 1.0, -1e6):
                self.assertElementsClose(interpolate(interpolator, t), first, 0.0, f"{kind} t={t}")
            for t in (KEY_TIMES[-1] + 0.25, 1e6):
                self.assertElementsClose(interpolate(interpolator, t), last, 0.0, f"{kind} t={t}")
            # The clamp is reported, once per interpolator.
            self.assertEqual(len(warnings.messages), 1, kind)
            self.assertIn("clamped", warnings.messages[0])

    def test_nan_and_infinite_times_are_refused_and_output_untouched(self):
        interpolator = make_interpolator()
        out = vtkMatrix4x4()
        out.SetElement(0, 3, 42.0)
        before = elements(out)
        errors = ErrorRecorder(interpolator)
        for t in (math.nan, math.inf, -math.inf):
            self.assertEqual(interpolator.InterpolateTransform(t, out), 0, t)
            self.assertEqual(elements(out), before)
        self.assertEqual(len(errors.messages), 3)
        self.assertIn("t is NaN", errors.messages[0])
        self.assertIn("infinite", errors.messages[1])


class TestEditing(InterpolatorTestCase):
    def test_add_at_the_same_time_replaces(self):
        interpolator = make_interpolator()
        replacement = vtkTransform()
        replacement.RotateZ(30.0)
        replacement.Translate(0.0, 5.0, 0.0)
        self.assertEqual(interpolator.AddTransform(KEY_TIMES[2], replacement), 1)
        self.assertEqual(interpolator.GetNumberOfTransforms(), len(KEY_TIMES))
        self.assertElementsClose(interpolate(interpolator, KEY_TIMES[2]),
                                 elements(replacement.GetMatrix()), TOL, "replaced key")
        # The neighbours are still the original keys.
        for k in (1, 3):
            self.assertElementsClose(interpolate(interpolator, KEY_TIMES[k]), key_elements(k),
                                     TOL, f"key {k}")

    def test_keys_added_out_of_order(self):
        interpolator = vtkTransformInterpolatorLCT()
        interpolator.SetInterpolationTypeToSpline()
        for k in (3, 0, 4, 1, 2):
            self.assertEqual(interpolator.AddTransform(KEY_TIMES[k], key_transform(k)), 1)
        reference = make_interpolator("Spline")
        for t in (0.0, 0.3, 1.7, 2.9, 4.5):
            self.assertElementsClose(interpolate(interpolator, t), interpolate(reference, t),
                                     TOL, f"t={t}")

    def test_remove_transform(self):
        interpolator = make_interpolator("Linear")
        interpolator.RemoveTransform(KEY_TIMES[2])
        self.assertEqual(interpolator.GetNumberOfTransforms(), len(KEY_TIMES) - 1)
        # Linear now runs straight from key 1 to key 3 across the removed time.
        reference = vtkTransformInterpolatorLCT()
        reference.SetInterpolationTypeToLinear()
        for k in (0, 1, 3, 4):
            reference.AddTransform(KEY_TIMES[k], key_transform(k))
        for t in (1.5, 2.5, 2.8):
            self.assertElementsClose(interpolate(interpolator, t), interpolate(reference, t),
                                     TOL, f"t={t}")
        # Removing a time without a key changes nothing.
        interpolator.RemoveTransform(1.234)
        self.assertEqual(interpolator.GetNumberOfTransforms(), len(KEY_TIMES) - 1)
        # Removing the end keys moves the range.
        interpolator.RemoveTransform(KEY_TIMES[0])
        interpolator.RemoveTransform(KEY_TIMES[-1])
        self.assertEqual(interpolator.GetNumberOfTransforms(), 2)
        self.assertEqual(interpolator.GetMinimumT(), KEY_TIMES[1])
        self.assertEqual(interpolator.GetMaximumT(), KEY_TIMES[3])
        self.assertElementsClose(interpolate(interpolator, 0.0), key_elements(1), TOL, "clamped")

    def test_single_key_is_constant(self):
        interpolator = vtkTransformInterpolatorLCT()
        self.assertEqual(interpolator.AddTransform(2.0, key_transform(3)), 1)
        for t in (-1.0, 2.0, 7.0):
            self.assertElementsClose(interpolate(interpolator, t), key_elements(3), TOL, f"t={t}")

    def test_initialize_removes_all_keys(self):
        interpolator = make_interpolator()
        interpolator.Initialize()
        self.assertEqual(interpolator.GetNumberOfTransforms(), 0)
        errors = ErrorRecorder(interpolator)
        self.assertEqual(interpolator.InterpolateTransform(0.0, vtkMatrix4x4()), 0)
        self.assertGreaterEqual(len(errors.messages), 1)

    def test_actor_as_key(self):
        actor = vtkActor()
        actor.SetOrigin(0.5, 0.0, -0.5)
        actor.SetPosition(1.0, 2.0, 3.0)
        actor.SetOrientation(20.0, -35.0, 60.0)
        actor.SetScale(2.0, 0.5, 1.5)
        interpolator = make_interpolator()
        self.assertEqual(interpolator.AddTransform(6.0, actor), 1)
        self.assertEqual(interpolator.GetNumberOfTransforms(), len(KEY_TIMES) + 1)
        self.assertEqual(interpolator.GetMaximumT(), 6.0)
        self.assertElementsClose(interpolate(interpolator, 6.0), elements(actor.GetMatrix()),
                                 TOL, "actor key")
        # The key is a copy: moving the actor afterwards does not move the key.
        expected = elements(actor.GetMatrix())
        actor.SetPosition(-4.0, 0.0, 0.0)
        self.assertElementsClose(interpolate(interpolator, 6.0), expected, TOL, "copied key")


class TestBadInput(InterpolatorTestCase):
    def setUp(self):
        self.interpolator = make_interpolator()
        self.errors = ErrorRecorder(self.interpolator)
        self.samples = (0.0, 0.8, 2.5, 4.0, 4.5)
        self.before = [interpolate(self.interpolator, t) for t in self.samples]

    def assertRejected(self, result, what):
        self.assertEqual(result, 0, f"{what} was accepted")
        self.assertGreaterEqual(len(self.errors.messages), 1, f"{what}: no ErrorEvent")
        self.assertIn("AddTransform", self.errors.messages[-1], what)
        self.assertEqual(self.interpolator.GetNumberOfTransforms(), len(KEY_TIMES),
                         f"{what}: key count changed")
        self.assertEqual(self.interpolator.GetMinimumT(), KEY_TIMES[0])
        self.assertEqual(self.interpolator.GetMaximumT(), KEY_TIMES[-1])
        after = [interpolate(self.interpolator, t) for t in self.samples]
        self.assertEqual(after, self.before, f"{what}: interpolation changed")

    def bad_matrix(self, row, column, value):
        m = vtkMatrix4x4()
        m.DeepCopy(key_transform(2).GetMatrix())
        m.SetElement(row, column, value)
        return m

    def test_nan(self):
        # At a new time, and at an existing key's time (must not replace it).
        for t in (2.0, KEY_TIMES[2]):
            self.assertRejected(self.interpolator.AddTransform(t, self.bad_matrix(1, 2, math.nan)),
                                f"NaN matrix at t={t}")

    def test_infinite(self):
        self.assertRejected(self.interpolator.AddTransform(2.0, self.bad_matrix(0, 3, math.inf)),
                            "Inf translation")

    def test_negative_determinant(self):
        mirror = vtkMatrix4x4()
        mirror.SetElement(0, 0, -1.0)
        self.assertRejected(self.interpolator.AddTransform(2.0, mirror), "mirror matrix")
        t = vtkTransform()
        t.Scale(1.0, -2.0, 1.0)
        self.assertRejected(self.interpolator.AddTransform(KEY_TIMES[1], t),
                            "vtkTransform with det < 0 at a key's time")
        actor = vtkActor()
        actor.SetScale(-1.0, 1.0, 1.0)
        self.assertRejected(self.interpolator.AddTransform(2.0, actor), "mirrored actor")

    def test_singular(self):
        m = vtkMatrix4x4()
        m.SetElement(2, 2, 0.0)
        self.assertRejected(self.interpolator.AddTransform(2.0, m), "singular matrix")

    def test_projective(self):
        self.assertRejected(self.interpolator.AddTransform(2.0, self.bad_matrix(3, 0, 0.1)),
                            "projective bottom row")
        self.assertRejected(self.interpolator.AddTransform(2.0, self.bad_matrix(3, 3, 2.0)),
                            "bottom row (0, 0, 0, 2)")
        perspective = vtkTransform()
        perspective.SetMatrix([1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -0.5, 1])
        self.assertRejected(self.interpolator.AddTransform(2.0, perspective),
                            "perspective vtkTransform")

    def test_good_key_fires_no_error(self):
        self.assertEqual(self.interpolator.AddTransform(2.0, key_transform(1)), 1)
        self.assertEqual(self.errors.messages, [])
        self.assertEqual(self.interpolator.GetNumberOfTransforms(), len(KEY_TIMES) + 1)

    def test_no_keys(self):
        empty = vtkTransformInterpolatorLCT()
        errors = ErrorRecorder(empty)
        for out in (vtkMatrix4x4(), vtkTransform()):
            if isinstance(out, vtkTransform):
                out.Translate(1.0, 2.0, 3.0)
                before = elements(out.GetMatrix())
            else:
                out.SetElement(1, 3, 7.0)
                before = elements(out)
            count = len(errors.messages)
            self.assertEqual(empty.InterpolateTransform(0.5, out), 0)
            self.assertEqual(len(errors.messages), count + 1, "no ErrorEvent")
            self.assertIn("InterpolateTransform", errors.messages[-1])
            after = elements(out.GetMatrix()) if isinstance(out, vtkTransform) else elements(out)
            self.assertEqual(after, before, "output changed")


class TestAnimationScene(InterpolatorTestCase):
    """ParaView-style: a scene in sequence mode drives a cue; the cue's AnimationCueTickEvent
    observer asks the interpolator for the actor's UserTransform at the cue's time."""

    FRAME_RATE = 4.0  # frames per unit of time: KEY_TIMES fall on frames

    def test_cue_moves_actor_along_the_interpolation(self):
        interpolator = make_interpolator("Spline")
        actor = vtkActor()
        user_transform = vtkTransform()
        actor.SetUserTransform(user_transform)

        scene = vtkAnimationScene()
        scene.SetModeToSequence()
        scene.SetLoop(0)
        scene.SetFrameRate(self.FRAME_RATE)
        scene.SetStartTime(KEY_TIMES[0])
        scene.SetEndTime(KEY_TIMES[-1])

        cue = vtkAnimationCue()
        cue.SetTimeModeToRelative()
        cue.SetStartTime(0.0)
        cue.SetEndTime(KEY_TIMES[-1] - KEY_TIMES[0])
        scene.AddCue(cue)

        seen = []  # (cue time, actor matrix) per tick
        failures = []

        def on_tick(caller, event):
            t = KEY_TIMES[0] + caller.GetAnimationTime()
            if interpolator.InterpolateTransform(t, user_transform) != 1:
                failures.append(t)
            seen.append((t, elements(actor.GetMatrix())))

        cue.AddObserver(vtkCommand.AnimationCueTickEvent, on_tick)
        scene.Play()
        scene.Stop()

        self.assertEqual(failures, [])
        expected_frames = int(round((KEY_TIMES[-1] - KEY_TIMES[0]) * self.FRAME_RATE)) + 1
        self.assertEqual(len(seen), expected_frames)
        times = [t for t, _ in seen]
        self.assertAlmostEqual(times[0], KEY_TIMES[0], delta=1e-12)
        self.assertAlmostEqual(times[-1], KEY_TIMES[-1], delta=1e-12)
        self.assertTrue(all(b > a for a, b in zip(times, times[1:])), "times not increasing")

        # The actor (no position/orientation/scale of its own) is where the interpolator says.
        for t, matrix in seen:
            self.assertElementsClose(matrix, interpolate(interpolator, t), TOL, f"frame at t={t}")
        # On the frames that fall on key times the actor is exactly at the keys.
        for k, key_time in enumerate(KEY_TIMES):
            frame = min(seen, key=lambda s: abs(s[0] - key_time))
            self.assertAlmostEqual(frame[0], key_time, delta=1e-9)
            self.assertElementsClose(frame[1], key_elements(k), 1e-9, f"frame at key {k}")


if __name__ == "__main__":
    unittest.main(verbosity=2)
