"""A ParaView-style scripted animation with vtklct: an animation scene, a camera flight with a
window-centre shift and a 150-degree turn, a prop that spins 400 degrees with shear, frames
written to PNG.

Run by CTest under xvfb-run (scripts/test) with /usr/bin/python3 and the build tree on
PYTHONPATH. Exits 125 (skipped) without a display: this VTK renders through X only.
"""
import math
import os
import sys
import tempfile
import unittest

if not os.environ.get("DISPLAY"):
    print("TestScriptedAnimation: no DISPLAY (run under xvfb-run -a); skipped")
    sys.exit(125)

from vtklct import (vtkCameraInterpolatorLCT, vtkCameraPathMetric, vtkInterpolatorCueLCT,
                    vtkTransformInterpolatorLCT)
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkAnimationScene
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkCubeSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)

FRAMES = 12


def actor_for(source, color, position):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.SetPosition(*position)
    return actor


def camera(position, focal, up, angle, center=(0.0, 0.0)):
    c = vtkCamera()
    c.SetFocalPoint(*focal)
    c.SetPosition(*position)
    c.SetViewUp(*up)
    c.SetViewAngle(angle)
    c.SetWindowCenter(*center)
    return c


class ScriptedAnimation(unittest.TestCase):
    def setUp(self):
        self.renderer = vtkRenderer()
        self.renderer.SetBackground(0.95, 0.95, 0.92)
        self.renderer.AddActor(actor_for(vtkSphereSource(), (0.8, 0.3, 0.2), (-1.5, 0, 0)))
        self.renderer.AddActor(actor_for(vtkCubeSource(), (0.2, 0.5, 0.8), (1.5, 0, 0)))
        self.spinner = actor_for(vtkConeSource(), (0.3, 0.7, 0.3), (0, 0, 0))
        self.renderer.AddActor(self.spinner)
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(1)
        self.window.SetSize(160, 120)
        self.window.AddRenderer(self.renderer)

        # Keys as a ParaView user sets them: a few cameras along the flight.
        self.path = vtkCameraInterpolatorLCT()
        for t, angle_deg, center, view in ((0.0, 0, (0.0, 0.0), 40), (1.0, 75, (0.3, 0.1), 30),
                                           (2.0, 150, (0.0, 0.2), 25)):
            a = math.radians(angle_deg)
            key = camera((8 * math.sin(a), 2.0, 8 * math.cos(a)), (0, 0, 0), (0, 1, 0), view, center)
            self.assertEqual(self.path.AddCamera(t, key), 1)

        # The cone spins 400 degrees about y with a shear, in 100-degree steps.
        self.spin = vtkTransformInterpolatorLCT()
        for k in range(5):
            shear = vtkMatrix4x4()
            shear.SetElement(0, 1, 0.3 * (k % 2))
            key = vtkTransform()
            key.PostMultiply()
            key.Concatenate(shear)
            key.RotateY(100.0 * k)
            self.assertEqual(self.spin.AddTransform(float(k), key), 1)
        self.spin.ConsistentRotationOn()

    def test_scene_writes_frames_that_follow_the_keys(self):
        cue = vtkInterpolatorCueLCT()
        cue.SetCamera(self.renderer.GetActiveCamera())
        cue.SetCameraInterpolator(self.path)
        cue.SetRenderer(self.renderer)
        cue.AddProp(self.spinner, self.spin)
        cue.SetTimeModeToNormalized()
        cue.SetStartTime(0.0)
        cue.SetEndTime(1.0)

        out = tempfile.mkdtemp(prefix="lct-frames-")
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        writer = vtkPNGWriter()
        writer.SetInputConnection(grab.GetOutputPort())
        written = []
        centers = []

        def on_tick(caller, event):
            self.window.Render()
            grab.Modified()
            name = os.path.join(out, "frame_%04d.png" % len(written))
            writer.SetFileName(name)
            writer.Write()
            written.append(name)
            centers.append(self.renderer.GetActiveCamera().GetWindowCenter())

        cue.AddObserver(vtkCommand.AnimationCueTickEvent, on_tick)
        scene = vtkAnimationScene()
        scene.SetModeToSequence()
        scene.SetFrameRate(FRAMES - 1)
        scene.SetStartTime(0.0)
        scene.SetEndTime(1.0)
        scene.AddCue(cue)
        scene.Play()

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

    def test_path_metric_of_the_flight(self):
        metric = vtkCameraPathMetric()
        sphere = vtkSphereSource()
        sphere.Update()
        metric.SetPoints(sphere.GetOutput().GetPoints())
        self.assertEqual(metric.EvaluateInterpolator(self.path, 0.0, 2.0), 1)
        self.assertGreaterEqual(metric.GetCameraSpaceExcess(), 0.0)
        self.assertLess(metric.GetCameraSpaceExcess(), 100.0)
        self.assertEqual(metric.GetNumberOfPointsLeavingView(), 0)


if __name__ == "__main__":
    unittest.main()
