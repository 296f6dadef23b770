// Fuzz target: vtkCameraInterpolatorLCT with arbitrary key cameras and queries. Each input is a
// sequence of AddCamera (position, focal point, view up, view angle, parallel scale, window
// centre, view shear, clipping range, projection; new times, existing times to replace a key,
// NaN/Inf), RemoveCamera, interpolation type (out of range too), ConsistentRotation,
// MonotoneTangents, method (FocalFrame / CameraMatrix), Initialize and the timing controls
// (FuzzTiming.h), interleaved with InterpolateCamera.
//
// Properties: no crash, sanitizer report or hang; AddCamera accepts exactly the keys that
// lct::toCameraKey accepts (finite time, same projection as the others) and the bookkeeping
// matches a shadow model; InterpolateCamera returning 1 reports no error and leaves every
// parameter of the camera finite; returning 0 reported an error and left the camera untouched;
// the interpolating types reproduce a key's position and focal point at its time (without
// ConstantSpeed, which moves key times).
#include "FuzzInput.h"
#include "FuzzTiming.h"

#include "vtkCameraInterpolatorLCT.h"
#include "vtkLCTCameraParameters.h" // the parameters AddCamera reads

#include "lct/CameraKey.h"

#include "vtkCamera.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;

/// What InterpolateCamera writes, read back from the camera.
struct CameraState
{
  double Values[24];

  static CameraState Of(vtkCamera* c)
  {
    CameraState s;
    double* v = s.Values;
    c->GetPosition(v);
    c->GetFocalPoint(v + 3);
    c->GetViewUp(v + 6);
    v[9] = c->GetViewAngle();
    v[10] = c->GetParallelScale();
    c->GetWindowCenter(v + 11);
    c->GetViewShear(v + 13);
    c->GetClippingRange(v + 16);
    v[18] = c->GetDistance();
    c->GetDirectionOfProjection(v + 19);
    v[22] = c->GetParallelProjection();
    v[23] = 0.0;
    return s;
  }
  bool Finite() const { return AllFinite(this->Values, 24); }
  bool Same(const CameraState& o) const { return lct_fuzz::SameBits(this->Values, o.Values, 24); }
  std::string Describe() const
  {
    return "position " + Show(this->Values, 3) + "\nfocal point " + Show(this->Values + 3, 3) +
      "\nview up " + Show(this->Values + 6, 3) + "\nangle, parallel scale " +
      Show(this->Values + 9, 2) + "\nwindow centre " + Show(this->Values + 11, 2) +
      "\nview shear " + Show(this->Values + 13, 3) + "\nclipping range " +
      Show(this->Values + 16, 2) + "\ndistance " + Show(this->Values + 18, 1);
  }
};

struct ShadowKey
{
  bool Parallel;
  lct::CameraParameters Parameters;
  Eigen::Matrix4d CameraMatrix;
};

class Session
{
public:
  explicit Session(lct_fuzz::Input& in)
    : In(in)
  {
    lct_fuzz::QuietOutputWindow::Install();
    this->Errors.Observe(this->Path);
  }

  void Run()
  {
    for (int op = 0; op < 48 && !this->In.Empty(); ++op)
    {
      this->Step();
      this->CheckBookkeeping();
    }
  }

private:
  int ErrorCount() const
  {
    return this->Errors.Errors + lct_fuzz::QuietOutputWindow::Install()->Errors;
  }

  std::map<double, ShadowKey>::iterator Find(double t)
  {
    return std::isnan(t) ? this->Keys.end() : this->Keys.find(t);
  }

  double Time()
  {
    switch (this->In.Byte() % 6)
    {
      case 0:
      case 1:
        if (!this->Keys.empty())
        {
          auto it = this->Keys.begin();
          std::advance(it, this->In.Int(0, static_cast<int>(this->Keys.size()) - 1));
          return it->first;
        }
        return 0.0;
      case 2:
      case 3:
        return static_cast<double>(this->In.Int(-2, 12));
      case 4:
        return this->In.Provider().ConsumeFloatingPointInRange<double>(-1.0, 11.0);
      default:
        return this->In.Double();
    }
  }

  /// A key camera: mostly a sensible one, with any parameter replaced by an arbitrary value.
  void MakeCamera(vtkCamera* c)
  {
    const auto value = [&](double usual) {
      return this->In.Int(0, 5) == 0 ? this->In.Double() : usual;
    };
    const Eigen::Vector3d focal = this->In.Vector();
    Eigen::Vector3d position = focal + this->In.Scale() * this->In.Axis();
    if (this->In.Int(0, 7) == 0)
    {
      position = this->In.Vector();
    }
    const Eigen::Vector3d up = this->In.Int(0, 3) ? Eigen::Vector3d(0, 1, 0) : this->In.Vector();
    const bool parallel = this->In.Int(0, 3) == 0;
    c->SetFocalPoint(focal.data());
    c->SetPosition(position.data());
    c->SetViewUp(up.data());
    c->SetViewAngle(value(this->In.Provider().ConsumeFloatingPointInRange<double>(1.0, 170.0)));
    c->SetParallelScale(value(this->In.Scale()));
    c->SetWindowCenter(value(this->In.Provider().ConsumeFloatingPointInRange<double>(-1.0, 1.0)),
      value(this->In.Provider().ConsumeFloatingPointInRange<double>(-1.0, 1.0)));
    if (this->In.Int(0, 3) == 0)
    {
      c->SetViewShear(value(0.0), value(0.0), value(1.0));
    }
    if (this->In.Int(0, 2) == 0)
    {
      c->SetClippingRange(value(this->In.Scale()), value(this->In.Scale()));
    }
    c->SetParallelProjection(parallel);
  }

  void CheckBookkeeping()
  {
    LCT_FUZZ_CHECK(this->Path->GetNumberOfCameras() == static_cast<int>(this->Keys.size()),
      "the interpolator holds " << this->Path->GetNumberOfCameras() << " keys, the shadow "
                                << this->Keys.size());
    const double lo = this->Keys.empty() ? 0.0 : this->Keys.begin()->first;
    const double hi = this->Keys.empty() ? 0.0 : this->Keys.rbegin()->first;
    LCT_FUZZ_CHECK(this->Path->GetMinimumT() == lo && this->Path->GetMaximumT() == hi,
      "time range [" << this->Path->GetMinimumT() << ", " << this->Path->GetMaximumT()
                     << "], shadow [" << lo << ", " << hi << "]");
  }

  void Add()
  {
    const double t = this->Time();
    vtkNew<vtkCamera> camera;
    this->MakeCamera(camera);
    const bool null = this->In.Int(0, 15) == 0;
    const lct::CameraParameters p = vtkLCTCamera::FromVtk(camera);
    const auto key = lct::toCameraKey(p);
    bool consistent = true;
    for (const auto& [time, other] : this->Keys)
    {
      if (time != t && other.Parallel != p.parallelProjection)
      {
        consistent = false;
      }
    }
    // Key times must keep the span of the times finite (lct/Curves.h), and a key must give its
    // camera back (lct::fromCameraKey: the channels of a key lct::toCameraKey accepts can still
    // leave vtkCamera's range, e.g. near = far / 1e300 rounding).
    const bool finiteSpan = this->Keys.empty() ||
      std::isfinite(
        std::max(t, this->Keys.rbegin()->first) - std::min(t, this->Keys.begin()->first));
    const auto restored =
      key ? lct::fromCameraKey(key.value) : lct::Result<lct::CameraParameters>::failure(key.status);
    const bool valid =
      !null && std::isfinite(t) && finiteSpan && key.ok() && restored.ok() && consistent;
    LCT_FUZZ_TRACE("AddCamera t " << t << (null ? " (null)" : "") << " expected "
                                  << (valid ? "valid" : "invalid") << "\n"
                                  << CameraState::Of(camera).Describe());
    const int errors = this->ErrorCount();
    const int result = this->Path->AddCamera(t, null ? nullptr : camera.Get());
    // The CameraMatrix method also refuses a valid key with which a curve point would combine a
    // camera-matrix step without a MatrixLog logarithm (D19), naming the method.
    const bool refusedByMethod = valid && result == 0 && this->CameraMatrix() &&
      this->Errors.Last.find("with the CameraMatrix method") != std::string::npos;
    LCT_FUZZ_CHECK(result == (valid ? 1 : 0) || refusedByMethod,
      "AddCamera returned " << result << " for a key lct::toCameraKey calls "
                            << (key.ok() ? "valid" : "invalid") << " (t = " << t << ")\n"
                            << CameraState::Of(camera).Describe());
    LCT_FUZZ_CHECK((this->ErrorCount() > errors) == (result == 0),
      "AddCamera: error reporting does not match the result");
    if (result == 1)
    {
      this->Keys[t] = ShadowKey{ p.parallelProjection, p, lct::cameraMatrix(restored.value) };
    }
  }

  bool CameraMatrix() const
  {
    return this->Path->GetMethod() == vtkCameraInterpolatorLCT::METHOD_CAMERA_MATRIX;
  }

  void Remove()
  {
    const double t = this->Time();
    LCT_FUZZ_TRACE("RemoveCamera t " << t);
    const int errors = this->ErrorCount();
    const int result = this->Path->RemoveCamera(t);
    const auto it = this->Find(t);
    if (result == 0)
    {
      // Only the CameraMatrix method refuses, for the steps the removal would bring together.
      LCT_FUZZ_CHECK(this->CameraMatrix() && it != this->Keys.end() &&
          this->ErrorCount() > errors &&
          this->Path->GetNumberOfCameras() == static_cast<int>(this->Keys.size()),
        "RemoveCamera refused: " << this->Errors.Last);
      return;
    }
    LCT_FUZZ_CHECK(this->ErrorCount() == errors, "RemoveCamera reported an error");
    if (it != this->Keys.end())
    {
      this->Keys.erase(it);
    }
  }

  void Interpolate()
  {
    double t;
    switch (this->In.Byte() % 4)
    {
      case 0:
        t = this->Time();
        break;
      case 1:
        t = this->In.Double();
        break;
      default:
        t = this->Path->GetMinimumT() +
          this->In.Provider().ConsumeProbability<double>() *
            (this->Path->GetMaximumT() - this->Path->GetMinimumT());
        break;
    }
    const bool cameraMatrix =
      this->Path->GetMethod() == vtkCameraInterpolatorLCT::METHOD_CAMERA_MATRIX;
    vtkNew<vtkCamera> camera;
    camera->SetPosition(1.0, 2.0, 3.0); // a mark: untouched on failure
    const CameraState before = CameraState::Of(camera);
    LCT_FUZZ_TRACE("InterpolateCamera t " << t << " type " << this->Path->GetInterpolationType()
                                          << " consistent " << this->Path->GetConsistentRotation()
                                          << " method " << this->Path->GetMethod());
    const int errors = this->ErrorCount();
    const int result = this->Path->InterpolateCamera(t, camera);
    const CameraState after = CameraState::Of(camera);
    if (result == 0)
    {
      LCT_FUZZ_CHECK(this->ErrorCount() > errors, "InterpolateCamera returned 0 without an error");
      LCT_FUZZ_CHECK(after.Same(before), "InterpolateCamera failed but changed the camera");
      // The focal-frame method fails only where the weights overshoot (Spline, Subdivision; the
      // Linear and BSpline weights are convex, so every channel stays within those of the keys,
      // each of which gives its camera back) and the camera leaves vtkCamera's range.
      const int type = this->Path->GetInterpolationType();
      const bool overshoot = type == vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SPLINE ||
        type == vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION;
      LCT_FUZZ_CHECK(cameraMatrix || this->Keys.empty() || std::isnan(t) || std::isinf(t) ||
          (overshoot && this->Errors.Last.find("overshoot") != std::string::npos) ||
          (this->Path->GetConstantSpeed() &&
            lct_fuzz::ExplainedConstantSpeedRefusal(this->Errors.Last)),
        "InterpolateCamera (FocalFrame) failed at t = " << t << ": " << this->Errors.Last);
      // The CameraMatrix method may fail on its combination or its decomposition, never for a
      // missing MatrixLog step: the keys that need one are refused (D19). (A combination beyond
      // MatrixLog's magnitude range is a failure of the combination, MagnitudeOutOfRange.)
      LCT_FUZZ_CHECK(!cameraMatrix ||
          (this->Errors.Last.find(lct::describe(lct::Status::NoRealLogarithm)) ==
              std::string::npos &&
            this->Errors.Last.find("has no MatrixLog logarithm") == std::string::npos),
        "InterpolateCamera (CameraMatrix) misses a log at t = " << t << ": " << this->Errors.Last);
      return;
    }
    LCT_FUZZ_CHECK(!this->Keys.empty() && std::isfinite(t),
      "InterpolateCamera succeeded without keys or at a non-finite t");
    LCT_FUZZ_CHECK(this->ErrorCount() == errors, "InterpolateCamera returned 1 with an error");
    LCT_FUZZ_CHECK(after.Finite(),
      "InterpolateCamera returned 1 with a non-finite camera at t = " << t << "\n"
                                                                      << after.Describe());
    // The interpolating types pass through their keys (position and focal point).
    const auto key = this->Find(t);
    const int type = this->Path->GetInterpolationType();
    if (key != this->Keys.end() && !cameraMatrix && !this->Path->GetConstantSpeed() &&
      type != vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE &&
      !this->Path->GetConsistentRotation())
    {
      const lct::CameraParameters& k = key->second.Parameters;
      const double scale = 1.0 + std::max(k.position.norm(), k.focalPoint.norm());
      if (scale <= 1e100)
      {
        const double error =
          std::max((Eigen::Map<const Eigen::Vector3d>(after.Values) - k.position).norm(),
            (Eigen::Map<const Eigen::Vector3d>(after.Values + 3) - k.focalPoint).norm()) /
          scale;
        LCT_FUZZ_CHECK(error <= 1e-6,
          "InterpolateCamera does not reproduce the key at t = "
            << t << " (error " << error << ")\nkey position " << Show(k.position.transpose())
            << ", focal point " << Show(k.focalPoint.transpose()) << "\ngot\n"
            << after.Describe());
      }
    }
  }

  void Timing()
  {
    lct_fuzz::FuzzTiming(
      this->In, this->Path.Get(), [this] { return this->Time(); },
      [this](double t) { return this->Find(t) != this->Keys.end(); },
      this->Keys.empty() ? 0.0 : this->Keys.begin()->first,
      this->Keys.empty() ? 0.0 : this->Keys.rbegin()->first, static_cast<int>(this->Keys.size()),
      [this] { return this->ErrorCount(); },
      [this](lct_fuzz::Input& in) {
        const int measure = in.Int(-2, 4), before = this->Path->GetConstantSpeedMeasure();
        LCT_FUZZ_TRACE("SetConstantSpeedMeasure " << measure);
        // Out of range: refused with an error, the measure unchanged.
        const bool valid = measure >= 0 && measure <= 2;
        const int result = this->Path->SetConstantSpeedMeasure(measure);
        LCT_FUZZ_CHECK(this->Path->GetConstantSpeedMeasure() == (valid ? measure : before),
          "SetConstantSpeedMeasure(" << measure << ") left "
                                     << this->Path->GetConstantSpeedMeasure());
        return std::make_pair(result, valid);
      });
  }

  void Step()
  {
    switch (this->In.Byte() % 11)
    {
      case 10:
        this->Timing();
        break;
      case 0:
      case 1:
      case 2:
        this->Add();
        break;
      case 3:
        this->Remove();
        break;
      case 4:
      {
        const int type = this->In.Int(0, 7) == 0 ? this->In.Int(-3, 9) : this->In.Int(0, 3);
        LCT_FUZZ_TRACE("SetInterpolationType " << type);
        const int old = this->Path->GetInterpolationType();
        const int errors = this->ErrorCount();
        const int result = this->Path->SetInterpolationType(type);
        // Refused (reported, unchanged) out of range, or by the CameraMatrix method.
        const bool valid = type >= 0 && type <= 3;
        LCT_FUZZ_CHECK(result == 1
            ? valid && this->Path->GetInterpolationType() == type && this->ErrorCount() == errors
            : (!valid || this->CameraMatrix()) && this->Path->GetInterpolationType() == old &&
              this->ErrorCount() > errors,
          "SetInterpolationType(" << type << ") returned " << result);
        break;
      }
      case 5:
      {
        const bool on = this->In.Bool();
        if (this->In.Int(0, 3) == 0)
        {
          // The Spline's tangents: monotone (default) or Catmull-Rom; either reproduces the keys.
          LCT_FUZZ_TRACE("MonotoneTangents " << on);
          this->Path->SetMonotoneTangents(on);
          break;
        }
        LCT_FUZZ_TRACE("ConsistentRotation " << on);
        this->Path->SetConsistentRotation(on);
        break;
      }
      case 6:
      {
        const int method = this->In.Int(0, 7) == 0 ? this->In.Int(-2, 4) : this->In.Int(0, 1);
        LCT_FUZZ_TRACE("SetMethod " << method);
        const int old = this->Path->GetMethod();
        const int errors = this->ErrorCount();
        const int result = this->Path->SetMethod(method);
        // Out of [0, 1]: refused (it was clamped); CameraMatrix: refused where a log is missing.
        const bool inRange = method >= 0 && method <= 1;
        LCT_FUZZ_CHECK(result == 1
            ? inRange && this->Path->GetMethod() == method && this->ErrorCount() == errors
            : (!inRange || method == vtkCameraInterpolatorLCT::METHOD_CAMERA_MATRIX) &&
              this->Path->GetMethod() == old && this->ErrorCount() > errors,
          "SetMethod(" << method << ") returned " << result);
        break;
      }
      case 7:
        if (this->In.Int(0, 7) == 0)
        {
          LCT_FUZZ_TRACE("Initialize");
          this->Path->Initialize();
          this->Keys.clear();
          break;
        }
        this->Interpolate();
        break;
      default:
        this->Interpolate();
        break;
    }
  }

  lct_fuzz::Input& In;
  vtkNew<vtkCameraInterpolatorLCT> Path;
  std::map<double, ShadowKey> Keys;
  lct_fuzz::ErrorObserver Errors;
};
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::Input in(data, size);
  Session session(in);
  session.Run();
  return 0;
}
