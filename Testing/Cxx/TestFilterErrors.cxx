// Hostile input to the filters: an exception inside a filter (std::bad_alloc, or one carried
// out of a worker thread) becomes that filter's error instead of ending the program.
#include "MobiusTestUtilities.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSphericalScaleGrid.h"

#include "vtkExecutive.h"

#include <new>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using mobius_test::BumpyMesh;

// Runs `filter` and checks it fails with an error containing `words` and an empty output.
int ExpectError(vtkPolyDataAlgorithm* filter, const std::string& words)
{
  int failures = 0;
  mobius_test::MessageCatcher catcher(filter);
  mobius_test::MessageCatcher executiveCatcher(filter->GetExecutive());
  filter->Update();
  if (catcher.Error.find(words) == std::string::npos)
  {
    std::cerr << filter->GetClassName() << ": expected an error containing '" << words
              << "', got '" << catcher.Error << "'\n";
    ++failures;
  }
  MOBIUS_EXPECT(filter->GetOutput()->GetNumberOfPoints() == 0);
  return failures;
}

// The executive reports progress 0 and 1 around RequestData; the filters report values
// between while they work.
bool InsideRequestData(void* progress)
{
  const double fraction = *static_cast<double*>(progress);
  return fraction > 0 && fraction < 1;
}

// An exception thrown while a filter runs (here by a progress observer, standing in for
// std::bad_alloc in a worker thread) is reported as the filter's error; nothing escapes.
int TestExceptionsBecomeErrors()
{
  int failures = 0;
  vtkNew<vtkCallbackCommand> outOfMemory;
  outOfMemory->SetCallback([](vtkObject*, unsigned long, void*, void* progress) {
    if (InsideRequestData(progress))
    {
      throw std::bad_alloc();
    }
  });
  vtkNew<vtkCallbackCommand> failing;
  failing->SetCallback([](vtkObject*, unsigned long, void*, void* progress) {
    if (InsideRequestData(progress))
    {
      throw std::runtime_error("observer failed");
    }
  });

  auto map = mobius_test::MakeSphericalMap(2, mobius_test::BumpySurface);
  vtkNew<vtkSphericalConformalMap> conformal;
  conformal->SetInputData(BumpyMesh(2));
  conformal->AddObserver(vtkCommand::ProgressEvent, outOfMemory);
  failures += ExpectError(conformal, "out of memory");
  vtkNew<vtkMobiusCenter> center;
  center->SetInputData(map);
  center->AddObserver(vtkCommand::ProgressEvent, failing);
  failures += ExpectError(center, "observer failed");
  vtkNew<vtkSphericalScaleGrid> grid;
  grid->SetInputData(map);
  grid->SetResolution(16);
  grid->AddObserver(vtkCommand::ProgressEvent, outOfMemory);
  failures += ExpectError(grid, "out of memory");
  vtkNew<vtkSO3Register> registration;
  registration->SetSourceData(map);
  registration->SetTargetData(map);
  registration->SetResolution(16);
  registration->AddObserver(vtkCommand::ProgressEvent, outOfMemory);
  failures += ExpectError(registration, "out of memory");
  vtkNew<vtkDenseCorrespondence> correspondence;
  correspondence->SetSourceData(map);
  correspondence->SetTargetData(map);
  correspondence->AddObserver(vtkCommand::ProgressEvent, failing);
  failures += ExpectError(correspondence, "observer failed");
  return failures;
}
}

int TestFilterErrors(int, char*[])
{
  int failures = 0;
  failures += TestExceptionsBecomeErrors();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
