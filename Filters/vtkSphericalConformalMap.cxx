#include "vtkSphericalConformalMap.h"

#include "ConformalMap.h"
#include "FlowInput.h"
#include "MapDistortion.h"
#include "MapVerdict.h"
#include "MobiusSphericalMapData.h"
#include "RegistrationParameters.h"
#include "RepairMesh.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSphericalConformalMap);

namespace
{
// Copies attribute tuples from `source` to `target` following `provenance`; rows created
// by a repair get zeros.
void CopyAttributes(vtkDataSetAttributes* source, vtkDataSetAttributes* target,
  const std::vector<mobius::Index>& provenance)
{
  target->CopyAllocate(source, static_cast<vtkIdType>(provenance.size()));
  for (size_t i = 0; i < provenance.size(); ++i)
  {
    if (provenance[i] >= 0)
    {
      target->CopyData(source, provenance[i], static_cast<vtkIdType>(i));
    }
    else
    {
      target->NullData(static_cast<vtkIdType>(i));
    }
  }
}

// The input's triangles (TriangulatedSurface), with a warning for the vertex and line cells
// left out.
vtkSmartPointer<vtkPolyData> TriangleSurface(vtkSphericalConformalMap* filter, vtkPolyData* input)
{
  if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
  {
    vtkWarningWithObjectMacro(filter, << "Ignoring " << input->GetNumberOfVerts() << " vertex and "
                                      << input->GetNumberOfLines() << " line cells of the input.");
  }
  return mobius::vtk::TriangulatedSurface(input);
}

// The repairs' phrases (mobius::MeshRepairLog::Describe), joined by "; ".
std::string JoinedRepairs(const mobius::MeshRepairLog& log)
{
  std::string joined;
  for (const std::string& phrase : log.Describe())
  {
    joined += (joined.empty() ? "" : "; ") + phrase;
  }
  return joined;
}

// The mesh the flow runs on, and what the output needs of its preparation.
struct FlowMesh
{
  mobius::RepairedMesh Mesh; ///< scaled by 2^-ScaleExponent, facing outward
  int ScaleExponent = 0;
  bool ReversedTriangles = false; ///< turned to face outward
  mobius::Vector SurfaceAreas;    ///< per triangle, at the input's scale
};

// Extracts, rescales and repairs the surface for the flow; the reason it cannot be mapped
// if it cannot.
std::string PrepareFlowMesh(
  vtkSphericalConformalMap* filter, vtkPolyData* input, vtkPolyData* surface, FlowMesh& flowMesh)
{
  mobius::Points points;
  mobius::Triangles triangles;
  std::string error = mobius::vtk::ExtractPoints(surface, points);
  error = error.empty() ? mobius::vtk::ExtractTriangles(surface, triangles) : error;
  if (!error.empty())
  {
    return error;
  }
  error = mobius::CheckCoordinateRange(points, triangles);
  if (!error.empty())
  {
    return error;
  }
  flowMesh.ScaleExponent = mobius::ScaleToUnitOrder(points, triangles);
  mobius::RepairedMesh& mesh = flowMesh.Mesh;
  mesh = mobius::RepairMesh(std::move(points), std::move(triangles),
    { filter->GetRepair() != 0, filter->GetFillHoles() != 0, filter->GetKeepLargestComponent() != 0 });
  if (!mesh.Problem.empty())
  {
    return mesh.Problem;
  }
  const std::string repairs = JoinedRepairs(mesh.Log);
  if (!repairs.empty())
  {
    vtkWarningWithObjectMacro(filter, << "Repaired the mesh (" << input->GetNumberOfPoints()
                                      << " points in, " << mesh.Points.rows()
                                      << " out): " << repairs << ".");
  }
  flowMesh.ReversedTriangles = mobius::FaceOutward(mesh.Points, mesh.Triangles);
  mobius::TriangleAreasAtScale(
    mesh.Points, mesh.Triangles, flowMesh.ScaleExponent, flowMesh.SurfaceAreas, error);
  return error;
}

vtkSmartPointer<vtkDoubleArray> NamedDoubleArray(const char* name, int components, vtkIdType tuples)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  array->SetName(name);
  array->SetNumberOfComponents(components);
  array->SetNumberOfTuples(tuples);
  return array;
}

// The per-point and per-triangle arrays of the map: the surface positions at the input's
// scale, the input point each point came from, the triangles' surface areas.
void AddSurfaceArrays(const FlowMesh& flowMesh, vtkPolyData* output)
{
  const mobius::RepairedMesh& mesh = flowMesh.Mesh;
  const mobius::Points& points = mesh.Points;
  const mobius::Vector& areas = flowMesh.SurfaceAreas;
  auto surfacePoints = NamedDoubleArray(mobius::vtk::SurfacePointsArrayName, 3, points.rows());
  const double restore = std::ldexp(1.0, flowMesh.ScaleExponent); // the input's scale, exactly
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    surfacePoints->SetTuple3(i, restore * points(i, 0), restore * points(i, 1), restore * points(i, 2));
  }
  output->GetPointData()->AddArray(surfacePoints);
  // Repairs drop, merge and add points: results must still name the input's (the file's)
  // vertices, so every later filter passes this array on.
  vtkNew<vtkIdTypeArray> inputPointIds;
  inputPointIds->SetName(mobius::vtk::InputPointIdArrayName);
  inputPointIds->SetNumberOfTuples(points.rows());
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    inputPointIds->SetValue(i, static_cast<vtkIdType>(mesh.Provenance.PointSource[i]));
  }
  output->GetPointData()->AddArray(inputPointIds);
  // The same for the triangles: the input's triangle (after polygons are split) each came
  // from, -1 for one a repair created.
  vtkNew<vtkIdTypeArray> inputCellIds;
  inputCellIds->SetName(mobius::vtk::InputCellIdArrayName);
  inputCellIds->SetNumberOfTuples(mesh.Triangles.rows());
  for (Eigen::Index t = 0; t < mesh.Triangles.rows(); ++t)
  {
    inputCellIds->SetValue(t, static_cast<vtkIdType>(mesh.Provenance.TriangleSource[t]));
  }
  output->GetCellData()->AddArray(inputCellIds);
  auto surfaceAreas = NamedDoubleArray(mobius::vtk::SurfaceAreaArrayName, 1, areas.size());
  for (Eigen::Index t = 0; t < areas.size(); ++t)
  {
    surfaceAreas->SetValue(t, areas[t]);
  }
  output->GetCellData()->AddArray(surfaceAreas);
}

void AddStringValue(vtkFieldData* fieldData, const char* name, const std::string& value)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->InsertNextValue(value);
  fieldData->AddArray(array);
}

// What the repair did: `MeshRepairs` (one phrase per repair, none for a mesh that needed
// none) and the counts and sizes behind them.
void AddRepairFieldData(const mobius::MeshRepairLog& log, vtkFieldData* fieldData)
{
  using mobius::vtk::SetFieldCount;
  using mobius::vtk::SetFieldValue;
  vtkNew<vtkStringArray> phrases;
  phrases->SetName("MeshRepairs");
  for (const std::string& phrase : log.Describe())
  {
    phrases->InsertNextValue(phrase);
  }
  fieldData->AddArray(phrases);
  SetFieldCount(fieldData, "MergedDuplicatePoints", static_cast<vtkIdType>(log.MergedDuplicatePoints));
  SetFieldCount(fieldData, "CollapsedEdges", static_cast<vtkIdType>(log.CollapsedEdges));
  SetFieldCount(fieldData, "RemovedTriangles",
    static_cast<vtkIdType>(log.RemovedRepeatedVertexTriangles + log.RemovedNonFiniteTriangles +
      log.RemovedDuplicateTriangles));
  SetFieldCount(fieldData, "SplitNonManifoldVertices", static_cast<vtkIdType>(log.SplitVertices));
  SetFieldCount(fieldData, "ReversedTriangles", static_cast<vtkIdType>(log.ReversedTriangles));
  SetFieldCount(fieldData, "OrientationCutEdges", static_cast<vtkIdType>(log.OrientationCutEdges));
  SetFieldCount(fieldData, "DroppedComponents", static_cast<vtkIdType>(log.DroppedComponents));
  SetFieldValue(fieldData, "DroppedComponentAreaShare",
    log.InputArea > 0 ? log.DroppedComponentArea / log.InputArea : 0.0);
  mobius::vtk::SetFieldInteger(fieldData, "FilledHoles", static_cast<int>(log.FilledHoles));
  SetFieldCount(fieldData, "FilledBoundaryEdges", static_cast<vtkIdType>(log.FilledBoundaryEdges));
  SetFieldValue(fieldData, "FilledAreaShare", log.ProxyArea > 0 ? log.FilledArea / log.ProxyArea : 0.0);
  vtkNew<vtkDoubleArray> loops;
  loops->SetName("CutHandleLoopLengths"); // over sqrt(proxy area)
  for (double length : log.HandleLoopLengths)
  {
    loops->InsertNextValue(log.ProxyArea > 0 ? length / std::sqrt(log.ProxyArea) : 0.0);
  }
  fieldData->AddArray(loops);
}

// The flow's figures, the map's distortion, the repairs and the verdict, as field data.
void AddMapFieldData(const mobius::ConformalMapResult& result, const FlowMesh& flowMesh,
  const mobius::MapVerdict& verdict, vtkFieldData* fieldData)
{
  const mobius::RepairedMesh& mesh = flowMesh.Mesh;
  using mobius::vtk::SetFieldCount;
  using mobius::vtk::SetFieldInteger;
  using mobius::vtk::SetFieldValue;
  const mobius::MapDistortion& distortion = result.Distortion;
  SetFieldInteger(fieldData, "ConformalFlowIterations", result.Iterations);
  SetFieldValue(fieldData, "ConformalFlowRelativeChange", result.RelativeChange);
  SetFieldInteger(fieldData, "ConformalFlowConverged", result.Converged ? 1 : 0);
  SetFieldInteger(fieldData, "ConformalFlowLinearStart", result.LinearStart ? 1 : 0);
  SetFieldInteger(fieldData, "ConformalFlowFactorizations", result.Factorizations);
  SetFieldCount(fieldData, "FlippedTriangles", static_cast<vtkIdType>(distortion.FlippedTriangles));
  SetFieldValue(fieldData, "MeanQuasiConformalDistortion", distortion.MeanQuasiConformal);
  SetFieldValue(fieldData, "MaxQuasiConformalDistortion", distortion.MaxQuasiConformal);
  SetFieldValue(fieldData, "MedianQuasiConformalDistortion", distortion.MedianQuasiConformal);
  SetFieldValue(fieldData, "P95QuasiConformalDistortion", distortion.P95QuasiConformal);
  SetFieldValue(fieldData, "P99QuasiConformalDistortion", distortion.P99QuasiConformal);
  SetFieldValue(fieldData, "SquashedAreaShare", distortion.SquashedAreaShare);
  SetFieldValue(fieldData, "SmallestSphereAreaShare", distortion.SmallestMappedAreaShare);
  const double areaRange[2] = { distortion.MinAreaRatio, distortion.MaxAreaRatio };
  mobius::vtk::SetFieldValues(fieldData, "AreaDistortionRange", areaRange, 2);
  SetFieldInteger(fieldData, "IntrinsicDelaunayUsed", result.IntrinsicDelaunayUsed ? 1 : 0);
  SetFieldCount(fieldData, "IntrinsicDelaunayFlips", static_cast<vtkIdType>(result.IntrinsicFlips));
  AddRepairFieldData(mesh.Log, fieldData);
  SetFieldInteger(fieldData, "ReversedTriangleOrientation", flowMesh.ReversedTriangles ? 1 : 0);
  SetFieldCount(
    fieldData, "FlipRepairMovedVertices", static_cast<vtkIdType>(result.FlipRepair.MovedVertices));
  SetFieldInteger(fieldData, "SqueezedRegionRefinementFailed", result.Refinement.Success ? 0 : 1);
  SetFieldInteger(fieldData, "DegenerateMap", verdict.Degenerate() ? 1 : 0);
  AddStringValue(fieldData, "DegenerateMapReason", verdict.Reason());
  AddStringValue(fieldData, "MapWarning", verdict.UsableWarning());
}

// The input errors found before any work: the empty input, the tolerance the flow cannot
// reach, cells naming points that do not exist.
std::string CheckInput(vtkSphericalConformalMap* filter, vtkPolyData* input)
{
  if (input->GetNumberOfPoints() == 0)
  {
    return "Cannot map the mesh to the sphere: the input has no points.";
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    return "Cannot map the mesh to the sphere: the input has no triangles.";
  }
  if (filter->GetConvergenceTolerance() < mobius::MinimumFlowTolerance)
  {
    std::ostringstream message;
    message << "ConvergenceTolerance must be at least " << mobius::MinimumFlowTolerance
            << " (it is " << filter->GetConvergenceTolerance() << "): the flow's relative change "
            << "levels off near 1e-9, so the flow would never converge.";
    return message.str();
  }
  // Before anything reads the points through them (vtkTriangleFilter does).
  const std::string error = mobius::vtk::CheckCellPointIds(input);
  return error.empty() ? error : "Cannot map the mesh to the sphere: " + error + ".";
}

// The filter's settings as the flow's parameters, with its progress and abort.
mobius::ConformalMapParameters FlowParameters(vtkSphericalConformalMap* filter,
  const mobius::Points& points, const mobius::Triangles& triangles)
{
  mobius::ConformalMapParameters parameters;
  parameters.TimeStep = filter->GetTimeStep();
  parameters.MaximumNumberOfIterations = filter->GetMaximumNumberOfIterations();
  parameters.ConvergenceTolerance = filter->GetConvergenceTolerance();
  parameters.IntrinsicDelaunay = filter->GetIntrinsicDelaunay() == vtkSphericalConformalMap::INTRINSIC_DELAUNAY_ON ||
    (filter->GetIntrinsicDelaunay() == vtkSphericalConformalMap::INTRINSIC_DELAUNAY_AUTOMATIC &&
      mobius::SmallestTriangleAngleDegrees(points, triangles) < filter->GetIntrinsicDelaunayAngle());
  parameters.IntrinsicDelaunayWhenFolded = filter->GetIntrinsicDelaunay() == vtkSphericalConformalMap::INTRINSIC_DELAUNAY_AUTOMATIC;
  parameters.FlipRepairPasses = filter->GetFlipRepairPasses();
  parameters.MobiusCentering = filter->GetCenterBetweenSteps();
  parameters.LinearStart = filter->GetLinearStart();
  parameters.ReuseFactorization = filter->GetReuseFactorization();
  parameters.Progress = mobius::vtk::ProgressAndAbort(filter);
  return parameters;
}
}

//------------------------------------------------------------------------------
vtkSphericalConformalMap::vtkSphericalConformalMap()
{
  const mobius::RegistrationParameters defaults;
  this->MaximumNumberOfIterations = defaults.FlowIterations;
  this->ConvergenceTolerance = defaults.FlowTolerance;
  this->CenterBetweenSteps = defaults.CenterBetweenSteps;
  this->Repair = defaults.Repair;
  this->FillHoles = defaults.FillHoles;
  this->KeepLargestComponent = defaults.KeepLargestComponent;
}

//------------------------------------------------------------------------------
int vtkSphericalConformalMap::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output))
  {
    return 0;
  }
  const std::string inputError = CheckInput(this, input);
  if (!inputError.empty())
  {
    vtkErrorMacro(<< inputError);
    return 0;
  }
  const vtkSmartPointer<vtkPolyData> surface = TriangleSurface(this, input);
  FlowMesh flowMesh;
  const std::string meshError = PrepareFlowMesh(this, input, surface, flowMesh);
  if (!meshError.empty())
  {
    vtkErrorMacro(<< "Cannot map the mesh to the sphere: " << meshError << ".");
    return 0;
  }
  const mobius::RepairedMesh& mesh = flowMesh.Mesh;
  const mobius::ConformalMapResult result = mobius::ComputeSphericalConformalMap(
    mesh.Points, mesh.Triangles, FlowParameters(this, mesh.Points, mesh.Triangles));
  if (!result.Success)
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Conformal map failed: " << result.Message << ".");
    }
    return 0;
  }
  // A degenerate map is still output (a caller may want to look at it), but the field data
  // says it carries no trustworthy correspondence, and why.
  const mobius::MapVerdict verdict = mobius::JudgeConformalMap(result, this->ConvergenceTolerance);
  if (verdict.Degenerate())
  {
    vtkWarningMacro(<< "The map is degenerate: " << verdict.Reason() << ".");
  }
  else if (!verdict.Warning.empty())
  {
    vtkWarningMacro(<< "The map is usable, but " << verdict.Warning << ".");
  }
  mobius::vtk::SetPoints(output, result.SpherePoints);
  mobius::vtk::SetTriangles(output, mesh.Triangles);
  CopyAttributes(surface->GetPointData(), output->GetPointData(), mesh.Provenance.PointSource);
  CopyAttributes(surface->GetCellData(), output->GetCellData(), mesh.Provenance.TriangleSource);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());
  AddSurfaceArrays(flowMesh, output);
  // Colored by default by how far each triangle is from conformal.
  mobius::vtk::AddDistortionArrays(output, "QuasiConformalDistortion");
  AddMapFieldData(result, flowMesh, verdict, output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSphericalConformalMap::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "TimeStep: " << this->TimeStep << "\n";
  os << indent << "MaximumNumberOfIterations: " << this->MaximumNumberOfIterations << "\n";
  os << indent << "ConvergenceTolerance: " << this->ConvergenceTolerance << "\n";
  os << indent << "CenterBetweenSteps: " << this->CenterBetweenSteps << "\n";
  os << indent << "LinearStart: " << this->LinearStart << "\n";
  os << indent << "ReuseFactorization: " << this->ReuseFactorization << "\n";
  os << indent << "IntrinsicDelaunay: " << this->IntrinsicDelaunay << "\n";
  os << indent << "IntrinsicDelaunayAngle: " << this->IntrinsicDelaunayAngle << "\n";
  os << indent << "FlipRepairPasses: " << this->FlipRepairPasses << "\n";
  os << indent << "Repair: " << this->Repair << "\n";
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "KeepLargestComponent: " << this->KeepLargestComponent << "\n";
}
