"""vtkLogTransform from Python, together with VTK's own classes.

Run by CTest as `/usr/bin/python3 TestLogTransform.py` with the build tree's package directory on
PYTHONPATH (see Testing/Python/CMakeLists.txt). unittest.main() exits non-zero on any failure or
error, including a failed `from vtklct import vtkLogTransform`.
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkLogTransform
from vtkmodules.vtkCommonCore import vtkCollection, vtkDoubleArray
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkLinearTransform, vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource

TOL = 1e-12


def matrix_elements(m):
    """The 16 elements of a vtkMatrix4x4, row-major."""
    return [m.GetElement(i, j) for i in range(4) for j in range(4)]


def shear_matrix(xy=0.0, xz=0.0, yz=0.0):
    """x' = x + xy*y + xz*z, y' = y + yz*z."""
    m = vtkMatrix4x4()
    m.SetElement(0, 1, xy)
    m.SetElement(0, 2, xz)
    m.SetElement(1, 2, yz)
    return m


def general_affine():
    """A vtkTransform with rotation, non-uniform scale, shear and translation (det > 0)."""
    t = vtkTransform()
    t.PostMultiply()
    t.Concatenate(shear_matrix(xy=0.4, xz=-0.2, yz=0.3))
    t.Scale(1.7, 0.6, 1.2)
    t.RotateWXYZ(70.0, 1.0, 2.0, -0.5)
    t.Translate(0.5, -1.25, 2.0)
    return t


def rotation(angle, axis, translate=(0.0, 0.0, 0.0)):
    t = vtkTransform()
    t.PostMultiply()
    t.RotateWXYZ(angle, *axis)
    t.Translate(*translate)
    return t


def log_of(transform, parametrisation=vtkLogTransform.POLAR):
    """A new vtkLogTransform set from a linear transform; fails the test if rejected."""
    lt = vtkLogTransform()
    if parametrisation == vtkLogTransform.MATRIX_LOG:
        assert lt.SetParametrisationToMatrixLog() == 1
    assert lt.SetTransform(transform) == 1, "SetTransform rejected a valid transform"
    return lt


def coordinates(lt):
    c = [0.0] * 12
    lt.GetLogCoordinates(c)
    return c


class LogTransformTestCase(unittest.TestCase):
    def assertElementsClose(self, actual, expected, tol=TOL, msg=None):
        self.assertEqual(len(actual), len(expected))
        worst = max(abs(a - e) for a, e in zip(actual, expected))
        self.assertLessEqual(worst, tol, msg or f"max difference {worst:.3g} > {tol:g}:\n"
                             f"  actual   {actual}\n  expected {expected}")

    def assertMatrixClose(self, actual, expected, tol=TOL, msg=None):
        self.assertElementsClose(matrix_elements(actual), matrix_elements(expected), tol, msg)


class TestBasics(LogTransformTestCase):
    def test_is_a_vtk_linear_transform(self):
        lt = vtkLogTransform()
        self.assertIsInstance(lt, vtkLinearTransform)
        self.assertTrue(lt.IsA("vtkAbstractTransform"))
        self.assertEqual(lt.GetParametrisation(), vtkLogTransform.POLAR)
        self.assertEqual(lt.GetParametrisationAsString(), "Polar")
        identity = vtkMatrix4x4()
        self.assertMatrixClose(lt.GetMatrix(), identity, 0.0)
        self.assertEqual(coordinates(lt), [0.0] * 12)

    def test_round_trip_through_vtkTransform(self):
        # SetTransform and SetMatrix give back the same matrix, in both parametrisations.
        t = general_affine()
        for p in (vtkLogTransform.POLAR, vtkLogTransform.MATRIX_LOG):
            with self.subTest(parametrisation=p):
                lt = log_of(t, p)
                self.assertMatrixClose(lt.GetMatrix(), t.GetMatrix())
                lt2 = vtkLogTransform()
                lt2.SetParametrisation(p)
                self.assertEqual(lt2.SetMatrix(t.GetMatrix()), 1)
                self.assertMatrixClose(lt2.GetMatrix(), t.GetMatrix())
                self.assertEqual(lt2.SetMatrix(matrix_elements(t.GetMatrix())), 1)
                self.assertMatrixClose(lt2.GetMatrix(), t.GetMatrix())

    def test_point_and_inverse(self):
        t = general_affine()
        lt = log_of(t)
        p = (0.3, -1.1, 2.5)
        self.assertElementsClose(lt.TransformPoint(p), t.TransformPoint(p), 1e-12)
        back = lt.GetLinearInverse().TransformPoint(lt.TransformPoint(p))
        self.assertElementsClose(back, p, 1e-12)


class TestOperations(LogTransformTestCase):
    def test_half_twice_is_whole_matrix_log(self):
        # MatrixLog: 0.5 (.) M composed with itself is M, for a general affine map.
        t = general_affine()
        half = log_of(t, vtkLogTransform.MATRIX_LOG)
        self.assertEqual(half.Scale(0.5), 1)
        composed = vtkTransform()
        composed.Concatenate(half)
        composed.Concatenate(half)
        self.assertMatrixClose(composed.GetMatrix(), t.GetMatrix(), 1e-12)
        # ... and it really is a different map from M.
        self.assertGreater(max(abs(a - b) for a, b in zip(matrix_elements(half.GetMatrix()),
                                                          matrix_elements(t.GetMatrix()))), 0.1)

    def test_half_twice_is_whole_polar_rotation(self):
        # Polar: exact for pure rotations (their log is the rotation vector).
        t = rotation(130.0, (0.2, -1.0, 0.7))
        half = log_of(t)
        self.assertEqual(half.Scale(0.5), 1)
        composed = vtkTransform()
        composed.Concatenate(half)
        composed.Concatenate(half)
        self.assertMatrixClose(composed.GetMatrix(), t.GetMatrix(), 1e-12)
        expected_half = rotation(65.0, (0.2, -1.0, 0.7))
        self.assertMatrixClose(half.GetMatrix(), expected_half.GetMatrix(), 1e-12)

    def test_linear_combination_collection(self):
        a = log_of(general_affine())
        b = log_of(rotation(90.0, (0.0, 0.0, 1.0), (1.0, 0.0, 0.0)))
        c = log_of(rotation(-40.0, (1.0, 1.0, 0.0)))
        transforms = vtkCollection()
        for t in (a, b, c):
            transforms.AddItem(t)
        w = (0.3, -0.7, 1.4)
        weights = vtkDoubleArray()
        for x in w:
            weights.InsertNextValue(x)

        result = vtkLogTransform()
        self.assertEqual(vtkLogTransform.LinearCombination(transforms, weights, result), 1)
        # Linear in the log coordinates ...
        expected = [sum(wi * ci[k] for wi, ci in zip(w, map(coordinates, (a, b, c))))
                    for k in range(12)]
        self.assertElementsClose(coordinates(result), expected, 1e-12)
        # ... and the same as scalar multiples and additions.
        manual = vtkLogTransform()
        manual.DeepCopy(a)
        self.assertEqual(manual.Scale(w[0]), 1)
        for t, wi in ((b, w[1]), (c, w[2])):
            term = vtkLogTransform()
            term.DeepCopy(t)
            self.assertEqual(term.Scale(wi), 1)
            self.assertEqual(manual.Add(term), 1)
        self.assertMatrixClose(result.GetMatrix(), manual.GetMatrix(), 1e-10)

    def test_add_is_commutative_and_interpolate_ends(self):
        a = log_of(general_affine())
        b = log_of(rotation(90.0, (0.0, 0.0, 1.0), (1.0, 2.0, 3.0)))
        ab = vtkLogTransform()
        ab.DeepCopy(a)
        ab.Add(b)
        ba = vtkLogTransform()
        ba.DeepCopy(b)
        ba.Add(a)
        self.assertMatrixClose(ab.GetMatrix(), ba.GetMatrix(), 1e-12)

        mid = vtkLogTransform()
        for t, end in ((0.0, a), (1.0, b)):
            self.assertEqual(mid.Interpolate(a, b, t), 1)
            self.assertMatrixClose(mid.GetMatrix(), end.GetMatrix(), 1e-12)

    def test_in_a_pipeline(self):
        sphere = vtkSphereSource()
        sphere.SetCenter(0.5, -0.25, 1.0)
        sphere.SetRadius(2.0)
        sphere.SetThetaResolution(16)
        sphere.SetPhiResolution(12)
        sphere.Update()
        lt = log_of(general_affine())
        f = vtkTransformPolyDataFilter()
        f.SetInputConnection(sphere.GetOutputPort())
        f.SetTransform(lt)
        f.Update()

        def check(transform):
            m = transform.GetMatrix()
            src = sphere.GetOutput().GetPoints()
            out = f.GetOutput().GetPoints()
            self.assertEqual(out.GetNumberOfPoints(), src.GetNumberOfPoints())
            for i in (0, 7, src.GetNumberOfPoints() - 1):
                p = src.GetPoint(i)
                expected = [sum(m.GetElement(r, k) * p[k] for k in range(3)) + m.GetElement(r, 3)
                            for r in range(3)]
                # Points are stored as float32.
                self.assertElementsClose(out.GetPoint(i), expected, 1e-5)

        check(general_affine())
        # Changing the log transform re-executes the filter (MTime propagates).
        self.assertEqual(lt.Scale(-0.5), 1)
        f.Update()
        check(lt)
        half_inverse = log_of(general_affine())
        half_inverse.Scale(-0.5)
        self.assertMatrixClose(lt.GetMatrix(), half_inverse.GetMatrix(), 1e-12)

    def test_concatenated_in_vtkTransform_follows_changes(self):
        lt = log_of(rotation(90.0, (0.0, 0.0, 1.0)))
        outer = vtkTransform()
        outer.PostMultiply()
        outer.Concatenate(lt)
        outer.Translate(10.0, 0.0, 0.0)
        self.assertElementsClose(outer.TransformPoint(1.0, 0.0, 0.0), (10.0, 1.0, 0.0), 1e-12)
        lt.Scale(2.0)  # a half turn about z
        self.assertElementsClose(outer.TransformPoint(1.0, 0.0, 0.0), (9.0, 0.0, 0.0), 1e-12)


class TestBadInput(LogTransformTestCase):
    def setUp(self):
        self.lt = log_of(general_affine())
        self.errors = ErrorRecorder(self.lt)
        self.before_matrix = matrix_elements(self.lt.GetMatrix())
        self.before_coordinates = coordinates(self.lt)
        self.before_mtime = self.lt.GetMTime()

    def assertRejected(self, result, what):
        self.assertEqual(result, 0, f"{what} was accepted")
        self.assertGreaterEqual(len(self.errors.messages), 1, f"{what}: no ErrorEvent")
        self.assertEqual(coordinates(self.lt), self.before_coordinates, f"{what}: state changed")
        self.assertEqual(matrix_elements(self.lt.GetMatrix()), self.before_matrix)
        self.assertEqual(self.lt.GetMTime(), self.before_mtime, f"{what}: MTime changed")

    def test_nan(self):
        m = vtkMatrix4x4()
        m.SetElement(1, 2, math.nan)
        self.assertRejected(self.lt.SetMatrix(m), "NaN matrix")
        self.assertIn("SetMatrix", self.errors.messages[-1])

    def test_infinite(self):
        m = vtkMatrix4x4()
        m.SetElement(0, 3, math.inf)
        self.assertRejected(self.lt.SetMatrix(m), "Inf matrix")

    def test_negative_determinant(self):
        m = vtkMatrix4x4()
        m.SetElement(0, 0, -1.0)  # a mirror
        self.assertRejected(self.lt.SetMatrix(m), "mirror (det < 0)")
        t = vtkTransform()
        t.Scale(1.0, -2.0, 1.0)
        self.assertRejected(self.lt.SetTransform(t), "vtkTransform with det < 0")

    def test_singular(self):
        m = vtkMatrix4x4()
        m.SetElement(2, 2, 0.0)
        self.assertRejected(self.lt.SetMatrix(m), "singular matrix")

    def test_projective_bottom_row(self):
        m = vtkMatrix4x4()
        m.SetElement(3, 0, 0.1)
        self.assertRejected(self.lt.SetMatrix(m), "projective matrix")
        m = vtkMatrix4x4()
        m.SetElement(3, 3, 2.0)
        self.assertRejected(self.lt.SetMatrix(m), "bottom row (0, 0, 0, 2)")

    def test_bad_log_coordinates_and_factors(self):
        c = [0.0] * 12
        c[4] = math.nan
        self.assertRejected(self.lt.SetLogCoordinates(c), "NaN log coordinates")
        self.assertRejected(self.lt.Scale(math.inf), "Scale(inf)")
        self.assertRejected(self.lt.Scale(1e300), "Scale(1e300) (overflow)")

    def test_matrix_log_without_real_logarithm(self):
        # A half turn about z with non-uniform scale: Polar has coordinates for it, the matrix
        # logarithm does not.
        t = vtkTransform()
        t.PostMultiply()
        t.Scale(2.0, 0.5, 1.0)
        t.RotateZ(180.0)
        polar = log_of(t)
        self.assertMatrixClose(polar.GetMatrix(), t.GetMatrix(), 1e-12)
        self.assertEqual(self.lt.SetParametrisationToMatrixLog(), 1)
        self.before_coordinates = coordinates(self.lt)
        self.before_matrix = matrix_elements(self.lt.GetMatrix())
        self.before_mtime = self.lt.GetMTime()
        self.assertRejected(self.lt.SetTransform(t), "MatrixLog of a half turn with scale")

    def test_linear_combination_weight_mismatch(self):
        transforms = vtkCollection()
        transforms.AddItem(log_of(general_affine()))
        transforms.AddItem(log_of(rotation(30.0, (0.0, 1.0, 0.0))))
        weights = vtkDoubleArray()
        weights.InsertNextValue(1.0)
        self.assertRejected(vtkLogTransform.LinearCombination(transforms, weights, self.lt),
                            "LinearCombination with 2 transforms and 1 weight")

    def test_good_input_fires_no_error(self):
        self.assertEqual(self.lt.SetTransform(rotation(10.0, (1.0, 0.0, 0.0))), 1)
        self.assertEqual(self.errors.messages, [])
        self.assertGreater(self.lt.GetMTime(), self.before_mtime)


if __name__ == "__main__":
    unittest.main(verbosity=2)
