/**
 * @file MobiusInputArrays.h
 * @brief The point and cell arrays of a filter's input checked against its mesh (private to
 * the module).
 *
 * Every filter of the module carries its inputs' point and cell arrays (through the repairs,
 * onto the sphere, from the target to the source's points). An array with fewer values than
 * the mesh has points (or cells) would be read past its end: garbage or NaN in the output,
 * or a crash. VTK's readers refuse such files; a vtkPolyData built in Python or in ParaView
 * can hold one. Each input is checked before any filter uses it.
 */
#ifndef MobiusInputArrays_h
#define MobiusInputArrays_h

#include <string>

class vtkPolyData;

namespace mobius
{
namespace vtk
{
/// The first point array whose tuple count is not the number of points, or cell array whose
/// tuple count is not the number of cells, as "the point array 'T' has 10 values (tuples)
/// for 1197 points"; empty when every array fits.
std::string MismatchedArray(vtkPolyData* mesh);
}
}

#endif
