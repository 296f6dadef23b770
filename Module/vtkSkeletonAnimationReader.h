/**
 * @class   vtkSkeletonAnimationReader
 * @brief   reads a skeletal animation (BVH, and the animated formats assimp reads: FBX, glTF,
 *          Collada, X, ...) as a time-aware poly data source and as per-joint transforms
 *
 * The file is read with assimp (libassimp, Debian's 5.2.5). The skeleton is every node of the
 * file's first animation that has an animation channel, its descendants (end sites: nodes
 * without children and without channels) and, for each tree of animated nodes, nothing above
 * its top-most one. Each joint's local transform at each frame is T(position) R(rotation)
 * S(scale) from its channel's keys, sampled at the frame times (linear for position and scale,
 * slerp for rotation, between keys; a single key is constant), or the node's own transform for
 * joints without a channel (end sites, fixed helper nodes). Frames are the key times of the
 * channel with the most keys when they are evenly spaced (within 1 % of the step); where they
 * are not (keys at 1/24 s to 23/24 s, then at 4.2 s), or where other channels' keys or the
 * animation's duration reach beyond them, the frames cover that whole span, evenly spaced at
 * that channel's rate (for uneven keys, their finest spacing) or finer, within the limits below.
 * For BVH they are the file's data rows, at its Frame Time: as many as its Frames: line declares
 * (rows after them are not read, with a warning; a count the rows read do not match, such as
 * Frames: 0 before a row, is an error, and so is a MOTION section without rows). The text is
 * read as assimp reads it, as tokens between white space whatever the line ends (LF, CR LF, CR),
 * so the Frames: count or the Frame Time may be on the next line; a file starting with HIERARCHY
 * whose MOTION section does not read so, or whose Frames: count is not a whole number within the
 * limits below, is an error before assimp reads it. A BVH joint's translation is its OFFSET plus
 * its position channels (the BVH convention; assimp 5.2 replaces the OFFSET, which the reader
 * adds back). What assimp would read other than the text says is an error naming the line or
 * joint: a data row without one value per channel (assimp reads values regardless of lines and
 * would shift every later frame), position channels on a joint whose channel count is not 6
 * (assimp drops them), and a rotation value beyond +-10^4 degrees (assimp converts degrees to
 * radians in float32, which loses such an angle).
 *
 * Output (vtkPolyDataAlgorithm, one frame per request): the joints' world positions as points
 * (end sites included), bones as lines (parent to child), point data "JointName"
 * (vtkStringArray), "JointId", "Parent" and "Depth" (vtkIntArray), field data "Frame". The
 * frame times are advertised as TIME_STEPS (and TIME_RANGE), so VTK's animation machinery and
 * ParaView-style scripts step through them; a requested time between frames gives the nearest
 * frame, outside the range (+-Inf included) the first or last.
 *
 * For analysis and for the interpolators, after UpdateInformation() (or Update()):
 * GetNumberOfJoints, GetJointName, GetJointParent, IsEndSite, GetNumberOfFrames, GetFrameTime,
 * GetLocalTransform(joint, frame) and GetWorldTransform(joint, frame).
 *
 * Known limits of assimp 5.2: values are parsed as float32 (a BVH Frame Time outside float's
 * normal range is an error), and a BVH file's Euler channel order survives only inside the
 * rotation quaternions. Unreadable, empty or malformed files, a file without animation,
 * non-finite values, and more than 10000 joints or 3 10^7 transforms (frames x joints) are
 * reported with a vtkErrorMacro; the request fails, the output is emptied and TIME_STEPS and
 * TIME_RANGE are removed (a file read before leaves nothing behind).
 *
 * Thread safety: like any VTK algorithm, one reader must not be updated from two threads at
 * once; the Get methods only read, and may run concurrently once an update has returned.
 *
 * @sa vtkTransformSequencePCA vtkTransformInterpolatorLCT
 */
#ifndef vtkSkeletonAnimationReader_h
#define vtkSkeletonAnimationReader_h

#include "vtkLCTModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <string> // For the file name

class vtkMatrix4x4;

namespace lct
{
struct SkeletalAnimation;
}

class VTKLCT_EXPORT vtkSkeletonAnimationReader : public vtkPolyDataAlgorithm
{
public:
  static vtkSkeletonAnimationReader* New();
  vtkTypeMacro(vtkSkeletonAnimationReader, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  ///@{
  /**
   * The skeleton and its motion, valid after UpdateInformation() succeeded (0 or null, with an
   * error, before; and for indices out of range).
   */
  int GetNumberOfJoints();
  const char* GetJointName(int joint);
  int GetJointParent(int joint);
  int IsEndSite(int joint);
  int GetNumberOfFrames();
  double GetFrameTime();
  ///@}

  ///@{
  /**
   * The local transform of a joint at a frame (into its parent's frame), or its world
   * transform (root to joint). Return 0 with an error (result untouched) for indices out of
   * range or before the file was read.
   */
  int GetLocalTransform(int joint, int frame, vtkMatrix4x4* result);
  int GetWorldTransform(int joint, int frame, vtkMatrix4x4* result);
  ///@}

  /**
   * Write the animation read as a BVH file (lct/BVHWriter.h): the same joint names, hierarchy,
   * offsets and frame time, rotation channels in `rotationOrder` (a permutation of "XYZ", e.g.
   * "ZYX"), position channels for the root and any joint that moves. Written to a temporary
   * name and renamed, so a failure leaves no file. Returns 0 with an error before the file was
   * read, for a bad order, for transforms with scale or shear, for a skeleton with several roots
   * (a BVH file holds one hierarchy), or when writing fails.
   */
  int WriteBVH(const char* fileName, const char* rotationOrder);

#ifndef __VTK_WRAP__
  /**
   * The whole animation (null before the file was read): for C++ analysis code.
   */
  const lct::SkeletalAnimation* GetAnimation();
#endif

protected:
  vtkSkeletonAnimationReader();
  ~vtkSkeletonAnimationReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkSkeletonAnimationReader(const vtkSkeletonAnimationReader&) = delete;
  void operator=(const vtkSkeletonAnimationReader&) = delete;

  bool Load();
  bool Valid(int joint, int frame, const char* caller);

  char* FileName = nullptr;
  struct Internals;
  Internals* Internal;
};

#endif
