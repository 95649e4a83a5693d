#include "MobiusFilterMessages.h"

#include "vtkAlgorithm.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"

#include <algorithm>

namespace mobius
{
namespace vtk
{
std::string MessageSentence(const std::string& message)
{
  std::string text = message;
  // vtkErrorMacro's "ERROR: In /path/file.cxx, line 12\n" (or "Warning: In ...").
  const auto firstBreak = text.find('\n');
  if (firstBreak != std::string::npos && text.find(": In ") < firstBreak &&
    text.find(", line ") < firstBreak)
  {
    text = text.substr(firstBreak + 1);
  }
  // "vtkClass (0x1234): " before the reason.
  const auto object = text.find("): ");
  if (object != std::string::npos && object < text.find('\n'))
  {
    text = text.substr(object + 3);
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' '))
  {
    text.pop_back();
  }
  std::replace(text.begin(), text.end(), '\n', ' ');
  return text;
}

namespace
{
void Catch(vtkObject*, unsigned long event, void* clientData, void* callData)
{
  auto messages = static_cast<FilterMessages*>(clientData);
  const std::string text = MessageSentence(callData ? static_cast<const char*>(callData) : "");
  if (event == vtkCommand::ErrorEvent)
  {
    if (messages->Error.empty())
    {
      messages->Error = text;
    }
  }
  else
  {
    messages->Warnings.push_back(text);
  }
}

void CatchExecutive(vtkObject*, unsigned long, void* clientData, void* callData)
{
  auto messages = static_cast<FilterMessages*>(clientData);
  if (messages->ExecutiveError.empty())
  {
    messages->ExecutiveError = MessageSentence(callData ? static_cast<const char*>(callData) : "");
  }
}
}

FilterMessages::FilterMessages(vtkAlgorithm* filter, bool catchWarnings)
  : Filter(filter)
{
  this->Messages->SetClientData(this);
  this->Messages->SetCallback(Catch);
  this->ExecutiveMessages->SetClientData(this);
  this->ExecutiveMessages->SetCallback(CatchExecutive);
  this->ErrorTag = filter->AddObserver(vtkCommand::ErrorEvent, this->Messages);
  if (catchWarnings)
  {
    this->WarningTag = filter->AddObserver(vtkCommand::WarningEvent, this->Messages);
  }
  this->ExecutiveTag =
    filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveMessages);
}

FilterMessages::~FilterMessages()
{
  this->Filter->RemoveObserver(this->ErrorTag);
  if (this->WarningTag)
  {
    this->Filter->RemoveObserver(this->WarningTag);
  }
  this->Filter->GetExecutive()->RemoveObserver(this->ExecutiveTag);
}
}
}
