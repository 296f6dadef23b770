/**
 * @class   vtkProbeDeformerLCT
 * @brief   deforms a point set by a per-point blend of probe transforms in log coordinates
 *          (Kaji & Ochiai §5.2): Polar, MatrixLog, linear (LBS) or dual-quaternion skinning
 *
 * A probe is a pair (current, rest): each a vtkLinearTransform, a vtkMatrix4x4 or a vtkProp3D
 * (its matrix); a null rest is the identity. A point p moves by the blend of the probes'
 * relative transforms A_i = current_i rest_i^-1 with per-point weights w_i(p):
 *
 * - POLAR (default): phi(sum_i w_i psi(A_i)), Kaji & Ochiai eq. 9: rigid probes give rigid
 *   motion, twists keep their volume, and a probe's rotation may exceed 2 pi;
 * - MATRIX_LOG: exp(sum_i w_i log A_i) (Alexa 2002); principal logs only;
 * - LINEAR: sum_i w_i A_i, what vtkWeightedTransformFilter does (collapses under twist);
 * - DUAL_QUATERNION: "Polar+DQ" of Kaji & Ochiai Table 2 in Kavan et al.'s two phases: the
 *   stretches S_i of the polar split (about each probe's rest centre) blended as matrices,
 *   sum w_i S_i / sum w_i, then the rigid parts by the dual-quaternion linear blend with the
 *   hemisphere check; weights whose sum cancels (negative weights, no normalisation) are an
 *   error when a probe stretches.
 *
 * The log blends are taken about a centre per point, c(p) = sum |w_i| c_i / sum |w_i| of the
 * probes' rest centres c_i (the translation of each rest transform): unlike the paper's
 * origin-centred form, translating the mesh and every probe by d translates the output by d
 * exactly (see lct/ProbeBlend.h for why, and the README for the measured difference).
 *
 * Weights (SetWeightMode):
 * - INVERSE_DISTANCE (default): w_i = r_i / d_i^p, d_i the distance to the rest centre, r_i the
 *   probe radius (default 8), p the exponent (default 1) — Kaji's deformer's defaults;
 * - CUTOFF: w_i = ((r_i - d_i) / r_i)^p within the radius, 0 beyond;
 * - POINT_DATA: a point-data weight array (any real type, k components) and optionally a
 *   transform-index array (any integer type, or real holding integers; k components), as
 *   vtkWeightedTransformFilter takes them: slot j of a point has weight w_j for probe index_j
 *   (probe j without an index array).
 * then normalised per point (SetNormalization): LINEAR (w / sum w, default; the sum must be
 * positive where any weight is not 0, and a point whose weights are all 0 stays put), SOFTMAX
 * (exp(w) / sum exp(w); every probe then has a positive weight, CUTOFF's zeros included, so a
 * point beyond every radius moves with the probes' equal-weight blend: use LINEAR for a local
 * influence) or NONE (as given; LINEAR blend mode then sums the matrices as given).
 *
 * Rotation branches (POLAR): with ConsistentRotation on (default) each probe's rotation log is
 * the one nearest the log used at the previous successful execution (Kaji & Ochiai Alg. 1), so
 * a probe driven step by step through 3 pi twists by 3 pi; SetProbeRotationReference sets an
 * explicit reference instead (stateless, for pipelines that jump in time), and
 * ResetRotationHistory forgets the previous logs. AddProbe keeps the other probes' logs (the new
 * probe starts from its principal log), and an execution in another blend mode leaves them as
 * they were; RemoveAllProbes forgets them.
 *
 * Output: the input's structure and data; the points moved (float points stay float, points of
 * any other type, integers included, come out as double); the active normals and the arrays
 * named by AddNormalArrayName transformed by the inverse transpose of the blended linear part
 * (its cofactor matrix) and renormalised; the active vectors and the arrays named by
 * AddVectorArrayName transformed by the blended linear part. Probes at rest leave every point
 * exactly where it was. Multithreaded with vtkSMPTools above SerialThreshold points; the result
 * does not depend on the number of threads. MTime includes every probe's transforms.
 *
 * Bad input (no probes, a probe matrix that is not finite, affine or of positive determinant,
 * a MATRIX_LOG probe without a real logarithm, a non-positive radius or exponent, a missing or
 * mismatched weight or index array, NaN/Inf weights, an index out of range, weights whose sum
 * the normalisation cannot divide by, a result that overflows, probes that all shrink by 1e8 or
 * more, whose blend would keep fewer than 8 digits of the result's own size: points move as
 * p + (A - I)(p - c) + t, accurate near the identity, with round-off on the scale of the input,
 * so a region that one probe shrinks among others keeps the input's absolute accuracy, not its
 * own relative one) is reported with a vtkErrorMacro
 * naming the probe or point; RequestData then returns 0 and the output keeps the last valid
 * result (empty before the first).
 *
 * @sa vtkWeightedTransformFilter vtkLogTransform vtkShapeBlenderLCT
 */
#ifndef vtkProbeDeformerLCT_h
#define vtkProbeDeformerLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkPointSetAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkMatrix4x4;

class VTKLCT_EXPORT vtkProbeDeformerLCT : public vtkPointSetAlgorithm
{
public:
  static vtkProbeDeformerLCT* New();
  vtkTypeMacro(vtkProbeDeformerLCT, vtkPointSetAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum BlendModeType
  {
    POLAR = 0,
    MATRIX_LOG = 1,
    LINEAR = 2,
    DUAL_QUATERNION = 3
  };
  enum WeightModeType
  {
    INVERSE_DISTANCE = 0,
    CUTOFF = 1,
    POINT_DATA = 2
  };
  enum NormalizationType
  {
    NORMALIZE_LINEAR = 0,
    NORMALIZE_SOFTMAX = 1,
    NORMALIZE_NONE = 2
  };

  ///@{
  /**
   * Add a probe (current, rest), each a vtkLinearTransform, vtkMatrix4x4 or vtkProp3D (rest
   * may be null: the identity). Returns the probe's index, or -1 with an error for a null
   * current or another type (no probe added). The matrices are read at execution. At most
   * 65536 probes.
   */
  int AddProbe(vtkObject* current, vtkObject* rest);
  int AddProbe(vtkObject* current) { return this->AddProbe(current, nullptr); }
  ///@}

  /**
   * Replace probe i (its radius, rotation reference and rotation history are kept: with
   * ConsistentRotation the new probe's log is taken nearest the replaced one's last, as when a
   * probe is driven step by step; ResetRotationHistory starts from principal logs). Returns 1,
   * or 0 with an error for an index out of range, a null current or another type.
   */
  int SetProbe(int i, vtkObject* current, vtkObject* rest);

  void RemoveAllProbes();
  int GetNumberOfProbes();

  ///@{
  /**
   * The radius r_i of probe i (default 8; finite and positive, checked here). Returns 1, or 0
   * with an error. GetProbeRadius returns 0 for an index out of range.
   */
  int SetProbeRadius(int i, double radius);
  double GetProbeRadius(int i);
  ///@}

  ///@{
  /**
   * An explicit rotation reference (a rotation vector, radians) for probe i: its POLAR rotation
   * log is the one nearest to it, whatever the previous execution used. Clear it to go back to
   * ConsistentRotation. Returns 1, or 0 with an error (index out of range, not finite, beyond
   * 1e9 rad).
   */
  int SetProbeRotationReference(int i, const double reference[3]);
  int ClearProbeRotationReference(int i);
  ///@}

  ///@{
  /**
   * The blend: POLAR (default), MATRIX_LOG, LINEAR or DUAL_QUATERNION.
   */
  virtual int SetBlendMode(int value);
  int GetBlendModeMinValue() { return POLAR; }
  int GetBlendModeMaxValue() { return DUAL_QUATERNION; }
  vtkGetMacro(BlendMode, int);
  void SetBlendModeToPolar() { this->SetBlendMode(POLAR); }
  void SetBlendModeToMatrixLog() { this->SetBlendMode(MATRIX_LOG); }
  void SetBlendModeToLinear() { this->SetBlendMode(LINEAR); }
  void SetBlendModeToDualQuaternion() { this->SetBlendMode(DUAL_QUATERNION); }
  const char* GetBlendModeAsString();
  ///@}

  ///@{
  /**
   * Where the weights come from: INVERSE_DISTANCE (default), CUTOFF or POINT_DATA.
   */
  virtual int SetWeightMode(int value);
  int GetWeightModeMinValue() { return INVERSE_DISTANCE; }
  int GetWeightModeMaxValue() { return POINT_DATA; }
  vtkGetMacro(WeightMode, int);
  void SetWeightModeToInverseDistance() { this->SetWeightMode(INVERSE_DISTANCE); }
  void SetWeightModeToCutoff() { this->SetWeightMode(CUTOFF); }
  void SetWeightModeToPointData() { this->SetWeightMode(POINT_DATA); }
  ///@}

  ///@{
  /**
   * The exponent p of the distance weights (default 1; finite and positive, checked at
   * execution).
   */
  vtkSetMacro(Exponent, double);
  vtkGetMacro(Exponent, double);
  ///@}

  ///@{
  /**
   * Per-point normalisation of the weights: NORMALIZE_LINEAR (default), NORMALIZE_SOFTMAX or
   * NORMALIZE_NONE.
   */
  virtual int SetNormalization(int value);
  int GetNormalizationMinValue() { return NORMALIZE_LINEAR; }
  int GetNormalizationMaxValue() { return NORMALIZE_NONE; }
  vtkGetMacro(Normalization, int);
  void SetNormalizationToLinear() { this->SetNormalization(NORMALIZE_LINEAR); }
  void SetNormalizationToSoftmax() { this->SetNormalization(NORMALIZE_SOFTMAX); }
  void SetNormalizationToNone() { this->SetNormalization(NORMALIZE_NONE); }
  ///@}

  ///@{
  /**
   * POINT_DATA weights: the point-data array of weights (k components) and, optionally, of
   * probe indices (k components; null: component j is probe j).
   */
  vtkSetStringMacro(WeightArrayName);
  vtkGetStringMacro(WeightArrayName);
  vtkSetStringMacro(TransformIndexArrayName);
  vtkGetStringMacro(TransformIndexArrayName);
  ///@}

  ///@{
  /**
   * Choose each probe's rotation log nearest the previous execution's (default on).
   */
  vtkSetMacro(ConsistentRotation, vtkTypeBool);
  vtkGetMacro(ConsistentRotation, vtkTypeBool);
  vtkBooleanMacro(ConsistentRotation, vtkTypeBool);
  ///@}

  /**
   * Forget the rotation logs of the previous execution (the next takes principal logs).
   */
  void ResetRotationHistory();

  /**
   * The rotation log (rotation vector) probe i was blended with at the last successful
   * execution; returns 0 when there is none.
   */
  int GetProbeRotationLog(int i, double log[3]);

  ///@{
  /**
   * 3-component point-data arrays carried along besides the active normals and vectors: as
   * normals (cofactor of the blended linear part, renormalised) or as vectors (the linear part).
   * Float or double arrays; others are reported at execution.
   */
  void AddNormalArrayName(const char* name);
  void AddVectorArrayName(const char* name);
  void RemoveAllArrayNames();
  ///@}

  ///@{
  /**
   * Below this many points the filter runs serially (default 20000).
   */
  virtual int SetSerialThreshold(vtkIdType value);
  vtkIdType GetSerialThresholdMinValue() { return 0; }
  vtkIdType GetSerialThresholdMaxValue() { return VTK_ID_MAX; }
  vtkGetMacro(SerialThreshold, vtkIdType);
  ///@}

  /**
   * Includes the MTime of every probe's transforms, matrices or props.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkProbeDeformerLCT();
  ~vtkProbeDeformerLCT() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int BlendMode = POLAR;
  int WeightMode = INVERSE_DISTANCE;
  int Normalization = NORMALIZE_LINEAR;
  double Exponent = 1.0;
  char* WeightArrayName = nullptr;
  char* TransformIndexArrayName = nullptr;
  vtkTypeBool ConsistentRotation = 1;
  vtkIdType SerialThreshold = 20000;

private:
  vtkProbeDeformerLCT(const vtkProbeDeformerLCT&) = delete;
  void operator=(const vtkProbeDeformerLCT&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
