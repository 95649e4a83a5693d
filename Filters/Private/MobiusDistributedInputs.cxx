#include "MobiusDistributedInputs.h"

#include "MobiusInputArrays.h"
#include "MobiusLostPiecesCheck.h"
#include "MobiusMergePieces.h"
#include "MobiusSphericalMapData.h"

#include "vtkAlgorithm.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <string>
#include <vector>

namespace mobius
{
namespace vtk
{
namespace
{
// The rank that gathers the pieces and runs the algorithm.
constexpr int RootProcess = 0;

// The global controller when the output is requested as this process's piece of one
// piece per process; null for any other request.
vtkMultiProcessController* DistributingController(vtkInformationVector* outputVector)
{
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  vtkInformation* info = outputVector ? outputVector->GetInformationObject(0) : nullptr;
  if (!controller || controller->GetNumberOfProcesses() < 2 || !info ||
    !info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()) ||
    !info->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    return nullptr;
  }
  const int pieces = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES());
  const int piece = info->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  if (pieces != controller->GetNumberOfProcesses() || piece != controller->GetLocalProcessId())
  {
    return nullptr;
  }
  return controller;
}

// How messages name the input on `port`: Source and Target for the two-input filters,
// Input for the others.
std::string InputName(vtkAlgorithm* filter, int port)
{
  if (filter->GetNumberOfInputPorts() != 2)
  {
    return "Input";
  }
  return port == 0 ? "Source" : "Target";
}

// Gathers the pieces of the input on `port` on the root and joins them there; null on
// the other ranks. Every rank must call it, for every port in the same order.
vtkSmartPointer<vtkPolyData> GatherWholeInput(vtkAlgorithm* filter,
  vtkMultiProcessController* controller, vtkInformationVector* inputs, int port, bool& failed)
{
  vtkPolyData* local = vtkPolyData::GetData(inputs);
  std::vector<vtkSmartPointer<vtkDataObject>> received;
  if (!controller->Gather(local, received, RootProcess))
  {
    vtkErrorWithObjectMacro(filter, << "Could not gather the pieces of input " << port
                                    << " on rank " << RootProcess << ".");
    failed = true;
    return nullptr;
  }
  if (controller->GetLocalProcessId() != RootProcess)
  {
    return nullptr;
  }
  std::vector<vtkPolyData*> pieces;
  for (size_t rank = 0; rank < received.size(); ++rank)
  {
    // The root's own piece as it is (the received one went through serialization).
    pieces.push_back(static_cast<int>(rank) == RootProcess
        ? local
        : vtkPolyData::SafeDownCast(received[rank]));
    // Joining the pieces copies their arrays: each must fit its piece first.
    const std::string mismatch = MismatchedArray(pieces.back());
    if (!mismatch.empty())
    {
      vtkErrorWithObjectMacro(filter, << InputName(filter, port) << " (the piece of rank " << rank
                                      << "): " << mismatch << ".");
      failed = true;
      return nullptr;
    }
  }
  const MergedPieces merged = MergePieces(pieces);
  if (!merged.Error.empty())
  {
    vtkErrorWithObjectMacro(filter, << "Cannot join the pieces of input " << port
                                    << " gathered from the ranks: " << merged.Error << ".");
    failed = true;
    return nullptr;
  }
  if (!merged.GlobalIdsIgnored.empty())
  {
    vtkWarningWithObjectMacro(filter, << "The pieces of input " << port
                                      << " were joined by point position, not by their point "
                                         "global ids: "
                                      << merged.GlobalIdsIgnored
                                      << ". The points follow the ranks' order.");
  }
  return merged.Surface;
}

// Runs `compute` unless an input is empty (then the output stays empty: not an error, and a
// warning when another input is not) or holds an array that does not fit its mesh (an
// error).
int ComputeUnlessEmpty(vtkAlgorithm* filter, std::vector<vtkInformationVector*> inputs,
  const WholeInputsComputation& compute)
{
  std::string emptyInputs;
  size_t empty = 0;
  for (size_t port = 0; port < inputs.size(); ++port)
  {
    vtkPolyData* data = vtkPolyData::GetData(inputs[port]);
    if (data && IsEmptyPiece(data))
    {
      emptyInputs += (empty++ ? " and " : "") + InputName(filter, static_cast<int>(port));
    }
  }
  if (empty > 0)
  {
    // One input of two empty and the other not is the user's to know (a Target whose
    // filter produced nothing); nothing at all upstream is VTK's quiet empty pipeline.
    if (empty < inputs.size())
    {
      vtkWarningWithObjectMacro(filter, << emptyInputs << " is empty (no points and no cells): "
                                        << "the output is empty.");
    }
    return 1;
  }
  for (size_t port = 0; port < inputs.size(); ++port)
  {
    const std::string mismatch = MismatchedArray(vtkPolyData::GetData(inputs[port]));
    if (!mismatch.empty())
    {
      vtkErrorWithObjectMacro(filter, << InputName(filter, static_cast<int>(port)) << ": " << mismatch << ".");
      return 0;
    }
  }
  return compute(inputs.data());
}
}

//------------------------------------------------------------------------------
int RequestDataOnWholeInputs(vtkAlgorithm* filter, vtkInformationVector** inputVector,
  vtkInformationVector* outputVector, const WholeInputsComputation& filterComputation)
{
  // No exception may leave the pipeline (in ParaView it would end the application): running
  // out of memory, or a failure in a worker thread, becomes the filter's error.
  const WholeInputsComputation compute = [&](vtkInformationVector** wholeInputs) {
    try
    {
      return filterComputation(wholeInputs);
    }
    catch (...)
    {
      return ReportException(filter, outputVector);
    }
  };
  const int ports = filter->GetNumberOfInputPorts();
  if (vtkDataObject* output = vtkDataObject::GetData(outputVector))
  {
    output->Initialize();
  }
  vtkMultiProcessController* controller = DistributingController(outputVector);
  if (!controller)
  {
    return ComputeUnlessEmpty(filter,
      std::vector<vtkInformationVector*>(inputVector, inputVector + ports), compute);
  }

  // Every rank takes part in the same collectives, whatever happens on the root: the
  // gathers, one per port, and the status broadcast.
  int status = 1;
  bool failed = false;
  std::vector<vtkSmartPointer<vtkPolyData>> whole(ports);
  std::vector<vtkSmartPointer<vtkInformationVector>> wholeInputs(ports);
  for (int port = 0; port < ports; ++port)
  {
    try
    {
      whole[port] = GatherWholeInput(filter, controller, inputVector[port], port, failed);
    }
    catch (...) // out of memory joining the pieces: the next port's gather still runs
    {
      ReportException(filter, outputVector);
      failed = true;
    }
  }
  if (controller->GetLocalProcessId() == RootProcess)
  {
    const std::string lost = failed ? std::string() : LostPiecesReason(filter);
    if (!lost.empty())
    {
      // Holes where cells were lost are not the surface's own: refuse them, never fill them.
      vtkErrorWithObjectMacro(filter, << "The pieces gathered from the ranks are incomplete: "
                                      << lost << ".");
    }
    if (failed || !lost.empty())
    {
      status = 0;
    }
    else
    {
      std::vector<vtkInformationVector*> inputs(ports);
      for (int port = 0; port < ports; ++port)
      {
        vtkNew<vtkInformation> information;
        information->Set(vtkDataObject::DATA_OBJECT(), whole[port]);
        wholeInputs[port] = vtkSmartPointer<vtkInformationVector>::New();
        wholeInputs[port]->Append(information);
        inputs[port] = wholeInputs[port];
      }
      status = ComputeUnlessEmpty(filter, inputs, compute);
    }
  }
  controller->Broadcast(&status, 1, RootProcess);
  return status;
}
}
}
