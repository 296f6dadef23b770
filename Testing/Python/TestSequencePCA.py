"""vtkTransformSequencePCA from Python: an animation of two joints analysed, reconstructed with
every component, its eigen-motions, and the errors a script sees for bad input.

Run by CTest as `/usr/bin/python3 TestSequencePCA.py` with the build tree's package directory
on PYTHONPATH (see Testing/Python/CMakeLists.txt).
"""
import math
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkTransformSequencePCA
from vtkmodules.vtkCommonCore import vtkCollection, vtkDoubleArray
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform


def pose(frame):
    """Two joints: a knee bending and a hip swinging and lifting, with a 200-degree spin."""
    knee = vtkTransform()
    knee.RotateX(40.0 * math.sin(frame / 5.0))
    hip = vtkTransform()
    hip.Translate(0.0, 0.1 * math.cos(frame / 5.0), 0.0)
    hip.RotateY(200.0 * frame / 49.0)
    frame_items = vtkCollection()
    frame_items.AddItem(knee)
    frame_items.AddItem(hip)
    return frame_items, (knee, hip)


class SequencePCATest(unittest.TestCase):
    def test_analyse_and_reconstruct(self):
        pca = vtkTransformSequencePCA()
        errors = ErrorRecorder(pca)
        originals = []
        for f in range(50):
            items, transforms = pose(f)
            self.assertEqual(pca.AddFrame(items), 1)
            originals.append(transforms)
        self.assertEqual(pca.Compute(), 1)
        k = pca.GetNumberOfComponents()
        self.assertGreaterEqual(k, 2)
        self.assertAlmostEqual(pca.GetExplainedFraction(k), 1.0, places=12)
        fractions = vtkDoubleArray()
        self.assertEqual(pca.GetExplainedVariance(fractions), 1)
        self.assertEqual(fractions.GetNumberOfTuples(), k)
        m = vtkMatrix4x4()
        for f in (0, 17, 49):
            for c in (0, 1):
                self.assertEqual(pca.GetReconstructedTransform(f, c, k, m), 1)
                want = originals[f][c].GetMatrix()
                for i in range(4):
                    for j in range(4):
                        self.assertAlmostEqual(m.GetElement(i, j), want.GetElement(i, j), places=10)
        self.assertEqual(pca.GetEigenMotion(0, 1, 1.5, m), 1)
        self.assertEqual(errors.count, 0)

    def test_bad_input(self):
        pca = vtkTransformSequencePCA()
        errors = ErrorRecorder(pca)
        self.assertEqual(pca.Compute(), 0)
        self.assertIn("no frames", errors.messages[-1])
        items, _ = pose(0)
        self.assertEqual(pca.AddFrame(items), 1)
        single = vtkCollection()
        single.AddItem(vtkTransform())
        self.assertEqual(pca.AddFrame(single), 0)
        self.assertIn("1 transforms where every frame has 2 channels", errors.messages[-1])
        self.assertEqual(pca.GetReconstructedTransform(0, 0, 1, vtkMatrix4x4()), 0)
        self.assertIn("Compute() first", errors.messages[-1])
        self.assertEqual(pca.SetChannelWeight(0, -2.0), 0)


if __name__ == "__main__":
    unittest.main()
