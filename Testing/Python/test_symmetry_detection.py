"""The Python wrapping of vtkSymmetryDetection: an ellipsoid (a VTK sphere stretched along x
and y), mirror-symmetric, comes out nearly symmetric, with the documented arrays."""
from vtkmodules.vtkFiltersGeneral import vtkTransformPolyDataFilter
from vtkmodules.vtkCommonTransforms import vtkTransform
from vtkmodules.vtkFiltersSources import vtkSphereSource

from mobiusregistration import vtkSymmetryDetection

sphere = vtkSphereSource()
sphere.SetThetaResolution(24)
sphere.SetPhiResolution(24)
stretch = vtkTransform()
stretch.Scale(2.0, 1.3, 1.0)
ellipsoid = vtkTransformPolyDataFilter()
ellipsoid.SetInputConnection(sphere.GetOutputPort())
ellipsoid.SetTransform(stretch)

symmetry = vtkSymmetryDetection()
symmetry.SetInputConnection(ellipsoid.GetOutputPort())
symmetry.SetResolution(64)
symmetry.RefineOff()
symmetry.Update()
output = symmetry.GetOutput()
fields = output.GetFieldData()
distance = fields.GetArray("SymmetryDistance").GetValue(0)
print("ellipsoid: symmetry distance", distance)
assert 0 <= distance < 0.05, distance
assert output.GetPointData().GetArray("Asymmetry") is not None
assert fields.GetArray("MirrorPlaneNormal").GetNumberOfComponents() == 3
assert symmetry.GetCentering() and not symmetry.GetRefine()
