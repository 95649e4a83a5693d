#include "vtkSurfaceMeshReader.h"

#include "MobiusFilterMessages.h"

#include "MobiusMeshFileChecks.h"
#include "MobiusMeshFileParsers.h"
#include "MobiusSphericalMapData.h"

#include "vtkCellArray.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPLYReader.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSTLReader.h"
#include "vtkSmartPointer.h"
#include "vtkXMLDataElement.h"
#include "vtkXMLDataParser.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLReader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <sys/stat.h>
#include <vector>

vtkStandardNewMacro(vtkSurfaceMeshReader);

namespace
{
std::string LowerCaseExtension(const std::string& fileName)
{
  const auto dot = fileName.find_last_of('.');
  if (dot == std::string::npos)
  {
    return {};
  }
  std::string extension = fileName.substr(dot + 1);
  std::transform(extension.begin(), extension.end(), extension.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The reason in a VTK error message as one printable line.
std::string VTKMessageReason(const std::string& message)
{
  return mobius::vtk::PrintableLine(mobius::vtk::MessageSentence(message));
}

// An observer keeping the first message it sees in `message`.
vtkSmartPointer<vtkCallbackCommand> FirstMessageCatcher(std::string* message)
{
  auto catcher = vtkSmartPointer<vtkCallbackCommand>::New();
  catcher->SetClientData(message);
  catcher->SetCallback([](vtkObject*, unsigned long, void* clientData, void* callData) {
    auto first = static_cast<std::string*>(clientData);
    if (first->empty() && callData)
    {
      *first = static_cast<const char*>(callData);
    }
  });
  return catcher;
}

// Fails when a piece's points array in a parsed VTK XML file does not have 3 components.
// VTK 9.2's XML reader refuses such an array (a missing NumberOfComponents means 1), reads
// the coordinates anyway and leaks them (found by the fuzzer). The attribute is taken from
// the parsed elements, as the reader takes it: a search of the text for it was fooled by a
// longer attribute name ending in it.
std::string CheckXMLPointsComponents(vtkXMLReader* reader)
{
  vtkXMLDataParser* parser = reader->GetXMLParser();
  vtkXMLDataElement* root = parser ? parser->GetRootElement() : nullptr;
  vtkXMLDataElement* polyData = root ? root->FindNestedElementWithName("PolyData") : nullptr;
  for (int p = 0; polyData && p < polyData->GetNumberOfNestedElements(); ++p)
  {
    vtkXMLDataElement* piece = polyData->GetNestedElement(p);
    const char* name = piece->GetName();
    vtkXMLDataElement* points = name && std::strcmp(name, "Piece") == 0
      ? piece->FindNestedElementWithName("Points")
      : nullptr;
    for (int a = 0; points && a < points->GetNumberOfNestedElements(); ++a)
    {
      int components = 1;
      points->GetNestedElement(a)->GetScalarAttribute("NumberOfComponents", components);
      if (components != 3)
      {
        std::ostringstream message;
        message << "the points' data array in piece " << p << " has " << components
                << (components == 1 ? " component" : " components")
                << " per point (NumberOfComponents), not 3";
        return message.str();
      }
    }
  }
  return {};
}

// Runs a VTK reader, turning its error events into our message.
std::string ReadWithVTK(vtkAlgorithm* reader, vtkPolyData* output)
{
  mobius::vtk::FilterMessages messages(reader, /*catchWarnings=*/false);
  // The XML reader's own message for a file it cannot parse is "Error parsing input file.
  // ReadXMLInformation aborting.": the parser's (line, column and what is wrong) says more.
  std::string parserError;
  auto parserCatcher = FirstMessageCatcher(&parserError);
  if (auto xml = vtkXMLReader::SafeDownCast(reader))
  {
    xml->SetParserErrorObserver(parserCatcher);
    xml->UpdateInformation();
    if (messages.Error.empty() && messages.ExecutiveError.empty())
    {
      const std::string components = CheckXMLPointsComponents(xml);
      if (!components.empty())
      {
        return components;
      }
    }
  }
  reader->Update();
  // The executive's "returned failure" only when the reader said nothing itself.
  const std::string error = messages.Error.empty() ? messages.ExecutiveError : messages.Error;
  auto result = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (error.empty() && result)
  {
    output->ShallowCopy(result);
  }
  if (!error.empty() && !parserError.empty())
  {
    return "the VTK XML file cannot be parsed: " + VTKMessageReason(parserError);
  }
  return mobius::vtk::PrintableLine(error);
}

// Why `fileName` cannot be read as a mesh file, found before it is read; empty if it can.
// A directory opens as an empty stream, and a device such as /dev/zero never ends: the
// parsers would report nonsense or read forever. Checked before the file is opened:
// opening a FIFO waits for a writer, possibly forever.
std::string FileProblem(const std::string& fileName)
{
  struct stat information;
  if (stat(fileName.c_str(), &information) != 0)
  {
    return "cannot open the file for reading.";
  }
  if (S_ISDIR(information.st_mode))
  {
    return "is a directory, not a mesh file.";
  }
  if (!S_ISREG(information.st_mode))
  {
    return "is not a regular file (a device, pipe or socket); save the mesh to a file first.";
  }
  if (!std::ifstream(fileName))
  {
    return "cannot open the file for reading.";
  }
  if (!vtkSurfaceMeshReader::IsSupportedFile(fileName.c_str()))
  {
    return "unknown mesh format '." + LowerCaseExtension(fileName) +
      "' (supported: .obj, .off, .ply, .stl, .vtp, .vtk).";
  }
  return {};
}

std::string ReadPLY(const std::string& fileName, vtkPolyData* mesh)
{
  // VTK's PLY reader looks up the points of each face as it reads: a bad index must be
  // found before it runs.
  const std::string error = mobius::vtk::CheckPLYFile(fileName);
  if (!error.empty())
  {
    return error;
  }
  vtkNew<vtkPLYReader> ply;
  ply->SetFileName(fileName.c_str());
  const std::string readable = mobius::vtk::ReadablePLYText(fileName);
  if (!readable.empty())
  {
    ply->SetInputString(readable);
    ply->ReadFromInputStringOn();
  }
  return ReadWithVTK(ply, mesh);
}

std::string ReadSTL(vtkSurfaceMeshReader* filter, const std::string& fileName, vtkPolyData* mesh)
{
  if (mobius::vtk::IsAsciiSTL(fileName))
  {
    // VTK's reader takes text that does not start with exactly "solid" (a byte-order
    // mark, a blank line, "SOLID") for a binary file, and refuses long solid names.
    return mobius::vtk::ReadAsciiSTL(fileName, mesh);
  }
  long long triangles = 0, trailingBytes = 0;
  const std::string error = mobius::vtk::CheckSTLFile(fileName, triangles, trailingBytes);
  if (!error.empty())
  {
    return error;
  }
  if (trailingBytes > 0)
  {
    // VTK's reader would take the bytes after the header's triangles for triangles too.
    vtkWarningWithObjectMacro(filter, << fileName << ": " << trailingBytes
                                      << " bytes after the " << triangles
                                      << " triangles the header counts are ignored.");
    return mobius::vtk::ReadBinarySTL(fileName, triangles, mesh);
  }
  vtkNew<vtkSTLReader> stl;
  stl->SetFileName(fileName.c_str());
  return ReadWithVTK(stl, mesh);
}

std::string ReadVTP(const std::string& fileName, vtkPolyData* mesh)
{
  const std::string error = mobius::vtk::CheckVTKFileSizes(fileName, true);
  if (!error.empty())
  {
    return error;
  }
  vtkNew<vtkXMLPolyDataReader> vtp;
  vtp->SetFileName(fileName.c_str());
  return ReadWithVTK(vtp, mesh);
}

std::string ReadLegacyVTK(const std::string& fileName, vtkPolyData* mesh)
{
  std::string error = mobius::vtk::CheckVTKFileSizes(fileName, false);
  if (error.empty())
  {
    error = mobius::vtk::CheckLegacySections(fileName);
  }
  if (!error.empty())
  {
    return error;
  }
  vtkNew<vtkPolyDataReader> legacy;
  legacy->SetFileName(fileName.c_str());
  return ReadWithVTK(legacy, mesh);
}

// The mesh in `fileName` (of a supported format); the problem if it cannot be read. OFF and
// OBJ are parsed here; the others through VTK's readers (or our own where theirs fail), and
// their cells checked against the points.
std::string ReadMeshFile(vtkSurfaceMeshReader* filter, const std::string& fileName, vtkPolyData* mesh)
{
  const std::string extension = LowerCaseExtension(fileName);
  std::string error;
  if (extension == "off" || extension == "obj")
  {
    error = extension == "off" ? mobius::vtk::ReadOFF(fileName, mesh)
                               : mobius::vtk::ReadOBJ(fileName, mesh);
  }
  else
  {
    error = extension == "ply" ? ReadPLY(fileName, mesh)
      : extension == "stl"     ? ReadSTL(filter, fileName, mesh)
      : extension == "vtp"     ? ReadVTP(fileName, mesh)
                               : ReadLegacyVTK(fileName, mesh);
    if (error.empty())
    {
      error = mobius::vtk::CheckCellPointIds(mesh);
    }
  }
  if (error.empty() && mesh->GetNumberOfPoints() == 0)
  {
    error = "the file holds no points";
  }
  return error;
}
}

//------------------------------------------------------------------------------
vtkSurfaceMeshReader::vtkSurfaceMeshReader()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
vtkSurfaceMeshReader::~vtkSurfaceMeshReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkSurfaceMeshReader::IsSupportedFile(const char* fileName)
{
  static const char* supported[] = { "obj", "off", "ply", "stl", "vtp", "vtk" };
  const std::string extension = LowerCaseExtension(fileName ? fileName : "");
  return std::find(std::begin(supported), std::end(supported), extension) != std::end(supported);
}

//------------------------------------------------------------------------------
int vtkSurfaceMeshReader::ComputeOutput(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  const std::string fileName = this->FileName ? this->FileName : "";
  if (fileName.empty())
  {
    vtkErrorMacro(<< "No file name given.");
    return 0;
  }
  const std::string problem = FileProblem(fileName);
  if (!problem.empty())
  {
    vtkErrorMacro(<< fileName << ": " << problem);
    return 0;
  }
  vtkNew<vtkPolyData> mesh;
  const std::string error = ReadMeshFile(this, fileName, mesh);
  if (!error.empty())
  {
    // One printable line whatever the file held (a header line quoted from a binary file).
    vtkErrorMacro(<< fileName << ": " << mobius::vtk::PrintableLine(error));
    return 0;
  }
  output->ShallowCopy(mesh);
  return 1;
}

//------------------------------------------------------------------------------
void vtkSurfaceMeshReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
