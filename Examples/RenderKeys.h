// Keyframes for Examples/lct-render.cxx: the JSON keyframe file format, its validation (messages
// name the file and the key, e.g. `keys.json: camera.keys[3].view_angle must be in (0, 180)`) and
// the built-in keys (the CameraFlightScene flight plus a spinning, shearing cone).
//
// Header-only: everything is `inline`. Needs nlohmann_json and VTK::RenderingCore.
#ifndef RenderKeys_h
#define RenderKeys_h

#include "CameraFlightScene.h"

#include "vtkCamera.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"

#include <nlohmann/json.hpp>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iostream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace RenderKeys
{

/// An input error; what() is the complete message (file name first).
struct InputError : std::runtime_error
{
  using std::runtime_error::runtime_error;
};

struct CameraKey
{
  double Time = 0.0;
  vtkSmartPointer<vtkCamera> Camera;
  std::string Path; // "camera.keys[3]", for messages
};

struct PropKey
{
  double Time = 0.0;
  std::array<double, 16> Matrix{}; // row-major 4x4
  std::string Path;
};

struct PropTrack
{
  std::string Interpolation; // empty: the camera's
  bool ConsistentRotation = false;
  std::vector<PropKey> Keys;
};

struct Keys
{
  std::string Source = "built-in keys"; // file name, for messages
  std::string Interpolation = "spline";
  bool ConsistentRotation = false; // camera
  std::vector<CameraKey> Camera;
  std::map<std::string, PropTrack> Props;
};

inline bool IsInterpolationName(const std::string& name)
{
  return name == "linear" || name == "spline" || name == "bspline" || name == "subdivision";
}

/// Row-major matrix of translate * rotate * shear * scale (a point is scaled, sheared, rotated,
/// then translated). rotate = {angle in degrees, axis}; shear = {xy, xz, yz}: x += xy y + xz z,
/// y += yz z.
inline std::array<double, 16> ComposeTRS(
  const double translate[3], const double rotate[4], const double scale[3], const double shear[3])
{
  double axis[3] = { rotate[1], rotate[2], rotate[3] };
  double r[3][3];
  const double n = vtkMath::Norm(axis);
  if (n > 0.0)
  {
    const double a = vtkMath::RadiansFromDegrees(rotate[0]);
    const double c = std::cos(a), s = std::sin(a), C = 1.0 - c;
    const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
    const double rr[3][3] = { { c + x * x * C, x * y * C - z * s, x * z * C + y * s },
      { y * x * C + z * s, c + y * y * C, y * z * C - x * s },
      { z * x * C - y * s, z * y * C + x * s, c + z * z * C } };
    std::memcpy(r, rr, sizeof r);
  }
  else
  {
    vtkMath::Identity3x3(r);
  }
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

  void Warn(const std::string& what) const
  {
    std::cerr << this->File << ": warning: " << what << "\n";
  }

  void CheckKeys(
    const nlohmann::json& object, const std::string& path, const std::set<std::string>& known) const
  {
    for (auto it = object.begin(); it != object.end(); ++it)
    {
      if (!known.count(it.key()))
      {
        this->Warn("unknown key " + (path.empty() ? "" : path + ".") + it.key() + " (ignored)");
      }
    }
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

  double Number(const nlohmann::json& v, const std::string& path) const
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
    return d;
  }

  /// Reads key as an array of n finite numbers into out; returns false when absent.
  bool Vector(const nlohmann::json& object, const char* key, const std::string& path, size_t n,
    double* out) const
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
      out[i] = this->Number(v[i], p + "[" + std::to_string(i) + "]");
    }
    return true;
  }

  double Time(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.contains("time"))
    {
      this->Fail(path + ".time is missing");
    }
    return this->Number(key.at("time"), path + ".time");
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
      this->Fail(path + ".interpolation: unknown interpolation \"" + name +
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

  CameraKey ReadCameraKey(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.is_object())
    {
      this->Fail(path + " must be an object");
    }
    this->CheckKeys(key, path,
      { "time", "position", "focal_point", "view_up", "view_angle", "window_center", "view_shear",
        "parallel_scale", "parallel", "clipping_range" });
    CameraKey out;
    out.Path = path;
    out.Time = this->Time(key, path);
    double position[3], focal[3], up[3] = { 0.0, 1.0, 0.0 }, center[2] = { 0.0, 0.0 },
                                  shear[3] = { 0.0, 0.0, 1.0 }, range[2] = { 0.01, 1000.01 };
    if (!this->Vector(key, "position", path, 3, position))
    {
      this->Fail(path + ".position is missing");
    }
    if (!this->Vector(key, "focal_point", path, 3, focal))
    {
      this->Fail(path + ".focal_point is missing");
    }
    this->Vector(key, "view_up", path, 3, up);
    this->Vector(key, "window_center", path, 2, center);
    this->Vector(key, "view_shear", path, 3, shear);
    const bool hasRange = this->Vector(key, "clipping_range", path, 2, range);
    double angle = 30.0, scale = 1.0;
    bool parallel = false;
    if (key.contains("view_angle"))
    {
      angle = this->Number(key.at("view_angle"), path + ".view_angle");
      if (!(angle > 0.0 && angle < 180.0))
      {
        this->Fail(path + ".view_angle must be in (0, 180)");
      }
    }
    if (key.contains("parallel_scale"))
    {
      scale = this->Number(key.at("parallel_scale"), path + ".parallel_scale");
      if (!(scale > 0.0))
      {
        this->Fail(path + ".parallel_scale must be > 0");
      }
    }
    if (key.contains("parallel"))
    {
      parallel = this->Bool(key.at("parallel"), path + ".parallel");
    }
    double direction[3];
    vtkMath::Subtract(focal, position, direction);
    const double distance = vtkMath::Norm(direction);
    if (!(distance > 1e-12 * (1.0 + vtkMath::Norm(position))))
    {
      this->Fail(path + " is degenerate: position equals focal_point");
    }
    double cross[3];
    vtkMath::Cross(direction, up, cross);
    if (!(vtkMath::Norm(cross) > 1e-9 * distance * vtkMath::Norm(up)))
    {
      this->Fail(path + " is degenerate: view_up is zero or parallel to the view direction");
    }
    if (hasRange && !(range[0] > 0.0 && range[1] > range[0]))
    {
      this->Fail(path + ".clipping_range must be [near, far] with 0 < near < far");
    }
    out.Camera = vtkSmartPointer<vtkCamera>::New();
    vtkCamera* c = out.Camera;
    c->SetPosition(position);
    c->SetFocalPoint(focal);
    c->SetViewUp(up);
    c->SetViewAngle(angle);
    c->SetWindowCenter(center[0], center[1]);
    c->SetViewShear(shear);
    c->SetParallelScale(scale);
    c->SetParallelProjection(parallel ? 1 : 0);
    c->SetClippingRange(range);
    return out;
  }

  PropKey ReadPropKey(const nlohmann::json& key, const std::string& path) const
  {
    if (!key.is_object())
    {
      this->Fail(path + " must be an object");
    }
    this->CheckKeys(key, path, { "time", "matrix", "translate", "rotate", "scale", "shear" });
    PropKey out;
    out.Path = path;
    out.Time = this->Time(key, path);
    if (key.contains("matrix"))
    {
      for (const char* other : { "translate", "rotate", "scale", "shear" })
      {
        if (key.contains(other))
        {
          this->Fail(path + " has both matrix and " + other + " (give one or the other)");
        }
      }
      this->Vector(key, "matrix", path, 16, out.Matrix.data());
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
      this->Vector(key, "translate", path, 3, t);
      if (this->Vector(key, "rotate", path, 4, r) && r[0] != 0.0 && vtkMath::Norm(r + 1) == 0.0)
      {
        this->Fail(path + ".rotate: the axis [ax, ay, az] must not be zero");
      }
      this->Vector(key, "scale", path, 3, s);
      if (!(s[0] > 0.0 && s[1] > 0.0 && s[2] > 0.0))
      {
        this->Fail(path + ".scale must be positive (a mirror has no rotation log)");
      }
      this->Vector(key, "shear", path, 3, h);
      out.Matrix = ComposeTRS(t, r, s, h);
    }
    return out;
  }

  Keys Read(const std::string& text) const
  {
    nlohmann::json doc;
    try
    {
      doc = nlohmann::json::parse(text);
    }
    catch (const nlohmann::json::parse_error& e)
    {
      // e.byte: 1-based index of the last byte read.
      size_t line = 1, column = 1;
      const size_t end = std::min<size_t>(e.byte > 0 ? e.byte - 1 : 0, text.size());
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
      std::string what = e.what();
      const size_t bracket = what.find("] ");
      if (what.rfind("[json.exception", 0) == 0 && bracket != std::string::npos)
      {
        what = what.substr(bracket + 2);
      }
      throw InputError(this->File + ":" + std::to_string(line) + ":" + std::to_string(column) +
        ": JSON parse error: " + what);
    }
    if (!doc.is_object())
    {
      this->Fail("the top level must be an object with \"camera\" (and optionally \"props\")");
    }
    this->CheckKeys(doc, "", { "camera", "props" });
    Keys keys;
    keys.Source = this->File;
    const nlohmann::json& camera = this->Object(doc, "camera", "");
    this->CheckKeys(camera, "camera", { "interpolation", "keys", "consistent_rotation" });
    if (camera.contains("interpolation"))
    {
      keys.Interpolation = this->Interpolation(camera, "camera");
    }
    if (camera.contains("consistent_rotation"))
    {
      keys.ConsistentRotation =
        this->Bool(camera.at("consistent_rotation"), "camera.consistent_rotation");
    }
    if (!camera.contains("keys") || !camera.at("keys").is_array())
    {
      this->Fail("camera.keys must be an array of key cameras");
    }
    const nlohmann::json& cameraKeys = camera.at("keys");
    std::map<double, std::string> times;
    for (size_t i = 0; i < cameraKeys.size(); ++i)
    {
      CameraKey key = this->ReadCameraKey(cameraKeys[i], "camera.keys[" + std::to_string(i) + "]");
      if (times.count(key.Time))
      {
        this->Fail(
          key.Path + ".time " + std::to_string(key.Time) + " repeats " + times[key.Time] + ".time");
      }
      times[key.Time] = key.Path;
      if (!keys.Camera.empty() &&
        keys.Camera.front().Camera->GetParallelProjection() != key.Camera->GetParallelProjection())
      {
        this->Fail(key.Path +
          ".parallel differs from camera.keys[0].parallel (all keys must "
          "use the same projection)");
      }
      keys.Camera.push_back(key);
    }
    if (keys.Camera.size() < 2)
    {
      this->Fail("camera.keys: needs at least 2 keys, found " + std::to_string(keys.Camera.size()));
    }
    if (doc.contains("props"))
    {
      const nlohmann::json& props = this->Object(doc, "props", "");
      for (auto it = props.begin(); it != props.end(); ++it)
      {
        const std::string path = "props." + it.key();
        if (!it.value().is_object())
        {
          this->Fail(path + " must be an object");
        }
        this->CheckKeys(it.value(), path, { "keys", "interpolation", "consistent_rotation" });
        PropTrack track;
        if (it.value().contains("interpolation"))
        {
          track.Interpolation = this->Interpolation(it.value(), path);
        }
        if (it.value().contains("consistent_rotation"))
        {
          track.ConsistentRotation =
            this->Bool(it.value().at("consistent_rotation"), path + ".consistent_rotation");
        }
        if (!it.value().contains("keys") || !it.value().at("keys").is_array() ||
          it.value().at("keys").empty())
        {
          this->Fail(path + ".keys must be a non-empty array of keys");
        }
        const nlohmann::json& propKeys = it.value().at("keys");
        std::map<double, std::string> propTimes;
        for (size_t i = 0; i < propKeys.size(); ++i)
        {
          PropKey key = this->ReadPropKey(propKeys[i], path + ".keys[" + std::to_string(i) + "]");
          if (propTimes.count(key.Time))
          {
            this->Fail(key.Path + ".time repeats " + propTimes[key.Time] + ".time");
          }
          propTimes[key.Time] = key.Path;
          track.Keys.push_back(key);
        }
        keys.Props[it.key()] = track;
      }
    }
    return keys;
  }

private:
  std::string File;
};

/**
 * A camera key from a ParaView camera file (.pvcc, written by ParaView's "Save Camera": a
 * PVCameraConfiguration holding the render view's Camera* properties). Position, focal point and
 * view up are required; view angle, parallel scale and parallel projection are read when
 * present. Throws InputError naming the file and the missing or malformed property.
 */
inline CameraKey ReadPvcc(const std::string& file, double time)
{
  vtkNew<vtkXMLDataParser> parser;
  parser->SetFileName(file.c_str());
  if (!std::ifstream(file).good())
  {
    throw InputError(file + ": cannot open camera file: " + std::strerror(errno));
  }
  parser->SetIgnoreCharacterData(1);
  if (!parser->Parse() || !parser->GetRootElement() ||
    std::string(parser->GetRootElement()->GetName()) != "PVCameraConfiguration")
  {
    throw InputError(file + ": not a ParaView camera file (no PVCameraConfiguration element)");
  }
  // name -> values of the <Property name=...><Element index=i value=v/></Property> elements.
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
    const char* name = e->GetAttribute("name");
    if (std::string(e->GetName()) != "Property" || !name)
    {
      continue;
    }
    std::vector<double>& values = properties[name];
    for (int i = 0; i < e->GetNumberOfNestedElements(); ++i)
    {
      vtkXMLDataElement* element = e->GetNestedElement(i);
      int index = -1;
      double value = 0.0;
      if (std::string(element->GetName()) == "Element" &&
        element->GetScalarAttribute("index", index) &&
        element->GetScalarAttribute("value", value) && index >= 0 && index < 16)
      {
        values.resize(std::max<size_t>(values.size(), index + 1), 0.0);
        values[index] = value;
      }
    }
  }
  auto vector3 = [&](const char* name) {
    const auto it = properties.find(name);
    if (it == properties.end() || it->second.size() != 3)
    {
      throw InputError(file + ": " + name + " is missing or not 3 numbers");
    }
    return it->second;
  };
  CameraKey key;
  key.Time = time;
  key.Path = "camera (" + file + ")";
  key.Camera = vtkSmartPointer<vtkCamera>::New();
  key.Camera->SetPosition(vector3("CameraPosition").data());
  key.Camera->SetFocalPoint(vector3("CameraFocalPoint").data());
  key.Camera->SetViewUp(vector3("CameraViewUp").data());
  const auto angle = properties.find("CameraViewAngle");
  if (angle != properties.end() && angle->second.size() == 1)
  {
    key.Camera->SetViewAngle(angle->second[0]);
  }
  const auto scale = properties.find("CameraParallelScale");
  if (scale != properties.end() && scale->second.size() == 1)
  {
    key.Camera->SetParallelScale(scale->second[0]);
  }
  const auto parallel = properties.find("CameraParallelProjection");
  if (parallel != properties.end() && parallel->second.size() == 1)
  {
    key.Camera->SetParallelProjection(parallel->second[0] != 0.0);
  }
  return key;
}

/// Reads and validates a keyframe file; throws InputError.
inline Keys ReadFile(const std::string& file)
{
  std::ifstream in(file, std::ios::binary);
  if (!in)
  {
    throw InputError(file + ": cannot open keys file: " + std::strerror(errno));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
  {
    throw InputError(file + ": cannot read keys file");
  }
  return Parser(file).Read(text.str());
}

} // namespace RenderKeys

#endif
