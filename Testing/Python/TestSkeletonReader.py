"""vtkSkeletonAnimationReader from Python: a CMU clip stepped through its TIME_STEPS, joint
transforms fed to vtkTransformSequencePCA, and an unreadable file.

Run by CTest as `/usr/bin/python3 TestSkeletonReader.py`; exits 125 (skipped) without the
assimp-testmodels data.
"""
import os
import sys
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkSkeletonAnimationReader, vtkTransformSequencePCA
from vtkmodules.vtkCommonCore import vtkCollection
from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline
from vtkmodules.vtkCommonMath import vtkMatrix4x4

CLIP = "/usr/share/assimp/models/BVH/01_03.bvh"


class SkeletonReaderTest(unittest.TestCase):
    def test_time_steps_and_analysis(self):
        reader = vtkSkeletonAnimationReader()
        reader.SetFileName(CLIP)
        reader.UpdateInformation()
        info = reader.GetOutputInformation(0)
        steps = info.Get(vtkStreamingDemandDrivenPipeline.TIME_STEPS())
        self.assertEqual(len(steps), reader.GetNumberOfFrames())
        reader.UpdateTimeStep(steps[40])
        skeleton = reader.GetOutput()
        self.assertEqual(skeleton.GetNumberOfPoints(), reader.GetNumberOfJoints())
        self.assertEqual(skeleton.GetFieldData().GetArray("Frame").GetValue(0), 40)
        self.assertEqual(reader.GetJointName(0), "Hips")
        # The joints with motion, every 10th frame, into the PCA.
        joints = [j for j in range(reader.GetNumberOfJoints()) if not reader.IsEndSite(j)]
        pca = vtkTransformSequencePCA()
        for f in range(0, reader.GetNumberOfFrames(), 10):
            frame = vtkCollection()
            for j in joints:
                m = vtkMatrix4x4()
                self.assertEqual(reader.GetLocalTransform(j, f, m), 1)
                frame.AddItem(m)
            self.assertEqual(pca.AddFrame(frame), 1)
        pca.SetRootChannel(0)
        self.assertEqual(pca.Compute(), 1)
        self.assertGreater(pca.GetExplainedFraction(10), 0.8)

    def test_unreadable_file(self):
        reader = vtkSkeletonAnimationReader()
        errors = ErrorRecorder(reader)
        reader.SetFileName("/nonexistent/clip.bvh")
        reader.UpdateInformation()
        self.assertEqual(reader.GetNumberOfJoints(), 0)
        self.assertIn("/nonexistent/clip.bvh", errors.messages[-1])


if __name__ == "__main__":
    if not os.path.exists(CLIP):
        print("skipped: assimp-testmodels is not installed")
        sys.exit(125)
    unittest.main()
