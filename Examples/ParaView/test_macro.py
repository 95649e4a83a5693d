"""Runs the macro twice as the GUI would, and checks the correspondence views it makes.

Usage: pvpython test_macro.py PLUGIN MESH MACRO OUTPUT_DIR

Run 1: the source is a copy of MESH with a point array `Height`, shown colored by it in the
active view (the user's pick); the target is MESH. Run 2, with the target selected: the
mesh without arrays becomes the source and is colored by position. Each run must make its
own layout with three linked views showing the expected objects and coloring arrays, and
the second run must not count the first run's filters (or labels) as loaded meshes. Both
meshes have the same surface and vertex numbering, so the right map sends every vertex
to (nearly) its own position: the map itself is checked too.
"""
import os
import sys

import numpy as np

from paraview import servermanager
from paraview.simple import (
    Calculator, ColorBy, CreateView, Delete, GetActiveSource, GetLayouts, LoadPlugin,
    OpenDataFile, SaveData, SaveScreenshot, SetActiveSource, SetActiveView, Show)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, mesh, macro, output = sys.argv[1:5]
os.makedirs(output, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())

# A mesh file with a point array of its own.
reader = OpenDataFile(mesh)
height = Calculator(Input=reader, ResultArrayName="Height", Function="coordsY")
with_height = os.path.join(output, "with_height.vtp")
SaveData(with_height, proxy=height, DataMode="Binary")
Delete(height)
Delete(reader)

source = OpenDataFile(with_height)
target = OpenDataFile(mesh)
view = CreateView("RenderView")
SetActiveView(view)
ColorBy(Show(source, view), ("POINTS", "Height"))
SetActiveSource(source)


def run_macro():
    exec(open(macro).read(), dict(globals()))
    correspondence = GetActiveSource()
    assert correspondence.GetXMLName() == "MobiusRegistration", correspondence.GetXMLName()
    return correspondence


def check_map(correspondence):
    """The two meshes are one surface: every source vertex maps onto its own position."""
    source = servermanager.Fetch(correspondence.Source)
    mapped = servermanager.Fetch(correspondence)
    assert mapped.GetNumberOfPoints() == source.GetNumberOfPoints() > 0
    points = vtk_to_numpy(source.GetPoints().GetData())
    errors = np.linalg.norm(vtk_to_numpy(mapped.GetPoints().GetData()) - points, axis=1)
    diagonal = np.linalg.norm(points.max(axis=0) - points.min(axis=0))
    median, worst = np.median(errors) / diagonal, np.percentile(errors, 95) / diagonal
    # A map turned or flipped by a wrong alignment puts most vertices a large part of the
    # diagonal away.
    assert median < MEDIAN_ERROR and worst < WORST_ERROR, (median, worst)
    return median, worst


def shown_port(view, proxy, port):
    """The view's display of output port `port` of `proxy`, if any."""
    for display in view.Representations:
        connection = display.SMProxy.GetProperty("Input")
        if (connection is not None and connection.GetNumberOfProxies() == 1
                and connection.GetProxy(0) == proxy.SMProxy
                and connection.GetOutputPortForConnection(0) == port):
            return display
    return None


def check_layout(number, correspondence, shown_source, array, direct_colors):
    layouts = [layout for (name, _), layout in GetLayouts().items() if name == f"Mobius correspondence {number}"]
    assert len(layouts) == 1, list(GetLayouts())
    views = [layouts[0].GetView(cell) for cell in (1, 5, 6)]  # the macro's cells
    assert all(v is not None for v in views), views
    views = [servermanager._getPyProxy(v) for v in views]
    # The same coloring array on the source and on the target's own mesh (the filter's port
    # 3). The spheres' view shows the aligned source sphere, the filter's port 1.
    for view, proxy, port in ((views[0], shown_source, 0), (views[1], correspondence, 3),
                              (views[2], correspondence, 1)):
        display = shown_port(view, proxy, port)
        assert display is not None and display.Visibility, (number, proxy.GetXMLName(), port)
        assert list(display.ColorArrayName) == ["POINTS", array], (number, list(display.ColorArrayName))
        assert display.MapScalars == (0 if direct_colors else 1)
    # Linked cameras: the two surfaces are seen from the same side.
    assert list(views[0].CameraPosition) == list(views[1].CameraPosition)
    # The colors are carried, not recomputed: every mapped vertex keeps its source value.
    shown = servermanager.Fetch(shown_source).GetPointData().GetArray(array)
    mapped = servermanager.Fetch(correspondence).GetPointData().GetArray(array)
    assert mapped is not None and (vtk_to_numpy(mapped) == vtk_to_numpy(shown)).all()
    # On the target's own mesh they are carried back: the meshes are one surface with one
    # numbering, so each target vertex takes (nearly) the value of its own source vertex.
    on_target = servermanager.Fetch(correspondence, idx=3).GetPointData().GetArray(array)
    assert on_target is not None and on_target.GetNumberOfTuples() == shown.GetNumberOfTuples()
    values = vtk_to_numpy(shown).reshape(shown.GetNumberOfTuples(), -1)
    spread = np.ptp(values, axis=0).max()
    differences = np.abs(vtk_to_numpy(on_target).reshape(values.shape) - values).max(axis=1)
    assert np.median(differences) < 0.01 * spread, (np.median(differences), spread)
    SaveScreenshot(os.path.join(output, f"macro_{number}.png"), layouts[0], ImageResolution=[1200, 400])


MEDIAN_ERROR, WORST_ERROR = 0.01, 0.05  # of the bounding box diagonal

first = run_macro()
assert first.Source is source and first.Target is target
check_layout(1, first, source, "Height", False)
print("run 1: source colored by its Height array in three linked views; "
      "median and 95th percentile error %.2g %.2g" % check_map(first))

SetActiveSource(target)
second = run_macro()
assert second is not first
# The target was selected: it is the source now, colored by position through a Calculator.
colored = second.Source
assert colored.GetXMLName() == "Calculator" and colored.Input is target
assert second.Target is source
check_layout(2, second, colored, "PositionColor", True)
colors = vtk_to_numpy(servermanager.Fetch(colored).GetPointData().GetArray("PositionColor"))
assert colors.shape[1] == 3 and colors.min() >= 0 and colors.max() <= 1 + 1e-9
print("run 2: position colors; median and 95th percentile error %.2g %.2g" % check_map(second),
      "; registration error",
      servermanager.Fetch(second).GetFieldData().GetArray("Registration.RegistrationError").GetValue(0))
