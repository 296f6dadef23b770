/**
 * @class   vtkSkinnedMeshReaderLCT
 * @brief   reads a skinned character (mesh, bones, per-vertex bone weights, animation) through
 *          assimp, ready for vtkProbeDeformerLCT
 *
 * Every format assimp reads (X, FBX, glTF, Collada, …). The output is the character in its bind
 * pose, in world coordinates: every mesh of the file (triangulated) placed by its node, with
 * point data "BoneWeights" (float) and "BoneIndices" (int), k components each (k the largest
 * number of bones acting on one vertex; unused slots have weight 0), and the file's normals.
 * A bone is a (mesh, bone) pair of the file: its rest matrix is where the bone sat at bind time
 * (the mesh's node transform times the inverse of the bone's offset matrix), its matrix at time t
 * the bone node's world transform with the first animation sampled at t (seconds; keys
 * interpolated as assimp's viewer does). A mesh without bones follows its own node: it is one
 * more bone, weight 1.
 *
 * ConfigureDeformer(deformer, t) gives a vtkProbeDeformerLCT one probe per bone (current =
 * the bone at t, rest = its rest matrix), the weight arrays and POINT_DATA weights; calling it
 * again with another t moves the probes (the deformer re-executes), so stepping t through
 * [GetStartTime(), GetEndTime()] animates the character with any blend mode.
 *
 * Errors (a missing, unreadable or mesh-less file, one whose structure assimp's validation
 * refuses, a node transform or bone offset matrix that is not affine or not finite, or whose
 * 3x3 part is singular or beyond condition number 1e13 (a zero scale), a NaN vertex or weight,
 * an animation key (value or time) that is not finite or a zero rotation quaternion,
 * more than 10^7 vertices, 65536 bones or 32 influences per vertex) are reported with a
 * vtkErrorMacro naming the file (and the node or bone); the request fails and the output is
 * empty. A bone naming no node of the file is a warning: its vertices stay in the bind pose.
 * Queries return 0 (null for names) before a successful update or for indices out of range.
 *
 * @sa vtkProbeDeformerLCT vtkSkeletonAnimationReader
 */
#ifndef vtkSkinnedMeshReaderLCT_h
#define vtkSkinnedMeshReaderLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // For std::unique_ptr
#include <string> // For std::string

class vtkMatrix4x4;
class vtkProbeDeformerLCT;

class VTKLCT_EXPORT vtkSkinnedMeshReaderLCT : public vtkPolyDataAlgorithm
{
public:
  static vtkSkinnedMeshReaderLCT* New();
  vtkTypeMacro(vtkSkinnedMeshReaderLCT, vtkPolyDataAlgorithm);
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
   * The file extensions this reader reads (assimp's, on this system): lower case with the dot,
   * separated by spaces (".3ds .ac .ase ..."); and whether `extension` (".fbx" or "fbx", any
   * case) is one of them.
   */
  static std::string GetFileExtensions();
  static bool IsExtensionSupported(const char* extension);
  ///@}

  int GetNumberOfBones();
  const char* GetBoneName(int bone);
  /**
   * k: the number of components of BoneWeights and BoneIndices.
   */
  int GetMaximumInfluences();

  ///@{
  /**
   * The first animation's time range in seconds (0, 0 without animation).
   */
  double GetStartTime();
  double GetEndTime();
  ///@}

  ///@{
  /**
   * A bone's rest matrix and its matrix at `time` (clamped to the animation's range), both world
   * coordinates. Return 1, or 0 with an error for an index out of range, a null result, a time
   * that is not finite, a bone matrix that overflows (not finite) or before an update.
   */
  int GetBoneRestMatrix(int bone, vtkMatrix4x4* result);
  int GetBoneMatrix(int bone, double time, vtkMatrix4x4* result);
  ///@}

  /**
   * Give `deformer` one probe per bone at `time` and this reader's weight arrays (POINT_DATA,
   * linear normalisation). The probe matrices are the deformer's own: configuring another
   * deformer at another time leaves this one as it is. Returns 1, or 0 with an error (null
   * deformer, before an update, a time or a bone matrix that is not finite; the deformer is then
   * unchanged).
   */
  int ConfigureDeformer(vtkProbeDeformerLCT* deformer, double time);

protected:
  vtkSkinnedMeshReaderLCT();
  ~vtkSkinnedMeshReaderLCT() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;

private:
  vtkSkinnedMeshReaderLCT(const vtkSkinnedMeshReaderLCT&) = delete;
  void operator=(const vtkSkinnedMeshReaderLCT&) = delete;

  bool Load();
  bool Ready(const char* caller);

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
