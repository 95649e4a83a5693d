#include "vtkMobiusThreadedPolyDataAlgorithm.h"

//------------------------------------------------------------------------------
void vtkMobiusThreadedPolyDataAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
}
