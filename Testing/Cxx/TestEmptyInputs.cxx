// VTK's convention, which ParaView relies on (a rank without data, a filter upstream that
// produced nothing): an empty input gives an empty output, with no error and no warning.
// For the two-input filters, one empty input is enough; when the other is not empty, a
// warning names the empty one (an empty Target gave an empty output without a word).
#include "MobiusTestUtilities.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkMobiusRegistration.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSphericalOrbifoldMap.h"
#include "vtkSphericalScaleGrid.h"
#include "vtkSymmetryDetection.h"

namespace
{
// An empty output, no error, and the warning `warning` (none when empty).
int ExpectEmptyOutput(vtkPolyDataAlgorithm* filter, const std::string& warning = "")
{
  int failures = 0;
  mobius_test::MessageCatcher catcher(filter);
  mobius_test::MessageCatcher executiveCatcher(filter->GetExecutive());
  const int status = filter->GetExecutive()->Update();
  const bool warned = warning.empty() ? catcher.Warning.empty()
                                      : catcher.Warning.find(warning) != std::string::npos;
  if (status != 1 || !catcher.Error.empty() || !warned || !executiveCatcher.Error.empty())
  {
    std::cerr << filter->GetClassName() << ": expected an empty output "
              << (warning.empty() ? "without a message" : "with the warning '" + warning + "'")
              << ", got status " << status << ", error '" << catcher.Error
              << executiveCatcher.Error << "', warning '" << catcher.Warning << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(filter->GetOutput()->GetNumberOfPoints() == 0);
  MOBIUS_EXPECT(filter->GetOutput()->GetNumberOfCells() == 0);
  return failures;
}

// `Filter` with two inputs (source, target): empty on either port or both.
template <typename Filter>
int ExpectEmptyOutputs(vtkPolyData* map)
{
  int failures = 0;
  vtkNew<vtkPolyData> empty;
  const char* warnings[4] = { "", "Source is empty (no points and no cells): the output is empty",
    "Target is empty (no points and no cells): the output is empty", "" };
  for (int emptyPorts : { 1, 2, 3 })
  {
    vtkNew<Filter> filter;
    filter->SetInputData(0, (emptyPorts & 1) ? empty.Get() : map);
    filter->SetInputData(1, (emptyPorts & 2) ? empty.Get() : map);
    failures += ExpectEmptyOutput(filter, warnings[emptyPorts]);
  }
  return failures;
}
}

int TestEmptyInputs(int, char*[])
{
  int failures = 0;
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkSphericalConformalMap> conformal;
  vtkNew<vtkMobiusCenter> center;
  vtkNew<vtkSphericalScaleGrid> grid;
  vtkNew<vtkSymmetryDetection> symmetry;
  vtkNew<vtkSphericalOrbifoldMap> orbifold;
  for (vtkPolyDataAlgorithm* filter : std::initializer_list<vtkPolyDataAlgorithm*>{
         conformal, center, grid, symmetry, orbifold })
  {
    filter->SetInputData(empty);
    failures += ExpectEmptyOutput(filter);
  }
  // Downstream of a filter whose output is empty.
  vtkNew<vtkSphericalConformalMap> first;
  first->SetInputData(empty);
  vtkNew<vtkMobiusCenter> next;
  next->SetInputConnection(first->GetOutputPort());
  failures += ExpectEmptyOutput(next);

  auto map = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  failures += ExpectEmptyOutputs<vtkSO3Register>(map);
  failures += ExpectEmptyOutputs<vtkDenseCorrespondence>(map);
  failures += ExpectEmptyOutputs<vtkCorrespondenceRefinement>(map);
  failures += ExpectEmptyOutputs<vtkMobiusRegistration>(mobius_test::BumpyMesh(2));

  // A mesh with points but no cells is not empty: still an error.
  vtkNew<vtkPolyData> pointsOnly;
  pointsOnly->SetPoints(mobius_test::BumpyMesh(1)->GetPoints());
  vtkNew<vtkSphericalConformalMap> noCells;
  noCells->SetInputData(pointsOnly);
  failures += ExpectError(noCells, "no triangles");

  // Nor is one with cells but no points: the filters that need points say so.
  vtkNew<vtkPoints> noPoints;
  vtkNew<vtkPolyData> cellsOnly;
  cellsOnly->SetPoints(noPoints);
  cellsOnly->SetPolys(mobius_test::BumpyMesh(1)->GetPolys());
  vtkNew<vtkSymmetryDetection> symmetryOfNothing;
  symmetryOfNothing->SetInputData(cellsOnly);
  failures += ExpectError(symmetryOfNothing, "Cannot detect symmetry: the input is empty.");
  vtkNew<vtkSphericalOrbifoldMap> orbifoldOfNothing;
  orbifoldOfNothing->SetInputData(cellsOnly);
  failures += ExpectError(orbifoldOfNothing, "Cannot compute an orbifold map: the input is empty.");
  return failures == 0 ? 0 : 1;
}
