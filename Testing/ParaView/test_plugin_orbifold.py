"""pvpython: Spherical Orbifold Map by its menu name on CGAL's hand (CC0), from the mesh and
from its spherical conformal map (the same cones and map)."""
import os
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin, mesh_dir = sys.argv[1], sys.argv[2]
LoadPlugin(plugin, remote=False, ns=globals())


def field(proxy, name, component=0):
    return servermanager.Fetch(proxy).GetFieldData().GetArray(name).GetComponent(0, component)


mesh = OpenDataFile(os.path.join(mesh_dir, "hand.off"))
orbifold = SphericalOrbifoldMap(Input=mesh, NumberOfCopies=4)
assert orbifold.OutputCovering == 0 and list(orbifold.ConeIds) == [-1, -1]
orbifold.UpdatePipeline()
output = servermanager.Fetch(orbifold)
assert output.GetNumberOfPolys() == servermanager.Fetch(mesh).GetNumberOfPolys()
error = field(orbifold, "SymmetryError")
print(f"Spherical Orbifold Map, hand, n = 4: symmetry error {error:.3g}, std log area ratio "
      f"{field(orbifold, 'StdLogAreaRatio'):.3f} (plain {field(orbifold, 'PlainStdLogAreaRatio'):.3f})")
assert error < 1e-6, error

from_map = SphericalOrbifoldMap(Input=SphericalConformalMap(Input=mesh), NumberOfCopies=4)
assert [field(from_map, "ConeIds", k) for k in range(2)] == [field(orbifold, "ConeIds", k) for k in range(2)]
assert abs(field(from_map, "StdLogAreaRatio") - field(orbifold, "StdLogAreaRatio")) < 1e-9
