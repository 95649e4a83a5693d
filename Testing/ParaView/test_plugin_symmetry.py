"""pvpython: Detect Symmetry by its menu name on CGAL's cow (CC0), from the mesh and from its
spherical conformal map (the same answer), with and without centering."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin, mesh_dir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())


def field(proxy, name, component=0):
    return servermanager.Fetch(proxy).GetFieldData().GetArray(name).GetComponent(0, component)


mesh = OpenDataFile(os.path.join(mesh_dir, "cow.off"))
symmetry = DetectSymmetry(Input=mesh, Resolution=64)
assert symmetry.Centering == 1 and symmetry.Refine == 1 and symmetry.BasisSize == 80
symmetry.UpdatePipeline()
output = servermanager.Fetch(symmetry)
distance = field(symmetry, "SymmetryDistance")
assert 0 < distance < 0.5, distance
for name in ("Asymmetry", "TargetCellId", "TargetBarycentric", "MappedPoints"):
    assert output.GetPointData().GetArray(name) is not None, name
assert output.GetNumberOfPoints() == servermanager.Fetch(mesh).GetNumberOfPoints()
normal = [field(symmetry, "MirrorPlaneNormal", k) for k in range(3)]
assert abs(sum(x * x for x in normal) - 1) < 1e-9, normal

# Detect Symmetry maps a mesh by the flow from the surface (which keeps a mirror symmetry
# exactly); the same map, given, gives the same answer.
from_map = DetectSymmetry(Input=SphericalConformalMap(Input=mesh, LinearStart=0), Resolution=64)
assert abs(field(from_map, "SymmetryDistance") - distance) < 1e-9

uncentered = DetectSymmetry(Input=mesh, Resolution=64, Centering=0, Refine=0)
print(f"Detect Symmetry on cow.off: distance {distance:.4f} centered, "
      f"{field(uncentered, 'SymmetryDistance'):.4f} uncentered; mean asymmetry "
      f"{field(symmetry, 'MeanAsymmetry'):.4f}")
assert field(uncentered, "SymmetryCentered") == 0
