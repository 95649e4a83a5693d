#include "vtkSphericalScaleGrid.h"

#include "ParallelFor.h"
#include "ScaleFactorSignal.h"
#include "MobiusSphericalMapData.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <cmath>
#include <sstream>

vtkStandardNewMacro(vtkSphericalScaleGrid);

namespace
{
// Point ids of the closed grid sphere: the north pole, N - 1 rings of N points, the south
// pole. Ring r (1..N-1) lies at theta = pi r / N; point i of a ring at phi = 2 pi i / N.
struct GridPointIds
{
  int N;
  vtkIdType North() const { return 0; }
  vtkIdType South() const { return 1 + static_cast<vtkIdType>(N - 1) * N; }
  vtkIdType Ring(int r, int i) const { return 1 + static_cast<vtkIdType>(r - 1) * N + (i % N); }
};

// The grid sphere's cells, in grid order j*N + i, outward oriented.
vtkNew<vtkCellArray> MakeGridCells(const GridPointIds& ids)
{
  const int N = ids.N;
  vtkNew<vtkCellArray> cells;
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      if (j == 0)
      {
        const vtkIdType tri[3] = { ids.North(), ids.Ring(1, i), ids.Ring(1, i + 1) };
        cells->InsertNextCell(3, tri);
      }
      else if (j == N - 1)
      {
        const vtkIdType tri[3] = { ids.Ring(N - 1, i), ids.South(), ids.Ring(N - 1, i + 1) };
        cells->InsertNextCell(3, tri);
      }
      else
      {
        const vtkIdType quad[4] = { ids.Ring(j, i), ids.Ring(j + 1, i), ids.Ring(j + 1, i + 1),
          ids.Ring(j, i + 1) };
        cells->InsertNextCell(4, quad);
      }
    }
  }
  return cells;
}

// Grid point positions; with `values` (cell-centered, N*N), each point's radius is the mean
// of |value| over its adjacent cells divided by the largest such mean.
vtkNew<vtkPoints> MakeGridPoints(const GridPointIds& ids, const std::vector<double>* values)
{
  const int N = ids.N;
  std::vector<double> radius(ids.South() + 1, 1.0);
  if (values)
  {
    auto cell = [&](int j, int i) { return std::abs((*values)[j * N + ((i + N) % N)]); };
    double north = 0, south = 0;
    for (int i = 0; i < N; ++i)
    {
      north += cell(0, i) / N;
      south += cell(N - 1, i) / N;
    }
    radius[ids.North()] = north;
    radius[ids.South()] = south;
    for (int r = 1; r < N; ++r)
    {
      for (int i = 0; i < N; ++i)
      {
        radius[ids.Ring(r, i)] =
          0.25 * (cell(r - 1, i - 1) + cell(r - 1, i) + cell(r, i - 1) + cell(r, i));
      }
    }
    double largest = 0;
    for (double r : radius)
    {
      largest = std::max(largest, r);
    }
    for (double& r : radius)
    {
      r = largest > 0 ? r / largest : 1.0;
    }
  }
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(ids.South() + 1);
  points->SetPoint(ids.North(), 0, 0, radius[ids.North()]);
  points->SetPoint(ids.South(), 0, 0, -radius[ids.South()]);
  for (int r = 1; r < N; ++r)
  {
    const double theta = vtkMath::Pi() * r / N;
    for (int i = 0; i < N; ++i)
    {
      const double phi = 2 * vtkMath::Pi() * i / N;
      const double rho = radius[ids.Ring(r, i)];
      points->SetPoint(ids.Ring(r, i), rho * std::sin(theta) * std::cos(phi),
        rho * std::sin(theta) * std::sin(phi), rho * std::cos(theta));
    }
  }
  return points;
}

vtkNew<vtkDoubleArray> MakeCellArray(const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(static_cast<vtkIdType>(values.size()));
  for (size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  return array;
}

// The input map's scale-factor signal; false after reporting the error (none when the
// filter was aborted).
bool SampleScaleFactors(vtkSphericalScaleGrid* filter, vtkPolyData* input, int threads,
  mobius::ScaleFactorSignal& signal)
{
  mobius::Points points;
  mobius::Triangles triangles;
  mobius::Vector areas;
  std::string error = mobius::vtk::ExtractSphericalMap(input, false, points, triangles, areas);
  if (!error.empty())
  {
    vtkErrorWithObjectMacro(filter, << "Cannot sample the scale factors: " << error << ".");
    return false;
  }
  mobius::ScaleFactorSignalParameters parameters;
  parameters.Resolution = filter->GetResolution();
  parameters.NumberOfThreads = threads;
  parameters.SmoothingTime = filter->GetSmoothingTime();
  parameters.Value = filter->GetValueMode() == vtkSphericalScaleGrid::AREA_RATIO
    ? mobius::ScaleFactorValue::AreaRatio
    : mobius::ScaleFactorValue::SquareRootAreaRatio;
  auto progress = [filter](double fraction) {
    filter->UpdateProgress(0.9 * fraction);
    return !filter->GetAbortExecute();
  };
  if (!mobius::ComputeScaleFactorSignal(
        points, triangles, areas, parameters, true, signal, error, progress))
  {
    if (!filter->GetAbortExecute())
    {
      vtkErrorWithObjectMacro(filter, << "Cannot sample the scale factors: " << error << ".");
    }
    return false;
  }
  return true;
}

// The grid sphere with its cell arrays.
void WriteGrid(
  vtkSphericalScaleGrid* filter, const mobius::ScaleFactorSignal& signal, vtkPolyData* output)
{
  const GridPointIds ids{ filter->GetResolution() };
  output->SetPoints(
    MakeGridPoints(ids, filter->GetDisplaceByValue() ? &signal.SmoothedValues : nullptr));
  output->SetPolys(MakeGridCells(ids));
  output->GetCellData()->AddArray(MakeCellArray("ConformalFactor", signal.Grid.Values));
  auto smoothed = MakeCellArray("ConformalFactorSmoothed", signal.SmoothedValues);
  output->GetCellData()->AddArray(smoothed);
  output->GetCellData()->SetActiveScalars("ConformalFactorSmoothed");
}

// The grid's settings and measures as field data.
void WriteGridFields(vtkSphericalScaleGrid* filter, const mobius::ScaleFactorSignal& signal,
  int threads, vtkFieldData* fieldData)
{
  mobius::vtk::SetFieldInteger(fieldData, "Resolution", filter->GetResolution());
  mobius::vtk::SetFieldInteger(fieldData, "Bandwidth", filter->GetResolution() / 2);
  mobius::vtk::SetFieldValue(fieldData, "TotalArea", signal.Grid.TotalArea);
  mobius::vtk::SetFieldValue(fieldData, "SmoothingTime", filter->GetSmoothingTime());
  mobius::vtk::SetFieldInteger(fieldData, "ValueMode", filter->GetValueMode());
  mobius::vtk::SetFieldInteger(fieldData, "NumberOfThreadsUsed", threads);
  const std::vector<double> energies = mobius::DegreeEnergies(signal.Coefficients);
  mobius::vtk::SetFieldValues(
    fieldData, "DegreeEnergies", energies.data(), static_cast<int>(energies.size()));
}
}

//------------------------------------------------------------------------------
vtkSphericalScaleGrid::vtkSphericalScaleGrid() = default;

//------------------------------------------------------------------------------
int vtkSphericalScaleGrid::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output))
  {
    return 0;
  }
  const std::string badResolution = mobius::CheckGridResolution(this->Resolution);
  if (!badResolution.empty())
  {
    vtkErrorMacro(<< badResolution << ".");
    return 0;
  }
  const int threads = mobius::ResolveThreadCount(this->NumberOfThreads);
  mobius::ScaleFactorSignal signal;
  if (!SampleScaleFactors(this, input, threads, signal))
  {
    return 0;
  }
  WriteGrid(this, signal, output);
  WriteGridFields(this, signal, threads, output->GetFieldData());
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSphericalScaleGrid::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Resolution: " << this->Resolution << "\n";
  os << indent << "SmoothingTime: " << this->SmoothingTime << "\n";
  os << indent << "ValueMode: " << this->ValueMode << "\n";
  os << indent << "DisplaceByValue: " << this->DisplaceByValue << "\n";
}
