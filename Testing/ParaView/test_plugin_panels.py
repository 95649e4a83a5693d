"""pvpython: what the GUI shows of the plugin. A new display of each filter is colored by its
documented array; properties are grouped by stage; Resolution only offers even sizes; every
filter has its documentation (ParaView's Help and the panel's ? button)."""
import sys

from paraview.simple import *  # noqa: F401,F403  (the usual pvpython namespace)
from paraview import servermanager

plugin = sys.argv[1]
LoadPlugin(plugin, remote=False, ns=globals())

# A closed genus-0 surface, pear-shaped (not centrally symmetric, so its map is not
# centered by symmetry alone).
sphere = Sphere(Radius=1.0, ThetaResolution=24, PhiResolution=16)
surface = Calculator(Input=sphere, CoordinateResults=1,
                     Function="(2*coordsX + 1.2*coordsY*coordsY)*iHat + coordsY*jHat + 0.6*coordsZ*kHat")
# Without centering between flow steps the map drifts: centering then has work to do.
conformal = SphericalConformalMap(Input=surface, CenterBetweenSteps=0, MaximumNumberOfIterations=20)
center = MobiusCenter(Input=conformal)
grid = SphericalScaleGrid(Input=center, Resolution=32)
symmetry = DetectSymmetry(Input=surface, Resolution=32, Refine=0)

view = CreateView("RenderView")
expected = {conformal: ("CELLS", "QuasiConformalDistortion"), center: ("CELLS", "LogAreaRatio"),
            grid: ("CELLS", "ConformalFactorSmoothed"), symmetry: ("POINTS", "Asymmetry")}
for proxy, (association, array) in expected.items():
    display = Show(proxy, view)
    assert list(display.ColorArrayName) == [association, array], (proxy.GetXMLName(), list(display.ColorArrayName))
# The arrays mean what they say: the stretched surface's map is not conformal everywhere
# (distortion >= 1), and the centered map spreads area more evenly than the first one.
cells = servermanager.Fetch(conformal).GetCellData()
low, high = cells.GetArray("QuasiConformalDistortion").GetRange()
assert 1.0 <= low and high > 1.0, (low, high)
# LogAreaRatio is the centered map's own (recomputed, not the input's passed through), and
# means what it says: the triangles' shares of the sphere, 2^LogAreaRatio times their shares
# of the surface, add up to the whole sphere.
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
before, after = (vtk_to_numpy(servermanager.Fetch(p).GetCellData().GetArray("LogAreaRatio")) for p in (conformal, center))
assert np.abs(before - after).max() > 0.01, np.abs(before - after).max()
areas = vtk_to_numpy(servermanager.Fetch(center).GetCellData().GetArray("SurfaceArea"))
total = (np.exp2(after) * areas / areas.sum()).sum()
assert abs(total - 1) < 1e-9, total

for name in ("SphericalConformalMap", "MobiusCenter", "SO3Register", "SphericalScaleGrid",
             "DenseCorrespondence", "RefineCorrespondence", "DetectSymmetry", "SphericalOrbifoldMap"):
    prototype = servermanager.ProxyManager().GetPrototypeProxy("filters", name)
    assert prototype is not None, name
    assert prototype.GetNumberOfPropertyGroups() >= 1, name
    grouped = {prototype.GetPropertyGroup(g).GetProperty(p).GetXMLLabel()
               for g in range(prototype.GetNumberOfPropertyGroups())
               for p in range(prototype.GetPropertyGroup(g).GetNumberOfProperties())}
    assert grouped, name
    documentation = prototype.GetDocumentation()
    assert documentation.GetShortHelp() and documentation.GetLongHelp(), name
    # Every property says what it does (the panel's tooltip); the applications' filters
    # (paper Section 5 and 7) put each of theirs in a group by stage.
    properties = servermanager.vtkSMPropertyIterator()
    properties.SetProxy(prototype)
    properties.Begin()
    while not properties.IsAtEnd():
        prop = properties.GetProperty()
        if prop.GetPanelVisibility() != "never" and not prop.GetInformationOnly():
            text = prop.GetDocumentation().GetDescription() if prop.GetDocumentation() else None
            assert text and text.strip(), (name, properties.GetKey())
            if name in ("MobiusCenter", "DetectSymmetry", "SphericalOrbifoldMap") and \
                    properties.GetKey() != "Input":
                assert prop.GetXMLLabel() in grouped, (name, properties.GetKey(), "not in a property group")
        properties.Next()
    resolution = prototype.GetProperty("Resolution")
    if resolution is not None:
        domain = resolution.FindDomain("vtkSMEnumerationDomain")
        values = [domain.GetEntryValue(k) for k in range(domain.GetNumberOfEntries())]
        # Even sizes only, up to what fits comfortably in memory; the default is offered.
        assert values and all(v % 2 == 0 and 16 <= v <= 2048 for v in values), (name, values)
        assert resolution.GetDefaultValue(0) in values, name
# The threaded filters' thread count: an advanced, documented property, 0 (automatic) by
# default; what ran is in the output's field data.
for name in ("SO3Register", "SphericalScaleGrid", "DenseCorrespondence", "RefineCorrespondence", "DetectSymmetry"):
    threads = servermanager.ProxyManager().GetPrototypeProxy("filters", name).GetProperty("NumberOfThreads")
    assert threads is not None, name
    assert threads.GetDefaultValue(0) == 0 and threads.GetPanelVisibility() == "advanced", name
    assert threads.GetDocumentation().GetDescription(), name
grid.NumberOfThreads = 1
used = servermanager.Fetch(grid).GetFieldData().GetArray("NumberOfThreadsUsed").GetValue(0)
assert used == 1, used
print("default coloring, property groups, Resolution sizes and documentation: as documented")
