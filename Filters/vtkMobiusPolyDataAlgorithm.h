/**
 * @class   vtkMobiusPolyDataAlgorithm
 * @brief   What every filter of the module shares: RequestData on whole inputs, the
 * exception guard, and running a filter inside another one.
 *
 * A filter derives from this class and implements ComputeOutput, its own work. RequestData
 * (final here) runs it:
 * - on the whole surface of every input, also when ParaView splits the inputs over ranks
 *   (the result then lives on rank 0; MobiusDistributedInputs.h); an empty input gives an
 *   empty output and no error (a two-input filter with one input empty and the other not
 *   warns, naming the empty one). A source (no input port) runs as it is.
 * - after SettingsError, whose message is the filter's error.
 * - behind the exception guard: no exception leaves the pipeline (in ParaView it would end
 *   the application); running out of memory, or a failure in a worker thread, becomes the
 *   filter's error, prefixed by ExceptionSubject (a file name), with an empty output.
 *
 * RunInternalFilter runs a filter inside ComputeOutput (a stage of this filter's own
 * pipeline): its progress becomes a slice of this filter's, this filter's abort stops it,
 * and its messages come back (MobiusFilterMessages.h) to be reported as this filter's own.
 *
 * @sa vtkMobiusThreadedPolyDataAlgorithm
 */
#ifndef vtkMobiusPolyDataAlgorithm_h
#define vtkMobiusPolyDataAlgorithm_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

#include "vtkSmartPointer.h" // For RunInternalFilter

#include <string> // For ExceptionSubject
#include <vector> // For RunInternalFilter

class VTKMOBIUSREGISTRATIONFILTERS_EXPORT vtkMobiusPolyDataAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkMobiusPolyDataAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

protected:
  vtkMobiusPolyDataAlgorithm() = default;
  ~vtkMobiusPolyDataAlgorithm() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) final;

  /**
   * The filter's work, given the whole inputs (RequestData's arguments otherwise); returns
   * RequestData's status. An exception thrown here becomes the filter's error.
   */
  virtual int ComputeOutput(vtkInformation*, vtkInformationVector**, vtkInformationVector*) = 0;

  /**
   * What an exception's message is about (a file name); empty (default): "Failed".
   */
  virtual std::string ExceptionSubject() { return {}; }

  /**
   * What is wrong with the filter's settings whatever its inputs (an odd number of landmark
   * values); empty (default) when nothing is. RequestData reports it as the filter's error,
   * with an empty output, before it reads the inputs.
   */
  virtual std::string SettingsError() { return {}; }

  /**
   * The polydata of input port 0 and of the output, or false after reporting why not: the
   * error "Missing input or output polydata." when one is missing and, given the filter's
   * `task` ("detect symmetry"), "Cannot <task>: the input is empty." when the input has no
   * points (an input with no points and no cells never gets here: RequestData gives it an
   * empty output, without an error).
   */
  bool GetInputAndOutput(vtkInformationVector** inputVector, vtkInformationVector* outputVector,
    vtkPolyData*& input, vtkPolyData*& output, const char* task = nullptr);

  /**
   * Runs `filter` as a stage of this filter, its progress the slice [begin, end] of this
   * filter's. Returns its output, or null when it reported an error (`error`, as a
   * sentence), produced no points (`error` empty) or this filter was aborted. Its warnings
   * are appended to `warnings`.
   */
  vtkSmartPointer<vtkPolyData> RunInternalFilter(vtkPolyDataAlgorithm* filter, double begin,
    double end, std::string& error, std::vector<std::string>& warnings);

private:
  vtkMobiusPolyDataAlgorithm(const vtkMobiusPolyDataAlgorithm&) = delete;
  void operator=(const vtkMobiusPolyDataAlgorithm&) = delete;
};

#endif
