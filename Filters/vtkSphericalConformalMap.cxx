#include "vtkSphericalConformalMap.h"

#include "RegistrationParameters.h"
#include "ConformalMap.h"
#include "MapDistortion.h"
#include "MapVerdict.h"
#include "MeshTopology.h"
#include "MobiusSphericalMapData.h"

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
#include "vtkTriangleFilter.h"

#include <Eigen/Geometry>

#include <cfloat>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkSphericalConformalMap);

namespace
{
// Where each point and triangle of the repaired mesh came from in the triangulated input
// (-1: created by a repair), composed over the repairs.
struct Provenance
{
  std::vector<mobius::Index> Points;
  std::vector<mobius::Index> Triangles;

  Provenance(mobius::Index points, mobius::Index triangles)
    : Points(points)
    , Triangles(triangles)
  {
    for (mobius::Index i = 0; i < points; ++i)
    {
      this->Points[i] = i;
    }
    for (mobius::Index t = 0; t < triangles; ++t)
    {
      this->Triangles[t] = t;
    }
  }

  static std::vector<mobius::Index> Compose(
    const std::vector<mobius::Index>& before, const std::vector<mobius::Index>& step)
  {
    std::vector<mobius::Index> composed(step.size());
    for (size_t i = 0; i < step.size(); ++i)
    {
      composed[i] = step[i] >= 0 ? before[step[i]] : -1;
    }
    return composed;
  }

  void Apply(const mobius::MeshProvenance& step)
  {
    this->Points = Compose(this->Points, step.PointSource);
    this->Triangles = Compose(this->Triangles, step.TriangleSource);
  }
};

// Drops points no triangle uses (e.g. the copies left by merging duplicates).
mobius::MeshProvenance RemoveUnusedPoints(mobius::Points& points, mobius::Triangles& triangles)
{
  std::vector<mobius::Index> newIndex(points.rows(), -1);
  mobius::MeshProvenance provenance;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      newIndex[triangles(t, k)] = 0;
    }
  }
  for (Eigen::Index i = 0; i < points.rows(); ++i)
  {
    if (newIndex[i] == 0)
    {
      newIndex[i] = static_cast<mobius::Index>(provenance.PointSource.size());
      provenance.PointSource.push_back(i);
    }
  }
  mobius::Points kept(provenance.PointSource.size(), 3);
  for (size_t i = 0; i < provenance.PointSource.size(); ++i)
  {
    kept.row(i) = points.row(provenance.PointSource[i]);
  }
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    provenance.TriangleSource.push_back(t);
    for (int k = 0; k < 3; ++k)
    {
      triangles(t, k) = newIndex[triangles(t, k)];
    }
  }
  points.swap(kept);
  return provenance;
}

bool NeedsTriangulation(vtkPolyData* input)
{
  if (input->GetNumberOfStrips() > 0 || input->GetNumberOfVerts() > 0 ||
    input->GetNumberOfLines() > 0)
  {
    return true;
  }
  vtkCellArray* polys = input->GetPolys();
  for (vtkIdType c = 0; c < polys->GetNumberOfCells(); ++c)
  {
    if (polys->GetCellSize(c) != 3)
    {
      return true;
    }
  }
  return false;
}

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
}

//------------------------------------------------------------------------------
vtkSphericalConformalMap::vtkSphericalConformalMap()
{
  const mobius::RegistrationParameters defaults;
  this->MaximumNumberOfIterations = defaults.FlowIterations;
  this->ConvergenceTolerance = defaults.FlowTolerance;
  this->CenterBetweenSteps = defaults.CenterBetweenSteps;
  this->FillHoles = defaults.FillHoles;
  this->KeepLargestComponent = defaults.KeepLargestComponent;
}

//------------------------------------------------------------------------------
int vtkSphericalConformalMap::ComputeOutput(
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
    vtkErrorMacro(<< "Cannot map the mesh to the sphere: the input has no points.");
    return 0;
  }
  if (input->GetNumberOfPolys() == 0 && input->GetNumberOfStrips() == 0)
  {
    vtkErrorMacro(<< "Cannot map the mesh to the sphere: the input has no triangles.");
    return 0;
  }
  if (this->ConvergenceTolerance < mobius::MinimumFlowTolerance)
  {
    vtkErrorMacro(<< "ConvergenceTolerance must be at least " << mobius::MinimumFlowTolerance
                  << " (it is " << this->ConvergenceTolerance << "): the flow's relative change "
                  << "levels off near 1e-9, so the flow would never converge.");
    return 0;
  }

  // Before anything reads the points through them (vtkTriangleFilter does).
  std::string error = mobius::vtk::CheckCellPointIds(input);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot map the mesh to the sphere: " << error << ".");
    return 0;
  }

  // Triangles only: split polygons and strips, drop vertices and lines (with their data).
  vtkSmartPointer<vtkPolyData> surface = input;
  if (NeedsTriangulation(input))
  {
    if (input->GetNumberOfVerts() > 0 || input->GetNumberOfLines() > 0)
    {
      vtkWarningMacro(<< "Ignoring " << input->GetNumberOfVerts() << " vertex and "
                      << input->GetNumberOfLines() << " line cells of the input.");
    }
    vtkNew<vtkPolyData> shallow;
    shallow->ShallowCopy(input);
    vtkNew<vtkTriangleFilter> triangulate;
    triangulate->SetInputData(shallow);
    triangulate->PassVertsOff();
    triangulate->PassLinesOff();
    triangulate->Update();
    surface = triangulate->GetOutput();
  }

  mobius::Points points;
  mobius::Triangles triangles;
  error = mobius::vtk::ExtractPoints(surface, points);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(surface, triangles);
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot map the mesh to the sphere: " << error << ".");
    return 0;
  }
  // The geometry squares lengths twice (areas as norms of cross products, cotangent
  // weights): coordinates beyond about 1e75 or below 1e-75 overflow or underflow double
  // precision (a mesh at 1e-100 had "320 zero-area triangles", one at 1e100 "no area").
  // Scaling by a power of two is exact, so everything runs on coordinates of order 1 and
  // the outputs are scaled back exactly.
  const double largestCoordinate = points.size() > 0 ? points.cwiseAbs().maxCoeff() : 0.0;
  const int scaleExponent = largestCoordinate > 0.0 ? std::ilogb(largestCoordinate) : 0;
  points *= std::ldexp(1.0, -scaleExponent);

  // Repairs that change nothing a user could want kept: merge exact duplicates, drop
  // unused points, orient consistently. FillHoles and KeepLargestComponent on request.
  Provenance provenance(points.rows(), triangles.rows());
  mobius::MeshTopologyReport report = mobius::AnalyzeMeshTopology(points, triangles);
  // Only a mesh with open edges is a triangle soup to merge: a closed mesh may have two
  // vertices at the same position (CGAL's cow does) and merging would pinch it.
  const mobius::Index duplicates = report.BoundaryEdges > 0 ? report.DuplicatePoints : 0;
  if (duplicates > 0)
  {
    provenance.Apply(mobius::MergeDuplicatePoints(points, triangles));
  }
  if (this->KeepLargestComponent && report.ConnectedComponents > 1)
  {
    provenance.Apply(mobius::ExtractLargestComponent(points, triangles));
  }
  // The report is recomputed only after a repair changed the mesh: on a clean mesh (the
  // usual case) it is still the first one, and the analysis is a large share of the filter's
  // time outside the flow.
  bool changed = duplicates > 0 || (this->KeepLargestComponent && report.ConnectedComponents > 1);
  const mobius::Index pointsBefore = points.rows();
  provenance.Apply(RemoveUnusedPoints(points, triangles));
  changed = changed || points.rows() != pointsBefore;
  if (changed)
  {
    report = mobius::AnalyzeMeshTopology(points, triangles);
  }
  mobius::Index filledHoles = 0;
  if (this->FillHoles && report.BoundaryLoops > 0)
  {
    mobius::MeshProvenance filled;
    filledHoles = mobius::FillHoles(points, triangles, &filled);
    provenance.Apply(filled);
    changed = true;
  }
  // With every two-sided edge agreeing (and the report current), re-orienting would flip
  // no triangle: each breadth-first choice keeps its neighbour's orientation.
  bool oriented = true;
  if (changed || report.InconsistentlyOrientedEdges > 0)
  {
    mobius::Index reversed = 0;
    oriented = mobius::OrientConsistently(triangles, &reversed);
    changed = changed || reversed > 0;
  }
  if (changed)
  {
    report = mobius::AnalyzeMeshTopology(points, triangles);
  }
  if (!report.IsTopologicalSphere())
  {
    std::ostringstream message;
    message << "Cannot map the mesh to the sphere: " << mobius::DescribeTopologyProblems(report);
    // Edges left disagreeing where no edge is non-manifold: no orientation exists, which
    // "orientations disagree" alone does not tell (re-orienting the file would not help).
    if (!oriented && report.NonManifoldEdges == 0 && report.InconsistentlyOrientedEdges > 0)
    {
      message << " (no orientation of the triangles agrees on every edge: the surface is not "
                 "orientable, like a Moebius strip or a Klein bottle)";
    }
    if (report.BoundaryLoops > 0 && !this->FillHoles)
    {
      message << ". Set FillHoles to close the holes";
    }
    if (report.ConnectedComponents > 1 && !this->KeepLargestComponent)
    {
      message << ". Set KeepLargestComponent to map only the largest component";
    }
    vtkErrorMacro(<< message.str() << ".");
    return 0;
  }
  if (report.UnusedPoints > 0 || points.rows() != input->GetNumberOfPoints())
  {
    vtkWarningMacro(<< "The output has " << points.rows() << " points, the input "
                    << input->GetNumberOfPoints()
                    << " (duplicates merged, unused points dropped, holes filled).");
  }
  // The flow keeps the orientation of the triangles; make them face outward so the map
  // comes out orientation-preserving and outward-facing on the sphere.
  const bool reversed = mobius::EnclosedVolume(points, triangles) < 0;
  if (reversed)
  {
    triangles.col(1).swap(triangles.col(2));
  }

  mobius::ConformalMapParameters parameters;
  parameters.TimeStep = this->TimeStep;
  parameters.MaximumNumberOfIterations = this->MaximumNumberOfIterations;
  parameters.ConvergenceTolerance = this->ConvergenceTolerance;
  parameters.IntrinsicDelaunay = this->IntrinsicDelaunay == INTRINSIC_DELAUNAY_ON ||
    (this->IntrinsicDelaunay == INTRINSIC_DELAUNAY_AUTOMATIC &&
      mobius::SmallestTriangleAngleDegrees(points, triangles) < this->IntrinsicDelaunayAngle);
  parameters.IntrinsicDelaunayWhenFolded = this->IntrinsicDelaunay == INTRINSIC_DELAUNAY_AUTOMATIC;
  parameters.FlipRepairPasses = this->FlipRepairPasses;
  parameters.MobiusCentering = this->CenterBetweenSteps;
  parameters.LinearStart = this->LinearStart;
  parameters.ReuseFactorization = this->ReuseFactorization;
  parameters.Progress = [this](double fraction) {
    this->UpdateProgress(fraction);
    return !this->GetAbortExecute();
  };
  mobius::Vector surfaceAreas(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const Eigen::Vector3d a = points.row(triangles(t, 0)), b = points.row(triangles(t, 1)),
                          c = points.row(triangles(t, 2));
    const double area = 0.5 * (b - a).cross(c - a).norm();
    surfaceAreas[t] = std::ldexp(area, 2 * scaleExponent);
    if (!std::isfinite(surfaceAreas[t]) || !(surfaceAreas[t] >= DBL_MIN))
    {
      vtkErrorMacro(<< "Cannot map the mesh to the sphere: its triangles' areas (triangle " << t
                    << ": 2^" << std::ilogb(area) + 2 * scaleExponent
                    << ") are beyond what double precision represents; rescale the mesh.");
      return 0;
    }
  }
  const mobius::ConformalMapResult result =
    mobius::ComputeSphericalConformalMap(points, triangles, parameters);
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
  const std::string degenerateReason = verdict.Reason();
  if (verdict.Degenerate())
  {
    vtkWarningMacro(<< "The map is degenerate: " << degenerateReason << ".");
  }
  else if (!verdict.Warning.empty())
  {
    vtkWarningMacro(<< "The map is usable, but " << verdict.Warning << ".");
  }

  // Assemble the spherical map.
  mobius::vtk::SetPoints(output, result.SpherePoints);
  vtkNew<vtkCellArray> polys;
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    const vtkIdType ids[3] = { triangles(t, 0), triangles(t, 1), triangles(t, 2) };
    polys->InsertNextCell(3, ids);
  }
  output->SetPolys(polys);
  CopyAttributes(surface->GetPointData(), output->GetPointData(), provenance.Points);
  CopyAttributes(surface->GetCellData(), output->GetCellData(), provenance.Triangles);
  output->GetFieldData()->ShallowCopy(input->GetFieldData());

  vtkNew<vtkDoubleArray> surfacePoints;
  surfacePoints->SetName(mobius::vtk::SurfacePointsArrayName);
  surfacePoints->SetNumberOfComponents(3);
  surfacePoints->SetNumberOfTuples(points.rows());
  const double restore = std::ldexp(1.0, scaleExponent); // the input's scale, exactly
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
    inputPointIds->SetValue(i, static_cast<vtkIdType>(provenance.Points[i]));
  }
  output->GetPointData()->AddArray(inputPointIds);
  vtkNew<vtkDoubleArray> areas;
  areas->SetName(mobius::vtk::SurfaceAreaArrayName);
  areas->SetNumberOfTuples(triangles.rows());
  for (Eigen::Index t = 0; t < triangles.rows(); ++t)
  {
    areas->SetValue(t, surfaceAreas[t]);
  }
  output->GetCellData()->AddArray(areas);
  // Colored by default by how far each triangle is from conformal.
  mobius::vtk::AddDistortionArrays(output, "QuasiConformalDistortion");

  vtkFieldData* fieldData = output->GetFieldData();
  using mobius::vtk::SetFieldCount;
  using mobius::vtk::SetFieldInteger;
  using mobius::vtk::SetFieldValue;
  SetFieldInteger(fieldData, "ConformalFlowIterations", result.Iterations);
  SetFieldValue(fieldData, "ConformalFlowRelativeChange", result.RelativeChange);
  SetFieldInteger(fieldData, "ConformalFlowConverged", result.Converged ? 1 : 0);
  SetFieldInteger(fieldData, "ConformalFlowLinearStart", result.LinearStart ? 1 : 0);
  SetFieldInteger(fieldData, "ConformalFlowFactorizations", result.Factorizations);
  SetFieldCount(
    fieldData, "FlippedTriangles", static_cast<vtkIdType>(result.Distortion.FlippedTriangles));
  SetFieldValue(fieldData, "MeanQuasiConformalDistortion", result.Distortion.MeanQuasiConformal);
  SetFieldValue(fieldData, "MaxQuasiConformalDistortion", result.Distortion.MaxQuasiConformal);
  SetFieldValue(fieldData, "MedianQuasiConformalDistortion", result.Distortion.MedianQuasiConformal);
  SetFieldValue(fieldData, "P95QuasiConformalDistortion", result.Distortion.P95QuasiConformal);
  SetFieldValue(fieldData, "P99QuasiConformalDistortion", result.Distortion.P99QuasiConformal);
  SetFieldValue(fieldData, "SquashedAreaShare", result.Distortion.SquashedAreaShare);
  SetFieldValue(fieldData, "SmallestSphereAreaShare", result.Distortion.SmallestMappedAreaShare);
  const double areaRange[2] = { result.Distortion.MinAreaRatio, result.Distortion.MaxAreaRatio };
  mobius::vtk::SetFieldValues(fieldData, "AreaDistortionRange", areaRange, 2);
  SetFieldInteger(fieldData, "IntrinsicDelaunayUsed", result.IntrinsicDelaunayUsed ? 1 : 0);
  SetFieldCount(fieldData, "IntrinsicDelaunayFlips", static_cast<vtkIdType>(result.IntrinsicFlips));
  SetFieldCount(fieldData, "MergedDuplicatePoints", static_cast<vtkIdType>(duplicates));
  SetFieldInteger(fieldData, "FilledHoles", static_cast<int>(filledHoles));
  SetFieldInteger(fieldData, "ReversedTriangleOrientation", reversed ? 1 : 0);
  SetFieldCount(
    fieldData, "FlipRepairMovedVertices", static_cast<vtkIdType>(result.FlipRepair.MovedVertices));
  SetFieldInteger(fieldData, "SqueezedRegionRefinementFailed", result.Refinement.Success ? 0 : 1);
  SetFieldInteger(fieldData, "DegenerateMap", verdict.Degenerate() ? 1 : 0);
  vtkNew<vtkStringArray> reason;
  reason->SetName("DegenerateMapReason");
  reason->InsertNextValue(degenerateReason);
  fieldData->AddArray(reason);
  vtkNew<vtkStringArray> warning;
  warning->SetName("MapWarning");
  warning->InsertNextValue(verdict.Degenerate() ? std::string() : verdict.Warning);
  fieldData->AddArray(warning);
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
  os << indent << "FillHoles: " << this->FillHoles << "\n";
  os << indent << "KeepLargestComponent: " << this->KeepLargestComponent << "\n";
}
