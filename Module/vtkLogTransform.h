/**
 * @class   vtkLogTransform
 * @brief   an affine transform held in log coordinates, so transforms can be scaled,
 *          added and blended like vectors (Alexa 2002; Kaji & Ochiai 2016)
 *
 * vtkLogTransform is a vtkLinearTransform whose state is the 12 log coordinates of an
 * orientation-preserving affine map M (see lct/LogCoords.h): translation, rotation vector
 * and symmetric stretch. It can be used anywhere VTK takes a transform
 * (vtkTransformPolyDataFilter, vtkProp3D::SetUserTransform, vtkTransform::Concatenate).
 *
 * The operations of Alexa's "Linear combination of transformations" act on the stored
 * coordinates:
 * - Scale(s):  M <- s (.) M = exp(s log M)            (scalar multiple, eq. 5)
 * - Add(B):    M <- M (+) B = exp(log M + log B)      (commutative addition, eq. 6)
 * - LinearCombination(w, T): exp(sum w_i log T_i)      (eq. 7)
 * - Interpolate(A, B, t):    exp((1 - t) log A + t log B)
 *
 * Two parametrisations are offered:
 * - Polar (default): Kaji & Ochiai's psi/phi, log M = (l, log U, log S) for the polar
 *   decomposition U S of the linear part. It covers all of Aff+(3) — every finite affine
 *   map with positive determinant has coordinates — and blends of rigid maps stay rigid,
 *   of similarities stay similarities. That is why it is the default: with the matrix log,
 *   about one generic affine key in seven (rotation and non-uniform scale) has no real
 *   logarithm at all.
 * - MatrixLog: Alexa's principal logarithm of the whole 4x4 matrix. Its scalar multiple is
 *   associative ((a b) (.) M = a (.) (b (.) M)), but maps whose linear part has a negative
 *   real eigenvalue (e.g. a half turn combined with non-uniform scale) are rejected.
 *
 * Every setter validates its input. NaN/Inf, a bottom row other than (0, 0, 0, 1), a
 * negative determinant, a singular map, a condition number above 1e13 (lct/Conditioning.h), a
 * subnormal stretch, (MatrixLog) a map without real logarithm or with eigenvalue magnitudes
 * beyond 1e+-135, and results that overflow, or whose inverse would, are reported with a
 * vtkErrorMacro naming the cause; the method returns 0 and the object keeps its previous state
 * (and MTime). Methods that succeed return 1 and call Modified(). So every state has a finite
 * matrix and a finite inverse: Inverse() and GetInverse() always succeed.
 *
 * Rotations: the rotation part is the principal one (angle <= 180 degrees) unless a
 * reference is given to SetMatrix(), in which case the equivalent rotation vector nearest to
 * the reference's is kept (Kaji & Ochiai Algorithm 1). A key sequence can thus spin beyond
 * 360 degrees: set each key with the previous one as reference.
 *
 * @warning Scale(s) here is the scalar multiple of a transform, not a geometric scaling
 * like vtkTransform::Scale(x, y, z).
 *
 * @sa vtkLinearTransform vtkTransform vtkTransformInterpolator
 */
#ifndef vtkLogTransform_h
#define vtkLogTransform_h

#include "vtkLCTModule.h" // For export macro
#include "vtkLinearTransform.h"

class vtkCollection;
class vtkDoubleArray;
class vtkMatrix4x4;

#include <atomic> // for std::atomic

class VTKLCT_EXPORT vtkLogTransform : public vtkLinearTransform
{
public:
  static vtkLogTransform* New();
  vtkTypeMacro(vtkLogTransform, vtkLinearTransform);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ParametrisationType
  {
    POLAR = 0,
    MATRIX_LOG = 1
  };

  ///@{
  /**
   * The parametrisation of the log coordinates: POLAR (default) or MATRIX_LOG. Changing it
   * re-expresses the current transform in the new coordinates (the map is unchanged; a
   * rotation wound beyond 180 degrees is brought back to its principal angle). Returns 0,
   * with an error and no change, when the map has no coordinates in the new one.
   */
  int SetParametrisation(int parametrisation);
  vtkGetMacro(Parametrisation, int);
  int SetParametrisationToPolar() { return this->SetParametrisation(POLAR); }
  int SetParametrisationToMatrixLog() { return this->SetParametrisation(MATRIX_LOG); }
  const char* GetParametrisationAsString();
  ///@}

  ///@{
  /**
   * Set the transform from a 4x4 affine matrix (copied). With a `reference`, the rotation
   * branch nearest to the reference's rotation part is kept (Polar only). Returns 1 on
   * success, 0 on invalid input (the object is then unchanged).
   */
  int SetMatrix(vtkMatrix4x4* matrix);
  int SetMatrix(vtkMatrix4x4* matrix, vtkLogTransform* reference);
  int SetMatrix(const double elements[16]);
  ///@}

  /**
   * Set the transform to the current matrix of another linear transform.
   */
  int SetTransform(vtkLinearTransform* transform);

  ///@{
  /**
   * The 12 log coordinates: translation part (3), rotation vector (3), symmetric part
   * (xx, yy, zz, xy, yz, xz). SetLogCoordinates rejects non-finite values and coordinates
   * whose map overflows.
   */
  int SetLogCoordinates(const double coordinates[12]);
  void GetLogCoordinates(double coordinates[12]);
  ///@}

  /**
   * Scalar multiple: M <- s (.) M. Returns 0 (unchanged) if the result overflows.
   */
  int Scale(double s);

  /**
   * Addition: M <- M (+) other, in this object's parametrisation. Returns 0 (unchanged)
   * when `other` is null, has no coordinates in this parametrisation or the sum overflows.
   */
  int Add(vtkLogTransform* other);

  ///@{
  /**
   * result <- (+)_i weights[i] (.) transforms[i], in result's parametrisation. Inputs in
   * another parametrisation are converted from their matrix. Returns 0 (result unchanged)
   * on a null or unconvertible input, a weight count mismatch, or overflow.
   * The collection form is the one available from Python.
   */
  static int LinearCombination(
    vtkCollection* transforms, vtkDoubleArray* weights, vtkLogTransform* result);
#ifndef __VTK_WRAP__
  static int LinearCombination(
    int count, const double* weights, vtkLogTransform* const* transforms, vtkLogTransform* result);
#endif
  ///@}

  /**
   * this <- (1 - t) (.) a (+) t (.) b: linear interpolation of the stored coordinates. Within
   * [0, 1] formed as (1 - t) log a + t log b, exactly a at 0 and b at 1 and finite for any finite
   * keys; outside it (extrapolation) from the nearer key, log a + t (log b - log a) or
   * log b + (1 - t) (log a - log b), so that a large t does not cancel. Returns 0 (unchanged) on
   * null input or when the result itself overflows.
   */
  int Interpolate(vtkLogTransform* a, vtkLogTransform* b, double t);

  /**
   * Reset to the identity (all coordinates zero).
   */
  void Identity();

  /**
   * Invert in place. Exact negation of the coordinates for MatrixLog; for Polar the closed form
   * of the inverse map's coordinates (the rotation branch kept). Never fails: the inverse state
   * is computed, and a state whose inverse is not representable refused, when a state is set,
   * so Inverse() swaps the two and inverting twice restores the state exactly.
   */
  void Inverse() override;

  /**
   * Copy another vtkLogTransform (state, parametrisation). Unlike vtkAbstractTransform::DeepCopy,
   * which dereferences its argument unchecked, a null or non-vtkLogTransform argument is
   * reported with an error and leaves this object unchanged (call through a vtkLogTransform
   * pointer: the base method is not virtual).
   */
  void DeepCopy(vtkAbstractTransform* transform);

  vtkAbstractTransform* MakeTransform() override;

  ///@{
  /**
   * Normals, by the inverse transpose of the linear part taken from the inverse the state holds,
   * then normalised. vtkLinearTransform inverts the matrix with vtkMatrix4x4::Invert, whose
   * determinant overflows beyond a scale of ~5e102 (zero normals; NaN through
   * vtkTransformPolyDataFilter) and underflows below ~1e-103 (the matrix left uninverted: the
   * rotation of every normal reversed); these hold at any scale a vtkLogTransform accepts.
   * (vtkLinearTransform::TransformPointsNormalsVectors, which vtkTransformPolyDataFilter calls,
   * goes through TransformNormals.)
   */
  void TransformNormals(vtkDataArray* inNms, vtkDataArray* outNms) override;
  void InternalTransformNormal(const float in[3], float out[3]) override;
  void InternalTransformNormal(const double in[3], double out[3]) override;
  ///@}

  /**
   * Also the time of a change made to GetMatrix() from outside (e.g. GetMatrix()->SetElement):
   * the state is the log coordinates, so the next Update() puts their matrix back, with a
   * warning, rather than leave TransformPoint and the inverse describing different maps. Use
   * SetMatrix to change the transform.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkLogTransform();
  ~vtkLogTransform() override;

  void InternalUpdate() override;
  void InternalDeepCopy(vtkAbstractTransform* transform) override;

private:
  vtkLogTransform(const vtkLogTransform&) = delete;
  void operator=(const vtkLogTransform&) = delete;

  int SetMatrixNear(const double elements[16], const double* referenceCoordinates);
  /// Writes the state's matrix into this->Matrix, which it then holds unchanged from outside.
  void WriteStateMatrix();
  /// Sets the state to `coordinates` in `parametrisation`, with its matrix and its inverse (see
  /// Inverse()); false, with an error naming `caller` and the state unchanged, when either is
  /// not representable.
  bool Commit(const double* coordinates, int parametrisation, const char* caller);
  /// LinearCombination's work, its messages under `caller` (Add and Interpolate use it too).
  static int Combine(int count, const double* weights, vtkLogTransform* const* transforms,
    vtkLogTransform* result, const char* caller);
  /// The 12 coordinates of `t` in `parametrisation` (converted from its matrix when it holds
  /// another); false, with an error on `result` naming `caller` and operand `index`.
  static bool CoordinatesIn(vtkLogTransform* t, int parametrisation, vtkLogTransform* result,
    const char* caller, int index, double out[12]);

  struct State;
  State* Internal;
  int Parametrisation = POLAR;
  /// The matrix's MTime when InternalUpdate last wrote it: a later one is a change from outside.
  std::atomic<vtkMTimeType> MatrixWrittenTime{ 0 };
};

#endif
