/**
 * @file vtkMeshFileChecks.h
 * @brief Checks of mesh files that must pass before VTK's own reader sees them (private to
 * the module).
 *
 * VTK 9.2's PLY reader trusts the face indices: it looks up the points of every face while
 * reading, so an index past the end or negative reads (and writes) out of bounds and can
 * crash the program before any check on its output could run. The check here walks the
 * whole file (ASCII and both binary encodings, every element and property, lists included)
 * without keeping it, and returns an empty string or the reason the file is bad.
 */
#ifndef vtkMeshFileChecks_h
#define vtkMeshFileChecks_h

#include <string>

namespace mobius
{
namespace vtk
{
/// Fails on a malformed or truncated PLY file, a vertex with a NaN or infinite x, y or z,
/// and a face (list `vertex_indices` or `vertex_index`) with fewer than 3 vertices or an
/// index outside [0, number of vertices).
std::string CheckPLYFile(const std::string& fileName);
}
}

#endif
