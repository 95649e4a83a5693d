// The properties of the spherical-map stage (repair, conformal flow, centering) that a filter
// mapping one mesh shares with the whole-pipeline filter, copied into the pipeline's
// parameters in one place: vtkMobiusRegistration and vtkCenteredSphericalMap have the same
// names for them, and a property added to both is read the same way by both.
#ifndef MobiusSphericalMapOptions_h
#define MobiusSphericalMapOptions_h

#include "RegistrationParameters.h"

namespace mobius
{
namespace vtk
{
/// Copies `filter`'s spherical-map properties into `options`; the others are left as they are.
template <class Filter>
void CopySphericalMapOptions(Filter* filter, RegistrationParameters& options)
{
  options.Repair = filter->GetRepair();
  options.FillHoles = filter->GetFillHoles();
  options.KeepLargestComponent = filter->GetKeepLargestComponent();
  options.AllowPoorMaps = filter->GetAllowPoorMaps();
  options.FlowIterations = filter->GetMaximumNumberOfIterations();
  options.FlowTolerance = filter->GetConvergenceTolerance();
  options.CenterBetweenSteps = filter->GetCenterBetweenSteps();
  options.CenteringDegree = filter->GetCenteringDegree();
}
}
}

#endif
