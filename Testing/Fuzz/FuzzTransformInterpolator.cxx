// Fuzz target: vtkTransformInterpolatorLCT with arbitrary key sequences. Each input is a sequence
// of AddTransform (vtkMatrix4x4 / vtkTransform / vtkProp3D / null; new times, the time of an
// existing key to replace it, neighbouring doubles, NaN/Inf), RemoveTransform, SetBezierControls,
// interpolation type (including out-of-range values), parametrisation, ConsistentRotation and
// Initialize, the timing controls (tension, continuity, bias, eases per path and per key,
// ConstantSpeed and its point, any double including NaN/Inf; GetKeyArrivalTimes), interleaved
// with InterpolateTransform into all three output types at key times, between them, outside the
// range, at NaN and +-Inf.
//
// Properties: no crash, sanitizer report or hang; the key bookkeeping matches a shadow model
// (count, time range, which calls succeed); a call returning 1 reports no error and its output is
// finite and affine; a call returning 0 reported an error and left the output untouched; a key
// time is reproduced by the interpolating types (without ConstantSpeed, which moves key times);
// a timing setter succeeds exactly for values in its range and a key at the time, else reports;
// arrival times are finite, in order, from the first key time to the last.
#include "FuzzInput.h"
#include "FuzzTiming.h"

#include "vtkLogTransform.h"
#include "vtkTransformInterpolatorLCT.h"

#include "lct/Affine.h"
#include "lct/Parametrisation.h"
#include "lct/PolarParametrisation.h"

#include "vtkAssembly.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkSmartPointer.h"
#include "vtkTransform.h"

#include <Eigen/SVD>

#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace
{
using lct_fuzz::AllFinite;
using lct_fuzz::Show;
using RowMajor4 = Eigen::Matrix<double, 4, 4, Eigen::RowMajor>;

Eigen::Matrix4d FromVtk(vtkMatrix4x4* m)
{
  return RowMajor4(Eigen::Map<const RowMajor4>(m->GetData()));
}

void ToVtk(const Eigen::Matrix4d& m, vtkMatrix4x4* out)
{
  const RowMajor4 r = m;
  out->DeepCopy(r.data());
}

/// Singular values in [1e-30, 1e30] within `condition`: a key whose reproduction can be checked.
bool WellConditioned(const Eigen::Matrix4d& m, double condition)
{
  if (lct::validateAffine(m) != lct::Status::Ok)
  {
    return false;
  }
  const Eigen::Vector3d s =
    Eigen::JacobiSVD<Eigen::Matrix3d>(Eigen::Matrix3d(m.topLeftCorner<3, 3>())).singularValues();
  return s[2] >= 1e-30 && s[0] <= 1e30 && s[0] <= condition * s[2] &&
    m.topRightCorner<3, 1>().norm() <= 1e30;
}

/// What the interpolator should hold.
struct ShadowKey
{
  Eigen::Matrix4d Matrix;
  bool HasIncoming = false;
  bool HasOutgoing = false;
  Eigen::Matrix4d Incoming;
  Eigen::Matrix4d Outgoing;
};

class Session
{
public:
  explicit Session(lct_fuzz::Input& in)
    : In(in)
  {
    lct_fuzz::QuietOutputWindow::Install();
    this->Errors.Observe(this->Path);
    this->Errors.Observe(this->LogOutput);
    this->LogOutputIsMatrixLog = in.Bool();
    if (this->LogOutputIsMatrixLog)
    {
      this->LogOutput->SetParametrisationToMatrixLog();
    }
  }

  void Run()
  {
    for (int op = 0; op < 64 && !this->In.Empty(); ++op)
    {
      this->Step();
      this->CheckBookkeeping();
    }
  }

private:
  bool MatrixLog() const
  {
    return this->Path->GetParametrisation() == vtkTransformInterpolatorLCT::MATRIX_LOG;
  }

  /// std::map::find treats NaN as equivalent to every key (NaN breaks the ordering).
  std::map<double, ShadowKey>::iterator Find(double t)
  {
    return std::isnan(t) ? this->Keys.end() : this->Keys.find(t);
  }

  int ErrorCount() const
  {
    return this->Errors.Errors + lct_fuzz::QuietOutputWindow::Install()->Errors;
  }

  /// A key time: an existing one (to replace it), its neighbouring double, small integers, or
  /// anything.
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
          if (this->In.Int(0, 3) == 0)
          {
            return std::nextafter(it->first, this->In.Bool() ? 1e308 : -1e308);
          }
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

  void CheckBookkeeping()
  {
    const int n = this->Path->GetNumberOfTransforms();
    LCT_FUZZ_CHECK(n == static_cast<int>(this->Keys.size()),
      "the interpolator holds " << n << " keys, the shadow " << this->Keys.size());
    const double lo = this->Keys.empty() ? 0.0 : this->Keys.begin()->first;
    const double hi = this->Keys.empty() ? 0.0 : this->Keys.rbegin()->first;
    LCT_FUZZ_CHECK(this->Path->GetMinimumT() == lo && this->Path->GetMaximumT() == hi,
      "time range [" << this->Path->GetMinimumT() << ", " << this->Path->GetMaximumT()
                     << "], shadow [" << lo << ", " << hi << "]");
    const int type = this->Path->GetInterpolationType();
    LCT_FUZZ_CHECK(type >= 0 && type <= 4, "interpolation type " << type);
  }

  void Add()
  {
    const double t = this->Time();
    const Eigen::Matrix4d m = this->In.Matrix();
    const int form = this->In.Int(0, 7);
    LCT_FUZZ_TRACE("AddTransform t " << t << " form " << form << "\n" << Show(m));
    const int errors = this->ErrorCount();
    int result = 0;
    Eigen::Matrix4d stored = m;
    vtkNew<vtkMatrix4x4> matrix;
    ToVtk(m, matrix);
    switch (form)
    {
      case 0:
        result = this->Path->AddTransform(t, static_cast<vtkMatrix4x4*>(nullptr));
        break;
      case 1:
      case 2:
        result = this->Path->AddTransform(t, matrix.Get());
        break;
      case 3:
      case 4:
      {
        vtkNew<vtkTransform> transform;
        transform->SetMatrix(matrix);
        stored = FromVtk(transform->GetMatrix());
        result = this->Path->AddTransform(t, transform.Get());
        break;
      }
      default:
      {
        vtkNew<vtkAssembly> prop;
        prop->SetUserMatrix(matrix);
        if (form == 7)
        {
          prop->SetPosition(this->In.Finite(), this->In.Finite(), this->In.Finite());
          prop->SetOrientation(this->In.Finite(), this->In.Finite(), this->In.Finite());
          prop->SetScale(this->In.Scale());
        }
        stored = FromVtk(prop->GetMatrix());
        result = this->Path->AddTransform(t, static_cast<vtkProp3D*>(prop.Get()));
        break;
      }
    }
    // Key times must keep the span of the times finite (lct/Curves.h: the weights divide by it).
    const bool finiteSpan = this->Keys.empty() ||
      std::isfinite(
        std::max(t, this->Keys.rbegin()->first) - std::min(t, this->Keys.begin()->first));
    const bool valid =
      form != 0 && std::isfinite(t) && finiteSpan && lct::validateAffine(stored) == lct::Status::Ok;
    if (result == 1)
    {
      LCT_FUZZ_CHECK(valid,
        "AddTransform accepted an invalid key (t = " << t << ")\n"
                                                     << Show(stored));
      LCT_FUZZ_CHECK(this->ErrorCount() == errors, "AddTransform returned 1 and reported an error");
      ShadowKey key;
      key.Matrix = stored;
      this->Keys[t] = key; // a replaced key loses its Bezier controls
    }
    else
    {
      LCT_FUZZ_CHECK(result == 0 && this->ErrorCount() > errors,
        "AddTransform returned " << result << " without an error");
      // Polar refuses a valid key only when a step to a neighbour has no log (e.g. a product
      // too close to singular), MatrixLog also for a missing real log; both are reported.
    }
  }

  void Remove()
  {
    const double t = this->Time();
    LCT_FUZZ_TRACE("RemoveTransform t " << t);
    const int errors = this->ErrorCount();
    const int before = this->Path->GetNumberOfTransforms();
    const int result = this->Path->RemoveTransform(t);
    const int after = this->Path->GetNumberOfTransforms();
    const auto it = this->Find(t);
    if (it == this->Keys.end())
    {
      LCT_FUZZ_CHECK(result == 1 && after == before && this->ErrorCount() == errors,
        "RemoveTransform of a time without a key changed something");
      return;
    }
    if (after == before - 1)
    {
      this->Keys.erase(it);
      LCT_FUZZ_CHECK(result == 1 && this->ErrorCount() == errors,
        "RemoveTransform removed and reported an error or returned " << result);
    }
    else
    {
      // Refused: the keys left would miss a log the curve combines (reported, key kept).
      LCT_FUZZ_CHECK(result == 0 && after == before && this->ErrorCount() > errors,
        "RemoveTransform neither removed the key nor reported why");
    }
  }

  void BezierControls()
  {
    const double t = this->Time();
    const bool hasIncoming = this->In.Bool();
    const bool hasOutgoing = this->In.Bool();
    const Eigen::Matrix4d incoming = this->In.Matrix();
    const Eigen::Matrix4d outgoing = this->In.Matrix();
    LCT_FUZZ_TRACE("SetBezierControls t " << t << " in " << hasIncoming << " out " << hasOutgoing
                                          << "\n"
                                          << Show(incoming) << "\n"
                                          << Show(outgoing));
    vtkNew<vtkMatrix4x4> in, out;
    ToVtk(incoming, in);
    ToVtk(outgoing, out);
    const int errors = this->ErrorCount();
    const int result = this->Path->SetBezierControls(
      t, hasIncoming ? in.Get() : nullptr, hasOutgoing ? out.Get() : nullptr);
    const auto it = this->Find(t);
    // A control is validated like a key on its own: it must have a Polar log (finite, affine,
    // det > 0, within the conditioning and range of the core).
    const auto usable = [](const Eigen::Matrix4d& m) { return lct::polarLog(m).ok(); };
    const bool valid = it != this->Keys.end() && (!hasIncoming || usable(incoming)) &&
      (!hasOutgoing || usable(outgoing));
    // A Bezier curve also refuses controls with which its curve points would miss a log (D19).
    const bool bezier =
      this->Path->GetInterpolationType() == vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BEZIER;
    LCT_FUZZ_CHECK(result == (valid ? 1 : 0) || (valid && bezier && result == 0),
      "SetBezierControls returned " << result << " for a " << (valid ? "valid" : "invalid")
                                    << " call");
    LCT_FUZZ_CHECK((this->ErrorCount() > errors) == (result == 0),
      "SetBezierControls: error reporting does not match the result");
    if (result == 1)
    {
      it->second.HasIncoming = hasIncoming;
      it->second.HasOutgoing = hasOutgoing;
      it->second.Incoming = incoming;
      it->second.Outgoing = outgoing;
    }
  }

  void Parametrisation()
  {
    const int choice = this->In.Int(0, 6);
    const int p = choice < 3
      ? vtkTransformInterpolatorLCT::POLAR
      : (choice < 6 ? vtkTransformInterpolatorLCT::MATRIX_LOG : this->In.Int(-2, 4));
    LCT_FUZZ_TRACE("SetParametrisation " << p);
    const int old = this->Path->GetParametrisation();
    const int errors = this->ErrorCount();
    const int result = this->Path->SetParametrisation(p);
    if (result == 1)
    {
      LCT_FUZZ_CHECK(this->Path->GetParametrisation() == p && this->ErrorCount() == errors,
        "SetParametrisation returned 1 but did not take cleanly");
    }
    else
    {
      LCT_FUZZ_CHECK(this->Path->GetParametrisation() == old && this->ErrorCount() > errors,
        "SetParametrisation failed without an error or changed the parametrisation");
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
    const int form = this->In.Int(0, 2);
    LCT_FUZZ_TRACE("InterpolateTransform t "
      << t << " form " << form << " type " << this->Path->GetInterpolationType() << " "
      << (this->MatrixLog() ? "MatrixLog" : "Polar") << " consistent "
      << this->Path->GetConsistentRotation());
    const int errors = this->ErrorCount();
    int result = 0;
    Eigen::Matrix4d before, after;
    switch (form)
    {
      case 0:
      {
        vtkNew<vtkMatrix4x4> out;
        out->SetElement(0, 3, 12345.0); // a mark: untouched on failure
        before = FromVtk(out);
        result = this->Path->InterpolateTransform(t, out.Get());
        after = FromVtk(out);
        break;
      }
      case 1:
      {
        vtkNew<vtkTransform> out;
        out->Translate(12345.0, 0.0, 0.0);
        before = FromVtk(out->GetMatrix());
        result = this->Path->InterpolateTransform(t, out.Get());
        after = FromVtk(out->GetMatrix());
        break;
      }
      default:
      {
        const double mark[16] = { 1, 0, 0, 12345.0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1 };
        this->LogOutput->SetMatrix(mark);
        before = FromVtk(this->LogOutput->GetMatrix());
        result = this->Path->InterpolateTransform(t, this->LogOutput.Get());
        after = FromVtk(this->LogOutput->GetMatrix());
        break;
      }
    }
    if (result == 0)
    {
      LCT_FUZZ_CHECK(
        this->ErrorCount() > errors, "InterpolateTransform returned 0 without an error");
      LCT_FUZZ_CHECK(lct_fuzz::SameBits(before.data(), after.data(), 16),
        "InterpolateTransform failed but changed the output");
      // Accepted keys must interpolate inside their range, in either parametrisation and for
      // every type: every call that changes which logs the curve combines checks them (D19). A
      // failure must be a refusal lct/KeyLogs.h documents for the combination (a result out of
      // range, too ill-conditioned, or inaccurate between ill-conditioned keys), or the
      // output's own SetMatrix.
      const bool explained = this->Keys.empty() || !std::isfinite(t) ||
        this->Errors.LastSource != this->Path.Get() ||
        lct_fuzz::ExplainedRefusal(this->Errors.Last) ||
        (this->Path->GetConstantSpeed() &&
          lct_fuzz::ExplainedConstantSpeedRefusal(this->Errors.Last));
      LCT_FUZZ_CHECK(explained,
        "InterpolateTransform (" << (this->MatrixLog() ? "MatrixLog" : "Polar") << ", type "
                                 << this->Path->GetInterpolationType() << ") failed at t = " << t
                                 << " with accepted keys: " << this->Errors.Last);
      return;
    }
    LCT_FUZZ_CHECK(!this->Keys.empty() && std::isfinite(t),
      "InterpolateTransform succeeded without keys or at a non-finite t");
    LCT_FUZZ_CHECK(this->ErrorCount() == errors, "InterpolateTransform returned 1 with an error");
    LCT_FUZZ_CHECK(AllFinite(after) && after.row(3) == Eigen::RowVector4d(0.0, 0.0, 0.0, 1.0),
      "InterpolateTransform returned 1 with a non-finite or non-affine output at t = "
        << t << "\n"
        << Show(after));
    // The interpolating types pass through their keys.
    const int type = this->Path->GetInterpolationType();
    const auto key = this->Find(t);
    if (key != this->Keys.end() && !this->Path->GetConstantSpeed() &&
      type != vtkTransformInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE &&
      !this->Path->GetConsistentRotation() && WellConditioned(key->second.Matrix, 1e6))
    {
      const Eigen::Matrix4d& k = key->second.Matrix;
      const double error = (after - k).norm() / std::max(1.0, k.norm());
      // Into a vtkLogTransform the key also makes a round trip through that output's log and
      // exp, which at condition 1e6 keeps ~1e-6 (as FuzzLogTransform measures SetMatrix).
      const double tolerance = form == 2 ? 1e-2 : 1e-6;
      LCT_FUZZ_CHECK(error <= tolerance,
        "InterpolateTransform does not reproduce the key at t = " << t << " (error " << error
                                                                  << ")\nkey\n"
                                                                  << Show(k) << "\ngot\n"
                                                                  << Show(after));
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
        const double p[3] = { in.Double(), in.Double(), in.Double() };
        LCT_FUZZ_TRACE("SetConstantSpeedPoint " << p[0] << " " << p[1] << " " << p[2]);
        return std::make_pair(this->Path->SetConstantSpeedPoint(p),
          std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]));
      });
  }

  void Step()
  {
    switch (this->In.Byte() % 13)
    {
      case 12:
        this->Timing();
        break;
      case 0:
      case 1:
      case 2:
      case 3:
        this->Add();
        break;
      case 4:
        this->Remove();
        break;
      case 5:
        this->BezierControls();
        break;
      case 6:
      {
        const int type = this->In.Int(0, 7) == 0 ? this->In.Int(-3, 9) : this->In.Int(0, 4);
        LCT_FUZZ_TRACE("SetInterpolationType " << type);
        const int old = this->Path->GetInterpolationType();
        const int errors = this->ErrorCount();
        const int result = this->Path->SetInterpolationType(type);
        // Refused (reported, unchanged) out of range, or when the keys miss a log its curve
        // points combine.
        const bool valid = type >= 0 && type <= 4;
        LCT_FUZZ_CHECK(result == 1
            ? valid && this->Path->GetInterpolationType() == type && this->ErrorCount() == errors
            : result == 0 && this->Path->GetInterpolationType() == old &&
              this->ErrorCount() > errors && (!valid || !this->Keys.empty()),
          "SetInterpolationType(" << type << ") returned " << result << ", type "
                                  << this->Path->GetInterpolationType());
        break;
      }
      case 7:
        this->Parametrisation();
        break;
      case 8:
      {
        const bool on = this->In.Bool();
        LCT_FUZZ_TRACE("ConsistentRotation " << on);
        const vtkTypeBool old = this->Path->GetConsistentRotation();
        const int errors = this->ErrorCount();
        const int result = this->Path->SetConsistentRotation(on);
        LCT_FUZZ_CHECK(result == 1
            ? this->Path->GetConsistentRotation() == on && this->ErrorCount() == errors
            : result == 0 && this->Path->GetConsistentRotation() == old &&
              this->ErrorCount() > errors &&
              (!this->Keys.empty() || (on && this->MatrixLog())), // MatrixLog: Polar only
          "SetConsistentRotation(" << on << ") returned " << result);
        break;
      }
      case 9:
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
  vtkNew<vtkTransformInterpolatorLCT> Path;
  vtkNew<vtkLogTransform> LogOutput;
  bool LogOutputIsMatrixLog = false;
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
