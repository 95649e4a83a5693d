#include "vtkMobiusPolyDataAlgorithm.h"

#include "MobiusFilterMessages.h"
#include "MobiusDistributedInputs.h"
#include "MobiusSphericalMapData.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkPolyData.h"

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
  // Settings no input can make right (the same on every rank: all ranks stop here alike).
  const std::string settings = this->SettingsError();
  if (!settings.empty())
  {
    if (vtkDataObject* output = vtkDataObject::GetData(outputVector))
    {
      output->Initialize();
    }
    vtkErrorMacro(<< settings);
    return 0;
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
bool vtkMobiusPolyDataAlgorithm::GetInputAndOutput(vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, vtkPolyData*& input, vtkPolyData*& output, const char* task)
{
  input = vtkPolyData::GetData(inputVector[0]);
  output = vtkPolyData::GetData(outputVector);
  if (!input || !output)
  {
    vtkErrorMacro(<< "Missing input or output polydata.");
    return false;
  }
  if (task && input->GetNumberOfPoints() == 0)
  {
    vtkErrorMacro(<< "Cannot " << task << ": the input is empty.");
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkMobiusPolyDataAlgorithm::RunInternalFilter(
  vtkPolyDataAlgorithm* filter, double begin, double end, std::string& error,
  std::vector<std::string>& warnings)
{
  struct Slice
  {
    vtkMobiusPolyDataAlgorithm* Owner;
    double Begin, End;
  } slice{ this, begin, end };
  vtkNew<vtkCallbackCommand> progress;
  progress->SetClientData(&slice);
  progress->SetCallback([](vtkObject* caller, unsigned long, void* clientData, void* callData) {
    auto stage = static_cast<Slice*>(clientData);
    const double fraction = callData ? *static_cast<double*>(callData) : 0.0;
    stage->Owner->UpdateProgress(stage->Begin + (stage->End - stage->Begin) * fraction);
    if (stage->Owner->GetAbortExecute())
    {
      static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    }
  });
  const unsigned long progressTag = filter->AddObserver(vtkCommand::ProgressEvent, progress);
  {
    mobius::vtk::FilterMessages messages(filter);
    filter->Update();
    error = messages.Error;
    warnings.insert(warnings.end(), messages.Warnings.begin(), messages.Warnings.end());
  }
  filter->RemoveObserver(progressTag);
  auto output = vtkSmartPointer<vtkPolyData>::New();
  output->ShallowCopy(filter->GetOutput());
  if (!error.empty() || output->GetNumberOfPoints() == 0 || this->GetAbortExecute())
  {
    return nullptr;
  }
  return output;
}

//------------------------------------------------------------------------------
void vtkMobiusPolyDataAlgorithm::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
