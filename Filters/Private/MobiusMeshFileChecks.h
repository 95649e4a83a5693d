/**
 * @file MobiusMeshFileChecks.h
 * @brief Checks of mesh files that must pass before VTK's own reader sees them (private to
 * the module).
 *
 * VTK 9.2's PLY reader trusts the face indices: it looks up the points of every face while
 * reading, so an index past the end or negative reads (and writes) out of bounds and can
 * crash the program before any check on its output could run. The check here walks the
 * whole file (ASCII and both binary encodings, every element and property, lists included)
 * without keeping it, and returns an empty string or the reason the file is bad.
 */
#ifndef MobiusMeshFileChecks_h
#define MobiusMeshFileChecks_h

#include <string>

namespace mobius
{
namespace vtk
{
/// Fails on a malformed or truncated PLY file, one without a vertex element with x, y and z
/// properties or with a face element without its index list, a vertex with a NaN or
/// infinite x, y or z,
/// and a face (list `vertex_indices` or `vertex_index`) with fewer than 3 vertices or an
/// index outside [0, number of vertices).
std::string CheckPLYFile(const std::string& fileName);

/// The text of a PLY file that passed CheckPLYFile, rewritten so that VTK 9.2's PLY reader
/// can read it, or an empty string when it can read the file as it is. Its parser crashes
/// (vtkPLY::get_ascii_item) or misreads the faces of a binary file on an element other than
/// `vertex` and `face` (a material list, a camera), reads the faces only after the vertices,
/// and fails an assertion (ending the program) on an ASCII file whose last line has no line
/// break or with blank lines among its items. The rewrite keeps the vertex element, then the
/// face element, byte for byte with their header lines (an ASCII file without its blank
/// lines), and ends an ASCII file with a line break.
std::string ReadablePLYText(const std::string& fileName);

/// Fails when the counts in a legacy .vtk file's section headers (POINTS, POLYGONS,
/// VERTICES, LINES, TRIANGLE_STRIPS, POINT_DATA, CELL_DATA) or a .vtp file's Piece
/// attributes (NumberOfPoints, NumberOfPolys, ...) claim more values than a file of its
/// size can hold. VTK's readers allocate what the header claims before reading: a file of
/// a few bytes claiming 2e9 points would otherwise make them ask for tens of gigabytes
/// (and, when that fails, write through a null array).
std::string CheckVTKFileSizes(const std::string& fileName, bool xml);

/// Fails when the POINTS section of a legacy .vtk file holds fewer values than it claims
/// (VTK's reader then passes on a mesh without its cells, and the error would be "no
/// triangles"), or, in an ASCII file, a coordinate is NaN, infinite or too large for a
/// double (VTK's reader stops at it with "Unrecognized keyword: nan"); or when a cell section
/// (POLYGONS, ...) of the classic layout has a cell whose point count runs past the
/// section's declared size, or counts that do not add up to it (VTK's reader walks the
/// counts and reads past its buffer). Call it after CheckVTKFileSizes, which bounds the
/// counts by the file's size.
std::string CheckLegacySections(const std::string& fileName);

/// Fails when a binary STL file's triangle count claims more 50-byte triangles than the file
/// holds: VTK's STL reader allocates the claim (2e9 triangles end the program in
/// vtkCellArray::AllocateExact). ASCII STL files (text from "solid" on) pass.
/// For a binary file, `triangles` is the count its header gives and `trailingBytes` the
/// bytes after them (-1 and 0 for an ASCII file).
std::string CheckSTLFile(const std::string& fileName, long long& triangles, long long& trailingBytes);
}
}

#endif
