/**
 * @class   vtkShapeBlenderLCT
 * @brief   blends compatibly triangulated meshes by their per-face affine maps in log
 *          coordinates, patched into one mesh by least squares (Kaji & Ochiai §5.3)
 *
 * Input port 0 is the rest mesh U_0 (triangles only); AddTarget adds meshes U_1 … U_k with the
 * same points count and the same triangles (the same connectivity, point ids in the same order),
 * and SetWeight(i, w_i) sets their weights (default 0; any finite real: w < 0 and w > 1
 * extrapolate). The output is the rest mesh's topology with the blended points:
 *
 * - per face j and target i, the linear map A_ij taking the rest triangle plus its ghost vertex
 *   (centroid + n / sqrt|n|, n the unnormalised normal; Sumner & Popović's fourth vertex as Kaji
 *   places it) to the target's; its Polar log psi(A_ij) (Kaji & Ochiai eq. 3) with rotation
 *   branches made consistent over the face-adjacency graph (a walk from the face that turned
 *   least, each face's log nearest its parent's, Alg. 1), so twists beyond 180 degrees blend
 *   without tearing or collapse;
 * - per face the blend B_j = phi(sum_i w_i psi(A_ij)) (eq. 9);
 * - the points whose per-face maps (with the ghost vertices as unknowns, solved out exactly) are
 *   closest to the B_j in least squares. The normal equations are factorised once per rest mesh
 *   (Eigen's SimplicialLDLT) and each blend is one back-substitution.
 *
 * Translation: each vertex-connected piece of the mesh is translated so that its point centroid
 * is (1 - sum_i w_i) c_0 + sum_i w_i c_i, the blend of that piece's centroids in the rest mesh and
 * the targets. So all weights 0 reproduce the rest mesh and w = e_i target i (to round-off), and
 * disconnected pieces are each placed by their own centroids. Points that no triangle uses move by
 * that linear blend of their own positions.
 *
 * Caching: the factorisation depends on the rest mesh only, the per-face logs on the rest mesh and
 * the targets; both are recomputed only when those change (their MTime), never when only the
 * weights change, so moving a weight slider costs one blend (GetNumberOfFactorizations and
 * GetNumberOfLogComputations count the recomputations). MTime includes the targets'.
 *
 * Output: the rest mesh's points (same precision: float or double; other types become double),
 * polys, verts and lines, point and cell data passed from the rest mesh, except the normals:
 * point and cell normals are dropped (they would be those of the rest shape; recompute them with
 * vtkPolyDataNormals).
 *
 * Bad input is reported with a vtkErrorMacro naming the target, face or point; RequestData then
 * returns 0 and the output keeps its last valid result (empty before the first): no input, no
 * triangles, polygons that are not triangles or triangle strips (run vtkTriangleFilter on the rest
 * mesh and every target), NaN/Inf points, degenerate (zero-area) triangles in the rest mesh or a
 * target, triangles too large or too small for double's range (beyond 2^+-480, ~1e+-144: areas
 * would overflow or underflow), a target with another point count or other triangles (count or
 * connectivity), NaN/Inf weights, a blend whose maps overflow (an extrapolation too far), float
 * points whose blend leaves float's range. SetWeight / GetWeight with an index out of range and
 * AddTarget(nullptr) are reported at once.
 *
 * @warning Targets are read when the filter executes; they are not pipeline inputs (a target
 * produced by a filter must be updated first). The filter holds a reference to each target.
 *
 * @sa vtkProbeDeformerLCT vtkLogTransform
 */
#ifndef vtkShapeBlenderLCT_h
#define vtkShapeBlenderLCT_h

#include "vtkLCTModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include <memory> // For std::unique_ptr

class vtkPolyData;

class VTKLCT_EXPORT vtkShapeBlenderLCT : public vtkPolyDataAlgorithm
{
public:
  static vtkShapeBlenderLCT* New();
  vtkTypeMacro(vtkShapeBlenderLCT, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Add a target mesh (weight 0). Returns its index, or -1 with an error for a null target.
   * Its points and triangles are checked against the rest mesh at execution.
   */
  int AddTarget(vtkPolyData* target);

  /**
   * Remove every target (and its weight).
   */
  void RemoveAllTargets();

  int GetNumberOfTargets();

  /**
   * Target i, or null with an error for an index out of range.
   */
  vtkPolyData* GetTarget(int i);

  ///@{
  /**
   * The weight of target i (default 0). Any value is stored; NaN and Inf are reported at
   * execution. An index out of range is an error: SetWeight returns 0 (1 on success), GetWeight
   * returns 0.
   */
  int SetWeight(int i, double w);
  double GetWeight(int i);
  ///@}

  ///@{
  /**
   * How many times the normal equations were factorised / the targets' per-face logs were
   * computed (for tests and profiling: weights alone change neither).
   */
  vtkGetMacro(NumberOfFactorizations, vtkIdType);
  vtkGetMacro(NumberOfLogComputations, vtkIdType);
  ///@}

  ///@{
  /**
   * Below this many faces the per-face work runs serially (default 5000); above it vtkSMPTools
   * splits it. The result does not depend on it.
   */
  virtual int SetSerialThreshold(vtkIdType value);
  vtkIdType GetSerialThresholdMinValue() { return 0; }
  vtkIdType GetSerialThresholdMaxValue() { return VTK_ID_MAX; }
  vtkGetMacro(SerialThreshold, vtkIdType);
  ///@}

  /**
   * Includes the MTime of every target.
   */
  vtkMTimeType GetMTime() override;

protected:
  vtkShapeBlenderLCT();
  ~vtkShapeBlenderLCT() override;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfFactorizations = 0;
  vtkIdType NumberOfLogComputations = 0;
  vtkIdType SerialThreshold = 5000;

private:
  vtkShapeBlenderLCT(const vtkShapeBlenderLCT&) = delete;
  void operator=(const vtkShapeBlenderLCT&) = delete;

  struct Internals;
  std::unique_ptr<Internals> Internal;
};

#endif
