"""vtkTransformBasisLCT from Python: factoring onto Alexa's rotation basis, a basis from
examples constraining a transform, and the errors a script sees for bad input.

Run by CTest as `/usr/bin/python3 TestTransformBasis.py` with the build tree's package directory
on PYTHONPATH (see Testing/Python/CMakeLists.txt).
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkTransformBasisLCT
from vtkmodules.vtkCommonCore import vtkCollection, vtkCommand, vtkDoubleArray
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform


def rotation(degrees, x, y, z):
    t = vtkTransform()
    t.RotateWXYZ(degrees, x, y, z)
    return t


def elements(m):
    return [m.GetElement(i, j) for i in range(4) for j in range(4)]


class TransformBasisTest(unittest.TestCase):
    def test_alexa_rotation_basis(self):
        basis = vtkTransformBasisLCT()
        phi = 30.0
        for axis in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
            self.assertEqual(basis.AddBasisTransform(rotation(phi, *axis)), 1)
        self.assertEqual(basis.GetRank(), 3)
        self.assertAlmostEqual(basis.GetConditionNumber(), 1.0, places=12)
        axis = (2.0, -1.0, 2.0)  # |axis| = 3
        theta = 150.0
        x = vtkDoubleArray()
        self.assertEqual(basis.Factor(rotation(theta, *axis).GetMatrix(), x), 1)
        coefficients = [x.GetValue(i) for i in range(x.GetNumberOfTuples())]
        for c, a in zip(coefficients, axis):
            self.assertAlmostEqual(c, theta / phi * a / 3.0, places=11)
        # The angle from Alexa's inner-product factors 2 phi theta a: |(x, y, z)| / (2 phi),
        # in radians, with x = 2 phi^2 c.
        phi_rad = math.radians(phi)
        factors = [2.0 * phi_rad * phi_rad * c for c in coefficients]
        norm = math.sqrt(sum(f * f for f in factors))
        self.assertAlmostEqual(norm / (2.0 * phi_rad), math.radians(theta), places=11)
        back = vtkMatrix4x4()
        self.assertEqual(basis.Reconstruct(x, back), 1)
        for got, want in zip(elements(back), elements(rotation(theta, *axis).GetMatrix())):
            self.assertAlmostEqual(got, want, places=12)

    def test_examples_constrain_a_transform(self):
        examples = vtkCollection()
        for i in range(7):
            t = vtkTransform()
            t.Translate(0.0, 0.3 * (i % 3), 0.0)
            t.RotateY(20.0 * i)
            examples.AddItem(t)
        basis = vtkTransformBasisLCT()
        self.assertEqual(basis.SetBasisFromExamples(examples, 1), 1)
        self.assertEqual(basis.GetNumberOfBasisTransforms(), 2)
        general = vtkTransform()
        general.Translate(1.0, 2.0, 3.0)
        general.RotateWXYZ(40.0, 1.0, 1.0, 0.0)
        result = vtkMatrix4x4()
        self.assertEqual(basis.Project(general.GetMatrix(), result), 1)
        self.assertGreater(basis.GetResidual(), 0.1)
        # A rotation about y and a translation along y only.
        self.assertAlmostEqual(result.GetElement(1, 1), 1.0, places=12)
        self.assertAlmostEqual(result.GetElement(0, 3), 0.0, places=12)
        self.assertAlmostEqual(result.GetElement(2, 3), 0.0, places=12)
        values = vtkDoubleArray()
        basis.GetSingularValues(values)
        self.assertEqual(values.GetNumberOfTuples(), 7)

    def test_bad_input_is_reported(self):
        basis = vtkTransformBasisLCT()
        errors = ErrorRecorder(basis)
        warnings = ErrorRecorder(basis, vtkCommand.WarningEvent)
        x = vtkDoubleArray()
        self.assertEqual(basis.Factor(vtkMatrix4x4(), x), 0)
        self.assertIn("no basis", errors.messages[-1])
        self.assertEqual(basis.AddBasisTransform(rotation(30, 1, 0, 0)), 1)
        self.assertEqual(basis.AddBasisTransform(rotation(-50, 1, 0, 0)), 1)
        self.assertIn("rank deficient", warnings.messages[-1])
        self.assertEqual(basis.Factor(rotation(10, 1, 0, 0).GetMatrix(), x), 0)
        self.assertIn("not unique", errors.messages[-1])
        m = vtkMatrix4x4()
        m.SetElement(0, 0, float("nan"))
        self.assertEqual(basis.Project(m, vtkMatrix4x4()), 0)
        self.assertIn("NaN", errors.messages[-1])
        x.SetNumberOfTuples(3)
        self.assertEqual(basis.Reconstruct(x, vtkMatrix4x4()), 0)
        self.assertIn("3 x 1 coefficients for a basis of 2", errors.messages[-1])
        self.assertEqual(basis.SetRankTolerance(2.0), 0)
        self.assertEqual(basis.GetRankTolerance(), 1e-8)


if __name__ == "__main__":
    unittest.main()
