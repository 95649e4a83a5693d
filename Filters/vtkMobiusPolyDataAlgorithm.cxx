#include "vtkMobiusPolyDataAlgorithm.h"

#include "vtkDistributedInputs.h"
#include "vtkSphericalMapData.h"

//------------------------------------------------------------------------------
int vtkMobiusPolyDataAlgorithm::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (this->GetNumberOfInputPorts() == 0)
  {
    // A source: nothing to gather, the pipeline asks it for piece 0 only.
    try
    {
      return this->ComputeOutput(request, inputVector, outputVector);
    }
    catch (...)
    {
      return mobius::vtk::ReportException(this, outputVector, this->ExceptionSubject());
    }
  }
  // The whole surface, also when ParaView splits it over ranks (the result then lives on
  // rank 0); an empty input gives an empty output; RequestDataOnWholeInputs guards against
  // exceptions.
  return mobius::vtk::RequestDataOnWholeInputs(
    this, inputVector, outputVector, [&](vtkInformationVector** wholeInputs) {
      return this->ComputeOutput(request, wholeInputs, outputVector);
    });
}

//------------------------------------------------------------------------------
void vtkMobiusPolyDataAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
