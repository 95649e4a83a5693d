"""Debian's python3, no PYTHONPATH: the installed package registers the installed cow with
a turned copy of itself, and the map carries values over (run by check-deb-in-chroot.sh)."""
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

import mobiusregistration

print("mobiusregistration from", mobiusregistration.__file__)
assert mobiusregistration.__file__.startswith("/usr/lib/python3/dist-packages/"), mobiusregistration.__file__
cow = "/usr/share/mobius-registration/meshes/cow.off"
reader = mobiusregistration.vtkSurfaceMeshReader()
reader.SetFileName(cow)
reader.Update()
positions = vtk_to_numpy(reader.GetOutput().GetPoints().GetData())
result = mobiusregistration.register(cow, cow, resolution=64, refine=False)
print(result)
# Every source vertex is mapped onto the target; transfer() of the target's positions
# gives the mapped points.
assert result.mapped_points.shape == positions.shape
assert np.abs(result.transfer(positions) - result.mapped_points).max() < 1e-6
print("register() and transfer() ran")
