#include "vtkSurfaceMeshReader.h"

#include "MobiusFilterMessages.h"

#include "MobiusMeshFileChecks.h"
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
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLReader.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
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

// Next line that is neither empty nor a comment.
bool NextDataLine(std::istream& in, std::string& line)
{
  while (std::getline(in, line))
  {
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    if (line.find_first_not_of(" \t\r") != std::string::npos)
    {
      return true;
    }
  }
  return false;
}

// VTK's readers quote what they could not parse ("Unrecognized keyword: <the bytes>"): in a
// garbage file that is binary, with control characters, escape sequences and line breaks,
// and it would break the one-line message apart. Keeps printable ASCII, shows the rest as
// '?' (line breaks as spaces), and cuts the text short.
std::string PrintableLine(const std::string& text)
{
  const size_t longest = 300;
  std::string printable;
  for (size_t k = 0; k < text.size() && printable.size() < longest; ++k)
  {
    const auto c = static_cast<unsigned char>(text[k]);
    printable += (c >= 32 && c < 127) ? static_cast<char>(c) : std::isspace(c) ? ' ' : '?';
  }
  if (printable.size() < text.size())
  {
    printable += "...";
  }
  return printable;
}

// Parses an OFF file: "OFF" (or COFF/NOFF/CNOFF...) header, "V F E", V vertex lines and
// F face lines "n i_1 ... i_n [color]". Returns an empty string or the reason it failed.
std::string ReadOFF(const std::string& fileName, vtkPolyData* output)
{
  std::ifstream in(fileName);
  std::string line;
  if (!NextDataLine(in, line))
  {
    return "the file is empty";
  }
  std::istringstream header(line);
  std::string keyword;
  header >> keyword;
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    return "no OFF header";
  }
  long long numberOfVertices = -1, numberOfFaces = -1, numberOfEdges = 0;
  // The counts may follow the keyword on the same line.
  if (!(header >> numberOfVertices))
  {
    if (!NextDataLine(in, line))
    {
      return "missing vertex and face counts";
    }
    header.clear();
    header.str(line);
    header >> numberOfVertices;
  }
  header >> numberOfFaces >> numberOfEdges;
  if (numberOfVertices <= 0 || numberOfFaces < 0)
  {
    return "invalid vertex or face count in the header line '" + PrintableLine(line) + "'";
  }
  // The counts are allocated before the lines are read: they must be plausible for the
  // file's size, or a header of a few bytes could ask for gigabytes. A vertex line takes at
  // least 6 bytes ("0 0 0\n") and a face line 7 ("3 0 1 2"); the bound is looser, so that a
  // file merely cut short gets the more precise message of the line that is missing.
  const long long size =
    static_cast<long long>(std::ifstream(fileName, std::ios::binary | std::ios::ate).tellg());
  if (numberOfVertices > size / 4 || numberOfFaces > size / 4 ||
    numberOfVertices + numberOfFaces > size / 4)
  {
    std::ostringstream error;
    error << "the header claims " << numberOfVertices << " vertices and " << numberOfFaces
          << " faces, more than a file of " << size << " bytes can hold";
    return error.str();
  }

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfVertices);
  for (long long i = 0; i < numberOfVertices; ++i)
  {
    double p[3];
    std::string text[3];
    bool numeric = NextDataLine(in, line);
    std::istringstream fields(line);
    for (int k = 0; numeric && k < 3; ++k)
    {
      // strtod, not operator>>: it reads "nan", "inf" and overflowing numbers (as infinite),
      // which must be reported as what they are, not as a malformed line.
      char* end = nullptr;
      numeric = static_cast<bool>(fields >> text[k]) &&
        (p[k] = std::strtod(text[k].c_str(), &end), *end == '\0');
    }
    if (!numeric)
    {
      std::ostringstream error;
      error << "vertex " << i << " of " << numberOfVertices << " is missing or malformed";
      return error.str();
    }
    for (int k = 0; k < 3; ++k)
    {
      if (!std::isfinite(p[k]))
      {
        std::ostringstream error;
        error << "vertex " << i << " has a NaN or infinite coordinate '" << text[k] << "'";
        return error.str();
      }
    }
    points->SetPoint(i, p);
  }
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (long long f = 0; f < numberOfFaces; ++f)
  {
    long long n = 0;
    std::istringstream face;
    const bool present = NextDataLine(in, line);
    if (present)
    {
      face.str(line);
      face >> n;
    }
    const auto faceError = [&](const std::string& problem) {
      return "face " + std::to_string(f) + " of " + std::to_string(numberOfFaces) + problem;
    };
    if (!present)
    {
      return faceError(" is missing: the file ends before it");
    }
    // Each index takes at least two characters of the line: a count larger than that is
    // not allocated (one line "2000000000 0 1 2" would ask for 16 GB).
    if (n > static_cast<long long>(line.size()) / 2)
    {
      return faceError(" claims " + std::to_string(n) + " vertices, but its line lists fewer");
    }
    if (n < 3)
    {
      return faceError(" has " + std::to_string(n) + " vertices; a face needs at least 3");
    }
    ids.resize(static_cast<size_t>(n));
    for (auto& id : ids)
    {
      // Each index whole, so that "1.5" or a number past 64 bits is named, not misread.
      std::string token;
      if (!(face >> token))
      {
        return faceError(" lists fewer than the " + std::to_string(n) + " vertex indices it claims");
      }
      errno = 0;
      char* end = nullptr;
      const long long index = std::strtoll(token.c_str(), &end, 10);
      if (*end != '\0' || errno == ERANGE)
      {
        return faceError(" has an invalid vertex index '" + PrintableLine(token) + "'");
      }
      if (index < 0 || index >= numberOfVertices)
      {
        return faceError(" refers to vertex " + std::to_string(index) +
          ", out of range: the file has " + std::to_string(numberOfVertices) +
          " vertices (numbered from 0)");
      }
      id = static_cast<vtkIdType>(index);
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  return {};
}

// Parses the positions and faces of an OBJ file. VTK's OBJ reader is not used: with
// texture coordinates or normals it renumbers the points in order of first use in the faces
// (so vertex numbers no longer match the file), it turns a NaN coordinate into the previous
// vertex's, and index 0 or an index past the end corrupts its memory. Here point i is the
// file's i-th `v`; faces may use `v`, `v/vt`, `v//vn`, `v/vt/vn` and negative (relative)
// indices, and have any number (>= 3) of vertices; other statements (vt, vn, g, o, s, usemtl,
// l, p, ...) are skipped. Returns an empty string or the reason it failed.
std::string ReadOBJ(const std::string& fileName, vtkPolyData* output)
{
  std::ifstream in(fileName);
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  // Faces may name vertices defined further down: those are checked at the end.
  struct ForwardReference
  {
    vtkIdType Index;
    long long Face, Line;
  };
  std::vector<ForwardReference> forwardReferences;
  std::string line, statement;
  long long lineNumber = 0, faces = 0;
  while (std::getline(in, line))
  {
    ++lineNumber;
    // A backslash at the end continues the statement on the next line.
    while (!line.empty() && (line.back() == '\\' || line.back() == '\r'))
    {
      const bool continued = line.back() == '\\';
      line.pop_back();
      std::string next;
      if (continued && std::getline(in, next))
      {
        ++lineNumber;
        line += ' ' + next;
      }
    }
    const auto hash = line.find('#');
    if (hash != std::string::npos)
    {
      line.erase(hash);
    }
    std::istringstream fields(line);
    if (!(fields >> statement))
    {
      continue;
    }
    if (statement == "v")
    {
      const vtkIdType vertex = points->GetNumberOfPoints();
      double p[3];
      std::string text[3];
      for (int k = 0; k < 3; ++k)
      {
        char* end = nullptr;
        if (!(fields >> text[k]) || (p[k] = std::strtod(text[k].c_str(), &end), *end != '\0'))
        {
          std::ostringstream error;
          error << "vertex " << vertex << " (line " << lineNumber
                << ") does not have three numeric coordinates";
          return error.str();
        }
        if (!std::isfinite(p[k]))
        {
          std::ostringstream error;
          error << "vertex " << vertex << " (line " << lineNumber
                << ") has a NaN or infinite coordinate '" << text[k] << "'";
          return error.str();
        }
      }
      points->InsertNextPoint(p);
    }
    else if (statement == "f")
    {
      ids.clear();
      std::string corner;
      while (fields >> corner)
      {
        // The vertex index is the part before the first '/'.
        errno = 0;
        char* end = nullptr;
        const long long index = std::strtoll(corner.c_str(), &end, 10);
        const bool isNumber = end != corner.c_str() && (*end == '\0' || *end == '/');
        const long long defined = points->GetNumberOfPoints();
        // Relative indices count back from the last vertex defined so far.
        const long long absolute = index > 0 ? index - 1 : defined + index;
        if (!isNumber || errno == ERANGE || index == 0 || absolute < 0)
        {
          std::ostringstream error;
          error << "face " << faces << " (line " << lineNumber << ") has an invalid vertex index '"
                << PrintableLine(corner) << "'"
                << (isNumber && index == 0 ? " (OBJ numbers vertices from 1)"
                    : isNumber && index < 0
                    ? " (a negative index counts back from the last vertex defined before it)"
                    : "");
          return error.str();
        }
        ids.push_back(static_cast<vtkIdType>(absolute));
      }
      if (ids.size() < 3)
      {
        std::ostringstream error;
        error << "face " << faces << " (line " << lineNumber << ") has fewer than 3 vertices";
        return error.str();
      }
      const vtkIdType largest = *std::max_element(ids.begin(), ids.end());
      if (largest >= points->GetNumberOfPoints())
      {
        forwardReferences.push_back({ largest, faces, lineNumber });
      }
      polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
      ++faces;
    }
  }
  if (in.bad())
  {
    return "reading the file failed";
  }
  for (const auto& reference : forwardReferences)
  {
    if (reference.Index >= points->GetNumberOfPoints())
    {
      std::ostringstream error;
      error << "face " << reference.Face << " (line " << reference.Line << ") refers to vertex "
            << reference.Index + 1 << " (OBJ numbering), but the file has "
            << points->GetNumberOfPoints() << " vertices";
      return error.str();
    }
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  return {};
}

// The reason in a VTK error message as one printable line.
std::string VTKMessageReason(const std::string& message)
{
  return PrintableLine(mobius::vtk::MessageSentence(message));
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
  return PrintableLine(error);
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
  struct stat information;
  if (stat(fileName.c_str(), &information) != 0 || !std::ifstream(fileName))
  {
    vtkErrorMacro(<< fileName << ": cannot open the file for reading.");
    return 0;
  }
  // A directory opens as an empty stream, and a device such as /dev/zero never ends: the
  // parsers below would report nonsense or read forever.
  if (S_ISDIR(information.st_mode))
  {
    vtkErrorMacro(<< fileName << ": is a directory, not a mesh file.");
    return 0;
  }
  if (!S_ISREG(information.st_mode))
  {
    vtkErrorMacro(<< fileName << ": is not a regular file (a device, pipe or socket); "
                  << "save the mesh to a file first.");
    return 0;
  }
  const std::string extension = LowerCaseExtension(fileName);
  vtkNew<vtkPolyData> mesh;
  std::string error;
  if (extension == "off")
  {
    error = ReadOFF(fileName, mesh);
  }
  else if (extension == "obj")
  {
    error = ReadOBJ(fileName, mesh);
  }
  else
  {
    vtkSmartPointer<vtkAlgorithm> reader;
    if (extension == "ply")
    {
      // VTK's PLY reader looks up the points of each face as it reads: a bad index must be
      // found before it runs.
      error = mobius::vtk::CheckPLYFile(fileName);
      auto ply = vtkSmartPointer<vtkPLYReader>::New();
      ply->SetFileName(fileName.c_str());
      if (error.empty() && mobius::vtk::PLYNeedsFinalLineBreak(fileName))
      {
        // The data is complete (the check read all of it), only the line break is missing:
        // give the reader the text with one.
        std::ifstream file(fileName, std::ios::binary);
        std::ostringstream text;
        text << file.rdbuf() << '\n';
        ply->SetInputString(text.str());
        ply->ReadFromInputStringOn();
      }
      reader = ply;
    }
    else if (extension == "stl")
    {
      error = mobius::vtk::CheckSTLFile(fileName);
      auto stl = vtkSmartPointer<vtkSTLReader>::New();
      stl->SetFileName(fileName.c_str());
      reader = stl;
    }
    else if (extension == "vtp")
    {
      error = mobius::vtk::CheckVTKFileSizes(fileName, true);
      auto vtp = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      vtp->SetFileName(fileName.c_str());
      reader = vtp;
    }
    else if (extension == "vtk")
    {
      error = mobius::vtk::CheckVTKFileSizes(fileName, false);
      if (error.empty())
      {
        error = mobius::vtk::CheckLegacySections(fileName);
      }
      auto legacy = vtkSmartPointer<vtkPolyDataReader>::New();
      legacy->SetFileName(fileName.c_str());
      reader = legacy;
    }
    else
    {
      vtkErrorMacro(<< fileName << ": unknown mesh format '." << extension
                    << "' (supported: .obj, .off, .ply, .stl, .vtp, .vtk).");
      return 0;
    }
    if (error.empty())
    {
      error = ReadWithVTK(reader, mesh);
    }
    if (error.empty())
    {
      error = mobius::vtk::CheckCellPointIds(mesh);
    }
  }
  if (error.empty() && mesh->GetNumberOfPoints() == 0)
  {
    error = "the file holds no points";
  }
  if (!error.empty())
  {
    // One printable line whatever the file held (a header line quoted from a binary file).
    vtkErrorMacro(<< fileName << ": " << PrintableLine(error));
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
