"""Run by the ParaView GUI from gui_screenshot.sh (MOBIUS_GUI_SCRIPT=this file): loads the
plugin and two four-legged meshes standing up +y (facing +x and -x, or MOBIUS_HEADINGS),
adds a Mobius Registration filter, then picks six landmarks on each as a user would with
Select Points On (the muzzle's tip, the rump's end, the lowest point of each leg), each pair
by the Add Landmark Pair macro, and writes a marker file when the landmarks' views are
drawn: the filter's panel shows the Landmarks, Apply is next. Paths come from the
environment (paraview passes no arguments to a script)."""
import os

import numpy as np

from paraview import servermanager
from paraview.simple import (
    GetLayouts, LoadPlugin, OpenDataFile, Render, SelectIDs, SetActiveSource, SetActiveView)
from vtkmodules.util.numpy_support import vtk_to_numpy

env = os.environ
LoadPlugin(env["MOBIUS_PLUGIN"], remote=False, ns=globals())
source = OpenDataFile(env["MOBIUS_SOURCE"])
target = OpenDataFile(env["MOBIUS_TARGET"])
# The filter as Filters -> Mobius Registration makes it, before Apply.
registration = MobiusRegistration(Source=source, Target=target)  # noqa: F821 (the plugin's)


def landmarks(mesh, heading):
    """Muzzle, rump, and the lowest point of each leg (front or back, left or right) of a
    four-legged mesh standing up +y and facing `heading` (+1: +x, -1: -x, turned about y)."""
    points = vtk_to_numpy(servermanager.Fetch(mesh).GetPoints().GetData())
    forward, side = heading * points[:, 0], heading * points[:, 2]
    chosen = [int(np.argmax(forward)), int(np.argmin(forward))]
    for front in (True, False):
        for left in (True, False):
            leg = np.flatnonzero(((forward > 0) == front) & ((side > 0) == left))
            chosen.append(int(leg[np.argmin(points[leg, 1])]))
    return chosen

def macro():
    exec(open(env["MOBIUS_LANDMARK_MACRO"]).read(), dict(globals()))


macro()  # nothing selected yet: the landmarks' tab, source and target side by side
layout = [layout for (name, _), layout in GetLayouts().items() if name.startswith("Mobius landmarks")][0]
views = [servermanager._getPyProxy(layout.GetView(cell)) for cell in (1, 2)]
meshes = (registration.Source, registration.Target)  # as shown in the tab
# CGAL's cow faces +x, its bull -x.
headings = [float(h) for h in env.get("MOBIUS_HEADINGS", "1 -1").split()]
for source_id, target_id in zip(landmarks(source, headings[0]), landmarks(target, headings[1])):
    # Each pick in the view that shows the mesh, as Select Points On makes it.
    for view, mesh, point_id in zip(views, meshes, (source_id, target_id)):
        SetActiveView(view)
        SelectIDs(IDs=[0, point_id], FieldType="POINT", Source=mesh)
        macro()
for view in views:
    Render(view)
SetActiveView(views[0])
SetActiveSource(registration)  # its panel, with the Landmarks, and Apply to click
with open(env["MOBIUS_DONE"], "w") as done:
    done.write("drawn\n")
