/**
 * @class   vtkTransformSequencePCA
 * @brief   principal component analysis of an animation of transforms in log space
 *          (Alexa 2002 §6.3): explained variance, reconstruction from r components, and the
 *          principal "eigen-motions" as transforms
 *
 * The input is F frames of C channels (the joints of a skeleton, the objects of a scene): add
 * one frame at a time as a vtkCollection of vtkMatrix4x4 or vtkLinearTransform, C items each.
 * Compute() takes the logs of every transform and analyses them (lct/SequencePCA.h):
 *
 * - logs continuous in time: with the POLAR parametrisation (default) each channel's log is
 *   taken nearest to the previous frame's (Kaji & Ochiai Algorithm 1), so a joint turning
 *   through 180 degrees does not jump by 2 pi; MATRIX_LOG (Alexa's) has principal logs only, and
 *   a channel whose rotation passes 180 degrees is reported as an error there;
 * - tangent PCA at each channel's mean log, in Alexa's entry-wise inner product of log
 *   matrices, weighted per channel (SetChannelWeight: e.g. by how far a joint's error travels
 *   down the skeleton);
 * - an optional root channel (SetRootChannel) that is factored out: its (global) motion is kept
 *   exactly, per frame, and the components describe the other channels only.
 *
 * Then GetExplainedVariance gives each component's share of the variance,
 * GetReconstructedTransform the transform of a frame and channel from the first r components,
 * GetEigenMotion the transform mean (+) s (.) component (s in standard deviations), for
 * visualising what each component does, and GetScores the coordinates of a frame.
 *
 * Every method validates its input (null or mismatched collections, invalid transforms with
 * the frame and channel named, indices and weights out of range, queries before Compute() or
 * after the input changed) with a vtkErrorMacro and a return value of 0; outputs are untouched.
 * Queries are read-only and may run concurrently once Compute() has returned; nothing may run
 * concurrently with a method that changes the input or with Compute().
 *
 * @sa vtkTransformBasisLCT vtkLogTransform
 */
#ifndef vtkTransformSequencePCA_h
#define vtkTransformSequencePCA_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"

class vtkCollection;
class vtkDoubleArray;
class vtkMatrix4x4;

class VTKLCT_EXPORT vtkTransformSequencePCA : public vtkObject
{
public:
  static vtkTransformSequencePCA* New();
  vtkTypeMacro(vtkTransformSequencePCA, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ParametrisationType
  {
    POLAR = 0,
    MATRIX_LOG = 1
  };

  ///@{
  /**
   * The parametrisation of the logs: POLAR (default) or MATRIX_LOG.
   */
  virtual int SetParametrisation(int value);
  int GetParametrisationMinValue() { return POLAR; }
  int GetParametrisationMaxValue() { return MATRIX_LOG; }
  vtkGetMacro(Parametrisation, int);
  void SetParametrisationToPolar() { this->SetParametrisation(POLAR); }
  void SetParametrisationToMatrixLog() { this->SetParametrisation(MATRIX_LOG); }
  ///@}

  /**
   * Append a frame: a collection of vtkMatrix4x4 or vtkLinearTransform, one per channel (the
   * first frame sets the channel count; at most 100000 channels and 10^8 transforms in all).
   * Returns 0 with an error (no frame added) for a null or empty collection, another item type
   * or a channel count other than the first frame's. The transforms are validated by Compute().
   */
  int AddFrame(vtkCollection* transforms);

  /**
   * Remove every frame (and the channel count, weights and root channel with it).
   */
  void RemoveAllFrames();

  int GetNumberOfFrames();
  int GetNumberOfChannels();

  ///@{
  /**
   * The weight of a channel in the analysis (default 1; must be finite and positive). Returns
   * 0 with an error for a bad channel or weight. Compute() refuses weights more than 1e16 apart
   * (lct::kMaxChannelWeightRatio): lighter channels would fall below the SVD's resolution.
   */
  int SetChannelWeight(int channel, double weight);
  double GetChannelWeight(int channel);
  ///@}

  ///@{
  /**
   * The root channel, factored out of the analysis and reproduced exactly (-1, the default:
   * none). Checked by Compute().
   */
  vtkSetMacro(RootChannel, int);
  vtkGetMacro(RootChannel, int);
  ///@}

  ///@{
  /**
   * Keep at most this many components (0, the default: every component with a non-zero
   * singular value).
   */
  virtual int SetMaximumNumberOfComponents(int value);
  int GetMaximumNumberOfComponentsMinValue() { return 0; }
  int GetMaximumNumberOfComponentsMaxValue() { return VTK_INT_MAX; }
  vtkGetMacro(MaximumNumberOfComponents, int);
  ///@}

  /**
   * Take the logs and analyse them. Returns 0 with an error naming the frame and channel of
   * an invalid transform (NaN/Inf, projective, det <= 0, singular, no MATRIX_LOG log, a
   * MATRIX_LOG rotation jumping through 180 degrees), a root channel out of range, or no
   * channel left to analyse; the previous analysis is then discarded.
   */
  int Compute();

  /**
   * The number of components kept by the last Compute() (0 before).
   */
  int GetNumberOfComponents();

  /**
   * Each kept component's fraction of the total variance of the analysed channels (in the
   * weighted inner product), descending. Returns 0 with an error before Compute().
   */
  int GetExplainedVariance(vtkDoubleArray* fractions);

  /**
   * The fraction of the variance the first r components explain (0 with an error for r < 0);
   * r beyond GetNumberOfComponents() counts the kept ones only, as GetReconstructedTransform
   * does.
   */
  double GetExplainedFraction(int components);

  /**
   * The transform of `channel` at `frame` reconstructed from the first `components`
   * components (clamped to GetNumberOfComponents(); 0: the channel's mean). The root channel
   * comes back as it was given. Returns 0 with an error for indices out of range, a negative
   * count or before Compute().
   */
  int GetReconstructedTransform(int frame, int channel, int components, vtkMatrix4x4* result);

  /**
   * Channel `channel` of the `component`-th eigen-motion at s standard deviations:
   * exp(mean + s sigma / sqrt(F) d). The root channel gives its mean. Returns 0 with an error
   * for indices out of range, a non-finite s, an overflow or before Compute().
   */
  int GetEigenMotion(int component, int channel, double s, vtkMatrix4x4* result);

  /**
   * The mean transform of a channel (exp of its mean log).
   */
  int GetMeanTransform(int channel, vtkMatrix4x4* result);

  /**
   * The coordinates of `frame` along every kept component (GetNumberOfComponents() tuples).
   * Returns 0 with an error (scores untouched) for a bad frame or before Compute().
   */
  int GetScores(int frame, vtkDoubleArray* scores);

protected:
  vtkTransformSequencePCA();
  ~vtkTransformSequencePCA() override;

private:
  vtkTransformSequencePCA(const vtkTransformSequencePCA&) = delete;
  void operator=(const vtkTransformSequencePCA&) = delete;

  struct Internals;
  /// Whether the analysis is current, with an error naming `caller` when not or when the
  /// caller's `output` is null.
  bool Analysed(const char* caller, const void* output);
  int Output(const double log[12], vtkMatrix4x4* result, const char* caller);

  Internals* Internal;
  int Parametrisation = POLAR;
  int RootChannel = -1;
  int MaximumNumberOfComponents = 0;
};

#endif
