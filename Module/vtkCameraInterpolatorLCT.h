/**
 * @class   vtkCameraInterpolatorLCT
 * @brief   interpolate vtkCamera keys as a rigid focal frame plus log-space intrinsics,
 *          including the centre-of-projection shift (Hawkins & Grimm 2005)
 *
 * A drop-in replacement for vtkCameraInterpolator with the same method names. VTK's class
 * interpolates position, focal point, view-up (as a raw vector), view angle, parallel scale and
 * clipping range one by one, and ignores WindowCenter and ViewShear. This class splits each key
 * camera into (see lct/CameraKey.h):
 *
 * - its focal frame F = [right up back | focal point]: the orientation is interpolated like
 *   vtkTransformInterpolatorLCT does (relative form about the key of largest weight, short way
 *   for turns over 180 degrees between neighbouring keys; or ConsistentRotation to keep a spin),
 *   and where the keys' focal points differ the whole frame moves as a screw (SetScrewMotion,
 *   default on; off: the focal point with the same curve weights, on the curve through the
 *   keys' focal points). The camera therefore turns about its focal point, and a focal point
 *   shared by all keys stays put;
 * - scalar channels with the same curve weights: the distance, f = cot(view angle / 2) and the
 *   parallel scale geometrically, the window centre and view shear linearly, the clipping
 *   range geometrically relative to the distance.
 *
 * Every parameter of a key (position, focal point, orthogonalised view-up, view angle, parallel
 * scale, window centre, view shear, clipping range) is reproduced at the key's time by the
 * interpolating types (Linear, Spline, Subdivision). The clipping range is interpolated, not
 * reset: call vtkRenderer::ResetCameraClippingRange() after InterpolateCamera to refit it to the
 * scene.
 *
 * Keys are copied when added and decomposed once; loading n keys in any order costs
 * O(n log n). Bad keys are rejected with a vtkErrorMacro naming the one condition that failed,
 * and leave the interpolator unchanged (AddCamera returns 0): NaN/Inf, coordinates beyond 1e150
 * (vtkCamera squares distances), position at the focal point, view-up zero or parallel to the
 * view direction, view angle outside (0, 180), parallel scale <= 0, an invalid clipping range,
 * or a key whose projection (parallel / perspective) differs from the keys already present.
 * InterpolateCamera returns 0 and leaves the camera untouched when there is no key, t is NaN or
 * infinite, or the interpolated camera is out of vtkCamera's range (a spline overshoot between
 * extreme keys overflowing the distance, scale or far plane): no NaN or Inf is ever written. A
 * finite t is clamped to [GetMinimumT(), GetMaximumT()] as in VTK, with one vtkWarningMacro per
 * interpolator so the clamp is not silent.
 *
 * Timing (issue #12 §3; lct/PathTiming.h): Kochanek-Bartels tension, continuity and bias of the
 * Spline type per path or per key, eases per key or at the path's ends (keys keep their
 * times), and ConstantSpeed, which reparametrises time by arc length so that the path is
 * travelled evenly (keys are then passed at the times GetKeyArrivalTimes gives). The curve
 * is the same; only when each of its points is reached, and with TCB its tangents, change.
 *
 * Concurrency: once the keys and settings no longer change, InterpolateCamera may be called from
 * several threads at once on one interpolator, each with its own output camera (the key logs
 * and the constant-speed table, rebuilt lazily, are built once, under a mutex;
 * Testing/Unit/TestConcurrency.cxx, run under ThreadSanitizer). Changing keys or settings (the
 * timing ones included) or calling GetKeyArrivalTimes while another thread interpolates is a
 * data race.
 *
 * @warning Derives from vtkObject, not from vtkCameraInterpolator: VTK 9.1 declares that class's
 * methods non-virtual, so a subclass would be silently bypassed through a base pointer.
 *
 * @sa vtkCameraInterpolator vtkTransformInterpolatorLCT vtkCameraPathMetric
 */
#ifndef vtkCameraInterpolatorLCT_h
#define vtkCameraInterpolatorLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"

class vtkCamera;
class vtkDoubleArray;

class VTKLCT_EXPORT vtkCameraInterpolatorLCT : public vtkObject
{
public:
  static vtkCameraInterpolatorLCT* New();
  vtkTypeMacro(vtkCameraInterpolatorLCT, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Number of key cameras.
   */
  int GetNumberOfCameras();

  ///@{
  /**
   * The time range of the keys (0 when there is none).
   */
  double GetMinimumT();
  double GetMaximumT();
  ///@}

  /**
   * Remove all keys.
   */
  void Initialize();

  /**
   * Add a key camera at time t (copied; a key at an existing time is replaced). Returns 1 on
   * success, 0 (with an error, interpolator unchanged) for a bad key (see the class description),
   * or with the CameraMatrix method for one whose camera matrix lacks a logarithm a curve point
   * combines (see SetMethod).
   */
  int AddCamera(double t, vtkCamera* camera);

  /**
   * Remove the key at time t (if any). Returns 1 when it was removed or there was none; 0, with
   * an error and the key kept, when (CameraMatrix method) the keys it leaves would make a curve
   * point combine a camera-matrix logarithm that does not exist.
   */
  int RemoveCamera(double t);

  /**
   * Set `camera` to the interpolated camera at time t (clamped to the key range). Returns 1 on
   * success, 0 when there is no key or t is NaN (the camera is then untouched).
   */
  int InterpolateCamera(double t, vtkCamera* camera);

  /// Linear and Spline have vtkCameraInterpolator's values. Its 2, INTERPOLATION_TYPE_MANUAL
  /// (per-parameter interpolators, which a matrix interpolator does not have), has no
  /// counterpart: here 2 is BSpline, which approximates its keys. Use the named setters.
  enum InterpolationTypes
  {
    INTERPOLATION_TYPE_LINEAR = 0,
    INTERPOLATION_TYPE_SPLINE = 1,
    INTERPOLATION_TYPE_BSPLINE = 2,
    INTERPOLATION_TYPE_SUBDIVISION = 3
  };

  ///@{
  /**
   * The curve scheme (see vtkTransformInterpolatorLCT). Default: Spline, as vtkCameraInterpolator.
   * Returns 1, or 0 with an error (type unchanged) for a value out of range or when, with the
   * CameraMatrix method, a curve point of the new type would combine a camera-matrix
   * logarithm that does not exist.
   */
  int SetInterpolationType(int type);
  vtkGetMacro(InterpolationType, int);
  int GetInterpolationTypeMinValue() { return INTERPOLATION_TYPE_LINEAR; }
  int GetInterpolationTypeMaxValue() { return INTERPOLATION_TYPE_SUBDIVISION; }
  int SetInterpolationTypeToLinear()
  {
    return this->SetInterpolationType(INTERPOLATION_TYPE_LINEAR);
  }
  int SetInterpolationTypeToSpline()
  {
    return this->SetInterpolationType(INTERPOLATION_TYPE_SPLINE);
  }
  int SetInterpolationTypeToBSpline()
  {
    return this->SetInterpolationType(INTERPOLATION_TYPE_BSPLINE);
  }
  int SetInterpolationTypeToSubdivision()
  {
    return this->SetInterpolationType(INTERPOLATION_TYPE_SUBDIVISION);
  }
  ///@}

  ///@{
  /**
   * Keep the winding of a key sequence that turns by more than 180 degrees between keys (see
   * vtkTransformInterpolatorLCT). Default off: turns take the short way. The orientations are
   * then blended by their absolute logs, i.e. about the world axes: the in-betweens depend on
   * the world frame (keys turned together about the scene do not give the same path turned),
   * and an orbit far from the identity orientation is distorted; the default relative form has
   * neither effect. The focal point is combined linearly (ScrewMotion is ignored).
   */
  vtkSetMacro(ConsistentRotation, vtkTypeBool);
  vtkGetMacro(ConsistentRotation, vtkTypeBool);
  vtkBooleanMacro(ConsistentRotation, vtkTypeBool);
  ///@}

  enum Methods
  {
    METHOD_FOCAL_FRAME = 0,
    METHOD_CAMERA_MATRIX = 1
  };

  ///@{
  /**
   * What is interpolated. FocalFrame (default): the decomposition described above.
   * CameraMatrix: Hawkins & Grimm's formulation taken literally (eq. 5, 7; see lct/CameraKey.h):
   * the matrix P_b S V (window centre, focal length and view transform together) by its matrix
   * log relative to the key of largest weight, decomposed back by RQ; skew and anisotropy that
   * appear in between are dropped. Offered for comparison: it moves scene points more, and a step
   * between camera matrices without a real matrix log (large turns) cannot be interpolated.
   * Under this method, AddCamera, RemoveCamera and SetInterpolationType refuse (with an error
   * naming the keys, unchanged) keys with which a curve point would combine such a step, and
   * SetMethod(METHOD_CAMERA_MATRIX) returns 0 (method unchanged) for keys that have one, so an
   * accepted key set never fails InterpolateCamera for a missing log. The FocalFrame method
   * combines rotations only, which always have logarithms.
   */
  int SetMethod(int method);
  vtkGetMacro(Method, int);
  int GetMethodMinValue() { return METHOD_FOCAL_FRAME; }
  int GetMethodMaxValue() { return METHOD_CAMERA_MATRIX; }
  int SetMethodToFocalFrame() { return this->SetMethod(METHOD_FOCAL_FRAME); }
  int SetMethodToCameraMatrix() { return this->SetMethod(METHOD_CAMERA_MATRIX); }
  ///@}

  ///@{
  /**
   * FocalFrame method: move the focal frame [orientation | focal point] as a screw motion where
   * the keys' focal points differ (issue #12 §2): the twist of each key's frame relative to the
   * reference key (its rigid logarithm: rotation vector w and v = J(w)^-1 t; lct/ScrewMotion.h)
   * blended with the curve weights, so the focal point moves on a helix about the turn's axis
   * instead of on the curve through the focal points. Keys sharing their focal point give the
   * same path either way. Default on: it moves scene points less on every set measured (README,
   * camera-path quality: 8.0 % / 17.6 % against 10.3 % / 21.2 % with jittered focal points);
   * ignored with ConsistentRotation (the focal point is then combined linearly).
   */
  vtkSetMacro(ScrewMotion, vtkTypeBool);
  vtkGetMacro(ScrewMotion, vtkTypeBool);
  vtkBooleanMacro(ScrewMotion, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Spline type only: the tangent at each inner key is Fritsch & Butland's monotone tangent
   * (issue #12 §3; lct/MonotoneTangents.h), as vtkTransformInterpolatorLCT's: each neighbouring
   * step weighted by the other's speed, 0 where the motion stops or turns back, never above
   * twice the slower step. Each part of the camera gets its own, from its own steps: the
   * orientation, the focal point (and screw), and each channel group (distance, view angle,
   * parallel scale, window centre, view shear, clipping range). So no part overshoots where it
   * slows down, stops or turns back at a key, whatever the others do: azimuth keys 0, 179.9 and
   * 180 degrees one time unit apart stay below 180 degrees (Catmull-Rom swings 13 degrees past),
   * a camera that only zooms between two keys and turns after the second does not turn back
   * first, one that orbits, then only pans, does not orbit past. The tangents do not depend on
   * the scene's scale. Keys are reproduced and the curve is C1 either way. Default on; off gives
   * plain Catmull-Rom (the curve before issue #12 §3).
   *
   * Not monotone: keys with Kochanek-Bartels tension, continuity or bias (per path: every key;
   * SetKeyTensionContinuityBias: that key) take KB's tangents, which are Catmull-Rom's shaped and
   * may overshoot; the CameraMatrix method combines the whole matrix with the orientation's
   * weights, so its intrinsics may overshoot.
   */
  vtkSetMacro(MonotoneTangents, vtkTypeBool);
  vtkGetMacro(MonotoneTangents, vtkTypeBool);
  vtkBooleanMacro(MonotoneTangents, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Kochanek-Bartels tension, continuity and bias of the Spline type for every key without its
   * own, each in [-1, 1] (else an error, 0 returned, unchanged); applied to the log steps of the
   * focal frame and to the channels alike (lct/KochanekBartels.h). All 0 (default) is
   * Catmull-Rom. Keys are reproduced at their times whatever the values.
   */
  int SetTension(double tension);
  int SetContinuity(double continuity);
  int SetBias(double bias);
  double GetTension();
  double GetContinuity();
  double GetBias();
  ///@}

  ///@{
  /**
   * Ease of the whole path: EaseIn makes it start slowly (from rest at 1), EaseOut end slowly
   * (to rest at 1), each in [0, 1] (else an error, 0 returned, unchanged). Without ConstantSpeed
   * they act on the first and the last key segment; with it, on the whole path.
   */
  int SetEaseIn(double ease);
  int SetEaseOut(double ease);
  double GetEaseIn();
  double GetEaseOut();
  ///@}

  /**
   * Timing of the key at time t: its own tension, continuity and bias (Spline type) and the
   * eases of the motion arriving at it and leaving it, each in [0, 1] (the camera's speed there
   * is multiplied by 1 - ease; lct/Ease.h); the key is still reached at its time. Kept until
   * the key is replaced or removed, or ClearKeyTiming(t). Returns 0, with an error and nothing
   * changed, when there is no key at t or a value is out of range.
   */
  int SetKeyTensionContinuityBias(double t, double tension, double continuity, double bias);
  int SetKeyEase(double t, double arriving, double leaving);
  int ClearKeyTiming(double t);

  enum ConstantSpeedMeasures
  {
    CONSTANT_SPEED_EYE_AND_FOCAL_POINT = 0,
    CONSTANT_SPEED_EYE = 1,
    CONSTANT_SPEED_FOCAL_POINT = 2
  };

  ///@{
  /**
   * Constant speed (default off): reparametrise time by the arc length of the camera's path, so
   * that it moves evenly whatever the key spacing (lct/ArcLength.h). The measure: the eye and
   * the focal point together (default: the length of the path of the pair (eye, focal point)
   * in R^6, so a pan about a fixed eye and a dolly with a fixed focal point both count), the
   * eye alone, or the focal point alone. The path is the same; the keys are passed at the times
   * their distance along it gives (GetKeyArrivalTimes), the first at GetMinimumT() and the last
   * at GetMaximumT(); per-key eases do not apply, EaseIn/EaseOut ease the whole path; stretches
   * in which the measured points stay still (a roll, a zoom) keep their duration.
   */
  vtkSetMacro(ConstantSpeed, vtkTypeBool);
  vtkGetMacro(ConstantSpeed, vtkTypeBool);
  vtkBooleanMacro(ConstantSpeed, vtkTypeBool);
  virtual int SetConstantSpeedMeasure(int value);
  int GetConstantSpeedMeasureMinValue() { return CONSTANT_SPEED_EYE_AND_FOCAL_POINT; }
  int GetConstantSpeedMeasureMaxValue() { return CONSTANT_SPEED_FOCAL_POINT; }
  vtkGetMacro(ConstantSpeedMeasure, int);
  ///@}

  /**
   * The times at which the interpolated path passes each key, in key order: the key times,
   * except under ConstantSpeed. Returns 0 (with an error, `times` untouched) for a null array,
   * no keys, or a path that cannot be measured.
   */
  int GetKeyArrivalTimes(vtkDoubleArray* times);

protected:
  vtkCameraInterpolatorLCT();
  ~vtkCameraInterpolatorLCT() override;

  int InterpolationType = INTERPOLATION_TYPE_SPLINE;
  vtkTypeBool ConsistentRotation = false;
  int Method = METHOD_FOCAL_FRAME;
  vtkTypeBool ScrewMotion = true;
  vtkTypeBool MonotoneTangents = true;
  vtkTypeBool ConstantSpeed = false;
  int ConstantSpeedMeasure = CONSTANT_SPEED_EYE_AND_FOCAL_POINT;

private:
  vtkCameraInterpolatorLCT(const vtkCameraInterpolatorLCT&) = delete;
  void operator=(const vtkCameraInterpolatorLCT&) = delete;

  /// The curve time of output time t (eases, constant speed); false, with an error, when the
  /// constant-speed path cannot be measured.
  bool CurveTime(double t, double& curveTime, const char* caller);

  struct Internals;
  Internals* Internal;
};

#endif
