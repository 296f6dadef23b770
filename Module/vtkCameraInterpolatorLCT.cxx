#include "vtkCameraInterpolatorLCT.h"

#include "vtkLCTCameraParameters.h"
#include "vtkLCTCheckedSet.h"

#include "lct/CameraKey.h"
#include "lct/Curves.h"
#include "lct/Format.h"
#include "lct/KeyLogs.h"
#include "lct/Keyframes.h"
#include "lct/MonotoneTangents.h"
#include "lct/PathTiming.h"
#include "lct/RebuildOnce.h"
#include "lct/ScrewMotion.h"

#include "vtkCamera.h"
#include "vtkDoubleArray.h"
#include "vtkLCTPathTiming.h"
#include "vtkObjectFactory.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <iterator>
#include <mutex>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkCameraInterpolatorLCT);

namespace
{
lct::CurveScheme toScheme(int type)
{
  switch (type)
  {
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_LINEAR:
      return lct::CurveScheme::Linear;
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_BSPLINE:
      return lct::CurveScheme::BSpline;
    case vtkCameraInterpolatorLCT::INTERPOLATION_TYPE_SUBDIVISION:
      return lct::CurveScheme::Subdivision;
    default:
      return lct::CurveScheme::CatmullRom;
  }
}

struct Key
{
  double Time;
  lct::CameraKey Camera;
  Eigen::Matrix4d CameraMatrix; ///< Hawkins & Grimm's P_b S V, for METHOD_CAMERA_MATRIX
  /// Its own tension, continuity, bias and eases (lct/PathTiming.h).
  lct::KeyTiming Timing;
};

const char* typeName(int type)
{
  static const char* const names[] = { "Linear", "Spline", "BSpline", "Subdivision" };
  return names[std::clamp(type, 0, 3)];
}

/// Why the camera matrices of keys at times `key` and `reference` cannot be combined by curve
/// points of `type` (METHOD_CAMERA_MATRIX), for an error message.
std::string describeMissing(const lct::MissingLog& missing, double key, double reference, int type)
{
  std::ostringstream os;
  os << "with the CameraMatrix method the " << typeName(type)
     << " curve combines the camera matrix of the key at t = " << lct::formatNumber(key)
     << " with that of the key at t = " << lct::formatNumber(reference)
     << " as its reference, but the step between them has no MatrixLog logarithm: "
     << lct::describe(missing.status)
     << " (the default FocalFrame method, SetMethodToFocalFrame(), interpolates any turn)";
  return os.str();
}

/// Whether the CameraMatrix method gives `key` back at its own time: its matrix P_b S V
/// decomposes (lct::fromCameraMatrix) into the key's position, window centre and view angle.
/// A window centre beyond ~1e16 leaves the matrix without their digits (1e20: NaN), so a key
/// the method accepted was refused at its own time. Else `why` says so.
bool cameraMatrixGivesKeyBack(const Key& key, std::string& why)
{
  const char* cause = "";
  const auto parameters = lct::fromCameraKey(key.Camera, &cause);
  const auto back = parameters
    ? lct::fromCameraMatrix(key.CameraMatrix, parameters.value)
    : lct::Result<lct::CameraParameters>::failure(lct::Status::NonFinite);
  if (back)
  {
    const lct::CameraParameters& p = parameters.value;
    const lct::CameraParameters& b = back.value;
    const double reach = p.position.cwiseAbs().maxCoeff() + (p.position - p.focalPoint).norm();
    if ((b.position - p.position).norm() <= 1e-8 * reach &&
      (b.windowCenter - p.windowCenter).norm() <= 1e-8 * (1.0 + p.windowCenter.norm()) &&
      (p.parallelProjection || std::abs(b.viewAngle - p.viewAngle) <= 1e-8 * p.viewAngle))
    {
      return true;
    }
  }
  std::ostringstream os;
  os << "with the CameraMatrix method the key at t = " << lct::formatNumber(key.Time)
     << " is not given back by its own camera matrix, Hawkins & Grimm's P_b S V, which keeps too "
        "few digits of it";
  if (parameters)
  {
    os << " (window centre (" << lct::formatNumber(parameters.value.windowCenter.x()) << ", "
       << lct::formatNumber(parameters.value.windowCenter.y()) << "))";
  }
  os << "; the default FocalFrame method, SetMethodToFocalFrame(), interpolates it";
  why = os.str();
  return false;
}
} // namespace

/// The keys and the logs of their orientations. Only the orientation of the focal frame goes
/// through the key logs: its translation, the focal point, is interpolated linearly (combining
/// whole rigid frames in Polar coordinates would move a focal point that the keys share).
/// Rotations always have logs (the relative and the absolute ones of every key: lct/KeyLogs.h),
/// so those updates cannot fail and no curve point misses one. The camera matrices of the
/// CameraMatrix method may lack a MatrixLog step: under that method every edit and setting is
/// checked first (CheckCameraMatrices, ValidateCameraMatrices), as vtkTransformInterpolatorLCT
/// checks its keys. Edits change the keys in O(log n)
/// and mark the logs stale (appends and replacements update current logs in place); the first
/// evaluation after that rebuilds them, under a mutex, so that evaluations may run concurrently
/// once the keys stop changing.
struct vtkCameraInterpolatorLCT::Internals
{
  lct::Keyframes<Key> Keys;
  std::mutex Mutex;
  std::atomic<bool> OrientationsCurrent{ true };
  lct::KeyLogs Orientations;
  /// Logs of the camera matrices (MatrixLog), built on the first CameraMatrix evaluation after a
  /// change, and why they are missing if they are.
  std::atomic<bool> CameraMatricesCurrent{ false };
  lct::KeyLogs CameraMatrices{ lct::Parametrisation::MatrixLog };
  lct::Status CameraMatricesStatus = lct::Status::Ok;
  std::atomic<bool> ClampReported{ false };
  /// Each key's monotone Spline tangents, rebuilt after any change of the keys.
  std::vector<lct::CameraTangents> KeyTangents;
  std::atomic<bool> KeyTangentsCurrent{ false };

  /// The timing controls and the constant-speed table (eye and focal point: 6-D).
  lct::PathTiming Timing;
  vtkLCTPathTiming::ConstantSpeedTable<6> ConstantSpeedTable;

  /// The largest rotation of a step whose twist the screw motion takes (J(w)^-1 is at most
  /// ~20 |t| below it).
  static constexpr double kScrewWinding = 2.0 * 3.14159265358979323846 - 0.25;

  /// The focal point of the screw motion of the focal frames (lct/ScrewMotion.h) about key r:
  /// f_r + R_r J(w) v with w = sum_j w_j log(R_r^T R_j), v = sum_j w_j J(w_j)^-1 R_r^T (f_j - f_r).
  Eigen::Vector3d ScrewFocalPointAbout(
    const lct::KeyLogs& orientations, const lct::CurveWeights& w, int r) const
  {
    const Eigen::Matrix4d& frame = this->Keys[r].Camera.focalFrame;
    const Eigen::Matrix3d rotation = frame.topLeftCorner<3, 3>();
    const Eigen::Vector3d origin = frame.topRightCorner<3, 1>();
    Eigen::Vector3d rotationSum = Eigen::Vector3d::Zero(), twistSum = Eigen::Vector3d::Zero();
    for (int j = 0; j < w.count; ++j)
    {
      // The orientations' steps are in world axes (lct::worldStep), the screw's in key r's frame:
      // log(R_r^T R_j) = R_r^T log(R_j R_r^T).
      const lct::LogCoords* log = orientations.relative(w.key[j], r);
      Eigen::Vector3d step = log ? Eigen::Vector3d(rotation.transpose() * lct::rotationPart(*log))
                                 : Eigen::Vector3d::Zero(); // rotations always have one
      if (log && std::abs(w.key[j] - r) >= 2)
      {
        // The rotation the orientations combine (continued through the keys between), so that
        // keys sampled from one screw motion give that screw motion; but J(w)^-1 grows without
        // bound as |w| nears 2 pi (a turn of 2 pi has no twist unless it translates along its
        // axis): beyond kScrewWinding the principal step.
        const Eigen::Vector3d continued = rotation.transpose() *
          lct::rotationPart(orientations.continuedRelative(w.key[j], r, *log));
        if (continued.norm() < kScrewWinding)
        {
          step = continued;
        }
      }
      const Eigen::Vector3d t = rotation.transpose() *
        (this->Keys[w.key[j]].Camera.focalFrame.topRightCorner<3, 1>() - origin);
      rotationSum += w.weight[j] * step;
      twistSum += w.weight[j] * lct::screwTwist(step, t);
    }
    return origin + rotation * lct::screwTranslation(rotationSum, twistSum);
  }

  /// The screw focal point about the key of largest weight, blended within the hand-over of
  /// lct::KeyLogs (a weight gap below kHandOver, the same smoothstep) with the one about the
  /// second: no jump where the reference changes, C1.
  Eigen::Vector3d ScrewFocalPoint(
    const lct::KeyLogs& orientations, const lct::CurveWeights& w) const
  {
    const lct::KeyLogs::HandOver h = lct::KeyLogs::handOver(w);
    const Eigen::Vector3d about = this->ScrewFocalPointAbout(orientations, w, w.key[h.first]);
    return h.share == 0.0
      ? about
      : Eigen::Vector3d((1.0 - h.share) * about +
          h.share * this->ScrewFocalPointAbout(orientations, w, w.key[h.second]));
  }

  /// The settings a curve point depends on.
  struct Settings
  {
    int InterpolationType;
    bool ConsistentRotation;
    bool ScrewMotion;
    bool MonotoneTangents;
    int Method;
  };

  static Settings SettingsOf(const vtkCameraInterpolatorLCT* self)
  {
    return { self->InterpolationType, self->ConsistentRotation != 0, self->ScrewMotion != 0,
      self->MonotoneTangents != 0, self->Method };
  }

  /// The curve weights of each part of a camera (lct::CameraPart: orientation, focal point and
  /// screw, channel groups). They differ only for the Spline type's monotone tangents.
  struct CameraWeights
  {
    lct::CurveWeights part[lct::CameraPartCount];
  };

  /// The monotone tangents at key k (lct/MonotoneTangents.h) from the steps to its neighbours;
  /// Catmull-Rom's (the secant) at the end keys.
  lct::CameraTangents ComputeMonotoneTangents(const lct::KeyLogs& orientations, int k) const
  {
    const int n = static_cast<int>(this->Keys.size());
    const double* times = this->Keys.times().data();
    const lct::LogCoords* before = k > 0 ? orientations.relative(k - 1, k) : nullptr;
    const lct::LogCoords* after = k + 1 < n ? orientations.relative(k + 1, k) : nullptr;
    if (!before || !after)
    {
      lct::CameraTangents catmullRom;
      std::fill(std::begin(catmullRom.part), std::end(catmullRom.part),
        lct::catmullRomTangent(times, n, k));
      return catmullRom;
    }
    return lct::monotoneCameraTangents(this->Keys[k - 1].Camera, this->Keys[k].Camera,
      this->Keys[k + 1].Camera, lct::rotationPart(*before), lct::rotationPart(*after),
      times[k] - times[k - 1], times[k + 1] - times[k]);
  }

  /// The curve weights at curve time t: the Spline type with the Kochanek-Bartels tangents where
  /// a key has tension, continuity or bias (lct/PathTiming.h), else the monotone tangents of each
  /// part or, with `monotone` off, Catmull-Rom's.
  CameraWeights WeightsAt(const lct::KeyLogs& orientations, double t, int type, bool monotone)
  {
    const int n = static_cast<int>(this->Keys.size());
    const double* times = this->Keys.times().data();
    const lct::CurveScheme scheme = toScheme(type);
    CameraWeights w;
    if (scheme != lct::CurveScheme::CatmullRom || n < 2 || !monotone)
    {
      const lct::CurveWeights all = scheme == lct::CurveScheme::CatmullRom && n >= 2
        ? lct::curveWeights(scheme, times, n, t,
            lct::splineTangents(
              times, n, lct::curveSegment(times, n, t), this->Timing,
              [this](int k) -> const lct::KeyTiming& { return this->Keys[k].Timing; },
              [times, n](int k) { return lct::catmullRomTangent(times, n, k); }))
        : lct::curveWeights(scheme, times, n, t);
      std::fill(std::begin(w.part), std::end(w.part), all);
      return w;
    }
    const int segment = lct::curveSegment(times, n, t);
    const std::vector<lct::CameraTangents>& tangents = this->MonotoneTangents(orientations);
    const lct::CameraTangents& start = tangents[segment];
    const lct::CameraTangents& end = tangents[segment + 1];
    const auto same = [](const lct::KeyTangent& a, const lct::KeyTangent& b) {
      return a.before == b.before && a.after == b.after;
    };
    for (int p = 0; p < lct::CameraPartCount; ++p)
    {
      // Parts with the same tangents share their weights (at the end keys, and for the parts
      // that do not move, all of them): each set costs a segment search and a Hermite basis.
      int shared = -1;
      for (int q = 0; q < p && shared < 0; ++q)
      {
        if (same(start.part[p], start.part[q]) && same(end.part[p], end.part[q]))
        {
          shared = q;
        }
      }
      w.part[p] = shared >= 0
        ? w.part[shared]
        : lct::curveWeights(scheme, times, n, t,
            lct::splineTangents(
              times, n, segment, this->Timing,
              [this](int k) -> const lct::KeyTiming& { return this->Keys[k].Timing; },
              [&](int k) { return (k == segment ? start : end).part[p]; }));
    }
    return w;
  }

  static bool allFinite(double x) { return std::isfinite(x); }
  static bool allFinite(const Eigen::Vector3d& v) { return v.allFinite(); }

  /// The camera at curve time t; false, with `why`, when it is not representable.
  bool CameraAt(double t, const Settings& settings, lct::CameraParameters& out, std::string& why)
  {
    const lct::KeyLogs& orientations = this->OrientationLogs();
    const CameraWeights parts =
      this->WeightsAt(orientations, t, settings.InterpolationType, settings.MonotoneTangents);
    const lct::CurveWeights& w = parts.part[lct::CameraOrientation];
    lct::CameraKey key;
    const lct::Status status = settings.ConsistentRotation
      ? orientations.combineAbsolute(w, key.focalFrame)
      : orientations.combineRelative(w, key.focalFrame);
    if (status != lct::Status::Ok)
    {
      why = lct::describe(status);
      return false;
    }
    // Combined as steps from the key of largest weight (the sum of the weights being 1): where
    // a key is very close in time to its neighbour, the Spline weights of the two are large and
    // opposite, and their absolute values would cancel catastrophically.
    const auto combine = [this](const lct::CurveWeights& weights, auto valueOf) {
      const int r = weights.key[lct::KeyLogs::handOver(weights).first];
      const auto reference = valueOf(this->Keys[r].Camera);
      auto sum = decltype(reference)(reference);
      for (int j = 0; j < weights.count; ++j)
      {
        if (weights.key[j] != r)
        {
          sum += weights.weight[j] * (valueOf(this->Keys[weights.key[j]].Camera) - reference);
        }
      }
      if (!allFinite(sum))
      {
        // Steps between values beyond half the double range overflow: the weighted sum itself.
        sum = weights.weight[0] * valueOf(this->Keys[weights.key[0]].Camera);
        for (int j = 1; j < weights.count; ++j)
        {
          sum += weights.weight[j] * valueOf(this->Keys[weights.key[j]].Camera);
        }
      }
      return sum;
    };
    const lct::CurveWeights& focalWeights = parts.part[lct::CameraFocalPoint];
    key.focalFrame.topRightCorner<3, 1>() = settings.ScrewMotion && !settings.ConsistentRotation
      ? this->ScrewFocalPoint(orientations, focalWeights)
      : combine(focalWeights, [](const lct::CameraKey& k) -> Eigen::Vector3d {
          return k.focalFrame.topRightCorner<3, 1>();
        });
    for (int c = 0; c < lct::CameraKey::ChannelCount; ++c)
    {
      key.channels[c] = combine(parts.part[lct::cameraChannelPart(c)],
        [c](const lct::CameraKey& k) { return k.channels[c]; });
    }
    key.parallelProjection = this->Keys[0].Camera.parallelProjection;
    key.horizontalViewAngle = this->Keys[0].Camera.horizontalViewAngle;
    const char* cause = "";
    const auto interpolated = lct::fromCameraKey(key, &cause);
    if (!interpolated)
    {
      why = std::string(cause) + " (a spline overshoot between extreme keys?)";
      return false;
    }
    out = interpolated.value;
    if (settings.Method == METHOD_CAMERA_MATRIX)
    {
      const lct::KeyLogs& logs = this->CameraMatrixLogs();
      Eigen::Matrix4d matrix;
      lct::Status matrixStatus = this->CameraMatricesStatus;
      if (matrixStatus == lct::Status::Ok)
      {
        matrixStatus = logs.combineRelative(w, matrix);
      }
      const auto fromMatrix = matrixStatus == lct::Status::Ok
        ? lct::fromCameraMatrix(matrix, out)
        : lct::Result<lct::CameraParameters>::failure(matrixStatus);
      if (!fromMatrix)
      {
        // A missing log cannot be the cause (every key set under this method was checked): the
        // combination's exp, or the decomposition of its result.
        why = std::string("CameraMatrix method: ") + lct::describe(fromMatrix.status);
        return false;
      }
      out = fromMatrix.value;
    }
    return true;
  }

  static Eigen::Matrix4d Orientation(const Key& key)
  {
    Eigen::Matrix4d m = key.Camera.focalFrame;
    m.topRightCorner<3, 1>().setZero();
    return m;
  }

  static std::vector<Eigen::Matrix4d> Matrices(
    const lct::Keyframes<Key>& keys, Eigen::Matrix4d (*of)(const Key&))
  {
    std::vector<Eigen::Matrix4d> out;
    out.reserve(keys.size());
    for (size_t i = 0; i < keys.size(); ++i)
    {
      out.push_back(of(keys[i]));
    }
    return out;
  }

  const lct::KeyLogs& OrientationLogs()
  {
    lct::rebuildOnce(this->OrientationsCurrent, this->Mutex, [this] {
      this->Keys.flatten();
      this->Orientations.build(
        Matrices(this->Keys, &Orientation), lct::Parametrisation::Polar, false);
    });
    return this->Orientations;
  }

  /// Each key's monotone tangents, for the current keys (after OrientationLogs).
  const std::vector<lct::CameraTangents>& MonotoneTangents(const lct::KeyLogs& orientations)
  {
    lct::rebuildOnce(this->KeyTangentsCurrent, this->Mutex, [this, &orientations] {
      this->KeyTangents.resize(this->Keys.size());
      for (size_t k = 0; k < this->Keys.size(); ++k)
      {
        this->KeyTangents[k] = this->ComputeMonotoneTangents(orientations, static_cast<int>(k));
      }
    });
    return this->KeyTangents;
  }

  const lct::KeyLogs& CameraMatrixLogs()
  {
    this->OrientationLogs(); // flattens the keys
    lct::rebuildOnce(this->CameraMatricesCurrent, this->Mutex, [this] {
      this->CameraMatricesStatus = this->CameraMatrices.build(
        Matrices(this->Keys, [](const Key& k) -> Eigen::Matrix4d { return k.CameraMatrix; }),
        lct::Parametrisation::MatrixLog, true);
    });
    return this->CameraMatrices;
  }

  static lct::CurveNeeds CameraMatrixNeeds(int type) { return { toScheme(type), false }; }

  /// Whether an edit at time t (`replacement` the key set there, null for a removal) keeps every
  /// camera-matrix log that curve points of `type` combine; else `why` says which is missing.
  bool CheckCameraMatrices(double t, const Key* replacement, int type, std::string& why) const
  {
    const lct::KeyWindow<Key> window = lct::keyWindow(this->Keys, t, replacement);
    const lct::MissingLog missing = lct::missingAfterEdit(
      window, replacement == nullptr, [](const Key& key) { return key.CameraMatrix; },
      lct::Parametrisation::MatrixLog, CameraMatrixNeeds(type), false);
    if (missing.missing())
    {
      why = describeMissing(
        missing, window.keys[missing.key]->Time, window.keys[missing.reference]->Time, type);
      return false;
    }
    return true;
  }

  /// Checks every camera-matrix log that curve points of `type` combine, in the logs when they
  /// are current, else building them. On failure nothing changes.
  bool ValidateCameraMatrices(int type, std::string& why)
  {
    this->OrientationLogs(); // flattens the keys
    std::lock_guard<std::mutex> lock(this->Mutex);
    for (std::size_t k = 0; k < this->Keys.size(); ++k)
    {
      if (!cameraMatrixGivesKeyBack(this->Keys[k], why))
      {
        return false;
      }
    }
    lct::MissingLog missing;
    if (this->CameraMatricesCurrent && this->CameraMatricesStatus == lct::Status::Ok)
    {
      missing = this->CameraMatrices.missingLog(CameraMatrixNeeds(type));
      if (missing.missing())
      {
        why = describeMissing(
          missing, this->Keys[missing.key].Time, this->Keys[missing.reference].Time, type);
        return false;
      }
      return true;
    }
    lct::KeyLogs logs{ lct::Parametrisation::MatrixLog };
    logs.build(Matrices(this->Keys, [](const Key& k) -> Eigen::Matrix4d { return k.CameraMatrix; }),
      lct::Parametrisation::MatrixLog, true, CameraMatrixNeeds(type), &missing);
    if (missing.missing())
    {
      why = describeMissing(
        missing, this->Keys[missing.key].Time, this->Keys[missing.reference].Time, type);
      return false;
    }
    this->CameraMatrices = std::move(logs);
    this->CameraMatricesStatus = lct::Status::Ok;
    this->CameraMatricesCurrent = true;
    return true;
  }

  void Add(const Key& key)
  {
    const bool replaces = this->Keys.find(key.Time) != nullptr;
    const bool append = this->Keys.isAppend(key.Time);
    bool current = false;
    if (this->OrientationsCurrent && (append || replaces))
    {
      this->Keys.flatten();
      const int index = replaces ? this->Keys.index(key.Time) : static_cast<int>(this->Keys.size());
      current =
        (replaces ? this->Orientations.replace(index, Orientation(key), false)
                  : this->Orientations.insert(index, Orientation(key), false)) == lct::Status::Ok;
    }
    this->Keys.set(key);
    this->OrientationsCurrent = current;
    this->CameraMatricesCurrent = false;
    this->KeyTangentsCurrent = false;
  }

  void Remove(double t)
  {
    this->Keys.erase(t);
    this->OrientationsCurrent = false;
    this->CameraMatricesCurrent = false;
    this->KeyTangentsCurrent = false;
  }

  /// A key at another time than t, if any (all keys share one projection type).
  const Key* Other(double t) const
  {
    const Key* before = this->Keys.before(t);
    return before ? before : this->Keys.after(t);
  }
};

//------------------------------------------------------------------------------
vtkCameraInterpolatorLCT::vtkCameraInterpolatorLCT()
  : Internal(new Internals)
{
}

//------------------------------------------------------------------------------
vtkCameraInterpolatorLCT::~vtkCameraInterpolatorLCT()
{
  delete this->Internal;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::GetNumberOfCameras()
{
  return static_cast<int>(this->Internal->Keys.size());
}

//------------------------------------------------------------------------------
double vtkCameraInterpolatorLCT::GetMinimumT()
{
  return this->Internal->Keys.minimumTime();
}

//------------------------------------------------------------------------------
double vtkCameraInterpolatorLCT::GetMaximumT()
{
  return this->Internal->Keys.maximumTime();
}

//------------------------------------------------------------------------------
void vtkCameraInterpolatorLCT::Initialize()
{
  Internals& in = *this->Internal;
  in.Keys.clear();
  in.Orientations = lct::KeyLogs();
  in.OrientationsCurrent = true;
  in.CameraMatricesCurrent = false;
  in.KeyTangentsCurrent = false;
  in.ClampReported = false; // new keys, a new range: its first clamp is reported again
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::AddCamera(double t, vtkCamera* camera)
{
  if (!camera)
  {
    vtkErrorMacro(<< "AddCamera: null camera; key rejected.");
    return 0;
  }
  if (!std::isfinite(t))
  {
    vtkErrorMacro(<< "AddCamera: the key time " << t << " is not finite; key rejected.");
    return 0;
  }
  if (!this->Internal->Keys.keepsFiniteSpan(t))
  {
    vtkErrorMacro(<< "AddCamera: the key time " << lct::formatNumber(t)
                  << " would make the key times span more than the double range; key rejected.");
    return 0;
  }
  const char* why = "";
  const auto key = lct::toCameraKey(vtkLCTCamera::FromVtk(camera), &why);
  if (!key)
  {
    vtkErrorMacro(<< "AddCamera at t = " << lct::formatNumber(t) << ": " << why
                  << "; key rejected.");
    return 0;
  }
  const Key* other = this->Internal->Other(t);
  const std::string mismatch = other
    ? vtkLCTCamera::KindMismatch(key.value.parallelProjection, key.value.horizontalViewAngle,
        other->Camera.parallelProjection, other->Camera.horizontalViewAngle)
    : std::string();
  if (!mismatch.empty())
  {
    vtkErrorMacro(<< "AddCamera at t = " << lct::formatNumber(t) << ": " << mismatch
                  << "; key rejected.");
    return 0;
  }
  const auto parameters = lct::fromCameraKey(key.value, &why);
  if (!parameters)
  {
    vtkErrorMacro(<< "AddCamera at t = " << lct::formatNumber(t) << ": " << why
                  << "; key rejected.");
    return 0;
  }
  const Key added{ t, key.value, lct::cameraMatrix(parameters.value), {} };
  std::string missing;
  if (this->Method == METHOD_CAMERA_MATRIX &&
    (!cameraMatrixGivesKeyBack(added, missing) ||
      !this->Internal->CheckCameraMatrices(t, &added, this->InterpolationType, missing)))
  {
    vtkErrorMacro(<< "AddCamera at t = " << lct::formatNumber(t) << ": " << missing
                  << "; key rejected.");
    return 0;
  }
  this->Internal->Add(added);
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::RemoveCamera(double t)
{
  if (!this->Internal->Keys.find(t))
  {
    return 1;
  }
  std::string missing;
  if (this->Method == METHOD_CAMERA_MATRIX &&
    !this->Internal->CheckCameraMatrices(t, nullptr, this->InterpolationType, missing))
  {
    vtkErrorMacro(<< "RemoveCamera(" << lct::formatNumber(t) << "): without this key, " << missing
                  << "; not removed.");
    return 0;
  }
  this->Internal->Remove(t);
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::SetInterpolationType(int type)
{
  if (!vtkLCTCheckedSet::InRange(this, "InterpolationType", this->InterpolationType, type,
        static_cast<int>(INTERPOLATION_TYPE_LINEAR),
        static_cast<int>(INTERPOLATION_TYPE_SUBDIVISION)))
  {
    return 0;
  }
  if (type == this->InterpolationType)
  {
    return 1;
  }
  std::string missing;
  if (this->Method == METHOD_CAMERA_MATRIX &&
    !this->Internal->ValidateCameraMatrices(type, missing))
  {
    vtkErrorMacro(<< "SetInterpolationType(" << typeName(type) << "): " << missing
                  << "; unchanged.");
    return 0;
  }
  this->InterpolationType = type;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::SetMethod(int method)
{
  if (!vtkLCTCheckedSet::InRange(this, "Method", this->Method, method,
        static_cast<int>(METHOD_FOCAL_FRAME), static_cast<int>(METHOD_CAMERA_MATRIX)))
  {
    return 0;
  }
  if (method == this->Method)
  {
    return 1;
  }
  std::string missing;
  if (method == METHOD_CAMERA_MATRIX &&
    !this->Internal->ValidateCameraMatrices(this->InterpolationType, missing))
  {
    vtkErrorMacro(<< "SetMethod(CameraMatrix): " << missing << "; unchanged.");
    return 0;
  }
  this->Method = method;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::InterpolateCamera(double t, vtkCamera* camera)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (!camera || n == 0 || !std::isfinite(t))
  {
    vtkErrorMacro(<< "InterpolateCamera: "
                  << (!camera            ? "null camera"
                         : n == 0        ? "no keys"
                         : std::isnan(t) ? "t is NaN"
                                         : "t is infinite")
                  << "; camera unchanged.");
    return 0;
  }
  if ((t < in.Keys.minimumTime() || t > in.Keys.maximumTime()) && !in.ClampReported.exchange(true))
  {
    vtkWarningMacro(<< "InterpolateCamera: t = " << lct::formatNumber(t)
                    << " is outside the key times [" << lct::formatNumber(in.Keys.minimumTime())
                    << ", " << lct::formatNumber(in.Keys.maximumTime())
                    << "]: clamped, as vtkCameraInterpolator does (reported once).");
  }
  double curveTime = t;
  if (!this->CurveTime(t, curveTime, "InterpolateCamera"))
  {
    return 0;
  }
  lct::CameraParameters result;
  std::string why;
  if (!in.CameraAt(curveTime, Internals::SettingsOf(this), result, why))
  {
    vtkErrorMacro(<< "InterpolateCamera(" << lct::formatNumber(t) << "): " << why
                  << "; camera unchanged.");
    return 0;
  }
  vtkLCTCamera::ToVtk(result, camera);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkCameraInterpolatorLCT::CurveTime(double t, double& curveTime, const char* caller)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  in.OrientationLogs(); // flattens the keys
  if (!this->ConstantSpeed || n < 2)
  {
    curveTime = n < 2 ? t : vtkLCTPathTiming::EasedCurveTime(in.Keys, in.Timing, t);
    return true;
  }
  const Internals::Settings settings = Internals::SettingsOf(this);
  const int measure = this->ConstantSpeedMeasure;
  const auto positionAt = [&](double tau, Eigen::Matrix<double, 6, 1>& p, std::string& cause) {
    lct::CameraParameters camera;
    if (!in.CameraAt(tau, settings, camera, cause))
    {
      return false;
    }
    p.head<3>() = measure == CONSTANT_SPEED_FOCAL_POINT ? Eigen::Vector3d::Zero() : camera.position;
    p.tail<3>() = measure == CONSTANT_SPEED_EYE ? Eigen::Vector3d::Zero() : camera.focalPoint;
    return true;
  };
  return in.ConstantSpeedTable.CurveTime(
    this, caller, this->GetMTime(), in.Keys.times().data(), n, in.Timing, t, positionAt, curveTime);
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::GetKeyArrivalTimes(vtkDoubleArray* arrivals)
{
  Internals& in = *this->Internal;
  const int n = static_cast<int>(in.Keys.size());
  if (!arrivals || n == 0)
  {
    vtkErrorMacro(<< "GetKeyArrivalTimes: " << (arrivals ? "no keys" : "null array")
                  << "; nothing written.");
    return 0;
  }
  in.OrientationLogs(); // flattens the keys
  if (!this->ConstantSpeed || n < 2)
  {
    vtkLCTPathTiming::KeyTimes(in.Keys.times(), arrivals);
    return 1;
  }
  double ignored;
  if (!this->CurveTime(in.Keys.minimumTime(), ignored, "GetKeyArrivalTimes"))
  {
    return 0; // CurveTime reported why
  }
  // Built for this MTime by CurveTime.
  in.ConstantSpeedTable.ArrivalTimes(in.Keys.times().data(), n, in.Timing, arrivals);
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::SetTension(double tension)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Tension, tension);
}
int vtkCameraInterpolatorLCT::SetContinuity(double continuity)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Continuity, continuity);
}
int vtkCameraInterpolatorLCT::SetBias(double bias)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::Bias, bias);
}
int vtkCameraInterpolatorLCT::SetEaseIn(double ease)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::EaseIn, ease);
}
int vtkCameraInterpolatorLCT::SetEaseOut(double ease)
{
  return vtkLCTPathTiming::SetPathTiming(
    this, this->Internal->Timing, vtkLCTPathTiming::Setting::EaseOut, ease);
}
double vtkCameraInterpolatorLCT::GetTension()
{
  return this->Internal->Timing.tensionContinuityBias.tension;
}
double vtkCameraInterpolatorLCT::GetContinuity()
{
  return this->Internal->Timing.tensionContinuityBias.continuity;
}
double vtkCameraInterpolatorLCT::GetBias()
{
  return this->Internal->Timing.tensionContinuityBias.bias;
}
double vtkCameraInterpolatorLCT::GetEaseIn()
{
  return this->Internal->Timing.easeIn;
}
double vtkCameraInterpolatorLCT::GetEaseOut()
{
  return this->Internal->Timing.easeOut;
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::SetKeyTensionContinuityBias(
  double t, double tension, double continuity, double bias)
{
  return vtkLCTPathTiming::SetKeyTensionContinuityBias(
    this, this->Internal->Keys, t, { tension, continuity, bias });
}
int vtkCameraInterpolatorLCT::SetKeyEase(double t, double arriving, double leaving)
{
  return vtkLCTPathTiming::SetKeyEase(this, this->Internal->Keys, t, arriving, leaving);
}
int vtkCameraInterpolatorLCT::ClearKeyTiming(double t)
{
  return vtkLCTPathTiming::ClearKeyTiming(this, this->Internal->Keys, t);
}

//------------------------------------------------------------------------------
void vtkCameraInterpolatorLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const types[] = { "Linear", "Spline", "BSpline", "Subdivision" };
  os << indent << "InterpolationType: " << types[this->InterpolationType] << "\n";
  os << indent << "ConsistentRotation: " << (this->ConsistentRotation ? "On" : "Off") << "\n";
  os << indent << "ScrewMotion: " << (this->ScrewMotion ? "On" : "Off") << "\n";
  os << indent << "MonotoneTangents: " << (this->MonotoneTangents ? "On" : "Off") << "\n";
  os << indent << "Method: " << (this->Method == METHOD_FOCAL_FRAME ? "FocalFrame" : "CameraMatrix")
     << "\n";
  vtkLCTPathTiming::Print(os, indent, this->Internal->Timing, this->ConstantSpeed);
  static const char* const measures[] = { "EyeAndFocalPoint", "Eye", "FocalPoint" };
  os << indent << "ConstantSpeedMeasure: " << measures[this->ConstantSpeedMeasure] << "\n";
  os << indent << "NumberOfCameras: " << this->GetNumberOfCameras() << "\n";
  if (!this->Internal->Keys.empty())
  {
    os << indent << "Time range: [" << this->GetMinimumT() << ", " << this->GetMaximumT() << "]\n";
  }
}

//------------------------------------------------------------------------------
int vtkCameraInterpolatorLCT::SetConstantSpeedMeasure(int value)
{
  return vtkLCTCheckedSet::Set(this, "ConstantSpeedMeasure", this->ConstantSpeedMeasure, value,
    static_cast<int>(CONSTANT_SPEED_EYE_AND_FOCAL_POINT),
    static_cast<int>(CONSTANT_SPEED_FOCAL_POINT));
}
