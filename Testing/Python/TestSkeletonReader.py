"""vtkSkeletonAnimationReader from Python: a CMU clip stepped through its TIME_STEPS, joint
transforms fed to vtkTransformSequencePCA, and an unreadable file.

Run by CTest as `/usr/bin/python3 TestSkeletonReader.py`; exits 125 (skipped) without the
assimp-testmodels data.
"""
import os
import sys
import tempfile
import unittest

from lct_testing import ErrorRecorder

from vtklct import vtkSkeletonAnimationReader, vtkTransformSequencePCA
from vtkmodules.vtkCommonCore import vtkCollection, vtkCommand
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

    def test_frames_line_against_data_rows(self):
        # The Frames: line is the frame count; assimp read "Frames: 0" and a row as one frame,
        # and dropped rows after the count without a word.
        header = """HIERARCHY
ROOT Hips
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  JOINT Chest
  {
    OFFSET 0 5 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    End Site
    {
      OFFSET 0 5 0
    }
  }
}
MOTION
Frames: %s
Frame Time: 0.04
"""
        row = "1 2 3 10 20 30 5 6 7\n"
        directory = tempfile.mkdtemp()

        def load(frames_line, rows):
            path = os.path.join(directory, "clip%d.bvh" % rows)
            with open(path, "w") as f:
                f.write(header % frames_line + row * rows)
            reader = vtkSkeletonAnimationReader()
            errors = ErrorRecorder(reader)
            warnings = ErrorRecorder(reader, vtkCommand.WarningEvent)
            reader.SetFileName(path)
            reader.UpdateInformation()
            return reader, errors, warnings

        reader, errors, warnings = load("0", 1)
        self.assertEqual(reader.GetNumberOfFrames(), 0)
        self.assertIn("Frames: line says 0 but its MOTION section holds 1 data row",
                      errors.messages[-1])
        reader, errors, warnings = load("2", 4)
        self.assertEqual(reader.GetNumberOfFrames(), 2)
        self.assertEqual(errors.count, 0)
        self.assertIn("2 data row(s) after the 2 its Frames: line declares are not read",
                      warnings.messages[-1])
        reader, errors, warnings = load("3.0", 3)
        self.assertEqual(reader.GetNumberOfFrames(), 3)
        self.assertEqual(errors.count + warnings.count, 0)


if __name__ == "__main__":
    if not os.path.exists(CLIP):
        print("skipped: assimp-testmodels is not installed")
        sys.exit(125)
    unittest.main()
