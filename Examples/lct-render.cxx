// lct-render: render a keyframed camera flight (and animated props) through
// vtkCameraInterpolatorLCT / vtkTransformInterpolatorLCT to PNG frames, an Ogg Theora video and a
// contact sheet, and print Hawkins & Grimm's path-quality metric. See `lct-render --help`.
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 ok, 1 error, 2 usage, 125 no DISPLAY.
#include "CameraFlightScene.h"
#include "RenderKeys.h"

#include "lct/OutputFile.h"

#include "vtkCallbackCommand.h"
#include "vtkCameraInterpolator.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCameraPathMetric.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCollection.h"
#include "vtkColorTransferFunction.h"
#include "vtkCommand.h"
#include "vtkCompositeDataGeometryFilter.h"
#include "vtkConeSource.h"
#include "vtkCubeSource.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGLTFReader.h"
#include "vtkGeometryFilter.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightKit.h"
#include "vtkLogger.h"
#include "vtkMatrix4x4.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkOggTheoraWriter.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkSkinnedMeshReaderLCT.h"
#include "vtkSphereSource.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransformInterpolatorLCT.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace
{
namespace fs = std::filesystem;
namespace Limits = RenderKeys::Limits;
using RenderKeys::InputError;
using RenderKeys::Num;

/// Cameras the path metric samples per key segment (and in all), whatever --frames says: the
/// metric then costs the same for 2 frames as for 10^6, and slices of a run agree on it.
constexpr int MetricSamples = 65;
constexpr int MetricBudget = 4000;

const char* const Usage =
  R"(usage: lct-render [options] [keys.json] [state.pvsm | view1.pvcc view2.pvcc ...]
       lct-render --describe [options] [keys.json] [...]
       lct-render assemble DIR [--fps N]

Renders a keyframed camera flight through vtkCameraInterpolatorLCT (props through
vtkTransformInterpolatorLCT) offscreen to DIR/frame_NNNN.png, DIR/video.ogv (Ogg Theora) and
DIR/contact_sheet.png (4x4 evenly spaced frames), and prints the path-quality metric
(vtkCameraPathMetric::EvaluateSegments: mean excess path length of the scene's points, camera
space and screen, per key segment and in total, against the true key cameras, with how far the
path misses its keys; sampled per segment until the excess converges, whatever --frames is;
with --compare also VTK's path, as it is and with the window centre lerped between the keys).

What is drawn: the objects of the keys file's "scene" section and the --mesh meshes, nothing
else. The built-in demo scene (floor, pedestal, the Wuson model, sphere, cube, cone; 6 x 6 units
on the floor y = 0 around the origin, named floor, pedestal, model, sphere, cube, cone) is drawn
only with --demo-scene, or when neither a keys file nor --mesh is given. Without a keys file the
built-in keys play: a 130-degree turn with a window-centre shift and a zoom, and the cone
tumbling 720 degrees while it shears (the cone's keys only with the demo scene).

options:
  --frames N         render N frames (default 48, 1 <= N <= 1000000); frame i is at time
                     tmin + i/(N-1) (tmax-tmin) (see "time" below)
  --frames A:B/N     render only frames A..B-1 of N (files keep their global numbers, so the
                     slices of several runs equal one full run); no video or contact sheet
                     (`lct-render assemble DIR` makes them once all slices are done).
                     A:B alone means A:B/48
  --size WxH         image size (default: the scene's "size", else 640x360; 16..16384 per side,
                     at most 2^26 = 67108864 pixels; above 2^22 pixels fewer multisamples are
                     used: 2^25 samples at most)
  --fps N            frame rate of video.ogv (default 24, 1 <= N <= 240)
  --interpolation linear|spline|bspline|subdivision
                     curve scheme for the camera and every prop (overrides the file)
  --tension T, --continuity C, --bias B
                     Kochanek-Bartels tension, continuity and bias (each in [-1, 1]) of the
                     camera path and every prop path, replacing the paths' own "tension",
                     "continuity", "bias" (keys with their own keep them); spline type only
  --tangents monotone|monotone_cubic|catmull_rom
                     the spline's tangents on the camera path and every prop path, replacing
                     the paths' own "tangents" (see "timing")
  --ease-in E, --ease-out E
                     ease of the camera path and every prop path (each in [0, 1]; 1: from or to
                     rest): ease-in starts slowly, ease-out ends slowly (replaces the paths' own)
  --constant-speed   constant speed on for the camera path and every prop path (see "timing")
                     Flags apply whatever the camera keys come from (keys file, .pvcc, .pvsm).
  --compare          split screen: left vtkCameraInterpolatorLCT, right VTK's vtkCameraInterpolator
                     on the same camera keys (bspline/subdivision: VTK uses its spline; at most
                     1000 camera keys: VTK's interpolator initialises in quadratic time)
  --mesh NAME=FILE   add a mesh (a mesh file as in scene objects, world coordinates) that
                     props.NAME can animate (repeatable; at most 16 mesh files in all)
  --demo-scene       draw the built-in demo scene too
  --describe         print the scene's bounds, each object's bounds, arrays and visibility, the
                     time ranges, the camera keys and every path's timing (with constant speed the
                     key arrival times), then exit (writes nothing, needs no X)
  --out DIR          output directory (default out/render; created if missing)
  --overwrite        replace the frames of a different earlier run in DIR (see "output")
  -h, --help         this help

a complete keys file (valid JSON, every field used once; it needs a part.vtu with a point
array "temperature" beside it; Render.HelpExample checks that it reads):
  {"scene": {
     "size": [640, 360], "anti_aliasing": "msaa",
     "background": [0.12, 0.14, 0.2], "background_top": [0.45, 0.55, 0.7],
     "lights": [{"position": [5, 8, 5], "focal_point": [0, 0, 0], "color": [1, 1, 0.95],
                 "intensity": 0.9, "camera": false}],
     "objects": {
       "part": {"file": "part.vtu", "color_by": "temperature", "color_map": "viridis",
                "scalar_range": [0, 1]},
       "ground": {"source": "plane", "center": [0, 0, 0], "size": [6, 6], "normal": [0, 1, 0],
                  "color": [0.7, 0.7, 0.65], "opacity": 1, "representation": "surface",
                  "visible": true, "line_width": 1, "point_size": 3},
       "ball": {"source": "sphere", "center": [1.5, 0.5, 0], "radius": 0.5, "resolution": 32},
       "box": {"source": "cube", "center": [-1.5, 0.5, 0], "size": [1, 1, 1]},
       "tip": {"source": "cone", "center": [0, 0.5, -1.5], "radius": 0.5, "height": 1,
               "direction": [0, 1, 0], "resolution": 32, "representation": "wireframe"},
       "frame": {"source": "axes", "center": [-2.5, 0, 2.5], "length": 1}}},
   "camera": {"interpolation": "spline", "consistent_rotation": false,
              "tension": 0, "continuity": 0, "bias": 0, "tangents": "monotone",
              "ease_in": 0.5, "ease_out": 0, "constant_speed": false,
              "constant_speed_measure": "eye_and_focal_point",
              "keys": [{"time": 0, "position": [5, 3, 6], "focal_point": [0, 0.5, 0],
                        "view_up": [0, 1, 0], "view_angle": 30, "window_center": [0, 0],
                        "view_shear": [0, 0, 1], "parallel_scale": 1, "parallel": false,
                        "clipping_range": [0.5, 30]},
                       {"time": 1, "position": [0, 3, 7], "focal_point": [0, 0.5, 0],
                        "clipping_range": [0.5, 30], "tension": 0.5, "continuity": 0,
                        "bias": -0.2, "ease_in": 0.3, "ease_out": 0.3},
                       {"time": 2, "position": [-5, 3, 6], "focal_point": [0, 0.5, 0],
                        "clipping_range": [0.5, 30]}]},
   "props": {"ball": {"interpolation": "spline", "consistent_rotation": false,
                      "tension": 0, "continuity": 0, "bias": 0, "tangents": "catmull_rom",
                      "ease_in": 0, "ease_out": 0.5, "constant_speed": true,
                      "constant_speed_point": [0, 0, 0],
                      "keys": [{"time": 0, "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]},
                               {"time": 2, "translate": [0, 1, 0], "rotate": [90, 0, 1, 0],
                                "scale": [1, 1.5, 1], "shear": [0.2, 0, 0]}]}}}

fields (defaults after "="): scene: size = --size or 640x360, anti_aliasing = msaa (msaa, fxaa,
  none), background = [0.96, 0.95, 0.92], background_top (a gradient; none), lights = "kit" (a
  vtkLightKit; "headlight"; or 1..16 lights: position, focal_point = [0,0,0], color = [1,1,1],
  intensity = 1, camera = false (true: moves with the camera)). Objects: "file" or "source"
  (sphere: center = [0,0,0], radius = 0.5, resolution = 32; cube: center, size = [1,1,1];
  cone: center, radius = 0.5, height = 1, direction = [0,1,0], resolution = 32; plane: center,
  size = [1,1], normal = [0,0,1]; axes: center, length = 1); color (none: the file's own RGB
  colours or a palette's; axes are red, green, blue), opacity = 1, representation = surface
  (surface, wireframe, points), visible = true, color_by (none), color_map = cool to warm
  (cool to warm, viridis, rainbow, grayscale), scalar_range = the array's, line_width = 1,
  point_size = 3. Camera keys: time, position, focal_point required; view_up = [0,1,0],
  view_angle = 30, window_center = [0,0], view_shear = [0,0,1], parallel_scale = 1,
  parallel = false, clipping_range (none: reset per frame); at least 2 keys. Prop keys: time,
  and matrix (16 numbers, row-major, last row 0 0 0 1) or translate = [0,0,0],
  rotate = [0, 0,0,1] (degrees, axis), scale = [1,1,1], shear = [0,0,0]. A key is a pose: its
  rotate is an orientation (720 and 0 are the same key, 270 is -90), and the path between two
  keys turns the short way; key a turn of more than 180 degrees in steps below 180.
  Timing (see "timing" below), of the camera and of each props.NAME: tension = 0,
  continuity = 0, bias = 0 (each in [-1, 1]), tangents = monotone (monotone_cubic, catmull_rom), ease_in = 0,
  ease_out = 0 (each in [0, 1]), constant_speed = false; the camera's constant_speed_measure = eye_and_focal_point (eye,
  focal_point), a prop's constant_speed_point = [0,0,0]. Of every camera and prop key:
  tension, continuity, bias (none: the path's; any one given: the key's own, the others 0),
  ease_in = 0, ease_out = 0.
  Unknown keys are errors (a misspelt field would otherwise silently keep its default).
  Object files: .vtp .vtu .vtk (legacy POLYDATA) .stl .ply .obj .glb .gltf (VTK's readers), and
  every other format assimp reads (.fbx .dae .x .3ds .blend .ms3d .md5mesh .lwo .off ...; an
  unsupported extension's message lists them all): all of the file's meshes in their bind pose,
  triangulated, with the bone weights as point data (vtkSkinnedMeshReaderLCT). A relative name is
  relative to the keys file's folder. color_by names a point array (else a cell array); arrays
  of several components are coloured by their magnitude. Colours are [r, g, b] in [0, 1].
  Without a "scene" section: no objects (give --mesh or --demo-scene), VTK's headlight, the
  default background.
  props.NAME animates the object NAME (a scene object, a --mesh name or, with the demo scene,
  a demo object). A prop key M = translate rotate shear scale is applied about the object's
  centre (its bounding-box centre in the scene), in world axes. shear [xy, xz, yz]: x moves by
  xy times y and by xz times z, y moves by yz times z (x' = x + xy y + xz z, y' = y + yz z).
  Keys may come in any order; their times must differ.

time: the frames span from the earliest key of any track (camera, each prop) to the latest.
  Each track is clamped to its own key range: before its first key it holds the first key,
  after its last key the last (so a prop whose keys end at t = 2 stands still while the camera
  flies on to t = 4). The path metric measures the camera over its own key range.
timing: tension, continuity and bias are the Kochanek-Bartels parameters of the spline type
  (vtkKochanekSpline's, applied in log space; all 0: the default tangents), for the keys without
  their own; every key is still reached at its time. tangents: the spline's tangents at keys
  without tension, continuity or bias: monotone (Fritsch & Butland's, the default: no
  overshoot where the path slows down, stops or turns back at a key; a prop's path is nearly
  straight beside a key it bounces off), monotone_cubic (the same tangents, the cubic beside
  such keys too; for the camera the same as monotone) or catmull_rom (the
  tangent parallel to the chord of the two neighbours, which swings past such keys). A path's
  ease_in makes it start slowly, ease_out end slowly (1: from or to rest; on the first and
  last key segment, with constant_speed on the whole path). A key's ease_in slows the motion arriving at it, ease_out
  the motion leaving it (speed times 1 - ease). constant_speed: the path is the same but is
  travelled at an even speed (by arc length; the keys' own eases then do not apply): the
  camera's eye and focal point together (eye_and_focal_point), the eye or the focal point; a
  prop's constant_speed_point, relative to the object's centre (default: the centre). The keys
  are then passed at other times, which --describe prints ("key arrival times"), with every
  path's timing. The flags --tension, --continuity, --bias, --tangents, --ease-in,
  --ease-out and --constant-speed replace these for every path.
clipping range: without clipping_range (the default), each frame's near and far planes are
  reset from the bounds of the visible objects (vtkRenderer::ResetCameraClippingRange); with
  clipping_range on every camera key, the interpolated range is used as it is. Some keys with
  and some without is an error.

ParaView files, as the camera keys (replacing the keys file's camera, which may then be left
out so that the keys file gives only the scene and props):
  .pvcc (ParaView's "Save Camera"), given in order: one key each, at t = 0, 1, 2, ...
  .pvsm (a saved state): the first enabled CameraAnimationCue (the Animation View's Camera
        track) with its CameraKeyFrame proxies: KeyTime, Position, FocalPoint, ViewUp,
        ViewAngle, ParallelScale, the view's CameraParallelProjection, the cue's Interpolation
        (linear or spline, unless --interpolation) at time StartTime + KeyTime (EndTime -
        StartTime) of the cue, whose times are fractions of the AnimationScene's StartTime ..
        EndTime (TimeMode Normalized, ParaView's default) or offsets from its StartTime
        (Relative). Path-based and follow-data tracks: the key frames' cameras are used.
  Any other XML is refused with what is accepted.

output: frames, video and sheet are written under a temporary name (.NAME.PID.RANDOM.part, created new) and renamed
when complete; a failed run removes its temporary files and never leaves a partial file under a
final name. A final name that is a symbolic link is written through (the link stays); one that is
a directory, FIFO or device is refused before rendering. DIR/manifest.json records the run
(frame count, size, fps, interpolation, compare, scene, and each input file's path, size and
FNV-1a hash). A run into a DIR that holds frames of a different run (or frames without a
manifest) is refused unless --overwrite, which removes those frames, video and sheet first;
slices of one run (same parameters and inputs) add up.
`lct-render assemble DIR [--fps N]` checks that DIR holds every frame of its manifest's run at
its size and writes video.ogv (at the manifest's fps unless --fps) and contact_sheet.png from
them (needs no X). Progress: per-frame lines with the rate and an ETA.

limits (input outside them is refused with a message naming the file and the key):
  keys file <= 32 MiB, JSON nesting <= 64; <= 10000 keys per track (camera, each prop)
  |time| <= 1e12; coordinates (position, focal_point, view_up, matrix, translate, center)
  within +-1e15; view_angle in [1e-08, 179] (vtkCamera's own range); parallel_scale,
  clipping_range, radius, height, size, length in [1e-12, 1e15]; window_center, view_shear,
  shear within +-1000; scale in [1e-09, 1e09]; rotate angle within +-1e6 degrees;
  tension, continuity, bias in [-1, 1]; ease_in, ease_out in [0, 1]; constant_speed_point
  within +-1e15;
  <= 256 scene objects, <= 16 lights, resolution 3..1024, line_width and point_size 0.1..100
  .pvcc file <= 1 MiB, .pvsm <= 64 MiB, XML nesting <= 256; every value of the properties read
  a complete, finite decimal number

meshes: a file is checked before a VTK reader sees it, then VTK's reader runs in a child
process (a crash or a runaway allocation of the reader is an error message, not a crash):
  all      a regular file, not empty, <= 1 GiB; after reading: >= 1 point, <= 2^24 points,
           <= 2^24 cells, <= 2^26 cell indices, every index in range, every point finite and
           within +-1e15, at least one cell
  .stl     binary (as VTK detects it): the file size must be 84 + 50 x the triangle count of its
           header; ASCII: must start with "solid" (the rest is VTK's parser, which reports errors)
  .ply     the whole file: header (the vertex element first), element counts against the file
           size, every line (ASCII) or byte (binary), list lengths, face indices in range
  .obj     the whole file: lines <= 262144 bytes, vertex coordinates finite, every face/line/
           point index (v, vt, vn, negative ones too) in range
  .vtk     legacy POLYDATA: header, declared point and cell counts against the limits and the
           file size; ASCII bodies: every point and cell token and index
  .vtp .vtu  declared NumberOf* counts against the limits; the XML and its data are VTK's
  .glb     the 12-byte header: magic, version 2, length = the file's size; .gltf: a JSON
           object with "asset"; the rest is VTK's vtkGLTFReader (in the child process)
  assimp's formats: the checks of all; the rest is assimp's (vtkSkinnedMeshReaderLCT, in the
           child process)

Run it under `xvfb-run -a` when there is no display.
exit codes: 0 ok, 1 error (bad input, failed interpolation, failed write), 2 usage,
125 no DISPLAY
)";

// ---------------------------------------------------------------------------------------------
// Temporary files: removed on every failure, also when a signal ends the process.

constexpr int MaxTemporaries = 4;
char Temporaries[MaxTemporaries][4096];

void RemoveTemporaries()
{
  for (auto& t : Temporaries)
  {
    if (t[0])
    {
      ::unlink(t); // async-signal-safe
      t[0] = '\0';
    }
  }
}

extern "C" void OnFatalSignal(int sig)
{
  RemoveTemporaries();
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

/// Where a write to `file` goes (lct::outputTarget): renaming over a link would replace it.
fs::path OutputTarget(const fs::path& file)
{
  return lct::outputTarget(file);
}

/// "FILE exists and is not a regular file" if `file` is, or leads to, a directory, a FIFO, a
/// device or a socket, which a write must not replace; else "".
std::string NotARegularFile(const fs::path& file)
{
  return lct::notARegularFile(file);
}

/// A file being written under a temporary name next to its final name (or, when that is a
/// symbolic link, next to the file it leads to); removed unless Commit() renamed it. The file is
/// created, empty, when the object is (lct::createTemporaryBeside: exclusively, under a name no
/// one can foresee), so a writer that opens path() itself (VTK's PNG and Ogg writers) writes
/// into this new file and never through a link or into a FIFO put there beforehand.
class Temporary
{
public:
  explicit Temporary(const fs::path& final)
    : Final(OutputTarget(final))
  {
    std::string path;
    this->Descriptor = lct::createTemporaryBeside(this->Final, path, this->Error);
    if (this->Descriptor < 0)
    {
      return;
    }
    this->Path = path;
    for (this->Slot = 0; this->Slot < MaxTemporaries && Temporaries[this->Slot][0]; ++this->Slot)
    {
    }
    if (this->Slot < MaxTemporaries && path.size() < sizeof Temporaries[0])
    {
      std::snprintf(Temporaries[this->Slot], sizeof Temporaries[0], "%s", path.c_str());
    }
    else
    {
      this->Slot = -1; // not removed by a signal; the destructor still removes it
    }
  }
  ~Temporary() { this->Discard(); }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;

  /// Why the file could not be created, or "".
  const std::string& error() const { return this->Error; }
  const fs::path& path() const { return this->Path; }
  /// The open file (-1 once closed or when it could not be created); CloseFile() closes it.
  int file() const { return this->Descriptor; }
  /// Closes the file; errno's message on failure (a full disk can show only here), else "".
  std::string CloseFile()
  {
    if (this->Descriptor >= 0 && ::close(std::exchange(this->Descriptor, -1)) != 0)
    {
      return std::strerror(errno);
    }
    return "";
  }

  /// Renames the temporary to the final name; on failure the temporary is removed and the
  /// reason returned.
  std::string Commit()
  {
    this->CloseFile();
    // Checked before the run too (CheckOutput, Assemble); again here (replaceWithTemporary), as
    // rename() would replace a FIFO or a device put under the final name since.
    std::string why;
    const bool renamed = lct::replaceWithTemporary(this->Path.string(), this->Final, why);
    this->Release();
    return renamed ? "" : why;
  }

  void Discard()
  {
    this->CloseFile();
    if (!this->Path.empty())
    {
      ::unlink(this->Path.c_str());
    }
    this->Release();
  }

private:
  void Release()
  {
    if (this->Slot >= 0)
    {
      Temporaries[this->Slot][0] = '\0';
      this->Slot = -1;
    }
    this->Path.clear();
  }
  fs::path Final;
  fs::path Path;
  std::string Error;
  int Descriptor = -1;
  int Slot = -1;
};

/// Writes `size` bytes to `file` through a temporary, checking every write (a full disk or a
/// file-size limit is an error here, not a short file). Returns the reason on failure.
std::string WriteFileAtomically(const fs::path& file, const unsigned char* data, size_t size)
{
  Temporary tmp(file);
  if (!tmp.error().empty())
  {
    return tmp.error();
  }
  size_t done = 0;
  while (done < size)
  {
    const ssize_t n = ::write(tmp.file(), data + done, size - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const std::string why = n < 0 ? std::strerror(errno) : "nothing written";
      return "writing " + file.string() + " failed: " + why;
    }
    done += static_cast<size_t>(n);
  }
  const std::string closeError = tmp.CloseFile();
  if (!closeError.empty())
  {
    return "writing " + file.string() + " failed: " + closeError;
  }
  return tmp.Commit();
}

// ---------------------------------------------------------------------------------------------
// VTK errors as messages

/// Collects the text of vtkErrorMacro calls on an object (instead of printing them) while it
/// exists: the observer is removed in the destructor, so no event can reach a dead catcher.
class ErrorCatcher
{
public:
  explicit ErrorCatcher(vtkObject* object)
    : Object(object)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      static_cast<ErrorCatcher*>(self)->Message = data ? static_cast<const char*>(data) : "";
    });
    this->Tag = object->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
  ~ErrorCatcher() { this->Object->RemoveObserver(this->Tag); }
  ErrorCatcher(const ErrorCatcher&) = delete;
  ErrorCatcher& operator=(const ErrorCatcher&) = delete;

  /// The last message without VTK's "ERROR: In file, line n\nclass (0x...): " prefix.
  std::string Take()
  {
    std::string m = this->Message;
    this->Message.clear();
    while (!m.empty() && (m.back() == '\n' || m.back() == ' '))
    {
      m.pop_back();
    }
    const size_t nl = m.rfind('\n');
    if (nl != std::string::npos)
    {
      m = m.substr(nl + 1);
    }
    const size_t self = m.find("): ");
    if (self != std::string::npos && m.find(" (0x") < self)
    {
      m = m.substr(self + 3);
    }
    return m.empty() ? "no reason given" : m;
  }

private:
  vtkSmartPointer<vtkObject> Object;
  vtkNew<vtkCallbackCommand> Command;
  unsigned long Tag = 0;
  std::string Message;
};

/// In the mesh-reading child: keeps the last lines VTK printed (errors and warnings of the
/// readers, several of which report through vtkGenericWarningMacro only).
class CapturingOutputWindow : public vtkOutputWindow
{
public:
  static CapturingOutputWindow* New();
  vtkTypeMacro(CapturingOutputWindow, vtkOutputWindow);
  void DisplayText(const char* text) override
  {
    if (text)
    {
      std::string line = text;
      const size_t start = line.find_first_not_of("\n ");
      line = start == std::string::npos ? "" : line.substr(start);
      const size_t nl = line.find("\n");
      if (line.rfind("ERROR: In ", 0) == 0 || line.rfind("Warning: In ", 0) == 0)
      {
        line = nl == std::string::npos ? "" : line.substr(nl + 1);
      }
      while (!line.empty() && (line.back() == '\n' || line.back() == ' '))
      {
        line.pop_back();
      }
      const size_t self = line.find("): ");
      if (self != std::string::npos && line.find(" (0x") < self)
      {
        line = line.substr(self + 3);
      }
      if (!line.empty() && line.find("returned failure for request") == std::string::npos)
      {
        this->Last = line.substr(0, 300);
      }
    }
  }
  std::string Last;
};
vtkStandardNewMacro(CapturingOutputWindow);

// ---------------------------------------------------------------------------------------------
// Command line

struct Options
{
  int Frames = 48;
  int First = 0;
  int Last = -1; // exclusive; -1: Frames
  int Width = 640;
  int Height = 360;
  bool SizeGiven = false; // --size (else the scene's size, else 640x360)
  int Fps = 24;
  std::string Interpolation; // empty: from the keys
  // Timing flags, for every path (camera and props): given ones replace the paths' own.
  bool HasTension = false, HasContinuity = false, HasBias = false;
  bool HasEaseIn = false, HasEaseOut = false;
  double Tension = 0.0, Continuity = 0.0, Bias = 0.0, EaseIn = 0.0, EaseOut = 0.0;
  std::string Tangents; // empty: the paths' own
  bool ConstantSpeed = false;
  bool Compare = false;
  bool DemoScene = false;
  bool Describe = false;
  bool Overwrite = false;
  std::string Out = "out/render";
  std::string KeysFile;
  std::vector<std::string> CameraFiles; // ParaView .pvcc files, one camera key each
  std::string StateFile;                // a ParaView .pvsm state with a camera track
  std::vector<std::pair<std::string, std::string>> Meshes;
};

bool EndsWith(const std::string& s, const char* tail)
{
  const size_t n = std::strlen(tail);
  return s.size() > n && s.compare(s.size() - n, n, tail) == 0;
}

/// Whether a file name ends in the extension `tail` (".pvcc"), in any case (V0.PVCC).
bool HasExtension(const std::string& s, const char* tail)
{
  std::string lower = s;
  std::transform(lower.begin(), lower.end(), lower.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return EndsWith(lower, tail);
}

/// A decimal integer in [0, 999999999] (10 digits or more, signs, exponents: no).
bool ParseInt(const std::string& s, int& out)
{
  if (s.empty() || s.size() > 9 || s.find_first_not_of("0123456789") != std::string::npos)
  {
    return false;
  }
  out = std::stoi(s);
  return true;
}

/// Returns an empty string on success, else the usage error.
std::string ParseArgs(int argc, char* argv[], Options& o, bool& help)
{
  const std::string maxFrames = std::to_string(Limits::MaxFrames);
  for (int i = 1; i < argc; ++i)
  {
    const std::string a = argv[i];
    auto value = [&](std::string& v) {
      if (i + 1 >= argc)
      {
        return false;
      }
      v = argv[++i];
      return true;
    };
    std::string v;
    if (a == "-h" || a == "--help")
    {
      help = true;
    }
    else if (a == "--compare")
    {
      o.Compare = true;
    }
    else if (a == "--demo-scene")
    {
      o.DemoScene = true;
    }
    else if (a == "--describe")
    {
      o.Describe = true;
    }
    else if (a == "--overwrite")
    {
      o.Overwrite = true;
    }
    else if (a == "--fps")
    {
      if (!value(v) || !ParseInt(v, o.Fps) || o.Fps < 1 || o.Fps > Limits::MaxFps)
      {
        return "--fps expects a frame rate N, 1 <= N <= " + std::to_string(Limits::MaxFps) +
          (v.empty() ? std::string("") : " (got " + RenderKeys::Printable(v) + ")");
      }
    }
    else if (a == "--frames")
    {
      if (!value(v))
      {
        return "--frames needs N or A:B/N";
      }
      const size_t colon = v.find(':');
      if (colon == std::string::npos)
      {
        if (!ParseInt(v, o.Frames) || o.Frames < 1 || o.Frames > Limits::MaxFrames)
        {
          return "--frames " + RenderKeys::Printable(v) +
            ": expected a frame count N, 1 <= N <= " + maxFrames + " (or A:B/N)";
        }
        o.First = 0;
        o.Last = -1;
        continue;
      }
      const size_t slash = v.find('/');
      if (slash != std::string::npos && slash < colon)
      {
        return "--frames " + RenderKeys::Printable(v) + ": expected A:B/N";
      }
      std::string total = slash == std::string::npos ? "48" : v.substr(slash + 1);
      if (!ParseInt(v.substr(0, colon), o.First) ||
        !ParseInt(
          v.substr(colon + 1, slash == std::string::npos ? std::string::npos : slash - colon - 1),
          o.Last) ||
        !ParseInt(total, o.Frames) || o.Frames < 1 || o.Frames > Limits::MaxFrames ||
        o.First >= o.Last || o.Last > o.Frames)
      {
        return "--frames " + RenderKeys::Printable(v) +
          ": expected A:B/N with 0 <= A < B <= N <= " + maxFrames;
      }
    }
    else if (a == "--size")
    {
      const size_t x = value(v) ? v.find('x') : std::string::npos;
      const std::string expect = "--size expects WxH with " + std::to_string(Limits::MinSide) +
        ".." + std::to_string(Limits::MaxSide) + " per side and at most " +
        std::to_string(Limits::MaxPixels) + " pixels, e.g. 640x360";
      if (x == std::string::npos || !ParseInt(v.substr(0, x), o.Width) ||
        !ParseInt(v.substr(x + 1), o.Height) || o.Width < Limits::MinSide ||
        o.Height < Limits::MinSide || o.Width > Limits::MaxSide || o.Height > Limits::MaxSide)
      {
        return expect + " (got " + RenderKeys::Printable(v) + ")";
      }
      if (static_cast<long long>(o.Width) * o.Height > Limits::MaxPixels)
      {
        return expect + " (" + v + " is " +
          std::to_string(static_cast<long long>(o.Width) * o.Height) + " pixels)";
      }
      o.SizeGiven = true;
    }
    else if (a == "--interpolation")
    {
      if (!value(v) || !RenderKeys::IsInterpolationName(v))
      {
        return "--interpolation expects linear, spline, bspline or subdivision";
      }
      o.Interpolation = v;
    }
    else if (a == "--tension" || a == "--continuity" || a == "--bias" || a == "--ease-in" ||
      a == "--ease-out")
    {
      const bool ease = a == "--ease-in" || a == "--ease-out";
      const double lo = ease ? 0.0 : -1.0;
      const char* letter = a == "--tension" ? "T"
        : a == "--continuity"               ? "C"
        : a == "--bias"                     ? "B"
                                            : "E";
      double number = 0.0;
      if (!value(v) || !RenderKeys::ParseNumber(v.c_str(), lo, 1.0, number))
      {
        return a + " expects a number " + letter + ", " + Num(lo) + " <= " + letter + " <= 1" +
          (v.empty() ? std::string("") : " (got " + RenderKeys::Printable(v) + ")");
      }
      if (a == "--tension")
      {
        o.HasTension = true;
        o.Tension = number;
      }
      else if (a == "--continuity")
      {
        o.HasContinuity = true;
        o.Continuity = number;
      }
      else if (a == "--bias")
      {
        o.HasBias = true;
        o.Bias = number;
      }
      else if (a == "--ease-in")
      {
        o.HasEaseIn = true;
        o.EaseIn = number;
      }
      else
      {
        o.HasEaseOut = true;
        o.EaseOut = number;
      }
    }
    else if (a == "--tangents")
    {
      const auto& names = RenderKeys::TangentNames();
      if (!value(v) || std::find(names.begin(), names.end(), v) == names.end())
      {
        return "--tangents expects monotone, monotone_cubic or catmull_rom" +
          (v.empty() ? std::string("") : " (got " + RenderKeys::Printable(v) + ")");
      }
      o.Tangents = v;
    }
    else if (a == "--constant-speed")
    {
      o.ConstantSpeed = true;
    }
    else if (a == "--mesh")
    {
      const size_t eq = value(v) ? v.find('=') : std::string::npos;
      if (eq == std::string::npos || eq == 0 || eq + 1 == v.size())
      {
        return "--mesh expects NAME=FILE";
      }
      if (static_cast<int>(o.Meshes.size()) >= Limits::MaxMeshes)
      {
        return "--mesh: at most " + std::to_string(Limits::MaxMeshes) + " meshes";
      }
      o.Meshes.emplace_back(v.substr(0, eq), v.substr(eq + 1));
    }
    else if (a == "--out")
    {
      if (!value(v) || v.empty())
      {
        return "--out needs a directory";
      }
      o.Out = v;
    }
    else if (!a.empty() && a[0] == '-')
    {
      return "unknown option " + RenderKeys::Printable(a);
    }
    else if (HasExtension(a, ".pvcc"))
    {
      if (o.CameraFiles.size() >= Limits::MaxKeys)
      {
        return "at most " + std::to_string(Limits::MaxKeys) + " .pvcc files";
      }
      o.CameraFiles.push_back(a);
    }
    else if (HasExtension(a, ".pvsm"))
    {
      if (!o.StateFile.empty())
      {
        return "more than one ParaView state file (" + RenderKeys::Printable(o.StateFile) + ", " +
          RenderKeys::Printable(a) + ")";
      }
      o.StateFile = a;
    }
    else if (o.KeysFile.empty())
    {
      o.KeysFile = a;
    }
    else
    {
      return "more than one keys file (" + RenderKeys::Printable(o.KeysFile) + ", " +
        RenderKeys::Printable(a) + ")";
    }
  }
  if (o.Last < 0)
  {
    o.Last = o.Frames;
  }
  if (!o.StateFile.empty() && !o.CameraFiles.empty())
  {
    return "camera keys from both a state file (" + RenderKeys::Printable(o.StateFile) +
      ") and .pvcc files: give one or the other";
  }
  return "";
}

int CameraType(const std::string& name)
{
  if (name == "linear")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR;
  }
  if (name == "bspline")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE;
  }
  if (name == "subdivision")
  {
    return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION;
  }
  return vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE;
}

/// The keys-file name of an interpolation type (CameraType's inverse).
const char* CameraTypeName(int type)
{
  switch (type)
  {
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR:
      return "linear";
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE:
      return "bspline";
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION:
      return "subdivision";
    default:
      return "spline";
  }
}

// ---------------------------------------------------------------------------------------------
// Timing: tension, continuity, bias, eases and constant speed of the paths

/// A path's timing from the keys file, with the timing flags given replacing its fields.
RenderKeys::PathTiming EffectiveTiming(RenderKeys::PathTiming t, const Options& o)
{
  t.Tension = o.HasTension ? o.Tension : t.Tension;
  t.Continuity = o.HasContinuity ? o.Continuity : t.Continuity;
  t.Bias = o.HasBias ? o.Bias : t.Bias;
  t.Tangents = o.Tangents.empty() ? t.Tangents : o.Tangents;
  t.EaseIn = o.HasEaseIn ? o.EaseIn : t.EaseIn;
  t.EaseOut = o.HasEaseOut ? o.EaseOut : t.EaseOut;
  t.ConstantSpeed = t.ConstantSpeed || o.ConstantSpeed;
  return t;
}

/// The timing flags given, for the manifest: "as in the keys" or e.g. "tension 0.5, constant
/// speed" (they change the frames as much as --interpolation does).
std::string TimingFlags(const Options& o)
{
  std::string out;
  auto add = [&](bool given, const char* name, double v) {
    if (given)
    {
      out += (out.empty() ? "" : ", ") + std::string(name) + " " + Num(v);
    }
  };
  add(o.HasTension, "tension", o.Tension);
  add(o.HasContinuity, "continuity", o.Continuity);
  add(o.HasBias, "bias", o.Bias);
  if (!o.Tangents.empty())
  {
    out += (out.empty() ? "" : ", ") + std::string("tangents ") + o.Tangents;
  }
  add(o.HasEaseIn, "ease in", o.EaseIn);
  add(o.HasEaseOut, "ease out", o.EaseOut);
  if (o.ConstantSpeed)
  {
    out += (out.empty() ? "" : ", ") + std::string("constant speed");
  }
  return out.empty() ? "as in the keys" : out;
}

/// Gives `path` (vtkCameraInterpolatorLCT or vtkTransformInterpolatorLCT, its keys already
/// added) the path's timing `t` and each key's own. The values were checked when read, so the
/// interpolator refuses none; if it does, the message says which (`where`: "camera",
/// "props.NAME"), else it is empty.
template <typename Interpolator, typename Key>
std::string ApplyTiming(Interpolator* path, const RenderKeys::PathTiming& t,
  const std::vector<Key>& keys, const std::string& where, ErrorCatcher& errors)
{
  const char* name = std::is_same<Interpolator, vtkCameraInterpolatorLCT>::value
    ? "vtkCameraInterpolatorLCT"
    : "vtkTransformInterpolatorLCT";
  auto refused = [&](const std::string& what) {
    return where + ": " + what + " refused by " + name + ": " + errors.Take();
  };
  if (!path->SetTension(t.Tension) || !path->SetContinuity(t.Continuity) || !path->SetBias(t.Bias))
  {
    return refused(
      "tension " + Num(t.Tension) + ", continuity " + Num(t.Continuity) + ", bias " + Num(t.Bias));
  }
  path->SetMonotoneTangents(t.Tangents != "catmull_rom");
  if constexpr (std::is_same<Interpolator, vtkTransformInterpolatorLCT>::value)
  {
    path->SetStraightenImpacts(t.Tangents == "monotone");
  }
  if (!path->SetEaseIn(t.EaseIn) || !path->SetEaseOut(t.EaseOut))
  {
    return refused("ease in " + Num(t.EaseIn) + ", ease out " + Num(t.EaseOut));
  }
  path->SetConstantSpeed(t.ConstantSpeed);
  if constexpr (std::is_same<Interpolator, vtkCameraInterpolatorLCT>::value)
  {
    const auto& measures = RenderKeys::ConstantSpeedMeasures();
    path->SetConstantSpeedMeasure(static_cast<int>(
      std::find(measures.begin(), measures.end(), t.ConstantSpeedMeasure) - measures.begin()));
  }
  else
  {
    if (!path->SetConstantSpeedPoint(t.ConstantSpeedPoint))
    {
      return refused("constant speed point (" + Num(t.ConstantSpeedPoint[0]) + ", " +
        Num(t.ConstantSpeedPoint[1]) + ", " + Num(t.ConstantSpeedPoint[2]) + ")");
    }
  }
  for (const auto& key : keys)
  {
    const RenderKeys::KeyTiming& k = key.Timing;
    if (k.HasTensionContinuityBias &&
      !path->SetKeyTensionContinuityBias(key.Time, k.Tension, k.Continuity, k.Bias))
    {
      return key.Path + ": tension, continuity and bias refused by " + name + ": " + errors.Take();
    }
    if (k.HasEase && !path->SetKeyEase(key.Time, k.EaseIn, k.EaseOut))
    {
      return key.Path + ": ease_in and ease_out refused by " + name + ": " + errors.Take();
    }
  }
  return "";
}

/// A key's own timing for --describe, "" when it has none: ", own tension 0.5, continuity 0,
/// bias 0, ease in 0, ease out 0.3".
std::string KeyTimingText(const RenderKeys::KeyTiming& k)
{
  std::string out;
  if (k.HasTensionContinuityBias)
  {
    out += ", own tension " + Num(k.Tension) + ", continuity " + Num(k.Continuity) + ", bias " +
      Num(k.Bias);
  }
  if (k.HasEase)
  {
    out += ", ease in " + Num(k.EaseIn) + ", ease out " + Num(k.EaseOut);
  }
  return out;
}

/// The "tangents" value `path` holds (one of RenderKeys::TangentNames()).
template <typename Interpolator>
const std::string& TangentsName(Interpolator* path)
{
  const auto& names = RenderKeys::TangentNames();
  if (!path->GetMonotoneTangents())
  {
    return names[2];
  }
  if constexpr (std::is_same<Interpolator, vtkTransformInterpolatorLCT>::value)
  {
    return names[path->GetStraightenImpacts() ? 0 : 1];
  }
  return names[0];
}

/// The timing `path` holds, for --describe: tension, continuity, bias, eases, constant speed
/// and, with constant speed, the times at which the path passes its keys (GetKeyArrivalTimes).
template <typename Interpolator>
std::string PathTimingText(Interpolator* path, bool keyEases, ErrorCatcher& errors)
{
  std::string out = "tension " + Num(path->GetTension()) + ", continuity " +
    Num(path->GetContinuity()) + ", bias " + Num(path->GetBias()) + ", tangents " +
    TangentsName(path);
  const bool tcb =
    path->GetTension() != 0.0 || path->GetContinuity() != 0.0 || path->GetBias() != 0.0;
  if (path->GetInterpolationType() != Interpolator::INTERPOLATION_TYPE_SPLINE)
  {
    out += tcb || !path->GetMonotoneTangents() ? " (unused: they shape the spline type only)" : "";
  }
  else if (tcb)
  {
    out += " (unused: every key takes Kochanek-Bartels' tangents)";
  }
  out += ", ease in " + Num(path->GetEaseIn()) + ", ease out " + Num(path->GetEaseOut());
  if (!path->GetConstantSpeed())
  {
    return out + ", constant speed off";
  }
  out += ", constant speed on";
  if constexpr (std::is_same<Interpolator, vtkCameraInterpolatorLCT>::value)
  {
    out +=
      " (measure: " + RenderKeys::ConstantSpeedMeasures()[path->GetConstantSpeedMeasure()] + ")";
  }
  else
  {
    double p[3];
    path->GetConstantSpeedPoint(p);
    out +=
      " (point (" + Num(p[0]) + ", " + Num(p[1]) + ", " + Num(p[2]) + ") from the object's centre)";
  }
  if (keyEases)
  {
    out += " (the keys' own eases do not apply under constant speed)";
  }
  vtkNew<vtkDoubleArray> arrivals;
  if (!path->GetKeyArrivalTimes(arrivals))
  {
    return out + "; key arrival times: not measured (" + errors.Take() + ")";
  }
  out += "; key arrival times t =";
  for (vtkIdType i = 0; i < arrivals->GetNumberOfTuples(); ++i)
  {
    out += std::string(i == 0 ? " " : ", ") + Num(arrivals->GetValue(i));
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Meshes

/// Keeps what lct-render renders of a mesh: points, cells, well-formed point normals and
/// colours, and the numeric point and cell arrays (for a scene object's color_by).
vtkSmartPointer<vtkPolyData> Geometry(vtkPolyData* mesh)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->SetPoints(mesh->GetPoints());
  out->SetVerts(mesh->GetVerts());
  out->SetLines(mesh->GetLines());
  out->SetPolys(mesh->GetPolys());
  out->SetStrips(mesh->GetStrips());
  const vtkIdType n = mesh->GetNumberOfPoints();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  if (normals && normals->GetNumberOfComponents() == 3 && normals->GetNumberOfTuples() == n)
  {
    bool finite = true;
    for (vtkIdType i = 0; i < n * 3 && finite; ++i)
    {
      finite = std::isfinite(normals->GetComponent(i / 3, static_cast<int>(i % 3)));
    }
    if (finite)
    {
      out->GetPointData()->SetNormals(normals);
    }
  }
  auto* colors = vtkUnsignedCharArray::SafeDownCast(mesh->GetPointData()->GetScalars());
  if (colors && (colors->GetNumberOfComponents() == 3 || colors->GetNumberOfComponents() == 4) &&
    colors->GetNumberOfTuples() == n)
  {
    out->GetPointData()->SetScalars(colors);
  }
  const vtkIdType cells = mesh->GetNumberOfCells();
  using Fields = std::tuple<vtkFieldData*, vtkFieldData*, vtkIdType>;
  for (auto [from, to, count] : { Fields{ mesh->GetPointData(), out->GetPointData(), n },
         Fields{ mesh->GetCellData(), out->GetCellData(), cells } })
  {
    for (int i = 0; i < from->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* a = from->GetArray(i);
      if (a && a->GetName() && *a->GetName() && a->GetNumberOfTuples() == count &&
        a->GetNumberOfComponents() <= 16 && !to->GetArray(a->GetName()))
      {
        to->AddArray(a);
      }
    }
  }
  return out;
}

/// The mesh formats VTK's readers read, by lower-case extension, and VTK's reader for each.
const std::map<std::string, const char*>& MeshReaders()
{
  static const std::map<std::string, const char*> readers = { { ".vtp", "vtkXMLPolyDataReader" },
    { ".vtu", "vtkXMLUnstructuredGridReader" }, { ".vtk", "vtkPolyDataReader" },
    { ".stl", "vtkSTLReader" }, { ".ply", "vtkPLYReader" }, { ".obj", "vtkOBJReader" },
    { ".glb", "vtkGLTFReader" }, { ".gltf", "vtkGLTFReader" } };
  return readers;
}

/// The reader of a mesh file by its lower-case extension: VTK's where VTK has one, else assimp's
/// formats (FBX, Collada, X, 3DS, Blender, ...) through vtkSkinnedMeshReaderLCT, whose output is
/// the file's meshes in their bind pose; null for neither.
const char* MeshReaderFor(const std::string& ext)
{
  const auto vtk = MeshReaders().find(ext);
  if (vtk != MeshReaders().end())
  {
    return vtk->second;
  }
  return vtkSkinnedMeshReaderLCT::IsExtensionSupported(ext.c_str())
    ? "vtkSkinnedMeshReaderLCT (assimp)"
    : nullptr;
}

/// Reads `file` with VTK's reader for its extension (in the child process); volumes and
/// multi-block scenes become their outer surface.
vtkSmartPointer<vtkPolyData> ReadWithVTK(const std::string& file, const std::string& ext)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  vtkSmartPointer<vtkAlgorithm> surface;
  if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  }
  else if (ext == ".vtu")
  {
    auto r = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
    surface = vtkSmartPointer<vtkGeometryFilter>::New();
  }
  else if (ext == ".glb" || ext == ".gltf")
  {
    auto r = vtkSmartPointer<vtkGLTFReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
    surface = vtkSmartPointer<vtkCompositeDataGeometryFilter>::New();
  }
  else if (ext == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  }
  else if (!MeshReaders().count(ext))
  {
    auto r = vtkSmartPointer<vtkSkinnedMeshReaderLCT>::New();
    r->SetFileName(file.c_str());
    reader = r;
  }
  else
  {
    vtkSmartPointer<vtkAbstractPolyDataReader> r;
    if (ext == ".stl")
    {
      r = vtkSmartPointer<vtkSTLReader>::New();
    }
    else if (ext == ".ply")
    {
      r = vtkSmartPointer<vtkPLYReader>::New();
    }
    else
    {
      r = vtkSmartPointer<vtkOBJReader>::New();
    }
    r->SetFileName(file.c_str());
    reader = r;
  }
  vtkAlgorithm* last = reader;
  if (surface)
  {
    surface->SetInputConnection(reader->GetOutputPort());
    last = surface;
  }
  last->Update();
  auto* mesh = vtkPolyData::SafeDownCast(last->GetOutputDataObject(0));
  if (!mesh)
  {
    throw InputError(file + ": no polygonal data could be read");
  }
  return Geometry(mesh);
}

/// Reads the pipe to its end; false on a read error.
bool ReadAll(int fd, std::string& out)
{
  char buffer[1 << 16];
  for (;;)
  {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n < 0)
    {
      return false;
    }
    if (n == 0)
    {
      return true;
    }
    out.append(buffer, static_cast<size_t>(n));
  }
}

bool WriteAll(int fd, const std::string& data)
{
  size_t done = 0;
  while (done < data.size())
  {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      return false;
    }
    done += static_cast<size_t>(n);
  }
  return true;
}

/// The mesh in `file`, checked (RenderKeys::CheckMeshFile) before VTK's reader sees it. The
/// reader runs in a child process with bounded memory and CPU time, so that what the checks
/// cannot see (VTK's readers crash on some malformed files, and allocate what a header
/// declares) ends in a message instead of a crash; the result comes back through a pipe in
/// VTK's binary legacy format and is checked again (RenderKeys::CheckMeshData).
vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& file)
{
  std::string ext = fs::path(file).extension().string();
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  const char* readerName = MeshReaderFor(ext);
  if (!readerName)
  {
    std::string known;
    for (const auto& r : MeshReaders())
    {
      known += (known.empty() ? "" : " ") + r.first;
    }
    throw InputError(file + ": unsupported mesh format \"" + RenderKeys::Printable(ext) +
      "\" (expected " + known +
      " or one of assimp's: " + vtkSkinnedMeshReaderLCT::GetFileExtensions() + ")");
  }
  RenderKeys::CheckMeshFile(file, ext);

  int fds[2];
  if (::pipe(fds) != 0)
  {
    throw InputError(file + ": cannot read the mesh: pipe: " + std::strerror(errno));
  }
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0)
  {
    ::close(fds[0]);
    ::close(fds[1]);
    throw InputError(file + ": cannot read the mesh: fork: " + std::strerror(errno));
  }
  if (pid == 0)
  {
    ::close(fds[0]);
    const rlim_t memory = rlim_t(6) << 30, cpu = 120;
    const rlimit as{ memory, memory }, seconds{ cpu, cpu };
    ::setrlimit(RLIMIT_AS, &as);
    ::setrlimit(RLIMIT_CPU, &seconds);
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
    vtkNew<CapturingOutputWindow> window;
    vtkOutputWindow::SetInstance(window);
    const std::string whose = MeshReaders().count(ext) ? "VTK's reader" : "assimp's reader";
    std::string reply;
    try
    {
      vtkSmartPointer<vtkPolyData> mesh = ReadWithVTK(file, ext);
      try
      {
        RenderKeys::CheckMeshData(mesh, file);
      }
      catch (const InputError& e)
      {
        std::string why = e.what();
        if (!window->Last.empty())
        {
          why += " (" + whose + " said: " + window->Last + ")";
        }
        throw InputError(why);
      }
      vtkNew<vtkPolyDataWriter> writer;
      writer->SetInputData(mesh);
      writer->SetFileTypeToBinary();
      writer->WriteToOutputStringOn();
      if (!writer->Write())
      {
        throw InputError(file + ": cannot pass the mesh on");
      }
      reply = "OK" + writer->GetOutputStdString();
    }
    catch (const InputError& e)
    {
      reply = std::string("ER") + e.what();
    }
    catch (const std::bad_alloc&)
    {
      reply = "ER" + file + ": " + whose + " needs more than the 6 GiB it is given: the file " +
        "declares sizes that its data do not hold";
    }
    catch (const std::exception& e)
    {
      reply = "ER" + file + ": " + whose + " failed: " + e.what();
    }
    vtkOutputWindow::SetInstance(nullptr);
    _exit(WriteAll(fds[1], reply) ? 0 : 3);
  }
  ::close(fds[1]);
  std::string reply;
  const bool read = ReadAll(fds[0], reply);
  ::close(fds[0]);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR)
  {
  }
  if (WIFSIGNALED(status))
  {
    const int sig = WTERMSIG(status);
    throw InputError(file + ": " + (MeshReaders().count(ext) ? "VTK's " : "") + readerName +
      " failed on this file (" +
      (sig == SIGXCPU ? std::string("it ran out of CPU time, 120 s")
          : sig == SIGABRT
          ? std::string(
              "it aborted, usually an allocation of a size the file declares beyond 6 GiB")
          : std::string("it crashed with ") + strsignal(sig)) +
      "): the file is malformed in a way the checks before it do not see");
  }
  if (!read || !WIFEXITED(status) || WEXITSTATUS(status) != 0 || reply.size() < 2)
  {
    throw InputError(file + ": reading the mesh failed (the reading process exited with " +
      std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")");
  }
  if (reply.compare(0, 2, "ER") == 0)
  {
    throw InputError(reply.substr(2));
  }
  vtkNew<vtkPolyDataReader> back;
  back->ReadFromInputStringOn();
  back->SetInputString(reply.data() + 2,
    static_cast<int>(
      std::min<size_t>(reply.size() - 2, static_cast<size_t>(std::numeric_limits<int>::max()))));
  back->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(back->GetOutput());
  RenderKeys::CheckMeshData(mesh, file);
  return mesh;
}

// ---------------------------------------------------------------------------------------------
// Frames

struct Prop
{
  std::string Name;
  std::string Origin; // "demo scene", "keys.json: scene.objects.NAME", "--mesh NAME=FILE"
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkMatrix4x4> Rest; // the actor's matrix before animation
  double Center[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkTransformInterpolatorLCT> Path; // null: static
  std::unique_ptr<ErrorCatcher> Errors;              // on Path, for as long as Path is used
  vtkSmartPointer<vtkMatrix4x4> Current;
};

bool Finite(const double* v, int n)
{
  return std::all_of(v, v + n, [](double x) { return std::isfinite(x); });
}

/// Empty if every parameter of `c` is finite and usable, else which is not.
std::string CheckCamera(vtkCamera* c)
{
  double p[3], f[3], u[3], w[2], s[3], r[2];
  c->GetPosition(p);
  c->GetFocalPoint(f);
  c->GetViewUp(u);
  c->GetWindowCenter(w);
  c->GetViewShear(s);
  c->GetClippingRange(r);
  const double angle = c->GetViewAngle(), scale = c->GetParallelScale();
  if (!Finite(p, 3) || !Finite(f, 3))
  {
    return "position (" + Num(p[0]) + ", " + Num(p[1]) + ", " + Num(p[2]) + ") or focal point (" +
      Num(f[0]) + ", " + Num(f[1]) + ", " + Num(f[2]) + ") is not finite";
  }
  if (!Finite(u, 3) || !Finite(w, 2) || !Finite(s, 3) || !Finite(r, 2) || !std::isfinite(angle) ||
    !std::isfinite(scale))
  {
    return "the view up, window centre, view shear, clipping range, view angle or parallel scale "
           "is not finite";
  }
  // Keys are held to +-1e15 exactly, but the interpolator reproduces a key's position only to
  // a few ulps (1e15 comes back as 1000000000000001.2): a relative slack far above that and far
  // below any motion makes every key that was accepted render.
  const double bound = Limits::MaxCoordinate * (1.0 + 1e-12);
  for (int i = 0; i < 3; ++i)
  {
    if (std::fabs(p[i]) > bound || std::fabs(f[i]) > bound)
    {
      return "position or focal point beyond +-1e15 (" + Num(p[i]) + ", " + Num(f[i]) + ")";
    }
  }
  if (!(c->GetDistance() > 0.0) || !std::isfinite(c->GetDistance()))
  {
    return "position equals focal point";
  }
  return "";
}

/// The prop's matrix at time t (about its centre, after its rest matrix); false with `why`.
bool PropMatrix(Prop& p, double t, vtkMatrix4x4* out, std::string& why)
{
  vtkNew<vtkMatrix4x4> k;
  // Each track holds its first and last key outside its own range (the frames may span more).
  if (!p.Path->InterpolateTransform(std::clamp(t, p.Path->GetMinimumT(), p.Path->GetMaximumT()), k))
  {
    why = "vtkTransformInterpolatorLCT failed: " + p.Errors->Take();
    return false;
  }
  if (!Finite(&k->Element[0][0], 16))
  {
    why = "vtkTransformInterpolatorLCT gave a matrix that is not finite";
    return false;
  }
  // out = T(c) K T(-c) Rest
  vtkNew<vtkTransform> x;
  x->PostMultiply();
  x->Concatenate(p.Rest);
  x->Translate(-p.Center[0], -p.Center[1], -p.Center[2]);
  x->Concatenate(k);
  x->Translate(p.Center);
  out->DeepCopy(x->GetMatrix());
  for (int i = 0; i < 3; ++i)
  {
    if (!(std::fabs(out->GetElement(i, 3)) <= Limits::MaxCoordinate))
    {
      why = "its translation " + Num(out->GetElement(i, 3)) + " is not finite or beyond +-1e15";
      return false;
    }
  }
  if (!Finite(&out->Element[0][0], 16))
  {
    why = "the matrix about the prop's centre is not finite";
    return false;
  }
  return true;
}

/// Walks the Ogg pages of `file` (RFC 3533): true if they are complete, in sequence, and the
/// last one ends the stream. vtkOggTheoraWriter does not check its writes, so a full disk or a
/// file-size limit would otherwise leave a cut video that looks written.
bool CompleteOgg(const fs::path& file, std::string& why)
{
  std::ifstream in(file, std::ios::binary);
  std::string data((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof())
  {
    why = "cannot read it back";
    return false;
  }
  size_t at = 0;
  bool ended = false;
  int pages = 0;
  while (at < data.size())
  {
    if (data.size() - at < 27 || data.compare(at, 4, "OggS") != 0)
    {
      why = "it is cut or damaged at byte " + std::to_string(at);
      return false;
    }
    const unsigned char type = static_cast<unsigned char>(data[at + 5]);
    const size_t segments = static_cast<unsigned char>(data[at + 26]);
    if (data.size() - at < 27 + segments)
    {
      why = "it is cut at byte " + std::to_string(at);
      return false;
    }
    size_t body = 0;
    for (size_t s = 0; s < segments; ++s)
    {
      body += static_cast<unsigned char>(data[at + 27 + s]);
    }
    if (data.size() - at < 27 + segments + body)
    {
      why = "its last page is cut (" + std::to_string(data.size()) + " bytes)";
      return false;
    }
    ended = (type & 0x04) != 0;
    at += 27 + segments + body;
    ++pages;
  }
  if (!ended || pages < 2)
  {
    why = "it has no end-of-stream page (" + std::to_string(data.size()) + " bytes)";
    return false;
  }
  return true;
}

/// PNG of `image` in memory, then to `file` through a temporary. Returns the reason on failure.
std::string WritePNG(vtkImageData* image, const fs::path& file)
{
  vtkNew<vtkPNGWriter> writer;
  ErrorCatcher errors(writer);
  writer->WriteToMemoryOn();
  writer->SetInputData(image);
  writer->Write();
  vtkUnsignedCharArray* png = writer->GetResult();
  if (writer->GetErrorCode() != 0 || !png || png->GetNumberOfValues() == 0)
  {
    return "encoding " + file.string() + " failed: " + errors.Take();
  }
  return WriteFileAtomically(
    file, png->GetPointer(0), static_cast<size_t>(png->GetNumberOfValues()));
}

/// The contact sheet: a 4x4 grid of cells (4-pixel gutters), filled frame by frame so that no
/// frame is kept; a cell is the frame shrunk by a box filter to at most 640x640.
class ContactSheet
{
public:
  ContactSheet(int width, int height)
  {
    this->Shrink = std::max({ width >= 320 ? 2 : 1, (width + 639) / 640, (height + 639) / 640 });
    this->W = width / this->Shrink;
    this->H = height / this->Shrink;
    const int gutter = 4;
    this->SheetW = 4 * this->W + 5 * gutter;
    this->SheetH = 4 * this->H + 5 * gutter;
    this->Image->SetDimensions(this->SheetW, this->SheetH, 1);
    this->Image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* out = static_cast<unsigned char*>(this->Image->GetScalarPointer());
    std::fill(out, out + 3 * static_cast<size_t>(this->SheetW) * this->SheetH,
      static_cast<unsigned char>(255));
  }

  void Add(int k, vtkImageData* frame)
  {
    int dims[3];
    frame->GetDimensions(dims);
    const int gutter = 4, shrink = this->Shrink;
    const int col = k % 4, row = k / 4; // row 0 at the top
    const int x0 = gutter + col * (this->W + gutter);
    const int y0 = this->SheetH - (row + 1) * (this->H + gutter); // image rows go bottom-up
    const auto* in = static_cast<const unsigned char*>(frame->GetScalarPointer());
    auto* out = static_cast<unsigned char*>(this->Image->GetScalarPointer());
    for (int y = 0; y < this->H; ++y)
    {
      for (int x = 0; x < this->W; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          int sum = 0;
          for (int dy = 0; dy < shrink; ++dy)
          {
            for (int dx = 0; dx < shrink; ++dx)
            {
              sum += in[3 *
                  (static_cast<size_t>(y * shrink + dy) * dims[0] +
                    static_cast<size_t>(x * shrink + dx)) +
                c];
            }
          }
          out[3 * (static_cast<size_t>(y0 + y) * this->SheetW + x0 + x) + c] =
            static_cast<unsigned char>((sum + shrink * shrink / 2) / (shrink * shrink));
        }
      }
    }
  }

  vtkImageData* image() { return this->Image; }

private:
  int Shrink = 1, W = 0, H = 0, SheetW = 0, SheetH = 0;
  vtkNew<vtkImageData> Image;
};

std::string Bar(int done, int total)
{
  const int width = 10, filled = total > 0 ? done * width / total : width;
  return "[" + std::string(filled, '#') + std::string(width - filled, ' ') + "]";
}

/// The first problem with the output directory and the final names in it, or "".
std::string CheckOutput(const fs::path& dir, const Options& opt, bool full)
{
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir))
  {
    return "cannot create output directory " + dir.string() +
      (ec                   ? ": " + ec.message()
          : fs::exists(dir) ? ": it exists and is not a directory"
                            : std::string(""));
  }
  if (::access(dir.c_str(), W_OK | X_OK) != 0)
  {
    return "cannot write to output directory " + dir.string() + ": " + std::strerror(errno);
  }
  // A directory (or anything but a file) under a final name would only fail at the rename,
  // after the whole render: find it first.
  for (int i = opt.First; i < opt.Last; ++i)
  {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    const std::string problem = NotARegularFile(dir / name);
    if (!problem.empty())
    {
      return problem;
    }
  }
  for (const char* name : { "video.ogv", "contact_sheet.png" })
  {
    const std::string problem = full ? NotARegularFile(dir / name) : "";
    if (!problem.empty())
    {
      return problem;
    }
  }
  return "";
}

/// "frame_0042.png".
std::string FrameName(int i)
{
  char name[32];
  std::snprintf(name, sizeof name, "frame_%04d.png", i);
  return name;
}

// ---------------------------------------------------------------------------------------------
// The scene section

/// Colours of objects that have none of their own (scene objects without "color", --mesh).
const double Palette[6][3] = { { 0.6, 0.3, 0.7 }, { 0.9, 0.8, 0.2 }, { 0.2, 0.7, 0.7 },
  { 0.9, 0.5, 0.6 }, { 0.35, 0.55, 0.85 }, { 0.55, 0.75, 0.35 } };

/// A source object of the scene section as poly data.
vtkSmartPointer<vtkPolyData> MakeSource(const RenderKeys::SceneObject& o)
{
  auto out = vtkSmartPointer<vtkPolyData>::New();
  if (o.Source == "axes")
  {
    // Three lines from the centre along +x, +y, +z, coloured red, green, blue per cell.
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(o.Center);
    vtkNew<vtkCellArray> lines;
    vtkNew<vtkUnsignedCharArray> colors;
    colors->SetNumberOfComponents(3);
    colors->SetName("axis colours");
    for (int axis = 0; axis < 3; ++axis)
    {
      double end[3] = { o.Center[0], o.Center[1], o.Center[2] };
      end[axis] += o.Length;
      const vtkIdType line[2] = { 0, points->InsertNextPoint(end) };
      lines->InsertNextCell(2, line);
      const unsigned char rgb[3] = { static_cast<unsigned char>(axis == 0 ? 220 : 40),
        static_cast<unsigned char>(axis == 1 ? 180 : 40),
        static_cast<unsigned char>(axis == 2 ? 220 : 40) };
      colors->InsertNextTypedTuple(rgb);
    }
    out->SetPoints(points);
    out->SetLines(lines);
    out->GetCellData()->SetScalars(colors);
    return out;
  }
  vtkSmartPointer<vtkPolyDataAlgorithm> source;
  if (o.Source == "sphere")
  {
    auto s = vtkSmartPointer<vtkSphereSource>::New();
    s->SetCenter(o.Center);
    s->SetRadius(o.Radius);
    s->SetThetaResolution(o.Resolution);
    s->SetPhiResolution(std::max(3, o.Resolution / 2 + 1));
    source = s;
  }
  else if (o.Source == "cube")
  {
    auto s = vtkSmartPointer<vtkCubeSource>::New();
    s->SetCenter(o.Center);
    s->SetXLength(o.Size[0]);
    s->SetYLength(o.Size[1]);
    s->SetZLength(o.Size[2]);
    source = s;
  }
  else if (o.Source == "cone")
  {
    auto s = vtkSmartPointer<vtkConeSource>::New();
    s->SetCenter(o.Center);
    s->SetRadius(o.Radius);
    s->SetHeight(o.Height);
    s->SetDirection(o.Direction);
    s->SetResolution(o.Resolution);
    source = s;
  }
  else // plane
  {
    auto s = vtkSmartPointer<vtkPlaneSource>::New();
    s->SetOrigin(-0.5 * o.Size[0], -0.5 * o.Size[1], 0.0);
    s->SetPoint1(0.5 * o.Size[0], -0.5 * o.Size[1], 0.0);
    s->SetPoint2(-0.5 * o.Size[0], 0.5 * o.Size[1], 0.0);
    s->SetCenter(o.Center[0], o.Center[1], o.Center[2]);
    s->SetNormal(o.Direction[0], o.Direction[1], o.Direction[2]); // turns it about its centre
    source = s;
  }
  source->Update();
  out->DeepCopy(source->GetOutput());
  return out;
}

/// The colour transfer function of a colour map over [lo, hi].
vtkSmartPointer<vtkColorTransferFunction> MakeColorMap(
  const std::string& name, double lo, double hi)
{
  auto lut = vtkSmartPointer<vtkColorTransferFunction>::New();
  if (name == "cool to warm")
  {
    lut->SetColorSpaceToDiverging();
  }
  else
  {
    lut->SetColorSpaceToLab();
  }
  for (const auto& p : RenderKeys::ColorMaps().at(name))
  {
    lut->AddRGBPoint(lo + p[0] * (hi - lo), p[1], p[2], p[3]);
  }
  return lut;
}

/// The names of an object's point and cell arrays, for messages.
std::string ArrayNames(vtkPolyData* data)
{
  std::string names;
  for (auto [fields, kind] :
    { std::pair<vtkFieldData*, const char*>{ data->GetPointData(), "point" },
      std::pair<vtkFieldData*, const char*>{ data->GetCellData(), "cell" } })
  {
    for (int i = 0; i < fields->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* a = fields->GetArray(i);
      if (a && a->GetName())
      {
        names += (names.empty() ? "" : ", ") + RenderKeys::Printable(a->GetName()) + " (" + kind +
          ", " + std::to_string(a->GetNumberOfComponents()) + " component" +
          (a->GetNumberOfComponents() == 1 ? "" : "s") + ")";
      }
    }
  }
  return names.empty() ? "none" : names;
}

/// Gives the actor of a scene object its appearance. `where` ("keys.json: scene.objects.x")
/// prefixes the messages.
void ApplyLook(const RenderKeys::Appearance& look, vtkActor* actor, vtkPolyData* data, size_t index,
  const std::string& where)
{
  auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
  vtkProperty* property = actor->GetProperty();
  if (!look.ColorBy.empty())
  {
    vtkDataArray* array = data->GetPointData()->GetArray(look.ColorBy.c_str());
    const bool point = array != nullptr;
    if (!array)
    {
      array = data->GetCellData()->GetArray(look.ColorBy.c_str());
    }
    if (!array)
    {
      throw InputError(where + ".color_by: the object has no point or cell array \"" +
        RenderKeys::Printable(look.ColorBy) + "\" (its arrays: " + ArrayNames(data) + ")");
    }
    const int components = array->GetNumberOfComponents();
    double range[2] = { look.ScalarRange[0], look.ScalarRange[1] };
    if (!look.HasScalarRange)
    {
      array->GetRange(range, components > 1 ? -1 : 0); // -1: the magnitude
      if (!std::isfinite(range[0]) || !std::isfinite(range[1]))
      {
        throw InputError(where + ".color_by: the array \"" + RenderKeys::Printable(look.ColorBy) +
          "\" has values that are not finite; give scalar_range");
      }
      if (range[0] == range[1]) // a constant array: one colour, the map's middle
      {
        range[0] -= 0.5;
        range[1] += 0.5;
      }
    }
    auto lut = MakeColorMap(look.ColorMap, range[0], range[1]);
    if (components > 1)
    {
      lut->SetVectorModeToMagnitude();
    }
    mapper->SetLookupTable(lut);
    mapper->UseLookupTableScalarRangeOn();
    mapper->SetColorModeToMapScalars();
    if (point)
    {
      mapper->SetScalarModeToUsePointFieldData();
    }
    else
    {
      mapper->SetScalarModeToUseCellFieldData();
    }
    mapper->SelectColorArray(look.ColorBy.c_str());
    mapper->ScalarVisibilityOn();
  }
  else if (look.HasColor)
  {
    mapper->ScalarVisibilityOff();
    property->SetColor(look.Color[0], look.Color[1], look.Color[2]);
  }
  else if (!data->GetPointData()->GetScalars() && !data->GetCellData()->GetScalars())
  {
    property->SetColor(Palette[index % 6][0], Palette[index % 6][1], Palette[index % 6][2]);
  }
  property->SetOpacity(look.Opacity);
  if (look.Representation == "wireframe")
  {
    property->SetRepresentationToWireframe();
  }
  else if (look.Representation == "points")
  {
    property->SetRepresentationToPoints();
  }
  property->SetLineWidth(static_cast<float>(look.LineWidth));
  property->SetPointSize(static_cast<float>(look.PointSize));
  actor->SetVisibility(look.Visible ? 1 : 0);
}

/// An actor drawing `data`.
vtkSmartPointer<vtkActor> MakeMeshActor(vtkPolyData* data)
{
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(data);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  return actor;
}

/// "x [a, b]  y [c, d]  z [e, f]", to 7 digits: the points are float32, and 0.01 is easier to
/// place a camera by than 0.009999999776482582.
std::string BoundsText(const double b[6])
{
  auto n = [](double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", v);
    return std::string(text);
  };
  return "x [" + n(b[0]) + ", " + n(b[1]) + "]  y [" + n(b[2]) + ", " + n(b[3]) + "]  z [" +
    n(b[4]) + ", " + n(b[5]) + "]";
}

/// `--describe`: what a user needs to place cameras and check an import, on stdout.
void Describe(const RenderKeys::Keys& keys, const std::vector<Prop>& props, bool demo,
  const std::string& cameraNote, double tmin, double tmax, double cameraMin, double cameraMax,
  bool fixedClipping, vtkCameraInterpolatorLCT* cameraPath, ErrorCatcher& cameraErrors)
{
  auto anyKeyEase = [](const auto& keyList) {
    return std::any_of(
      keyList.begin(), keyList.end(), [](const auto& k) { return k.Timing.HasEase; });
  };
  double all[6] = { VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX, VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX,
    VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  int visible = 0;
  for (const auto& p : props)
  {
    if (p.Actor->GetVisibility())
    {
      const double* b = p.Actor->GetBounds();
      for (int c = 0; c < 3; ++c)
      {
        all[2 * c] = std::min(all[2 * c], b[2 * c]);
        all[2 * c + 1] = std::max(all[2 * c + 1], b[2 * c + 1]);
      }
      ++visible;
    }
  }
  std::printf("lct-render: %s\n", keys.Source.c_str());
  std::printf("scene: %zu objects (%d visible)%s\n", props.size(), visible,
    demo ? ", with the demo scene" : "");
  if (visible > 0)
  {
    const double diagonal = std::sqrt(
      vtkMath::Distance2BetweenPoints(std::array<double, 3>{ all[0], all[2], all[4] }.data(),
        std::array<double, 3>{ all[1], all[3], all[5] }.data()));
    std::printf("  bounds of the visible objects at rest: %s, centre (%s, %s, %s), diagonal %s\n",
      BoundsText(all).c_str(), Num(0.5 * (all[0] + all[1])).c_str(),
      Num(0.5 * (all[2] + all[3])).c_str(), Num(0.5 * (all[4] + all[5])).c_str(),
      Num(diagonal).c_str());
  }
  for (const auto& p : props)
  {
    auto* data = vtkPolyData::SafeDownCast(p.Actor->GetMapper()->GetInput());
    std::printf("  %s: %s, %s, %lld points, %lld cells%s%s, from %s\n",
      RenderKeys::Printable(p.Name).c_str(), BoundsText(p.Actor->GetBounds()).c_str(),
      p.Actor->GetVisibility() ? "visible" : "hidden",
      static_cast<long long>(data ? data->GetNumberOfPoints() : 0),
      static_cast<long long>(data ? data->GetNumberOfCells() : 0), data ? ", arrays: " : "",
      data ? ArrayNames(data).c_str() : "", p.Origin.c_str());
  }
  std::printf("time: frames span t = %s..%s, camera keys t = %s..%s (%zu keys)", Num(tmin).c_str(),
    Num(tmax).c_str(), Num(cameraMin).c_str(), Num(cameraMax).c_str(), keys.Camera.size());
  for (const auto& p : props)
  {
    if (p.Path)
    {
      std::printf(", props.%s t = %s..%s (%d keys)", RenderKeys::Printable(p.Name).c_str(),
        Num(p.Path->GetMinimumT()).c_str(), Num(p.Path->GetMaximumT()).c_str(),
        p.Path->GetNumberOfTransforms());
    }
  }
  std::printf(" (each track holds its first and last key outside its own range)\n");
  std::printf("camera keys (%s%s, clipping range %s):\n",
    cameraNote.empty() ? keys.Source.c_str() : cameraNote.c_str(),
    // The type the path uses: --interpolation and a .pvsm cue override the keys file's.
    (std::string(", ") + CameraTypeName(cameraPath->GetInterpolationType())).c_str(),
    fixedClipping ? "interpolated from the keys" : "reset from the scene's bounds per frame");
  auto v3 = [](const double* v) {
    return "(" + Num(v[0]) + ", " + Num(v[1]) + ", " + Num(v[2]) + ")";
  };
  for (const auto& k : keys.Camera)
  {
    vtkCamera* c = k.Camera;
    std::printf("  t = %s: position %s, focal point %s, view up %s, %s%s\n", Num(k.Time).c_str(),
      v3(c->GetPosition()).c_str(), v3(c->GetFocalPoint()).c_str(), v3(c->GetViewUp()).c_str(),
      c->GetParallelProjection() ? ("parallel scale " + Num(c->GetParallelScale())).c_str()
                                 : ("view angle " + Num(c->GetViewAngle())).c_str(),
      KeyTimingText(k.Timing).c_str());
  }
  std::printf("camera timing: %s\n",
    PathTimingText(cameraPath, anyKeyEase(keys.Camera), cameraErrors).c_str());
  for (const auto& p : props)
  {
    if (!p.Path)
    {
      continue;
    }
    const auto track = keys.Props.find(p.Name);
    const std::vector<RenderKeys::PropKey> none;
    const auto& propKeys = track != keys.Props.end() ? track->second.Keys : none;
    std::printf("props.%s timing: %s\n", RenderKeys::Printable(p.Name).c_str(),
      PathTimingText(p.Path.GetPointer(), anyKeyEase(propKeys), *p.Errors).c_str());
    for (const auto& k : propKeys)
    {
      const std::string own = KeyTimingText(k.Timing);
      if (!own.empty())
      {
        std::printf("  key t = %s: %s\n", Num(k.Time).c_str(), own.substr(2).c_str());
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// The manifest: the run a folder's frames belong to

/// FNV-1a (64 bits) of a file's bytes, read in blocks; "" (with `why`) if it cannot be read.
std::string Fnv1a(const std::string& file, std::uintmax_t& bytes, std::string& why)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    why = std::strerror(errno);
    return "";
  }
  std::uint64_t h = 14695981039346656037ull;
  std::vector<char> block(1 << 16);
  bytes = 0;
  while (in)
  {
    in.read(block.data(), static_cast<std::streamsize>(block.size()));
    const std::streamsize n = in.gcount();
    for (std::streamsize i = 0; i < n; ++i)
    {
      h = (h ^ static_cast<unsigned char>(block[i])) * 1099511628211ull;
    }
    bytes += static_cast<std::uintmax_t>(n);
  }
  if (in.bad())
  {
    why = "read error";
    return "";
  }
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

constexpr const char* ManifestName = "manifest.json";

/// What makes the frames of a run: two runs with equal manifests render equal frames, so their
/// slices add up.
nlohmann::json RunManifest(
  const Options& opt, int width, int height, bool demo, const std::vector<std::string>& inputs)
{
  nlohmann::json files = nlohmann::json::array();
  for (const auto& file : inputs)
  {
    std::uintmax_t bytes = 0;
    std::string why;
    const std::string hash = Fnv1a(file, bytes, why);
    if (hash.empty())
    {
      throw InputError(file + ": cannot read it to record it in the manifest: " + why);
    }
    files.push_back({ { "file", fs::absolute(file).lexically_normal().string() },
      { "bytes", bytes }, { "fnv1a64", hash } });
  }
  return { { "lct-render manifest", 1 }, { "frames", opt.Frames }, { "size", { width, height } },
    { "fps", opt.Fps },
    { "interpolation", opt.Interpolation.empty() ? "as in the keys" : opt.Interpolation },
    { "timing", TimingFlags(opt) }, { "compare", opt.Compare }, { "demo_scene", demo },
    { "inputs", files } };
}

/// The differences between two manifests, for the message that refuses a run.
std::string ManifestDifferences(const nlohmann::json& here, const nlohmann::json& there)
{
  std::string out;
  for (auto it = here.begin(); it != here.end(); ++it)
  {
    if (!there.is_object() || !there.contains(it.key()) || there.at(it.key()) != it.value())
    {
      const std::string old = there.is_object() && there.contains(it.key())
        ? there.at(it.key()).dump()
        : std::string("(none)");
      out += std::string(out.empty() ? "" : "; ") + it.key() + " " +
        (it.key() == "inputs" ? "differ"
                              : RenderKeys::Printable(old) + " there, " +
              RenderKeys::Printable(it.value().dump()) + " here");
    }
  }
  return out;
}

/// Holds an flock on a directory while it exists, so that slices started at the same time check
/// and write the manifest one after the other.
class DirectoryLock
{
public:
  explicit DirectoryLock(const fs::path& dir)
    : Fd(::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC))
  {
    while (this->Fd >= 0 && ::flock(this->Fd, LOCK_EX) != 0 && errno == EINTR)
    {
    }
  }
  ~DirectoryLock()
  {
    if (this->Fd >= 0)
    {
      ::close(this->Fd); // releases the lock
    }
  }
  DirectoryLock(const DirectoryLock&) = delete;
  DirectoryLock& operator=(const DirectoryLock&) = delete;

private:
  int Fd;
};

/// Frames (regular files named frame_*.png) in `dir`.
std::vector<fs::path> FramesIn(const fs::path& dir)
{
  std::vector<fs::path> frames;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
  {
    const std::string name = it->path().filename().string();
    if (name.rfind("frame_", 0) == 0 && EndsWith(name, ".png") && it->is_regular_file(ec))
    {
      frames.push_back(it->path());
    }
  }
  return frames;
}

/// Makes `dir` the folder of this run: a folder of the same run (its manifest equal to
/// `manifest`) is kept, so that slices add up; one of a different run, or with frames but no
/// manifest, is refused unless `overwrite`, which first removes its frames, video and sheet.
/// Returns the problem, or "".
std::string ClaimOutput(const fs::path& dir, const nlohmann::json& manifest, bool overwrite)
{
  DirectoryLock lock(dir);
  const fs::path file = dir / ManifestName;
  std::error_code ec;
  std::string mismatch;
  if (fs::exists(fs::symlink_status(file, ec)))
  {
    nlohmann::json there;
    try
    {
      there = nlohmann::json::parse(RenderKeys::ReadSmallFile(file.string(), 1u << 20, "manifest"));
    }
    catch (const std::exception& e)
    {
      mismatch = std::string("its manifest cannot be read (") + e.what() + ")";
    }
    if (mismatch.empty())
    {
      if (there == manifest)
      {
        return "";
      }
      mismatch = "it holds another run (" + ManifestDifferences(manifest, there) + ")";
    }
  }
  else
  {
    const auto frames = FramesIn(dir);
    if (!frames.empty())
    {
      mismatch =
        "it holds " + std::to_string(frames.size()) + " frame_*.png of a run without a manifest";
    }
  }
  if (!mismatch.empty())
  {
    if (!overwrite)
    {
      return "output directory " + dir.string() + ": " + mismatch +
        "; its frames would mix with this run's. Use another --out, or --overwrite to remove "
        "them first";
    }
    auto stale = FramesIn(dir);
    for (const char* name : { "video.ogv", "contact_sheet.png", ManifestName })
    {
      if (fs::is_regular_file(fs::symlink_status(dir / name, ec)))
      {
        stale.push_back(dir / name);
      }
    }
    for (const auto& f : stale)
    {
      if (!fs::remove(f, ec) && ec)
      {
        return "--overwrite: cannot remove " + f.string() + ": " + ec.message();
      }
    }
    std::printf("lct-render: --overwrite: removed %zu files of an earlier run from %s (%s)\n",
      stale.size(), dir.string().c_str(), mismatch.c_str());
  }
  const std::string text = manifest.dump(2) + "\n";
  return WriteFileAtomically(
    file, reinterpret_cast<const unsigned char*>(text.data()), text.size());
}

// ---------------------------------------------------------------------------------------------
// Video and contact sheet, from frames in order (a full render, or `lct-render assemble`)

class Assembler
{
public:
  Assembler(const fs::path& dir, int width, int height, int frames, int fps)
    : VideoFile(dir / "video.ogv")
    , SheetFile(dir / "contact_sheet.png")
    , VideoTmp(VideoFile)
    , Sheet(width, height)
    , Errors(Video)
  {
    this->Video->SetInputData(this->Frame);
    this->Video->SetFileName(this->VideoTmp.path().c_str());
    this->Video->SetRate(fps);
    this->Video->SetQuality(2);
    // 16 evenly spaced frames (fewer when there are fewer than 16).
    for (int k = 0; k < 16; ++k)
    {
      const int i = frames >= 16 ? static_cast<int>(std::lround(k * (frames - 1) / 15.0)) : k;
      if (i < frames)
      {
        this->SheetSlot.emplace(i, k);
      }
    }
  }

  /// Adds frame i (frames come in order); returns the problem, or "".
  std::string Add(int i, vtkImageData* image)
  {
    this->Frame->ShallowCopy(image);
    this->Frame->Modified();
    if (!this->Started)
    {
      if (!this->VideoTmp.error().empty())
      {
        return this->VideoTmp.error();
      }
      this->VideoTmp.CloseFile(); // the writer opens the new, empty file by its name
      this->Video->Start();
      this->Started = true;
    }
    this->Video->Write();
    if (this->Video->GetErrorCode() != 0)
    {
      return "writing " + this->VideoFile.string() + " failed: " + this->Errors.Take();
    }
    const auto slot = this->SheetSlot.find(i);
    if (slot != this->SheetSlot.end())
    {
      this->Sheet.Add(slot->second, image);
    }
    return "";
  }

  /// Ends the video, checks and renames it, writes the contact sheet; returns the problem.
  std::string Finish()
  {
    this->Video->End();
    std::string why;
    if (this->Video->GetErrorCode() != 0)
    {
      return "writing " + this->VideoFile.string() + " failed: " + this->Errors.Take();
    }
    if (!CompleteOgg(this->VideoTmp.path(), why))
    {
      return "writing " + this->VideoFile.string() + " failed: " + why +
        " (disk full or a file-size limit?)";
    }
    why = this->VideoTmp.Commit();
    if (!why.empty())
    {
      return why;
    }
    std::printf("lct-render: video %s\n", this->VideoFile.string().c_str());
    why = WritePNG(this->Sheet.image(), this->SheetFile);
    if (!why.empty())
    {
      return why;
    }
    std::printf("lct-render: contact sheet %s\n", this->SheetFile.string().c_str());
    return "";
  }

private:
  fs::path VideoFile, SheetFile;
  Temporary VideoTmp;
  ContactSheet Sheet;
  vtkNew<vtkOggTheoraWriter> Video;
  ErrorCatcher Errors;
  vtkNew<vtkImageData> Frame;
  std::map<int, int> SheetSlot;
  bool Started = false;
};

/// `lct-render assemble DIR [--fps N]`: the video and contact sheet of a run rendered in
/// slices, from DIR's frames and manifest.
int Assemble(int argc, char* argv[])
{
  std::string dirName;
  int fps = -1;
  for (int i = 2; i < argc; ++i)
  {
    const std::string a = argv[i];
    if (a == "-h" || a == "--help")
    {
      std::cout << "usage: lct-render assemble DIR [--fps N]\n\nWrites DIR/video.ogv and "
                   "DIR/contact_sheet.png from the frames of DIR's run (DIR/manifest.json),\n"
                   "at the run's --fps unless --fps N is given. Needs every frame, no X.\n";
      return 0;
    }
    if (a == "--fps")
    {
      if (i + 1 >= argc || !ParseInt(argv[i + 1], fps) || fps < 1 || fps > Limits::MaxFps)
      {
        std::cerr << "lct-render: assemble: --fps expects a frame rate N, 1 <= N <= "
                  << Limits::MaxFps << "\n";
        return 2;
      }
      ++i;
    }
    else if (!a.empty() && a[0] != '-' && dirName.empty())
    {
      dirName = a;
    }
    else
    {
      std::cerr << "lct-render: assemble: unexpected argument " << RenderKeys::Printable(a)
                << "\nusage: lct-render assemble DIR [--fps N]\n";
      return 2;
    }
  }
  if (dirName.empty())
  {
    std::cerr << "lct-render: assemble needs the output directory of a run\nusage: lct-render "
                 "assemble DIR [--fps N]\n";
    return 2;
  }
  const fs::path dir = dirName;
  int frames = 0, width = 0, height = 0;
  try
  {
    const std::string file = (dir / ManifestName).string();
    nlohmann::json m;
    try
    {
      m = nlohmann::json::parse(RenderKeys::ReadSmallFile(file, 1u << 20, "manifest"));
    }
    catch (const nlohmann::json::exception& e)
    {
      throw InputError(file + ": not a manifest of lct-render: " + e.what());
    }
    auto number = [&](const nlohmann::json& v, int lo, int hi, const char* what) {
      if (!v.is_number_integer() || v.get<long long>() < lo || v.get<long long>() > hi)
      {
        throw InputError(file + ": " + what + " must be a whole number in [" + std::to_string(lo) +
          ", " + std::to_string(hi) + "]");
      }
      return v.get<int>();
    };
    if (!m.is_object() || !m.contains("frames") || !m.contains("size") || !m.contains("fps") ||
      !m.at("size").is_array() || m.at("size").size() != 2)
    {
      throw InputError(file + ": not a manifest of lct-render (frames, size and fps expected)");
    }
    frames = number(m.at("frames"), 1, Limits::MaxFrames, "frames");
    width = number(m.at("size")[0], Limits::MinSide, Limits::MaxSide, "size[0]");
    height = number(m.at("size")[1], Limits::MinSide, Limits::MaxSide, "size[1]");
    if (fps < 0)
    {
      fps = number(m.at("fps"), 1, Limits::MaxFps, "fps");
    }
  }
  catch (const InputError& e)
  {
    std::cerr << "lct-render: assemble: " << e.what()
              << (fs::exists(dir / ManifestName) ? ""
                                                 : " (assemble needs the --out folder of a run)")
              << "\n";
    return 1;
  }
  // Every frame first: a missing one is named before anything is written.
  std::vector<int> missing;
  for (int i = 0; i < frames; ++i)
  {
    std::error_code ec;
    if (!fs::is_regular_file(dir / FrameName(i), ec))
    {
      missing.push_back(i);
    }
  }
  if (!missing.empty())
  {
    std::string list;
    for (size_t k = 0; k < missing.size() && k < 8; ++k)
    {
      list += (k ? ", " : "") + FrameName(missing[k]);
    }
    std::cerr << "lct-render: assemble: " << dir.string() << " lacks " << missing.size() << " of "
              << frames << " frames (" << list << (missing.size() > 8 ? ", ..." : "")
              << "): render the missing slices first (e.g. --frames " << missing.front() << ":"
              << missing.back() + 1 << "/" << frames << ")\n";
    return 1;
  }
  for (const char* name : { "video.ogv", "contact_sheet.png" })
  {
    const std::string problem = NotARegularFile(dir / name);
    if (!problem.empty())
    {
      std::cerr << "lct-render: assemble: " << problem << "\n";
      return 1;
    }
  }
  Assembler out(dir, width, height, frames, fps);
  for (int i = 0; i < frames; ++i)
  {
    const fs::path name = dir / FrameName(i);
    vtkNew<vtkPNGReader> reader;
    ErrorCatcher errors(reader);
    std::string why;
    if (!reader->CanReadFile(name.c_str()))
    {
      why = name.string() + " is not a PNG file";
    }
    else
    {
      reader->SetFileName(name.c_str());
      reader->Update();
      vtkImageData* image = reader->GetOutput();
      int dims[3];
      image->GetDimensions(dims);
      if (reader->GetErrorCode() != 0 || !image->GetScalarPointer())
      {
        why = "reading " + name.string() + " failed: " + errors.Take();
      }
      else if (dims[0] != width || dims[1] != height || image->GetNumberOfScalarComponents() != 3 ||
        image->GetScalarType() != VTK_UNSIGNED_CHAR)
      {
        why = name.string() + " is a " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
          " image of " + std::to_string(image->GetNumberOfScalarComponents()) +
          " components; the run's frames are " + std::to_string(width) + "x" +
          std::to_string(height) + " RGB";
      }
      else
      {
        why = out.Add(i, image);
      }
    }
    if (!why.empty())
    {
      std::cerr << "lct-render: assemble: " << why << "\n";
      RemoveTemporaries();
      return 1;
    }
  }
  const std::string why = out.Finish();
  if (!why.empty())
  {
    std::cerr << "lct-render: assemble: " << why << "\n";
    RemoveTemporaries();
    return 1;
  }
  std::printf("lct-render: assembled %d frames of %dx%d at %d fps in %s\n", frames, width, height,
    fps, dir.string().c_str());
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  // Every signal whose default action ends the process: a temporary must not outlive it (`| head`
  // ends a run with SIGPIPE, a CPU-time limit with SIGXCPU, batch systems send USR1 or ALRM).
  for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGALRM, SIGVTALRM, SIGPROF, SIGUSR1,
         SIGUSR2, SIGXCPU, SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL, SIGTRAP, SIGSYS })
  {
    std::signal(sig, OnFatalSignal);
  }
  // SIGXFSZ is ignored instead: a file-size limit then fails the write (EFBIG, reported, the
  // temporary removed) instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  // Xlib ends the process with exit() when the X server goes away mid-run.
  std::atexit(RemoveTemporaries);

  if (argc > 1 && std::string(argv[1]) == "assemble")
  {
    return Assemble(argc, argv);
  }

  Options opt;
  bool help = false;
  const std::string usageError = ParseArgs(argc, argv, opt, help);
  if (help)
  {
    std::cout << Usage;
    return 0;
  }
  if (!usageError.empty())
  {
    std::cerr << "lct-render: " << usageError << "\n(lct-render --help for usage)\n";
    return 2;
  }

  // ---- keys and scene (validated before anything needs a display)
  RenderKeys::Keys keys;
  std::vector<Prop> props;
  vtkNew<vtkCameraInterpolatorLCT> cameraPath;
  vtkNew<vtkCameraInterpolator> vtkPath;
  ErrorCatcher cameraErrors(cameraPath);
  vtkNew<vtkPoints> scenePoints;
  std::string modelSource;
  // The demo scene only when asked for, or when nothing says what to draw.
  const bool demo = opt.DemoScene || (opt.KeysFile.empty() && opt.Meshes.empty());
  std::vector<std::string> inputs; // every file the frames depend on, for the manifest
  std::string cameraNote;          // where the camera keys came from, for --describe
  try
  {
    const bool paraViewCamera = !opt.CameraFiles.empty() || !opt.StateFile.empty();
    if (!opt.KeysFile.empty())
    {
      keys = RenderKeys::ReadFile(opt.KeysFile, paraViewCamera);
      inputs.push_back(opt.KeysFile);
    }
    else
    {
      keys = RenderKeys::BuiltIn();
      if (!demo)
      {
        keys.Props.clear(); // the built-in prop keys move the demo scene's cone
      }
    }
    std::string cameraInterpolation = keys.Interpolation;
    if (!opt.CameraFiles.empty())
    {
      // ParaView camera files, in the order given, are the camera keys at t = 0, 1, 2, ...
      keys.Camera.clear();
      for (size_t i = 0; i < opt.CameraFiles.size(); ++i)
      {
        keys.Camera.push_back(RenderKeys::ReadPvcc(opt.CameraFiles[i], static_cast<double>(i)));
        inputs.push_back(opt.CameraFiles[i]);
        if (keys.Camera.back().Camera->GetParallelProjection() !=
          keys.Camera.front().Camera->GetParallelProjection())
        {
          throw InputError(opt.CameraFiles[i] + ": CameraParallelProjection differs from " +
            opt.CameraFiles[0] + "'s (all keys must use the same projection)");
        }
        keys.Camera.back().Path = "camera (" + opt.CameraFiles[i] + ")";
      }
      if (keys.Camera.size() < 2)
      {
        throw InputError(opt.CameraFiles[0] +
          ": a camera path needs at least 2 keys (give 2 or more .pvcc files)");
      }
      cameraNote = std::to_string(keys.Camera.size()) + " .pvcc files";
    }
    if (!opt.StateFile.empty())
    {
      RenderKeys::StateCamera state = RenderKeys::ReadPvsm(opt.StateFile);
      inputs.push_back(opt.StateFile);
      keys.Camera = state.Keys;
      // The cue's interpolation is the camera's: the keys file's props keep the file's default.
      cameraInterpolation = state.Interpolation;
      keys.ConsistentRotation = false;
      keys.CameraTiming = RenderKeys::PathTiming(); // a state has no timing fields
      cameraNote = opt.StateFile + ", " + state.Cue + ", AnimationScene t = " + Num(state.Start) +
        ".." + Num(state.End);
    }
    if (paraViewCamera && opt.KeysFile.empty())
    {
      keys.Props.clear(); // the built-in prop keys belong to the built-in flight
      keys.Source = !opt.StateFile.empty() ? opt.StateFile : opt.CameraFiles[0];
    }
    const std::string& source = keys.Source;
    if (opt.Compare && keys.Camera.size() > Limits::MaxCompareKeys)
    {
      throw InputError(source + ": " + std::to_string(keys.Camera.size()) +
        " camera keys; --compare accepts at most " + std::to_string(Limits::MaxCompareKeys) +
        " (VTK's vtkCameraInterpolator initialises in quadratic time)");
    }
    const std::string cameraScheme =
      opt.Interpolation.empty() ? cameraInterpolation : opt.Interpolation;

    cameraPath->SetInterpolationType(CameraType(cameraScheme));
    cameraPath->SetConsistentRotation(keys.ConsistentRotation);
    vtkPath->SetInterpolationType(cameraScheme == "linear"
        ? vtkCameraInterpolator::INTERPOLATION_TYPE_LINEAR
        : vtkCameraInterpolator::INTERPOLATION_TYPE_SPLINE);
    // keys.Camera is sorted by time: each key goes to the end of the interpolators' arrays.
    for (const auto& key : keys.Camera)
    {
      if (!cameraPath->AddCamera(key.Time, key.Camera))
      {
        throw InputError(source + ": " + key.Path +
          " is degenerate (rejected by vtkCameraInterpolatorLCT: " + cameraErrors.Take() + ")");
      }
      if (opt.Compare)
      {
        vtkPath->AddCamera(key.Time, key.Camera);
      }
    }
    const std::string cameraTiming = ApplyTiming(static_cast<vtkCameraInterpolatorLCT*>(cameraPath),
      EffectiveTiming(keys.CameraTiming, opt), keys.Camera, "camera", cameraErrors);
    if (!cameraTiming.empty())
    {
      throw InputError(source + ": " + cameraTiming);
    }

    // Meshes: --mesh and the scene's files, each read in a forked child (ReadMesh).
    const auto& objects = keys.View.Objects;
    const size_t files = opt.Meshes.size() +
      std::count_if(objects.begin(), objects.end(),
        [](const RenderKeys::SceneObject& o) { return !o.File.empty(); });
    if (files > static_cast<size_t>(Limits::MaxMeshes))
    {
      throw InputError(source + ": " + std::to_string(files) +
        " mesh files (scene objects and --mesh); at most " + std::to_string(Limits::MaxMeshes) +
        " are accepted");
    }
    auto add = [&](const std::string& name, vtkSmartPointer<vtkActor> actor,
                 const std::string& origin) {
      for (const auto& p : props)
      {
        if (p.Name == name)
        {
          throw InputError(origin + ": the name " + RenderKeys::Printable(name) +
            " is already used by the " + p.Origin);
        }
      }
      Prop p;
      p.Name = name;
      p.Actor = actor;
      p.Origin = origin;
      props.push_back(std::move(p));
    };
    if (demo)
    {
      // The demo scene: CameraFlightScene's actors, by name.
      const char* const names[] = { "floor", "pedestal", "model", "sphere", "cube", "cone" };
      const auto actors = CameraFlightScene::MakeActors(&modelSource);
      for (size_t i = 0; i < actors.size(); ++i)
      {
        add(i < 6 ? names[i] : "actor" + std::to_string(i), actors[i], "demo scene");
      }
    }
    for (size_t i = 0; i < objects.size(); ++i)
    {
      const RenderKeys::SceneObject& o = objects[i];
      const std::string where = source + ": " + o.Path;
      vtkSmartPointer<vtkPolyData> data;
      if (!o.File.empty())
      {
        try
        {
          data = ReadMesh(o.File);
        }
        catch (const InputError& e)
        {
          throw InputError(where + ".file: " + e.what());
        }
        inputs.push_back(o.File);
      }
      else
      {
        data = MakeSource(o);
      }
      auto actor = MakeMeshActor(data);
      ApplyLook(o.Look, actor, data, i, where);
      add(o.Name, actor, where);
    }
    for (size_t m = 0; m < opt.Meshes.size(); ++m)
    {
      const auto& [name, file] = opt.Meshes[m];
      auto data = ReadMesh(file);
      inputs.push_back(file);
      auto actor = MakeMeshActor(data);
      RenderKeys::Appearance look;
      ApplyLook(look, actor, data, m, "--mesh " + RenderKeys::Printable(name));
      add(name, actor, "--mesh " + RenderKeys::Printable(name) + "=" + file);
    }
    if (props.empty())
    {
      throw InputError(source +
        ": nothing to draw: the keys file has no \"scene\" section (scene.objects), and "
        "neither --mesh NAME=FILE nor --demo-scene is given");
    }
    for (auto& p : props)
    {
      p.Rest = vtkSmartPointer<vtkMatrix4x4>::New();
      p.Rest->DeepCopy(p.Actor->GetMatrix());
      const double* b = p.Actor->GetBounds();
      for (int c = 0; c < 3; ++c)
      {
        p.Center[c] = 0.5 * (b[2 * c] + b[2 * c + 1]);
      }
      // The visible scene's points at rest, for the path metric (at most ~2000 per actor).
      auto* data = vtkPolyData::SafeDownCast(p.Actor->GetMapper()->GetInput());
      if (p.Actor->GetVisibility() && data && data->GetNumberOfPoints() > 0)
      {
        const vtkIdType n = data->GetNumberOfPoints();
        const vtkIdType stride = std::max<vtkIdType>(1, n / 2000);
        for (vtkIdType i = 0; i < n; i += stride)
        {
          double x[4] = { 0.0, 0.0, 0.0, 1.0 };
          data->GetPoint(i, x);
          p.Rest->MultiplyPoint(x, x);
          scenePoints->InsertNextPoint(x);
        }
      }
    }
    for (const auto& [name, track] : keys.Props)
    {
      auto it =
        std::find_if(props.begin(), props.end(), [&](const Prop& p) { return p.Name == name; });
      if (it == props.end())
      {
        std::string known;
        for (const auto& p : props)
        {
          known += (known.empty() ? "" : ", ") + RenderKeys::Printable(p.Name);
        }
        throw InputError(source + ": props." + RenderKeys::Printable(name) +
          ": no such object in the scene (known: " + known +
          "). Add objects in scene.objects, meshes with --mesh NAME=FILE, or --demo-scene for "
          "the demo objects");
      }
      it->Path = vtkSmartPointer<vtkTransformInterpolatorLCT>::New();
      it->Errors = std::make_unique<ErrorCatcher>(it->Path);
      const std::string scheme = !opt.Interpolation.empty() ? opt.Interpolation
        : !track.Interpolation.empty()                      ? track.Interpolation
                                                            : keys.Interpolation;
      it->Path->SetInterpolationType(CameraType(scheme)); // same enum values 0..3
      it->Path->SetConsistentRotation(track.ConsistentRotation);
      for (const auto& key : track.Keys) // sorted by time
      {
        vtkNew<vtkMatrix4x4> m;
        m->DeepCopy(key.Matrix.data());
        if (!it->Path->AddTransform(key.Time, m))
        {
          throw InputError(source + ": " + key.Path +
            " is not a usable transform (rejected by vtkTransformInterpolatorLCT: " +
            it->Errors->Take() + ")");
        }
      }
      const std::string timing =
        ApplyTiming(it->Path.GetPointer(), EffectiveTiming(track.Timing, opt), track.Keys,
          "props." + RenderKeys::Printable(name), *it->Errors);
      if (!timing.empty())
      {
        throw InputError(source + ": " + timing);
      }
      it->Current = vtkSmartPointer<vtkMatrix4x4>::New();
      it->Actor->SetUserMatrix(it->Current);
    }
  }
  catch (const InputError& e)
  {
    std::cerr << "lct-render: " << e.what() << "\n";
    return 1;
  }
  catch (const std::bad_alloc&)
  {
    std::cerr << "lct-render: out of memory while reading the input\n";
    return 1;
  }

  // ---- time: the frames span every track's keys; each track is clamped to its own range.
  const double cameraMin = cameraPath->GetMinimumT(), cameraMax = cameraPath->GetMaximumT();
  double tmin = cameraMin, tmax = cameraMax;
  for (const auto& p : props)
  {
    if (p.Path)
    {
      tmin = std::min(tmin, p.Path->GetMinimumT());
      tmax = std::max(tmax, p.Path->GetMaximumT());
    }
  }
  auto cameraTime = [&](double t) { return std::clamp(t, cameraMin, cameraMax); };
  const int N = opt.Frames;
  const bool full = opt.First == 0 && opt.Last == N;
  auto frameTime = [&](int i) {
    return N > 1 ? tmin + (tmax - tmin) * (static_cast<double>(i) / (N - 1)) : tmin;
  };
  const int width = opt.SizeGiven || keys.View.Width == 0 ? opt.Width : keys.View.Width;
  const int height = opt.SizeGiven || keys.View.Height == 0 ? opt.Height : keys.View.Height;
  const bool fixedClipping = keys.Camera.front().ClippingRange;

  if (opt.Describe)
  {
    Describe(keys, props, demo, cameraNote, tmin, tmax, cameraMin, cameraMax, fixedClipping,
      cameraPath, cameraErrors);
    return 0;
  }

  // ---- every frame's camera and props, before anything is written: an interpolation that
  // fails or leaves the finite range stops the run here, with no file touched.
  {
    // Test hook (Testing/Render, Render.Fault.*): the interpolators reject no key that passes
    // the checks above, so LCT_RENDER_TEST_NAN_FRAME=F (or F:props) hands them a NaN time at
    // frame F, for the camera (or the props), to make them report an error on purpose.
    int nanFrame = -1;
    bool nanProps = false;
    if (const char* hook = std::getenv("LCT_RENDER_TEST_NAN_FRAME"))
    {
      const std::string h = hook;
      nanProps = h.size() > 6 && h.compare(h.size() - 6, 6, ":props") == 0;
      if (!ParseInt(nanProps ? h.substr(0, h.size() - 6) : h, nanFrame))
      {
        nanFrame = -1;
      }
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    vtkNew<vtkCamera> camera;
    vtkNew<vtkMatrix4x4> m;
    for (int i = opt.First; i < opt.Last; ++i)
    {
      const double t = frameTime(i);
      std::string why;
      if (!cameraPath->InterpolateCamera(i == nanFrame && !nanProps ? nan : cameraTime(t), camera))
      {
        why = "vtkCameraInterpolatorLCT failed: " + cameraErrors.Take();
      }
      else
      {
        why = CheckCamera(camera);
      }
      if (why.empty() && opt.Compare)
      {
        vtkPath->InterpolateCamera(cameraTime(t), camera);
        why = CheckCamera(camera);
        if (!why.empty())
        {
          why = "VTK's vtkCameraInterpolator (--compare): " + why;
        }
      }
      if (!why.empty())
      {
        std::cerr << "lct-render: " << keys.Source << ": the camera of frame " << i
                  << " (t = " << Num(t) << ") is unusable: " << why << "\n";
        return 1;
      }
      for (auto& p : props)
      {
        if (p.Path && !PropMatrix(p, i == nanFrame && nanProps ? nan : t, m, why))
        {
          std::cerr << "lct-render: " << keys.Source << ": props." << RenderKeys::Printable(p.Name)
                    << " at frame " << i << " (t = " << Num(t) << ") is unusable: " << why << "\n";
          return 1;
        }
      }
    }
  }

  const char* display = std::getenv("DISPLAY");
  if (!display || !*display)
  {
    std::cerr << "lct-render: DISPLAY is not set; this VTK renders through X only (no EGL or "
                 "OSMesa), even offscreen. Run it as: xvfb-run -a lct-render ...\n";
    return 125;
  }

  // ---- output directory and its manifest
  const fs::path outDir = opt.Out;
  {
    std::string problem = CheckOutput(outDir, opt, full);
    if (problem.empty())
    {
      try
      {
        problem = ClaimOutput(outDir, RunManifest(opt, width, height, demo, inputs), opt.Overwrite);
      }
      catch (const InputError& e)
      {
        problem = e.what();
      }
    }
    if (!problem.empty())
    {
      std::cerr << "lct-render: " << problem << "\n";
      return 1;
    }
  }

  // ---- path metric per key segment against the true key cameras (issue #12), at the metric's
  // resolution (at most MetricSamples cameras per segment, MetricBudget in all), whatever the
  // number of frames; VTK's path as it is and with the window centre lerped (the fair baseline)
  {
    vtkNew<vtkCameraPathMetric> metric;
    ErrorCatcher metricErrors(metric);
    metric->SetPoints(scenePoints);
    metric->SetAspect((opt.Compare ? 0.5 : 1.0) * width / height);
    for (const auto& key : keys.Camera)
    {
      metric->AddKeyCamera(key.Time, key.Camera);
    }
    const int segments = static_cast<int>(keys.Camera.size()) - 1;
    metric->SetSamplesPerSegment(std::clamp(MetricBudget / segments, 2, MetricSamples));
    const long long points = scenePoints->GetNumberOfPoints();
    const auto print = [&](const char* name, int ok) {
      if (!ok)
      {
        std::printf(
          "lct-render: metric %s: not measured (%s)\n", name, metricErrors.Take().c_str());
        return;
      }
      std::printf("lct-render: metric %s: %.2f %% excess in camera space, %.2f %% on screen; "
                  "largest key miss %.2f %% / %.2f %%; %d of %lld points leave the view between "
                  "keys (%d segments of %d cameras, against the key cameras)\n",
        name, metric->GetTotalCameraSpaceExcess(), metric->GetTotalScreenSpaceExcess(),
        metric->GetLargestKeyMissCameraSpace(), metric->GetLargestKeyMissScreenSpace(),
        metric->GetNumberOfPointsLeavingViewBetweenKeys(), points, segments,
        metric->GetSamplesPerSegmentUsed());
      for (int k = 0; k < std::min(segments, 8); ++k)
      {
        // The times at which the path passes the two keys (their arrival times under constant
        // speed).
        std::printf("lct-render:   segment %d (t = %s..%s): %.2f %% / %.2f %%\n", k,
          Num(metric->GetKeyPassTime(k)).c_str(), Num(metric->GetKeyPassTime(k + 1)).c_str(),
          metric->GetSegmentCameraSpaceExcess(k), metric->GetSegmentScreenSpaceExcess(k));
      }
    };
    print("LCT path (vtkCameraInterpolatorLCT)", metric->EvaluateSegments(cameraPath));
    if (opt.Compare)
    {
      print("VTK path (vtkCameraInterpolator)", metric->EvaluateSegments(vtkPath, 0));
      print("VTK path, window centre lerped between the keys (VTK ignores it)",
        metric->EvaluateSegments(vtkPath, 1));
    }
    std::fflush(stdout);
  }

  // ---- render window
  const RenderKeys::Scene& view = keys.View;
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  // Multisample buffers cost 8 bytes per sample: at most 2^25 samples (256 MiB).
  const long long pixels = static_cast<long long>(width) * height;
  int samples = view.AntiAliasing == "msaa" ? 8 : 0;
  while (samples > 0 && samples * pixels > (1LL << 25))
  {
    samples /= 2;
  }
  window->SetMultiSamples(samples < 2 ? 0 : samples);
  window->SetSize(width, height);
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;
  for (int side = 0; side < (opt.Compare ? 2 : 1); ++side)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(
      opt.Compare ? 0.5 * side : 0.0, 0.0, opt.Compare ? 0.5 * (side + 1) : 1.0, 1.0);
    renderer->SetBackground(view.Background[0], view.Background[1], view.Background[2]);
    if (view.Gradient)
    {
      renderer->GradientBackgroundOn();
      renderer->SetBackground2(view.BackgroundTop[0], view.BackgroundTop[1], view.BackgroundTop[2]);
    }
    renderer->SetUseFXAA(view.AntiAliasing == "fxaa");
    // Without a scene section: VTK's headlight, as the demo scene has always been lit.
    if (view.Given && view.Lights == "kit")
    {
      vtkNew<vtkLightKit> kit;
      kit->AddLightsToRenderer(renderer);
    }
    for (const auto& l : view.LightList)
    {
      vtkNew<vtkLight> light;
      if (l.Camera)
      {
        light->SetLightTypeToCameraLight();
      }
      else
      {
        light->SetLightTypeToSceneLight();
      }
      light->SetPosition(l.Position);
      light->SetFocalPoint(l.FocalPoint);
      light->SetColor(l.Color[0], l.Color[1], l.Color[2]);
      light->SetIntensity(l.Intensity);
      renderer->AddLight(light);
    }
    for (const auto& p : props)
    {
      renderer->AddActor(p.Actor);
    }
    if (opt.Compare)
    {
      vtkNew<vtkTextActor> label;
      label->SetInput(side == 0 ? "LCT: vtkCameraInterpolatorLCT" : "VTK: vtkCameraInterpolator");
      label->GetTextProperty()->SetFontSize(std::max(10, height / 20));
      label->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
      label->GetPositionCoordinate()->SetCoordinateSystemToNormalizedViewport();
      label->GetPositionCoordinate()->SetValue(0.015, 0.025);
      renderer->AddActor2D(label);
    }
    window->AddRenderer(renderer);
    renderers.push_back(renderer);
  }
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();

  std::unique_ptr<Assembler> assembler;
  if (full)
  {
    assembler = std::make_unique<Assembler>(outDir, width, height, N, opt.Fps);
  }
  auto fail = [&](const std::string& why) {
    std::cerr << "lct-render: " << why << "\n";
    assembler.reset();
    RemoveTemporaries();
    return 1;
  };

  const bool tty = isatty(STDOUT_FILENO);
  const int count = opt.Last - opt.First;
  const auto start = std::chrono::steady_clock::now();
  int lastDecile = 0;
  for (int i = opt.First; i < opt.Last; ++i)
  {
    const double t = frameTime(i);
    std::string why;
    for (auto& p : props)
    {
      if (p.Path && !PropMatrix(p, t, p.Current, why))
      {
        return fail("props." + RenderKeys::Printable(p.Name) + " at t = " + Num(t) + ": " + why);
      }
    }
    if (!cameraPath->InterpolateCamera(cameraTime(t), renderers[0]->GetActiveCamera()))
    {
      return fail("interpolating the camera at t = " + Num(t) + " failed: " + cameraErrors.Take());
    }
    if (opt.Compare)
    {
      vtkPath->InterpolateCamera(cameraTime(t), renderers[1]->GetActiveCamera());
    }
    if (!fixedClipping)
    {
      for (auto& r : renderers)
      {
        r->ResetCameraClippingRange();
      }
    }
    window->Render();
    grab->Modified();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    if (dims[0] != width || dims[1] != height || !image->GetScalarPointer())
    {
      return fail("rendering frame " + std::to_string(i) + " at " + std::to_string(width) + "x" +
        std::to_string(height) + " failed: the window gave a " + std::to_string(dims[0]) + "x" +
        std::to_string(dims[1]) + " image (is the size beyond what the X server renders?)");
    }

    why = WritePNG(image, outDir / FrameName(i));
    if (why.empty() && assembler)
    {
      why = assembler->Add(i, image);
    }
    if (!why.empty())
    {
      return fail(why);
    }

    const int done = i - opt.First + 1;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double fps = elapsed > 0.0 ? done / elapsed : 0.0;
    const double eta = fps > 0.0 ? (count - done) / fps : 0.0;
    if (tty)
    {
      std::printf("\r%s %d/%d frames, %.1f fps, ETA %.0f s   ", Bar(done, count).c_str(), done,
        count, fps, eta);
      if (done == count)
      {
        std::printf("\n");
      }
      std::fflush(stdout);
    }
    else if (static_cast<long long>(done) * 10 / count > lastDecile)
    {
      lastDecile = static_cast<int>(static_cast<long long>(done) * 10 / count);
      std::printf("rendered %d/%d frames, %.1f fps, ETA %.0f s\n", done, count, fps, eta);
      std::fflush(stdout);
    }
  }
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf(
    "lct-render: %d frames (%d..%d of %d) at %dx%d in %.2f s (%.1f fps) -> %s/frame_NNNN.png\n",
    count, opt.First, opt.Last - 1, N, width, height, elapsed, elapsed > 0 ? count / elapsed : 0.0,
    outDir.string().c_str());
  if (full)
  {
    const std::string why = assembler->Finish();
    if (!why.empty())
    {
      return fail(why);
    }
  }
  else if (FramesIn(outDir).size() == static_cast<size_t>(N))
  {
    std::printf("lct-render: %s holds all %d frames of the run: `lct-render assemble %s` makes "
                "the video and the contact sheet\n",
      outDir.string().c_str(), N, outDir.string().c_str());
  }
  return 0;
}
