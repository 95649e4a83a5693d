// Catching a filter's messages (MobiusFilterMessages.h): VTK's text becomes the sentence the
// user reads, the first error is kept and every warning (unless they are left to VTK), the
// executive's repetition is kept apart, and the observers leave with the catcher.
#include "MobiusFilterMessages.h"
#include "vtkSurfaceMeshReader.h"

#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkNew.h"

#include <cstdlib>
#include <iostream>
#include <string>

namespace
{
int Expect(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << std::endl;
    return 1;
  }
  return 0;
}

int TestSentences()
{
  using mobius::vtk::MessageSentence;
  int failures = 0;
  const std::string error =
    "ERROR: In /src/vtkFoo.cxx, line 12\nvtkFoo (0x55d0): The reason (see a): b.\n\n";
  failures += Expect(MessageSentence(error) == "The reason (see a): b.",
    "an error's sentence, its own \"): \" kept: '" + MessageSentence(error) + "'");
  const std::string generic =
    "Generic Warning: In /src/x.cxx, line 3\nA warning\non two lines\n\n";
  failures += Expect(MessageSentence(generic) == "A warning on two lines",
    "a generic warning as one line: '" + MessageSentence(generic) + "'");
  failures += Expect(MessageSentence("plain text  \n") == "plain text", "plain text trimmed");
  return failures;
}

int TestReaderMessages()
{
  int failures = 0;
  const std::string path = "/nonexistent/folder/mesh.off";
  vtkNew<vtkSurfaceMeshReader> reader;
  reader->SetFileName(path.c_str());
  {
    mobius::vtk::FilterMessages messages(reader);
    vtkWarningWithObjectMacro(reader, << "first warning");
    vtkWarningWithObjectMacro(reader, << "second warning");
    reader->Update();
    failures += Expect(messages.Error.compare(0, path.size(), path) == 0,
      "the reader's error starts with the file name: '" + messages.Error + "'");
    failures += Expect(messages.Error.find("ERROR") == std::string::npos &&
        messages.Error.find("vtkSurfaceMeshReader (") == std::string::npos,
      "no VTK prefixes in the error: '" + messages.Error + "'");
    failures += Expect(messages.Warnings.size() == 2 && messages.Warnings[0] == "first warning" &&
        messages.Warnings[1] == "second warning",
      "both warnings, in order");
    failures += Expect(
      !messages.ExecutiveError.empty() && messages.ExecutiveError != messages.Error,
      "the executive's error kept apart: '" + messages.ExecutiveError + "'");
  }
  {
    // A program that shows VTK's warnings itself (mobius-register) leaves them to it.
    mobius::vtk::FilterMessages errorsOnly(reader, /*catchWarnings=*/false);
    failures += Expect(reader->HasObserver(vtkCommand::ErrorEvent) &&
        !reader->HasObserver(vtkCommand::WarningEvent),
      "errors only: the warnings are not observed");
  }
  failures += Expect(!reader->HasObserver(vtkCommand::ErrorEvent) &&
      !reader->HasObserver(vtkCommand::WarningEvent) &&
      !reader->GetExecutive()->HasObserver(vtkCommand::ErrorEvent),
    "the observers leave with the catcher");
  return failures;
}
}

int TestFilterMessages(int, char*[])
{
  const int failures = TestSentences() + TestReaderMessages();
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
