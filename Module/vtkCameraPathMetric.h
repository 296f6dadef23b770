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
 * whose chord is negligible are skipped). ScreenSpaceExcess does the same with the normalised
 * device coordinates of the composite projection (for the given Aspect). A point that is behind
 * the camera or off screen at some sample has left the view.
 *
 * Lower is better: 0 means every point moves on a straight line, in camera space or on the
 * screen respectively.
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

#include <vector> // For the per-point flags

class vtkCamera;
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
  vtkSetClampMacro(Aspect, double, 1e-6, 1e6);
  vtkGetMacro(Aspect, double);
  ///@}

  ///@{
  /**
   * Number of samples EvaluateInterpolator takes, both ends included. Default 11, at most
   * 100000 (the samples' matrices are kept: 256 bytes each).
   */
  vtkSetClampMacro(NumberOfSamples, int, 2, 100000);
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

protected:
  vtkCameraPathMetric();
  ~vtkCameraPathMetric() override;

  double Aspect = 1.0;
  int NumberOfSamples = 11;
  double CameraSpaceExcess = 0.0;
  double ScreenSpaceExcess = 0.0;
  int NumberOfPointsLeavingView = 0;

private:
  vtkCameraPathMetric(const vtkCameraPathMetric&) = delete;
  void operator=(const vtkCameraPathMetric&) = delete;

  /// Appends the view and composite projection matrices of `camera`.
  void Sample(vtkCamera* camera);
  int Measure();

  std::vector<Eigen::Matrix4d, Eigen::aligned_allocator<Eigen::Matrix4d>> Views, Projections;

  vtkSmartPointer<vtkPoints> Points;
  std::vector<char> LeftView;
};

#endif
