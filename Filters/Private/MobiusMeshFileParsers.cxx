#include "MobiusMeshFileParsers.h"

#include "vtkCellArray.h"
#include "vtkMergePoints.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace mobius
{
namespace vtk
{
std::string NormalizedText(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  std::string raw = bytes.str();
  const std::size_t start = raw.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  std::string text;
  text.reserve(raw.size() - start);
  for (std::size_t k = start; k < raw.size(); ++k)
  {
    if (raw[k] != '\r')
    {
      text += raw[k];
    }
    else if (k + 1 == raw.size() || raw[k + 1] != '\n')
    {
      text += '\n';
    }
  }
  return text;
}

namespace
{
// The tokens of an OFF file: '#' comments out the rest of its line. OFF is free-format, so
// Next crosses line breaks; NextOnLine and SkipLine serve the optional fields that end a
// line (a face's color, the edge count).
class OffTokens
{
public:
  explicit OffTokens(const std::string& text)
    : Text(text)
  {
  }
  bool Next(std::string& token)
  {
    while (!(this->Line >> token))
    {
      std::string line;
      if (!std::getline(this->Text, line))
      {
        return false;
      }
      const auto hash = line.find('#');
      if (hash != std::string::npos)
      {
        line.erase(hash);
      }
      this->Line.clear();
      this->Line.str(line);
      ++this->LineNumber;
    }
    return true;
  }
  bool NextOnLine(std::string& token) { return static_cast<bool>(this->Line >> token); }
  int TokensLeftOnLine()
  {
    const auto position = this->Line.tellg();
    int count = 0;
    for (std::string token; this->Line >> token;)
    {
      ++count;
    }
    this->Line.clear();
    this->Line.seekg(position);
    return count;
  }
  void SkipLine() { this->Line.str(std::string()); }
  long long LineNumber = 0;

private:
  std::istringstream Text, Line;
};

bool ParseReal(const std::string& token, double& value)
{
  char* end = nullptr;
  value = std::strtod(token.c_str(), &end); // reads nan, inf and overflow (as infinite)
  return end != token.c_str() && *end == '\0';
}

bool ParseInteger(const std::string& token, long long& value)
{
  errno = 0;
  char* end = nullptr;
  value = std::strtoll(token.c_str(), &end, 10);
  return end != token.c_str() && *end == '\0' && errno != ERANGE;
}

// The optional prefixes of an OFF keyword, in the specified order [ST][C][N][4][n]OFF.
struct OffHeader
{
  bool Homogeneous = false;       // 4: a fourth coordinate w divides the others
  bool Dimension = false;         // n: the dimension follows the keyword
};

bool ParseOffKeyword(const std::string& keyword, OffHeader& header)
{
  if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
  {
    return false;
  }
  std::string prefix = keyword.substr(0, keyword.size() - 3);
  const auto take = [&prefix](const char* part) {
    const std::string text(part);
    if (prefix.compare(0, text.size(), text) != 0)
    {
      return false;
    }
    prefix.erase(0, text.size());
    return true;
  };
  take("ST"); // texture coordinates, colors and normals follow the coordinates on their
  take("C");  // line, which ReadOffVertices skips
  take("N");
  header.Homogeneous = take("4");
  header.Dimension = take("n");
  return prefix.empty();
}

// How the vertices and faces are laid out over the lines.
enum class OffLayout
{
  // Each vertex and face starts a line and the rest of its last line is skipped: the fields
  // the header announces (ST, C, N), or fields it does not (a color some writers add to
  // plain OFF files, which are then still read right). Coordinates and indices may still run
  // over lines.
  ElementLines,
  // Token after token, wherever the lines break (all of a file on one line, several
  // vertices per line): OFF is free-format. Nothing may follow the last face.
  FreeFormat
};

// The vertices: coordinates may run over lines (free format); after them, in ElementLines,
// the rest of the line is skipped.
template <typename Next>
std::string ReadOffVertices(OffTokens& tokens, Next& next, const OffHeader& header,
  long long numberOfVertices, OffLayout layout, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfVertices);
  const int coordinates = header.Homogeneous ? 4 : 3;
  for (long long i = 0; i < numberOfVertices; ++i)
  {
    double p[4];
    std::string text[4];
    for (int k = 0; k < coordinates; ++k)
    {
      if (!next(text[k]) || !ParseReal(text[k], p[k]))
      {
        return "vertex " + std::to_string(i) + " of " + std::to_string(numberOfVertices) +
          " is missing or malformed";
      }
    }
    for (int k = 0; k < coordinates; ++k)
    {
      if (!std::isfinite(p[k]))
      {
        return "vertex " + std::to_string(i) + " has a NaN or infinite coordinate '" +
          PrintableLine(text[k]) + "'";
      }
    }
    if (header.Homogeneous)
    {
      if (p[3] == 0)
      {
        return "vertex " + std::to_string(i) + " has the homogeneous coordinate w = 0";
      }
      for (int k = 0; k < 3; ++k)
      {
        p[k] /= p[3];
      }
    }
    points->SetPoint(i, p);
    if (layout == OffLayout::ElementLines)
    {
      tokens.SkipLine();
    }
  }
  output->SetPoints(points);
  return {};
}

// The faces "n i_1 ... i_n [color]": in ElementLines, the indices on the count's line, or on
// the lines after it when the count stands alone (free format), and the rest of the last
// line is the color; in FreeFormat the n tokens after the count.
template <typename Next>
std::string ReadOffFaces(OffTokens& tokens, Next& next, long long numberOfVertices,
  long long numberOfFaces, long long textSize, OffLayout layout, vtkPolyData* output)
{
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  for (long long f = 0; f < numberOfFaces; ++f)
  {
    const auto faceError = [&](const std::string& problem) {
      return "face " + std::to_string(f) + " of " + std::to_string(numberOfFaces) + problem;
    };
    std::string token;
    long long n = 0;
    if (!next(token))
    {
      return faceError(" is missing: the file ends before it");
    }
    if (!ParseInteger(token, n))
    {
      return faceError(" does not start with its number of vertices but with '" +
        PrintableLine(token) + "'");
    }
    const int onLine = layout == OffLayout::ElementLines ? tokens.TokensLeftOnLine() : 0;
    // Not allocated beyond what the text can list (one line "2000000000 0 1 2" would ask
    // for 16 GB).
    if (onLine > 0 && n > onLine)
    {
      return faceError(" claims " + std::to_string(n) + " vertices, but its line lists fewer");
    }
    if (onLine == 0 && n > textSize / 2)
    {
      return faceError(" claims " + std::to_string(n) + " vertices, more than the file can list");
    }
    if (n < 3)
    {
      return faceError(" has " + std::to_string(n) + " vertices; a face needs at least 3");
    }
    ids.resize(static_cast<size_t>(n));
    for (auto& id : ids)
    {
      long long index = 0;
      if (!(onLine > 0 ? tokens.NextOnLine(token) : next(token)))
      {
        return faceError(" lists fewer than the " + std::to_string(n) + " vertex indices it claims");
      }
      // Each index whole, so that "1.5" or a number past 64 bits is named, not misread.
      if (!ParseInteger(token, index))
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
    if (layout == OffLayout::ElementLines)
    {
      tokens.SkipLine();
    }
    polys->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  std::string rest;
  if (layout == OffLayout::FreeFormat && next(rest))
  {
    return "'" + PrintableLine(rest) + "' follows the last face";
  }
  output->SetPolys(polys);
  return {};
}
}

namespace
{
// The OFF file's text read with the layout given.
std::string ReadOffText(const std::string& text, OffLayout layout, vtkPolyData* output)
{
  OffTokens tokens(text);
  std::string keyword, pending;
  if (!tokens.Next(keyword))
  {
    return "the file is empty";
  }
  // "OFF490 518 0": the counts' line joined to the keyword's (ModelNet's files).
  if (keyword.size() > 3 && keyword.compare(0, 3, "OFF") == 0 &&
    std::all_of(keyword.begin() + 3, keyword.end(), [](unsigned char c) { return std::isdigit(c); }))
  {
    pending = keyword.substr(3);
    keyword.resize(3);
  }
  OffHeader header;
  if (!ParseOffKeyword(keyword, header))
  {
    return "no OFF header: the file starts with '" + PrintableLine(keyword) + "'";
  }
  if (pending.empty() && tokens.NextOnLine(pending) && pending == "BINARY")
  {
    return "binary OFF ('" + PrintableLine(keyword) +
      " BINARY') is not supported: save the mesh as ASCII OFF, PLY or STL";
  }
  // The first count (or the dimension) may follow the keyword on its line.
  const auto next = [&](std::string& token) {
    if (pending.empty())
    {
      return tokens.Next(token);
    }
    token = std::move(pending);
    pending.clear();
    return true;
  };
  std::string field;
  long long dimension = 3;
  if (header.Dimension && !(next(field) && ParseInteger(field, dimension)))
  {
    return "the nOFF header has no dimension after its keyword";
  }
  if (dimension != 3)
  {
    return "the nOFF file's vertices have " + std::to_string(dimension) +
      " coordinates; only surfaces in 3 dimensions can be mapped";
  }
  long long numberOfVertices = -1, numberOfFaces = -1;
  std::string counts[2];
  if (!next(counts[0]))
  {
    return "missing vertex and face counts";
  }
  const long long countsLine = tokens.LineNumber;
  if (!next(counts[1]) || !ParseInteger(counts[0], numberOfVertices) ||
    !ParseInteger(counts[1], numberOfFaces) || numberOfVertices <= 0 || numberOfFaces < 0)
  {
    return "invalid vertex or face count in the header '" + PrintableLine(counts[0] + " " + counts[1]) + "'";
  }
  // The edge count (unused) ends the counts' line, or is on a line of its own when the
  // counts are spread over lines.
  if (tokens.LineNumber != countsLine || tokens.TokensLeftOnLine() > 0)
  {
    next(field);
  }
  // The counts are allocated before the data is read: they must be plausible for the file's
  // size, or a header of a few bytes could ask for gigabytes. A vertex takes at least 6
  // bytes ("0 0 0\n") and a face 7 ("3 0 1 2"); the bound is looser, so that a file merely
  // cut short gets the more precise message of what is missing.
  const auto size = static_cast<long long>(text.size());
  if (numberOfVertices > size / 4 || numberOfFaces > size / 4 ||
    numberOfVertices + numberOfFaces > size / 4)
  {
    std::ostringstream error;
    error << "the header claims " << numberOfVertices << " vertices and " << numberOfFaces
          << " faces, more than a file of " << size << " bytes can hold";
    return error.str();
  }
  std::string error = ReadOffVertices(tokens, next, header, numberOfVertices, layout, output);
  return error.empty()
    ? ReadOffFaces(tokens, next, numberOfVertices, numberOfFaces, size, layout, output)
    : error;
}
}

std::string ReadOFF(const std::string& fileName, vtkPolyData* output)
{
  const std::string text = NormalizedText(fileName);
  // A line per vertex and per face first: what most writers write, extra fields at the lines'
  // ends included. A file that cannot be read so (all of it on one line, several vertices per
  // line) is read token by token, as OFF's free format allows, when that reads every token of
  // it; otherwise the first reading's reason stands.
  const std::string error = ReadOffText(text, OffLayout::ElementLines, output);
  if (error.empty())
  {
    return error;
  }
  vtkNew<vtkPolyData> freeFormat;
  if (!ReadOffText(text, OffLayout::FreeFormat, freeFormat).empty())
  {
    return error;
  }
  output->ShallowCopy(freeFormat);
  return {};
}

namespace
{
void StripComment(std::string& line)
{
  const auto hash = line.find('#');
  if (hash != std::string::npos)
  {
    line.erase(hash);
  }
}

// The next statement of an OBJ file in `line`, without its comments; false at the end of the
// file. A backslash at the end continues the statement on the next line; a comment ends at
// the end of its line, whatever its last character (it must not swallow the next `v`).
bool NextOBJStatement(std::istream& in, std::string& line, long long& lineNumber)
{
  if (!std::getline(in, line))
  {
    return false;
  }
  ++lineNumber;
  StripComment(line);
  while (!line.empty() && line.back() == '\\')
  {
    line.pop_back();
    std::string next;
    if (std::getline(in, next))
    {
      ++lineNumber;
      StripComment(next);
      line += ' ' + next;
    }
  }
  return true;
}

// The coordinates of vertex `vertex` from the rest of its `v` statement; the problem if it
// does not have three finite numbers.
std::string ReadOBJVertex(
  std::istringstream& fields, vtkIdType vertex, long long lineNumber, double p[3])
{
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
  return {};
}

// The point ids of face `face` from the rest of its `f` statement, `defined` vertices being
// defined before it; the problem if an index names no vertex or there are fewer than 3.
std::string ReadOBJFace(std::istringstream& fields, long long face, long long lineNumber,
  long long defined, std::vector<vtkIdType>& ids)
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
    // Relative indices count back from the last vertex defined so far.
    const long long absolute = index > 0 ? index - 1 : defined + index;
    if (!isNumber || errno == ERANGE || index == 0 || absolute < 0)
    {
      std::ostringstream error;
      error << "face " << face << " (line " << lineNumber << ") has an invalid vertex index '"
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
    error << "face " << face << " (line " << lineNumber << ") has fewer than 3 vertices";
    return error.str();
  }
  return {};
}

// A face naming a vertex not defined before it: checked once the file is read.
struct ForwardReference
{
  vtkIdType Index;
  long long Face, Line;
};

// The first face naming a vertex the file does not define, as the problem; empty if none.
std::string CheckForwardReferences(
  const std::vector<ForwardReference>& references, vtkIdType vertices)
{
  for (const auto& reference : references)
  {
    if (reference.Index >= vertices)
    {
      std::ostringstream error;
      error << "face " << reference.Face << " (line " << reference.Line << ") refers to vertex "
            << reference.Index + 1 << " (OBJ numbering), but the file has " << vertices
            << " vertices";
      return error.str();
    }
  }
  return {};
}
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
  std::istringstream in(NormalizedText(fileName));
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  vtkNew<vtkCellArray> polys;
  std::vector<vtkIdType> ids;
  // Faces may name vertices defined further down: those are checked at the end.
  std::vector<ForwardReference> forwardReferences;
  std::string line, statement, error;
  long long lineNumber = 0, faces = 0;
  while (NextOBJStatement(in, line, lineNumber))
  {
    std::istringstream fields(line);
    if (!(fields >> statement))
    {
      continue;
    }
    if (statement == "v")
    {
      double p[3];
      error = ReadOBJVertex(fields, points->GetNumberOfPoints(), lineNumber, p);
      if (!error.empty())
      {
        return error;
      }
      points->InsertNextPoint(p);
    }
    else if (statement == "f")
    {
      error = ReadOBJFace(fields, faces, lineNumber, points->GetNumberOfPoints(), ids);
      if (!error.empty())
      {
        return error;
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
  error = CheckForwardReferences(forwardReferences, points->GetNumberOfPoints());
  if (!error.empty())
  {
    return error;
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  return {};
}


namespace
{
// Triangles (corners 3t, 3t + 1, 3t + 2) with their corners merged where their coordinates
// are equal, in the order they come, and the triangles that merging collapses dropped: as
// VTK's STL reader builds its output (with its default locator, vtkMergePoints).
void MergeTriangleCorners(vtkPoints* corners, vtkPolyData* output)
{
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> triangles;
  vtkNew<vtkMergePoints> locator;
  double bounds[6];
  corners->GetBounds(bounds);
  locator->InitPointInsertion(points, bounds);
  for (vtkIdType t = 0; 3 * t + 2 < corners->GetNumberOfPoints(); ++t)
  {
    vtkIdType ids[3];
    for (int k = 0; k < 3; ++k)
    {
      locator->InsertUniquePoint(corners->GetPoint(3 * t + k), ids[k]);
    }
    if (ids[0] != ids[1] && ids[0] != ids[2] && ids[1] != ids[2])
    {
      triangles->InsertNextCell(3, ids);
    }
  }
  output->SetPoints(points);
  output->SetPolys(triangles);
}
}

std::string ReadBinarySTL(const std::string& fileName, long long count, vtkPolyData* output)
{
  std::ifstream in(fileName, std::ios::binary);
  in.seekg(84);
  vtkNew<vtkPoints> corners; // float, as in the file
  corners->SetNumberOfPoints(3 * count);
  char facet[50];
  for (long long t = 0; t < count; ++t)
  {
    if (!in.read(facet, sizeof facet))
    {
      return "the file ends inside triangle " + std::to_string(t);
    }
    for (int k = 0; k < 3; ++k)
    {
      float xyz[3]; // little-endian in the file, as VTK's reader assumes of the host
      std::memcpy(xyz, facet + 12 * (k + 1), sizeof xyz);
      corners->SetPoint(3 * t + k, xyz[0], xyz[1], xyz[2]);
    }
  }
  MergeTriangleCorners(corners, output);
  return {};
}

bool IsAsciiSTL(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary | std::ios::ate);
  const auto size = static_cast<long long>(in.tellg());
  in.seekg(0);
  std::string head(static_cast<std::size_t>(std::max(0LL, std::min(size, 512LL))), '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  if (size >= 84)
  {
    const auto byte = [&head](int k) { return static_cast<long long>(static_cast<unsigned char>(head[k])); };
    const long long triangles = byte(80) | (byte(81) << 8) | (byte(82) << 16) | (byte(83) << 24);
    if (size == 84 + 50 * triangles)
    {
      return false;
    }
  }
  std::size_t start = head.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0;
  while (start < head.size() && std::isspace(static_cast<unsigned char>(head[start])))
  {
    ++start;
  }
  std::string keyword = head.substr(start, 5);
  std::transform(keyword.begin(), keyword.end(), keyword.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return keyword == "solid";
}

namespace
{
std::string Lower(std::string word)
{
  std::transform(word.begin(), word.end(), word.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return word;
}

// The corners of an ASCII STL file's triangles, three per facet, as floats (as VTK's reader
// and the binary format keep them). Empty string, or what is wrong and where.
std::string ReadAsciiSTLCorners(const std::string& fileName, std::vector<float>& corners)
{
  std::istringstream in(NormalizedText(fileName));
  std::string word;
  long long facet = 0;
  const auto expected = [&](const std::string& what, const std::string& found) {
    return "facet " + std::to_string(facet) + ": expected " + what + ", found " +
      (found.empty() ? std::string("the end of the file") : "'" + PrintableLine(found) + "'");
  };
  while (in >> word)
  {
    const std::string keyword = Lower(word);
    if (keyword == "solid" || keyword == "endsolid")
    {
      std::getline(in, word); // the solid's name, any text
      continue;
    }
    if (keyword != "facet")
    {
      return expected("'facet', 'solid' or 'endsolid'", word);
    }
    std::string text[3];
    if (!(in >> word) || Lower(word) != "normal" || !(in >> text[0] >> text[1] >> text[2]))
    {
      return expected("'normal' and three numbers", word);
    }
    if (!(in >> word) || Lower(word) != "outer" || !(in >> word) || Lower(word) != "loop")
    {
      return expected("'outer loop'", word);
    }
    for (int corner = 0; corner < 3; ++corner)
    {
      word.clear();
      if (!(in >> word) || Lower(word) != "vertex" || !(in >> text[0] >> text[1] >> text[2]))
      {
        return expected("'vertex' and three coordinates", word);
      }
      for (const std::string& coordinate : text)
      {
        char* end = nullptr;
        const float value = std::strtof(coordinate.c_str(), &end);
        if (end == coordinate.c_str() || *end != '\0')
        {
          return expected("a coordinate", coordinate);
        }
        if (!std::isfinite(value))
        {
          return "facet " + std::to_string(facet) + " has a NaN or infinite coordinate '" +
            PrintableLine(coordinate) + "'";
        }
        corners.push_back(value);
      }
    }
    word.clear();
    if (!(in >> word) || Lower(word) != "endloop" || !(in >> word) || Lower(word) != "endfacet")
    {
      return expected("'endloop' and 'endfacet' (an STL facet is a triangle)", word);
    }
    ++facet;
  }
  return {};
}
}

std::string ReadAsciiSTL(const std::string& fileName, vtkPolyData* output)
{
  std::vector<float> corners;
  const std::string error = ReadAsciiSTLCorners(fileName, corners);
  if (!error.empty())
  {
    return error;
  }
  if (corners.empty())
  {
    return "the file holds no triangles";
  }
  vtkNew<vtkPoints> all;
  all->SetNumberOfPoints(static_cast<vtkIdType>(corners.size() / 3));
  for (vtkIdType k = 0; k < all->GetNumberOfPoints(); ++k)
  {
    all->SetPoint(k, corners[3 * k], corners[3 * k + 1], corners[3 * k + 2]);
  }
  MergeTriangleCorners(all, output);
  return {};
}

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
}
}
