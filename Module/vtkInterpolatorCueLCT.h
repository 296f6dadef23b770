/**
 * @class   vtkInterpolatorCueLCT
 * @brief   an animation cue that drives a camera and props from LCT interpolators, for
 *          vtkAnimationScene (sequence and real-time modes)
 *
 * Add it to a vtkAnimationScene like any vtkAnimationCue. On every tick it maps the cue time
 * onto key time, sets the camera from a vtkCameraInterpolatorLCT and the user matrix of each
 * prop from its vtkTransformInterpolatorLCT, optionally refits the renderer's clipping range,
 * and then fires AnimationCueTickEvent as usual (render or write frames in an observer, as with
 * any cue).
 *
 * Time mapping: with KeyTimeMappingToRange (default), the cue's [StartTime, EndTime] is mapped
 * linearly onto each interpolator's own key range [GetMinimumT(), GetMaximumT()], so every path
 * spans the whole cue whatever its key times. With KeyTimeMappingToCueTime, key time = cue time
 * - StartTime (keys given in seconds of the cue).
 *
 * Props: the interpolated matrix becomes the prop's UserMatrix; keep the prop's own position,
 * orientation, scale and origin at their defaults (keys taken from vtkProp3D::GetMatrix() already
 * contain them). An interpolator that fails (no key) is reported with an error and leaves its
 * camera or prop unchanged for that tick.
 *
 * @sa vtkAnimationScene vtkAnimationCue vtkCameraInterpolatorLCT vtkTransformInterpolatorLCT
 */
#ifndef vtkInterpolatorCueLCT_h
#define vtkInterpolatorCueLCT_h

#include "vtkAnimationCue.h"
#include "vtkLCTModule.h" // For export macro

class vtkCamera;
class vtkCameraInterpolatorLCT;
class vtkProp3D;
class vtkRenderer;
class vtkTransformInterpolatorLCT;

class VTKLCT_EXPORT vtkInterpolatorCueLCT : public vtkAnimationCue
{
public:
  static vtkInterpolatorCueLCT* New();
  vtkTypeMacro(vtkInterpolatorCueLCT, vtkAnimationCue);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The camera to drive and its path. Both null: no camera animation. A path without a camera is
   * reported with an error when the cue starts (StartCueInternal) and not played; a camera
   * without a path stays still (its clipping range is still refitted when a renderer is set).
   */
  void SetCamera(vtkCamera* camera);
  vtkCamera* GetCamera();
  void SetCameraInterpolator(vtkCameraInterpolatorLCT* path);
  vtkCameraInterpolatorLCT* GetCameraInterpolator();
  ///@}

  ///@{
  /**
   * Props moved by transform interpolators. AddProp returns 0 (with an error) for null arguments.
   */
  int AddProp(vtkProp3D* prop, vtkTransformInterpolatorLCT* path);
  void RemoveAllProps();
  int GetNumberOfProps();
  ///@}

  ///@{
  /**
   * When set, the clipping range of the cue's camera is refitted to the renderer's visible props
   * after the props and then the camera move (also for a camera without a path, when the cue
   * moves props) (vtkRenderer::ResetCameraClippingRange; when the
   * cue's camera is not the renderer's active camera it is made active for the fit, and the
   * active camera put back). Default null: the interpolated range is kept.
   */
  void SetRenderer(vtkRenderer* renderer);
  vtkRenderer* GetRenderer();
  ///@}

  enum KeyTimeMappings
  {
    KEY_TIME_MAPPING_RANGE = 0,
    KEY_TIME_MAPPING_CUE_TIME = 1
  };

  ///@{
  /**
   * How cue time maps to key time (see the class description). Default: range.
   */
  virtual int SetKeyTimeMapping(int value);
  int GetKeyTimeMappingMinValue() { return KEY_TIME_MAPPING_RANGE; }
  int GetKeyTimeMappingMaxValue() { return KEY_TIME_MAPPING_CUE_TIME; }
  vtkGetMacro(KeyTimeMapping, int);
  void SetKeyTimeMappingToRange() { this->SetKeyTimeMapping(KEY_TIME_MAPPING_RANGE); }
  void SetKeyTimeMappingToCueTime() { this->SetKeyTimeMapping(KEY_TIME_MAPPING_CUE_TIME); }
  ///@}

  /**
   * The key time of interpolator range [minimumT, maximumT] at cue time `cueTime`, at any
   * magnitude (a cue from -1e308 to 1e308 maps its middle to the middle of the range); cue times
   * outside [StartTime, EndTime] map to the range's ends with range mapping. Where the
   * cue has no valid times (cueTime, StartTime or EndTime NaN or infinite, or EndTime before
   * StartTime with range mapping) there is none: it returns minimumT, and Tick reports the cue's
   * times with an error and moves nothing.
   */
  double KeyTime(double cueTime, double minimumT, double maximumT);

  /**
   * vtkAnimationCue's, reporting a cue that cannot run: StartTime or EndTime NaN or infinite
   * (vtkAnimationCue never starts such a cue, silently) or, with range mapping, EndTime before
   * StartTime.
   */
  void Initialize() override;

protected:
  vtkInterpolatorCueLCT();
  ~vtkInterpolatorCueLCT() override;

  void TickInternal(double currenttime, double deltatime, double clocktime) override;
  void StartCueInternal() override;

  int KeyTimeMapping = KEY_TIME_MAPPING_RANGE;

  /// Whether cue time `cueTime` has a key time (finite times; with range mapping, a cue that
  /// does not end before it starts).
  bool HasValidTimes(double cueTime) const;

private:
  vtkInterpolatorCueLCT(const vtkInterpolatorCueLCT&) = delete;
  void operator=(const vtkInterpolatorCueLCT&) = delete;

  struct Internals;
  Internals* Internal;
};

#endif
