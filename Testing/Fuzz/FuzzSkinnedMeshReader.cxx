// Fuzz target: vtkSkinnedMeshReaderLCT (assimp underneath) on arbitrary bytes written as an .obj
// file, then the mesh driven by vtkProbeDeformerLCT in every blend mode at three times.
//
// OBJ only: assimp 5.2's binary X and Collada loaders allocate from counts in the file without a
// bound (2 GB from a 2.8 kB .x, 3 GB from a .dae, found here: README T2), which is assimp's
// defect, fuzzed upstream, and no longer this target's subject. OBJ declares no counts: what its
// loader allocates grows with the bytes it reads. The reader's own code (node walk, meshes
// without bones, weights, bounds, the deformer on its output) is what is fuzzed.
//
// Properties: no crash, sanitizer report or hang; a read that succeeds reports no error and gives
// finite points, weights with an index per slot inside the bone range, finite bone matrices; a
// failed read reports an error and has no points and no bones; the deformer either succeeds with
// finite points or reports an error.
#include "FuzzInput.h"

#include "vtkProbeDeformerLCT.h"
#include "vtkSkinnedMeshReaderLCT.h"

#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  // assimp picks its OBJ loader by the extension, whatever the bytes look like.
  const std::string file = "/tmp/lct-fuzz-skinned-" + std::to_string(getpid()) + ".obj";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  lct_fuzz::ErrorObserver errors;
  vtkNew<vtkSkinnedMeshReaderLCT> reader;
  errors.Observe(reader);
  errors.Observe(reader->GetExecutive());
  reader->SetFileName(file.c_str());
  const int ok = reader->GetExecutive()->Update();
  vtkPolyData* mesh = reader->GetOutput();
  if (!ok)
  {
    LCT_FUZZ_CHECK(errors.Errors > 0, "a failed read reported no error");
    LCT_FUZZ_CHECK(mesh->GetNumberOfPoints() == 0 && reader->GetNumberOfBones() == 0,
      "a failed read has points or bones");
    std::remove(file.c_str());
    return 0;
  }
  LCT_FUZZ_CHECK(errors.Errors == 0, "a successful read reported an error: " << errors.Last);
  const int bones = reader->GetNumberOfBones();
  vtkDataArray* idx = mesh->GetPointData()->GetArray("BoneIndices");
  vtkDataArray* w = mesh->GetPointData()->GetArray("BoneWeights");
  LCT_FUZZ_CHECK(idx && w && bones > 0, "a read mesh without bones or weights");
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    LCT_FUZZ_CHECK(lct_fuzz::AllFinite(p, 3), "a non-finite point was read");
    for (int k = 0; k < idx->GetNumberOfComponents(); ++k)
    {
      const double b = idx->GetComponent(i, k);
      LCT_FUZZ_CHECK(b >= 0 && b < bones, "bone index " << b << " of " << bones);
      LCT_FUZZ_CHECK(std::isfinite(w->GetComponent(i, k)), "a non-finite weight was read");
    }
  }
  vtkNew<vtkMatrix4x4> m;
  for (int b = 0; b < bones && b < 64; ++b)
  {
    LCT_FUZZ_CHECK(reader->GetBoneRestMatrix(b, m) == 1, "GetBoneRestMatrix failed");
    LCT_FUZZ_CHECK(lct_fuzz::AllFinite(m->GetData(), 16), "a non-finite rest matrix");
  }
  vtkNew<vtkProbeDeformerLCT> deformer;
  errors.Observe(deformer);
  errors.Observe(deformer->GetExecutive());
  deformer->SetInputConnection(reader->GetOutputPort());
  const double t0 = reader->GetStartTime(), t1 = reader->GetEndTime();
  for (int mode = 0; mode < 4; ++mode)
  {
    deformer->SetBlendMode(mode);
    for (const double t : { t0, 0.5 * (t0 + t1), t1 })
    {
      LCT_FUZZ_CHECK(reader->ConfigureDeformer(deformer, t) == 1, "ConfigureDeformer failed");
      const int before = errors.Errors;
      if (deformer->GetExecutive()->Update())
      {
        LCT_FUZZ_CHECK(errors.Errors == before, "a successful deformation reported an error");
        vtkPointSet* out = vtkPointSet::SafeDownCast(deformer->GetOutputDataObject(0));
        for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
        {
          double p[3];
          out->GetPoint(i, p);
          LCT_FUZZ_CHECK(lct_fuzz::AllFinite(p, 3), "a non-finite deformed point");
        }
      }
      else
      {
        LCT_FUZZ_CHECK(errors.Errors > before, "a failed deformation reported no error");
      }
    }
  }
  std::remove(file.c_str());
  return 0;
}
