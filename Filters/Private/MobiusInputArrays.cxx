#include "MobiusInputArrays.h"

#include "vtkAbstractArray.h"
#include "vtkCellData.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

namespace mobius
{
namespace vtk
{
namespace
{
// The first array of `attributes` without `count` tuples, described; empty if none.
std::string MismatchedArray(vtkDataSetAttributes* attributes, vtkIdType count, const char* kind)
{
  for (int k = 0; attributes && k < attributes->GetNumberOfArrays(); ++k)
  {
    vtkAbstractArray* array = attributes->GetAbstractArray(k);
    if (!array || array->GetNumberOfTuples() == count)
    {
      continue;
    }
    const char* name = array->GetName();
    return std::string("the ") + kind + " array '" + (name ? name : "(unnamed)") + "' has " +
      std::to_string(array->GetNumberOfTuples()) + " values (tuples) for " +
      std::to_string(count) + " " + kind + "s: an array holds one per " + kind +
      "; fix or remove it";
  }
  return {};
}
}

std::string MismatchedArray(vtkPolyData* mesh)
{
  if (!mesh)
  {
    return {};
  }
  const std::string points = MismatchedArray(mesh->GetPointData(), mesh->GetNumberOfPoints(), "point");
  return points.empty() ? MismatchedArray(mesh->GetCellData(), mesh->GetNumberOfCells(), "cell")
                        : points;
}
}
}
