/**
 * @file MobiusFilterMessages.h
 * @brief Running a VTK filter and catching its messages, instead of letting VTK print them.
 *
 * The module's filters, the command-line tools and the benchmarks all run filters whose
 * errors they report in their own words: one filter inside another (vtkSymmetryDetection's
 * stages), a reader whose message names the file (mobius-register), a pipeline stage
 * (RegistrationPipeline). This is the one place that observes a filter's messages and
 * turns VTK's text into the sentence the user reads.
 */
#ifndef MobiusFilterMessages_h
#define MobiusFilterMessages_h

#include "vtkMobiusRegistrationFiltersModule.h" // For export macro
#include "vtkNew.h"                             // For the observers
#include "vtkSmartPointer.h"                    // For the observed filter

#include <string> // For the messages
#include <vector> // For the warnings

class vtkAlgorithm;
class vtkCallbackCommand;

namespace mobius
{
namespace vtk
{
/// A VTK message as one sentence: without the "ERROR: In file, line n" line and the
/// "vtkClass (0x...): " prefix, line breaks as spaces, no trailing space.
VTKMOBIUSREGISTRATIONFILTERS_EXPORT std::string MessageSentence(const std::string& text);

/// Catches the error and warning messages of `filter` from construction to destruction
/// (run the filter in between). The executive's own error ("Algorithm ... returned
/// failure"), which repeats the filter's, is caught apart. Without `catchWarnings` the
/// warnings go on to VTK's output window (a program that captures it shows them).
class VTKMOBIUSREGISTRATIONFILTERS_EXPORT FilterMessages
{
public:
  explicit FilterMessages(vtkAlgorithm* filter, bool catchWarnings = true);
  ~FilterMessages();
  FilterMessages(const FilterMessages&) = delete;
  FilterMessages& operator=(const FilterMessages&) = delete;

  /// The first error, as MessageSentence makes it; empty when there was none.
  std::string Error;
  /// The executive's first error, which says less than the filter's (MessageSentence).
  std::string ExecutiveError;
  /// Every warning, in order (MessageSentence), when caught.
  std::vector<std::string> Warnings;

private:
  vtkSmartPointer<vtkAlgorithm> Filter;
  vtkNew<vtkCallbackCommand> Messages;
  vtkNew<vtkCallbackCommand> ExecutiveMessages;
  unsigned long ErrorTag, ExecutiveTag;
  unsigned long WarningTag = 0;
};
}
}

#endif
