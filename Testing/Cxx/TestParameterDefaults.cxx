// The filters' defaults and ranges are the core's (mobius::RegistrationParameters): each
// default-constructed filter reports the core default, and each setter clamps to the core's
// range, so that the command line (which refuses values outside it) and the filters (which
// clamp) draw the same line. The plugin XML and the Python module are checked against the
// filters by test_parameter_defaults.py.
#include "MobiusTestUtilities.h"
#include "RegistrationParameters.h"
#include "vtkCorrespondenceRefinement.h"
#include "vtkDenseCorrespondence.h"
#include "vtkMobiusCenter.h"
#include "vtkSO3Register.h"
#include "vtkSphericalConformalMap.h"
#include "vtkSymmetryDetection.h"

#include <iostream>

namespace
{
int failures = 0;

template <typename T>
void ExpectEqual(const char* what, T actual, T expected)
{
  if (!(actual == expected))
  {
    std::cerr << what << ": " << actual << ", expected " << expected << "\n";
    ++failures;
  }
}

// Sets `below` and `above` in turn through `set` and expects `get` to come back with the ends
// of `range`.
template <typename Filter, typename Owner>
void ExpectClamp(const char* what, Filter* filter, void (Owner::*set)(int), int (Owner::*get)(),
  const mobius::IntegerRange& range)
{
  (filter->*set)(range.Minimum - 1);
  ExpectEqual(what, (filter->*get)(), range.Minimum);
  (filter->*set)(range.Maximum + 1);
  ExpectEqual(what, (filter->*get)(), range.Maximum);
}
}

int TestParameterDefaults(int, char*[])
{
  const mobius::RegistrationParameters core;

  vtkNew<vtkSphericalConformalMap> conformal;
  ExpectEqual("conformal MaximumNumberOfIterations", conformal->GetMaximumNumberOfIterations(),
    core.FlowIterations);
  ExpectEqual("conformal ConvergenceTolerance", conformal->GetConvergenceTolerance(), core.FlowTolerance);
  ExpectEqual("conformal CenterBetweenSteps", conformal->GetCenterBetweenSteps() != 0, core.CenterBetweenSteps);
  ExpectEqual("conformal Repair", conformal->GetRepair() != 0, core.Repair);
  ExpectEqual("conformal FillHoles", conformal->GetFillHoles() != 0, core.FillHoles);
  ExpectEqual("conformal KeepLargestComponent", conformal->GetKeepLargestComponent() != 0,
    core.KeepLargestComponent);

  vtkNew<vtkMobiusCenter> center;
  ExpectEqual("center Tolerance", center->GetTolerance(), core.CenteringTolerance);
  ExpectEqual("center GeneralizedTolerance", center->GetGeneralizedTolerance(),
    core.GeneralizedCenteringTolerance);
  // The drift this replaced: 1e-8 in the core, 1e-10 in the filter, which the pipeline used.
  ExpectEqual("core generalized centering tolerance", core.GeneralizedCenteringTolerance,
    mobius::GeneralizedCenteringParameters().Tolerance);
  ExpectEqual("center Degree", center->GetDegree(), core.CenteringDegree);
  ExpectClamp("center Degree range", center.Get(), &vtkMobiusCenter::SetDegree,
    &vtkMobiusCenter::GetDegree, mobius::CenteringDegreeRange);

  vtkNew<vtkSO3Register> registration;
  ExpectEqual("register Resolution", registration->GetResolution(), core.Resolution);
  ExpectEqual("register SmoothingTime", registration->GetSmoothingTime(), core.SmoothingTime);
  ExpectEqual("register TransformMode", registration->GetTransformMode(), core.TransformMode);
  ExpectEqual("register NumberOfCandidates", registration->GetNumberOfCandidates(),
    core.NumberOfCandidates);
  ExpectEqual("register CandidateSeparation", registration->GetCandidateSeparation(),
    core.CandidateSeparation);
  ExpectEqual("register NumberOfThreads", registration->GetNumberOfThreads(), core.NumberOfThreads);
  ExpectClamp("register NumberOfThreads range", registration.Get(),
    &vtkSO3Register::SetNumberOfThreads, &vtkSO3Register::GetNumberOfThreads,
    mobius::ThreadCountRange);

  vtkNew<vtkDenseCorrespondence> dense;
  ExpectEqual("dense OutputGeometry", dense->GetOutputGeometry(), core.OutputGeometry);
  ExpectEqual("dense NumberOfThreads", dense->GetNumberOfThreads(), core.NumberOfThreads);

  vtkNew<vtkCorrespondenceRefinement> refinement;
  ExpectEqual("refinement BasisSize", refinement->GetBasisSize(), core.BasisSize);
  ExpectEqual("refinement StartBasisSize", refinement->GetStartBasisSize(), core.StartBasisSize);
  ExpectEqual("refinement ScreeningBasisSize", refinement->GetScreeningBasisSize(),
    core.ScreeningBasisSize);
  ExpectEqual("refinement GeometricPolish", refinement->GetGeometricPolish(), core.GeometricPolish);
  ExpectEqual("refinement BothDirections", refinement->GetBothDirections(), core.BothDirections);
  ExpectEqual("refinement Candidate", refinement->GetCandidate(), core.Candidate);
  ExpectEqual("refinement OutputGeometry", refinement->GetOutputGeometry(), core.OutputGeometry);
  ExpectEqual("refinement NumberOfThreads", refinement->GetNumberOfThreads(), core.NumberOfThreads);
  ExpectClamp("refinement BasisSize range", refinement.Get(),
    &vtkCorrespondenceRefinement::SetBasisSize, &vtkCorrespondenceRefinement::GetBasisSize,
    mobius::BasisSizeRange);
  ExpectClamp("refinement Candidate range", refinement.Get(),
    &vtkCorrespondenceRefinement::SetCandidate, &vtkCorrespondenceRefinement::GetCandidate,
    mobius::CandidateRange);
  // The refinement rule: twice as many points as eigenfunctions.
  ExpectEqual("CanRefine(160, 80)", vtkCorrespondenceRefinement::CanRefine(160, 80), true);
  ExpectEqual("CanRefine(159, 80)", vtkCorrespondenceRefinement::CanRefine(159, 80), false);

  vtkNew<vtkSymmetryDetection> symmetry;
  ExpectEqual("symmetry Centering", symmetry->GetCentering(), core.Centering);
  ExpectEqual("symmetry Resolution", symmetry->GetResolution(), core.Resolution);
  ExpectEqual("symmetry SmoothingTime", symmetry->GetSmoothingTime(), core.SmoothingTime);
  ExpectEqual("symmetry NumberOfCandidates", symmetry->GetNumberOfCandidates(), core.NumberOfCandidates);
  ExpectEqual("symmetry Refine", symmetry->GetRefine(), core.Refine);
  ExpectEqual("symmetry BasisSize", symmetry->GetBasisSize(), core.BasisSize);
  ExpectEqual("symmetry GeometricPolish", symmetry->GetGeometricPolish(), core.GeometricPolish);
  ExpectEqual("symmetry NumberOfThreads", symmetry->GetNumberOfThreads(), core.NumberOfThreads);
  return failures == 0 ? 0 : 1;
}
