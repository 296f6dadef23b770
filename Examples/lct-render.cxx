// lct-render: render a keyframed camera flight (and animated props) through
// vtkCameraInterpolatorLCT / vtkTransformInterpolatorLCT to PNG frames, an Ogg Theora video and a
// contact sheet, and print Hawkins & Grimm's path-quality metric. See `lct-render --help`.
//
// Needs an X display (this VTK build has no EGL/OSMesa): run it under `xvfb-run -a`.
// Exit codes: 0 ok, 1 error, 2 usage, 125 no DISPLAY.
#include "CameraFlightScene.h"
#include "RenderKeys.h"

#include "vtkCallbackCommand.h"
#include "vtkCameraInterpolator.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCameraPathMetric.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkLogger.h"
#include "vtkMatrix4x4.h"
#include "vtkOBJReader.h"
#include "vtkObjectFactory.h"
#include "vtkOggTheoraWriter.h"
#include "vtkOutputWindow.h"
#include "vtkPLYReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSTLReader.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransformInterpolatorLCT.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <map>
#include <memory>
#include <string>
#include <system_error>
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
  R"(usage: lct-render [options] [keys.json] [view1.pvcc view2.pvcc ...]

Renders a keyframed camera flight through vtkCameraInterpolatorLCT (props through
vtkTransformInterpolatorLCT) offscreen to DIR/frame_NNNN.png, DIR/video.ogv (Ogg Theora) and
DIR/contact_sheet.png (4x4 evenly spaced frames), and prints the path-quality metric
(vtkCameraPathMetric::EvaluateSegments: mean excess path length of the scene's points, camera
space and screen, per key segment and in total, against the true key cameras, with how far the
path misses its keys; up to 65 cameras per segment, whatever --frames is; with --compare also
VTK's path, as it is and with the window centre lerped between the keys).
Without keys.json it renders the built-in keys: a 130-degree turn with a window-centre shift and a
zoom, and the cone tumbling 720 degrees while it shears.

options:
  --frames N         render N frames (default 48, 1 <= N <= 1000000); frame i is at key time
                     tmin + i/(N-1) (tmax-tmin)
  --frames A:B/N     render only frames A..B-1 of N (files keep their global numbers, so the
                     slices of several runs equal one full run); no video or contact sheet.
                     A:B alone means A:B/48
  --size WxH         image size (default 640x360; 16..16384 per side, at most 2^26 = 67108864
                     pixels; above 2^22 pixels fewer multisamples are used: 2^25 samples at most)
  --interpolation linear|spline|bspline|subdivision
                     curve scheme for the camera and every prop (overrides the file)
  --compare          split screen: left vtkCameraInterpolatorLCT, right VTK's vtkCameraInterpolator
                     on the same camera keys (bspline/subdivision: VTK uses its spline; at most
                     1000 camera keys: VTK's interpolator initialises in quadratic time)
  --mesh NAME=FILE   add a mesh (.vtp .vtk .stl .ply .obj, world coordinates) that props.NAME
                     can animate (repeatable, at most 16)
  --out DIR          output directory (default out/render; created if missing)
  -h, --help         this help

keys.json:
  {"camera": {"interpolation": "spline", "consistent_rotation": false,
              "keys": [{"time": 0, "position": [x,y,z], "focal_point": [x,y,z], "view_up": [0,1,0],
                        "view_angle": 30, "window_center": [0,0], "view_shear": [0,0,1],
                        "parallel_scale": 1, "parallel": false,
                        "clipping_range": [near, far]}, ...]},       (at least 2 keys)
   "props": {"NAME": {"interpolation": "spline", "consistent_rotation": false,
                      "keys": [{"time": 0, "matrix": [16 numbers, row-major]}
                               or {"time": 0, "translate": [x,y,z], "rotate": [deg, ax,ay,az],
                                   "scale": [sx,sy,sz], "shear": [xy, xz, yz]}, ...]}}}
  Only time, position and focal_point are required. Keys may come in any order; their times must
  differ. A prop key M = translate rotate shear scale is applied about the prop's centre (its
  bounding-box centre in the scene), in world axes. NAME is one of the default scene's model,
  sphere, cube, cone, floor, pedestal, or a --mesh name.

limits (input outside them is refused with a message naming the file and the key):
  keys file <= 32 MiB, JSON nesting <= 64; <= 10000 keys per track (camera, each prop)
  |time| <= 1e12; coordinates (position, focal_point, view_up, matrix, translate) within +-1e15
  view_angle in [1e-08, 179] (vtkCamera's own range); parallel_scale, clipping_range in
  [1e-12, 1e15]; window_center, view_shear, shear within +-1000; scale in [1e-09, 1e09];
  rotate angle within +-1e6 degrees
  .pvcc file <= 1 MiB; every value of its Camera* properties a complete, finite decimal number

meshes: a file is checked before a VTK reader sees it, then VTK's reader runs in a child
process (a crash or a runaway allocation of the reader is an error message, not a crash):
  all      a regular file, not empty, <= 1 GiB; after reading: >= 1 point, <= 2^24 points,
           <= 2^24 cells, <= 2^26 cell indices, every index in range, every point finite and
           within +-1e15, at least one cell
  .stl     binary (as VTK detects it): the file size must be 84 + 50 x the triangle count of its
           header; ASCII: must start with "solid" (the rest is VTK's parser, which reports errors)
  .ply     the whole file: header, element counts against the file size, every line (ASCII) or
           byte (binary), list lengths, face indices in range
  .obj     the whole file: lines <= 262144 bytes, vertex coordinates finite, every face/line/
           point index (v, vt, vn, negative ones too) in range
  .vtk     legacy POLYDATA: header, declared point and cell counts against the limits and the
           file size; ASCII bodies: every point and cell token and index
  .vtp     declared NumberOf* counts against the limits; the XML and its data are VTK's

ParaView camera files (.pvcc, from ParaView's "Save Camera"), given in order, become the camera
keys at t = 0, 1, 2, ... (replacing the keys file's camera keys).

Every output is written under a temporary name (.NAME.PID.part) and renamed when complete; a
failed run removes its temporary files and never leaves a partial file under a final name.
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

/// A file being written under a temporary name in its final directory; removed unless
/// Commit() renamed it.
class Temporary
{
public:
  explicit Temporary(const fs::path& final)
    : Final(final)
    , Path(final.parent_path() /
        ("." + final.filename().string() + "." + std::to_string(::getpid()) + ".part"))
  {
    for (this->Slot = 0; this->Slot < MaxTemporaries && Temporaries[this->Slot][0]; ++this->Slot)
    {
    }
    if (this->Slot < MaxTemporaries && this->Path.string().size() < sizeof Temporaries[0])
    {
      std::snprintf(Temporaries[this->Slot], sizeof Temporaries[0], "%s", this->Path.c_str());
    }
    else
    {
      this->Slot = -1;
    }
  }
  ~Temporary() { this->Discard(); }
  Temporary(const Temporary&) = delete;
  Temporary& operator=(const Temporary&) = delete;

  const fs::path& path() const { return this->Path; }

  /// Renames the temporary to the final name; on failure the temporary is removed and the
  /// reason returned.
  std::string Commit()
  {
    if (::rename(this->Path.c_str(), this->Final.c_str()) != 0)
    {
      const std::string why = std::strerror(errno);
      this->Discard();
      return "renaming " + this->Path.string() + " to " + this->Final.string() + " failed: " + why;
    }
    this->Release();
    return "";
  }

  void Discard()
  {
    if (this->Slot >= 0)
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
  }
  fs::path Final;
  fs::path Path;
  int Slot = -1;
};

/// Writes `size` bytes to `file` through a temporary, checking every write (a full disk or a
/// file-size limit is an error here, not a short file). Returns the reason on failure.
std::string WriteFileAtomically(const fs::path& file, const unsigned char* data, size_t size)
{
  Temporary tmp(file);
  const int fd = ::open(tmp.path().c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0)
  {
    return "cannot create " + tmp.path().string() + ": " + std::strerror(errno);
  }
  size_t done = 0;
  while (done < size)
  {
    const ssize_t n = ::write(fd, data + done, size - done);
    if (n < 0 && errno == EINTR)
    {
      continue;
    }
    if (n <= 0)
    {
      const std::string why = n < 0 ? std::strerror(errno) : "nothing written";
      ::close(fd);
      return "writing " + file.string() + " failed: " + why;
    }
    done += static_cast<size_t>(n);
  }
  if (::close(fd) != 0)
  {
    return "writing " + file.string() + " failed: " + std::strerror(errno);
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
  std::string Interpolation; // empty: from the keys
  bool Compare = false;
  std::string Out = "out/render";
  std::string KeysFile;
  std::vector<std::string> CameraFiles; // ParaView .pvcc files, one camera key each
  std::vector<std::pair<std::string, std::string>> Meshes;
};

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
    }
    else if (a == "--interpolation")
    {
      if (!value(v) || !RenderKeys::IsInterpolationName(v))
      {
        return "--interpolation expects linear, spline, bspline or subdivision";
      }
      o.Interpolation = v;
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
    else if (a.size() > 5 && a.compare(a.size() - 5, 5, ".pvcc") == 0)
    {
      if (o.CameraFiles.size() >= Limits::MaxKeys)
      {
        return "at most " + std::to_string(Limits::MaxKeys) + " .pvcc files";
      }
      o.CameraFiles.push_back(a);
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

// ---------------------------------------------------------------------------------------------
// Meshes

/// Keeps what lct-render renders of a mesh: points, cells, well-formed point normals and colours.
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
  return out;
}

/// Reads `file` with VTK's reader for its extension (in the child process).
vtkSmartPointer<vtkPolyData> ReadWithVTK(const std::string& file, const std::string& ext)
{
  vtkSmartPointer<vtkAlgorithm> reader;
  if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(file.c_str());
    reader = r;
  }
  else if (ext == ".vtk")
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
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
  reader->Update();
  auto* mesh = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
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
  if (ext != ".vtp" && ext != ".vtk" && ext != ".stl" && ext != ".ply" && ext != ".obj")
  {
    throw InputError(file + ": unsupported mesh format \"" + RenderKeys::Printable(ext) +
      "\" (expected .vtp .vtk .stl .ply .obj)");
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
          why += " (VTK's reader said: " + window->Last + ")";
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
      reply = "ER" + file + ": VTK's reader needs more than the 6 GiB it is given: the file " +
        "declares sizes that its data do not hold";
    }
    catch (const std::exception& e)
    {
      reply = "ER" + file + ": VTK's reader failed: " + e.what();
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
  const std::string reader = ext == ".vtp" ? "vtkXMLPolyDataReader"
    : ext == ".vtk"                        ? "vtkPolyDataReader"
    : ext == ".stl"                        ? "vtkSTLReader"
    : ext == ".ply"                        ? "vtkPLYReader"
                                           : "vtkOBJReader";
  if (WIFSIGNALED(status))
  {
    const int sig = WTERMSIG(status);
    throw InputError(file + ": VTK's " + reader + " failed on this file (" +
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
  for (int i = 0; i < 3; ++i)
  {
    if (std::fabs(p[i]) > Limits::MaxCoordinate || std::fabs(f[i]) > Limits::MaxCoordinate)
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
  if (!p.Path->InterpolateTransform(t, k))
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
  auto inTheWay = [&](const fs::path& file) {
    const auto s = fs::symlink_status(file, ec);
    return !ec && fs::exists(s) && !fs::is_regular_file(s);
  };
  for (int i = opt.First; i < opt.Last; ++i)
  {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    if (inTheWay(dir / name))
    {
      return (dir / name).string() + " exists and is not a regular file";
    }
  }
  for (const char* name : { "video.ogv", "contact_sheet.png" })
  {
    if (full && inTheWay(dir / name))
    {
      return (dir / name).string() + " exists and is not a regular file";
    }
  }
  return "";
}

} // namespace

int main(int argc, char* argv[])
{
  for (int sig : { SIGINT, SIGTERM, SIGHUP, SIGSEGV, SIGBUS, SIGABRT, SIGFPE })
  {
    std::signal(sig, OnFatalSignal);
  }
  // A file-size limit then fails the write (EFBIG, reported) instead of killing the process.
  std::signal(SIGXFSZ, SIG_IGN);
  // Xlib ends the process with exit() when the X server goes away mid-run.
  std::atexit(RemoveTemporaries);

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
  try
  {
    // Meshes first: their reader runs in a forked child, best before anything else exists.
    std::vector<vtkSmartPointer<vtkPolyData>> meshes;
    for (const auto& mesh : opt.Meshes)
    {
      meshes.push_back(ReadMesh(mesh.second));
    }
    keys = opt.KeysFile.empty() ? RenderKeys::BuiltIn() : RenderKeys::ReadFile(opt.KeysFile);
    if (!opt.CameraFiles.empty())
    {
      // ParaView camera files, in the order given, are the camera keys at t = 0, 1, 2, ...
      keys.Camera.clear();
      for (size_t i = 0; i < opt.CameraFiles.size(); ++i)
      {
        keys.Camera.push_back(RenderKeys::ReadPvcc(opt.CameraFiles[i], static_cast<double>(i)));
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
      if (opt.KeysFile.empty())
      {
        keys.Props.clear(); // the built-in prop keys belong to the built-in flight
        keys.Source = opt.CameraFiles[0];
      }
    }
    const std::string& source = keys.Source;
    if (opt.Compare && keys.Camera.size() > Limits::MaxCompareKeys)
    {
      throw InputError(source + ": " + std::to_string(keys.Camera.size()) +
        " camera keys; --compare accepts at most " + std::to_string(Limits::MaxCompareKeys) +
        " (VTK's vtkCameraInterpolator initialises in quadratic time)");
    }
    const std::string cameraScheme =
      opt.Interpolation.empty() ? keys.Interpolation : opt.Interpolation;

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

    // The scene: CameraFlightScene's actors, by name, plus --mesh meshes.
    const char* const names[] = { "floor", "pedestal", "model", "sphere", "cube", "cone" };
    const auto actors = CameraFlightScene::MakeActors(&modelSource);
    for (size_t i = 0; i < actors.size(); ++i)
    {
      Prop p;
      p.Name = i < 6 ? names[i] : "actor" + std::to_string(i);
      p.Actor = actors[i];
      props.push_back(std::move(p));
    }
    const double colors[4][3] = { { 0.6, 0.3, 0.7 }, { 0.9, 0.8, 0.2 }, { 0.2, 0.7, 0.7 },
      { 0.9, 0.5, 0.6 } };
    for (size_t m = 0; m < opt.Meshes.size(); ++m)
    {
      const auto& [name, file] = opt.Meshes[m];
      for (const auto& p : props)
      {
        if (p.Name == name)
        {
          throw InputError("--mesh " + RenderKeys::Printable(name) + "=" + file + ": the name " +
            RenderKeys::Printable(name) + " is already used by the scene");
        }
      }
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(meshes[m]);
      Prop p;
      p.Name = name;
      p.Actor = vtkSmartPointer<vtkActor>::New();
      p.Actor->SetMapper(mapper);
      p.Actor->GetProperty()->SetColor(colors[m % 4][0], colors[m % 4][1], colors[m % 4][2]);
      props.push_back(std::move(p));
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
      // The scene's points at rest, for the path metric (at most ~2000 per actor).
      auto* data = vtkPolyData::SafeDownCast(p.Actor->GetMapper()->GetInput());
      if (data && data->GetNumberOfPoints() > 0)
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
          ": no such object in the scene (known: " + known + "; add meshes with --mesh NAME=FILE)");
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

  const double tmin = cameraPath->GetMinimumT(), tmax = cameraPath->GetMaximumT();
  const int N = opt.Frames;
  const bool full = opt.First == 0 && opt.Last == N;
  auto frameTime = [&](int i) {
    return N > 1 ? tmin + (tmax - tmin) * (static_cast<double>(i) / (N - 1)) : tmin;
  };

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
      if (!cameraPath->InterpolateCamera(i == nanFrame && !nanProps ? nan : t, camera))
      {
        why = "vtkCameraInterpolatorLCT failed: " + cameraErrors.Take();
      }
      else
      {
        why = CheckCamera(camera);
      }
      if (why.empty() && opt.Compare)
      {
        vtkPath->InterpolateCamera(t, camera);
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

  // ---- output directory
  const fs::path outDir = opt.Out;
  {
    const std::string problem = CheckOutput(outDir, opt, full);
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
    metric->SetAspect((opt.Compare ? 0.5 : 1.0) * opt.Width / opt.Height);
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
        metric->GetSamplesPerSegment());
      for (int k = 0; k < std::min(segments, 8); ++k)
      {
        std::printf("lct-render:   segment %d (t = %s..%s): %.2f %% / %.2f %%\n", k,
          Num(keys.Camera[k].Time).c_str(), Num(keys.Camera[k + 1].Time).c_str(),
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
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  // Multisample buffers cost 8 bytes per sample: at most 2^25 samples (256 MiB).
  const long long pixels = static_cast<long long>(opt.Width) * opt.Height;
  int samples = 8;
  while (samples > 0 && samples * pixels > (1LL << 25))
  {
    samples /= 2;
  }
  window->SetMultiSamples(samples < 2 ? 0 : samples);
  window->SetSize(opt.Width, opt.Height);
  std::vector<vtkSmartPointer<vtkRenderer>> renderers;
  for (int side = 0; side < (opt.Compare ? 2 : 1); ++side)
  {
    auto renderer = vtkSmartPointer<vtkRenderer>::New();
    renderer->SetViewport(
      opt.Compare ? 0.5 * side : 0.0, 0.0, opt.Compare ? 0.5 * (side + 1) : 1.0, 1.0);
    renderer->SetBackground(0.96, 0.95, 0.92);
    for (const auto& p : props)
    {
      renderer->AddActor(p.Actor);
    }
    if (opt.Compare)
    {
      vtkNew<vtkTextActor> label;
      label->SetInput(side == 0 ? "LCT: vtkCameraInterpolatorLCT" : "VTK: vtkCameraInterpolator");
      label->GetTextProperty()->SetFontSize(std::max(10, opt.Height / 20));
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

  vtkNew<vtkOggTheoraWriter> video;
  ErrorCatcher videoErrors(video);
  const fs::path videoFile = outDir / "video.ogv";
  std::unique_ptr<Temporary> videoTmp;
  std::unique_ptr<ContactSheet> sheet;
  if (full)
  {
    videoTmp = std::make_unique<Temporary>(videoFile);
    video->SetInputConnection(grab->GetOutputPort());
    video->SetFileName(videoTmp->path().c_str());
    video->SetRate(24);
    video->SetQuality(2);
    sheet = std::make_unique<ContactSheet>(opt.Width, opt.Height);
  }
  auto fail = [&](const std::string& why) {
    std::cerr << "lct-render: " << why << "\n";
    if (videoTmp)
    {
      videoTmp->Discard();
    }
    RemoveTemporaries();
    return 1;
  };

  // Contact-sheet frames: 16 evenly spaced frames (fewer when N < 16).
  std::map<int, int> sheetSlot;
  for (int k = 0; k < 16 && full; ++k)
  {
    const int i = N >= 16 ? static_cast<int>(std::lround(k * (N - 1) / 15.0)) : k;
    if (i < N)
    {
      sheetSlot.emplace(i, k);
    }
  }

  const bool tty = isatty(STDOUT_FILENO);
  const int count = opt.Last - opt.First;
  const auto start = std::chrono::steady_clock::now();
  int lastDecile = 0;
  bool videoStarted = false;
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
    if (!cameraPath->InterpolateCamera(t, renderers[0]->GetActiveCamera()))
    {
      return fail("interpolating the camera at t = " + Num(t) + " failed: " + cameraErrors.Take());
    }
    if (opt.Compare)
    {
      vtkPath->InterpolateCamera(t, renderers[1]->GetActiveCamera());
    }
    for (auto& r : renderers)
    {
      r->ResetCameraClippingRange();
    }
    window->Render();
    grab->Modified();
    grab->Update();
    vtkImageData* image = grab->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    if (dims[0] != opt.Width || dims[1] != opt.Height || !image->GetScalarPointer())
    {
      return fail("rendering frame " + std::to_string(i) + " at " + std::to_string(opt.Width) +
        "x" + std::to_string(opt.Height) + " failed: the window gave a " + std::to_string(dims[0]) +
        "x" + std::to_string(dims[1]) + " image (is the size beyond what the X server renders?)");
    }

    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    why = WritePNG(image, outDir / name);
    if (!why.empty())
    {
      return fail(why);
    }
    if (full)
    {
      if (!videoStarted)
      {
        video->Start();
        videoStarted = true;
      }
      video->Write();
      if (video->GetErrorCode() != 0)
      {
        return fail("writing " + videoFile.string() + " failed: " + videoErrors.Take());
      }
      const auto slot = sheetSlot.find(i);
      if (slot != sheetSlot.end())
      {
        sheet->Add(slot->second, image);
      }
    }

    const int done = i - opt.First + 1;
    const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double fps = elapsed > 0.0 ? done / elapsed : 0.0;
    if (tty)
    {
      std::printf("\r%s %d/%d frames, %.1f fps, ETA %.0f s   ", Bar(done, count).c_str(), done,
        count, fps, fps > 0.0 ? (count - done) / fps : 0.0);
      if (done == count)
      {
        std::printf("\n");
      }
      std::fflush(stdout);
    }
    else if (static_cast<long long>(done) * 10 / count > lastDecile)
    {
      lastDecile = static_cast<int>(static_cast<long long>(done) * 10 / count);
      std::printf("rendered %d/%d frames\n", done, count);
      std::fflush(stdout);
    }
  }
  const double elapsed =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::printf(
    "lct-render: %d frames (%d..%d of %d) at %dx%d in %.2f s (%.1f fps) -> %s/frame_NNNN.png\n",
    count, opt.First, opt.Last - 1, N, opt.Width, opt.Height, elapsed,
    elapsed > 0 ? count / elapsed : 0.0, outDir.string().c_str());
  if (full)
  {
    video->End();
    std::string why;
    if (video->GetErrorCode() != 0)
    {
      return fail("writing " + videoFile.string() + " failed: " + videoErrors.Take());
    }
    if (!CompleteOgg(videoTmp->path(), why))
    {
      return fail(
        "writing " + videoFile.string() + " failed: " + why + " (disk full or a file-size limit?)");
    }
    why = videoTmp->Commit();
    if (!why.empty())
    {
      return fail(why);
    }
    std::printf("lct-render: video %s\n", videoFile.string().c_str());
    const fs::path sheetFile = outDir / "contact_sheet.png";
    why = WritePNG(sheet->image(), sheetFile);
    if (!why.empty())
    {
      return fail(why);
    }
    std::printf("lct-render: contact sheet %s\n", sheetFile.string().c_str());
  }
  return 0;
}
