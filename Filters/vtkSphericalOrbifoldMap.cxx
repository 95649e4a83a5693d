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
}

//------------------------------------------------------------------------------
vtkSphericalOrbifoldMap::vtkSphericalOrbifoldMap() = default;

//------------------------------------------------------------------------------
int vtkSphericalOrbifoldMap::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0]);
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro(<< "Missing input or output polydata.");
    return 0;
  }
  if (input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: the input is empty.");
    return 0;
  }
  // The parameters first: a bad one fails at once, before any flow runs. Cones are named
  // by `InputPointId` when the input is a map carrying it, else by the input's point ids.
  const bool inputIsMap = IsSphericalMap(input);
  vtkDataArray* inputIdArray = inputIsMap
    ? input->GetPointData()->GetArray(mobius::vtk::InputPointIdArrayName)
    : nullptr;
  vtkIdType idCount = input->GetNumberOfPoints();
  if (inputIdArray)
  {
    idCount = std::max<vtkIdType>(idCount, static_cast<vtkIdType>(inputIdArray->GetRange(0)[1]) + 1);
  }
  const std::string problem = mobius::CheckOrbifoldParameters(
    idCount, this->NumberOfCopies, this->ConeIds[0], this->ConeIds[1]);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: " << problem << ".");
    return 0;
  }

  // The surface's own spherical map (with its repairs), unless the input is one.
  vtkSmartPointer<vtkPolyData> map = vtkSmartPointer<vtkPolyData>::New();
  map->ShallowCopy(input);
  if (!inputIsMap)
  {
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
      return 0;
    }
    map->ShallowCopy(conformalMap);
  }
  this->UpdateProgress(0.2);

  mobius::Points sphere, surface;
  mobius::Triangles triangles;
  std::string error = mobius::vtk::ExtractPoints(map, sphere);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(map, triangles);
  }
  if (error.empty())
  {
    error = mobius::vtk::ExtractSurfacePoints(map, surface);
  }
  if (error.empty() && triangles.rows() == 0)
  {
    error = "the input has no triangles";
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: " << error);
    return 0;
  }
  // The input's point id of each map point (the map's own numbering for a map input).
  std::vector<vtkIdType> inputIds(static_cast<size_t>(sphere.rows()));
  vtkDataArray* ids = map->GetPointData()->GetArray(mobius::vtk::InputPointIdArrayName);
  for (vtkIdType i = 0; i < sphere.rows(); ++i)
  {
    inputIds[i] = ids ? static_cast<vtkIdType>(ids->GetTuple1(i)) : i;
  }

  mobius::SphericalOrbifoldMapParameters parameters;
  parameters.Copies = this->NumberOfCopies;
  for (int c = 0; c < 2 && this->ConeIds[0] >= 0; ++c)
  {
    parameters.Cones[c] = -1;
    for (vtkIdType i = 0; i < sphere.rows(); ++i)
    {
      if (inputIds[i] == this->ConeIds[c])
      {
        parameters.Cones[c] = i;
      }
    }
    if (parameters.Cones[c] < 0)
    {
      vtkErrorMacro(<< "Cannot compute an orbifold map: cone " << this->ConeIds[c]
                    << " is not a vertex of the repaired surface (an unused or duplicate "
                       "point the conformal map dropped).");
      return 0;
    }
  }
  parameters.Progress = [this](double fraction) {
    this->UpdateProgress(0.2 + 0.75 * fraction);
    return !this->GetAbortExecute();
  };
  const mobius::SphericalOrbifoldMapResult result =
    mobius::ComputeSphericalOrbifoldMap(surface, triangles, sphere, parameters);
  if (this->GetAbortExecute())
  {
    return 1;
  }
  if (!result.Success)
  {
    vtkErrorMacro(<< "Cannot compute an orbifold map: " << result.Message << ".");
    return 0;
  }
  if (result.FlippedTriangles > 0)
  {
    vtkWarningMacro(<< "The orbifold map has " << result.FlippedTriangles
                    << " flipped triangles on the covering.");
  }

  // One copy (copy 0: its own vertices and the next copy's along the cut's left side) or
  // the whole covering, with the points renumbered in order of use.
  const mobius::CyclicCovering& covering = result.Covering;
  const mobius::Index F = triangles.rows();
  const mobius::Index outputTriangles = this->OutputCovering ? covering.CoveringTriangles.rows() : F;
  std::vector<vtkIdType> newId(covering.SourceVertex.size(), -1);
  std::vector<mobius::Index> usedVertices;
  vtkNew<vtkCellArray> polys;
  vtkNew<vtkIntArray> cellCopy;
  cellCopy->SetName("Copy");
  vtkNew<vtkDoubleArray> cellArea;
  cellArea->SetName(mobius::vtk::SurfaceAreaArrayName);
  const mobius::Vector areas = [&] {
    mobius::Vector a(F);
    for (mobius::Index t = 0; t < F; ++t)
    {
      const Eigen::Vector3d p0 = surface.row(triangles(t, 0)), p1 = surface.row(triangles(t, 1)),
                            p2 = surface.row(triangles(t, 2));
      a[t] = 0.5 * (p1 - p0).cross(p2 - p0).norm();
    }
    return a;
  }();
  for (mobius::Index t = 0; t < outputTriangles; ++t)
  {
    vtkIdType cell[3];
    for (int c = 0; c < 3; ++c)
    {
      const mobius::Index w = covering.CoveringTriangles(t, c);
      if (newId[w] < 0)
      {
        newId[w] = static_cast<vtkIdType>(usedVertices.size());
        usedVertices.push_back(w);
      }
      cell[c] = newId[w];
    }
    polys->InsertNextCell(3, cell);
    cellCopy->InsertNextValue(static_cast<int>(t / F));
    cellArea->InsertNextValue(areas[t % F]);
  }
  mobius::Points outputPoints(static_cast<mobius::Index>(usedVertices.size()), 3);
  vtkNew<vtkDoubleArray> surfacePoints;
  surfacePoints->SetName(mobius::vtk::SurfacePointsArrayName);
  surfacePoints->SetNumberOfComponents(3);
  surfacePoints->SetNumberOfTuples(static_cast<vtkIdType>(usedVertices.size()));
  vtkNew<vtkIdTypeArray> pointIds;
  pointIds->SetName(mobius::vtk::InputPointIdArrayName);
  pointIds->SetNumberOfTuples(static_cast<vtkIdType>(usedVertices.size()));
  vtkNew<vtkIntArray> pointCopy;
  pointCopy->SetName("Copy");
  pointCopy->SetNumberOfTuples(static_cast<vtkIdType>(usedVertices.size()));
  for (size_t i = 0; i < usedVertices.size(); ++i)
  {
    const mobius::Index w = usedVertices[i];
    const mobius::Index v = covering.SourceVertex[w];
    outputPoints.row(static_cast<mobius::Index>(i)) = result.CoveringMap.row(w);
    surfacePoints->SetTuple3(static_cast<vtkIdType>(i), surface(v, 0), surface(v, 1), surface(v, 2));
    pointIds->SetValue(static_cast<vtkIdType>(i), inputIds[v]);
    pointCopy->SetValue(static_cast<vtkIdType>(i), covering.VertexCopy[w]);
  }

  output->Initialize();
  mobius::vtk::SetPoints(output, outputPoints);
  output->SetPolys(polys);
  output->GetPointData()->AddArray(surfacePoints);
  output->GetPointData()->AddArray(pointIds);
  output->GetPointData()->AddArray(pointCopy);
  output->GetCellData()->AddArray(cellArea);
  output->GetCellData()->AddArray(cellCopy);
  vtkFieldData* fields = output->GetFieldData();
  fields->PassData(map->GetFieldData());
  mobius::vtk::SetFieldInteger(fields, "NumberOfCopies", this->NumberOfCopies);
  AddIds(fields, "ConeIds", { inputIds[result.Cones[0]], inputIds[result.Cones[1]] }, 2);
  std::vector<vtkIdType> cut;
  for (const mobius::Index v : covering.CutPath)
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
