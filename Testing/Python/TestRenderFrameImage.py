"""Regression image of one lct-render frame: frame 24 of the built-in 48-frame flight with
--compare, at 320x180, against Testing/Data/Baseline/RenderFrame24.png (vtkImageDifference, the
comparison VTK's regression tests use).

Run by CTest under xvfb-run with LCT_SOURCE_DIR and LCT_BINARY_DIR set; exits 125 without a
display.
"""
import os
import subprocess
import sys
import tempfile
import unittest

if not os.environ.get("DISPLAY"):
    print("TestRenderFrameImage: no DISPLAY (run under xvfb-run -a); skipped")
    sys.exit(125)

from vtkmodules.vtkImagingCore import vtkImageDifference  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

SOURCE = os.environ["LCT_SOURCE_DIR"]
BINARY = os.environ["LCT_BINARY_DIR"]
BASELINE = os.path.join(SOURCE, "Testing", "Data", "Baseline", "RenderFrame24.png")
THRESHOLD = 10.0  # vtkImageDifference's thresholded error, as in vtkRegressionTestImage


def read(name):
    reader = vtkPNGReader()
    reader.SetFileName(name)
    reader.Update()
    return reader


class RenderFrameImage(unittest.TestCase):
    def test_frame_matches_the_baseline(self):
        out = tempfile.mkdtemp(prefix="lct-render-frame-")
        command = [os.path.join(BINARY, "bin", "lct-render"), "--compare", "--frames", "24:25/48",
                   "--size", "320x180", "--out", out]
        result = subprocess.run(command, capture_output=True, text=True)
        self.assertEqual(result.returncode, 0, result.stderr)
        frame = os.path.join(out, "frame_0024.png")
        self.assertTrue(os.path.isfile(frame))
        if not os.path.isfile(BASELINE):
            self.fail("no baseline: look at %s, then copy it to %s" % (frame, BASELINE))
        rendered, baseline = read(frame), read(BASELINE)  # keep the readers alive
        difference = vtkImageDifference()
        difference.SetInputConnection(rendered.GetOutputPort())
        difference.SetImageConnection(baseline.GetOutputPort())
        difference.Update()
        self.assertLess(difference.GetThresholdedError(), THRESHOLD, frame)


if __name__ == "__main__":
    unittest.main()
