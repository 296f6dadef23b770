"""A ParaView-style scripted animation with vtklct.

An animation scene with one cue that flies the camera through three keys (a 150-degree turn, a
shift of the centre of projection, a zoom) and spins a cone through 400 degrees with shear, and a
tick observer that renders each frame offscreen and writes it as a PNG:

    xvfb-run -a /usr/bin/python3 Examples/ScriptedAnimation.py [--size WxH] [out_dir] [frames]

with the build tree on PYTHONPATH (`scripts/env python3 Examples/ScriptedAnimation.py`), or an
installed prefix (PYTHONPATH=<prefix>/lib/python3/dist-packages). `--help` for the options.
"""
import argparse
import ctypes
import ctypes.util
import math
import os
import re
import sys

try:
    from vtklct import (vtkCameraInterpolatorLCT, vtkInterpolatorCueLCT,
                        vtkTransformInterpolatorLCT)
    from vtkmodules.vtkCommonCore import vtkCommand
    from vtkmodules.vtkCommonDataModel import vtkAnimationScene
    from vtkmodules.vtkCommonMath import vtkMatrix4x4
    from vtkmodules.vtkCommonTransforms import vtkTransform
    from vtkmodules.vtkFiltersSources import vtkConeSource, vtkCubeSource, vtkSphereSource
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkCamera, vtkPolyDataMapper, vtkRenderer,
                                             vtkRenderWindow, vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401  (the OpenGL render window)
except ImportError as error:
    if __name__ != "__main__":
        raise
    # The usual cause is the interpreter or the path, not the script: say which to use.
    sys.exit("ScriptedAnimation: %s\nRun it with /usr/bin/python3 (Debian's VTK is built for it) "
             "and PYTHONPATH=<build>/lib/python3/dist-packages or "
             "<prefix>/lib/python3/dist-packages." % error)

DEFAULT_OUT = "out/scripted"
DEFAULT_FRAMES = 36
DEFAULT_SIZE = (480, 270)
MIN_FRAMES, MAX_FRAMES = 2, 100000  # the scene needs two ticks; the top bounds the disk use
MIN_SIDE, MAX_SIDE, MAX_PIXELS = 16, 16384, 1 << 26  # what lct-render accepts


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


def build(width=DEFAULT_SIZE[0], height=DEFAULT_SIZE[1]):
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
    `on_frame(anim)` is called after each frame is written. Raises RuntimeError if a frame
    cannot be written."""
    if frames < MIN_FRAMES:
        raise ValueError("frames = %d: the scene needs at least %d" % (frames, MIN_FRAMES))
    os.makedirs(out_dir, exist_ok=True)
    grab = vtkWindowToImageFilter()
    grab.SetInput(anim.window)
    writer = vtkPNGWriter()
    writer.SetInputConnection(grab.GetOutputPort())
    written = []
    failed = []

    def write_frame(caller, event):
        anim.window.Render()
        grab.Modified()
        name = os.path.join(out_dir, "frame_%04d.png" % (len(written) + len(failed)))
        writer.SetFileName(name)
        writer.Write()
        # VTK reports a failed write through the error code only (an exception raised in an
        # observer would be printed and swallowed), so collect it and raise after Play().
        if writer.GetErrorCode() != 0:
            failed.append(name)
            return
        written.append(name)
        if on_frame:
            on_frame(anim)

    observer = anim.cue.AddObserver(vtkCommand.AnimationCueTickEvent, write_frame)
    scene = vtkAnimationScene()
    scene.SetModeToSequence()
    # The scene adds 1/FrameRate per tick; with exactly frames - 1 the rounding of that sum can
    # step past EndTime and drop the last frame (36 asked, 35 written). A rate larger by a
    # relative 1e-9 keeps the last tick inside [0, 1], 1e-9 short of its end (far below what
    # a pixel shows), and the next one beyond it, for any frame count up to MAX_FRAMES.
    scene.SetFrameRate((frames - 1) * (1.0 + 1e-9))
    scene.SetStartTime(0.0)
    scene.SetEndTime(1.0)
    scene.AddCue(anim.cue)
    scene.Play()
    anim.cue.RemoveObserver(observer)
    if failed:
        more = " (and %d more frames)" % (len(failed) - 1) if len(failed) > 1 else ""
        raise RuntimeError("cannot write %s%s" % (failed[0], more))
    return written


def frame_count(text):
    """argparse type of `frames`: a whole number in [MIN_FRAMES, MAX_FRAMES]."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError("%r is not a whole number" % text)
    if not MIN_FRAMES <= value <= MAX_FRAMES:
        raise argparse.ArgumentTypeError(
            "%d is out of range: must be in [%d, %d]" % (value, MIN_FRAMES, MAX_FRAMES))
    return value


def image_size(text):
    """argparse type of --size: WxH within the sides and pixel count lct-render accepts."""
    match = re.fullmatch(r"([0-9]+)x([0-9]+)", text)
    if not match:
        raise argparse.ArgumentTypeError("%r is not of the form WxH, e.g. 640x360" % text)
    width, height = int(match.group(1)), int(match.group(2))
    if not (MIN_SIDE <= width <= MAX_SIDE and MIN_SIDE <= height <= MAX_SIDE) or \
            width * height > MAX_PIXELS:
        raise argparse.ArgumentTypeError(
            "%s is out of range: %d..%d per side and at most %d pixels"
            % (text, MIN_SIDE, MAX_SIDE, MAX_PIXELS))
    return width, height


def parse_arguments(argv):
    """The parsed command line; exits 0 after --help, 2 (with a message) on a usage error."""
    parser = argparse.ArgumentParser(
        description="Play a ParaView-style animation scene driven by vtklct's interpolators "
        "(a camera flight with a 150-degree turn, a window-centre shift and a zoom, and a cone "
        "spinning 400 degrees with shear) and write every frame as OUT_DIR/frame_NNNN.png.",
        epilog="Renders offscreen through X (this VTK has no EGL or OSMesa): without a display "
        "run it as `xvfb-run -a /usr/bin/python3 ScriptedAnimation.py ...`. Needs vtklct on "
        "PYTHONPATH (<build>/lib/python3/dist-packages or <prefix>/lib/python3/"
        "dist-packages). Exit codes: 0 all frames written, 1 error, 2 usage, 125 no DISPLAY.")
    parser.add_argument(
        "out_dir", nargs="?", default=DEFAULT_OUT,
        help="output directory, created if missing (default: %(default)s)")
    parser.add_argument(
        "frames", nargs="?", type=frame_count, default=DEFAULT_FRAMES,
        help="number of frames, %d..%d (default: %%(default)s)" % (MIN_FRAMES, MAX_FRAMES))
    parser.add_argument(
        "--size", type=image_size, default=DEFAULT_SIZE, metavar="WxH",
        help="image size, %d..%d per side (default: %dx%d)"
        % (MIN_SIDE, MAX_SIDE, DEFAULT_SIZE[0], DEFAULT_SIZE[1]))
    args = parser.parse_args(argv)
    if not args.out_dir:
        parser.error("argument out_dir: must not be empty")
    if os.path.exists(args.out_dir) and not os.path.isdir(args.out_dir):
        parser.error("argument out_dir: %s exists and is not a directory" % args.out_dir)
    return args


def display_answers():
    """Whether an X server answers at DISPLAY: VTK 9.1's X render window calls abort() when
    none does (exit 134), so it is asked first."""
    if not os.environ.get("DISPLAY"):
        return False
    try:
        xlib = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    except OSError:
        return True  # no Xlib to ask with: let VTK try
    xlib.XOpenDisplay.restype = ctypes.c_void_p
    xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
    xlib.XCloseDisplay.argtypes = [ctypes.c_void_p]
    connection = xlib.XOpenDisplay(None)
    if not connection:
        return False
    xlib.XCloseDisplay(connection)
    return True


def main(argv=None):
    args = parse_arguments(sys.argv[1:] if argv is None else argv)
    if not display_answers():
        print("ScriptedAnimation: no X display (DISPLAY unset, or no server answers at %r); "
              "run it under xvfb-run -a" % os.environ.get("DISPLAY", ""), file=sys.stderr)
        return 125
    try:
        written = play(build(*args.size), args.out_dir, args.frames)
    except (OSError, RuntimeError) as error:
        print("ScriptedAnimation: %s" % error, file=sys.stderr)
        return 1
    print("ScriptedAnimation: wrote %d frames to %s" % (len(written), args.out_dir))
    if len(written) != args.frames:
        print("ScriptedAnimation: %d frames asked for" % args.frames, file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
