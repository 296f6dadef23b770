/**
 * @class   vtkCameraPathMetric
 * @brief   measure how far scene points travel along a camera path beyond the straight line:
 *          Hawkins & Grimm's path-quality metric (§5.1)
 *
 * Give the scene points (SetPoints) and a camera path, either an interpolator with a time
 * interval (EvaluateInterpolator, sampled at NumberOfSamples evenly spaced times including both
 * ends; Hawkins & Grimm used the keys plus t = 0.1 .. 0.9, i.e. 11 samples) or the sampled cameras
 * themselves (EvaluateCameras, e.g. from vtkCameraInterpolator for comparison). For each point,
 * l is the length of its sampled path in camera space and l0 the straight chord between its first
 * and last positions; the excess is 100 (l - l0) / l0 percent, averaged over the points (those
 * whose chord is negligible are skipped; negligible is relative to the point's path and
 * distance, so the measure does not change with the scene's size). ScreenSpaceExcess does the
 * same on the screen: the normalised device coordinates of the composite projection for the
 * given Aspect, x times the Aspect, so that both directions count in screen heights as pixels
 * do (points behind the camera at some sample have no screen path and are left out). A point
 * that is behind the camera or off screen at some sample has left the view.
 *
 * Lower is better: 0 means every point moves on a straight line, in camera space or on the
 * screen respectively.
 *
 * That chord from the first to the last sample is Hawkins & Grimm's for a key PAIR. For a path
 * through several keys use the per-segment measure (issue #12): give the true key cameras
 * (AddKeyCamera) and call EvaluateSegments with an interpolator, LCT's or VTK's. Each key
 * segment is then sampled at GetSamplesPerSegment() cameras (a resolution chosen here, so the
 * result does not depend on how many frames are rendered), and each point's length runs from
 * its position in the TRUE key camera, through the path's samples, to its position in the next
 * true key camera: a path that misses its keys pays the misses in its length and can never read
 * below 0. The chord is between the true key positions; the total is against the polygon
 * through them. How far the path misses each key is reported next to the excess (camera space:
 * % of the point's distance; screen: % of the screen height), and points leaving the view are
 * counted only on segments where they are in view at both keys. For VTK's
 * vtkCameraInterpolator, which ignores the window centre, EvaluateSegments can give its
 * cameras the window centre lerped between the keys (the fair baseline; say so when you print
 * it). See lct/SegmentPathMetric.h for the definitions.
 *
 * @sa vtkCameraInterpolatorLCT vtkCameraInterpolator
 */
#ifndef vtkCameraPathMetric_h
#define vtkCameraPathMetric_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For the points

#include <Eigen/Core>      // For the sampled matrices
#include <Eigen/StdVector> // For the sampled matrices

#include <memory> // For the segment results
#include <vector> // For the per-point flags

class vtkCamera;
class vtkCameraInterpolator;
class vtkCameraInterpolatorLCT;
class vtkCollection;
class vtkPoints;

class VTKLCT_EXPORT vtkCameraPathMetric : public vtkObject
{
public:
  static vtkCameraPathMetric* New();
  vtkTypeMacro(vtkCameraPathMetric, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The scene points whose paths are measured (e.g. a mesh's points).
   */
  void SetPoints(vtkPoints* points);
  vtkPoints* GetPoints();
  ///@}

  ///@{
  /**
   * Aspect ratio (width / height) of the viewport for the screen-space measure. Default 1.
   */
  virtual int SetAspect(double value);
  double GetAspectMinValue() { return 1e-6; }
  double GetAspectMaxValue() { return 1e6; }
  vtkGetMacro(Aspect, double);
  ///@}

  ///@{
  /**
   * Number of samples EvaluateInterpolator takes, both ends included. Default 11, at most
   * 100000 (the samples' matrices are kept: 256 bytes each).
   */
  virtual int SetNumberOfSamples(int value);
  int GetNumberOfSamplesMinValue() { return 2; }
  int GetNumberOfSamplesMaxValue() { return 100000; }
  vtkGetMacro(NumberOfSamples, int);
  ///@}

  /**
   * Measure the path of `path` over [t0, t1]. Returns 1 on success, 0 (with an error, results
   * unchanged) without points, with a NaN/Inf point, a null path or non-finite times, if the
   * path fails, or when the excess is undefined: no point has a measurable chord between the
   * first and last samples (a closed path such as a full orbit, or points that do not move).
   */
  int EvaluateInterpolator(vtkCameraInterpolatorLCT* path, double t0, double t1);

  /**
   * Measure the path given by the vtkCamera items of `cameras`, in order (at least two, at most
   * 100000). Returns 1 on success, 0 (with an error, results unchanged) otherwise, for the same
   * reasons as EvaluateInterpolator.
   */
  int EvaluateCameras(vtkCollection* cameras);

  ///@{
  /**
   * Results of the last successful evaluation.
   */
  vtkGetMacro(CameraSpaceExcess, double);
  vtkGetMacro(ScreenSpaceExcess, double);
  vtkGetMacro(NumberOfPointsLeavingView, int);
  /// Whether point i left the view at some sample (0 if i is out of range).
  int GetPointLeftView(vtkIdType i);
  ///@}

  ///@{
  /**
   * The true key cameras the per-segment measure compares a path with (copied; a key at an
   * existing time replaces it). AddKeyCamera returns 0 (with an error, keys unchanged) for a
   * null camera or a non-finite time.
   */
  int AddKeyCamera(double t, vtkCamera* camera);
  void RemoveAllKeyCameras();
  int GetNumberOfKeyCameras();
  ///@}

  ///@{
  /**
   * Cameras sampled per key segment by EvaluateSegments to start with, both keys included.
   * Default 65; 2 to 1000. EvaluateSegments then refines the samples (n -> 2 n - 1) until no
   * excess, per segment or in total, changes by more than 0.01 percentage points, up to 4097
   * per segment, 2e6 in all and 2e8 point projections (a warning says when that budget stops it
   * first): uniform samples in time under-measure a segment whose speed is uneven (keys at 0, 1,
   * 1.001 and 4 read 48.5 % at 65 where the path gives 50.7 %). It is the metric's resolution, not
   * the number of frames a user renders; lower it only for paths with very many keys (the
   * samples' matrices are kept, 256 bytes each). GetSamplesPerSegmentUsed() gives the last
   * evaluation's.
   */
  virtual int SetSamplesPerSegment(int value);
  int GetSamplesPerSegmentMinValue() { return 2; }
  int GetSamplesPerSegmentMaxValue() { return 1000; }
  vtkGetMacro(SamplesPerSegment, int);
  vtkGetMacro(SamplesPerSegmentUsed, int);
  /// Whether the last EvaluateSegments converged within the budget (else it warned: typically
  /// points passing close to the camera's plane, whose screen paths have no bounded length).
  vtkGetMacro(Converged, int);
  ///@}

  ///@{
  /**
   * The per-segment measure of `path` against the key cameras (at least two). With VTK's
   * interpolator and `lerpWindowCenter` on, each sampled camera gets the window centre
   * interpolated linearly in time between the key cameras' (VTK 9.1 ignores the window centre,
   * so its path would otherwise miss every key with a shifted one). A vtkCameraInterpolatorLCT
   * under ConstantSpeed passes its keys at other times than theirs (GetKeyArrivalTimes): each
   * segment is then sampled between the times at which the path passes its two keys, so that
   * the same path reads the same with and without ConstantSpeed (give the metric the path's own
   * keys). Returns 1 on success, 0
   * (with an error, results unchanged) without points or key cameras, with a NaN/Inf point, a
   * null path, a vtkCameraInterpolator with fewer than 2 cameras, a path that fails at a sample,
   * more than 2e6 samples in all, when no point can be measured over the path, or when a
   * segment has no measurable point: every point is behind a camera at some sample of it, or
   * moves and comes back between two key cameras that give the same view (its excess is
   * unbounded; it never reads as 0).
   */
  int EvaluateSegments(vtkCameraInterpolatorLCT* path);
  int EvaluateSegments(vtkCameraInterpolator* path, int lerpWindowCenter);
  ///@}

  ///@{
  /**
   * Results of the last successful EvaluateSegments: per segment k (0 .. keys - 2) and in
   * total (against the polygon through the key positions), excess in camera space and on the
   * screen in percent; points that leave the view between two keys at which they are in view;
   * per key the mean miss of the path (camera space: % of the point's distance; screen: % of
   * the screen height) and the largest over the keys; the time at which the path was compared
   * with each key (its key time, or its arrival time under ConstantSpeed). Out-of-range indices
   * give 0.
   */
  int GetNumberOfSegments();
  double GetSegmentCameraSpaceExcess(int k);
  double GetSegmentScreenSpaceExcess(int k);
  int GetSegmentPointsLeavingView(int k);
  double GetKeyMissCameraSpace(int key);
  double GetKeyMissScreenSpace(int key);
  double GetKeyPassTime(int key);
  vtkGetMacro(TotalCameraSpaceExcess, double);
  vtkGetMacro(TotalScreenSpaceExcess, double);
  vtkGetMacro(NumberOfPointsLeavingViewBetweenKeys, int);
  vtkGetMacro(LargestKeyMissCameraSpace, double);
  vtkGetMacro(LargestKeyMissScreenSpace, double);
  ///@}

protected:
  vtkCameraPathMetric();
  ~vtkCameraPathMetric() override;

  double Aspect = 1.0;
  int NumberOfSamples = 11;
  int SamplesPerSegment = 65;
  int SamplesPerSegmentUsed = 0;
  int Converged = 0;
  double CameraSpaceExcess = 0.0;
  double ScreenSpaceExcess = 0.0;
  int NumberOfPointsLeavingView = 0;
  double TotalCameraSpaceExcess = 0.0;
  double TotalScreenSpaceExcess = 0.0;
  int NumberOfPointsLeavingViewBetweenKeys = 0;
  double LargestKeyMissCameraSpace = 0.0;
  double LargestKeyMissScreenSpace = 0.0;

private:
  vtkCameraPathMetric(const vtkCameraPathMetric&) = delete;
  void operator=(const vtkCameraPathMetric&) = delete;

  /// Appends the view and composite projection matrices of `camera`.
  void Sample(vtkCamera* camera);
  int Measure();
  /// Samples every key segment through `sample(t, camera)` and measures against the keys.
  /// passTimes: the times at which the path passes the keys (null: the keys' own times).
  template <typename Sampler>
  int MeasureSegments(const char* caller, Sampler&& sample, const std::vector<double>* passTimes);

  struct SegmentResults;
  std::unique_ptr<SegmentResults> Segments;

  std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>> Views, Projections;

  vtkSmartPointer<vtkPoints> Points;
  std::vector<char> LeftView;
};

#endif
