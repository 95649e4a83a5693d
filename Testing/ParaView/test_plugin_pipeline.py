"""pvpython: the filters by their menu names on a real mesh (CGAL's hand, from libcgal-demo):
OFF reader -> Spherical Conformal Map -> Mobius Center -> Spherical Scale Grid, and
SO3 Register of the centered map with itself."""
import math
import os
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin, mesh_dir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())


def field(proxy, name, component=0):
    return servermanager.Fetch(proxy).GetFieldData().GetArray(name).GetComponent(0, component)


mesh = OpenDataFile(os.path.join(mesh_dir, "hand.off"))  # our OFF reader, by extension
assert mesh.GetXMLName() == "OFFMeshReader", mesh.GetXMLName()
spherical = SphericalConformalMap(Input=mesh)
assert spherical.FillHoles == 0 and spherical.TimeStep == 0.4
spherical.UpdatePipeline()
assert field(spherical, "FlippedTriangles") == 0
assert 1.0 <= field(spherical, "MeanQuasiConformalDistortion") < 1.3

centered = MobiusCenter(Input=spherical)
assert field(centered, "CenterOfMassNorm") <= 1e-10

grid = SphericalScaleGrid(Input=centered, Resolution=32)
grid_data = servermanager.Fetch(grid)
assert grid_data.GetNumberOfCells() == 32 * 32
total = field(grid, "TotalArea")
areas = servermanager.Fetch(centered).GetCellData().GetArray("SurfaceArea")
surface_area = sum(areas.GetValue(i) for i in range(areas.GetNumberOfTuples()))
assert abs(total - surface_area) <= 1e-9 * surface_area, (total, surface_area)

registration = SO3Register(Source=centered, Target=centered, Resolution=64)
rotation = [field(registration, "Rotation", k) for k in range(9)]
angle = math.degrees(math.acos(max(-1.0, min(1.0, (rotation[0] + rotation[4] + rotation[8] - 1) / 2))))
print(f"pipeline on hand.off: self-registration angle {angle:.4f} deg, "
      f"error {field(registration, 'RegistrationError'):.2e}")
assert field(registration, "Determinant") == 1
assert angle < 0.1, angle
