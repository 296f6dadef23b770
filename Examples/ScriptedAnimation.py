"""A ParaView-style scripted animation with vtklct.

An animation scene with one cue that flies the camera through three keys (a 150-degree turn, a
shift of the centre of projection, a zoom) and spins a cone through 400 degrees with shear, and a
tick observer that renders each frame offscreen and writes it as a PNG:

    xvfb-run -a /usr/bin/python3 Examples/ScriptedAnimation.py [out_dir] [frames]

with the build tree on PYTHONPATH (`scripts/env python3 Examples/ScriptedAnimation.py`).
"""
import math
import os
import sys

from vtklct import vtkCameraInterpolatorLCT, vtkInterpolatorCueLCT, vtkTransformInterpolatorLCT
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkAnimationScene
from vtkmodules.vtkCommonMath import vtkMatrix4x4
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersSources import vtkConeSource, vtkCubeSource, vtkSphereSource
from vtkmodules.vtkIOImage import vtkPNGWriter
from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer,
                                         vtkRenderWindow, vtkWindowToImageFilter)
import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)


def add(renderer, source, color, position):
    mapper = vtkPolyDataMapper()
    mapper.SetInputConnection(source.GetOutputPort())
    actor = vtkActor()
    actor.SetMapper(mapper)
    actor.GetProperty().SetColor(*color)
    actor.SetPosition(*position)
    renderer.AddActor(actor)
    return actor


class Animation:
    """The view, the paths and the cue of the animation (built by `build`)."""


def build(width=480, height=270):
    """The scene, the camera and cone paths, and the cue that drives them."""
    anim = Animation()
    # The view, as a ParaView user has it.
    anim.renderer = vtkRenderer()
    anim.renderer.SetBackground(0.95, 0.95, 0.92)
    add(anim.renderer, vtkSphereSource(), (0.8, 0.3, 0.2), (-1.5, 0, 0))
    add(anim.renderer, vtkCubeSource(), (0.2, 0.5, 0.8), (1.5, 0, 0))
    anim.cone = add(anim.renderer, vtkConeSource(), (0.3, 0.7, 0.3), (0, 0, 0))
    anim.window = vtkRenderWindow()
    anim.window.SetOffScreenRendering(1)
    anim.window.SetSize(width, height)
    anim.window.AddRenderer(anim.renderer)

    # Camera keys: the path is interpolated as whole cameras, window centre included.
    anim.path = vtkCameraInterpolatorLCT()
    for t, azimuth, center, angle in ((0, 0, (0.0, 0.0), 40), (1, 75, (0.3, 0.1), 30),
                                      (2, 150, (0.0, 0.2), 25)):
        a = math.radians(azimuth)
        key = vtkCamera()
        key.SetFocalPoint(0, 0, 0)
        key.SetPosition(8 * math.sin(a), 2.0, 8 * math.cos(a))
        key.SetViewAngle(angle)
        key.SetWindowCenter(*center)
        if not anim.path.AddCamera(t, key):
            raise RuntimeError("camera key %d rejected" % t)

    # Prop keys: the cone spins 400 degrees in 100-degree steps, shearing as it goes.
    anim.spin = vtkTransformInterpolatorLCT()
    anim.spin.ConsistentRotationOn()  # keep spinning past 180 degrees per step
    for k in range(5):
        shear = vtkMatrix4x4()
        shear.SetElement(0, 1, 0.3 * (k % 2))
        key = vtkTransform()
        key.PostMultiply()
        key.Concatenate(shear)
        key.RotateY(100.0 * k)
        if not anim.spin.AddTransform(k, key):
            raise RuntimeError("cone key %d rejected" % k)

    # The cue.
    anim.cue = vtkInterpolatorCueLCT()
    anim.cue.SetCamera(anim.renderer.GetActiveCamera())
    anim.cue.SetCameraInterpolator(anim.path)
    anim.cue.SetRenderer(anim.renderer)  # refit the clipping range every frame
    anim.cue.AddProp(anim.cone, anim.spin)
    anim.cue.SetTimeModeToNormalized()
    anim.cue.SetStartTime(0.0)
    anim.cue.SetEndTime(1.0)
    return anim


def play(anim, out_dir, frames, on_frame=None):
    """Plays the scene in sequence mode, writing each frame; returns the file names.
    `on_frame(anim)` is called after each frame is written."""
    os.makedirs(out_dir, exist_ok=True)
    grab = vtkWindowToImageFilter()
    grab.SetInput(anim.window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    written = []

    def write_frame(caller, event):
        anim.window.Render()
        grab.Modified()
        name = os.path.join(out_dir, "frame_%04d.png" % len(written))
        writer.SetFileName(name)
        writer.Write()
        written.append(name)
        if on_frame:
            on_frame(anim)

    observer = anim.cue.AddObserver(vtkCommand.AnimationCueTickEvent, write_frame)
    scene = vtkAnimationScene()
    scene.SetModeToSequence()
    scene.SetFrameRate(frames - 1)
    scene.SetStartTime(0.0)
    scene.SetEndTime(1.0)
    scene.AddCue(anim.cue)
    scene.Play()
    anim.cue.RemoveObserver(observer)
    return written


def main(out_dir="out/scripted", frames=36):
    if not os.environ.get("DISPLAY"):
        print("ScriptedAnimation: no DISPLAY; run it under xvfb-run -a")
        return 125
    written = play(build(), out_dir, frames)
    print("ScriptedAnimation: wrote %d frames to %s" % (len(written), out_dir))
    return 0 if len(written) >= frames - 1 else 1


if __name__ == "__main__":
    sys.exit(main(*(sys.argv[1:2] + [int(a) for a in sys.argv[2:3]])))
