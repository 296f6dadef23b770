// The input of Examples/lct-render.cxx: the JSON keyframe file format and its validation
// (messages name the file and the key, e.g. `keys.json: camera.keys[3].view_angle must be in
// [1e-08, 179]`), ParaView camera files (.pvcc), the built-in keys (the CameraFlightScene flight
// plus a spinning, shearing cone), the limits every input is held to, and the checks a mesh file
// passes before a VTK reader sees it (RenderMeshCheck below).
//
// Header-only: everything is `inline`. Needs nlohmann_json and VTK::RenderingCore.
#ifndef RenderKeys_h
#define RenderKeys_h

#include "CameraFlightScene.h"

#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <numeric>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace RenderKeys
{

/// What lct-render accepts. Each bounds an allocation or keeps a value where double (and the
/// single-precision OpenGL pipeline) still computes something meaningful; `lct-render --help`
/// and the README list them.
namespace Limits
{
constexpr int MaxFrames = 1000000;
constexpr int MinSide = 16;
constexpr int MaxSide = 16384;
constexpr long long MaxPixels = 1LL << 26; // 67 Mpixel, e.g. 8192x8192
/// Keys per track (the camera, each prop). vtkCameraInterpolatorLCT loads 10^4 keys in 0.15 s.
constexpr size_t MaxKeys = 10000;
/// Camera keys with --compare: VTK's vtkCameraInterpolator rebuilds its splines in quadratic
/// time (7 s for 10^4 keys, 87 s for 3 10^4).
constexpr size_t MaxCompareKeys = 1000;
constexpr std::uintmax_t MaxKeysFileBytes = 32u << 20;
constexpr int MaxJsonDepth = 64;
constexpr std::uintmax_t MaxPvccBytes = 1u << 20;
constexpr int MaxPvccElements = 10000;
/// |time| of a key; key times are also compared exactly, so they must be distinct doubles.
constexpr double MaxTime = 1e12;
/// |coordinate| of positions, focal points, translations and mesh points: the squared
/// distances stay far from overflow and 7 significant digits of float32 keep their meaning.
constexpr double MaxCoordinate = 1e15;
/// Lengths: parallel scale, clipping range.
constexpr double MinLength = 1e-12;
constexpr double MaxLength = 1e15;
/// vtkCamera::SetViewAngle clamps to this range, so a key outside it would not be reproduced.
constexpr double MinViewAngle = 1e-8;
constexpr double MaxViewAngle = 179.0;
/// |window_center|, |view_shear| and |shear| entries.
constexpr double MaxOffset = 1e3;
constexpr double MinScale = 1e-9;
constexpr double MaxScale = 1e9;
/// |rotate angle| in degrees.
constexpr double MaxAngle = 1e6;
/// Mesh files of a run: --mesh and scene objects read from files together.
constexpr int MaxMeshes = 16;
/// Objects of a scene section (files and sources).
constexpr size_t MaxObjects = 256;
/// Lights of a scene section (a light kit is 4, ParaView's light inspector offers 8 or so).
constexpr size_t MaxLights = 16;
/// Source tessellation: a sphere of 1024 x 1024 quads is 2 million triangles.
constexpr int MinResolution = 3;
constexpr int MaxResolution = 1024;
/// Line width and point size in pixels.
constexpr double MaxPixelSize = 100.0;
/// Video frame rate (--fps): Ogg Theora stores it as a fraction; beyond 240 no player keeps up.
constexpr int MaxFps = 240;
/// ParaView state files: a state with a few hundred proxies is ~1 MiB; 64 MiB holds embedded
/// data too. vtkXMLDataElement frees its children recursively, so the nesting is bounded.
constexpr std::uintmax_t MaxStateBytes = 64u << 20;
constexpr int MaxXmlDepth = 256;
constexpr std::uintmax_t MaxMeshFileBytes = 1u << 30;
constexpr long long MaxMeshPoints = 1LL << 24;
constexpr long long MaxMeshCells = 1LL << 24;
/// Indices in all cells of a mesh.
constexpr long long MaxMeshIndices = 1LL << 26;
} // namespace Limits

/// An input error; what() is the complete message (file name first).
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

/// The shortest text that reads back as exactly `v` (so 1e-07 is not printed as 0.000000, and
/// two times that differ in the 17th digit look different).
inline std::string Num(double v)
{
  if (std::isnan(v))
  {
    return "nan";
  }
  if (std::isinf(v))
  {
    return v > 0 ? "inf" : "-inf";
  }
  char buffer[32];
  if (v == std::floor(v) && std::fabs(v) < 1e15)
  {
    std::snprintf(buffer, sizeof buffer, "%.0f", v);
    return buffer;
  }
  for (int precision = 1; precision <= 17; ++precision)
  {
    std::snprintf(buffer, sizeof buffer, "%.*g", precision, v);
    if (std::strtod(buffer, nullptr) == v)
    {
      break;
    }
  }
  return buffer;
}

/// `text` with bytes that could drive a terminal (or are not ASCII) shown as \xNN, cut to 80
/// characters: names from a hostile file end up in messages.
inline std::string Printable(const std::string& text)
{
  std::string out;
  for (size_t i = 0; i < text.size() && i < 80; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f)
    {
      out += static_cast<char>(c);
    }
    else
    {
      char hex[8];
      std::snprintf(hex, sizeof hex, "\\x%02x", c);
      out += hex;
    }
  }
  if (text.size() > 80)
  {
    out += "...";
  }
  return out;
}

/// "1:7" for byte offset `offset` (0-based) of `text`.
inline std::string LineColumn(const std::string& text, size_t offset)
{
  size_t line = 1, column = 1;
  const size_t end = std::min(offset, text.size());
  for (size_t i = 0; i < end; ++i)
  {
    if (text[i] == '\n')
    {
      ++line;
      column = 1;
    }
    else
    {
      ++column;
    }
  }
  return std::to_string(line) + ":" + std::to_string(column);
}

/// The whole of a regular file of at most `limit` bytes; throws InputError naming `what`.
inline std::string ReadSmallFile(const std::string& file, std::uintmax_t limit, const char* what)
{
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
  {
    throw InputError(file + ": cannot open " + what + ": " +
      (ec ? ec.message() : std::string(std::strerror(ENOENT))));
  }
  if (!std::filesystem::is_regular_file(status))
  {
    throw InputError(file + ": cannot open " + what + ": not a regular file");
  }
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec)
  {
    throw InputError(file + ": cannot open " + what + ": " + ec.message());
  }
  if (size > limit)
  {
    throw InputError(file + ": the " + what + " has " + std::to_string(size) + " bytes; at most " +
      std::to_string(limit) + " are accepted");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    throw InputError(file + ": cannot open " + what + ": " + std::strerror(errno));
  }
  std::string text(static_cast<size_t>(size), '\0');
  in.read(&text[0], static_cast<std::streamsize>(size));
  if (in.gcount() != static_cast<std::streamsize>(size))
  {
    throw InputError(file + ": cannot read " + what);
  }
  return text;
}

/// The timing fields of a key: its own Kochanek-Bartels tension, continuity and bias (any of
/// the three given: the key has its own, the missing ones 0; else the path's apply) and the
/// eases of the motion arriving at it (ease_in) and leaving it (ease_out), each in [0, 1].
struct KeyTiming
{
  bool HasTensionContinuityBias = false;
  double Tension = 0.0;
  double Continuity = 0.0;
  double Bias = 0.0;
  bool HasEase = false; // ease_in or ease_out given (the other one 0)
  double EaseIn = 0.0;  // arriving at the key
  double EaseOut = 0.0; // leaving the key
};

/// The timing fields of a path (the camera, each prop): tension, continuity and bias in
/// [-1, 1] for the keys without their own, the spline's tangents (one of TangentNames()), the
/// eases of the whole path in [0, 1] (ease_in: it starts slowly, ease_out: it ends slowly) and
/// constant speed.
struct PathTiming
{
  double Tension = 0.0;
  double Continuity = 0.0;
  double Bias = 0.0;
  std::string Tangents = "monotone";
  double EaseIn = 0.0;
  double EaseOut = 0.0;
  bool ConstantSpeed = false;
  /// Props: the point whose path is measured, relative to the object's centre.
  double ConstantSpeedPoint[3] = { 0.0, 0.0, 0.0 };
  /// The camera: what is measured, one of ConstantSpeedMeasures().
  std::string ConstantSpeedMeasure = "eye_and_focal_point";
};

/// The values of "tangents": the interpolators' MonotoneTangents on (Fritsch & Butland's
/// tangents, the default: no overshoot where a path slows down or turns back; for props with
/// vtkTransformInterpolatorLCT's StraightenImpacts on), on with StraightenImpacts off
/// ("monotone_cubic": the cubic beside impact keys too; the camera has no impact rule, so for it
/// the same as "monotone"), and off (plain Catmull-Rom).
inline const std::vector<std::string>& TangentNames()
{
  static const std::vector<std::string> names = { "monotone", "monotone_cubic", "catmull_rom" };
  return names;
}

/// The values of the camera's constant_speed_measure, in vtkCameraInterpolatorLCT's order
/// (CONSTANT_SPEED_EYE_AND_FOCAL_POINT, CONSTANT_SPEED_EYE, CONSTANT_SPEED_FOCAL_POINT).
inline const std::vector<std::string>& ConstantSpeedMeasures()
{
  static const std::vector<std::string> names = { "eye_and_focal_point", "eye", "focal_point" };
  return names;
}

struct CameraKey
{
  double Time = 0.0;
  vtkSmartPointer<vtkCamera> Camera;
  std::string Path;           // "camera.keys[3]", for messages
  bool ClippingRange = false; // given by the key (else reset from the scene's bounds per frame)
  KeyTiming Timing;
};

struct PropKey
{
  double Time = 0.0;
  std::array<double, 16> Matrix{}; // row-major 4x4
  std::string Path;
  KeyTiming Timing;
};

struct PropTrack
{
  std::string Interpolation; // empty: the camera's
  bool ConsistentRotation = false;
  PathTiming Timing;
  std::vector<PropKey> Keys;
};

/// How an object of the scene section is drawn (vtkProperty and the mapper's scalar colouring).
struct Appearance
{
  bool HasColor = false; // else the object's own colours (a file's, the axes') or a palette's
  double Color[3] = { 0.8, 0.8, 0.8 };
  double Opacity = 1.0;
  std::string Representation = "surface"; // surface, wireframe, points
  bool Visible = true;
  std::string ColorBy;                   // a point or cell array of the object; empty: none
  std::string ColorMap = "cool to warm"; // see ColorMapNames()
  bool HasScalarRange = false;           // else the array's range
  double ScalarRange[2] = { 0.0, 1.0 };
  double LineWidth = 1.0;
  double PointSize = 3.0;
};

/// An object of the scene section: a mesh file or a source, named as props name it.
struct SceneObject
{
  std::string Name;
  std::string Path;   // "scene.objects.NAME", for messages
  std::string File;   // the file (relative names resolved against the keys file's folder), or ""
  std::string Source; // sphere, cube, cone, plane, axes (when File is empty)
  double Center[3] = { 0.0, 0.0, 0.0 };
  double Radius = 0.5;                     // sphere, cone
  double Height = 1.0;                     // cone
  double Size[3] = { 1.0, 1.0, 1.0 };      // cube: edge lengths; plane: [width, height]
  double Direction[3] = { 0.0, 0.0, 1.0 }; // cone axis (base to tip), plane normal
  double Length = 1.0;                     // axes
  int Resolution = 32;                     // sphere, cone
  Appearance Look;
};

struct SceneLight
{
  double Position[3] = { 1.0, 1.0, 1.0 };
  double FocalPoint[3] = { 0.0, 0.0, 0.0 };
  double Color[3] = { 1.0, 1.0, 1.0 };
  double Intensity = 1.0;
  bool Camera = false; // moves with the camera (position and focal point in camera coordinates)
};

/// The scene section: what is drawn, and how the image is made.
struct Scene
{
  bool Given = false; // the keys file has a "scene" section
  double Background[3] = { 0.96, 0.95, 0.92 };
  bool Gradient = false; // Background at the bottom, BackgroundTop at the top
  double BackgroundTop[3] = { 1.0, 1.0, 1.0 };
  std::string Lights = "kit"; // kit, headlight, list (Lights below)
  std::vector<SceneLight> LightList;
  int Width = 0, Height = 0;         // 0: not given (--size, else 640x360)
  std::string AntiAliasing = "msaa"; // msaa, fxaa, none
  std::vector<SceneObject> Objects;  // sorted by name
};

struct Keys
{
  std::string Source = "built-in keys"; // file name, for messages
  std::string Interpolation = "spline";
  bool ConsistentRotation = false; // camera
  PathTiming CameraTiming;
  std::vector<CameraKey> Camera; // in increasing time (see SortByTime)
  std::map<std::string, PropTrack> Props;
  Scene View;
};

/// The colour maps of Appearance::ColorMap: name and control points (value in [0, 1], r, g, b),
/// interpolated in Lab space (cool to warm: Moreland's diverging map, as ParaView's default;
/// viridis: 9 samples of matplotlib's table).
inline const std::map<std::string, std::vector<std::array<double, 4>>>& ColorMaps()
{
  static const std::map<std::string, std::vector<std::array<double, 4>>> maps = {
    { "cool to warm",
      { { 0.0, 0.231, 0.298, 0.753 }, { 0.5, 0.865, 0.865, 0.865 },
        { 1.0, 0.706, 0.016, 0.150 } } },
    { "viridis",
      { { 0.0, 0.267, 0.005, 0.329 }, { 0.125, 0.283, 0.141, 0.458 }, { 0.25, 0.254, 0.265, 0.530 },
        { 0.375, 0.207, 0.372, 0.553 }, { 0.5, 0.164, 0.471, 0.558 },
        { 0.625, 0.128, 0.567, 0.551 }, { 0.75, 0.135, 0.659, 0.518 },
        { 0.875, 0.478, 0.821, 0.318 }, { 1.0, 0.993, 0.906, 0.144 } } },
    { "rainbow",
      { { 0.0, 0.0, 0.0, 1.0 }, { 0.25, 0.0, 1.0, 1.0 }, { 0.5, 0.0, 1.0, 0.0 },
        { 0.75, 1.0, 1.0, 0.0 }, { 1.0, 1.0, 0.0, 0.0 } } },
    { "grayscale", { { 0.0, 0.0, 0.0, 0.0 }, { 1.0, 1.0, 1.0, 1.0 } } },
  };
  return maps;
}

/// "a, b or c" of a set of names, for messages.
template <typename Names>
std::string OneOf(const Names& names)
{
  std::string out;
  size_t i = 0;
  for (const auto& n : names)
  {
    const std::string name = Printable(n);
    out += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + name;
    ++i;
  }
  return out;
}

inline bool IsInterpolationName(const std::string& name)
{
  return name == "linear" || name == "spline" || name == "bspline" || name == "subdivision";
}

/// Sorts keys by time and refuses equal times, in O(n log n). Key files may list keys in any
/// order; the interpolators load sorted keys at the end of their arrays, which is the cheap end.
template <typename Key>
void SortByTime(std::vector<Key>& keys, const std::string& file)
{
  std::stable_sort(
    keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.Time < b.Time; });
  for (size_t i = 1; i < keys.size(); ++i)
  {
    if (keys[i].Time == keys[i - 1].Time)
    {
      throw InputError(file + ": " + keys[i].Path + ".time " + Num(keys[i].Time) + " repeats " +
        keys[i - 1].Path + ".time (key times must differ)");
    }
  }
}

/// A camera key's values before they become a vtkCamera (shared by the JSON and .pvcc readers).
struct CameraValues
{
  double Position[3] = { 0.0, 0.0, 1.0 };
  double FocalPoint[3] = { 0.0, 0.0, 0.0 };
  double ViewUp[3] = { 0.0, 1.0, 0.0 };
  double ViewAngle = 30.0;
  double ParallelScale = 1.0;
  bool Parallel = false;
  double WindowCenter[2] = { 0.0, 0.0 };
  double ViewShear[3] = { 0.0, 0.0, 1.0 };
  double ClippingRange[2] = { 0.01, 1000.01 };
};

/// The checks of a camera key beyond the ranges of single values, each naming the true cause;
/// `fail` receives the message (after `path`). Values are finite and in range here, so no
/// product below can overflow.
template <typename Fail>
vtkSmartPointer<vtkCamera> MakeCamera(CameraValues v, const std::string& path, Fail fail)
{
  double direction[3];
  vtkMath::Subtract(v.FocalPoint, v.Position, direction);
  const double distance = vtkMath::Norm(direction);
  // Relative to the coordinates (as vtkCameraInterpolatorLCT::AddCamera judges a key), and above
  // 1e-150, where vtkCamera's squared distances would underflow.
  const double scale = std::max(vtkMath::Norm(v.Position), vtkMath::Norm(v.FocalPoint));
  if (!(distance > 1e-12 * scale) || !(distance > 1e-150))
  {
    fail(path + " is degenerate: position and focal_point " +
      (distance == 0.0 ? std::string("are equal")
          : distance > 1e-12 * scale
          ? "are only " + Num(distance) + " apart, below 1e-150"
          : "are only " + Num(distance) + " apart, below 1e-12 of their magnitude"));
  }
  // The view-up direction matters, not its length: scale by its largest entry so that tiny
  // (even denormal) vectors are judged by their direction and vtkCamera gets a normal one.
  const double upMax =
    std::max({ std::fabs(v.ViewUp[0]), std::fabs(v.ViewUp[1]), std::fabs(v.ViewUp[2]) });
  if (upMax == 0.0)
  {
    fail(path + ".view_up is zero");
  }
  double up[3] = { v.ViewUp[0] / upMax, v.ViewUp[1] / upMax, v.ViewUp[2] / upMax };
  vtkMath::Normalize(up);
  double unit[3] = { direction[0] / distance, direction[1] / distance, direction[2] / distance };
  double cross[3];
  vtkMath::Cross(unit, up, cross);
  if (!(vtkMath::Norm(cross) > 1e-9))
  {
    fail(path + " is degenerate: view_up is parallel to the view direction");
  }
  if (!(v.ClippingRange[1] > v.ClippingRange[0]))
  {
    fail(path + ".clipping_range must be [near, far] with near < far");
  }
  auto c = vtkSmartPointer<vtkCamera>::New();
  c->SetPosition(v.Position);
  c->SetFocalPoint(v.FocalPoint);
  c->SetViewUp(up);
  c->SetViewAngle(v.ViewAngle);
  c->SetWindowCenter(v.WindowCenter[0], v.WindowCenter[1]);
  c->SetViewShear(v.ViewShear);
  c->SetParallelScale(v.ParallelScale);
  c->SetParallelProjection(v.Parallel ? 1 : 0);
  c->SetClippingRange(v.ClippingRange);
  return c;
}

/// Row-major matrix of translate * rotate * shear * scale (a point is scaled, sheared, rotated,
/// then translated). rotate = {angle in degrees, axis}; shear = {xy, xz, yz}: x += xy y + xz z,
/// y += yz z. The axis must not be zero.
inline std::array<double, 16> ComposeTRS(
  const double translate[3], const double rotate[4], const double scale[3], const double shear[3])
{
  // Scale the axis by its largest entry first: its norm could overflow (1e200) or underflow
  // (1e-200) and leave a matrix that is no rotation at all.
  const double axisMax =
    std::max({ std::fabs(rotate[1]), std::fabs(rotate[2]), std::fabs(rotate[3]) });
  double axis[3] = { 0.0, 0.0, 1.0 };
  if (axisMax > 0.0)
  {
    axis[0] = rotate[1] / axisMax;
    axis[1] = rotate[2] / axisMax;
    axis[2] = rotate[3] / axisMax;
  }
  const double n = vtkMath::Norm(axis);
  const double a = vtkMath::RadiansFromDegrees(std::fmod(rotate[0], 360.0));
  const double c = std::cos(a), s = std::sin(a), C = 1.0 - c;
  const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
  const double r[3][3] = { { c + x * x * C, x * y * C - z * s, x * z * C + y * s },
    { y * x * C + z * s, c + y * y * C, y * z * C - x * s },
    { z * x * C - y * s, z * y * C + x * s, c + z * z * C } };
  const double sh[3][3] = { { 1.0, shear[0], shear[1] }, { 0.0, 1.0, shear[2] },
    { 0.0, 0.0, 1.0 } };
  double rs[3][3];
  vtkMath::Multiply3x3(r, sh, rs);
  std::array<double, 16> m{};
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      m[4 * i + j] = rs[i][j] * scale[j];
    }
    m[4 * i + 3] = translate[i];
  }
  m[15] = 1.0;
  return m;
}

/// The built-in keys: CameraFlightScene's three cameras (a 130-degree turn, a window-centre
/// shift and a zoom) at t = 0, 1, 2, and the cone lifting off, tumbling 720 degrees (144 per key)
/// about a near-horizontal axis while it shears back and forth, and landing again, with
/// ConsistentRotation on.
inline Keys BuiltIn()
{
  Keys keys;
  for (int k = 0; k < 3; ++k)
  {
    CameraKey key;
    key.Time = k;
    key.Camera = vtkSmartPointer<vtkCamera>::New();
    CameraFlightScene::MakeKey(k, key.Camera);
    key.Path = "camera.keys[" + std::to_string(k) + "]";
    keys.Camera.push_back(key);
  }
  PropTrack cone;
  cone.ConsistentRotation = true;
  const double lift[6] = { 0.0, 0.75, 0.8, 0.8, 0.75, 0.0 };
  const double lean[6] = { 0.0, 0.4, 0.0, -0.4, 0.4, 0.0 };
  for (int k = 0; k < 6; ++k)
  {
    const double t[3] = { 0.0, lift[k], 0.0 };
    const double r[4] = { 144.0 * k, 0.3, 0.0, 1.0 };
    const double s[3] = { 1.0, 1.0, 1.0 };
    const double h[3] = { lean[k], 0.0, 0.0 };
    PropKey key;
    key.Time = 0.4 * k;
    key.Matrix = ComposeTRS(t, r, s, h);
    key.Path = "props.cone.keys[" + std::to_string(k) + "]";
    cone.Keys.push_back(key);
  }
  keys.Props["cone"] = cone;
  return keys;
}

// ---------------------------------------------------------------------------------------------
// JSON

/// nlohmann's DOM builder, but a parse error (including a number that overflows a double, e.g.
/// 1e400, which nlohmann reports as out_of_range 406) keeps the byte offset it happened at and
/// the place in the document (`scene.objects.ball.color[0]`), so that a message names the field
/// as well as the line and column. The base class's methods are not virtual: sax_parse calls
/// these through the static type, and each forwards to the base after noting where it is.
struct JsonBuilder : nlohmann::detail::json_sax_dom_parser<nlohmann::json>
{
  using Base = nlohmann::detail::json_sax_dom_parser<nlohmann::json>;
  using Base::Base;
  size_t ErrorOffset = 0;
  std::string ErrorMessage;
  std::string ErrorPath; // where the error happened; "" at the top level

  bool null() { return this->Value() && Base::null(); }
  bool boolean(bool v) { return this->Value() && Base::boolean(v); }
  bool number_integer(number_integer_t v) { return this->Value() && Base::number_integer(v); }
  bool number_unsigned(number_unsigned_t v) { return this->Value() && Base::number_unsigned(v); }
  bool number_float(number_float_t v, const string_t& s)
  {
    return this->Value() && Base::number_float(v, s);
  }
  bool string(string_t& v) { return this->Value() && Base::string(v); }
  bool binary(binary_t& v) { return this->Value() && Base::binary(v); }
  bool start_object(std::size_t n)
  {
    this->Value();
    this->Levels.push_back({ false, "", 0, {} });
    return Base::start_object(n);
  }
  bool key(string_t& k)
  {
    Level& level = this->Levels.back();
    level.Key = k;
    // JSON leaves repeated keys to the reader, and nlohmann's DOM keeps the last: a second
    // "camera" section or "position" would replace the first without a word, as a misspelt key
    // would be ignored (refused by CheckKeys). The first repeat is noted and refused after the
    // parse, at its path.
    if (!level.Seen.insert(k).second && this->Duplicate.empty())
    {
      this->Duplicate = this->Path();
    }
    return Base::key(k);
  }
  bool end_object()
  {
    this->Levels.pop_back();
    return Base::end_object();
  }
  bool start_array(std::size_t n)
  {
    this->Value();
    this->Levels.push_back({ true, "", 0, {} });
    return Base::start_array(n);
  }
  bool end_array()
  {
    this->Levels.pop_back();
    return Base::end_array();
  }

  std::string Duplicate; // the path of the first key repeated in its object; "" if none

  template <class Exception>
  bool parse_error(size_t offset, const std::string&, const Exception& ex)
  {
    this->ErrorOffset = offset;
    this->ErrorMessage = ex.what();
    this->ErrorPath = this->Path();
    return false;
  }

private:
  struct Level
  {
    bool Array;
    std::string Key;            // objects: the last key read
    size_t Count;               // arrays: the elements started
    std::set<std::string> Seen; // objects: the keys read
  };
  std::vector<Level> Levels;

  /// Where the parse is: `scene.objects.ball.color[0]`.
  std::string Path() const
  {
    std::string path;
    for (size_t i = 0; i < this->Levels.size(); ++i)
    {
      const Level& l = this->Levels[i];
      const bool innermost = i + 1 == this->Levels.size();
      if (l.Array)
      {
        // The element being read: the next one in the innermost array, the open one above it.
        const size_t index = innermost ? l.Count : (l.Count > 0 ? l.Count - 1 : 0);
        path += "[" + std::to_string(index) + "]";
      }
      else if (!l.Key.empty())
      {
        path += (path.empty() ? "" : ".") + Printable(l.Key);
      }
    }
    return path;
  }

  /// Counts a value (or a nested object or array) started in the enclosing array.
  bool Value()
  {
    if (!this->Levels.empty() && this->Levels.back().Array)
    {
      ++this->Levels.back().Count;
    }
    return true;
  }
};

class Parser
{
public:
  explicit Parser(std::string file)
    : File(std::move(file))
  {
  }

  [[noreturn]] void Fail(const std::string& what) const
  {
    throw InputError(this->File + ": " + what);
  }

  /// Refuses a key that is not in `known`: a misspelt field ("colour", "visble") would
  /// otherwise be ignored and the user would see the default without knowing why. Suggests the
  /// known key nearest in edit distance when it is close.
  void CheckKeys(
    const nlohmann::json& object, const std::string& path, const std::set<std::string>& known) const
  {
    for (auto it = object.begin(); it != object.end(); ++it)
    {
      if (known.count(it.key()))
      {
        continue;
      }
      std::string nearest;
      size_t best = 3; // at most 2 edits away
      for (const auto& k : known)
      {
        const size_t d = EditDistance(it.key(), k);
        if (d < best)
        {
          best = d;
          nearest = k;
        }
      }
      this->Fail((path.empty() ? "" : path + ".") + Printable(it.key()) + ": unknown key" +
        (nearest.empty() ? "" : " (did you mean \"" + nearest + "\"?)") + "; " +
        (path.empty() ? "the top level" : path) + " takes " + OneOf(known));
    }
  }

  static size_t EditDistance(const std::string& a, const std::string& b)
  {
    if (a.size() > 64 || b.size() > 64)
    {
      return 64;
    }
    std::vector<size_t> row(b.size() + 1);
    std::iota(row.begin(), row.end(), size_t(0));
    for (size_t i = 1; i <= a.size(); ++i)
    {
      size_t diagonal = row[0];
      row[0] = i;
      for (size_t j = 1; j <= b.size(); ++j)
      {
        const size_t up = row[j];
        row[j] = std::min({ row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] != b[j - 1]) });
        diagonal = up;
      }
    }
    return row[b.size()];
  }

  const nlohmann::json& Object(
    const nlohmann::json& parent, const char* key, const std::string& path) const
  {
    const std::string p = path.empty() ? key : path + "." + key;
    if (!parent.contains(key))
    {
      this->Fail(p + " is missing");
    }
    const nlohmann::json& v = parent.at(key);
    if (!v.is_object())
    {
      this->Fail(p + " must be an object");
    }
    return v;
  }

  /// A finite number within [lo, hi] (the parser already refuses overflow, NaN and Inf are no
  /// JSON; the range is what each field can meaningfully hold).
  double Number(const nlohmann::json& v, const std::string& path, double lo, double hi) const
  {
    if (!v.is_number())
    {
      this->Fail(path + " must be a number");
    }
    const double d = v.get<double>();
    if (!std::isfinite(d))
    {
      this->Fail(path + " must be finite");
    }
    if (!(d >= lo && d <= hi))
    {
      this->Fail(
        path + " = " + Num(d) + " is out of range: must be in [" + Num(lo) + ", " + Num(hi) + "]");
    }
    return d;
  }

  /// Reads key as an array of n numbers in [lo, hi] into out; returns false when absent.
  bool Vector(const nlohmann::json& object, const char* key, const std::string& path, size_t n,
    double* out, double lo, double hi) const
  {
    if (!object.contains(key))
    {
      return false;
    }
    const std::string p = path + "." + key;
    const nlohmann::json& v = object.at(key);
    if (!v.is_array() || v.size() != n)
    {
      this->Fail(p + " must be an array of " + std::to_string(n) + " numbers");
    }
    for (size_t i = 0; i < n; ++i)
    {
      out[i] = this->Number(v[i], p + "[" + std::to_string(i) + "]", lo, hi);
    }
    return true;
  }

  double Time(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.contains("time"))
    {
      this->Fail(path + ".time is missing");
    }
    return this->Number(key.at("time"), path + ".time", -Limits::MaxTime, Limits::MaxTime);
  }

  std::string Interpolation(const nlohmann::json& object, const std::string& path) const
  {
    const nlohmann::json& v = object.at("interpolation");
    if (!v.is_string())
    {
      this->Fail(path + ".interpolation must be a string");
    }
    const std::string name = v.get<std::string>();
    if (!IsInterpolationName(name))
    {
      this->Fail(path + ".interpolation: unknown interpolation \"" + Printable(name) +
        "\" (expected linear, spline, bspline or subdivision)");
    }
    return name;
  }

  bool Bool(const nlohmann::json& v, const std::string& path) const
  {
    if (!v.is_boolean())
    {
      this->Fail(path + " must be true or false");
    }
    return v.get<bool>();
  }

  const nlohmann::json& KeyArray(
    const nlohmann::json& object, const std::string& path, size_t limit) const
  {
    if (!object.contains("keys") || !object.at("keys").is_array())
    {
      this->Fail(path + ".keys must be an array of keys");
    }
    const nlohmann::json& keys = object.at("keys");
    if (keys.size() > limit)
    {
      this->Fail(path + ".keys has " + std::to_string(keys.size()) + " keys; at most " +
        std::to_string(limit) + " are accepted");
    }
    return keys;
  }

  /// A key's timing fields (tension, continuity, bias in [-1, 1]; ease_in, ease_out in [0, 1]).
  KeyTiming ReadKeyTiming(const nlohmann::json& key, const std::string& path) const
  {
    KeyTiming out;
    double* tcb[3] = { &out.Tension, &out.Continuity, &out.Bias };
    const char* names[3] = { "tension", "continuity", "bias" };
    for (int i = 0; i < 3; ++i)
    {
      if (key.contains(names[i]))
      {
        *tcb[i] = this->Number(key.at(names[i]), path + "." + names[i], -1.0, 1.0);
        out.HasTensionContinuityBias = true;
      }
    }
    if (key.contains("ease_in"))
    {
      out.EaseIn = this->Number(key.at("ease_in"), path + ".ease_in", 0.0, 1.0);
      out.HasEase = true;
    }
    if (key.contains("ease_out"))
    {
      out.EaseOut = this->Number(key.at("ease_out"), path + ".ease_out", 0.0, 1.0);
      out.HasEase = true;
    }
    return out;
  }

  /// The timing fields of a path (`object` is the camera or a prop); `camera` selects
  /// constant_speed_measure (the camera) or constant_speed_point (a prop).
  PathTiming ReadPathTiming(
    const nlohmann::json& object, const std::string& path, bool camera) const
  {
    PathTiming out;
    const std::pair<const char*, double*> tcb[3] = { { "tension", &out.Tension },
      { "continuity", &out.Continuity }, { "bias", &out.Bias } };
    for (const auto& [name, value] : tcb)
    {
      if (object.contains(name))
      {
        *value = this->Number(object.at(name), path + "." + name, -1.0, 1.0);
      }
    }
    if (object.contains("tangents"))
    {
      out.Tangents = this->Choice(object, "tangents", path, TangentNames());
    }
    if (object.contains("ease_in"))
    {
      out.EaseIn = this->Number(object.at("ease_in"), path + ".ease_in", 0.0, 1.0);
    }
    if (object.contains("ease_out"))
    {
      out.EaseOut = this->Number(object.at("ease_out"), path + ".ease_out", 0.0, 1.0);
    }
    if (object.contains("constant_speed"))
    {
      out.ConstantSpeed = this->Bool(object.at("constant_speed"), path + ".constant_speed");
    }
    if (camera && object.contains("constant_speed_measure"))
    {
      out.ConstantSpeedMeasure =
        this->Choice(object, "constant_speed_measure", path, ConstantSpeedMeasures());
    }
    if (!camera)
    {
      const double X = Limits::MaxCoordinate;
      this->Vector(object, "constant_speed_point", path, 3, out.ConstantSpeedPoint, -X, X);
    }
    return out;
  }

  CameraKey ReadCameraKey(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.is_object())
    {
      this->Fail(path + " must be an object");
    }
    this->CheckKeys(key, path,
      { "time", "position", "focal_point", "view_up", "view_angle", "window_center", "view_shear",
        "parallel_scale", "parallel", "clipping_range", "tension", "continuity", "bias", "ease_in",
        "ease_out" });
    CameraKey out;
    out.Path = path;
    out.Time = this->Time(key, path);
    out.Timing = this->ReadKeyTiming(key, path);
    CameraValues v;
    const double X = Limits::MaxCoordinate;
    if (!this->Vector(key, "position", path, 3, v.Position, -X, X))
    {
      this->Fail(path + ".position is missing");
    }
    if (!this->Vector(key, "focal_point", path, 3, v.FocalPoint, -X, X))
    {
      this->Fail(path + ".focal_point is missing");
    }
    this->Vector(key, "view_up", path, 3, v.ViewUp, -X, X);
    this->Vector(
      key, "window_center", path, 2, v.WindowCenter, -Limits::MaxOffset, Limits::MaxOffset);
    this->Vector(key, "view_shear", path, 3, v.ViewShear, -Limits::MaxOffset, Limits::MaxOffset);
    out.ClippingRange = this->Vector(
      key, "clipping_range", path, 2, v.ClippingRange, Limits::MinLength, Limits::MaxLength);
    if (key.contains("view_angle"))
    {
      v.ViewAngle = this->Number(
        key.at("view_angle"), path + ".view_angle", Limits::MinViewAngle, Limits::MaxViewAngle);
    }
    if (key.contains("parallel_scale"))
    {
      v.ParallelScale = this->Number(
        key.at("parallel_scale"), path + ".parallel_scale", Limits::MinLength, Limits::MaxLength);
    }
    if (key.contains("parallel"))
    {
      v.Parallel = this->Bool(key.at("parallel"), path + ".parallel");
    }
    out.Camera = MakeCamera(v, path, [this](const std::string& m) { this->Fail(m); });
    return out;
  }

  PropKey ReadPropKey(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.is_object())
    {
      this->Fail(path + " must be an object");
    }
    this->CheckKeys(key, path,
      { "time", "matrix", "translate", "rotate", "scale", "shear", "tension", "continuity", "bias",
        "ease_in", "ease_out" });
    PropKey out;
    out.Path = path;
    out.Time = this->Time(key, path);
    out.Timing = this->ReadKeyTiming(key, path);
    const double X = Limits::MaxCoordinate;
    if (key.contains("matrix"))
    {
      for (const char* other : { "translate", "rotate", "scale", "shear" })
      {
        if (key.contains(other))
        {
          this->Fail(path + " has both matrix and " + other + " (give one or the other)");
        }
      }
      this->Vector(key, "matrix", path, 16, out.Matrix.data(), -X, X);
      if (out.Matrix[12] != 0.0 || out.Matrix[13] != 0.0 || out.Matrix[14] != 0.0 ||
        out.Matrix[15] != 1.0)
      {
        this->Fail(path + ".matrix must be affine: its last row must be [0, 0, 0, 1]");
      }
    }
    else
    {
      double t[3] = { 0.0, 0.0, 0.0 }, r[4] = { 0.0, 0.0, 0.0, 1.0 }, s[3] = { 1.0, 1.0, 1.0 },
             h[3] = { 0.0, 0.0, 0.0 };
      this->Vector(key, "translate", path, 3, t, -X, X);
      if (this->Vector(key, "rotate", path, 4, r, -X, X))
      {
        if (!(std::fabs(r[0]) <= Limits::MaxAngle))
        {
          this->Fail(path + ".rotate[0] = " + Num(r[0]) +
            " is out of range: the angle must be in [" + Num(-Limits::MaxAngle) + ", " +
            Num(Limits::MaxAngle) + "] degrees");
        }
        if (r[1] == 0.0 && r[2] == 0.0 && r[3] == 0.0)
        {
          this->Fail(path + ".rotate: the axis [ax, ay, az] must not be zero");
        }
      }
      this->Vector(key, "scale", path, 3, s, -Limits::MaxScale, Limits::MaxScale);
      for (int i = 0; i < 3; ++i)
      {
        if (!(s[i] >= Limits::MinScale))
        {
          // What the factor is, then the range: 0 is singular (not a mirror), < 0 a mirror.
          const std::string what = s[i] == 0.0
            ? "a zero scale is singular (it flattens the object) and has no logarithm; to grow "
              "an object from nothing, start from a tiny positive scale such as 1e-6"
            : s[i] < 0.0 ? "a negative scale is a mirror, which has no rotation logarithm"
                         : "too small for a usable logarithm";
          this->Fail(path + ".scale[" + std::to_string(i) + "] = " + Num(s[i]) + ": " + what +
            "; scale factors must be in [" + Num(Limits::MinScale) + ", " + Num(Limits::MaxScale) +
            "]");
        }
      }
      this->Vector(key, "shear", path, 3, h, -Limits::MaxOffset, Limits::MaxOffset);
      out.Matrix = ComposeTRS(t, r, s, h);
    }
    return out;
  }

  /// Refuses nesting deeper than MaxJsonDepth before nlohmann builds (and later destroys) it.
  void CheckDepth(const std::string& text) const
  {
    int depth = 0;
    bool inString = false;
    for (size_t i = 0; i < text.size(); ++i)
    {
      const char c = text[i];
      if (inString)
      {
        if (c == '\\')
        {
          ++i;
        }
        else if (c == '"')
        {
          inString = false;
        }
      }
      else if (c == '"')
      {
        inString = true;
      }
      else if (c == '[' || c == '{')
      {
        if (++depth > Limits::MaxJsonDepth)
        {
          throw InputError(this->File + ":" + LineColumn(text, i) + ": JSON nested deeper than " +
            std::to_string(Limits::MaxJsonDepth) + " levels");
        }
      }
      else if (c == ']' || c == '}')
      {
        --depth;
      }
    }
  }

  nlohmann::json Parse(const std::string& text) const
  {
    this->CheckDepth(text);
    nlohmann::json doc;
    JsonBuilder builder(doc, true);
    bool ok = false;
    try
    {
      ok = nlohmann::json::sax_parse(text, &builder);
    }
    catch (const nlohmann::json::exception& e)
    {
      // Not reported through parse_error (nlohmann throws some errors directly).
      this->Fail(std::string("JSON error: ") + e.what());
    }
    if (!ok)
    {
      // The offset is one past the last byte read.
      std::string what = builder.ErrorMessage;
      const size_t bracket = what.find("] ");
      if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      {
        what = what.substr(bracket + 2);
      }
      // JSON has no NaN or Infinity; a value that starts like one is the common cause.
      const size_t at = builder.ErrorOffset > 0 ? builder.ErrorOffset - 1 : 0;
      const size_t word = text.find_last_of(" \t\r\n[,:", at);
      const std::string token =
        text.substr(word == std::string::npos ? 0 : word + 1, 9); // "-Infinity"
      const bool nanLike = token.rfind("NaN", 0) == 0 || token.rfind("nan", 0) == 0 ||
        token.rfind("Inf", 0) == 0 || token.rfind("inf", 0) == 0 || token.rfind("-Inf", 0) == 0 ||
        token.rfind("-inf", 0) == 0;
      throw InputError(this->File + ":" + LineColumn(text, at) + ": JSON parse error: " + what +
        (builder.ErrorPath.empty() ? "" : " (at " + builder.ErrorPath + ")") +
        (nanLike ? " (JSON has no NaN or Infinity: every value must be a finite number)" : ""));
    }
    if (!builder.Duplicate.empty())
    {
      this->Fail(builder.Duplicate +
        ": appears twice in its object (JSON keeps only the last, so the first would be dropped "
        "without a word); give each key once");
    }
    return doc;
  }

  Keys Read(const std::string& text) const
  {
    const nlohmann::json doc = this->Parse(text);
    try
    {
      return this->Read(doc);
    }
    catch (const nlohmann::json::exception& e)
    {
      // Every access above is checked first; this is the net under them.
      this->Fail(std::string("unexpected JSON content: ") + e.what());
    }
  }

  Keys Read(const nlohmann::json& doc) const
  {
    if (!doc.is_object())
    {
      this->Fail("the top level must be an object with \"camera\" (and optionally \"props\" "
                 "and \"scene\")");
    }
    this->CheckKeys(doc, "", { "camera", "props", "scene" });
    Keys keys;
    keys.Source = this->File;
    if (doc.contains("camera") || !this->CameraOptional)
    {
      this->ReadCamera(this->Object(doc, "camera", ""), keys);
    }
    if (doc.contains("props"))
    {
      const nlohmann::json& props = this->Object(doc, "props", "");
      for (auto it = props.begin(); it != props.end(); ++it)
      {
        const std::string path = "props." + Printable(it.key());
        if (!it.value().is_object())
        {
          this->Fail(path + " must be an object");
        }
        this->CheckKeys(it.value(), path,
          { "keys", "interpolation", "consistent_rotation", "tension", "continuity", "bias",
            "tangents", "ease_in", "ease_out", "constant_speed", "constant_speed_point" });
        PropTrack track;
        track.Timing = this->ReadPathTiming(it.value(), path, false);
        if (it.value().contains("interpolation"))
        {
          track.Interpolation = this->Interpolation(it.value(), path);
        }
        if (it.value().contains("consistent_rotation"))
        {
          track.ConsistentRotation =
            this->Bool(it.value().at("consistent_rotation"), path + ".consistent_rotation");
        }
        const nlohmann::json& propKeys = this->KeyArray(it.value(), path, Limits::MaxKeys);
        if (propKeys.empty())
        {
          this->Fail(path + ".keys must be a non-empty array of keys");
        }
        for (size_t i = 0; i < propKeys.size(); ++i)
        {
          track.Keys.push_back(
            this->ReadPropKey(propKeys[i], path + ".keys[" + std::to_string(i) + "]"));
        }
        SortByTime(track.Keys, this->File);
        keys.Props[it.key()] = track;
      }
    }
    if (doc.contains("scene"))
    {
      this->ReadScene(this->Object(doc, "scene", ""), keys.View);
    }
    return keys;
  }

  /// Set by lct-render when camera keys come from ParaView files: the keys file may then hold
  /// only a scene and props.
  void SetCameraOptional(bool optional) { this->CameraOptional = optional; }

private:
  void ReadCamera(const nlohmann::json& camera, Keys& keys) const
  {
    this->CheckKeys(camera, "camera",
      { "interpolation", "keys", "consistent_rotation", "tension", "continuity", "bias", "tangents",
        "ease_in", "ease_out", "constant_speed", "constant_speed_measure" });
    keys.CameraTiming = this->ReadPathTiming(camera, "camera", true);
    if (camera.contains("interpolation"))
    {
      keys.Interpolation = this->Interpolation(camera, "camera");
    }
    if (camera.contains("consistent_rotation"))
    {
      keys.ConsistentRotation =
        this->Bool(camera.at("consistent_rotation"), "camera.consistent_rotation");
    }
    const nlohmann::json& cameraKeys = this->KeyArray(camera, "camera", Limits::MaxKeys);
    for (size_t i = 0; i < cameraKeys.size(); ++i)
    {
      CameraKey key = this->ReadCameraKey(cameraKeys[i], "camera.keys[" + std::to_string(i) + "]");
      if (!keys.Camera.empty() &&
        keys.Camera.front().Camera->GetParallelProjection() != key.Camera->GetParallelProjection())
      {
        this->Fail(key.Path +
          ".parallel differs from camera.keys[0].parallel (all keys must "
          "use the same projection)");
      }
      // Interpolated clipping ranges between keys that have one and keys that are refitted
      // each frame would jump: all or none.
      if (!keys.Camera.empty() && keys.Camera.front().ClippingRange != key.ClippingRange)
      {
        const CameraKey& with = key.ClippingRange ? key : keys.Camera.front();
        const CameraKey& without = key.ClippingRange ? keys.Camera.front() : key;
        this->Fail(without.Path + " has no clipping_range but " + with.Path +
          " has one: give it on every camera key (interpolated) or on none (reset from the "
          "scene's bounds at every frame)");
      }
      keys.Camera.push_back(key);
    }
    if (keys.Camera.size() < 2)
    {
      this->Fail("camera.keys: needs at least 2 keys, found " + std::to_string(keys.Camera.size()));
    }
    SortByTime(keys.Camera, this->File);
  }

  /// A colour: [r, g, b] in [0, 1].
  void Color(
    const nlohmann::json& object, const char* key, const std::string& path, double* out) const
  {
    this->Vector(object, key, path, 3, out, 0.0, 1.0);
  }

  std::string Choice(const nlohmann::json& object, const char* key, const std::string& path,
    const std::vector<std::string>& names) const
  {
    const std::string p = path + "." + key;
    const nlohmann::json& v = object.at(key);
    if (!v.is_string())
    {
      this->Fail(p + " must be a string: " + OneOf(names));
    }
    const std::string name = v.get<std::string>();
    if (std::find(names.begin(), names.end(), name) == names.end())
    {
      this->Fail(p + ": unknown value \"" + Printable(name) + "\" (expected " + OneOf(names) + ")");
    }
    return name;
  }

  void ReadScene(const nlohmann::json& scene, Scene& out) const
  {
    out.Given = true;
    this->CheckKeys(scene, "scene",
      { "objects", "background", "background_top", "lights", "size", "anti_aliasing" });
    this->Color(scene, "background", "scene", out.Background);
    out.Gradient = scene.contains("background_top");
    this->Color(scene, "background_top", "scene", out.BackgroundTop);
    if (scene.contains("size"))
    {
      double size[2];
      this->Vector(scene, "size", "scene", 2, size, Limits::MinSide, Limits::MaxSide);
      if (size[0] != std::floor(size[0]) || size[1] != std::floor(size[1]))
      {
        this->Fail("scene.size must be two whole numbers [width, height]");
      }
      if (size[0] * size[1] > static_cast<double>(Limits::MaxPixels))
      {
        this->Fail("scene.size " + Num(size[0]) + "x" + Num(size[1]) + " has more than " +
          std::to_string(Limits::MaxPixels) + " pixels");
      }
      out.Width = static_cast<int>(size[0]);
      out.Height = static_cast<int>(size[1]);
    }
    if (scene.contains("anti_aliasing"))
    {
      out.AntiAliasing = this->Choice(scene, "anti_aliasing", "scene", { "msaa", "fxaa", "none" });
    }
    if (scene.contains("lights"))
    {
      const nlohmann::json& lights = scene.at("lights");
      if (lights.is_string())
      {
        out.Lights = this->Choice(scene, "lights", "scene", { "kit", "headlight" });
      }
      else if (lights.is_array() && !lights.empty() && lights.size() <= Limits::MaxLights)
      {
        out.Lights = "list";
        for (size_t i = 0; i < lights.size(); ++i)
        {
          out.LightList.push_back(
            this->ReadLight(lights[i], "scene.lights[" + std::to_string(i) + "]"));
        }
      }
      else
      {
        this->Fail("scene.lights must be \"kit\", \"headlight\" or an array of 1 to " +
          std::to_string(Limits::MaxLights) + " lights");
      }
    }
    if (!scene.contains("objects"))
    {
      this->Fail("scene.objects is missing (an object of NAME: {\"file\": ...} or "
                 "{\"source\": ...} entries)");
    }
    const nlohmann::json& objects = this->Object(scene, "objects", "scene");
    if (objects.empty() || objects.size() > Limits::MaxObjects)
    {
      this->Fail("scene.objects must hold 1 to " + std::to_string(Limits::MaxObjects) +
        " objects, found " + std::to_string(objects.size()));
    }
    for (auto it = objects.begin(); it != objects.end(); ++it)
    {
      out.Objects.push_back(this->ReadObject(it.key(), it.value()));
    }
  }

  SceneLight ReadLight(const nlohmann::json& light, const std::string& path) const
  {
    if (!light.is_object())
    {
      this->Fail(path + " must be an object");
    }
    this->CheckKeys(light, path, { "position", "focal_point", "color", "intensity", "camera" });
    SceneLight out;
    const double X = Limits::MaxCoordinate;
    if (!this->Vector(light, "position", path, 3, out.Position, -X, X))
    {
      this->Fail(path + ".position is missing");
    }
    this->Vector(light, "focal_point", path, 3, out.FocalPoint, -X, X);
    this->Color(light, "color", path, out.Color);
    if (light.contains("intensity"))
    {
      out.Intensity = this->Number(light.at("intensity"), path + ".intensity", 0.0, 100.0);
    }
    if (light.contains("camera"))
    {
      out.Camera = this->Bool(light.at("camera"), path + ".camera");
    }
    return out;
  }

  SceneObject ReadObject(const std::string& name, const nlohmann::json& object) const
  {
    SceneObject out;
    out.Name = name;
    out.Path = "scene.objects." + Printable(name);
    const std::string& path = out.Path;
    if (name.empty() || Printable(name) != name)
    {
      this->Fail(path + ": an object name must be 1 to 80 printable ASCII characters");
    }
    if (!object.is_object())
    {
      this->Fail(path + " must be an object with \"file\" or \"source\"");
    }
    if (object.contains("file") == object.contains("source"))
    {
      this->Fail(path + " needs exactly one of \"file\" (a mesh) and \"source\" (" +
        OneOf(SourceNames()) + ")");
    }
    std::set<std::string> known = { "color", "opacity", "representation", "visible", "color_by",
      "color_map", "scalar_range", "line_width", "point_size" };
    if (object.contains("file"))
    {
      known.insert("file");
      const nlohmann::json& file = object.at("file");
      if (!file.is_string() || file.get<std::string>().empty())
      {
        this->Fail(path + ".file must be a file name");
      }
      out.File = file.get<std::string>();
      const std::filesystem::path f(out.File);
      if (f.is_relative())
      {
        // Relative to the keys file, so that a scene and its meshes move together.
        out.File = (std::filesystem::path(this->File).parent_path() / f).string();
      }
    }
    else
    {
      out.Source = this->Choice(object, "source", path, SourceNames());
      known.insert("source");
      const std::map<std::string, std::set<std::string>> parameters = {
        { "sphere", { "center", "radius", "resolution" } },
        { "cube", { "center", "size" } },
        { "cone", { "center", "radius", "height", "direction", "resolution" } },
        { "plane", { "center", "size", "normal" } },
        { "axes", { "center", "length" } },
      };
      for (auto it = object.begin(); it != object.end(); ++it)
      {
        for (const auto& [source, names] : parameters)
        {
          if (source != out.Source && names.count(it.key()) &&
            !parameters.at(out.Source).count(it.key()))
          {
            this->Fail(path + "." + it.key() + ": not a parameter of a " + out.Source + " (a " +
              out.Source + " takes " + OneOf(parameters.at(out.Source)) + ")");
          }
        }
      }
      known.insert(parameters.at(out.Source).begin(), parameters.at(out.Source).end());
      const double X = Limits::MaxCoordinate, L = Limits::MaxLength, l = Limits::MinLength;
      this->Vector(object, "center", path, 3, out.Center, -X, X);
      if (object.contains("radius"))
      {
        out.Radius = this->Number(object.at("radius"), path + ".radius", l, L);
      }
      if (object.contains("height"))
      {
        out.Height = this->Number(object.at("height"), path + ".height", l, L);
      }
      if (object.contains("length"))
      {
        out.Length = this->Number(object.at("length"), path + ".length", l, L);
      }
      if (out.Source == "plane")
      {
        if (object.contains("size"))
        {
          this->Vector(object, "size", path, 2, out.Size, l, L);
        }
      }
      else
      {
        this->Vector(object, "size", path, 3, out.Size, l, L);
      }
      if (out.Source == "cone")
      {
        out.Direction[0] = 0.0; // a cone points up (+y) unless told otherwise
        out.Direction[1] = 1.0;
        out.Direction[2] = 0.0;
      }
      for (const char* axis : { "direction", "normal" })
      {
        if (this->Vector(object, axis, path, 3, out.Direction, -X, X) && out.Direction[0] == 0.0 &&
          out.Direction[1] == 0.0 && out.Direction[2] == 0.0)
        {
          this->Fail(path + "." + axis + " must not be zero");
        }
      }
      if (object.contains("resolution"))
      {
        const double r = this->Number(object.at("resolution"), path + ".resolution",
          Limits::MinResolution, Limits::MaxResolution);
        if (r != std::floor(r))
        {
          this->Fail(path + ".resolution must be a whole number");
        }
        out.Resolution = static_cast<int>(r);
      }
    }
    this->CheckKeys(object, path, known);
    Appearance& look = out.Look;
    look.HasColor = this->Vector(object, "color", path, 3, look.Color, 0.0, 1.0);
    if (object.contains("opacity"))
    {
      look.Opacity = this->Number(object.at("opacity"), path + ".opacity", 0.0, 1.0);
    }
    if (object.contains("representation"))
    {
      look.Representation =
        this->Choice(object, "representation", path, { "surface", "wireframe", "points" });
    }
    if (object.contains("visible"))
    {
      look.Visible = this->Bool(object.at("visible"), path + ".visible");
    }
    if (object.contains("color_by"))
    {
      const nlohmann::json& v = object.at("color_by");
      if (!v.is_string() || v.get<std::string>().empty())
      {
        this->Fail(path + ".color_by must be the name of a point or cell array");
      }
      look.ColorBy = v.get<std::string>();
    }
    for (const char* needsArray : { "color_map", "scalar_range" })
    {
      if (object.contains(needsArray) && look.ColorBy.empty())
      {
        this->Fail(path + "." + needsArray + " needs color_by (the array to colour by)");
      }
    }
    if (object.contains("color_map"))
    {
      std::vector<std::string> names;
      for (const auto& m : ColorMaps())
      {
        names.push_back(m.first);
      }
      look.ColorMap = this->Choice(object, "color_map", path, names);
    }
    if (object.contains("scalar_range"))
    {
      look.HasScalarRange = true;
      this->Vector(object, "scalar_range", path, 2, look.ScalarRange, -DBL_MAX, DBL_MAX);
      if (!(look.ScalarRange[0] < look.ScalarRange[1]))
      {
        this->Fail(path + ".scalar_range must be [low, high] with low < high");
      }
    }
    if (object.contains("line_width"))
    {
      look.LineWidth =
        this->Number(object.at("line_width"), path + ".line_width", 0.1, Limits::MaxPixelSize);
    }
    if (object.contains("point_size"))
    {
      look.PointSize =
        this->Number(object.at("point_size"), path + ".point_size", 0.1, Limits::MaxPixelSize);
    }
    return out;
  }

public:
  static const std::vector<std::string>& SourceNames()
  {
    static const std::vector<std::string> names = { "sphere", "cube", "cone", "plane", "axes" };
    return names;
  }

private:
  std::string File;
  bool CameraOptional = false;
};

/// `text` as a finite number in [lo, hi], all of it (strtod alone would take "12abc" as 12 and
/// "nan" as NaN; VTK's GetScalarAttribute takes "abc" as 0).
inline bool ParseNumber(const char* text, double lo, double hi, double& out)
{
  if (!text)
  {
    return false;
  }
  const char* begin = text;
  while (*begin == ' ' || *begin == '\t' || *begin == '\n' || *begin == '\r')
  {
    ++begin;
  }
  // Only decimal notation: strtod would also take hex floats, "inf" and "nan".
  for (const char* p = begin; *p; ++p)
  {
    if (!std::strchr("0123456789+-.eE \t\r\n", *p))
    {
      return false;
    }
  }
  char* end = nullptr;
  // An underflow (ERANGE with a denormal or zero) is taken at its value; an overflow is not
  // finite and fails below.
  const double v = std::strtod(begin, &end);
  if (end == begin)
  {
    return false;
  }
  while (*end == ' ' || *end == '\t' || *end == '\n' || *end == '\r')
  {
    ++end;
  }
  if (*end != '\0' || !std::isfinite(v) || !(v >= lo && v <= hi))
  {
    return false;
  }
  out = v;
  return true;
}

// ---------------------------------------------------------------------------------------------
// ParaView XML: camera files (.pvcc) and state files (.pvsm), read with VTK's XML parser.

/// What lct-render reads, for the message about any other file.
constexpr const char* AcceptedInputs =
  "lct-render reads a JSON keys file, ParaView camera files (.pvcc, <PVCameraConfiguration>) "
  "and ParaView state files (.pvsm, <ParaView><ServerManagerState>) with a camera track";

/// `text` parsed by vtkXMLDataParser (kept alive with its elements), or null when it is not
/// well-formed XML. Refuses nesting deeper than MaxXmlDepth first: vtkXMLDataElement frees its
/// children recursively, so depth must be bounded before the parser builds the tree.
inline vtkSmartPointer<vtkXMLDataParser> ParseXml(const std::string& file, const std::string& text)
{
  int depth = 0;
  char quote = 0;
  bool inTag = false;
  for (size_t i = 0; i < text.size(); ++i)
  {
    const char c = text[i];
    if (quote)
    {
      quote = c == quote ? 0 : quote;
    }
    else if (inTag && (c == '"' || c == '\''))
    {
      quote = c;
    }
    else if (c == '<')
    {
      const char next = i + 1 < text.size() ? text[i + 1] : '\0';
      inTag = true;
      if (next == '/')
      {
        --depth;
      }
      else if (next != '?' && next != '!' && ++depth > Limits::MaxXmlDepth)
      {
        throw InputError(file + ":" + LineColumn(text, i) + ": XML nested deeper than " +
          std::to_string(Limits::MaxXmlDepth) + " levels");
      }
    }
    else if (c == '>')
    {
      if (inTag && i > 0 && text[i - 1] == '/')
      {
        --depth;
      }
      inTag = false;
    }
  }
  auto parser = vtkSmartPointer<vtkXMLDataParser>::New();
  parser->SetIgnoreCharacterData(1);
  // The parser reports malformed XML through vtkErrorMacro; the callers' messages say it better,
  // and an observer keeps VTK from printing it.
  vtkNew<vtkCallbackCommand> quiet;
  parser->AddObserver(vtkCommand::ErrorEvent, quiet);
  parser->AddObserver(vtkCommand::WarningEvent, quiet);
  std::istringstream stream(text);
  parser->SetStream(&stream);
  const bool ok = parser->Parse() && parser->GetRootElement();
  parser->SetStream(nullptr);
  return ok ? parser : nullptr;
}

/// The range and element count of a ParaView property lct-render reads.
struct PropertyRange
{
  int Size;
  double Lo, Hi;
};

/// The values of a ParaView <Property> (its <Element index= value=> children): every element
/// present once, each a complete finite decimal number in the range. `where` names the file and
/// the property in messages.
inline std::vector<double> PropertyValues(
  vtkXMLDataElement* property, const PropertyRange& range, const std::string& where)
{
  std::vector<double> values(range.Size, 0.0);
  std::vector<bool> seen(range.Size, false);
  for (int i = 0; i < property->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* element = property->GetNestedElement(i);
    if (std::string(element->GetName()) != "Element")
    {
      continue;
    }
    const char* indexText = element->GetAttribute("index");
    const char* valueText = element->GetAttribute("value");
    double index = -1.0;
    if (!ParseNumber(indexText, 0.0, range.Size - 1, index) || index != std::floor(index))
    {
      throw InputError(where + ": element index \"" +
        Printable(indexText ? indexText : "(missing)") + "\" is not one of 0.." +
        std::to_string(range.Size - 1));
    }
    const int k = static_cast<int>(index);
    if (seen[k])
    {
      throw InputError(where + ": element " + std::to_string(k) + " appears twice");
    }
    if (!ParseNumber(valueText, range.Lo, range.Hi, values[k]))
    {
      throw InputError(where + "[" + std::to_string(k) + "]: value \"" +
        Printable(valueText ? valueText : "(missing)") + "\" is not a finite number in [" +
        Num(range.Lo) + ", " + Num(range.Hi) + "]");
    }
    seen[k] = true;
  }
  for (int k = 0; k < range.Size; ++k)
  {
    if (!seen[k])
    {
      throw InputError(where + " has no element " + std::to_string(k) + " (needs " +
        std::to_string(range.Size) + ")");
    }
  }
  return values;
}

/// The <Property name=...> children of `proxy` whose names are in `wanted`, read by
/// PropertyValues; a property given twice is an error. `where` prefixes the messages.
inline std::map<std::string, std::vector<double>> ReadProperties(vtkXMLDataElement* proxy,
  const std::map<std::string, PropertyRange>& wanted, const std::string& where)
{
  std::map<std::string, std::vector<double>> properties;
  for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* e = proxy->GetNestedElement(i);
    const char* name = e->GetAttribute("name");
    if (std::string(e->GetName()) != "Property" || !name || !wanted.count(name))
    {
      continue;
    }
    if (properties.count(name))
    {
      throw InputError(where + name + " appears twice");
    }
    properties[name] = PropertyValues(e, wanted.at(name), where + name);
  }
  return properties;
}

/// A camera key from a ParaView camera's values (`p`: position, focal point, view up, and
/// optionally view angle, parallel scale, parallel projection under the names in `names`).
inline CameraKey CameraFromProperties(std::map<std::string, std::vector<double>>& p,
  const std::array<const char*, 6>& names, double time, const std::string& where)
{
  CameraValues v;
  std::copy_n(p[names[0]].begin(), 3, v.Position);
  std::copy_n(p[names[1]].begin(), 3, v.FocalPoint);
  if (p.count(names[2]))
  {
    std::copy_n(p[names[2]].begin(), 3, v.ViewUp);
  }
  if (p.count(names[3]))
  {
    v.ViewAngle = p[names[3]][0];
  }
  if (p.count(names[4]))
  {
    v.ParallelScale = p[names[4]][0];
  }
  if (p.count(names[5]))
  {
    v.Parallel = p[names[5]][0] != 0.0;
  }
  CameraKey key;
  key.Time = time;
  key.Path = where;
  key.Camera = MakeCamera(v, where, [&](const std::string& m) { throw InputError(m); });
  return key;
}

/// The ranges of the camera properties, under ParaView's names with `prefix` ("Camera" in a
/// .pvcc's view properties, "" in a CameraKeyFrame).
inline std::map<std::string, PropertyRange> CameraProperties(const std::string& prefix)
{
  const double X = Limits::MaxCoordinate;
  return { { prefix + "Position", { 3, -X, X } }, { prefix + "FocalPoint", { 3, -X, X } },
    { prefix + "ViewUp", { 3, -X, X } },
    { prefix + "ViewAngle", { 1, Limits::MinViewAngle, Limits::MaxViewAngle } },
    { prefix + "ParallelScale", { 1, Limits::MinLength, Limits::MaxLength } },
    { prefix + "ParallelProjection", { 1, 0.0, 1.0 } } };
}

/**
 * A camera key from a ParaView camera file (.pvcc, written by ParaView's "Save Camera": a
 * PVCameraConfiguration holding the render view's Camera* properties). Position, focal point and
 * view up are required; view angle, parallel scale and parallel projection are read when
 * present. Every value of these properties must be a finite decimal number in its field's range
 * (Limits); each property must have all of its elements, once. Throws InputError naming the
 * file, the property and the bad text.
 */
inline CameraKey ReadPvcc(const std::string& file, double time)
{
  const std::string text = ReadSmallFile(file, Limits::MaxPvccBytes, "camera file");
  // A real .pvcc has about 40 elements.
  if (std::count(text.begin(), text.end(), '<') > Limits::MaxPvccElements)
  {
    throw InputError(file + ": more than " + std::to_string(Limits::MaxPvccElements) +
      " XML elements; not a ParaView camera file");
  }
  const auto parser = ParseXml(file, text);
  if (!parser || std::string(parser->GetRootElement()->GetName()) != "PVCameraConfiguration")
  {
    throw InputError(file +
      ": not a ParaView camera file (malformed XML or no "
      "PVCameraConfiguration element)");
  }
  // The Camera* properties may sit on any element below the root (the view's proxy).
  std::map<std::string, std::vector<double>> properties;
  std::vector<vtkXMLDataElement*> pending{ parser->GetRootElement() };
  while (!pending.empty())
  {
    vtkXMLDataElement* e = pending.back();
    pending.pop_back();
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    {
      pending.push_back(e->GetNestedElement(i));
    }
    for (auto& [name, values] : ReadProperties(e, CameraProperties("Camera"), file + ": "))
    {
      if (properties.count(name))
      {
        throw InputError(file + ": " + name + " appears twice");
      }
      properties[name] = values;
    }
  }
  for (const char* required : { "CameraPosition", "CameraFocalPoint", "CameraViewUp" })
  {
    if (!properties.count(required))
    {
      throw InputError(file + ": " + required + " is missing");
    }
  }
  CameraKey key = CameraFromProperties(properties,
    { "CameraPosition", "CameraFocalPoint", "CameraViewUp", "CameraViewAngle",
      "CameraParallelScale", "CameraParallelProjection" },
    time, file + ": camera");
  key.Path = "camera";
  return key;
}

/// The camera track of a ParaView state file.
struct StateCamera
{
  std::vector<CameraKey> Keys;   // sorted by time
  std::string Interpolation;     // linear or spline (the cue's Interpolation)
  double Start = 0.0, End = 1.0; // the animation scene's StartTime and EndTime
  std::string Cue;               // "CameraAnimationCue id 4655", for messages
};

/**
 * The camera track of a ParaView state file (.pvsm: <ParaView><ServerManagerState> with
 * <Proxy group= type= id=> elements): the first enabled CameraAnimationCue with key frames, its
 * CameraKeyFrame proxies (KeyTime, Position, FocalPoint, ViewUp, ViewAngle, ParallelScale; see
 * ParaView's Remoting/Animation/Resources/animation.xml), the view's CameraParallelProjection,
 * and the AnimationScene's StartTime and EndTime. A key frame's KeyTime is a fraction of its
 * cue, and the cue's StartTime/EndTime are fractions of the scene (TimeMode 0, Normalized,
 * ParaView's default) or offsets from the scene's start (TimeMode 1, Relative): a key's time is
 * cueStart + KeyTime (cueEnd - cueStart). Throws InputError naming the file, the proxy and the
 * property.
 */
inline StateCamera ReadPvsm(const std::string& file)
{
  const std::string text = ReadSmallFile(file, Limits::MaxStateBytes, "ParaView state file");
  const auto parser = ParseXml(file, text);
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* state = root && std::string(root->GetName()) == "ParaView"
    ? root->FindNestedElementWithName("ServerManagerState")
    : nullptr;
  if (!state)
  {
    throw InputError(file + ": not a ParaView state file (" +
      (!parser ? std::string("malformed XML")
               : "root element <" + Printable(root->GetName()) +
            ">, not <ParaView><ServerManagerState>") +
      "). " + AcceptedInputs);
  }
  // Proxies by id.
  std::map<std::string, vtkXMLDataElement*> proxies;
  std::vector<vtkXMLDataElement*> cues;
  vtkXMLDataElement* scene = nullptr;
  for (int i = 0; i < state->GetNumberOfNestedElements(); ++i)
  {
    vtkXMLDataElement* e = state->GetNestedElement(i);
    const char* id = e->GetAttribute("id");
    const char* type = e->GetAttribute("type");
    if (std::string(e->GetName()) != "Proxy" || !id || !type)
    {
      continue;
    }
    proxies[id] = e;
    if (std::string(type) == "CameraAnimationCue")
    {
      cues.push_back(e);
    }
    else if (std::string(type) == "AnimationScene" && !scene)
    {
      scene = e;
    }
  }
  if (cues.empty())
  {
    throw InputError(file +
      ": the state has no camera track (no CameraAnimationCue proxy); in ParaView, add a "
      "Camera track with key frames in the Animation View, then save the state");
  }
  auto proxyList = [&](vtkXMLDataElement* proxy, const char* property) {
    std::vector<std::string> ids;
    for (int i = 0; i < proxy->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* e = proxy->GetNestedElement(i);
      const char* name = e->GetAttribute("name");
      if (std::string(e->GetName()) != "Property" || !name || std::string(name) != property)
      {
        continue;
      }
      for (int j = 0; j < e->GetNumberOfNestedElements(); ++j)
      {
        vtkXMLDataElement* p = e->GetNestedElement(j);
        if (std::string(p->GetName()) == "Proxy" && p->GetAttribute("value"))
        {
          ids.emplace_back(p->GetAttribute("value"));
        }
      }
    }
    return ids;
  };
  const std::map<std::string, PropertyRange> cueProperties = { { "Enabled", { 1, 0.0, 1.0 } },
    { "Interpolation", { 1, 0.0, 1.0 } }, { "Mode", { 1, 0.0, 2.0 } },
    { "TimeMode", { 1, 0.0, 1.0 } }, { "StartTime", { 1, -Limits::MaxTime, Limits::MaxTime } },
    { "EndTime", { 1, -Limits::MaxTime, Limits::MaxTime } } };
  vtkXMLDataElement* cue = nullptr;
  std::map<std::string, std::vector<double>> cueValues;
  std::string skipped;
  for (vtkXMLDataElement* c : cues)
  {
    const std::string where = file + ": CameraAnimationCue id " + c->GetAttribute("id") + ": ";
    auto values = ReadProperties(c, cueProperties, where);
    const bool enabled = !values.count("Enabled") || values["Enabled"][0] != 0.0;
    if (enabled && !proxyList(c, "KeyFrames").empty())
    {
      cue = c;
      cueValues = values;
      break;
    }
    skipped += std::string(skipped.empty() ? "" : "; ") + "id " + c->GetAttribute("id") +
      (enabled ? " has no key frames" : " is disabled");
  }
  if (!cue)
  {
    throw InputError(file + ": no usable camera track (CameraAnimationCue " + skipped + ")");
  }
  StateCamera out;
  out.Cue = std::string("CameraAnimationCue id ") + cue->GetAttribute("id");
  out.Interpolation =
    cueValues.count("Interpolation") && cueValues["Interpolation"][0] == 0.0 ? "linear" : "spline";
  if (cueValues.count("Mode") && cueValues["Mode"][0] != 0.0)
  {
    // Path-based and follow-data tracks still store a camera per key frame: those are read.
    std::cerr << file << ": note: " << out.Cue << " is in "
              << (cueValues["Mode"][0] == 1.0 ? "Path-based" : "Follow-data")
              << " mode; lct-render interpolates the cameras of its key frames\n";
  }
  if (scene)
  {
    auto values = ReadProperties(scene,
      { { "StartTime", { 1, -Limits::MaxTime, Limits::MaxTime } },
        { "EndTime", { 1, -Limits::MaxTime, Limits::MaxTime } } },
      file + ": AnimationScene id " + scene->GetAttribute("id") + ": ");
    out.Start = values.count("StartTime") ? values["StartTime"][0] : 0.0;
    out.End = values.count("EndTime") ? values["EndTime"][0] : 1.0;
  }
  if (!(out.End > out.Start))
  {
    throw InputError(file + ": the AnimationScene's EndTime " + Num(out.End) +
      " is not after its StartTime " + Num(out.Start));
  }
  const double span = out.End - out.Start;
  const bool relative = cueValues.count("TimeMode") && cueValues["TimeMode"][0] == 1.0;
  const double cs = cueValues.count("StartTime") ? cueValues["StartTime"][0] : 0.0;
  const double ce = cueValues.count("EndTime") ? cueValues["EndTime"][0] : 1.0;
  const double cueStart = relative ? out.Start + cs : out.Start + cs * span;
  const double cueEnd = relative ? out.Start + ce : out.Start + ce * span;
  // The view the cue animates holds the projection (a key frame has no ParallelProjection).
  bool parallel = false;
  const auto views = proxyList(cue, "AnimatedProxy");
  if (!views.empty() && proxies.count(views[0]))
  {
    auto values = ReadProperties(proxies[views[0]],
      { { "CameraParallelProjection", { 1, 0.0, 1.0 } } }, file + ": view id " + views[0] + ": ");
    parallel = values.count("CameraParallelProjection") && values["CameraParallelProjection"][0];
  }
  const auto frames = proxyList(cue, "KeyFrames");
  if (frames.size() > Limits::MaxKeys)
  {
    throw InputError(file + ": " + out.Cue + " has " + std::to_string(frames.size()) +
      " key frames; at most " + std::to_string(Limits::MaxKeys) + " are accepted");
  }
  auto keyProperties = CameraProperties("");
  keyProperties.erase("ParallelProjection");
  keyProperties["KeyTime"] = { 1, 0.0, 1.0 };
  for (size_t k = 0; k < frames.size(); ++k)
  {
    const std::string where = out.Cue + ".KeyFrames[" + std::to_string(k) +
      "] (CameraKeyFrame id " + Printable(frames[k]) + ")";
    auto it = proxies.find(frames[k]);
    if (it == proxies.end() || std::string(it->second->GetAttribute("type")) != "CameraKeyFrame")
    {
      throw InputError(
        file + ": " + where + ": the state has no CameraKeyFrame proxy with this id");
    }
    auto values = ReadProperties(it->second, keyProperties, file + ": " + where + ": ");
    for (const char* required : { "KeyTime", "Position", "FocalPoint" })
    {
      if (!values.count(required))
      {
        throw InputError(file + ": " + where + ": " + required + " is missing");
      }
    }
    values["ParallelProjection"] = { parallel ? 1.0 : 0.0 };
    const double time = cueStart + values["KeyTime"][0] * (cueEnd - cueStart);
    CameraKey key = CameraFromProperties(values,
      { "Position", "FocalPoint", "ViewUp", "ViewAngle", "ParallelScale", "ParallelProjection" },
      time, file + ": " + where);
    key.Path = where;
    out.Keys.push_back(key);
  }
  if (out.Keys.size() < 2)
  {
    throw InputError(file + ": " + out.Cue + " has " + std::to_string(out.Keys.size()) +
      " key frame, but a camera path needs at least 2");
  }
  SortByTime(out.Keys, file);
  return out;
}

/// Reads and validates a keyframe file; throws InputError. An XML file is refused with what is
/// accepted (a ParaView file given as the keys file is read as JSON otherwise, and JSON's
/// message about '<' helps nobody). `cameraOptional`: camera keys come from elsewhere.
inline Keys ReadFile(const std::string& file, bool cameraOptional = false)
{
  const std::string text = ReadSmallFile(file, Limits::MaxKeysFileBytes, "keys file");
  const size_t first = text.find_first_not_of(" \t\r\n");
  if (first != std::string::npos && text[first] == '<')
  {
    throw InputError(file + ": an XML file given as the keys file. " + AcceptedInputs +
      " (give ParaView files their .pvcc or .pvsm extension)");
  }
  Parser parser(file);
  parser.SetCameraOptional(cameraOptional);
  return parser.Read(text);
}

// ---------------------------------------------------------------------------------------------
// RenderMeshCheck: what a --mesh file must pass before a VTK reader sees it. VTK 9.1's readers
// crash (PLY: an out-of-range face index, a short line, a truncated file; OBJ: an out-of-range
// vt/vn index; legacy VTK: a truncated ASCII body) or allocate whatever a header declares (PLY,
// binary STL, legacy VTK, XML) on hostile files, and pass out-of-range indices and NaN points on
// to the renderer. lct-render also runs the reader in a child process (see ReadMesh there).

/// Reads a file's bytes through a cursor, naming the file and the offending line or offset.
class MeshText
{
public:
  MeshText(std::string file, std::string data)
    : File(std::move(file))
    , Data(std::move(data))
  {
  }

  [[noreturn]] void Fail(const std::string& what) const
  {
    throw InputError(this->File + ": " + what);
  }
  [[noreturn]] void FailAt(const std::string& what) const
  {
    throw InputError(this->File + ":" + LineColumn(this->Data, this->At) + ": " + what);
  }

  bool AtEnd() const { return this->At >= this->Data.size(); }
  size_t Remaining() const { return this->Data.size() - std::min(this->At, this->Data.size()); }

  /// The next line without its end of line; false at the end of the data.
  bool Line(std::string& line, size_t maxLength)
  {
    if (this->AtEnd())
    {
      return false;
    }
    const size_t nl = this->Data.find('\n', this->At);
    const size_t end = nl == std::string::npos ? this->Data.size() : nl;
    if (end - this->At > maxLength)
    {
      this->FailAt("line longer than " + std::to_string(maxLength) + " bytes");
    }
    line.assign(this->Data, this->At, end - this->At);
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    this->LineStart = this->At;
    this->At = nl == std::string::npos ? this->Data.size() : nl + 1;
    return true;
  }

  /// Moves back to the start of the line last read (for messages about it).
  void Rewind() { this->At = this->LineStart; }

  /// The next whitespace-separated token (across lines); empty at the end.
  std::string Token()
  {
    while (!this->AtEnd() && std::isspace(static_cast<unsigned char>(this->Data[this->At])))
    {
      ++this->At;
    }
    const size_t begin = this->At;
    while (!this->AtEnd() && !std::isspace(static_cast<unsigned char>(this->Data[this->At])))
    {
      ++this->At;
    }
    return this->Data.substr(begin, this->At - begin);
  }

  const unsigned char* Bytes(size_t n)
  {
    if (this->Remaining() < n)
    {
      this->FailAt("the file is truncated: " + std::to_string(n) + " more bytes expected, " +
        std::to_string(this->Remaining()) + " left");
    }
    const auto* p = reinterpret_cast<const unsigned char*>(this->Data.data() + this->At);
    this->At += n;
    return p;
  }

  const std::string& data() const { return this->Data; }
  size_t& position() { return this->At; }
  const std::string& file() const { return this->File; }

private:
  std::string File;
  std::string Data;
  size_t At = 0;
  size_t LineStart = 0;
};

inline std::vector<std::string> Words(const std::string& line)
{
  std::vector<std::string> words;
  std::istringstream in(line);
  std::string w;
  while (in >> w)
  {
    words.push_back(w);
  }
  return words;
}

/// A whole decimal integer token in [lo, hi].
inline bool ParseInteger(const std::string& token, long long lo, long long hi, long long& out)
{
  if (token.empty() || token.size() > 20)
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const long long v = std::strtoll(token.c_str(), &end, 10);
  if (errno != 0 || *end != '\0' || v < lo || v > hi)
  {
    return false;
  }
  out = v;
  return true;
}

/// Binary scalar types of PLY and legacy VTK files: size in bytes, integer or not.
struct ScalarType
{
  int Size = 0;
  bool Integer = false;
  bool Signed = false;
};

inline bool PlyType(const std::string& name, ScalarType& t)
{
  static const std::map<std::string, ScalarType> types = { { "char", { 1, true, true } },
    { "int8", { 1, true, true } }, { "uchar", { 1, true, false } }, { "uint8", { 1, true, false } },
    { "short", { 2, true, true } }, { "int16", { 2, true, true } },
    { "ushort", { 2, true, false } }, { "uint16", { 2, true, false } },
    { "int", { 4, true, true } }, { "int32", { 4, true, true } }, { "uint", { 4, true, false } },
    { "uint32", { 4, true, false } }, { "float", { 4, false, true } },
    { "float32", { 4, false, true } }, { "double", { 8, false, true } },
    { "float64", { 8, false, true } } };
  const auto it = types.find(name);
  if (it == types.end())
  {
    return false;
  }
  t = it->second;
  return true;
}

/// A binary value of type t at p, as double (integers exactly up to 2^53).
inline double BinaryValue(const unsigned char* p, const ScalarType& t, bool bigEndian)
{
  unsigned char b[8];
  for (int i = 0; i < t.Size; ++i)
  {
    b[i] = bigEndian ? p[t.Size - 1 - i] : p[i]; // to little endian (this machine's)
  }
  if (!t.Integer)
  {
    if (t.Size == 4)
    {
      float f;
      std::memcpy(&f, b, 4);
      return f;
    }
    double d;
    std::memcpy(&d, b, 8);
    return d;
  }
  unsigned long long u = 0;
  for (int i = t.Size - 1; i >= 0; --i)
  {
    u = (u << 8) | b[i];
  }
  if (t.Signed && t.Size < 8 && (u >> (8 * t.Size - 1)))
  {
    return static_cast<double>(static_cast<long long>(u) - (1LL << (8 * t.Size)));
  }
  return static_cast<double>(u);
}

inline void CheckCoordinate(const MeshText& text, double v, const std::string& where)
{
  if (!std::isfinite(v) || std::fabs(v) > Limits::MaxCoordinate)
  {
    text.FailAt(where + " = " + Num(v) + " is not a finite coordinate within +-1e15");
  }
}

/// PLY (ASCII, binary little/big endian): the header, then every element instance the way
/// vtkPLY reads it (ASCII: one instance per line, of at most 4095 bytes).
inline void CheckPly(MeshText& text)
{
  struct Property
  {
    std::string Name;
    ScalarType Type;
    bool List = false;
    ScalarType CountType;
  };
  struct Element
  {
    std::string Name;
    long long Count = 0;
    std::vector<Property> Properties;
  };
  std::string line;
  if (!text.Line(line, 4095) || line != "ply")
  {
    text.Fail("not a PLY file (the first line is not \"ply\")");
  }
  std::string format;
  std::vector<Element> elements;
  bool ended = false;
  while (!ended && text.Line(line, 4095))
  {
    const std::vector<std::string> w = Words(line);
    if (w.empty() || w[0] == "comment" || w[0] == "obj_info")
    {
      continue;
    }
    if (w[0] == "format" && w.size() == 3)
    {
      format = w[1];
      if (format != "ascii" && format != "binary_little_endian" && format != "binary_big_endian")
      {
        text.Rewind();
        text.FailAt("unknown PLY format \"" + Printable(format) + "\"");
      }
    }
    else if (w[0] == "element" && w.size() == 3)
    {
      Element e;
      e.Name = w[1];
      // vtkPLYReader takes the first element to be the vertices: it crashes (SIGSEGV) on a
      // face, or any other element, before them.
      if (elements.empty() && e.Name != "vertex")
      {
        text.Rewind();
        text.FailAt("the first element is \"" + Printable(e.Name) +
          "\", not \"vertex\" (vtkPLYReader reads only files whose vertex element comes first)");
      }
      // It reads the first vertex element (the checks below took the last), and in ASCII it reads
      // the lines of any other element before the faces as faces (an edge element: a polygon
      // without points, on which GetCell crashes).
      const bool faceSeen = std::any_of(
        elements.begin(), elements.end(), [](const Element& seen) { return seen.Name == "face"; });
      if (!elements.empty() && !faceSeen && e.Name != "face")
      {
        text.Rewind();
        text.FailAt("element \"" + Printable(e.Name) +
          "\" comes between the vertex and face elements (vtkPLYReader reads only one vertex "
          "element, followed by the faces; other elements may come after them)");
      }
      // A second vertex (or face) element anywhere: vtkPLYReader reads the first, and the checks
      // would have to guess which one it indexes (a second vertex element after the faces
      // crashed the reader).
      if ((e.Name == "vertex" || e.Name == "face") &&
        std::any_of(elements.begin(), elements.end(),
          [&](const Element& seen) { return seen.Name == e.Name; }))
      {
        text.Rewind();
        text.FailAt("a second \"" + e.Name +
          "\" element (vtkPLYReader reads one vertex and one face element)");
      }
      const long long limit = e.Name == "vertex" ? Limits::MaxMeshPoints : Limits::MaxMeshCells;
      if (!ParseInteger(w[2], 0, limit, e.Count))
      {
        text.Rewind();
        text.FailAt("element " + Printable(e.Name) + " count \"" + Printable(w[2]) +
          "\" is not an integer in [0, " + std::to_string(limit) + "]");
      }
      elements.push_back(e);
    }
    else if (w[0] == "property" && !elements.empty() &&
      ((w.size() == 3 && w[1] != "list") || (w.size() == 5 && w[1] == "list")))
    {
      Property p;
      p.List = w[1] == "list";
      p.Name = w.back();
      if (!PlyType(w[p.List ? 3 : 1], p.Type) || (p.List && !PlyType(w[2], p.CountType)) ||
        (p.List && !p.CountType.Integer))
      {
        text.Rewind();
        text.FailAt("bad property type in \"" + Printable(line) + "\"");
      }
      elements.back().Properties.push_back(p);
    }
    else if (w[0] == "end_header" && w.size() == 1)
    {
      ended = true;
    }
    else
    {
      text.Rewind();
      text.FailAt("unexpected PLY header line \"" + Printable(line) + "\"");
    }
  }
  if (!ended || format.empty())
  {
    text.Fail("the PLY header is incomplete (no format line or no end_header)");
  }
  const Element* vertex = nullptr;
  for (const auto& e : elements)
  {
    if (e.Name == "vertex" && !vertex)
    {
      vertex = &e;
    }
  }
  auto has = [](const Element* e, const char* name) {
    return e && std::any_of(e->Properties.begin(), e->Properties.end(), [&](const Property& p) {
      return p.Name == name && !p.List;
    });
  };
  if (!has(vertex, "x") || !has(vertex, "y") || !has(vertex, "z"))
  {
    text.Fail("no vertex element with x, y and z properties");
  }
  const bool ascii = format == "ascii", big = format == "binary_big_endian";
  // A first bound before walking: every instance takes at least one byte per scalar.
  unsigned long long least = 0;
  for (const auto& e : elements)
  {
    least += static_cast<unsigned long long>(e.Count) * (ascii ? 2 : 1) *
      std::max<size_t>(1, e.Properties.size());
  }
  if (least > text.Remaining())
  {
    text.Fail("the file is truncated: its header declares at least " + std::to_string(least) +
      " bytes of data, the file has " + std::to_string(text.Remaining()) + " after the header");
  }
  const long long vertices = vertex->Count;
  for (const auto& e : elements)
  {
    const bool isFace = e.Name == "face";
    for (long long i = 0; i < e.Count; ++i)
    {
      const std::string where = e.Name + " " + std::to_string(i);
      std::vector<std::string> w;
      size_t next = 0;
      if (ascii)
      {
        if (!text.Line(line, 4095))
        {
          text.FailAt(
            "the file is truncated: " + where + " of " + std::to_string(e.Count) + " is missing");
        }
        w = Words(line);
        text.Rewind();
      }
      auto value = [&](const ScalarType& t, const std::string& what) {
        if (!ascii)
        {
          return BinaryValue(text.Bytes(static_cast<size_t>(t.Size)), t, big);
        }
        if (next >= w.size())
        {
          text.FailAt(where + ": too few values on its line (" + std::to_string(w.size()) + ")");
        }
        const std::string& token = w[next++];
        double v = 0.0;
        if (!ParseNumber(token.c_str(), -DBL_MAX, DBL_MAX, v) || (t.Integer && v != std::floor(v)))
        {
          text.FailAt(where + ": " + what + " \"" + Printable(token) + "\" is not " +
            (t.Integer ? "an integer" : "a finite number"));
        }
        return v;
      };
      for (const auto& p : e.Properties)
      {
        if (!p.List)
        {
          const double v = value(p.Type, p.Name);
          if (&e == vertex && (p.Name == "x" || p.Name == "y" || p.Name == "z"))
          {
            CheckCoordinate(text, v, where + " " + p.Name);
          }
          continue;
        }
        const double n = value(p.CountType, p.Name + " count");
        const bool indices = isFace && (p.Name == "vertex_indices" || p.Name == "vertex_index");
        if (n < 0 || n > (ascii ? static_cast<double>(w.size()) : 1e9) ||
          n * p.Type.Size > static_cast<double>(text.Remaining()) + (ascii ? 1e9 : 0.0))
        {
          text.FailAt(where + ": list " + p.Name + " of " + Num(n) + " entries does not fit");
        }
        if (indices && n < 3)
        {
          text.FailAt(where + ": a face needs at least 3 vertices, this one has " + Num(n));
        }
        for (long long k = 0; k < static_cast<long long>(n); ++k)
        {
          const double v = value(p.Type, p.Name);
          if (indices && !(v >= 0 && v < static_cast<double>(vertices) && v == std::floor(v)))
          {
            text.FailAt(where + ": vertex index " + Num(v) + " is out of range (the file has " +
              std::to_string(vertices) + " vertices)");
          }
        }
      }
      if (ascii)
      {
        if (next != w.size())
        {
          text.FailAt(where + ": " + std::to_string(w.size()) + " values on its line, " +
            std::to_string(next) + " expected");
        }
        text.Line(line, 4095);
      }
    }
  }
}

/// OBJ: every line; indices may be negative (relative to the entries so far) or positive (at
/// most the file's count), never 0.
inline void CheckObj(MeshText& text)
{
  const size_t maxLine = 262144;    // vtkOBJReader's line buffer
  long long total[3] = { 0, 0, 0 }; // v, vt, vn
  std::string line;
  while (text.Line(line, maxLine - 1))
  {
    const std::vector<std::string> w = Words(line);
    if (!w.empty() && (w[0] == "v" || w[0] == "vt" || w[0] == "vn"))
    {
      ++total[w[0] == "v" ? 0 : w[0] == "vt" ? 1 : 2];
    }
  }
  text.position() = 0;
  long long seen[3] = { 0, 0, 0 };
  const char* const kinds[3] = { "vertex", "texture coordinate", "normal" };
  const char* const plural[3] = { "vertices", "texture coordinates", "normals" };
  while (text.Line(line, maxLine - 1))
  {
    const std::vector<std::string> w = Words(line);
    if (w.empty() || w[0][0] == '#')
    {
      continue;
    }
    text.Rewind();
    if (w[0] == "v" || w[0] == "vt" || w[0] == "vn")
    {
      const int kind = w[0] == "v" ? 0 : w[0] == "vt" ? 1 : 2;
      const size_t needed = kind == 1 ? 2 : 3;
      if (w.size() < needed + 1)
      {
        text.FailAt(w[0] + " needs " + std::to_string(needed) + " numbers");
      }
      for (size_t i = 1; i < w.size(); ++i)
      {
        double v = 0.0;
        if (!ParseNumber(w[i].c_str(), -Limits::MaxCoordinate, Limits::MaxCoordinate, v))
        {
          text.FailAt(w[0] + ": \"" + Printable(w[i]) + "\" is not a finite number within +-1e15");
        }
      }
      ++seen[kind];
    }
    else if (w[0] == "f" || w[0] == "l" || w[0] == "p")
    {
      const size_t least = w[0] == "f" ? 3 : w[0] == "l" ? 2 : 1;
      if (w.size() < least + 1)
      {
        text.FailAt(w[0] + " needs at least " + std::to_string(least) + " vertices");
      }
      for (size_t i = 1; i < w.size(); ++i)
      {
        // i, i/j, i//k, i/j/k
        size_t start = 0;
        for (int part = 0; part < 3 && start <= w[i].size(); ++part)
        {
          const size_t slash = w[i].find('/', start);
          const std::string token =
            w[i].substr(start, slash == std::string::npos ? std::string::npos : slash - start);
          start = slash == std::string::npos ? w[i].size() + 1 : slash + 1;
          if (token.empty() && part > 0)
          {
            continue;
          }
          long long index = 0;
          if (!ParseInteger(token, -total[part], total[part], index) || index == 0 ||
            (index < 0 && -index > seen[part]))
          {
            text.FailAt(w[0] + ": " + kinds[part] + " index \"" + Printable(token) +
              "\" is out of range (the file has " + std::to_string(total[part]) + " " +
              (total[part] == 1 ? kinds[part] : plural[part]) + ")");
          }
        }
        if (start <= w[i].size())
        {
          text.FailAt(w[0] + ": \"" + Printable(w[i]) + "\" is not i, i/j, i//k or i/j/k");
        }
      }
    }
    text.Line(line, maxLine - 1);
  }
  if (total[0] > Limits::MaxMeshPoints)
  {
    text.Fail(std::to_string(total[0]) + " vertices; at most " +
      std::to_string(Limits::MaxMeshPoints) + " are accepted");
  }
}

/// STL: binary (as VTK's vtksys::SystemTools::DetectFileType decides: 5 % or more of the first
/// 256 bytes not text) must be exactly 84 + 50 n bytes with n from its header; ASCII must start
/// with "solid" and is then VTK's parser's (it reports errors and does not over-allocate).
inline void CheckStl(MeshText& text)
{
  const std::string& d = text.data();
  const size_t probe = std::min<size_t>(d.size(), 256);
  size_t binary = 0;
  for (size_t i = 0; i < probe; ++i)
  {
    const unsigned char c = static_cast<unsigned char>(d[i]);
    if (!(std::isprint(c) || std::isspace(c)))
    {
      ++binary;
    }
  }
  if (probe > 0 && binary * 20 < probe)
  {
    const size_t begin = d.find_first_not_of(" \t\r\n");
    if (begin == std::string::npos || d.compare(begin, 5, "solid") != 0)
    {
      text.Fail("neither a binary STL file nor an ASCII one (an ASCII STL starts with \"solid\")");
    }
    return;
  }
  if (d.size() < 84)
  {
    text.Fail("binary STL file of " + std::to_string(d.size()) +
      " bytes is shorter than its 84-byte header");
  }
  const unsigned long long n = static_cast<unsigned long long>(
    BinaryValue(reinterpret_cast<const unsigned char*>(d.data()) + 80, { 4, true, false }, false));
  const unsigned long long expected = 84 + 50 * n;
  if (expected != d.size())
  {
    text.Fail("binary STL header declares " + std::to_string(n) + " triangle(s) (" +
      std::to_string(expected) + " bytes), but the file has " + std::to_string(d.size()) +
      " bytes");
  }
  if (n == 0 || static_cast<long long>(n) > Limits::MaxMeshCells)
  {
    text.Fail("binary STL with " + std::to_string(n) + " triangles; 1 to " +
      std::to_string(Limits::MaxMeshCells) + " are accepted");
  }
  for (unsigned long long i = 0; i < n; ++i)
  {
    const auto* tri = reinterpret_cast<const unsigned char*>(d.data()) + 84 + 50 * i;
    for (int c = 3; c < 12; ++c) // the 3 vertices (the normal is recomputed by nobody: ignored)
    {
      const double v = BinaryValue(tri + 4 * c, { 4, false, true }, false);
      if (!std::isfinite(v) || std::fabs(v) > Limits::MaxCoordinate)
      {
        text.Fail("triangle " + std::to_string(i) + " has the vertex coordinate " + Num(v) +
          " (not finite or beyond +-1e15)");
      }
    }
  }
}

/// Legacy VTK POLYDATA: the header, then POINTS and the cell sections (legacy "n size" layout
/// and the OFFSETS/CONNECTIVITY one of version 5.1), ASCII or binary; attribute sections after
/// them (POINT_DATA, CELL_DATA, FIELD) are VTK's.
inline void CheckLegacyVtk(MeshText& text)
{
  std::string line;
  if (!text.Line(line, 256) || line.rfind("# vtk DataFile Version", 0) != 0)
  {
    text.Fail("not a legacy VTK file (no \"# vtk DataFile Version\" first line)");
  }
  if (!text.Line(line, 256))
  {
    text.Fail("the file is truncated after its first line");
  }
  if (!text.Line(line, 256) ||
    (Words(line) != std::vector<std::string>{ "ASCII" } &&
      Words(line) != std::vector<std::string>{ "BINARY" }))
  {
    text.Fail("the third line must be ASCII or BINARY");
  }
  const bool binary = Words(line)[0] == "BINARY";
  if (text.Token() != "DATASET" || text.Token() != "POLYDATA")
  {
    text.Fail("lct-render reads DATASET POLYDATA only from legacy VTK files");
  }
  static const std::map<std::string, ScalarType> types = { { "bit", { 0, true, false } },
    { "unsigned_char", { 1, true, false } }, { "char", { 1, true, true } },
    { "unsigned_short", { 2, true, false } }, { "short", { 2, true, true } },
    { "unsigned_int", { 4, true, false } }, { "int", { 4, true, true } },
    { "unsigned_long", { 8, true, false } }, { "long", { 8, true, true } },
    { "vtktypeint64", { 8, true, true } }, { "vtktypeuint64", { 8, true, false } },
    { "vtkIdType", { 8, true, true } }, { "float", { 4, false, true } },
    { "double", { 8, false, true } } };
  long long points = -1;
  long long totalCells = 0, totalIndices = 0;
  // n values of type t: binary after the end of the current line, ASCII as tokens.
  auto values = [&](long long n, const ScalarType& t, const std::string& what, auto&& each) {
    if (binary)
    {
      std::string rest;
      text.Line(rest, 1 << 20); // the end of the keyword line
      const double bytes = static_cast<double>(n) * t.Size;
      if (bytes > static_cast<double>(text.Remaining()))
      {
        text.FailAt("the file is truncated: " + what + " needs " + Num(bytes) + " bytes, " +
          std::to_string(text.Remaining()) + " left");
      }
      for (long long i = 0; i < n; ++i)
      {
        each(i, BinaryValue(text.Bytes(static_cast<size_t>(t.Size)), t, true));
      }
      return;
    }
    if (static_cast<double>(n) * 2 > static_cast<double>(text.Remaining()) + 1)
    {
      text.FailAt("the file is truncated: " + what + " declares " + std::to_string(n) +
        " values, the " + std::to_string(text.Remaining()) + " bytes left cannot hold them");
    }
    for (long long i = 0; i < n; ++i)
    {
      const std::string token = text.Token();
      double v = 0.0;
      if (token.empty())
      {
        text.FailAt("the file is truncated: " + what + " has " + std::to_string(i) + " of " +
          std::to_string(n) + " values");
      }
      if (!ParseNumber(token.c_str(), -DBL_MAX, DBL_MAX, v) || (t.Integer && v != std::floor(v)))
      {
        text.FailAt(what + ": \"" + Printable(token) + "\" is not " +
          (t.Integer ? "an integer" : "a finite number"));
      }
      each(i, v);
    }
  };
  auto checkIndex = [&](double v, const std::string& what) {
    if (!(v >= 0 && v < static_cast<double>(points)))
    {
      text.FailAt(what + ": point index " + Num(v) + " is out of range (the file has " +
        std::to_string(points) + " points)");
    }
  };
  for (;;)
  {
    const size_t keywordAt = text.position();
    const std::string keyword = text.Token();
    if (keyword.empty())
    {
      break;
    }
    if (keyword == "POINT_DATA" || keyword == "CELL_DATA" || keyword == "FIELD")
    {
      break;
    }
    if (keyword == "METADATA")
    {
      // Information keys up to the next empty line.
      const size_t blank = text.data().find("\n\n", text.position());
      text.position() = blank == std::string::npos ? text.data().size() : blank + 2;
      continue;
    }
    long long n = 0, size = 0;
    if (keyword == "POINTS")
    {
      const std::string count = text.Token(), type = text.Token();
      if (points >= 0 || !ParseInteger(count, 0, Limits::MaxMeshPoints, n) || !types.count(type) ||
        types.at(type).Size == 0)
      {
        text.position() = keywordAt;
        text.FailAt("POINTS " + Printable(count) + " " + Printable(type) +
          ": expected one POINTS section of at most " + std::to_string(Limits::MaxMeshPoints) +
          " points of a numeric type");
      }
      points = n;
      values(3 * n, types.at(type), "POINTS", [&](long long i, double v) {
        if (!std::isfinite(v) || std::fabs(v) > Limits::MaxCoordinate)
        {
          text.FailAt("POINTS: coordinate " + std::to_string(i) + " = " + Num(v) +
            " is not finite or beyond +-1e15");
        }
      });
      continue;
    }
    if (keyword != "VERTICES" && keyword != "LINES" && keyword != "POLYGONS" &&
      keyword != "TRIANGLE_STRIPS")
    {
      text.position() = keywordAt;
      text.FailAt("unexpected \"" + Printable(keyword) + "\" in a POLYDATA file");
    }
    const std::string a = text.Token(), b = text.Token();
    if (points < 0)
    {
      text.position() = keywordAt;
      text.FailAt(keyword + " before POINTS");
    }
    if (!ParseInteger(a, 0, Limits::MaxMeshCells + 1, n) ||
      !ParseInteger(b, 0, Limits::MaxMeshIndices + Limits::MaxMeshCells, size))
    {
      text.position() = keywordAt;
      text.FailAt(keyword + " " + Printable(a) + " " + Printable(b) + ": counts beyond " +
        std::to_string(Limits::MaxMeshCells) + " cells or " +
        std::to_string(Limits::MaxMeshIndices) + " indices, or not integers");
    }
    const size_t afterCounts = text.position();
    const std::string next = text.Token();
    text.position() = afterCounts;
    if (next == "OFFSETS")
    {
      // Version 5.1: n offsets (cells + 1), size connectivity entries.
      text.Token();
      const std::string type = text.Token();
      if (!types.count(type) || !types.at(type).Integer || types.at(type).Size == 0)
      {
        text.FailAt("OFFSETS of type \"" + Printable(type) + "\"");
      }
      double previous = 0.0;
      values(n, types.at(type), keyword + " OFFSETS", [&](long long i, double v) {
        if ((i == 0 && v != 0.0) || v < previous || v > static_cast<double>(size))
        {
          text.FailAt(keyword + " OFFSETS: offset " + std::to_string(i) + " = " + Num(v) +
            " is not in order within [0, " + std::to_string(size) + "]");
        }
        previous = v;
      });
      if (n > 0 && previous != static_cast<double>(size))
      {
        text.FailAt(keyword + ": the last offset " + Num(previous) +
          " is not the connectivity "
          "size " +
          std::to_string(size));
      }
      if (text.Token() != "CONNECTIVITY")
      {
        text.FailAt(keyword + ": CONNECTIVITY expected after OFFSETS");
      }
      const std::string ctype = text.Token();
      if (!types.count(ctype) || !types.at(ctype).Integer || types.at(ctype).Size == 0)
      {
        text.FailAt("CONNECTIVITY of type \"" + Printable(ctype) + "\"");
      }
      values(size, types.at(ctype), keyword + " CONNECTIVITY",
        [&](long long, double v) { checkIndex(v, keyword); });
      totalCells += std::max<long long>(0, n - 1);
      totalIndices += size;
    }
    else
    {
      // Legacy: n cells as (count, indices...) in size integers.
      long long remaining = 0, cells = 0;
      values(size, { 4, true, true }, keyword, [&](long long, double v) {
        if (remaining == 0)
        {
          if (!(v >= 1 && v <= static_cast<double>(size)) || ++cells > n)
          {
            text.FailAt(keyword + ": cell " + std::to_string(cells) + " has the size " + Num(v) +
              " (the section declares " + std::to_string(n) + " cells in " + std::to_string(size) +
              " values)");
          }
          remaining = static_cast<long long>(v);
          return;
        }
        checkIndex(v, keyword);
        --remaining;
      });
      if (remaining != 0 || cells != n)
      {
        text.FailAt(keyword + ": " + std::to_string(cells) + " cells in " + std::to_string(size) +
          " values, the section declares " + std::to_string(n));
      }
      totalCells += n;
      totalIndices += size - n;
    }
    if (totalCells > Limits::MaxMeshCells || totalIndices > Limits::MaxMeshIndices)
    {
      text.Fail("more than " + std::to_string(Limits::MaxMeshCells) + " cells or " +
        std::to_string(Limits::MaxMeshIndices) + " cell indices");
    }
  }
  if (points <= 0)
  {
    text.Fail("no points (a POLYDATA file needs a POINTS section with at least one point)");
  }
}

/// glTF 2.0: a .glb's 12-byte header (magic "glTF", version 2, the length of the whole file), a
/// .gltf's JSON (an object with "asset"). Buffers, accessors and the rest are vtkGLTFReader's,
/// in the reading child process.
inline void CheckGltf(MeshText& text, bool binary)
{
  const std::string& d = text.data();
  if (binary)
  {
    const auto* p = reinterpret_cast<const unsigned char*>(d.data());
    if (d.size() < 12 || d.compare(0, 4, "glTF") != 0)
    {
      text.Fail("not a binary glTF file (no \"glTF\" magic in its 12-byte header)");
    }
    const double version = BinaryValue(p + 4, { 4, true, false }, false);
    const double length = BinaryValue(p + 8, { 4, true, false }, false);
    if (version != 2.0)
    {
      text.Fail("binary glTF version " + Num(version) + "; vtkGLTFReader reads version 2");
    }
    if (length != static_cast<double>(d.size()))
    {
      text.Fail("the glTF header declares " + Num(length) + " bytes, but the file has " +
        std::to_string(d.size()) + " (truncated or padded)");
    }
    return;
  }
  Parser json(text.file());
  const nlohmann::json doc = json.Parse(d);
  if (!doc.is_object() || !doc.contains("asset"))
  {
    text.Fail("not a glTF file (no JSON object with \"asset\")");
  }
}

/// VTK XML PolyData: the NumberOf* attributes of each Piece against the limits (the reader
/// allocates them before it reads a byte of data); the XML and its data are VTK's.
inline void CheckVtp(MeshText& text)
{
  const std::string& d = text.data();
  const size_t end = std::min(d.size(), d.find("<AppendedData"));
  long long points = 0, cells = 0;
  for (const char* attribute : { "NumberOfPoints=\"", "NumberOfVerts=\"", "NumberOfLines=\"",
         "NumberOfStrips=\"", "NumberOfPolys=\"", "NumberOfCells=\"" })
  {
    for (size_t at = d.find(attribute); at < end; at = d.find(attribute, at + 1))
    {
      const size_t begin = at + std::strlen(attribute);
      const size_t close = d.find('"', begin);
      long long n = 0;
      if (close == std::string::npos ||
        !ParseInteger(d.substr(begin, close - begin), 0, Limits::MaxMeshPoints, n))
      {
        text.position() = at;
        text.FailAt(std::string(attribute, std::strlen(attribute) - 2) + " \"" +
          Printable(d.substr(begin, std::min<size_t>(close - begin, 40))) +
          "\" is not an integer in [0, " + std::to_string(Limits::MaxMeshPoints) + "]");
      }
      (std::strcmp(attribute, "NumberOfPoints=\"") == 0 ? points : cells) += n;
    }
  }
  if (points > Limits::MaxMeshPoints || cells > Limits::MaxMeshCells)
  {
    text.Fail("the pieces declare " + std::to_string(points) + " points and " +
      std::to_string(cells) + " cells; at most " + std::to_string(Limits::MaxMeshPoints) + " and " +
      std::to_string(Limits::MaxMeshCells) + " are accepted");
  }
}

/// The checks of a mesh file before a VTK reader opens it (`ext` lower case, with the dot).
inline void CheckMeshFile(const std::string& file, const std::string& ext)
{
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status))
  {
    throw InputError(file +
      ": cannot open mesh file: " + (ec ? ec.message() : std::string(std::strerror(ENOENT))));
  }
  if (!std::filesystem::is_regular_file(status))
  {
    throw InputError(file + ": cannot open mesh file: not a regular file");
  }
  if (std::filesystem::file_size(file, ec) == 0 && !ec)
  {
    throw InputError(file + ": the mesh file is empty");
  }
  MeshText text(file, ReadSmallFile(file, Limits::MaxMeshFileBytes, "mesh file"));
  if (ext == ".ply")
  {
    CheckPly(text);
  }
  else if (ext == ".obj")
  {
    CheckObj(text);
  }
  else if (ext == ".stl")
  {
    CheckStl(text);
  }
  else if (ext == ".vtk")
  {
    CheckLegacyVtk(text);
  }
  else if (ext == ".glb" || ext == ".gltf")
  {
    CheckGltf(text, ext == ".glb");
  }
  else if (ext == ".vtp" || ext == ".vtu")
  {
    CheckVtp(text);
  }
  // assimp's formats: the checks above and those of what the reader produced (CheckMeshData).
}

/// The checks of what a reader produced: points and cells present and within the limits, every
/// point finite and within +-1e15, every cell index in range.
inline void CheckMeshData(vtkPolyData* mesh, const std::string& file)
{
  const vtkIdType n = mesh ? mesh->GetNumberOfPoints() : 0;
  if (n == 0)
  {
    throw InputError(file + ": no points could be read (empty or malformed mesh)");
  }
  if (n > Limits::MaxMeshPoints)
  {
    throw InputError(file + ": " + std::to_string(n) + " points; at most " +
      std::to_string(Limits::MaxMeshPoints) + " are accepted");
  }
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    for (double v : x)
    {
      if (!std::isfinite(v) || std::fabs(v) > Limits::MaxCoordinate)
      {
        throw InputError(file + ": point " + std::to_string(i) + " has the coordinate " + Num(v) +
          " (not finite or beyond +-1e15)");
      }
    }
  }
  long long cells = 0, indices = 0;
  for (vtkCellArray* array :
    { mesh->GetVerts(), mesh->GetLines(), mesh->GetPolys(), mesh->GetStrips() })
  {
    if (!array)
    {
      continue;
    }
    cells += array->GetNumberOfCells();
    vtkDataArray* connectivity = array->GetConnectivityArray();
    const vtkIdType m = connectivity ? connectivity->GetNumberOfTuples() : 0;
    indices += m;
    if (cells > Limits::MaxMeshCells || indices > Limits::MaxMeshIndices)
    {
      throw InputError(file + ": more than " + std::to_string(Limits::MaxMeshCells) + " cells or " +
        std::to_string(Limits::MaxMeshIndices) + " cell indices");
    }
    for (vtkIdType i = 0; i < m; ++i)
    {
      const double v = connectivity->GetComponent(i, 0);
      if (!(v >= 0 && v < static_cast<double>(n)))
      {
        throw InputError(file + ": a cell refers to point " + Num(v) +
          ", out of range (the mesh has " + std::to_string(n) + " points)");
      }
    }
  }
  if (cells == 0)
  {
    throw InputError(file + ": the mesh has points but no cells (nothing to draw)");
  }
}

} // namespace RenderKeys

#endif
