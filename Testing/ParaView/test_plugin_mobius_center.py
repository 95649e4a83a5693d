"""pvpython: load the plugin, run "Mobius Center" by its menu name on a spherical map."""
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

# A unit sphere whose triangles carry original areas crowded toward +x.
sphere = Sphere(Radius=1.0, ThetaResolution=48, PhiResolution=24)
spherical_map = ProgrammableFilter(Input=sphere)
spherical_map.Script = """
import numpy as np
from vtkmodules.numpy_interface import dataset_adapter as dsa
mesh = dsa.WrapDataObject(self.GetPolyDataInput())
out = self.GetPolyDataOutput()
out.ShallowCopy(mesh.VTKObject)
points = mesh.Points / np.linalg.norm(mesh.Points, axis=1)[:, None]
out.GetPoints().SetData(dsa.numpyTovtkDataArray(points))
ids = mesh.Polygons.reshape(-1, 4)[:, 1:]
x = points[ids].mean(axis=1)[:, 0]
dsa.WrapDataObject(out).CellData.append(np.exp(2.0 * x), "SurfaceArea")
"""

center = MobiusCenter(Input=spherical_map)
assert center.Tolerance == 1e-10
assert center.MaximumNumberOfIterations == 100
center.UpdatePipeline()
result = servermanager.Fetch(center)
field = result.GetFieldData()
initial = field.GetArray("InitialCenterOfMassNorm").GetValue(0)
final = field.GetArray("CenterOfMassNorm").GetValue(0)
print(f"Mobius Center in pvpython: |mu| {initial:.3g} -> {final:.3g}")
assert initial > 0.3, initial
assert final <= 1e-10, final
assert result.GetNumberOfPoints() == servermanager.Fetch(spherical_map).GetNumberOfPoints()
