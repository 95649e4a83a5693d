"""Drives the Add Landmark Pair macro with programmatic point selections, as the GUI's
selection tools would leave them, and checks the landmarks it makes.

Usage: pvpython test_landmarks_macro.py PLUGIN MESH MACRO OUTPUT_DIR [CORRESPONDENCE_MACRO]

The source is MESH, the target MESH turned by a Transform (its own pipeline object): vertex
i of one is vertex i of the other, so the right pairs are (i, i). Checked: the refusals (no
filter, zero or several points selected, a point that is a landmark already), a pick on the
target then on the source and the other way round (a pending pick in between, the first
one before the landmark pipelines exist), both at once with the target's point selected on
the reader under the Transform; the filter's Landmarks property after each run;
the glyph filters' points and numbers on each mesh; and, after the registration, the
landmarks' field data and the map at the landmarks; then that the correspondence macro, if
given, still finds the two meshes among the pipeline objects the landmark macro adds.
"""
import os
import sys

import numpy as np

from paraview import servermanager
from paraview.simple import (
    ClearSelection, CreateView, FindSource, GetActiveSource, GetLayouts, GetRepresentation,
    LoadPlugin, OpenDataFile, SaveScreenshot, SelectIDs, SetActiveSource, SetActiveView, Show,
    Transform)
from vtkmodules.util.numpy_support import vtk_to_numpy

plugin, mesh, macro, output = sys.argv[1:5]
os.makedirs(output, exist_ok=True)
LoadPlugin(plugin, remote=False, ns=globals())
assert servermanager.ProxyManager().GetPrototypeProxy(
    "filters", "MobiusRegistration").GetProperty("Landmarks") is not None


def run_macro():
    exec(open(macro).read(), dict(globals()))


def expect_refusal(words):
    try:
        run_macro()
    except RuntimeError as error:
        assert words in str(error), str(error)
        print("refused:", error)
        return
    raise AssertionError(f"the macro did not refuse: {words}")


def select_points(proxy, *point_ids):
    SelectIDs(IDs=[i for point_id in point_ids for i in (0, point_id)], FieldType="POINT", Source=proxy)


def stored_ids(side):
    """The point ids the macro keeps for the landmarks on `side`, in landmark order."""
    selection = FindSource(f"Landmark ids on {side} of MobiusRegistration1")
    return [int(v) for v in selection.IDs][1::2]


def landmark_points(side):
    """The macro's points of the landmarks on `side` (an ExtractSelection of the mesh)."""
    return FindSource(f"Landmarks on {side} of MobiusRegistration1")


def points(proxy):
    return vtk_to_numpy(servermanager.Fetch(proxy).GetPoints().GetData())


source = OpenDataFile(mesh)
target_reader = OpenDataFile(mesh)
target = Transform(Input=target_reader)
target.Transform.Rotate = [0.0, 0.0, 90.0]
source_points, target_points = points(source), points(target)
# The GUI's first view, with the two meshes (ParaView's selections are made in a view).
first_view = CreateView("RenderView")
SetActiveView(first_view)
Show(source, first_view)
Show(target, first_view)

expect_refusal("no Mobius Registration filter")
registration = MobiusRegistration(Source=source, Target=target)  # noqa: F821 (the plugin's)
SetActiveSource(source)  # as after a selection in the GUI: the macro must find the filter

# Three landmarks far apart: the extreme vertices along x, y and z.
a, b, c = (int(np.argmax(source_points[:, axis])) for axis in range(3))
assert len({a, b, c}) == 3, (a, b, c)

# A pick on the target before the first run: the landmark pipelines made by this run (their
# ExtractSelection would take the target's selection as its own) must keep their own ids.
select_points(target, a)
run_macro()
assert list(registration.Landmarks) == [] and stored_ids("target") == [a], stored_ids("target")
assert np.array_equal(points(landmark_points("target")), target_points[[a]])
layouts = [layout for (name, _), layout in GetLayouts().items()
           if name == "Mobius landmarks: MobiusRegistration1"]
assert len(layouts) == 1 and None not in [layouts[0].GetView(cell) for cell in (1, 2)], list(GetLayouts())
assert target.SMProxy.GetSelectionInput(0) is None  # the pick was consumed

# Its partner on the source: the pair.
select_points(source, a)
run_macro()
assert list(registration.Landmarks) == [a, a], list(registration.Landmarks)

# Nothing selected: nothing changes.
run_macro()
assert list(registration.Landmarks) == [a, a]

# Source first: a pending pick, then the pair.
select_points(source, b)
run_macro()
assert list(registration.Landmarks) == [a, a], list(registration.Landmarks)
assert source.SMProxy.GetSelectionInput(0) is None
assert stored_ids("source") == [a, b] and stored_ids("target") == [a]
assert np.array_equal(points(landmark_points("source")), source_points[sorted([a, b])])
select_points(target, b)
run_macro()
assert list(registration.Landmarks) == [a, a, b, b], list(registration.Landmarks)

# Refusals: several points, or none (an id the mesh does not have), on one mesh; a point
# that is a landmark already.
select_points(source, a, b)
expect_refusal("2 points are selected on the source")
select_points(source, len(source_points) + 5)
expect_refusal("0 points are selected on the source")
ClearSelection(source)
select_points(target, b)  # the filter refuses a vertex in two landmarks
expect_refusal("target point %d is landmark 2's already" % b)

# Both at once, the target's point selected on the reader under the Transform (same points).
select_points(source, c)
select_points(target_reader, c)
run_macro()
assert list(registration.Landmarks) == [a, a, b, b, c, c], list(registration.Landmarks)

# The glyphs: each mesh's landmarks at its own points; landmark k has color k on both meshes,
# and the color legend says k.
views = [servermanager._getPyProxy(layouts[0].GetView(cell)) for cell in (1, 2)]
colors = []
for side, view, mesh_points in zip(("source", "target"), views, (source_points, target_points)):
    assert stored_ids(side) == [a, b, c]
    glyphs = FindSource(f"Landmark glyphs on {side} of MobiusRegistration1")
    marked = servermanager.Fetch(FindSource(f"Landmark point ids on {side} of MobiusRegistration1"))
    marked_ids = vtk_to_numpy(marked.GetPointData().GetArray("LandmarkPointId")).astype(int)
    assert sorted(marked_ids) == sorted([a, b, c])
    assert np.allclose(vtk_to_numpy(marked.GetPoints().GetData()), mesh_points[marked_ids])
    display = GetRepresentation(glyphs, view)
    assert display.Visibility and list(display.ColorArrayName) == ["POINTS", "LandmarkPointId"]
    table = display.LookupTable
    assert list(table.Annotations) == [str(a), "1", str(b), "2", str(c), "3"], list(table.Annotations)
    colors.append(list(table.IndexedColors))
assert colors[0] == colors[1] and len(set(map(tuple, np.reshape(colors[0], (-1, 3))))) == 3
# Each mesh's color map is its own (the same number is another point id on the other mesh).
glyphs = [FindSource(f"Landmark glyphs on {side} of MobiusRegistration1") for side in ("source", "target")]
tables = [GetRepresentation(proxy, view).LookupTable for proxy, view in zip(glyphs, views)]
assert tables[0] != tables[1]
SaveScreenshot(os.path.join(output, "landmarks.png"), layouts[0], ImageResolution=[1000, 500])

# The registration with the three landmarks: one residual per landmark, and the map sends
# each landmark's source point onto its target point.
registration.UpdatePipeline()
result = servermanager.Fetch(registration)
fields = result.GetFieldData()
assert fields.GetArray("LandmarkCount").GetValue(0) == 3
residuals = vtk_to_numpy(fields.GetArray("LandmarkResidual"))
diagonal = np.linalg.norm(target_points.max(axis=0) - target_points.min(axis=0))
mapped = vtk_to_numpy(result.GetPoints().GetData())
errors = np.linalg.norm(mapped[[a, b, c]] - target_points[[a, b, c]], axis=1) / diagonal
# The residual is the distance between the image of the source landmark and the target
# landmark over sqrt(target area); the pairs are right, so both are small.
assert residuals.shape[0] == 3 and np.all(residuals < 0.02), residuals
assert errors.max() < 0.02, errors
# And the map elsewhere: every vertex near its own position on the turned copy.
median = np.median(np.linalg.norm(mapped - target_points, axis=1)) / diagonal
assert median < 0.01, median
print("3 landmarks; residuals", residuals, "; mapped landmark error / diagonal", errors,
      "; median error / diagonal %.2g" % median)

# LandmarkMode through its panel entry: the 3 landmarks met exactly by a Moebius transform.
registration.LandmarkMode = "Exact Moebius Fit"
registration.UpdatePipeline()
fields = servermanager.Fetch(registration).GetFieldData()
exact = vtk_to_numpy(fields.GetArray("LandmarkResidual"))
assert registration.SMProxy.GetProperty("LandmarkMode").GetElement(0) == 1
assert fields.GetArray("LandmarkCount").GetValue(0) == 3
assert exact.shape[0] == 3 and np.all(exact < 0.02), exact
print("Exact Moebius Fit: residuals", exact)

# The correspondence macro counts the readers and sources without input as the loaded meshes:
# the landmarks' selection sources must not count.
if len(sys.argv) > 5:
    SetActiveSource(source)
    exec(open(sys.argv[5]).read(), dict(globals()))
    pipeline = GetActiveSource()
    assert pipeline.GetXMLName() == "MobiusRegistration" and pipeline is not registration
    assert pipeline.Target is target_reader, pipeline.Target
    print("the correspondence macro found the two meshes")
