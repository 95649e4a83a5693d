#include "vtkSphericalOrbifoldMap.h"

#include "SphericalOrbifoldMap.h"
#include "vtkSphericalConformalMap.h"
#include "MobiusSphericalMapData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSphericalOrbifoldMap);

namespace
{
// A spherical map carries its surface in `SurfacePoints` and lies on the unit sphere; any
// other input is a surface mesh still to be mapped.
bool IsSphericalMap(vtkPolyData* input)
{
  mobius::Points points;
  return mobius::vtk::CheckSurfacePoints(input).empty() &&
    input->GetCellData()->GetArray(mobius::vtk::SurfaceAreaArrayName) &&
    mobius::vtk::ExtractPoints(input, points).empty() &&
    mobius::vtk::CheckOnUnitSphere(points).empty();
}

void AddIds(vtkFieldData* fieldData, const char* name, const std::vector<vtkIdType>& ids,
  int components = 1)
{
  vtkNew<vtkIdTypeArray> array;
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(static_cast<vtkIdType>(ids.size()) / components);
  for (size_t i = 0; i < ids.size(); ++i)
  {
    array->SetValue(static_cast<vtkIdType>(i), ids[i]);
  }
  fieldData->RemoveArray(name);
  fieldData->AddArray(array);
}

// The number of point ids a cone can name: the input's points, or more when the input is a
// map whose `InputPointId` names points it dropped.
vtkIdType InputIdCount(vtkPolyData* input, bool inputIsMap)
{
  vtkDataArray* inputIdArray =
    inputIsMap ? input->GetPointData()->GetArray(mobius::vtk::InputPointIdArrayName) : nullptr;
  vtkIdType idCount = input->GetNumberOfPoints();
  if (inputIdArray)
  {
    idCount = std::max<vtkIdType>(idCount, static_cast<vtkIdType>(inputIdArray->GetRange(0)[1]) + 1);
  }
  return idCount;
}

// What the core needs of a spherical map: its sphere and surface points, its triangles and
// the input's point id of each point (the map's own numbering where it carries none).
struct OrbifoldInputs
{
  mobius::Points Sphere, Surface;
  mobius::Triangles Triangles;
  std::vector<mobius::Index> InputIds;
};

// ... and the mesh vertices of the cones named by point id.
std::string ExtractOrbifoldInputs(
  vtkPolyData* map, const vtkIdType coneIds[2], OrbifoldInputs& in, mobius::Index cones[2])
{
  std::string error = mobius::vtk::ExtractPoints(map, in.Sphere);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(map, in.Triangles);
  }
  if (error.empty())
  {
    error = mobius::vtk::ExtractSurfacePoints(map, in.Surface);
  }
  if (error.empty() && in.Triangles.rows() == 0)
  {
    error = "the input has no triangles";
  }
  in.InputIds.resize(static_cast<size_t>(in.Sphere.rows()));
  vtkDataArray* ids = map->GetPointData()->GetArray(mobius::vtk::InputPointIdArrayName);
  for (vtkIdType i = 0; error.empty() && i < in.Sphere.rows(); ++i)
  {
    in.InputIds[i] = ids ? static_cast<mobius::Index>(ids->GetTuple1(i)) : i;
  }
  const mobius::Index coneIdValues[2] = { coneIds[0], coneIds[1] };
  return error.empty() ? mobius::FindConeVertices(in.InputIds, coneIdValues, cones) : error;
}

template <typename ArrayType>
vtkSmartPointer<ArrayType> NamedArray(const char* name, vtkIdType tuples, int components = 1)
{
  vtkSmartPointer<ArrayType> array = vtkSmartPointer<ArrayType>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

// The core's parameters: the number of copies and the filter's progress over the last 75%
// of its bar (the cones are found with the inputs).
mobius::SphericalOrbifoldMapParameters OrbifoldParameters(vtkAlgorithm* filter, int copies)
{
  mobius::SphericalOrbifoldMapParameters parameters;
  parameters.Copies = copies;
  parameters.Progress = [filter](double fraction) {
    filter->UpdateProgress(0.2 + 0.75 * fraction);
    return !filter->GetAbortExecute();
  };
  return parameters;
}

// Reports a failed orbifold map (an error) or one with flipped triangles on the covering (a
// warning); false when it failed.
bool ReportOrbifoldResult(vtkAlgorithm* filter, const mobius::SphericalOrbifoldMapResult& result)
{
  if (!result.Success)
  {
    vtkErrorWithObjectMacro(
      filter, << "Cannot compute an orbifold map: " << result.Message << ".");
    return false;
  }
  if (result.FlippedTriangles > 0)
  {
    vtkWarningWithObjectMacro(filter, << "The orbifold map has " << result.FlippedTriangles
                                      << " flipped triangles on the covering.");
  }
  return true;
}

// The output mesh with its point arrays (surface points, input point ids, copies) and cell
// arrays (surface areas, copies).
void WriteOrbifoldMesh(
  vtkPolyData* output, const mobius::OrbifoldOutputMesh& mesh, const OrbifoldInputs& in)
{
  const vtkIdType n = static_cast<vtkIdType>(mesh.SourceVertex.size());
  auto surfacePoints =
    NamedArray<vtkDoubleArray>(mobius::vtk::SurfacePointsArrayName, n, 3);
  auto pointIds = NamedArray<vtkIdTypeArray>(mobius::vtk::InputPointIdArrayName, n);
  auto pointCopy = NamedArray<vtkIntArray>("Copy", n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    surfacePoints->SetTuple3(i, mesh.SurfacePoints(i, 0), mesh.SurfacePoints(i, 1),
      mesh.SurfacePoints(i, 2));
    pointIds->SetValue(i, in.InputIds[mesh.SourceVertex[i]]);
    pointCopy->SetValue(i, mesh.VertexCopy[i]);
  }
  const vtkIdType cells = mesh.OutputTriangles.rows();
  auto cellArea = NamedArray<vtkDoubleArray>(mobius::vtk::SurfaceAreaArrayName, cells);
  auto cellCopy = NamedArray<vtkIntArray>("Copy", cells);
  for (vtkIdType t = 0; t < cells; ++t)
  {
    cellArea->SetValue(t, mesh.TriangleAreas[t]);
    cellCopy->SetValue(t, mesh.TriangleCopy[t]);
  }
  output->Initialize();
  mobius::vtk::SetPoints(output, mesh.SpherePoints);
  mobius::vtk::SetTriangles(output, mesh.OutputTriangles);
  output->GetPointData()->AddArray(surfacePoints);
  output->GetPointData()->AddArray(pointIds);
  output->GetPointData()->AddArray(pointCopy);
  output->GetCellData()->AddArray(cellArea);
  output->GetCellData()->AddArray(cellCopy);
}

// The map's own field data, then the orbifold map's cones, cut and measures.
void WriteOrbifoldFields(vtkFieldData* fields, vtkFieldData* mapFields, int copies,
  const mobius::SphericalOrbifoldMapResult& result, const std::vector<mobius::Index>& inputIds)
{
  fields->PassData(mapFields);
  mobius::vtk::SetFieldInteger(fields, "NumberOfCopies", copies);
  AddIds(fields, "ConeIds", { inputIds[result.Cones[0]], inputIds[result.Cones[1]] }, 2);
  std::vector<vtkIdType> cut;
  for (const mobius::Index v : result.Covering.CutPath)
  {
    cut.push_back(inputIds[v]);
  }
  AddIds(fields, "CutPathPointIds", cut);
  mobius::vtk::SetFieldValue(fields, "SymmetryError", result.Symmetry.MaximumDistance);
  mobius::vtk::SetFieldValue(fields, "ConeAntipodality", result.ConeAntipodality);
  mobius::vtk::SetFieldCount(
    fields, "FlippedTriangles", static_cast<vtkIdType>(result.FlippedTriangles));
  mobius::vtk::SetFieldValue(fields, "StdLogAreaRatio", result.OrbifoldAreaDistortion.StdLogAreaRatio);
  mobius::vtk::SetFieldValue(fields, "PlainStdLogAreaRatio", result.PlainAreaDistortion.StdLogAreaRatio);
  mobius::vtk::SetFieldInteger(fields, "ConformalFlowIterations", result.CoveringFlow.Iterations);
  mobius::vtk::SetFieldInteger(
    fields, "ConformalFlowConverged", result.CoveringFlow.Converged ? 1 : 0);
}
}

//------------------------------------------------------------------------------
vtkSphericalOrbifoldMap::vtkSphericalOrbifoldMap() = default;

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkSphericalOrbifoldMap::SphericalMapOf(
  vtkPolyData* input, bool inputIsMap)
{
  vtkSmartPointer<vtkPolyData> map = vtkSmartPointer<vtkPolyData>::New();
  map->ShallowCopy(input);
  if (inputIsMap)
  {
    return map;
  }
  vtkNew<vtkSphericalConformalMap> conformal;
  conformal->SetInputData(map);
  std::string error;
  std::vector<std::string> warnings;
  vtkSmartPointer<vtkPolyData> conformalMap =
    this->RunInternalFilter(conformal, 0.0, 0.2, error, warnings);
  for (const auto& warning : warnings)
  {
    vtkWarningMacro(<< "conformal map: " << warning);
  }
  if (!conformalMap)
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Cannot compute an orbifold map: conformal map: "
                    << (error.empty() ? "no output" : error));
    }
    return nullptr;
  }
  map->ShallowCopy(conformalMap);
  return map;
}

//------------------------------------------------------------------------------
int vtkSphericalOrbifoldMap::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output, "compute an orbifold map"))
  {
    return 0;
  }
  // The parameters first: a bad one fails at once, before any flow runs. Cones are named
  // by `InputPointId` when the input is a map carrying it, else by the input's point ids.
  const bool inputIsMap = IsSphericalMap(input);
  const std::string problem = mobius::CheckOrbifoldParameters(InputIdCount(input, inputIsMap),
    this->NumberOfCopies, this->ConeIds[0], this->ConeIds[1]);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: " << problem << ".");
    return 0;
  }
  // The surface's own spherical map (with its repairs), unless the input is one.
  vtkSmartPointer<vtkPolyData> map = this->SphericalMapOf(input, inputIsMap);
  if (!map)
  {
    return 0;
  }
  this->UpdateProgress(0.2);
  OrbifoldInputs in;
  auto parameters = OrbifoldParameters(this, this->NumberOfCopies);
  const std::string error = ExtractOrbifoldInputs(map, this->ConeIds, in, parameters.Cones);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: " << error << ".");
    return 0;
  }
  const mobius::SphericalOrbifoldMapResult result =
    mobius::ComputeSphericalOrbifoldMap(in.Surface, in.Triangles, in.Sphere, parameters);
  if (this->GetAbortExecute())
  {
    return 1;
  }
  if (!ReportOrbifoldResult(this, result))
  {
    return 0;
  }
  WriteOrbifoldMesh(output,
    mobius::SelectOrbifoldOutput(result, in.Surface, in.Triangles, this->OutputCovering), in);
  WriteOrbifoldFields(
    output->GetFieldData(), map->GetFieldData(), this->NumberOfCopies, result, in.InputIds);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSphericalOrbifoldMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfCopies: " << this->NumberOfCopies << "\n";
  os << indent << "ConeIds: " << this->ConeIds[0] << " " << this->ConeIds[1] << "\n";
  os << indent << "OutputCovering: " << this->OutputCovering << "\n";
}
