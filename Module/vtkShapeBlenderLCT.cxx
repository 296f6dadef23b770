#include "vtkShapeBlenderLCT.h"

#include "vtkLCTCheckedSet.h"

#include "lct/Format.h"
#include "lct/ShapeBlend.h"
#include "lct/Status.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLCTLastOutput.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkShapeBlenderLCT);

namespace
{
struct Target
{
  vtkSmartPointer<vtkPolyData> Mesh;
  double Weight = 0.0;
};

/// What the cached geometry of a mesh was computed from: its points and polys objects and their
/// MTimes (not the mesh's MTime, which also moves with its point and cell data).
struct GeometryKey
{
  const void* Mesh = nullptr;
  /// The mesh object's own time too (not vtkDataSet::GetMTime, which point data arrays also
  /// advance): vtkPoints::SetPoint does not modify the points, and a user who then calls
  /// Modified() on the mesh (the usual way) changes only the mesh's own time.
  vtkMTimeType MeshTime = 0;
  const void* Points = nullptr;
  vtkMTimeType PointsTime = 0;
  const void* Polys = nullptr;
  vtkMTimeType PolysTime = 0;
  vtkMTimeType StripsTime = 0;

  bool operator==(const GeometryKey& o) const
  {
    return Mesh == o.Mesh && MeshTime == o.MeshTime && Points == o.Points &&
      PointsTime == o.PointsTime && Polys == o.Polys && PolysTime == o.PolysTime &&
      StripsTime == o.StripsTime;
  }
};

GeometryKey keyOf(vtkPolyData* pd)
{
  GeometryKey k;
  k.Mesh = pd;
  k.MeshTime = pd->vtkObject::GetMTime();
  k.Points = pd->GetPoints();
  k.PointsTime = pd->GetPoints() ? pd->GetPoints()->GetMTime() : 0;
  k.Polys = pd->GetPolys();
  k.PolysTime = pd->GetPolys() ? pd->GetPolys()->GetMTime() : 0;
  k.StripsTime = pd->GetStrips() ? pd->GetStrips()->GetMTime() : 0;
  return k;
}

std::vector<Eigen::Vector3d> pointsOf(vtkPolyData* pd)
{
  const vtkIdType n = pd->GetNumberOfPoints();
  std::vector<Eigen::Vector3d> out(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    pd->GetPoint(i, out[i].data());
  }
  return out;
}

std::string formatPoint(const Eigen::Vector3d& p)
{
  return "(" + lct::formatNumber(p[0]) + ", " + lct::formatNumber(p[1]) + ", " +
    lct::formatNumber(p[2]) + ")";
}

/// The triangles of a mesh's polys; empty with `error` set when a polygon is not a triangle.
std::vector<lct::Triangle> trianglesOf(vtkPolyData* pd, std::string& error)
{
  std::vector<lct::Triangle> out;
  vtkCellArray* polys = pd->GetPolys();
  if (!polys)
  {
    return out;
  }
  out.reserve(polys->GetNumberOfCells());
  auto it = vtk::TakeSmartPointer(polys->NewIterator());
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    it->GetCurrentCell(n, ids);
    if (n != 3)
    {
      error = "polygon " + std::to_string(it->GetCurrentCellId()) + " has " + std::to_string(n) +
        " points: only triangles are blended (run vtkTriangleFilter on the rest mesh and every "
        "target)";
      return {};
    }
    out.push_back({ ids[0], ids[1], ids[2] });
  }
  return out;
}

std::string describeTriangle(const std::vector<lct::Triangle>& triangles, std::int64_t face)
{
  if (face < 0 || face >= static_cast<std::int64_t>(triangles.size()))
  {
    return "triangle " + std::to_string(face);
  }
  const lct::Triangle& t = triangles[face];
  return "triangle " + std::to_string(face) + " (points " + std::to_string(t[0]) + ", " +
    std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")";
}

/// lct::triangleThinness of triangle t.
double thinness(const lct::Triangle& t, const std::vector<Eigen::Vector3d>& points)
{
  return lct::triangleThinness(points[t[0]], points[t[1]], points[t[2]]);
}

/// Why a triangle beyond lct::kTriangleScaleExponent is refused, with its size.
std::string scaleRangeProblem(const lct::Triangle& t, const std::vector<Eigen::Vector3d>& points)
{
  const double largest = lct::triangleSize(points[t[0]], points[t[1]], points[t[2]]);
  const double bound = std::ldexp(1.0, lct::kTriangleScaleExponent);
  return std::string("too ") + (largest > 1.0 ? "large" : "small") +
    " (its largest edge coordinate is " + lct::formatNumber(largest) + "; the blender needs " +
    lct::formatNumber(1.0 / bound) + " to " + lct::formatNumber(bound) +
    ", so that areas stay within double's range): rescale the meshes";
}
} // namespace

struct vtkShapeBlenderLCT::Internals
{
  std::vector<Target> Targets;
  lct::ShapeBlender Blender;
  /// The rest geometry the factorisation was computed from (valid when RestValid).
  bool RestValid = false;
  GeometryKey Rest;
  std::vector<lct::Triangle> Triangles;
  /// The targets the logs were computed from (valid when TargetsValid).
  bool TargetsValid = false;
  std::vector<GeometryKey> TargetKeys;
  /// The last valid output, handed back when an execution fails.
  vtkLCTLastOutput LastOutput;
};

vtkShapeBlenderLCT::vtkShapeBlenderLCT()
  : Internal(new Internals)
{
}

vtkShapeBlenderLCT::~vtkShapeBlenderLCT() = default;

int vtkShapeBlenderLCT::AddTarget(vtkPolyData* target)
{
  if (!target)
  {
    vtkErrorMacro(<< "AddTarget: the target is null");
    return -1;
  }
  this->Internal->Targets.push_back({ target, 0.0 });
  this->Modified();
  return static_cast<int>(this->Internal->Targets.size()) - 1;
}

void vtkShapeBlenderLCT::RemoveAllTargets()
{
  if (!this->Internal->Targets.empty())
  {
    this->Internal->Targets.clear();
    this->Modified();
  }
}

int vtkShapeBlenderLCT::GetNumberOfTargets()
{
  return static_cast<int>(this->Internal->Targets.size());
}

vtkPolyData* vtkShapeBlenderLCT::GetTarget(int i)
{
  if (i < 0 || i >= this->GetNumberOfTargets())
  {
    vtkErrorMacro(<< "GetTarget: target " << i << " is outside [0, " << this->GetNumberOfTargets()
                  << ")");
    return nullptr;
  }
  return this->Internal->Targets[i].Mesh;
}

int vtkShapeBlenderLCT::SetWeight(int i, double w)
{
  if (i < 0 || i >= this->GetNumberOfTargets())
  {
    vtkErrorMacro(<< "SetWeight: target " << i << " is outside [0, " << this->GetNumberOfTargets()
                  << ")");
    return 0;
  }
  // Compared bitwise so that setting NaN again still counts as no change.
  double& stored = this->Internal->Targets[i].Weight;
  if (!(stored == w) && !(std::isnan(stored) && std::isnan(w)))
  {
    stored = w;
    this->Modified();
  }
  return 1;
}

double vtkShapeBlenderLCT::GetWeight(int i)
{
  if (i < 0 || i >= this->GetNumberOfTargets())
  {
    vtkErrorMacro(<< "GetWeight: target " << i << " is outside [0, " << this->GetNumberOfTargets()
                  << ")");
    return 0.0;
  }
  return this->Internal->Targets[i].Weight;
}

vtkMTimeType vtkShapeBlenderLCT::GetMTime()
{
  vtkMTimeType m = this->Superclass::GetMTime();
  for (const Target& t : this->Internal->Targets)
  {
    m = std::max(m, t.Mesh->GetMTime());
  }
  return this->Internal->LastOutput.WithFailure(m);
}

int vtkShapeBlenderLCT::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  Internals& in = *this->Internal;
  // On any failure: the message, and the last valid output back in place.
  const auto fail = [&]() { return in.LastOutput.Restore(output); };
  if (!input || !output)
  {
    vtkErrorMacro(<< "no input: connect the rest mesh (vtkPolyData) to port 0");
    return fail();
  }
  const vtkIdType serialThreshold = this->SerialThreshold;
  const lct::ParallelFor parallel = [serialThreshold](std::int64_t n,
                                      const std::function<void(std::int64_t, std::int64_t)>& body) {
    if (n < serialThreshold)
    {
      body(0, n);
    }
    else
    {
      vtkSMPTools::For(0, static_cast<vtkIdType>(n), [&body](vtkIdType begin, vtkIdType end) {
        body(static_cast<std::int64_t>(begin), static_cast<std::int64_t>(end));
      });
    }
  };

  // The rest mesh: validated and factorised when its geometry changed.
  const GeometryKey restKey = keyOf(input);
  if (!in.RestValid || !(in.Rest == restKey))
  {
    in.RestValid = false;
    in.TargetsValid = false;
    if (input->GetStrips() && input->GetStrips()->GetNumberOfCells() > 0)
    {
      vtkErrorMacro(<< "rest mesh: it has " << input->GetStrips()->GetNumberOfCells()
                    << " triangle strips; only polys that are triangles are blended (run "
                       "vtkTriangleFilter on the rest mesh and every target)");
      return fail();
    }
    std::string error;
    std::vector<lct::Triangle> triangles = trianglesOf(input, error);
    if (!error.empty())
    {
      vtkErrorMacro(<< "rest mesh: " << error);
      return fail();
    }
    if (triangles.empty())
    {
      vtkErrorMacro(<< "rest mesh: it has no triangles (" << input->GetNumberOfPoints()
                    << " points, " << input->GetNumberOfCells() << " cells)");
      return fail();
    }
    const std::vector<Eigen::Vector3d> points = pointsOf(input);
    const lct::ShapeBlendIssue issue = in.Blender.setRest(points, triangles, parallel);
    ++this->NumberOfFactorizations;
    if (!issue.ok())
    {
      if (issue.status == lct::Status::NonFinite && issue.point >= 0)
      {
        vtkErrorMacro(<< "rest mesh: point " << issue.point << " is "
                      << formatPoint(points[issue.point]) << ": NaN or Inf");
      }
      else if (issue.status == lct::Status::Singular)
      {
        vtkErrorMacro(<< "rest mesh: " << describeTriangle(triangles, issue.face)
                      << " is degenerate (zero or near-zero area): its affine map is undefined");
      }
      else if (issue.status == lct::Status::OutOfRange && issue.face >= 0 &&
        !lct::isTriangleScaleInRange(points[triangles[issue.face][0]],
          points[triangles[issue.face][1]], points[triangles[issue.face][2]]))
      {
        vtkErrorMacro(<< "rest mesh: " << describeTriangle(triangles, issue.face) << " is "
                      << scaleRangeProblem(triangles[issue.face], points));
      }
      else if (issue.status == lct::Status::OutOfRange && issue.face >= 0)
      {
        vtkErrorMacro(<< "rest mesh: " << describeTriangle(triangles, issue.face)
                      << " is too thin for its size: " << lct::describe(issue.status));
      }
      else if (issue.status == lct::Status::InvalidArgument && issue.face >= 0)
      {
        vtkErrorMacro(<< "rest mesh: " << describeTriangle(triangles, issue.face)
                      << " refers to a point outside [0, " << points.size() << ")");
      }
      else if (issue.status == lct::Status::NumericalFailure)
      {
        // Not an eigensolver (lct::describe's words for NumericalFailure): the sparse LDL^T of
        // the normal equations, whose entries grow as 1 / (area): slivers above the degenerate
        // threshold (sine 1e-9 of the smallest angle) already make it indefinite in double.
        std::size_t thinnest = 0;
        for (std::size_t j = 1; j < triangles.size(); ++j)
        {
          thinnest =
            thinness(triangles[j], points) < thinness(triangles[thinnest], points) ? j : thinnest;
        }
        vtkErrorMacro(<< "rest mesh: the normal equations cannot be factorised in double "
                         "precision: its thinnest triangle, "
                      << describeTriangle(triangles, static_cast<std::int64_t>(thinnest))
                      << ", has |n| / (longest edge)^2 = "
                      << lct::formatNumber(thinness(triangles[thinnest], points))
                      << " (degenerate at 1e-12): remesh or remove such slivers");
      }
      else
      {
        vtkErrorMacro(<< "rest mesh: the normal equations cannot be factorised: "
                      << lct::describe(issue.status));
      }
      return fail();
    }
    in.Triangles = std::move(triangles);
    in.Rest = restKey;
    in.RestValid = true;
  }

  // The targets: validated and their per-face logs computed when any of them changed.
  const int k = this->GetNumberOfTargets();
  std::vector<GeometryKey> targetKeys(k);
  for (int i = 0; i < k; ++i)
  {
    targetKeys[i] = keyOf(in.Targets[i].Mesh);
  }
  if (!in.TargetsValid || in.TargetKeys.size() != targetKeys.size() ||
    !std::equal(targetKeys.begin(), targetKeys.end(), in.TargetKeys.begin()))
  {
    in.TargetsValid = false;
    std::vector<std::vector<Eigen::Vector3d>> targets(k);
    const vtkIdType points = input->GetNumberOfPoints();
    for (int i = 0; i < k; ++i)
    {
      vtkPolyData* t = in.Targets[i].Mesh;
      if (t->GetNumberOfPoints() != points)
      {
        vtkErrorMacro(<< "target " << i << " has " << t->GetNumberOfPoints()
                      << " points where the rest mesh has " << points);
        return fail();
      }
      if (t->GetStrips() && t->GetStrips()->GetNumberOfCells() > 0)
      {
        vtkErrorMacro(<< "target " << i
                      << " has triangle strips; its polys must be the rest mesh's "
                      << "triangles (run vtkTriangleFilter)");
        return fail();
      }
      std::string error;
      const std::vector<lct::Triangle> triangles = trianglesOf(t, error);
      if (!error.empty())
      {
        vtkErrorMacro(<< "target " << i << ": " << error);
        return fail();
      }
      if (triangles.size() != in.Triangles.size())
      {
        vtkErrorMacro(<< "target " << i << " has " << triangles.size()
                      << " triangles where the rest mesh has " << in.Triangles.size()
                      << ": the targets must have the rest mesh's triangulation");
        return fail();
      }
      const auto differ = std::mismatch(triangles.begin(), triangles.end(), in.Triangles.begin());
      if (differ.first != triangles.end())
      {
        const std::int64_t face = differ.first - triangles.begin();
        vtkErrorMacro(<< "target " << i << ": " << describeTriangle(triangles, face)
                      << " differs from the rest mesh's " << describeTriangle(in.Triangles, face)
                      << ": the targets must have the rest mesh's triangulation");
        return fail();
      }
      targets[i] = pointsOf(t);
    }
    const lct::ShapeBlendIssue issue = in.Blender.setTargets(targets, parallel);
    ++this->NumberOfLogComputations;
    if (!issue.ok())
    {
      // NonFinite and Singular also come from polarLog, with no point and a triangle that
      // passed the checks: those take the last branch, not the point's or the triangle's words.
      if (issue.status == lct::Status::NonFinite && issue.point >= 0)
      {
        vtkErrorMacro(<< "target " << issue.target << ": point " << issue.point << " is "
                      << formatPoint(targets[issue.target][issue.point]) << ": NaN or Inf");
      }
      else if (issue.status == lct::Status::Singular && issue.face >= 0 &&
        lct::isDegenerateTriangle(targets[issue.target][in.Triangles[issue.face][0]],
          targets[issue.target][in.Triangles[issue.face][1]],
          targets[issue.target][in.Triangles[issue.face][2]]))
      {
        vtkErrorMacro(<< "target " << issue.target << ": "
                      << describeTriangle(in.Triangles, issue.face)
                      << " is degenerate (zero or near-zero area): its affine map is singular");
      }
      else if (issue.status == lct::Status::OutOfRange && issue.face >= 0 &&
        !lct::isTriangleScaleInRange(targets[issue.target][in.Triangles[issue.face][0]],
          targets[issue.target][in.Triangles[issue.face][1]],
          targets[issue.target][in.Triangles[issue.face][2]]))
      {
        vtkErrorMacro(<< "target " << issue.target << ": "
                      << describeTriangle(in.Triangles, issue.face) << " is "
                      << scaleRangeProblem(in.Triangles[issue.face], targets[issue.target]));
      }
      else
      {
        vtkErrorMacro(<< "target " << issue.target << ": the affine map of "
                      << describeTriangle(in.Triangles, issue.face)
                      << " has no usable log: " << lct::describe(issue.status));
      }
      return fail();
    }
    in.TargetKeys = std::move(targetKeys);
    in.TargetsValid = true;
  }

  // The blend: one back-substitution.
  std::vector<double> weights(k);
  for (int i = 0; i < k; ++i)
  {
    weights[i] = in.Targets[i].Weight;
    if (!std::isfinite(weights[i]))
    {
      vtkErrorMacro(<< "the weight of target " << i << " is " << lct::formatNumber(weights[i])
                    << ": weights must be finite");
      return fail();
    }
  }
  std::vector<Eigen::Vector3d> blended;
  const lct::ShapeBlendIssue issue = in.Blender.blend(weights, blended, parallel);
  if (!issue.ok())
  {
    if (issue.face >= 0)
    {
      vtkErrorMacro(<< "the blended map of " << describeTriangle(in.Triangles, issue.face)
                    << " cannot be formed: " << lct::describe(issue.status)
                    << " (weights too far beyond the targets?)");
    }
    else
    {
      vtkErrorMacro(<< "the blend cannot be computed: " << lct::describe(issue.status));
    }
    return fail();
  }

  // Float points are blended in double, where the overflow checks hold: a point beyond float's
  // range was narrowed to Inf and reported as a success.
  const bool floatPoints = input->GetPoints()->GetDataType() == VTK_FLOAT;
  if (floatPoints)
  {
    const double floatMax = static_cast<double>(std::numeric_limits<float>::max());
    for (std::size_t v = 0; v < blended.size(); ++v)
    {
      if (!(blended[v].cwiseAbs().maxCoeff() <= floatMax))
      {
        vtkErrorMacro(<< "the blended point " << v << " is " << formatPoint(blended[v])
                      << ": out of the range of float, the rest mesh's point type (weights too "
                         "far beyond the targets, or give the rest mesh double points); output "
                         "unchanged.");
        return fail();
      }
    }
  }

  // The output: the rest mesh's topology and data (without normals), the blended points.
  output->CopyStructure(input);
  output->GetPointData()->CopyNormalsOff();
  output->GetPointData()->PassData(input->GetPointData());
  output->GetCellData()->CopyNormalsOff();
  output->GetCellData()->PassData(input->GetCellData());
  vtkNew<vtkPoints> outPoints;
  outPoints->SetDataType(floatPoints ? VTK_FLOAT : VTK_DOUBLE);
  outPoints->SetNumberOfPoints(static_cast<vtkIdType>(blended.size()));
  for (std::size_t v = 0; v < blended.size(); ++v)
  {
    outPoints->SetPoint(static_cast<vtkIdType>(v), blended[v].data());
  }
  output->SetPoints(outPoints);
  in.LastOutput.Remember(output);
  return 1;
}

void vtkShapeBlenderLCT::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfTargets: " << this->Internal->Targets.size() << "\n";
  for (std::size_t i = 0; i < this->Internal->Targets.size(); ++i)
  {
    const Target& t = this->Internal->Targets[i];
    os << indent.GetNextIndent() << "Target " << i << ": " << t.Mesh->GetNumberOfPoints()
       << " points, " << t.Mesh->GetNumberOfPolys() << " polys, weight "
       << lct::formatNumber(t.Weight) << "\n";
  }
  os << indent << "NumberOfFactorizations: " << this->NumberOfFactorizations << "\n";
  os << indent << "NumberOfLogComputations: " << this->NumberOfLogComputations << "\n";
  os << indent << "SerialThreshold: " << this->SerialThreshold << "\n";
  os << indent << "Cached rest mesh: "
     << (this->Internal->RestValid ? std::to_string(this->Internal->Blender.numberOfFaces()) +
              " triangles, " + std::to_string(this->Internal->Blender.numberOfPieces()) + " pieces"
                                   : std::string("none"))
     << "\n";
}

//------------------------------------------------------------------------------
int vtkShapeBlenderLCT::SetSerialThreshold(vtkIdType value)
{
  return vtkLCTCheckedSet::Set(this, "SerialThreshold", this->SerialThreshold, value,
    static_cast<vtkIdType>(0), static_cast<vtkIdType>(VTK_ID_MAX));
}
