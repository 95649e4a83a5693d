#include "VTKMessages.h"

#include "MobiusFilterMessages.h"

#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"

#include <algorithm>
#include <mutex>

namespace
{
// Messages are kept until taken; identical ones are counted, not stored, so a flood of
// them costs no memory.
struct Buffer
{
  std::mutex Lock;
  std::vector<std::string> Distinct;
  std::size_t Dropped = 0;
};

Buffer& Messages()
{
  static Buffer buffer;
  return buffer;
}
}

class vtkCapturedOutputWindow : public vtkOutputWindow
{
public:
  static vtkCapturedOutputWindow* New();
  vtkTypeMacro(vtkCapturedOutputWindow, vtkOutputWindow);

  // Each kind of message is taken over where it enters the window (the base class would
  // format it and print it).
  void DisplayErrorText(const char* text) override { Capture(text); }
  void DisplayWarningText(const char* text) override { Capture(text); }
  void DisplayGenericWarningText(const char* text) override { Capture(text); }
  // Plain text (PrintSelf and the like) and debug output are not messages to the user.
  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}

protected:
  vtkCapturedOutputWindow() = default;
  ~vtkCapturedOutputWindow() override = default;

private:
  static void Capture(const char* text);
};
vtkStandardNewMacro(vtkCapturedOutputWindow);

void vtkCapturedOutputWindow::Capture(const char* text)
{
  const std::string sentence = mobius::vtk::MessageSentence(text ? text : "");
  if (sentence.empty())
  {
    return;
  }
  Buffer& buffer = Messages();
  std::lock_guard<std::mutex> guard(buffer.Lock);
  if (std::find(buffer.Distinct.begin(), buffer.Distinct.end(), sentence) == buffer.Distinct.end())
  {
    if (buffer.Distinct.size() < 100)
    {
      buffer.Distinct.push_back(sentence);
    }
    else
    {
      ++buffer.Dropped;
    }
  }
}

void CaptureVTKMessages()
{
  vtkNew<vtkCapturedOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  // vtkLogger writes some messages to standard error by itself, bypassing the window.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

std::vector<std::string> TakeVTKMessages(std::size_t limit)
{
  Buffer& buffer = Messages();
  std::lock_guard<std::mutex> guard(buffer.Lock);
  std::vector<std::string> taken;
  taken.swap(buffer.Distinct);
  std::size_t more = buffer.Dropped;
  buffer.Dropped = 0;
  if (taken.size() > limit)
  {
    more += taken.size() - limit;
    taken.resize(limit);
  }
  if (more > 0)
  {
    taken.push_back("VTK reported " + std::to_string(more) + " more messages, not shown");
  }
  return taken;
}
