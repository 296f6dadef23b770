"""vtkMotionCodecLCT from Python: a CMU clip compressed to 1 % of its height, decoded to BVH and
read back within the bound; a corrupted file and a bad tolerance refused, nothing written.

Run by CTest as `/usr/bin/python3 TestMotionCodec.py`; exits 125 (skipped) without the
assimp-testmodels data.
"""
import math
import os
import sys
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkMotionCodecLCT, vtkSkeletonAnimationReader
from vtkmodules.vtkCommonMath import vtkMatrix4x4

CLIP = "/usr/share/assimp/models/BVH/Boxing_Toes.bvh"
OUT = os.environ.get("LCT_TEST_OUTPUT_DIR", ".")


def read(path):
    reader = vtkSkeletonAnimationReader()
    reader.SetFileName(path)
    reader.UpdateInformation()
    return reader


def world_position(reader, joint, frame):
    m = vtkMatrix4x4()
    assert reader.GetWorldTransform(joint, frame, m) == 1
    return [m.GetElement(i, 3) for i in range(3)]


class MotionCodecTest(unittest.TestCase):
    def test_round_trip_holds_the_bound(self):
        reader = read(CLIP)
        codec = vtkMotionCodecLCT()
        codec.SetRelativeTolerance(0.01)
        codec.SetRotationOrder("ZXY")
        lctm = os.path.join(OUT, "codec-python.lctm")
        self.assertEqual(codec.Compress(reader, lctm), 1)
        tolerance = 0.01 * codec.GetSkeletonHeight()
        self.assertGreater(codec.GetCompressionFactor(), 35.0)
        self.assertLessEqual(codec.GetMaximumError(), tolerance)
        self.assertLessEqual(codec.GetMeanError(), codec.GetP99Error())
        self.assertEqual(codec.GetCompressedBytes(), os.path.getsize(lctm))
        bvh = os.path.join(OUT, "codec-python.bvh")
        self.assertEqual(vtkMotionCodecLCT().Decompress(lctm, bvh), 1)
        decoded = read(bvh)
        self.assertEqual(decoded.GetNumberOfFrames(), reader.GetNumberOfFrames())
        self.assertEqual(decoded.GetNumberOfJoints(), reader.GetNumberOfJoints())
        worst = 0.0
        for frame in range(0, reader.GetNumberOfFrames(), 7):
            for joint in range(reader.GetNumberOfJoints()):
                worst = max(worst, math.dist(world_position(reader, joint, frame),
                                             world_position(decoded, joint, frame)))
        # 10 significant digits in the BVH text and float32 parsing add ~1e-6 of H.
        self.assertLessEqual(worst, tolerance * (1 + 1e-4))

    def test_bad_input_is_refused(self):
        codec = vtkMotionCodecLCT()
        errors = ErrorRecorder(codec)
        target = os.path.join(OUT, "codec-python-bad.lctm")
        if os.path.exists(target):
            os.remove(target)
        self.assertEqual(codec.Compress(vtkSkeletonAnimationReader(), target), 0)
        self.assertIn("UpdateInformation", errors.messages[-1])
        codec.SetRelativeTolerance(-0.01)
        self.assertEqual(codec.Compress(read(CLIP), target), 0)
        self.assertIn("not positive and finite", errors.messages[-1])
        self.assertFalse(os.path.exists(target))
        self.assertEqual(codec.GetCompressedBytes(), 0)
        # A NaN Tolerance is named as such (it blamed the relative fallback's value), and a
        # rotation order Decompress would refuse is refused before anything is written.
        codec.SetRelativeTolerance(0.01)
        codec.SetTolerance(float("nan"))
        self.assertEqual(codec.Compress(read(CLIP), target), 0)
        self.assertIn("Tolerance is nan", errors.messages[-1])
        # A bound below what float32 (assimp's reading) resolves: it would be verified against
        # the float32 values and missed against the file's text, so it is refused.
        codec.SetTolerance(1e-5)
        self.assertEqual(codec.Compress(read(CLIP), target), 0)
        self.assertIn("below the precision of the input as read", errors.messages[-1])
        self.assertFalse(os.path.exists(target))
        codec.SetTolerance(0.0)
        codec.SetRotationOrder("ABC")
        self.assertEqual(codec.Compress(read(CLIP), target), 0)
        self.assertIn("not a permutation of XYZ", errors.messages[-1])
        self.assertFalse(os.path.exists(target))
        codec.SetRotationOrder(None)
        corrupted = os.path.join(OUT, "codec-python-corrupted.lctm")
        with open(corrupted, "wb") as f:
            f.write(b"LCTM\x01\x00\x00\x00" + bytes(40))
        bvh = os.path.join(OUT, "codec-python-never.bvh")
        self.assertEqual(codec.Decompress(corrupted, bvh), 0)
        self.assertIn("corrupted", errors.messages[-1])
        self.assertFalse(os.path.exists(bvh))
        # An endless stream is refused at its signature (it was read whole first: 1.4 GB after
        # 10 s, never returning).
        if os.path.exists("/dev/zero"):
            self.assertEqual(codec.Decompress("/dev/zero", bvh), 0)
            self.assertIn("no LCTM signature", errors.messages[-1])
            self.assertFalse(os.path.exists(bvh))


if __name__ == "__main__":
    if not os.path.exists(CLIP):
        print("skipped: assimp-testmodels is not installed")
        sys.exit(125)
    unittest.main()
