// Fuzz target: vtkProbeDeformerLCT with arbitrary probes (NaN/Inf, projective, reflections,
// singular and extreme maps, exact half turns), points (float or double, extreme magnitudes),
// weights (distance kinds with arbitrary radii and exponents, or point-data arrays with NaN,
// negative sums and indices out of range), every blend mode and normalisation, serial or threaded,
// re-executed after a probe changes.
//
// Properties: no crash, sanitizer report or hang; an execution that succeeds reports no error and
// writes only finite points of the input's count; one that fails reports an error and leaves the
// output as the last valid result (same point count and coordinates).
#include "FuzzInput.h"

#include "vtkProbeDeformerLCT.h"

#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <vector>

namespace
{
using lct_fuzz::RowMajor4;
using lct_fuzz::ToVtk;

std::vector<double> PointsOf(vtkPointSet* p)
{
  std::vector<double> x;
  for (vtkIdType i = 0; i < p->GetNumberOfPoints(); ++i)
  {
    double q[3];
    p->GetPoint(i, q);
    x.insert(x.end(), q, q + 3);
  }
  return x;
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
  lct_fuzz::QuietOutputWindow::Install();
  lct_fuzz::Input in(data, size);
  const int probes = in.Int(0, 5);
  const int points = in.Int(0, 40);
  vtkNew<vtkPolyData> pd;
  vtkNew<vtkPoints> pts;
  if (in.Bool())
  {
    pts->SetDataTypeToDouble();
  }
  for (int i = 0; i < points; ++i)
  {
    const Eigen::Vector3d v = in.Vector();
    pts->InsertNextPoint(v.data());
  }
  pd->SetPoints(pts);
  const int slots = in.Int(1, 4);
  vtkSmartPointer<vtkDataArray> weights;
  weights.TakeReference(in.Bool() ? static_cast<vtkDataArray*>(vtkFloatArray::New())
                                  : static_cast<vtkDataArray*>(vtkDoubleArray::New()));
  weights->SetName("w");
  weights->SetNumberOfComponents(slots);
  weights->SetNumberOfTuples(points);
  vtkNew<vtkIntArray> indices;
  indices->SetName("i");
  indices->SetNumberOfComponents(slots);
  indices->SetNumberOfTuples(points);
  for (int i = 0; i < points * slots; ++i)
  {
    weights->SetComponent(i / slots, i % slots, in.Bool() ? in.Double() : in.Finite());
    indices->SetValue(i, in.Int(-1, probes));
  }
  pd->GetPointData()->AddArray(weights);
  pd->GetPointData()->AddArray(indices);

  lct_fuzz::ErrorObserver errors;
  vtkNew<vtkProbeDeformerLCT> f;
  errors.Observe(f);
  errors.Observe(f->GetExecutive());
  std::vector<vtkSmartPointer<vtkMatrix4x4>> current;
  for (int p = 0; p < probes; ++p)
  {
    current.push_back(ToVtk(in.Matrix()));
    f->AddProbe(current.back(), in.Bool() ? ToVtk(in.Matrix()).Get() : nullptr);
    f->SetProbeRadius(p, in.Double());
  }
  f->SetInputData(pd);
  std::vector<double> last;
  bool haveLast = false;
  for (int step = 0; step < 3 && !in.Empty(); ++step)
  {
    f->SetBlendMode(in.Int(0, 3));
    f->SetWeightMode(in.Int(0, 2));
    f->SetNormalization(in.Int(0, 2));
    f->SetExponent(in.Bool() ? in.Double() : 1.0);
    f->SetTransformIndexArrayName(in.Bool() ? "i" : nullptr);
    f->SetSerialThreshold(in.Bool() ? 0 : VTK_ID_MAX);
    if (probes > 0 && in.Bool())
    {
      const double r[3] = { in.Double(), in.Double(), in.Double() };
      f->SetProbeRotationReference(in.Int(0, probes - 1), r);
    }
    if (probes > 0)
    {
      current[in.Int(0, probes - 1)]->DeepCopy(RowMajor4(in.Matrix()).data());
    }
    const int before = errors.Errors;
    const int ok = f->GetExecutive()->Update();
    auto* out = vtkPointSet::SafeDownCast(f->GetOutputDataObject(0));
    const std::vector<double> now = PointsOf(out);
    if (ok)
    {
      LCT_FUZZ_CHECK(errors.Errors == before, "a successful execution reported an error");
      LCT_FUZZ_CHECK(out->GetNumberOfPoints() == points, "the output lost points");
      LCT_FUZZ_CHECK(lct_fuzz::AllFinite(now.data(), static_cast<int>(now.size())),
        "a non-finite point left a successful execution");
      last = now;
      haveLast = true;
    }
    else
    {
      LCT_FUZZ_CHECK(errors.Errors > before, "a failed execution reported no error");
      LCT_FUZZ_CHECK(haveLast ? now == last : now.empty(),
        "a failed execution changed the output (it must keep the last valid result)");
    }
  }
  return 0;
}
