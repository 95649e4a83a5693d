#include "MobiusMeshFileChecks.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <climits>
#include <cstring>
#include <fstream>
#include <sstream>
#include <vector>

namespace mobius
{
namespace vtk
{
namespace
{
struct ScalarType
{
  int Size = 0; // bytes in the binary encodings; 0: unknown type name
  bool IsInteger = false;
  bool IsSigned = false;
};

ScalarType ParseScalarType(const std::string& name)
{
  if (name == "char" || name == "int8")
    return { 1, true, true };
  if (name == "uchar" || name == "uint8")
    return { 1, true, false };
  if (name == "short" || name == "int16")
    return { 2, true, true };
  if (name == "ushort" || name == "uint16")
    return { 2, true, false };
  if (name == "int" || name == "int32")
    return { 4, true, true };
  if (name == "uint" || name == "uint32")
    return { 4, true, false };
  if (name == "float" || name == "float32")
    return { 4, false, true };
  if (name == "double" || name == "float64")
    return { 8, false, true };
  return {};
}

struct Property
{
  std::string Name;
  bool IsList = false;
  ScalarType CountType, ValueType;
};

struct Element
{
  std::string Name;
  long long Count = 0;
  std::vector<Property> Properties;
  std::string HeaderLines; // the element's line and its property lines, as in the file
};

enum class Encoding
{
  Ascii,
  LittleEndian,
  BigEndian
};

// Reads one value of a given type, in any of the three encodings, as a double (floating
// types) or a long long (integer types).
class ValueReader
{
public:
  ValueReader(std::istream& in, Encoding encoding)
    : In(in)
    , Format(encoding)
  {
  }

  // In ASCII every element item is a line of its own (as VTK reads it); call this before
  // each item. False at the end of the file.
  bool BeginItem()
  {
    if (this->Format != Encoding::Ascii)
    {
      return true;
    }
    std::string line;
    while (std::getline(this->In, line))
    {
      if (line.find_first_not_of(" \t\r") != std::string::npos)
      {
        this->Line.clear();
        this->Line.str(line);
        return true;
      }
    }
    return false;
  }

  // False at the end of the file (or, in ASCII, of the item's line), or for an ASCII token
  // that is not a number of the type (Malformed).
  bool Read(const ScalarType& type, double& real, long long& integer)
  {
    if (this->Format == Encoding::Ascii)
    {
      std::string token;
      if (!(this->Line >> token))
      {
        return false;
      }
      char* end = nullptr;
      errno = 0;
      if (type.IsInteger)
      {
        integer = std::strtoll(token.c_str(), &end, 10);
        real = static_cast<double>(integer);
      }
      else
      {
        real = std::strtod(token.c_str(), &end);
        integer = 0;
      }
      // A float out of range is infinite (or, below the smallest, zero), reported by the
      // NaN check as such; an integer out of range cannot be represented at all.
      // The whole token must be the number: a NUL byte inside it would end the C string
      // early and pass here, and VTK's ASCII PLY parser segfaults on it (found by the fuzzer).
      this->Malformed = end == token.c_str() || end != token.c_str() + token.size() ||
        (errno == ERANGE && type.IsInteger);
      return !this->Malformed;
    }
    unsigned char bytes[8];
    if (!this->In.read(reinterpret_cast<char*>(bytes), type.Size))
    {
      return false;
    }
    const bool little = this->Format == Encoding::LittleEndian;
    std::uint64_t bits = 0;
    for (int k = 0; k < type.Size; ++k)
    {
      bits |= static_cast<std::uint64_t>(bytes[little ? k : type.Size - 1 - k]) << (8 * k);
    }
    if (type.IsInteger)
    {
      const int unused = 64 - 8 * type.Size;
      integer = type.IsSigned
        ? static_cast<long long>(static_cast<std::int64_t>(bits << unused) >> unused)
        : static_cast<long long>(bits);
      real = static_cast<double>(integer);
    }
    else if (type.Size == 4)
    {
      const auto narrow = static_cast<std::uint32_t>(bits);
      float value;
      std::memcpy(&value, &narrow, sizeof value);
      real = value;
    }
    else
    {
      std::memcpy(&real, &bits, sizeof real);
    }
    return true;
  }

  bool Malformed = false;

private:
  std::istream& In;
  Encoding Format;
  std::istringstream Line;
};

std::string ReadHeader(std::istream& in, Encoding& encoding, std::vector<Element>& elements)
{
  std::string line;
  if (!std::getline(in, line) || line.compare(0, 3, "ply") != 0 ||
    line.find_first_not_of(" \t\r", 3) != std::string::npos)
  {
    return "not a PLY file (the first line is not 'ply')";
  }
  bool haveFormat = false;
  for (int number = 2; std::getline(in, line); ++number)
  {
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    // VTK's reader splits a header line at spaces and tabs only: another blank (a form
    // feed, a vertical tab, a carriage return) stays inside its word, which the stream
    // below would split off; "int\f" is then no type, and reading the data asserts.
    if (line.find_first_of("\f\v\r") != std::string::npos)
    {
      return "malformed PLY header line " + std::to_string(number) +
        ": a control character (form feed, vertical tab or carriage return) where words "
        "are separated by spaces or tabs";
    }
    std::istringstream fields(line);
    std::string keyword;
    fields >> keyword;
    // VTK's reader takes the first word of every header line without checking that there
    // is one: an empty line made it read through a null pointer (found by the fuzzer).
    if (keyword.empty())
    {
      return "malformed PLY header line " + std::to_string(number) +
        ": an empty line, which VTK's PLY reader cannot read (remove it)";
    }
    if (keyword == "end_header")
    {
      if (!haveFormat)
      {
        return "the PLY header has no 'format' line";
      }
      return {};
    }
    std::ostringstream malformed;
    malformed << "malformed PLY header line " << number << " '" << line << "'";
    if (keyword == "format")
    {
      std::string name;
      fields >> name;
      if (name == "ascii")
        encoding = Encoding::Ascii;
      else if (name == "binary_little_endian")
        encoding = Encoding::LittleEndian;
      else if (name == "binary_big_endian")
        encoding = Encoding::BigEndian;
      else
        return malformed.str();
      haveFormat = true;
    }
    else if (keyword == "element")
    {
      Element element;
      if (!(fields >> element.Name >> element.Count) || element.Count < 0)
      {
        return malformed.str();
      }
      element.HeaderLines = line + '\n';
      elements.push_back(element);
    }
    else if (keyword == "property")
    {
      Property property;
      std::string type;
      fields >> type;
      if (type == "list")
      {
        std::string countType, valueType;
        fields >> countType >> valueType;
        property.IsList = true;
        property.CountType = ParseScalarType(countType);
        property.ValueType = ParseScalarType(valueType);
        if (!property.CountType.IsInteger)
        {
          return malformed.str();
        }
      }
      else
      {
        property.ValueType = ParseScalarType(type);
      }
      if (elements.empty() || !(fields >> property.Name) || property.ValueType.Size == 0)
      {
        return malformed.str();
      }
      elements.back().Properties.push_back(property);
      elements.back().HeaderLines += line + '\n';
    }
    else if (keyword != "comment" && keyword != "obj_info")
    {
      return malformed.str();
    }
  }
  return "the PLY header has no 'end_header' line";
}
}

namespace
{
// What VTK 9.2's PLY reader needs of the header, or it crashes: a vertex element with
// scalar x, y and z (without them it reports "Cannot read geometry", closes the file and
// then reads it); a face element, if any, with its vertex_indices (or vertex_index) list.
// (The order of the elements it needs too, vertices then faces and nothing else, is given
// to it by ReadablePLYText.)
std::string CheckPLYLayout(const std::vector<Element>& elements)
{
  const auto find = [&elements](const std::string& name) {
    return std::find_if(elements.begin(), elements.end(),
      [&name](const Element& element) { return element.Name == name; });
  };
  const auto hasProperty = [](const Element& element, const std::string& name, bool list) {
    return std::any_of(element.Properties.begin(), element.Properties.end(),
      [&](const Property& property) { return property.Name == name && property.IsList == list; });
  };
  const auto vertex = find("vertex");
  if (vertex == elements.end())
  {
    return "the PLY header has no 'vertex' element";
  }
  for (const char* coordinate : { "x", "y", "z" })
  {
    if (!hasProperty(*vertex, coordinate, false))
    {
      return std::string("the PLY vertex element has no scalar property '") + coordinate + "'";
    }
  }
  const auto face = find("face");
  if (face != elements.end())
  {
    if (!hasProperty(*face, "vertex_indices", true) && !hasProperty(*face, "vertex_index", true))
    {
      return "the PLY face element has no list property 'vertex_indices'";
    }
  }
  return {};
}
}

namespace
{
// Every vertex element with x, y and z, and a face element's index list; the number of
// vertices (of the last vertex element). VTK 9.2's PLY reader crashes (a segmentation fault
// in vtkPLY::find_element) on a vertex element without x, y or z, and on a file without a
// vertex element (found by the fuzzer, Testing/Fuzz/Regressions/ply-vertex-without-y,
// ply-no-vertex-element).
std::string CheckPLYElements(const std::vector<Element>& elements, long long& numberOfVertices)
{
  numberOfVertices = -1;
  for (const auto& element : elements)
  {
    if (element.Name == "vertex")
    {
      numberOfVertices = element.Count;
      for (const char* coordinate : { "x", "y", "z" })
      {
        const bool found = std::any_of(element.Properties.begin(), element.Properties.end(),
          [coordinate](const Property& property) {
            return !property.IsList && property.Name == coordinate;
          });
        if (!found)
        {
          return std::string("the vertex element has no property '") + coordinate +
            "' (a PLY mesh needs x, y and z)";
        }
      }
    }
  }
  if (numberOfVertices < 0)
  {
    return "the PLY file has no 'vertex' element";
  }
  // A face element without its index list crashes VTK's reader too (it reads the faces
  // anyway; found by the fuzzer, Testing/Fuzz/Regressions/ply-face-without-indices).
  for (const auto& element : elements)
  {
    if (element.Name == "face" &&
      std::none_of(element.Properties.begin(), element.Properties.end(), [](const Property& property) {
        return property.IsList && (property.Name == "vertex_indices" || property.Name == "vertex_index");
      }))
    {
      return "the face element has no list property 'vertex_indices'";
    }
  }
  return {};
}

// The largest vertex index the faces name so far, and the face that names it.
struct LargestFaceIndex
{
  long long Index = -1;
  long long Face = -1;
};

// Vertex index `index` of face `face`: of an integer type and naming a vertex.
std::string CheckFaceIndex(const Property& property, long long face, long long index,
  long long numberOfVertices, LargestFaceIndex& largest)
{
  if (!property.ValueType.IsInteger)
  {
    return "the face element stores its vertex indices as floating-point numbers; "
           "PLY vertex indices must be of an integer type (int, uint, ...)";
  }
  if (index < 0 || (numberOfVertices >= 0 && index >= numberOfVertices))
  {
    std::ostringstream message;
    message << "face " << face << " refers to vertex " << index << ", but the file has "
            << std::max(0LL, numberOfVertices) << " vertices (numbered from 0)";
    return message.str();
  }
  if (index > largest.Index)
  {
    largest.Index = index;
    largest.Face = face;
  }
  return {};
}

// The values of `property` of item `item` of `element`, read and checked: a list's length, a
// vertex's coordinates finite, a face's vertex indices.
std::string CheckPLYProperty(ValueReader& reader, const Element& element, long long item,
  const Property& property, long long numberOfVertices, LargestFaceIndex& largest)
{
  const bool isVertex = element.Name == "vertex", isFace = element.Name == "face";
  std::ostringstream where;
  where << element.Name << " " << item << " (property '" << property.Name << "')";
  double real = 0;
  long long count = 1;
  if (property.IsList && !reader.Read(property.CountType, real, count))
  {
    return where.str() + (reader.Malformed ? " is malformed" : " is missing");
  }
  const bool isFaceIndices = isFace && property.IsList &&
    (property.Name == "vertex_indices" || property.Name == "vertex_index");
  if (isFaceIndices && count < 3)
  {
    std::ostringstream message;
    message << "face " << item << " has " << count << " vertices; a face needs at least 3";
    return message.str();
  }
  if (count < 0)
  {
    return where.str() + " has a negative list length";
  }
  for (long long k = 0; k < count; ++k)
  {
    long long integer = 0;
    if (!reader.Read(property.ValueType, real, integer))
    {
      return where.str() + (reader.Malformed ? " is malformed" : " is missing");
    }
    if (isVertex && !property.IsList &&
      (property.Name == "x" || property.Name == "y" || property.Name == "z") &&
      !std::isfinite(real))
    {
      std::ostringstream message;
      message << "vertex " << item << " has a NaN or infinite coordinate " << property.Name;
      return message.str();
    }
    const std::string error = isFaceIndices
      ? CheckFaceIndex(property, item, integer, numberOfVertices, largest)
      : std::string();
    if (!error.empty())
    {
      return error;
    }
  }
  return {};
}

// Every item of every element, read and checked after the header.
std::string CheckPLYData(std::istream& in, Encoding encoding,
  const std::vector<Element>& elements, long long numberOfVertices)
{
  // The faces may come before the vertices: the largest index is checked again at the end.
  LargestFaceIndex largest;
  ValueReader reader(in, encoding);
  for (const auto& element : elements)
  {
    for (long long item = 0; item < element.Count; ++item)
    {
      if (!reader.BeginItem())
      {
        std::ostringstream message;
        message << "the file ends before " << element.Name << " " << item << " of "
                << element.Count;
        return message.str();
      }
      for (const auto& property : element.Properties)
      {
        const std::string error =
          CheckPLYProperty(reader, element, item, property, numberOfVertices, largest);
        if (!error.empty())
        {
          return error;
        }
      }
    }
  }
  if (largest.Index >= std::max(0LL, numberOfVertices))
  {
    std::ostringstream message;
    message << "face " << largest.Face << " refers to vertex " << largest.Index
            << ", but the file has " << std::max(0LL, numberOfVertices)
            << " vertices (numbered from 0)";
    return message.str();
  }
  return {};
}
}

std::string CheckPLYFile(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  long long numberOfVertices = -1;
  std::string error = ReadHeader(in, encoding, elements);
  if (error.empty())
  {
    error = CheckPLYLayout(elements);
  }
  if (error.empty())
  {
    error = CheckPLYElements(elements, numberOfVertices);
  }
  return error.empty() ? CheckPLYData(in, encoding, elements, numberOfVertices) : error;
}

namespace
{
// Reads past the `count` items of an element (the file checked by CheckPLYFile).
bool SkipItems(ValueReader& reader, const Element& element)
{
  for (long long item = 0; item < element.Count; ++item)
  {
    if (!reader.BeginItem())
    {
      return false;
    }
    for (const auto& property : element.Properties)
    {
      double real = 0;
      long long count = 1;
      if (property.IsList && !reader.Read(property.CountType, real, count))
      {
        return false;
      }
      for (long long k = 0; k < count; ++k)
      {
        long long integer = 0;
        if (!reader.Read(property.ValueType, real, integer))
        {
          return false;
        }
      }
    }
  }
  return true;
}

bool IsBlankLine(const std::string& line)
{
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// Whether the text from `begin` on has a line of nothing but white space.
bool HasBlankLine(std::istream& in, std::streamoff begin)
{
  in.seekg(begin);
  std::string line;
  bool blank = false;
  while (!blank && std::getline(in, line))
  {
    blank = IsBlankLine(line);
  }
  in.clear();
  return blank;
}

// The lines of an ASCII block but its blank ones, each ended by a line break.
std::string WithoutBlankLines(const std::string& block)
{
  std::istringstream lines(block);
  std::string line, kept;
  while (std::getline(lines, line))
  {
    if (!IsBlankLine(line))
    {
      kept += line;
      kept += '\n';
    }
  }
  return kept;
}
}

std::string ReadablePLYText(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  Encoding encoding = Encoding::Ascii;
  std::vector<Element> elements;
  if (!ReadHeader(in, encoding, elements).empty())
  {
    return {};
  }
  const auto named = [&elements](const char* name) {
    return std::find_if(elements.begin(), elements.end(),
      [name](const Element& element) { return element.Name == name; });
  };
  const auto vertex = named("vertex"), face = named("face");
  const bool onlyVerticesThenFaces = vertex == elements.begin() &&
    (elements.size() == 1 || (elements.size() == 2 && face == elements.begin() + 1));
  const std::streamoff dataStart = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff fileEnd = in.tellg();
  in.seekg(dataStart);
  char last = '\n';
  if (fileEnd > dataStart)
  {
    in.seekg(-1, std::ios::end);
    in.get(last);
    in.seekg(dataStart);
  }
  const bool lineBreakMissing = encoding == Encoding::Ascii && last != '\n';
  // VTK's ASCII parser takes every line for an item, a blank one too: after a blank line it
  // reads on past the end of the file and fails an assertion (found by the fuzzer,
  // Testing/Fuzz/Regressions/ply-blank-lines-between-vertices). Looked for only in a file
  // that would otherwise be read as it is: a rewrite drops them anyway.
  const bool readableAsIs = onlyVerticesThenFaces && !lineBreakMissing &&
    !(encoding == Encoding::Ascii && HasBlankLine(in, dataStart));
  in.seekg(dataStart);
  if (readableAsIs)
  {
    return {};
  }
  // Where each element's data lies (its items are contiguous, in header order).
  std::vector<std::pair<std::streamoff, std::streamoff>> spans;
  ValueReader reader(in, encoding);
  for (const auto& element : elements)
  {
    const std::streamoff begin = in.tellg();
    if (!SkipItems(reader, element))
    {
      return {};
    }
    const std::streamoff end = in.eof() ? fileEnd : static_cast<std::streamoff>(in.tellg());
    spans.emplace_back(begin, end);
    in.clear();
  }
  const char* format = encoding == Encoding::Ascii ? "ascii"
    : encoding == Encoding::LittleEndian           ? "binary_little_endian"
                                                   : "binary_big_endian";
  std::string text = std::string("ply\nformat ") + format + " 1.0\n";
  std::vector<std::size_t> kept{ static_cast<std::size_t>(vertex - elements.begin()) };
  if (face != elements.end())
  {
    kept.push_back(static_cast<std::size_t>(face - elements.begin()));
  }
  for (const std::size_t k : kept)
  {
    text += elements[k].HeaderLines;
  }
  text += "end_header\n";
  for (const std::size_t k : kept)
  {
    const auto [begin, end] = spans[k];
    std::string block(static_cast<std::size_t>(end - begin), '\0');
    in.seekg(begin);
    in.read(&block[0], static_cast<std::streamsize>(block.size()));
    // Every ASCII line ends in a line break (WithoutBlankLines ends the last one too): VTK's
    // parser fails an assertion (which ends the program) at the end of the file inside a line.
    text += encoding == Encoding::Ascii ? WithoutBlankLines(block) : block;
  }
  return in ? text : std::string();
}

namespace
{
long long FileSize(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary | std::ios::ate);
  return in ? static_cast<long long>(in.tellg()) : -1;
}

// A legacy FIELD block's array header, "name components tuples type".
bool IsFieldArrayHeader(const std::string& line, long long& components, long long& tuples)
{
  static const char* const types[] = { "bit", "char", "signed_char", "unsigned_char", "short",
    "unsigned_short", "int", "unsigned_int", "long", "unsigned_long", "vtktypeint64",
    "vtktypeuint64", "float", "double", "string", "utf8_string", "vtkIdType" };
  std::istringstream fields(line);
  std::string name, type, rest;
  if (!(fields >> name >> components >> tuples >> type) || (fields >> rest))
  {
    return false;
  }
  char* end = nullptr;
  std::strtod(name.c_str(), &end);
  return *end != '\0' && std::find(std::begin(types), std::end(types), type) != std::end(types);
}

std::string TooLarge(const std::string& what, long long claimed, long long values, long long size)
{
  std::ostringstream message;
  message << "the header claims " << claimed << " " << what << " (" << values
          << " values), more than a file of " << size << " bytes can hold";
  return message.str();
}
}

namespace
{
// The problem with one line of a legacy VTK file, if it is a section header claiming more
// values than the file's `size` bytes can hold. Every value takes at least one byte (a
// binary char; two in ASCII).
std::string CheckLegacySizeLine(const std::string& line, long long size)
{
  std::istringstream fields(line);
  std::string keyword;
  fields >> keyword;
  long long first = -1, second = -1;
  if (keyword == "POINTS")
  {
    if ((fields >> first) && (first < 0 || first > size / 3))
    {
      return TooLarge("points", first, first < 0 || first > LLONG_MAX / 3 ? first : 3 * first, size);
    }
  }
  else if (keyword == "POLYGONS" || keyword == "VERTICES" || keyword == "LINES" ||
    keyword == "TRIANGLE_STRIPS")
  {
    if ((fields >> first >> second) && (first < 0 || second < 0 || first > size || second > size))
    {
      std::string cells = keyword;
      std::transform(cells.begin(), cells.end(), cells.begin(),
        [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
      return TooLarge(cells, first, std::max(first, second), size);
    }
  }
  else if (IsFieldArrayHeader(line, first, second))
  {
    // "name components tuples type" in a FIELD block: components x tuples values.
    if (first < 0 || second < 0 || (first > 0 && second > size / first))
    {
      std::ostringstream message;
      message << "the field array line '" << line << "' claims " << first << " x " << second
              << " values, more than a file of " << size << " bytes can hold";
      return message.str();
    }
  }
  else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
  {
    if ((fields >> first) && (first < 0 || first > size))
    {
      return TooLarge(keyword == "POINT_DATA" ? "point data tuples" : "cell data tuples",
        first, first, size);
    }
  }
  return {};
}

// Binary sections may hold newlines too: a line that does not parse as a section header is
// skipped.
std::string CheckLegacySizes(std::istream& in, long long size)
{
  std::string line;
  while (std::getline(in, line))
  {
    const std::string problem = CheckLegacySizeLine(line, size);
    if (!problem.empty())
    {
      return problem;
    }
  }
  return {};
}

// The number after the attribute starting at `at` in `head` into `claimed`; false when
// there is none (errno tells an overflow).
bool ClaimedNumber(const std::string& head, size_t at, const char* attribute, long long& claimed)
{
  const char* start = head.c_str() + at + std::strlen(attribute);
  char* end = nullptr;
  errno = 0;
  claimed = std::strtoll(start, &end, 10);
  return end != start;
}

// The Piece's counts of points and cells against the file's `size` (times `ratio` when
// compressed); the largest count, at least 1, in `largestCount`.
std::string CheckXMLPieceCounts(
  const std::string& head, long long size, long long ratio, long long& largestCount)
{
  const struct
  {
    const char* Attribute;
    const char* What;
    long long ValuesPerItem;
  } counts[] = { { "NumberOfPoints=\"", "points", 3 }, { "NumberOfVerts=\"", "vertex cells", 1 },
    { "NumberOfLines=\"", "line cells", 1 }, { "NumberOfStrips=\"", "strips", 1 },
    { "NumberOfPolys=\"", "polygons", 1 } };
  largestCount = 1;
  for (const auto& count : counts)
  {
    for (auto at = head.find(count.Attribute); at != std::string::npos;
         at = head.find(count.Attribute, at + 1))
    {
      long long claimed = 0;
      if (!ClaimedNumber(head, at, count.Attribute, claimed))
      {
        continue;
      }
      if (claimed < 0 || errno == ERANGE || claimed > size * ratio / count.ValuesPerItem)
      {
        const long long values = claimed > LLONG_MAX / count.ValuesPerItem
          ? claimed
          : claimed * count.ValuesPerItem;
        return TooLarge(count.What, claimed, values, size);
      }
      largestCount = std::max(largestCount, claimed);
    }
  }
  return {};
}

// A data array holds components x tuples values, the tuples being points, cells or (for
// field data) NumberOfTuples.
std::string CheckXMLArrayCounts(
  const std::string& head, long long size, long long ratio, long long largestCount)
{
  for (const char* attribute : { "NumberOfComponents=\"", "NumberOfTuples=\"" })
  {
    const bool components = attribute[8] == 'C';
    for (auto at = head.find(attribute); at != std::string::npos; at = head.find(attribute, at + 1))
    {
      long long claimed = 0;
      if (!ClaimedNumber(head, at, attribute, claimed))
      {
        continue;
      }
      const long long limit = size * ratio / (components ? largestCount : 1);
      if (claimed < 0 || errno == ERANGE || claimed > limit)
      {
        std::ostringstream message;
        message << "a data array claims " << claimed
                << (components ? " components per tuple" : " tuples") << ", more than a file of "
                << size << " bytes can hold";
        return message.str();
      }
    }
  }
  return {};
}

// XML: the Piece attributes come before the data; the start of the file is read only.
std::string CheckXMLSizes(std::istream& in, long long size)
{
  std::string head(static_cast<size_t>(std::min<long long>(size, 1 << 20)), '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  head.resize(static_cast<size_t>(std::max<std::streamsize>(0, in.gcount())));
  // zlib, the best of VTK's compressors, shrinks data at most about 1000-fold.
  const long long ratio = head.find("compressor=") != std::string::npos ? 1100 : 1;
  long long largestCount = 1;
  const std::string problem = CheckXMLPieceCounts(head, size, ratio, largestCount);
  return problem.empty() ? CheckXMLArrayCounts(head, size, ratio, largestCount) : problem;
}
}

std::string CheckVTKFileSizes(const std::string& fileName, bool xml)
{
  const long long size = FileSize(fileName);
  if (size < 0)
  {
    return "cannot read the file";
  }
  std::ifstream in(fileName, std::ios::binary);
  return xml ? CheckXMLSizes(in, size) : CheckLegacySizes(in, size);
}

namespace
{
// The POINTS section from the stream's position on: `count` points of `type`.
std::string CheckLegacyPointsSection(
  std::istream& in, bool ascii, long long count, const std::string& type)
{
  const auto missing = [count](long long values) {
    std::ostringstream message;
    message << "the file ends inside the POINTS section, before point " << values / 3 << " of "
            << count;
    return message.str();
  };
  if (!ascii)
  {
    // VTK's reader reads what there is and passes the mesh on without its cells.
    const ScalarType scalar = ParseScalarType(type == "unsigned_char" ? "uchar"
        : type == "unsigned_short"                                    ? "ushort"
        : type == "unsigned_int"                                      ? "uint"
                                                                      : type);
    const long long start = static_cast<long long>(in.tellg());
    in.seekg(0, std::ios::end);
    const long long bytes = static_cast<long long>(in.tellg()) - start;
    if (scalar.Size == 0)
    {
      return {}; // a type VTK may know and we do not: its reader decides
    }
    if (bytes / scalar.Size < 3 * count)
    {
      return missing(bytes / scalar.Size);
    }
    in.seekg(start + 3 * count * scalar.Size);
    return {};
  }
  std::string token;
  long long value = 0;
  for (; value < 3 * count && (in >> token); ++value)
  {
    char* end = nullptr;
    const double coordinate = std::strtod(token.c_str(), &end);
    if (*end != '\0')
    {
      break; // a keyword: the section is short
    }
    if (!std::isfinite(coordinate))
    {
      std::ostringstream message;
      message << "point " << value / 3 << " has a NaN or infinite coordinate '" << token << "'";
      return message.str();
    }
  }
  return value < 3 * count ? missing(value) : std::string();
}

// One integer of a legacy cell section: a token in ASCII, a big-endian int32 in binary.
bool ReadLegacyInteger(std::istream& in, bool ascii, long long& value)
{
  if (ascii)
  {
    std::string token;
    if (!(in >> token))
    {
      return false;
    }
    errno = 0;
    char* end = nullptr;
    value = std::strtoll(token.c_str(), &end, 10);
    return *end == '\0' && errno != ERANGE;
  }
  unsigned char bytes[4];
  if (!in.read(reinterpret_cast<char*>(bytes), 4))
  {
    return false;
  }
  value = static_cast<std::int32_t>((static_cast<std::uint32_t>(bytes[0]) << 24) |
    (static_cast<std::uint32_t>(bytes[1]) << 16) | (static_cast<std::uint32_t>(bytes[2]) << 8) |
    static_cast<std::uint32_t>(bytes[3]));
  return true;
}

// A cell section of the classic layout ("POLYGONS cells size", then per cell its point
// count and points, `size` values in all). VTK's reader walks the counts without checking
// them against the size: a count past the end reads beyond its buffer.
std::string CheckLegacyCellSection(
  std::istream& in, bool ascii, const std::string& keyword, long long cells, long long size)
{
  std::string name = keyword;
  std::transform(name.begin(), name.end(), name.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  long long used = 0;
  for (long long cell = 0; cell < cells; ++cell)
  {
    long long count = 0;
    std::ostringstream message;
    message << "the " << keyword << " section: ";
    if (!ReadLegacyInteger(in, ascii, count))
    {
      message << "cell " << cell << " of " << cells << " is missing or malformed";
      return message.str();
    }
    if (count < 0 || count > size - used - 1)
    {
      message << "cell " << cell << " claims " << count << " points, more than the "
              << size << " values the section declares leave room for";
      return message.str();
    }
    for (long long k = 0; k < count; ++k)
    {
      long long index = 0;
      if (!ReadLegacyInteger(in, ascii, index))
      {
        message << "cell " << cell << " of " << cells << " is cut short or malformed";
        return message.str();
      }
    }
    used += 1 + count;
  }
  if (used != size)
  {
    std::ostringstream message;
    message << "the " << keyword << " section declares " << size << " values, but its " << cells
            << " " << name << " hold " << used;
    return message.str();
  }
  return {};
}
}

std::string CheckLegacySections(const std::string& fileName)
{
  std::ifstream in(fileName, std::ios::binary);
  std::string line;
  // The third line of a legacy file says ASCII or BINARY.
  for (int number = 1; number <= 3; ++number)
  {
    if (!std::getline(in, line))
    {
      return {};
    }
  }
  const bool ascii = line.compare(0, 5, "ASCII") == 0;
  // CheckVTKFileSizes has bounded the counts by the file's size.
  while (std::getline(in, line))
  {
    std::istringstream fields(line);
    std::string keyword, type;
    long long first = -1, second = -1;
    fields >> keyword;
    std::string error;
    if (keyword == "POINTS" && (fields >> first >> type) && first >= 0)
    {
      error = CheckLegacyPointsSection(in, ascii, first, type);
    }
    else if ((keyword == "POLYGONS" || keyword == "VERTICES" || keyword == "LINES" ||
               keyword == "TRIANGLE_STRIPS") &&
      (fields >> first >> second) && first >= 0 && second >= 0)
    {
      // Files of version 5 list OFFSETS and CONNECTIVITY arrays instead.
      const auto start = in.tellg();
      std::string next;
      const bool offsets = (in >> next) && next == "OFFSETS";
      in.clear();
      in.seekg(start);
      if (!offsets)
      {
        error = CheckLegacyCellSection(in, ascii, keyword, first, second);
      }
    }
    if (!error.empty())
    {
      return error;
    }
  }
  return {};
}

std::string CheckSTLFile(const std::string& fileName, long long& triangles, long long& trailingBytes)
{
  triangles = -1;
  trailingBytes = 0;
  const long long size = FileSize(fileName);
  std::ifstream in(fileName, std::ios::binary);
  std::string head(static_cast<size_t>(std::max(0LL, std::min<long long>(size, 256))), '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  const bool text = std::all_of(head.begin(), head.end(), [](char c) {
    const auto u = static_cast<unsigned char>(c);
    return (u >= 32 && u < 127) || c == '\n' || c == '\r' || c == '\t';
  });
  if (head.compare(0, 5, "solid") == 0 && text)
  {
    return {};
  }
  if (size < 84)
  {
    return "a binary STL file needs an 84-byte header; this one has " + std::to_string(size) +
      " bytes";
  }
  const auto byte = [&head](int k) { return static_cast<unsigned char>(head[k]); };
  const long long claimed = static_cast<long long>(byte(80)) | (static_cast<long long>(byte(81)) << 8) |
    (static_cast<long long>(byte(82)) << 16) | (static_cast<long long>(byte(83)) << 24);
  if (claimed == 0)
  {
    return "the binary STL header says the file holds no triangles";
  }
  const long long room = (size - 84) / 50;
  if (claimed > room)
  {
    std::ostringstream message;
    message << "the header claims " << claimed << " triangles, but a file of " << size
            << " bytes holds at most " << room;
    return message.str();
  }
  triangles = claimed;
  trailingBytes = size - 84 - 50 * claimed;
  return {};
}
}
}
