/**
 * @file MobiusMeshFileParsers.h
 * @brief The project's own parsers of OFF, OBJ and STL files (private to the module).
 *
 * VTK's readers of these formats renumber vertices (OBJ), trust indices (OBJ), take an ASCII
 * STL file that does not start with exactly "solid" for a binary one, or have no OFF reader.
 * These keep the file's vertex numbers and return an empty string or the reason the file
 * cannot be read, naming the vertex, face or line.
 *
 * The text parsers read the text as NormalizedText gives it: without a UTF-8 byte-order mark,
 * with CR LF and lone CR line endings turned into LF.
 */
#ifndef MobiusMeshFileParsers_h
#define MobiusMeshFileParsers_h

#include <string>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
/// The file's bytes without a leading UTF-8 byte-order mark (which Windows editors write and
/// which would hide the first keyword), every CR LF or lone CR (old Mac tools) made an LF.
std::string NormalizedText(const std::string& fileName);

/// OFF as specified (free-format: counts, coordinates and indices may be spread over lines
/// as the writer likes, all of them on one line included; '#' comments), with the optional
/// prefixes ST, C, N, 4 and n of the header keyword. A face's color after its indices, and
/// fields after a vertex's coordinates on its line, are skipped when each vertex and face
/// starts a line. `OFF BINARY` is refused with a message that says so.
std::string ReadOFF(const std::string& fileName, vtkPolyData* output);

/// OBJ positions and faces; see the definition for what is read and skipped.
std::string ReadOBJ(const std::string& fileName, vtkPolyData* output);

/// True when an STL file is text: after an optional byte-order mark and white space it
/// starts with "solid" (any case), and its size is not exactly that of a binary file with
/// the triangle count its bytes 80-83 would give (binary files may start with "solid" too).
bool IsAsciiSTL(const std::string& fileName);

/// ASCII STL: keywords in any case, any white space, any solid name (UTF-8, any length),
/// several solids in one file. Corners at equal coordinates are merged, in the order they
/// come, and triangles that merging collapses dropped, as VTK's STL reader does.
std::string ReadAsciiSTL(const std::string& fileName, vtkPolyData* output);

/// The `count` triangles of a binary STL file (CheckSTLFile gives the count), merged as
/// ReadAsciiSTL merges them. VTK's reader reads triangles to the end of the file and sizes
/// its arrays by the file's length: padding after the triangles becomes triangles, and
/// 512 MB of it exhausts a 1 GB address space.
std::string ReadBinarySTL(const std::string& fileName, long long count, vtkPolyData* output);

/// Printable ASCII of `text` (the rest as '?', line breaks as spaces), cut after 300
/// characters: messages stay one printable line whatever a file held.
std::string PrintableLine(const std::string& text);
}
}

#endif
