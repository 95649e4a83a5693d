"""The Python wrapping: build a spherical map with VTK, center it with vtkMobiusCenter."""
import math
import sys

from vtkmodules.vtkCommonCore import vtkDoubleArray
from vtkmodules.vtkFiltersSources import vtkSphereSource
from vtkmodules.vtkFiltersCore import vtkTriangleFilter

import mobiusregistration
from mobiusregistration import vtkMobiusCenter


def off_center_map():
    """A unit sphere whose triangles carry original areas crowded toward +x."""
    sphere = vtkSphereSource()
    sphere.SetRadius(1.0)
    sphere.SetThetaResolution(48)
    sphere.SetPhiResolution(24)
    sphere.SetOutputPointsPrecision(1)  # double
    triangles = vtkTriangleFilter()
    triangles.SetInputConnection(sphere.GetOutputPort())
    triangles.Update()
    mesh = triangles.GetOutput()
    areas = vtkDoubleArray()
    areas.SetName("SurfaceArea")
    for cell in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(cell).GetPointIds()
        x = sum(mesh.GetPoint(ids.GetId(k))[0] for k in range(3)) / 3.0
        areas.InsertNextValue(math.exp(2.0 * x))
    mesh.GetCellData().AddArray(areas)
    return mesh


def area_weighted_mean_direction(mesh):
    """Sum over triangles of SurfaceArea times the unit direction of the triangle's centroid,
    over the total SurfaceArea."""
    areas = mesh.GetCellData().GetArray("SurfaceArea")
    total, mean = 0.0, [0.0, 0.0, 0.0]
    for cell in range(mesh.GetNumberOfCells()):
        ids = mesh.GetCell(cell).GetPointIds()
        centroid = [sum(mesh.GetPoint(ids.GetId(k))[c] for k in range(3)) / 3.0 for c in range(3)]
        norm = math.hypot(*centroid)
        area = areas.GetValue(cell)
        total += area
        mean = [m + area * c / norm for m, c in zip(mean, centroid)]
    return [m / total for m in mean]


def main():
    mesh = off_center_map()
    center = vtkMobiusCenter()
    center.SetInputData(mesh)
    center.SetTolerance(1e-10)
    assert center.GetMaximumNumberOfIterations() == 100
    center.Update()
    out = center.GetOutput()
    field = out.GetFieldData()
    initial = field.GetArray("InitialCenterOfMassNorm").GetValue(0)
    final = field.GetArray("CenterOfMassNorm").GetValue(0)
    iterations = field.GetArray("CenteringIterations").GetValue(0)
    transform = field.GetArray("MobiusTransform")
    print(f"|mu| {initial:.3g} -> {final:.3g} in {iterations:.0f} iterations")
    assert initial > 0.3, initial
    assert final <= 1e-10, final
    assert 1 <= iterations <= 10, iterations
    assert transform.GetNumberOfComponents() == 16
    # Every point is still on the unit sphere, and the map moved area away from +x: the
    # surface-area-weighted mean of the triangles' directions, computed here independently
    # of the filter, went from far toward +x to the center.
    radii = [math.dist(out.GetPoint(i), (0, 0, 0)) for i in range(out.GetNumberOfPoints())]
    assert max(abs(r - 1) for r in radii) < 1e-12
    assert out.GetCellData().GetArray("SurfaceArea") is not None
    before, after = area_weighted_mean_direction(mesh), area_weighted_mean_direction(out)
    print(f"area-weighted mean direction {before} -> {after}")
    assert before[0] > 0.3, before
    assert abs(after[0]) < 0.05 * before[0] and math.hypot(*after) < 0.05 * before[0], after
    # The wrapped class reports its parameters.
    assert "Tolerance: 1e-10" in str(center)
    return 0


if __name__ == "__main__":
    sys.exit(main())
