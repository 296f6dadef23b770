/**
 * @class   vtkTransformInterpolatorLCT
 * @brief   interpolate a sequence of whole affine transforms in log space (Alexa 2002,
 *          Hawkins & Grimm 2005, Kaji & Ochiai 2016)
 *
 * A drop-in replacement for vtkTransformInterpolator with the same method names. Where VTK's
 * class splits each key into translation, quaternion and a diagonal scale (so keys with shear or
 * scale along rotated axes are not reproduced), this one interpolates the log coordinates of the
 * whole matrix: every output is the key of largest weight K_r = [L_r, t_r] moved by the weighted
 * log steps to the others, [exp(sum_i w_i log(L_i L_r^-1)) L_r, sum_i w_i t_i] (MatrixLog:
 * K_r exp(sum_i w_i log(K_r^-1 K_i))), one weighted sum and one exp, with the weights w_i of the
 * chosen curve scheme (the relative form of Hawkins & Grimm eq. 7, its linear step in world axes
 * as theirs, the translation as the weighted sum: a translation the keys share stays put, a bone
 * keeps its length, and no in-between is stretched beyond the keys). Rotations between neighbouring
 * keys take the short way and the logarithms stay near the identity, where they are best
 * conditioned. The result depends on the reference key, so where the two largest weights cross, the
 * results about both are blended along the step between them (a smoothstep over a weight gap of
 * 0.1): the curve has no jump there and stays C1. See lct/KeyLogs.h.
 *
 * Interpolation types: Linear, Spline (interpolating C1 Catmull-Rom on the key times, VTK's
 * default), BSpline (approximating cubic, through the end keys), Subdivision (the 4-point
 * interpolating scheme, Hawkins & Grimm §3.3.2) and Bezier (cubic segments whose tangents are
 * given by control transforms, Alexa §6.1; see SetBezierControls). See lct/Curves.h for the
 * exact definitions.
 *
 * Parametrisation: Polar (default; every key with det > 0 works, rigid keys give rigid
 * in-betweens) or MatrixLog (Alexa; keys or key-to-key steps without a real logarithm are
 * rejected when added).
 *
 * ConsistentRotation (off by default): combine the absolute log coordinates of the keys, each
 * taken on the rotation branch nearest to the previous key's (Kaji & Ochiai Algorithm 1), so a
 * key sequence that spins (0, 170, 340, 510 degrees) keeps spinning instead of taking the short
 * way between keys. Meant for spins: over hundreds of keys the absolute rotation vectors wind up
 * far from the identity, where log-space blending distorts (measured on motion capture). Polar
 * only: MatrixLog's logs are principal, so SetConsistentRotation(on) in MatrixLog, and
 * SetParametrisation(MatrixLog) with it on, are refused.
 *
 * Keys are copied when added; an AddTransform at an existing time replaces that key (as VTK
 * does). Each key is validated on its own (finite, affine, det > 0, condition number up to 1e13,
 * no subnormal stretch; lct/Conditioning.h), and then against the curve: every logarithm that a
 * curve point of the interpolation type may combine must exist in the parametrisation — the step
 * from each key a point weights to each key that can be its reference, up to three keys apart
 * (lct::curveStencil; Linear: the neighbours both ways), with ConsistentRotation the absolute
 * log of each key (and the steps to the neighbours), for Bezier also the logs between the keys
 * and control transforms of each segment. A key failing either is rejected with a vtkErrorMacro
 * naming the keys and the cause, and leaves the interpolator unchanged (AddTransform returns 0,
 * else 1). The same holds for every call that changes which logs are needed (RemoveTransform,
 * SetBezierControls, SetInterpolationType, SetParametrisation, SetConsistentRotation): it is
 * refused, with the keys named, and changes nothing. So InterpolateTransform never fails inside
 * the key range for a missing logarithm. Only the keys near the change are checked: loading n
 * keys in any order costs O(n log n); the key logs are computed once, by the first
 * InterpolateTransform after the keys changed (appends and replacements update them in place;
 * the setters compute them at once).
 *
 * InterpolateTransform clamps a finite t to [GetMinimumT(), GetMaximumT()] like VTK (with one
 * vtkWarningMacro per interpolator, so the clamp is never silent); it returns 0 with an error,
 * leaving the output untouched, when there is no key, t is NaN or infinite, or the result is
 * not representable (e.g. a spline overshoot that overflows, or an in-between beyond the
 * conditioning limit): no NaN or Inf is ever written.
 *
 * Timing (issue #12 §3; lct/PathTiming.h): Kochanek-Bartels tension, continuity and bias of the
 * Spline type per path or per key, eases per key or at the path's ends (keys keep their
 * times), and ConstantSpeed, which reparametrises time by arc length so that the path is
 * travelled evenly (keys are then passed at the times GetKeyArrivalTimes gives). The curve
 * is the same; only when each of its points is reached, and with TCB its tangents, change.
 *
 * Concurrency: once the keys and the settings no longer change, InterpolateTransform may be
 * called from several threads at once on one interpolator, each thread with its own output
 * object (the key logs and the constant-speed table, rebuilt lazily, are built once, under a
 * mutex; the checks are Testing/Unit/TestConcurrency.cxx and TestTimingControls.cxx, run under
 * ThreadSanitizer). Adding or removing keys, changing a setting (the timing ones included) or
 * calling GetKeyArrivalTimes while another thread interpolates is a data race.
 *
 * @warning This class derives from vtkObject, not from vtkTransformInterpolator: VTK 9.1 declares
 * that class's methods non-virtual, so a subclass would be silently bypassed through a base
 * pointer.
 *
 * @sa vtkTransformInterpolator vtkLogTransform
 */
#ifndef vtkTransformInterpolatorLCT_h
#define vtkTransformInterpolatorLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"

class vtkDoubleArray;
class vtkLogTransform;
class vtkMatrix4x4;
class vtkProp3D;
class vtkTransform;

class VTKLCT_EXPORT vtkTransformInterpolatorLCT : public vtkObject
{
public:
  static vtkTransformInterpolatorLCT* New();
  vtkTypeMacro(vtkTransformInterpolatorLCT, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Number of keys.
   */
  int GetNumberOfTransforms();

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

  ///@{
  /**
   * Add a key at time t (copied). A key at an existing time replaces it. Returns 1 on success,
   * 0 (with an error naming the cause, interpolator unchanged) for a null key, a non-finite t,
   * a key that is non-finite, projective, orientation-reversing, singular or beyond the
   * conditioning limit, or one with which a curve point would combine a logarithm that does not
   * exist in the parametrisation (see the class description; the error names both keys).
   */
  int AddTransform(double t, vtkTransform* xform);
  int AddTransform(double t, vtkMatrix4x4* matrix);
  int AddTransform(double t, vtkProp3D* prop3D);
  ///@}

  /**
   * Remove the key at time t (if any). Returns 1 when it was removed or there was none; 0, with
   * an error naming the keys and the key kept, when the keys it leaves would make a curve point
   * combine a logarithm that does not exist (e.g. its two neighbours joined by a step without
   * one).
   */
  int RemoveTransform(double t);

  ///@{
  /**
   * The transform at time t (a finite t is clamped to the key range, with a warning once).
   * Returns 1 on success; 0, with an error and the output untouched, when there is no key, t is
   * NaN or infinite, or the result cannot be represented.
   */
  int InterpolateTransform(double t, vtkTransform* xform);
  int InterpolateTransform(double t, vtkMatrix4x4* matrix);
  int InterpolateTransform(double t, vtkLogTransform* xform);
  ///@}

  /// Linear and Spline have vtkTransformInterpolator's values. Its 2, INTERPOLATION_TYPE_MANUAL
  /// (per-channel interpolators, which a matrix interpolator does not have), has no
  /// counterpart: here 2 is BSpline, which approximates its keys. Use the named setters.
  enum InterpolationTypes
  {
    INTERPOLATION_TYPE_LINEAR = 0,
    INTERPOLATION_TYPE_SPLINE = 1,
    INTERPOLATION_TYPE_BSPLINE = 2,
    INTERPOLATION_TYPE_SUBDIVISION = 3,
    INTERPOLATION_TYPE_BEZIER = 4
  };

  ///@{
  /**
   * The curve scheme. Default: Spline, as vtkTransformInterpolator. Returns 1, or 0 with an
   * error (the type unchanged) for a value out of range (vtkSetClampMacro would clamp it
   * silently) or when the keys do not have every logarithm a curve point of the new type
   * combines (a wider stencil reaches keys farther apart).
   */
  int SetInterpolationType(int type);
  vtkGetMacro(InterpolationType, int);
  int GetInterpolationTypeMinValue() { return INTERPOLATION_TYPE_LINEAR; }
  int GetInterpolationTypeMaxValue() { return INTERPOLATION_TYPE_BEZIER; }
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
  int SetInterpolationTypeToBezier()
  {
    return this->SetInterpolationType(INTERPOLATION_TYPE_BEZIER);
  }
  ///@}

  /**
   * Bezier tangents (Alexa §6.1): the control transforms just before (`incoming`) and just after
   * (`outgoing`) the key at time t; the curve leaves the key towards `outgoing` and arrives from
   * `incoming`, like the inner control points of a cubic Bezier segment. Either may be null: that
   * side gets the automatic control exp(+-h/3 m) K, with m the Catmull-Rom tangent of the logs
   * relative to the key and h the segment's duration, so without controls Bezier follows the
   * Spline type closely. Controls are kept until the key is replaced or removed. Returns 0 (with
   * an error, unchanged) when there is no key at t, a control is not a valid affine map, or
   * (type Bezier) a curve point of the two segments beside the key would combine a logarithm
   * that does not exist.
   */
  int SetBezierControls(double t, vtkMatrix4x4* incoming, vtkMatrix4x4* outgoing);

  enum ParametrisationTypes
  {
    POLAR = 0,
    MATRIX_LOG = 1
  };

  ///@{
  /**
   * The parametrisation (see vtkLogTransform). Changing it recomputes the key logs; it returns 0
   * (with an error naming the keys, unchanged) if a logarithm that a curve point combines does
   * not exist in the new one.
   */
  int SetParametrisation(int parametrisation);
  vtkGetMacro(Parametrisation, int);
  int SetParametrisationToPolar() { return this->SetParametrisation(POLAR); }
  int SetParametrisationToMatrixLog() { return this->SetParametrisation(MATRIX_LOG); }
  ///@}

  ///@{
  /**
   * Keep the rotation winding of the key sequence (see the class description). Default off.
   * Returns 1, or 0 with an error naming the key (setting unchanged) when a logarithm the new
   * setting combines does not exist (MatrixLog: a key without an absolute one; off: a relative
   * step of the interpolation type).
   */
  int SetConsistentRotation(vtkTypeBool consistentRotation);
  vtkGetMacro(ConsistentRotation, vtkTypeBool);
  int ConsistentRotationOn() { return this->SetConsistentRotation(1); }
  int ConsistentRotationOff() { return this->SetConsistentRotation(0); }
  ///@}

  ///@{
  /**
   * Spline type only: the tangent at each inner key without its own tension, continuity or bias
   * is Fritsch & Butland's monotone tangent of the log steps to its neighbours (the steps from
   * the key, as the curve combines them; lct/MonotoneTangents.h): each step weighted by the other's
   * speed, the speeds taken unit-free on the translation and on the linear (rotation and stretch)
   * part. It is 0 where the motion turns back and never above twice the slower step, so the curve
   * does not overshoot where the motion slows down or stops at a key: keys 0, 179.9 and 180 degrees
   * one time unit apart stay below 180 degrees (plain Catmull-Rom swings 13 degrees past). On
   * motion capture its mean and max error are at or below Linear's at every key spacing of issue
   * #12's protocol, with StraightenImpacts on (README, "Real motion capture"). Every key is still
   * reproduced at its time and the curve stays C1. Default on; off gives plain Catmull-Rom.
   */
  vtkSetMacro(MonotoneTangents, vtkTypeBool);
  vtkGetMacro(MonotoneTangents, vtkTypeBool);
  vtkBooleanMacro(MonotoneTangents, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Spline type with MonotoneTangents only: where the motion turns back at a key that it reaches
   * and leaves at least 1.5 times as fast as it moves on the steps around it (a bounce, a strike,
   * a glitch in a recording; fully from 2.5 times, lct::impactWeight), the two segments beside
   * the key are nearly straight (Delbourgo & Gregory's rational cubic, lct::SegmentTangents) with
   * the same keys and tangents, so still C1 and without overshoot, instead of dwelling near the
   * key for a third of each segment. A smooth turn (reached slowly) and a swing keyed at its
   * extremes (the same speed throughout) keep the cubic. Keys with tension, continuity or bias
   * (their own or the path's) are left to them. Default on; off gives the cubic everywhere (the
   * curves of vtkLCT before this setting).
   */
  vtkSetMacro(StraightenImpacts, vtkTypeBool);
  vtkGetMacro(StraightenImpacts, vtkTypeBool);
  vtkBooleanMacro(StraightenImpacts, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Kochanek-Bartels tension, continuity and bias of the Spline type (vtkKochanekSpline's
   * parameters, applied to the log steps between keys; lct/KochanekBartels.h) for every key
   * without its own (SetKeyTensionContinuityBias). Each in [-1, 1]; a value outside (or NaN) is
   * refused with an error, returning 0 and keeping the old one. All 0 (default): the key's
   * tangent is the monotone one (or Catmull-Rom's with MonotoneTangentsOff), and TCB = 0 with
   * MonotoneTangentsOff is exactly Catmull-Rom. Keys are reproduced at their times whatever the
   * values; continuity != 0 puts a corner at the keys.
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
   * Timing of the key at time t: its own tension, continuity and bias (Spline type), and the
   * eases of the motion arriving at it and leaving it (each in [0, 1]: the speed there is
   * multiplied by 1 - ease, so 1 arrives at or leaves from rest; lct/Ease.h). The key is still
   * reached at its time t. Kept until the key is replaced or removed, or ClearKeyTiming(t).
   * Returns 0, with an error and nothing changed, when there is no key at t or a value is out
   * of range.
   */
  int SetKeyTensionContinuityBias(double t, double tension, double continuity, double bias);
  int SetKeyEase(double t, double arriving, double leaving);
  int ClearKeyTiming(double t);

  ///@{
  /**
   * Constant speed (default off): reparametrise time by the arc length of the path of one point
   * moved by the interpolated transforms, the ConstantSpeedPoint (default the origin, i.e. the
   * transform's translation), so that it moves evenly along the path whatever the key spacing
   * (lct/ArcLength.h). The path is the same; the keys are then passed at the times their
   * distance along it gives (GetKeyArrivalTimes), the first at GetMinimumT() and the last at
   * GetMaximumT(); per-key eases do not apply, EaseIn/EaseOut ease the whole path. Stretches in
   * which the point stays still (a turn about it) keep their duration. The table is built by the
   * first InterpolateTransform after a change (n key segments: 32 n evaluations).
   */
  vtkSetMacro(ConstantSpeed, vtkTypeBool);
  vtkGetMacro(ConstantSpeed, vtkTypeBool);
  vtkBooleanMacro(ConstantSpeed, vtkTypeBool);
  int SetConstantSpeedPoint(double x, double y, double z);
  int SetConstantSpeedPoint(const double point[3])
  {
    return this->SetConstantSpeedPoint(point[0], point[1], point[2]);
  }
  void GetConstantSpeedPoint(double point[3]);
  ///@}

  /**
   * The times at which the interpolated path passes each key, in key order: the key times,
   * except under ConstantSpeed. Returns 0 (with an error, `times` untouched) for a null array,
   * no keys, or a path that cannot be measured.
   */
  int GetKeyArrivalTimes(vtkDoubleArray* times);

protected:
  vtkTransformInterpolatorLCT();
  ~vtkTransformInterpolatorLCT() override;

  int InterpolationType = INTERPOLATION_TYPE_SPLINE;
  int Parametrisation = POLAR;
  vtkTypeBool ConsistentRotation = false;
  vtkTypeBool MonotoneTangents = true;
  vtkTypeBool StraightenImpacts = true;
  vtkTypeBool ConstantSpeed = false;

private:
  vtkTransformInterpolatorLCT(const vtkTransformInterpolatorLCT&) = delete;
  void operator=(const vtkTransformInterpolatorLCT&) = delete;

  int AddKey(double t, const double elements[16], const char* caller);
  bool Evaluate(double t, double out[16]);
  /// The curve time of output time t (eases, constant speed); false, with an error, when the
  /// constant-speed path cannot be measured.
  bool CurveTime(double t, double& curveTime, const char* caller);

  struct Internals;
  Internals* Internal;
};

#endif
