"""The ParaView-style scripted animation of Examples/ScriptedAnimation.py, checked: an animation
scene, a camera flight with a window-centre shift and a 150-degree turn, a prop that spins 400
degrees with shear, frames written to PNG.

Run by CTest under xvfb-run (scripts/test) with /usr/bin/python3 and the build tree on
PYTHONPATH. Exits 125 (skipped) without a display: this VTK renders through X only.
"""
import os
import sys
import tempfile
import unittest

if not os.environ.get("DISPLAY"):
    print("TestScriptedAnimation: no DISPLAY (run under xvfb-run -a); skipped")
    sys.exit(125)

sys.path.insert(0, os.path.join(os.environ.get("LCT_SOURCE_DIR", ""), "Examples"))
import ScriptedAnimation as example  # noqa: E402  (Examples/ScriptedAnimation.py)

from vtklct import vtkCameraPathMetric  # noqa: E402
from vtkmodules.vtkFiltersSources import vtkSphereSource  # noqa: E402
from vtkmodules.vtkIOImage import vtkPNGReader  # noqa: E402

FRAMES = 12


class ScriptedAnimation(unittest.TestCase):
    def setUp(self):
        self.anim = example.build(160, 120)

    def test_scene_writes_frames_that_follow_the_keys(self):
        centers = []
        written = example.play(
            self.anim, tempfile.mkdtemp(prefix="lct-frames-"), FRAMES,
            lambda anim: centers.append(anim.renderer.GetActiveCamera().GetWindowCenter()))

        self.assertGreaterEqual(len(written), FRAMES - 1)
        for name in written:
            self.assertTrue(os.path.getsize(name) > 0, name)
        # The frames differ (the camera moves), and the window centre of the middle key is
        # reached in between.
        first, last = vtkPNGReader(), vtkPNGReader()
        first.SetFileName(written[0])
        last.SetFileName(written[-1])
        first.Update()
        last.Update()
        a = first.GetOutput().GetPointData().GetScalars()
        b = last.GetOutput().GetPointData().GetScalars()
        differing = sum(1 for i in range(0, a.GetNumberOfTuples(), 7)
                        if a.GetTuple3(i) != b.GetTuple3(i))
        self.assertGreater(differing, 100)
        self.assertGreater(max(c[0] for c in centers), 0.25)

    def test_an_unanswered_display_is_exit_125_not_an_abort(self):
        # Audit (session 29): with DISPLAY set but no X server answering, VTK 9.1's render
        # window called abort() (exit 134); the example asks Xlib first.
        import subprocess
        env = dict(os.environ, DISPLAY=":87")
        out = tempfile.mkdtemp(prefix="lct-nodisplay-")
        result = subprocess.run(
            [sys.executable, os.path.join(os.environ.get("LCT_SOURCE_DIR", ""), "Examples",
                                          "ScriptedAnimation.py"), out, "3"],
            env=env, capture_output=True, text=True, timeout=120)
        self.assertEqual(result.returncode, 125, result.stderr)
        self.assertIn("no server answers", result.stderr)
        self.assertEqual(os.listdir(out), [])

    def test_path_metric_of_the_flight(self):
        metric = vtkCameraPathMetric()
        sphere = vtkSphereSource()
        sphere.Update()
        metric.SetPoints(sphere.GetOutput().GetPoints())
        self.assertEqual(metric.EvaluateInterpolator(self.anim.path, 0.0, 2.0), 1)
        self.assertGreaterEqual(metric.GetCameraSpaceExcess(), 0.0)
        self.assertLess(metric.GetCameraSpaceExcess(), 100.0)
        self.assertEqual(metric.GetNumberOfPointsLeavingView(), 0)


if __name__ == "__main__":
    unittest.main()
