// Fuzz target: vtkSkeletonAnimationReader (assimp underneath) on arbitrary bytes written as a
// .bvh file: read it, step through a few of its times, query joints and transforms, and write it
// back as BVH.
//
// Properties: no crash, sanitizer report or hang in our code or assimp's; a file that loads has
// finite local transforms and finite output points, and a failed read reports an error and has
// no joints; WriteBVH either writes (and says nothing) or reports an error and leaves no file.
#include "FuzzInput.h"

#include "lct/Skeleton.h"
#include "vtkSkeletonAnimationReader.h"

#include "vtkInformation.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cstdio>
#include <fstream>
#include <string>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  static const std::string base = "/tmp/lct-fuzz-skeleton-" + std::to_string(getpid());
  const std::string file = base + ".bvh", written = base + "-out.bvh";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  lct_fuzz::ErrorObserver errors;
  vtkNew<vtkSkeletonAnimationReader> reader;
  errors.Observe(reader);
  reader->SetFileName(file.c_str());
  reader->UpdateInformation();
  const lct::SkeletalAnimation* a = reader->GetAnimation();
  if (!a)
  {
    LCT_FUZZ_CHECK(errors.Errors > 0, "a failed read reported no error");
    LCT_FUZZ_CHECK(reader->GetNumberOfJoints() == 0, "a failed read has joints");
    std::remove(file.c_str());
    return 0;
  }
  for (const Eigen::Matrix4d& m : a->locals)
  {
    LCT_FUZZ_CHECK(m.allFinite(), "a non-finite local transform was accepted");
  }
  const int before = errors.Errors;
  vtkInformation* info = reader->GetOutputInformation(0);
  const int steps = info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  LCT_FUZZ_CHECK(steps == a->frames, "TIME_STEPS " << steps << " for " << a->frames << " frames");
  const double* times = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  for (const int f : { 0, a->frames / 2, a->frames - 1 })
  {
    reader->UpdateTimeStep(times[f]);
    vtkPolyData* skeleton = reader->GetOutput();
    LCT_FUZZ_CHECK(skeleton->GetNumberOfPoints() == a->jointCount(), "one point per joint");
    for (vtkIdType p = 0; p < skeleton->GetNumberOfPoints(); ++p)
    {
      double x[3];
      skeleton->GetPoint(p, x);
      // World positions are products of finite transforms: finite unless they overflow.
      LCT_FUZZ_CHECK(std::isfinite(x[0] + x[1] + x[2]) || errors.Errors > before,
        "a non-finite joint position without an error");
    }
  }
  vtkNew<vtkMatrix4x4> m;
  LCT_FUZZ_CHECK(reader->GetLocalTransform(a->jointCount() - 1, a->frames - 1, m) == 1,
    "GetLocalTransform of the last joint and frame");
  const int writeErrors = errors.Errors;
  const int wrote = reader->WriteBVH(written.c_str(), "ZXY");
  LCT_FUZZ_CHECK((errors.Errors > writeErrors) == (wrote == 0), "WriteBVH error reporting");
  std::ifstream probe(written);
  LCT_FUZZ_CHECK(probe.good() == (wrote == 1), "WriteBVH left " << (wrote ? "no" : "a") << " file");
  std::ifstream part(written + ".part");
  LCT_FUZZ_CHECK(!part.good(), "WriteBVH left a .part file");
  std::remove(written.c_str());
  std::remove(file.c_str());
  return 0;
}
