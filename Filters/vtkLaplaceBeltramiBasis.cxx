#include "vtkLaplaceBeltramiBasis.h"

#include "LaplaceBeltramiBasis.h"
#include "MobiusLaplaceBeltramiBasisData.h"
#include "MobiusSphericalMapData.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkLaplaceBeltramiBasis);

//------------------------------------------------------------------------------
int vtkLaplaceBeltramiBasis::ComputeOutput(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = nullptr;
  vtkPolyData* output = nullptr;
  if (!this->GetInputAndOutput(inputVector, outputVector, input, output))
  {
    return 0;
  }
  // The surface exactly as vtkCorrespondenceRefinement reads it, so that the fingerprints
  // agree and the basis is the one it would compute.
  mobius::Points surface;
  mobius::Triangles triangles;
  const bool isMap =
    input->GetPointData()->GetArray(mobius::vtk::SurfacePointsArrayName) != nullptr;
  std::string error = isMap ? mobius::vtk::ExtractSurfacePoints(input, surface)
                            : mobius::vtk::ExtractPoints(input, surface);
  if (error.empty())
  {
    error = mobius::vtk::ExtractTriangles(input, triangles);
  }
  if (error.empty() && triangles.rows() == 0)
  {
    error = "it has no triangles";
  }
  if (error.empty() && surface.rows() <= this->BasisSize)
  {
    error = "it has " + std::to_string(surface.rows()) + " points; a basis of " +
      std::to_string(this->BasisSize) + " functions needs more";
  }
  if (!error.empty())
  {
    vtkErrorMacro(<< "Cannot compute the Laplace-Beltrami basis of the input: " << error << ".");
    return 0;
  }
  mobius::vtk::NormalizeSurfaceScale(surface);
  const std::string fingerprint = mobius::vtk::SurfaceFingerprint(surface, triangles);
  mobius::vtk::CenterSurface(surface);
  this->UpdateProgress(0.05);

  mobius::LaplaceBeltramiBasis basis;
  if (!mobius::ComputeLaplaceBeltramiBasis(surface, triangles, this->BasisSize, basis, error))
  {
    vtkErrorMacro(<< "Cannot compute the Laplace-Beltrami basis of the input: " << error << ".");
    return 0;
  }
  output->ShallowCopy(input);
  mobius::vtk::AddBasisArrays(output, basis, fingerprint);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLaplaceBeltramiBasis::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "BasisSize: " << this->BasisSize << "\n";
}
