/**
 * @class   vtkMotionCodecLCT
 * @brief   error-bounded compression of a skeletal animation into an .lctm file, and back
 *
 * The VTK face of lct/MotionCodec.h (the method and the file format are documented there and
 * in the README; `lct-mocap` is the command-line tool on the same code). Compress() takes the
 * animation a vtkSkeletonAnimationReader read, and writes an .lctm file whose decoded motion
 * is within the tolerance at every joint and end site of every frame (world positions; the
 * compressor decodes what it wrote and measures before the file is renamed into place).
 * Decompress() writes a decoded file back as BVH.
 *
 * The tolerance is Tolerance (file units) when it is positive, else RelativeTolerance times the
 * skeleton height H (the Y extent of the rest pose; default 0.01, i.e. 1 % of H). It must be at
 * least the precision of the reader's float32 values in world position
 * (lct::float32PositionResolution, ~1e-6 of H on the CMU clips): a smaller bound would be
 * verified against those values and missed against the file's own text.
 *
 * After a successful Compress(): GetCompressedBytes(), GetCompressionFactor() (4 bytes x frames
 * x channels / bytes, channels counted as a BVH file has them: 6 for each root, 3 for every
 * other joint with motion), GetMaximumError(), GetP99Error(), GetMeanError() (file units) and
 * GetSkeletonHeight(). After a failed call these are 0.
 *
 * Errors (vtkErrorMacro, return 0, no file written): no reader or a reader that has not read a
 * file, a tolerance that is not positive and finite, an animation the codec refuses (NaN, a
 * reflection, a tolerance below the precision of the values), an unwritable file name; for
 * Decompress a file that is not a complete, intact .lctm file (its reason named), a rotation
 * order that is not a permutation of "XYZ".
 *
 * Thread safety: one codec object must not be used from two threads at once.
 *
 * @sa vtkSkeletonAnimationReader vtkTransformSequencePCA
 */
#ifndef vtkMotionCodecLCT_h
#define vtkMotionCodecLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkObject.h"

class vtkSkeletonAnimationReader;

class VTKLCT_EXPORT vtkMotionCodecLCT : public vtkObject
{
public:
  static vtkMotionCodecLCT* New();
  vtkTypeMacro(vtkMotionCodecLCT, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The bound, in file units (used when > 0; default 0) or as a fraction of the skeleton
   * height (default 0.01).
   */
  vtkSetMacro(Tolerance, double);
  vtkGetMacro(Tolerance, double);
  vtkSetMacro(RelativeTolerance, double);
  vtkGetMacro(RelativeTolerance, double);
  ///@}

  ///@{
  /**
   * The BVH rotation channel order (a permutation of "XYZ"): stored in the file by Compress,
   * used by Decompress for the channels it writes. Default null: Compress stores "ZYX" and
   * Decompress uses the order stored in the file.
   */
  vtkSetStringMacro(RotationOrder);
  vtkGetStringMacro(RotationOrder);
  ///@}

  /**
   * Compresses the animation `reader` read (UpdateInformation() first) into `fileName`.
   * Returns 1 on success, 0 with an error (nothing written) for a bad setting, an animation
   * that cannot be held within the tolerance, or when memory runs out.
   */
  int Compress(vtkSkeletonAnimationReader* reader, const char* fileName);

  /**
   * Decodes `lctmFile` and writes it as BVH to `bvhFile`. Returns 1 on success, 0 with an
   * error (nothing written) for a file that is not a valid .lctm, a bad rotation order, or when
   * memory runs out (a small file can describe up to 3e7 transforms, ~4 GB decoded).
   */
  int Decompress(const char* lctmFile, const char* bvhFile);

  ///@{
  /**
   * Figures of the last successful Compress() (0 otherwise).
   */
  vtkGetMacro(CompressedBytes, vtkIdType);
  vtkGetMacro(CompressionFactor, double);
  vtkGetMacro(MaximumError, double);
  vtkGetMacro(P99Error, double);
  vtkGetMacro(MeanError, double);
  vtkGetMacro(SkeletonHeight, double);
  ///@}

protected:
  vtkMotionCodecLCT();
  ~vtkMotionCodecLCT() override;

private:
  /// The bodies of Compress and Decompress, which turn std::bad_alloc into an error.
  int CompressOrThrow(vtkSkeletonAnimationReader* reader, const char* fileName);
  int DecompressOrThrow(const char* lctmFile, const char* bvhFile);
  vtkMotionCodecLCT(const vtkMotionCodecLCT&) = delete;
  void operator=(const vtkMotionCodecLCT&) = delete;

  void ResetFigures();

  double Tolerance = 0.0;
  double RelativeTolerance = 0.01;
  char* RotationOrder = nullptr;
  vtkIdType CompressedBytes = 0;
  double CompressionFactor = 0.0;
  double MaximumError = 0.0;
  double P99Error = 0.0;
  double MeanError = 0.0;
  double SkeletonHeight = 0.0;
};

#endif
