// VTK's own error and warning messages, taken over by mobius-register. Without this, a VTK
// class that nobody observes (an XML parser inside a reader, a renderer) prints coloured,
// timestamped, multi-line log entries straight to the terminal, past --quiet; a hostile
// file could make VTK's PLY reader print one per vertex, gigabytes of them.
#ifndef VTKMessages_h
#define VTKMessages_h

#include <string>
#include <vector>

/// Routes every message VTK prints (vtkOutputWindow and vtkLogger's standard error) into a
/// buffer for the rest of the program. Call once, first thing in main.
void CaptureVTKMessages();

/// The messages since the last call, one sentence each (VTK's file, line and object
/// prefixes dropped), each distinct sentence once, at most `limit` of them plus one saying
/// how many more were left out.
std::vector<std::string> TakeVTKMessages(std::size_t limit = 5);

#endif
