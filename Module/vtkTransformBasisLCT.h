/**
 * @class   vtkTransformBasisLCT
 * @brief   factor transforms onto a basis of transforms in log space, and constrain them to
 *          its span (Alexa 2002 §6.2)
 *
 * Log coordinates form a vector space, so a transform T can be written as
 * T = exp(sum_i x_i log B_i) for basis transforms B_i, and a transform outside their span has
 * a nearest transform inside it. vtkTransformBasisLCT holds such a basis:
 *
 * - given explicitly (AddBasisTransform), e.g. Alexa's rotations R_x(phi), R_y(phi), R_z(phi);
 * - or found from examples of permissible transforms (SetBasisFromExamples): the orthonormal
 *   basis of the span of their logs by SVD (Alexa §6.2), optionally about their mean log
 *   (centred: the subspace is then mean + span, an affine subspace of the log space).
 *
 * Factor(T) gives the coefficients x (least squares in log space) and the residual, the log
 * distance of T from the span; Reconstruct(x) gives exp(origin + sum_i x_i log B_i); Project(T)
 * the nearest transform in the span ("constraining a transform").
 *
 * The inner product is Alexa's entry-wise product of the 4x4 log matrices (eq. 8); for rotation
 * vectors it is twice their dot product, so the inner products of R(a, theta) with the basis
 * R_x(phi), R_y(phi), R_z(phi) are 2 phi theta a, and Factor's coefficients x (those inner
 * products through the inverse Gram matrix, 2 phi^2 I) are theta / phi a: the axis is x / |x| and
 * the angle phi |x| (the paper's "(x + y + z) / phi" is a misprint). See lct/LogBasis.h.
 *
 * The basis is analysed by an SVD: its rank (singular values above RankTolerance times the
 * largest) and the condition number of its Gram matrix are reported. A rank-deficient basis is
 * kept (with a warning) but Factor refuses it, because its coefficients are not unique;
 * Project is still defined. Logs are principal (rotation angle <= 180 degrees), in the chosen
 * parametrisation: POLAR (default, all of Aff+(3)) or MATRIX_LOG (Alexa's).
 *
 * Every method validates its input: a null, non-finite, projective, reflecting, singular or
 * (MATRIX_LOG) log-less transform, a coefficient array of the wrong size or with NaN/Inf, a
 * 13th basis transform, and results that overflow are reported with a vtkErrorMacro; the method
 * returns 0 and the object, and any output argument, keep their previous state.
 *
 * Thread safety: the Get methods and Reconstruct only read, and may run concurrently once the
 * basis is set; Factor and Project also write the residual, so give each thread its own object
 * (or lock) for them. Setting the basis, the tolerance or the parametrisation must not overlap
 * any other call.
 *
 * @sa vtkLogTransform
 */
#ifndef vtkTransformBasisLCT_h
#define vtkTransformBasisLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"

class vtkCollection;
class vtkDoubleArray;
class vtkLinearTransform;
class vtkMatrix4x4;

class VTKLCT_EXPORT vtkTransformBasisLCT : public vtkObject
{
public:
  static vtkTransformBasisLCT* New();
  vtkTypeMacro(vtkTransformBasisLCT, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ParametrisationType
  {
    POLAR = 0,
    MATRIX_LOG = 1
  };

  ///@{
  /**
   * The parametrisation of the logs: POLAR (default) or MATRIX_LOG. Changing it re-takes the
   * logs of the basis transforms (or examples); returns 0, with an error and no change, when
   * one of them has no log in the new parametrisation.
   */
  int SetParametrisation(int parametrisation);
  vtkGetMacro(Parametrisation, int);
  int SetParametrisationToPolar() { return this->SetParametrisation(POLAR); }
  int SetParametrisationToMatrixLog() { return this->SetParametrisation(MATRIX_LOG); }
  const char* GetParametrisationAsString();
  ///@}

  ///@{
  /**
   * The rank tolerance: a basis direction whose singular value is at most RankTolerance times
   * the largest counts as dependent (default 1e-8, a Gram condition number of 1e16). Setting
   * it re-analyses the basis; returns 0 (unchanged) for a value outside [0, 1) or when the
   * examples would then span nothing.
   */
  int SetRankTolerance(double tolerance);
  vtkGetMacro(RankTolerance, double);
  ///@}

  ///@{
  /**
   * Add a basis transform (at most 12: the dimension of the log space). Returns 1, or 0 with
   * an error (the basis unchanged) for invalid input. Adding to a basis found from examples
   * replaces it by the explicit basis {transform}.
   */
  int AddBasisTransform(vtkMatrix4x4* matrix);
  int AddBasisTransform(vtkLinearTransform* transform);
  ///@}

  /**
   * Remove every basis transform (and examples): no basis.
   */
  void RemoveAllBasisTransforms();

  /**
   * Replace the basis by the orthonormal basis of the span of the examples' logs (a
   * vtkCollection of vtkMatrix4x4 or vtkLinearTransform), about their mean log when `centred`
   * is non-zero. Directions below RankTolerance are dropped, and at most MaximumRank are kept
   * when it is positive; they come in order of decreasing spread. Returns 0 (unchanged) for a
   * null or empty collection, an item of another type, an invalid transform, or examples that
   * span nothing.
   */
  int SetBasisFromExamples(vtkCollection* examples, int centred);

  ///@{
  /**
   * For SetBasisFromExamples: keep at most this many directions (0, the default: all above
   * the rank tolerance). Changing it re-analyses a basis made from examples (as SetRankTolerance
   * does); 0 with an error, unchanged, when that fails or the value is outside [0, 12].
   */
  virtual int SetMaximumRank(int value);
  int GetMaximumRankMinValue() { return 0; }
  int GetMaximumRankMaxValue() { return 12; }
  vtkGetMacro(MaximumRank, int);
  ///@}

  /**
   * The number of basis vectors: the transforms added, or the directions kept from examples.
   */
  int GetNumberOfBasisTransforms();

  /**
   * The number of independent basis vectors (to RankTolerance).
   */
  int GetRank();

  /**
   * The condition number of the Gram matrix of the basis logs (Alexa's V): 1 for an
   * orthonormal basis, +Inf when rank deficient, 0 without a basis.
   */
  double GetConditionNumber();

  /**
   * The singular values of the (metric-weighted) basis logs, descending; their squares are
   * the Gram matrix's. For a basis from examples: of the example matrix, all min(n, 12) of
   * them, kept or not (their squares over n: the mean square spread along each direction).
   */
  void GetSingularValues(vtkDoubleArray* values);

  ///@{
  /**
   * The i-th basis transform (the one added, or exp of the i-th direction from examples) and
   * the origin of the subspace (the identity, or exp of the examples' mean log). Return 0 with
   * an error for a bad index, a null matrix or no basis.
   */
  int GetBasisTransform(int i, vtkMatrix4x4* result);
  int GetOrigin(vtkMatrix4x4* result);
  ///@}

  /**
   * The coefficients of `transform` on the basis (one tuple per basis transform): the least
   * squares solution in log space, exact when the transform lies in the span. Sets the
   * residual and GetCoefficientErrorBound(). Returns 0 with an error (coefficients untouched)
   * for invalid input, no basis, a rank-deficient basis, or coefficients that double precision
   * does not determine to CoefficientTolerance: their error bound exceeds
   * CoefficientTolerance * (1 + max |x_i|). That happens for a basis of transforms close to
   * the identity (a small smallest singular value, whatever the Gram condition number) and a
   * transform close to the identity too: the matrix holds 1 + 3e-14 only to 1.1e-16, so a
   * basis log of size 1e-12 gives its coefficient to about 1e-4 (Testing/Fuzz/README.md, A4).
   */
  int Factor(vtkMatrix4x4* transform, vtkDoubleArray* coefficients);

  ///@{
  /**
   * The accuracy Factor() must reach: it refuses coefficients whose error bound exceeds
   * CoefficientTolerance * (1 + max |x_i|) (default 1e-6). Returns 0 (unchanged) for a value
   * that is not positive (NaN, 0 or negative); +Inf accepts every bound.
   */
  int SetCoefficientTolerance(double tolerance);
  vtkGetMacro(CoefficientTolerance, double);
  ///@}

  /**
   * A bound on the error (2-norm) of the last coefficients Factor() computed, relative to the
   * exact coefficients of its input matrix: kLogAccuracy eps (1 + |log T|) / sigma_min plus
   * the rounding of the solve (lct::coefficientErrorBound). Factor(Reconstruct(x)) differs
   * from x by up to about (1 + cond(A)) times it, A the reconstruction's linear part: the
   * rounding of that matrix adds the log's sensitivity to it.
   */
  vtkGetMacro(CoefficientErrorBound, double);

  /**
   * result = exp(origin + sum_i coefficients_i log B_i). Returns 0 with an error (result
   * untouched) for a coefficient count other than GetNumberOfBasisTransforms(), NaN/Inf
   * coefficients, no basis or an overflowing result.
   */
  int Reconstruct(vtkDoubleArray* coefficients, vtkMatrix4x4* result);

  /**
   * The transform of the subspace nearest to `transform` in log space (defined for
   * rank-deficient bases too). Sets the residual. Returns 0 with an error (result untouched)
   * for invalid input or no basis.
   */
  int Project(vtkMatrix4x4* transform, vtkMatrix4x4* result);

  /**
   * The log distance of the last Factor or Project input from the subspace (0 in the span).
   */
  vtkGetMacro(Residual, double);

protected:
  vtkTransformBasisLCT();
  ~vtkTransformBasisLCT() override;

private:
  vtkTransformBasisLCT(const vtkTransformBasisLCT&) = delete;
  void operator=(const vtkTransformBasisLCT&) = delete;

  struct Internals;
  struct Candidate;
  bool Commit(const Candidate& candidate, const char* caller);
  bool Ready(const char* caller);
  /// The log of a Factor/Project input, after the null checks (of it and of `output`) and the
  /// basis check, with an error naming `caller` on failure.
  bool LogOfInput(vtkMatrix4x4* transform, const void* output, const char* outputName,
    const char* caller, double log[12]);

  Internals* Internal;
  int Parametrisation = POLAR;
  double RankTolerance = 1e-8;
  int MaximumRank = 0;
  double Residual = 0.0;
  double CoefficientTolerance = 1e-6;
  double CoefficientErrorBound = 0.0;
};

#endif
