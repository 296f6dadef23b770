#include "vtkCameraPathMetric.h"

#include "vtkLCTCameraParameters.h"
#include "vtkLCTCheckedSet.h"

#include "lct/PathMetric.h"
#include "lct/SegmentPathMetric.h"

#include "vtkCamera.h"
#include "vtkCameraInterpolator.h"
#include "vtkCameraInterpolatorLCT.h"
#include "vtkCollection.h"
#include "vtkDoubleArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"

#include <algorithm>
#include <cmath>
#include <map>

vtkStandardNewMacro(vtkCameraPathMetric);

namespace
{
/// EvaluateSegments refines its samples until no excess changes by more than this (percentage
/// points) between n and 2 n - 1 samples per segment, up to this many per segment.
constexpr double kConvergedExcess = 0.01;
constexpr int kMaxRefinedSamplesPerSegment = 4097;
/// The samples the metric keeps at most (256 bytes each).
constexpr double kMaxSamples = 2e6;
/// Refinement stops before points x samples exceeds this (each a projection: seconds of work).
constexpr double kMaxProjections = 2e8;
} // namespace

namespace
{
Eigen::Matrix4d toEigen(vtkMatrix4x4* m)
{
  return Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m->GetData());
}

/// The time `k / n` of the way from `t0` to `t1`; finite for any finite ends (t1 - t0 overflows
/// beyond the double range: t0 = -1e308, t1 = 1e308).
double timeBetween(double t0, double t1, int k, int n)
{
  const double span = t1 - t0;
  if (std::isfinite(span))
  {
    return t0 + span * k / n;
  }
  const double u = static_cast<double>(k) / n;
  return (1.0 - u) * t0 + u * t1;
}

/// Why a camera cannot be measured (the checks of vtkCameraInterpolatorLCT::AddCamera: NaN,
/// position at the focal point, view up along the view direction, ...), or null: a degenerate
/// camera's view matrix has zero rows and gives any excess at all.
const char* cameraProblem(vtkCamera* camera)
{
  const char* why = "";
  return lct::toCameraKey(vtkLCTCamera::FromVtk(camera), &why).ok() ? nullptr : why;
}
} // namespace

/// The key cameras and the results of the per-segment measure.
struct vtkCameraPathMetric::SegmentResults
{
  std::map<double, vtkSmartPointer<vtkCamera>> Keys;
  lct::SegmentPathMetricResult Result;
  std::vector<double> PassTimes; ///< of the last successful EvaluateSegments
};

//------------------------------------------------------------------------------
vtkCameraPathMetric::vtkCameraPathMetric()
  : Segments(new SegmentResults)
{
}
vtkCameraPathMetric::~vtkCameraPathMetric() = default;

//------------------------------------------------------------------------------
int vtkCameraPathMetric::AddKeyCamera(double t, vtkCamera* camera)
{
  if (!camera || !std::isfinite(t))
  {
    vtkErrorMacro(<< "AddKeyCamera: " << (camera ? "the time is not finite" : "null camera")
                  << "; keys unchanged.");
    return 0;
  }
  if (const char* problem = cameraProblem(camera))
  {
    vtkErrorMacro(<< "AddKeyCamera at t = " << t << ": " << problem << "; keys unchanged.");
    return 0;
  }
  for (const auto& [time, key] : this->Segments->Keys)
  {
    // The samples are projected with the keys' projection and kind of view angle
    // (vtkCameraInterpolator sets neither): keys of both kinds have no one kind to measure the
    // path with (vtkCameraInterpolatorLCT refuses such keys too).
    if (time == t)
    {
      continue;
    }
    const std::string mismatch = vtkLCTCamera::KindMismatch(camera->GetParallelProjection() != 0,
      camera->GetUseHorizontalViewAngle() != 0, key->GetParallelProjection() != 0,
      key->GetUseHorizontalViewAngle() != 0);
    if (!mismatch.empty())
    {
      vtkErrorMacro(<< "AddKeyCamera at t = " << t << ": " << mismatch << "; keys unchanged.");
      return 0;
    }
  }
  auto copy = vtkSmartPointer<vtkCamera>::New();
  copy->DeepCopy(camera);
  this->Segments->Keys[t] = copy;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::RemoveAllKeyCameras()
{
  this->Segments->Keys.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::GetNumberOfKeyCameras()
{
  return static_cast<int>(this->Segments->Keys.size());
}

//------------------------------------------------------------------------------
template <typename Sampler>
int vtkCameraPathMetric::MeasureSegments(
  const char* caller, Sampler&& sample, const std::vector<double>* passTimes)
{
  const auto& keys = this->Segments->Keys;
  if (keys.size() < 2)
  {
    vtkErrorMacro(<< caller << ": " << keys.size()
                  << " key cameras (AddKeyCamera); at least 2 are needed; results unchanged.");
    return 0;
  }
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< caller << ": no points to measure; results unchanged.");
    return 0;
  }
  std::vector<Eigen::Vector3d> points(this->Points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < this->Points->GetNumberOfPoints(); ++i)
  {
    this->Points->GetPoint(i, points[i].data());
    if (!points[i].allFinite())
    {
      vtkErrorMacro(<< caller << ": point " << i << " is NaN or Inf; results unchanged.");
      return 0;
    }
  }
  lct::Matrices4d keyViews, keyProjections, views, projections;
  const auto add = [this](vtkCamera* camera, lct::Matrices4d& v, lct::Matrices4d& p) {
    v.push_back(toEigen(camera->GetViewTransformMatrix()));
    p.push_back(toEigen(camera->GetCompositeProjectionTransformMatrix(this->Aspect, -1.0, 1.0)));
    return v.back().allFinite() && p.back().allFinite();
  };
  if (static_cast<double>(keys.size() - 1) * this->SamplesPerSegment > kMaxSamples)
  {
    vtkErrorMacro(<< caller << ": " << keys.size() - 1 << " segments of " << this->SamplesPerSegment
                  << " samples exceed the 2e6 samples the metric keeps; lower SamplesPerSegment. "
                  << "Results unchanged.");
    return 0;
  }
  // The times at which the path passes the keys: their own, or (ConstantSpeed) passTimes.
  if (passTimes && passTimes->size() != keys.size())
  {
    vtkErrorMacro(<< caller << ": the path passes " << passTimes->size()
                  << " keys (ConstantSpeed moves the times at which it passes them) and there "
                  << "are " << keys.size() << " key cameras: give the metric the path's keys "
                  << "(AddKeyCamera) so that each key is compared where the path passes it; "
                  << "results unchanged.");
    return 0;
  }
  std::vector<double> pass;
  if (passTimes)
  {
    pass = *passTimes;
  }
  else
  {
    for (const auto& key : keys)
    {
      pass.push_back(key.first);
    }
  }
  for (const auto& key : keys)
  {
    add(key.second, keyViews, keyProjections);
  }
  // The path's cameras at n samples per segment (both keys included).
  vtkNew<vtkCamera> camera;
  // vtkCameraInterpolator leaves the projection and the kind of view angle as the camera had
  // them: the keys' kinds, as a user renders with (vtkCameraInterpolatorLCT sets both from its
  // keys). A fresh camera is perspective: parallel keys' paths were measured in perspective.
  camera->SetParallelProjection(keys.begin()->second->GetParallelProjection());
  camera->SetUseHorizontalViewAngle(keys.begin()->second->GetUseHorizontalViewAngle());
  // n samples per segment (both keys included). When refining (previous = the n' = (n + 1) / 2
  // samples per segment taken before), sample s = 2 s' is the earlier sample s': the same time
  // exactly (2 s' / (2 (n' - 1)) is s' / (n' - 1) in floating point), so only the midpoints
  // are new and the refinement costs a third less.
  const auto sampleSegments = [&](int n, bool refining) {
    lct::Matrices4d previousViews, previousProjections;
    std::swap(previousViews, views);
    std::swap(previousProjections, projections);
    const int previousN = (n + 1) / 2;
    int k = 0;
    for (auto it = keys.begin(), next = std::next(it); next != keys.end(); ++it, ++next, ++k)
    {
      for (int s = 0; s < n; ++s)
      {
        if (refining && s % 2 == 0)
        {
          const std::size_t earlier = static_cast<std::size_t>(k) * previousN + s / 2;
          views.push_back(previousViews[earlier]);
          projections.push_back(previousProjections[earlier]);
          continue;
        }
        // The ends exactly at the pass times (no rounding of t0 + (t1 - t0) * 1).
        const double t = s == n - 1 ? pass[k + 1] : timeBetween(pass[k], pass[k + 1], s, n - 1);
        if (!sample(t, it, next, camera.Get()))
        {
          vtkErrorMacro(<< caller << ": the path failed at t = " << t << "; results unchanged.");
          return false;
        }
        const char* problem = cameraProblem(camera);
        if (problem || !add(camera, views, projections))
        {
          vtkErrorMacro(<< caller << ": the path's camera at t = " << t << " cannot be measured: "
                        << (problem ? problem : "its matrices overflow") << "; results unchanged.");
          return false;
        }
      }
    }
    return true;
  };
  // Refined (n -> 2 n - 1, the samples so far and the midpoints) until no excess changes by
  // more than kConvergedExcess percentage points: uniform samples in time under-measure a
  // segment whose speed is uneven (keys at 0, 1, 1.001, 4 read 48.5 % at 65 samples where the
  // path's length gives 50.7 %).
  int n = this->SamplesPerSegment;
  if (!sampleSegments(n, false))
  {
    return 0;
  }
  lct::SegmentPathMetricResult r =
    lct::measureSegments(keyViews, keyProjections, views, projections, n, points, this->Aspect);
  const double segments = static_cast<double>(keys.size() - 1);
  bool converged = false;
  const double pointCount = static_cast<double>(points.size());
  while (!converged && 2 * n - 1 <= kMaxRefinedSamplesPerSegment &&
    segments * (2 * n - 1) <= kMaxSamples && pointCount * segments * (2 * n - 1) <= kMaxProjections)
  {
    n = 2 * n - 1;
    if (!sampleSegments(n, true))
    {
      return 0;
    }
    lct::SegmentPathMetricResult finer =
      lct::measureSegments(keyViews, keyProjections, views, projections, n, points, this->Aspect);
    converged = true;
    const auto close = [&](double a, double b) {
      converged = converged && std::abs(a - b) <= kConvergedExcess;
    };
    close(r.total.camera, finer.total.camera);
    close(r.total.screen, finer.total.screen);
    for (std::size_t j = 0; j < r.segments.size() && j < finer.segments.size(); ++j)
    {
      close(r.segments[j].camera, finer.segments[j].camera);
      close(r.segments[j].screen, finer.segments[j].screen);
    }
    r = std::move(finer);
  }
  if (r.total.measuredCamera == 0 || r.total.measuredScreen == 0 ||
    !std::isfinite(r.total.camera) || !std::isfinite(r.total.screen))
  {
    vtkErrorMacro(<< caller << ": no point can be measured over the whole path (each moves and "
                  << "comes back, or is behind a camera at some sample); results unchanged.");
    return 0;
  }
  // A segment none of whose points can be measured has no value: reading 0 there would say the
  // path is straight (e.g. VTK's path wandering between two equal key cameras).
  int k = 0;
  for (auto it = keys.begin(), next = std::next(it); next != keys.end(); ++it, ++next, ++k)
  {
    const lct::SegmentExcess& segment = r.segments[k];
    const bool camera = segment.measuredCamera > 0, screen = segment.measuredScreen > 0;
    if (!camera || !screen || !std::isfinite(segment.camera) || !std::isfinite(segment.screen))
    {
      vtkErrorMacro(<< caller << ": segment " << k << " (key cameras at t = " << it->first
                    << " and " << next->first << ") cannot be measured "
                    << (!camera ? "in camera space" : "on the screen") << ": "
                    << (segment.closedCamera > 0 || segment.closedScreen > 0
                           ? "every point moves between the keys and ends where it started (the "
                             "key cameras give the same view), so its excess over a zero chord "
                             "is unbounded"
                           : "every point is behind a camera at some sample")
                    << "; results unchanged.");
      return 0;
    }
  }
  if (!converged)
  {
    vtkWarningMacro(<< caller << ": the excess has not converged to " << kConvergedExcess
                    << " percentage points at " << n
                    << " samples per segment (the sample budget); it is measured there.");
  }
  this->SamplesPerSegmentUsed = n;
  this->Converged = converged ? 1 : 0;
  this->Segments->Result = std::move(r);
  this->Segments->PassTimes = std::move(pass);
  const lct::SegmentPathMetricResult& out = this->Segments->Result;
  this->TotalCameraSpaceExcess = out.total.camera;
  this->TotalScreenSpaceExcess = out.total.screen;
  this->NumberOfPointsLeavingViewBetweenKeys = out.total.leavingView;
  this->LargestKeyMissCameraSpace = out.largestMiss.camera;
  this->LargestKeyMissScreenSpace = out.largestMiss.screen;
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateSegments(vtkCameraInterpolatorLCT* path)
{
  if (!path)
  {
    vtkErrorMacro(<< "EvaluateSegments: null path; results unchanged.");
    return 0;
  }
  std::vector<double> arrivals;
  if (path->GetConstantSpeed())
  {
    // The path passes its keys at other times than theirs: sample between those.
    vtkNew<vtkDoubleArray> times;
    if (!path->GetKeyArrivalTimes(times))
    {
      vtkErrorMacro(<< "EvaluateSegments: the times at which the ConstantSpeed path passes its "
                    << "keys cannot be computed (see the path's error); results unchanged.");
      return 0;
    }
    for (vtkIdType i = 0; i < times->GetNumberOfTuples(); ++i)
    {
      arrivals.push_back(times->GetValue(i));
    }
  }
  return this->MeasureSegments(
    "EvaluateSegments",
    [path](double t, auto, auto, vtkCamera* c) { return path->InterpolateCamera(t, c) != 0; },
    path->GetConstantSpeed() ? &arrivals : nullptr);
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateSegments(vtkCameraInterpolator* path, int lerpWindowCenter)
{
  if (!path)
  {
    vtkErrorMacro(<< "EvaluateSegments: null path; results unchanged.");
    return 0;
  }
  if (path->GetNumberOfCameras() < 2)
  {
    // VTK 9.1 leaves the camera untouched then: the metric would measure a default vtkCamera.
    vtkErrorMacro(<< "EvaluateSegments: the vtkCameraInterpolator has "
                  << path->GetNumberOfCameras()
                  << " cameras; it interpolates none below 2; results unchanged.");
    return 0;
  }
  return this->MeasureSegments(
    "EvaluateSegments",
    [path, lerpWindowCenter](double t, auto key, auto next, vtkCamera* c) {
      path->InterpolateCamera(t, c); // VTK 9.1 reports no failure
      if (lerpWindowCenter)
      {
        const double u = (t - key->first) / (next->first - key->first);
        const double* a = key->second->GetWindowCenter();
        const double* b = next->second->GetWindowCenter();
        c->SetWindowCenter((1 - u) * a[0] + u * b[0], (1 - u) * a[1] + u * b[1]);
      }
      return true;
    },
    nullptr);
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::GetNumberOfSegments()
{
  return static_cast<int>(this->Segments->Result.segments.size());
}

//------------------------------------------------------------------------------
double vtkCameraPathMetric::GetSegmentCameraSpaceExcess(int k)
{
  return k >= 0 && k < this->GetNumberOfSegments() ? this->Segments->Result.segments[k].camera
                                                   : 0.0;
}

//------------------------------------------------------------------------------
double vtkCameraPathMetric::GetSegmentScreenSpaceExcess(int k)
{
  return k >= 0 && k < this->GetNumberOfSegments() ? this->Segments->Result.segments[k].screen
                                                   : 0.0;
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::GetSegmentPointsLeavingView(int k)
{
  return k >= 0 && k < this->GetNumberOfSegments() ? this->Segments->Result.segments[k].leavingView
                                                   : 0;
}

//------------------------------------------------------------------------------
double vtkCameraPathMetric::GetKeyMissCameraSpace(int key)
{
  const auto& keys = this->Segments->Result.keys;
  return key >= 0 && key < static_cast<int>(keys.size()) ? keys[key].camera : 0.0;
}

//------------------------------------------------------------------------------
double vtkCameraPathMetric::GetKeyMissScreenSpace(int key)
{
  const auto& keys = this->Segments->Result.keys;
  return key >= 0 && key < static_cast<int>(keys.size()) ? keys[key].screen : 0.0;
}

//------------------------------------------------------------------------------
double vtkCameraPathMetric::GetKeyPassTime(int key)
{
  const auto& times = this->Segments->PassTimes;
  return key >= 0 && key < static_cast<int>(times.size()) ? times[key] : 0.0;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::SetPoints(vtkPoints* points)
{
  if (this->Points != points)
  {
    this->Points = points;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPoints* vtkCameraPathMetric::GetPoints()
{
  return this->Points;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::Sample(vtkCamera* camera)
{
  this->Views.push_back(toEigen(camera->GetViewTransformMatrix()));
  this->Projections.push_back(
    toEigen(camera->GetCompositeProjectionTransformMatrix(this->Aspect, -1.0, 1.0)));
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::Measure()
{
  std::vector<Eigen::Vector3d> points(this->Points->GetNumberOfPoints());
  for (vtkIdType i = 0; i < this->Points->GetNumberOfPoints(); ++i)
  {
    this->Points->GetPoint(i, points[i].data());
    if (!points[i].allFinite())
    {
      vtkErrorMacro(<< "point " << i << " is NaN or Inf; results unchanged.");
      return 0;
    }
  }
  for (size_t s = 0; s < this->Views.size(); ++s)
  {
    if (!this->Views[s].allFinite() || !this->Projections[s].allFinite())
    {
      vtkErrorMacro(<< "camera sample " << s << " has a NaN or Inf matrix; results unchanged.");
      return 0;
    }
  }
  const lct::PathMetricResult r =
    lct::measurePath(this->Views, this->Projections, points, this->Aspect);
  if (r.closedCamera > 0 || r.closedScreen > 0)
  {
    vtkErrorMacro(<< "the path is closed for " << std::max(r.closedCamera, r.closedScreen) << " of "
                  << points.size() << " points: they move but end where they started "
                  << (r.closedCamera > 0 ? "in camera space" : "on the screen")
                  << " (e.g. a full orbit), so their excess over a zero chord is unbounded; "
                  << "measure an open part of the path. Results unchanged.");
    return 0;
  }
  if (r.pointsMeasuredScreen == 0)
  {
    vtkErrorMacro(<< "no point stays in front of the camera over the whole path: the screen-space "
                  << "excess is undefined. Results unchanged.");
    return 0;
  }
  if (!std::isfinite(r.cameraSpaceExcess) || !std::isfinite(r.screenSpaceExcess))
  {
    vtkErrorMacro(<< "the path gives non-finite path lengths; results unchanged.");
    return 0;
  }
  this->CameraSpaceExcess = r.cameraSpaceExcess;
  this->ScreenSpaceExcess = r.screenSpaceExcess;
  this->LeftView = r.leftView;
  this->NumberOfPointsLeavingView = 0;
  for (char left : this->LeftView)
  {
    this->NumberOfPointsLeavingView += left ? 1 : 0;
  }
  this->Modified();
  return 1;
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateInterpolator(vtkCameraInterpolatorLCT* path, double t0, double t1)
{
  if (!path || !std::isfinite(t0) || !std::isfinite(t1))
  {
    vtkErrorMacro(<< "EvaluateInterpolator: null path or non-finite times; results unchanged.");
    return 0;
  }
  if (t0 == t1)
  {
    vtkErrorMacro(<< "EvaluateInterpolator: t0 = t1 = " << t0
                  << ": one camera is no path (nothing to measure); results unchanged.");
    return 0;
  }
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "EvaluateInterpolator: no points to measure; results unchanged.");
    return 0;
  }
  this->Views.clear();
  this->Projections.clear();
  vtkNew<vtkCamera> camera; // one camera, re-used: memory does not grow with the samples
  for (int k = 0; k < this->NumberOfSamples; ++k)
  {
    const double t = timeBetween(t0, t1, k, this->NumberOfSamples - 1);
    if (!path->InterpolateCamera(t, camera))
    {
      vtkErrorMacro(<< "EvaluateInterpolator: the path failed at t = " << t
                    << "; results unchanged.");
      return 0;
    }
    this->Sample(camera);
  }
  return this->Measure();
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::EvaluateCameras(vtkCollection* collection)
{
  if (!this->Points || this->Points->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "EvaluateCameras: no points to measure; results unchanged.");
    return 0;
  }
  const int count = collection ? collection->GetNumberOfItems() : 0;
  if (count < 2 || count > 100000)
  {
    vtkErrorMacro(<< "EvaluateCameras: " << count
                  << " cameras; 2 to 100000 are needed; results unchanged.");
    return 0;
  }
  this->Views.clear();
  this->Projections.clear();
  for (int i = 0; i < count; ++i)
  {
    vtkCamera* camera = vtkCamera::SafeDownCast(collection->GetItemAsObject(i));
    if (!camera)
    {
      vtkErrorMacro(<< "EvaluateCameras: item " << i << " is not a vtkCamera; results "
                    << "unchanged.");
      return 0;
    }
    if (const char* problem = cameraProblem(camera))
    {
      vtkErrorMacro(<< "EvaluateCameras: camera " << i << ": " << problem
                    << "; results unchanged.");
      return 0;
    }
    this->Sample(camera);
  }
  return this->Measure();
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::GetPointLeftView(vtkIdType i)
{
  return (i >= 0 && i < static_cast<vtkIdType>(this->LeftView.size()) && this->LeftView[i]) ? 1 : 0;
}

//------------------------------------------------------------------------------
void vtkCameraPathMetric::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Points: " << this->Points.Get() << "\n";
  os << indent << "Aspect: " << this->Aspect << "\n";
  os << indent << "NumberOfSamples: " << this->NumberOfSamples << "\n";
  os << indent << "CameraSpaceExcess: " << this->CameraSpaceExcess << " %\n";
  os << indent << "ScreenSpaceExcess: " << this->ScreenSpaceExcess << " %\n";
  os << indent << "NumberOfPointsLeavingView: " << this->NumberOfPointsLeavingView << "\n";
  os << indent << "SamplesPerSegment: " << this->SamplesPerSegment << "\n";
  os << indent << "SamplesPerSegmentUsed: " << this->SamplesPerSegmentUsed << "\n";
  os << indent << "Converged: " << this->Converged << "\n";
  os << indent << "NumberOfKeyCameras: " << this->GetNumberOfKeyCameras() << "\n";
  os << indent << "NumberOfSegments: " << this->GetNumberOfSegments() << "\n";
  os << indent << "TotalCameraSpaceExcess: " << this->TotalCameraSpaceExcess << " %\n";
  os << indent << "TotalScreenSpaceExcess: " << this->TotalScreenSpaceExcess << " %\n";
  os << indent
     << "NumberOfPointsLeavingViewBetweenKeys: " << this->NumberOfPointsLeavingViewBetweenKeys
     << "\n";
  os << indent << "LargestKeyMissCameraSpace: " << this->LargestKeyMissCameraSpace << " %\n";
  os << indent << "LargestKeyMissScreenSpace: " << this->LargestKeyMissScreenSpace << " %\n";
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::SetAspect(double value)
{
  return vtkLCTCheckedSet::Set(
    this, "Aspect", this->Aspect, value, static_cast<double>(1e-6), static_cast<double>(1e6));
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::SetNumberOfSamples(int value)
{
  return vtkLCTCheckedSet::Set(this, "NumberOfSamples", this->NumberOfSamples, value,
    static_cast<int>(2), static_cast<int>(100000));
}

//------------------------------------------------------------------------------
int vtkCameraPathMetric::SetSamplesPerSegment(int value)
{
  return vtkLCTCheckedSet::Set(this, "SamplesPerSegment", this->SamplesPerSegment, value,
    static_cast<int>(2), static_cast<int>(1000));
}
