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
#include "vtkCollection.h"
#include "vtkCommand.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkOBJReader.h"
#include "vtkOggTheoraWriter.h"
#include "vtkPLYReader.h"
#include "vtkPNGWriter.h"
#include "vtkPoints.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkTextActor.h"
#include "vtkTextProperty.h"
#include "vtkTransformInterpolatorLCT.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWindowToImageFilter.h"
#include "vtkXMLPolyDataReader.h"

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace
{
namespace fs = std::filesystem;

const char* const Usage =
  R"(usage: lct-render [options] [keys.json] [view1.pvcc view2.pvcc ...]

Renders a keyframed camera flight through vtkCameraInterpolatorLCT (props through
vtkTransformInterpolatorLCT) offscreen to DIR/frame_NNNN.png, DIR/video.ogv (Ogg Theora) and
DIR/contact_sheet.png (4x4 evenly spaced frames), and prints the path-quality metric
(vtkCameraPathMetric: mean excess path length of the scene's points, camera space and screen).
Without keys.json it renders the built-in keys: a 130-degree turn with a window-centre shift and a
zoom, and the cone tumbling 720 degrees while it shears.

options:
  --frames N         render N frames (default 48); frame i is at key time tmin + i/(N-1) (tmax-tmin)
  --frames A:B/N     render only frames A..B-1 of N (files keep their global numbers, so the
                     slices of several runs equal one full run); no video or contact sheet.
                     A:B alone means A:B/48
  --size WxH         image size (default 640x360)
  --interpolation linear|spline|bspline|subdivision
                     curve scheme for the camera and every prop (overrides the file)
  --compare          split screen: left vtkCameraInterpolatorLCT, right VTK's vtkCameraInterpolator
                     on the same camera keys (bspline/subdivision: VTK uses its spline)
  --mesh NAME=FILE   add a mesh (.vtp .vtk .stl .ply .obj, world coordinates) that props.NAME
                     can animate (repeatable)
  --out DIR          output directory (default out/render; created if missing)
  -h, --help         this help

keys.json:
  {"camera": {"interpolation": "spline", "consistent_rotation": false,
              "keys": [{"time": 0, "position": [x,y,z], "focal_point": [x,y,z], "view_up": [0,1,0],
                        "view_angle": 30, "window_center": [0,0], "view_shear": [0,0,1],
                        "parallel_scale": 1, "parallel": false}, ...]},       (at least 2 keys)
   "props": {"NAME": {"interpolation": "spline", "consistent_rotation": false,
                      "keys": [{"time": 0, "matrix": [16 numbers, row-major]}
                               or {"time": 0, "translate": [x,y,z], "rotate": [deg, ax,ay,az],
                                   "scale": [sx,sy,sz], "shear": [xy, xz, yz]}, ...]}}}
  Only time, position and focal_point are required. A prop key M = translate rotate shear scale is
  applied about the prop's centre (its bounding-box centre in the scene), in world axes. NAME is
  one of the default scene's model, sphere, cube, cone, floor, pedestal, or a --mesh name.

ParaView camera files (.pvcc, from ParaView's "Save Camera"), given in order, become the camera
keys at t = 0, 1, 2, ... (replacing the keys file's camera keys).

Run it under `xvfb-run -a` when there is no display.
exit codes: 0 ok, 1 error (bad input, failed write), 2 usage, 125 no DISPLAY
)";

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
        if (!ParseInt(v, o.Frames) || o.Frames < 1)
        {
          return "--frames " + v + ": expected a frame count N >= 1 or A:B/N";
        }
        continue;
      }
      const size_t slash = v.find('/');
      std::string total = slash == std::string::npos ? "48" : v.substr(slash + 1);
      if (!ParseInt(v.substr(0, colon), o.First) ||
        !ParseInt(
          v.substr(colon + 1, slash == std::string::npos ? std::string::npos : slash - colon - 1),
          o.Last) ||
        !ParseInt(total, o.Frames) || o.Frames < 1 || o.First >= o.Last || o.Last > o.Frames)
      {
        return "--frames " + v + ": expected A:B/N with 0 <= A < B <= N";
      }
    }
    else if (a == "--size")
    {
      const size_t x = value(v) ? v.find('x') : std::string::npos;
      if (x == std::string::npos || !ParseInt(v.substr(0, x), o.Width) ||
        !ParseInt(v.substr(x + 1), o.Height) || o.Width < 16 || o.Height < 16 || o.Width > 8192 ||
        o.Height > 8192)
      {
        return "--size expects WxH (16..8192 each), e.g. 640x360";
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
      return "unknown option " + a;
    }
    else if (a.size() > 5 && a.compare(a.size() - 5, 5, ".pvcc") == 0)
    {
      o.CameraFiles.push_back(a);
    }
    else if (o.KeysFile.empty())
    {
      o.KeysFile = a;
    }
    else
    {
      return "more than one keys file (" + o.KeysFile + ", " + a + ")";
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

/// Collects the text of vtkErrorMacro calls on an object (instead of printing them).
struct ErrorCatcher
{
  std::string Message;
  vtkNew<vtkCallbackCommand> Command;
  explicit ErrorCatcher(vtkObject* object)
  {
    this->Command->SetClientData(this);
    this->Command->SetCallback([](vtkObject*, unsigned long, void* self, void* data) {
      auto* catcher = static_cast<ErrorCatcher*>(self);
      catcher->Message = data ? static_cast<const char*>(data) : "unknown error";
      while (!catcher->Message.empty() &&
        (catcher->Message.back() == '\n' || catcher->Message.back() == ' '))
      {
        catcher->Message.pop_back();
      }
    });
    object->AddObserver(vtkCommand::ErrorEvent, this->Command);
  }
  std::string Take()
  {
    std::string m = this->Message;
    this->Message.clear();
    // Keep the last line (vtkErrorMacro prefixes the location).
    const size_t nl = m.rfind('\n');
    return nl == std::string::npos ? m : m.substr(nl + 1);
  }
};

struct Prop
{
  std::string Name;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkMatrix4x4> Rest; // the actor's matrix before animation
  double Center[3] = { 0.0, 0.0, 0.0 };
  vtkSmartPointer<vtkTransformInterpolatorLCT> Path; // null: static
  vtkSmartPointer<vtkMatrix4x4> Current;
};

vtkSmartPointer<vtkPolyData> ReadMesh(const std::string& file)
{
  std::string ext = fs::path(file).extension().string();
  std::transform(
    ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  if (!std::ifstream(file, std::ios::binary).good())
  {
    throw RenderKeys::InputError(file + ": cannot open mesh file: " + std::strerror(errno));
  }
  vtkSmartPointer<vtkAbstractPolyDataReader> abstractReader;
  vtkSmartPointer<vtkPolyData> mesh;
  if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> r;
    r->SetFileName(file.c_str());
    r->Update();
    mesh = r->GetOutput();
  }
  else if (ext == ".vtk")
  {
    vtkNew<vtkPolyDataReader> r;
    r->SetFileName(file.c_str());
    r->Update();
    mesh = r->GetOutput();
  }
  else if (ext == ".stl")
  {
    abstractReader = vtkSmartPointer<vtkSTLReader>::New();
  }
  else if (ext == ".ply")
  {
    abstractReader = vtkSmartPointer<vtkPLYReader>::New();
  }
  else if (ext == ".obj")
  {
    abstractReader = vtkSmartPointer<vtkOBJReader>::New();
  }
  else
  {
    throw RenderKeys::InputError(
      file + ": unsupported mesh format \"" + ext + "\" (expected .vtp .vtk .stl .ply .obj)");
  }
  if (abstractReader)
  {
    abstractReader->SetFileName(file.c_str());
    abstractReader->Update();
    mesh = abstractReader->GetOutput();
  }
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    throw RenderKeys::InputError(file + ": no polygonal data could be read");
  }
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->DeepCopy(mesh);
  return copy;
}

/// Writes `image` as PNG to a temporary name in the same directory, then renames it to `file`.
bool WritePNG(vtkImageData* image, const fs::path& file)
{
  const fs::path tmp = file.parent_path() / ("." + file.filename().string() + ".part");
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(tmp.c_str());
  writer->SetInputData(image);
  writer->Write();
  std::error_code ec;
  if (writer->GetErrorCode() != 0)
  {
    fs::remove(tmp, ec);
    std::cerr << "lct-render: writing " << file.string() << " failed\n";
    return false;
  }
  fs::rename(tmp, file, ec);
  if (ec)
  {
    std::cerr << "lct-render: renaming " << tmp.string() << " failed: " << ec.message() << "\n";
    return false;
  }
  return true;
}

/// A (4 * cell + gutter) grid of the given frames, each shrunk by `shrink` (box filter).
vtkSmartPointer<vtkImageData> ContactSheet(
  const std::vector<vtkSmartPointer<vtkImageData>>& frames, int shrink)
{
  int dims[3];
  frames.front()->GetDimensions(dims);
  const int w = dims[0] / shrink, h = dims[1] / shrink, gutter = 4;
  const int W = 4 * w + 5 * gutter, H = 4 * h + 5 * gutter;
  auto sheet = vtkSmartPointer<vtkImageData>::New();
  sheet->SetDimensions(W, H, 1);
  sheet->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(sheet->GetScalarPointer());
  std::fill(out, out + 3 * static_cast<size_t>(W) * H, static_cast<unsigned char>(255));
  for (size_t k = 0; k < frames.size() && k < 16; ++k)
  {
    const int col = static_cast<int>(k % 4), row = static_cast<int>(k / 4); // row 0 at the top
    const int x0 = gutter + col * (w + gutter);
    const int y0 = H - (row + 1) * (h + gutter); // image rows go bottom-up
    const auto* in = static_cast<const unsigned char*>(frames[k]->GetScalarPointer());
    for (int y = 0; y < h; ++y)
    {
      for (int x = 0; x < w; ++x)
      {
        for (int c = 0; c < 3; ++c)
        {
          int sum = 0;
          for (int dy = 0; dy < shrink; ++dy)
          {
            for (int dx = 0; dx < shrink; ++dx)
            {
              sum += in[3 * (static_cast<size_t>(y * shrink + dy) * dims[0] + x * shrink + dx) + c];
            }
          }
          out[3 * (static_cast<size_t>(y0 + y) * W + x0 + x) + c] =
            static_cast<unsigned char>((sum + shrink * shrink / 2) / (shrink * shrink));
        }
      }
    }
  }
  return sheet;
}

std::string Bar(int done, int total)
{
  const int width = 10, filled = total > 0 ? done * width / total : width;
  return "[" + std::string(filled, '#') + std::string(width - filled, ' ') + "]";
}

} // namespace

int main(int argc, char* argv[])
{
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
  vtkNew<vtkPoints> scenePoints;
  std::string modelSource;
  try
  {
    keys = opt.KeysFile.empty() ? RenderKeys::BuiltIn() : RenderKeys::ReadFile(opt.KeysFile);
    if (!opt.CameraFiles.empty())
    {
      // ParaView camera files, in the order given, are the camera keys at t = 0, 1, 2, ...
      keys.Camera.clear();
      for (size_t i = 0; i < opt.CameraFiles.size(); ++i)
      {
        keys.Camera.push_back(RenderKeys::ReadPvcc(opt.CameraFiles[i], static_cast<double>(i)));
      }
      if (keys.Camera.size() < 2)
      {
        throw RenderKeys::InputError(opt.CameraFiles[0] +
          ": a camera path needs at least 2 keys (give 2 or more .pvcc files)");
      }
      if (opt.KeysFile.empty())
      {
        keys.Props.clear(); // the built-in prop keys belong to the built-in flight
        keys.Source = opt.CameraFiles[0];
      }
    }
    const std::string& source = keys.Source;
    const std::string cameraScheme =
      opt.Interpolation.empty() ? keys.Interpolation : opt.Interpolation;

    cameraPath->SetInterpolationType(CameraType(cameraScheme));
    cameraPath->SetConsistentRotation(keys.ConsistentRotation);
    vtkPath->SetInterpolationType(cameraScheme == "linear"
        ? vtkCameraInterpolator::INTERPOLATION_TYPE_LINEAR
        : vtkCameraInterpolator::INTERPOLATION_TYPE_SPLINE);
    {
      ErrorCatcher errors(cameraPath);
      for (const auto& key : keys.Camera)
      {
        if (!cameraPath->AddCamera(key.Time, key.Camera))
        {
          throw RenderKeys::InputError(source + ": " + key.Path +
            " is degenerate (rejected by vtkCameraInterpolatorLCT: " + errors.Take() + ")");
        }
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
      props.push_back(p);
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
          throw RenderKeys::InputError(
            "--mesh " + name + "=" + file + ": the name " + name + " is already used by the scene");
        }
      }
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(ReadMesh(file));
      Prop p;
      p.Name = name;
      p.Actor = vtkSmartPointer<vtkActor>::New();
      p.Actor->SetMapper(mapper);
      p.Actor->GetProperty()->SetColor(colors[m % 4][0], colors[m % 4][1], colors[m % 4][2]);
      props.push_back(p);
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
          known += (known.empty() ? "" : ", ") + p.Name;
        }
        throw RenderKeys::InputError(source + ": props." + name +
          ": no such object in the scene (known: " + known + "; add meshes with --mesh NAME=FILE)");
      }
      it->Path = vtkSmartPointer<vtkTransformInterpolatorLCT>::New();
      const std::string scheme = !opt.Interpolation.empty() ? opt.Interpolation
        : !track.Interpolation.empty()                      ? track.Interpolation
                                                            : keys.Interpolation;
      it->Path->SetInterpolationType(CameraType(scheme)); // same enum values 0..3
      it->Path->SetConsistentRotation(track.ConsistentRotation);
      ErrorCatcher errors(it->Path);
      for (const auto& key : track.Keys)
      {
        vtkNew<vtkMatrix4x4> m;
        m->DeepCopy(key.Matrix.data());
        if (!it->Path->AddTransform(key.Time, m))
        {
          throw RenderKeys::InputError(source + ": " + key.Path +
            " is not a usable transform (rejected by vtkTransformInterpolatorLCT: " +
            errors.Take() + ")");
        }
      }
      it->Current = vtkSmartPointer<vtkMatrix4x4>::New();
      it->Actor->SetUserMatrix(it->Current);
    }
  }
  catch (const RenderKeys::InputError& e)
  {
    std::cerr << "lct-render: " << e.what() << "\n";
    return 1;
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
    std::error_code ec;
    fs::create_directories(outDir, ec);
    if (ec || !fs::is_directory(outDir))
    {
      std::cerr << "lct-render: cannot create output directory " << opt.Out
                << (ec ? ": " + ec.message() : "") << "\n";
      return 1;
    }
  }

  const double tmin = cameraPath->GetMinimumT(), tmax = cameraPath->GetMaximumT();
  const int N = opt.Frames;
  const bool full = opt.First == 0 && opt.Last == N;
  auto frameTime = [&](int i) { return N > 1 ? tmin + (tmax - tmin) * i / (N - 1) : tmin; };

  // ---- path metric
  {
    vtkNew<vtkCameraPathMetric> metric;
    metric->SetPoints(scenePoints);
    metric->SetAspect((opt.Compare ? 0.5 : 1.0) * opt.Width / opt.Height);
    metric->SetNumberOfSamples(std::max(N, 2));
    if (metric->EvaluateInterpolator(cameraPath, tmin, tmax))
    {
      std::printf("lct-render: metric LCT path (vtkCameraInterpolatorLCT): %.2f %% excess in "
                  "camera space, %.2f %% on screen, %d of %lld points leave the view\n",
        metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess(),
        metric->GetNumberOfPointsLeavingView(),
        static_cast<long long>(scenePoints->GetNumberOfPoints()));
    }
    if (opt.Compare)
    {
      vtkNew<vtkCollection> cameras;
      const int samples = std::max(N, 2);
      for (int s = 0; s < samples; ++s)
      {
        vtkNew<vtkCamera> c;
        vtkPath->InterpolateCamera(tmin + (tmax - tmin) * s / (samples - 1), c);
        cameras->AddItem(c);
      }
      if (metric->EvaluateCameras(cameras))
      {
        std::printf("lct-render: metric VTK path (vtkCameraInterpolator):    %.2f %% excess in "
                    "camera space, %.2f %% on screen, %d of %lld points leave the view\n",
          metric->GetCameraSpaceExcess(), metric->GetScreenSpaceExcess(),
          metric->GetNumberOfPointsLeavingView(),
          static_cast<long long>(scenePoints->GetNumberOfPoints()));
      }
    }
    std::fflush(stdout);
  }

  // ---- render window
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(8);
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
  const fs::path videoFile = outDir / "video.ogv";
  const fs::path videoTmp = outDir / ".video.ogv.part";
  if (full)
  {
    video->SetInputConnection(grab->GetOutputPort());
    video->SetFileName(videoTmp.c_str());
    video->SetRate(24);
    video->SetQuality(2);
  }

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
  std::vector<vtkSmartPointer<vtkImageData>> sheetFrames;

  const bool tty = isatty(STDOUT_FILENO);
  const int count = opt.Last - opt.First;
  const auto start = std::chrono::steady_clock::now();
  int lastDecile = 0;
  bool videoStarted = false;
  for (int i = opt.First; i < opt.Last; ++i)
  {
    const double t = frameTime(i);
    for (auto& p : props)
    {
      if (!p.Path)
      {
        continue;
      }
      vtkNew<vtkMatrix4x4> k;
      if (!p.Path->InterpolateTransform(t, k))
      {
        std::cerr << "lct-render: interpolating props." << p.Name << " at t = " << t << " failed\n";
        return 1;
      }
      // Current = T(c) K T(-c) Rest
      vtkNew<vtkTransform> x;
      x->PostMultiply();
      x->Concatenate(p.Rest);
      x->Translate(-p.Center[0], -p.Center[1], -p.Center[2]);
      x->Concatenate(k);
      x->Translate(p.Center);
      p.Current->DeepCopy(x->GetMatrix());
    }
    if (!cameraPath->InterpolateCamera(t, renderers[0]->GetActiveCamera()))
    {
      std::cerr << "lct-render: interpolating the camera at t = " << t << " failed\n";
      return 1;
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

    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", i);
    if (!WritePNG(image, outDir / name))
    {
      return 1;
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
        std::cerr << "lct-render: writing " << videoFile.string() << " failed\n";
        return 1;
      }
      if (sheetSlot.count(i))
      {
        auto copy = vtkSmartPointer<vtkImageData>::New();
        copy->DeepCopy(image);
        sheetFrames.push_back(copy);
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
    else if (done * 10 / count > lastDecile)
    {
      lastDecile = done * 10 / count;
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
    std::error_code ec;
    if (video->GetErrorCode() != 0 || !fs::exists(videoTmp) || fs::file_size(videoTmp, ec) == 0)
    {
      fs::remove(videoTmp, ec);
      std::cerr << "lct-render: writing " << videoFile.string() << " failed\n";
      return 1;
    }
    fs::rename(videoTmp, videoFile, ec);
    if (ec)
    {
      std::cerr << "lct-render: renaming to " << videoFile.string() << " failed: " << ec.message()
                << "\n";
      return 1;
    }
    std::printf("lct-render: video %s\n", videoFile.string().c_str());
    const fs::path sheetFile = outDir / "contact_sheet.png";
    if (!WritePNG(ContactSheet(sheetFrames, opt.Width >= 320 ? 2 : 1), sheetFile))
    {
      return 1;
    }
    std::printf("lct-render: contact sheet %s\n", sheetFile.string().c_str());
  }
  return 0;
}
