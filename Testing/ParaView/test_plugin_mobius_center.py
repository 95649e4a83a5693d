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

# Generalized centering (the paper's Figure 5) by the same filter's Degree: the moments of
# degrees 1 and 2 vanish, after some advection steps, with no triangle turned inside out.
generalized = MobiusCenter(Input=spherical_map, Degree=2)
assert generalized.GeneralizedTolerance == 1e-10 and generalized.GeneralizedMaximumNumberOfIterations == 200
generalized.UpdatePipeline()
result = servermanager.Fetch(generalized)
field = result.GetFieldData()
steps = field.GetArray("GeneralizedCenteringIterations").GetValue(0)
moments = field.GetArray("CenterOfMassNorm").GetValue(0)
print(f"Mobius Center, Degree 2, in pvpython: {steps:g} advection steps, moments left {moments:.3g}")
assert field.GetArray("CenteringDegree").GetValue(0) == 2
assert 0 < steps < 200 and moments <= 1e-10, (steps, moments)
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
x = vtk_to_numpy(result.GetPoints().GetData())
triangles = vtk_to_numpy(result.GetPolys().GetConnectivityArray()).reshape(-1, 3)
a, b, c = (x[triangles[:, k]] for k in range(3))
assert (np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c) > 0).all(), "a flipped triangle"
