"""The Python wrapping of vtkSphericalOrbifoldMap: a lopsided ellipsoid (a VTK sphere
stretched and sheared) gets a 3-fold orbifold map that is symmetric to rounding, with the
documented arrays; a bad NumberOfCopies is refused."""
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkFiltersSources import vtkSphereSource

from mobiusregistration import vtkSphericalOrbifoldMap

sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(24)
stretch = vtkTransform()
stretch.Scale(2.5, 1.0, 0.7)
stretch.RotateZ(20)
stretch.Scale(1.0, 1.4, 1.0)
ellipsoid = vtkTransformPolyDataFilter()
ellipsoid.SetInputConnection(sphere.GetOutputPort())
ellipsoid.SetTransform(stretch)

orbifold = vtkSphericalOrbifoldMap()
orbifold.SetInputConnection(ellipsoid.GetOutputPort())
orbifold.SetNumberOfCopies(3)
orbifold.OutputCoveringOn()
orbifold.Update()
output = orbifold.GetOutput()
fields = output.GetFieldData()
error = fields.GetArray("SymmetryError").GetValue(0)
print("ellipsoid, n = 3: symmetry error", error, "std log area ratio",
      fields.GetArray("StdLogAreaRatio").GetValue(0), "plain",
      fields.GetArray("PlainStdLogAreaRatio").GetValue(0))
assert error < 1e-6, error
assert fields.GetArray("ConeIds").GetNumberOfComponents() == 2
for name in ("SurfacePoints", "InputPointId", "Copy"):
    assert output.GetPointData().GetArray(name) is not None, name
assert output.GetCellData().GetArray("Copy").GetRange() == (0, 2)

orbifold.SetNumberOfCopies(12)
orbifold.GetExecutive().SetGlobalWarningDisplay(0)
orbifold.Update()
assert orbifold.GetOutput().GetNumberOfPoints() == 0
