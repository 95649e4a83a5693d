"""The two meshes the macro runs on, and the check of the side-by-side views it makes
(used in pvbatch and, through the check macro, in the paraview GUI)."""
import os

import numpy as np
from paraview import servermanager
from paraview.simple import (Delete, GetActiveSource, GetLayouts, OpenDataFile, SaveData,
                             SaveScreenshot, SetActiveSource, Transform)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

COW = "/usr/share/mobius-registration/meshes/cow.off"
MACRO = "/usr/share/mobius-registration/macros/MobiusRegistrationPipeline.py"


def open_two_meshes(folder):
    """The installed cow and a turned, stretched copy of it, written to a file and opened
    as a user opens two mesh files; the cow (the source) is selected."""
    cow = OpenDataFile(COW)
    turned = Transform(Input=cow)
    turned.Transform.Rotate = [20.0, 40.0, 10.0]
    turned.Transform.Scale = [1.2, 1.0, 1.0]
    path = os.path.join(folder, "cow-turned.vtp")
    SaveData(path, proxy=turned, DataMode="Binary")
    Delete(turned)
    target = OpenDataFile(path)
    SetActiveSource(cow)
    return cow, target


def check_views(screenshot):
    """The macro's layout: three views with the source, the mapped source on the target
    and the spheres, all shown, the first two colored alike; the map itself (the target is
    the source turned and stretched, vertex for vertex); saves and checks a picture."""
    layouts = [layout for (name, _), layout in GetLayouts().items() if name.startswith("Mobius correspondence")]
    assert len(layouts) == 1, f"layouts: {list(GetLayouts())}"
    correspondence = GetActiveSource()
    assert correspondence.GetXMLName() == "MobiusRegistration", correspondence.GetXMLName()
    views = [layouts[0].GetView(cell) for cell in (1, 5, 6)]  # the macro's three cells
    assert all(view is not None for view in views), f"the layout's views: {views}"
    views = [servermanager._getPyProxy(view) for view in views]
    cow_points = servermanager.Fetch(correspondence.Source).GetNumberOfPoints()
    mapped = servermanager.Fetch(correspondence)
    assert mapped.GetNumberOfPoints() == cow_points > 0, (mapped.GetNumberOfPoints(), cow_points)
    # Vertex i of the target is the cow's vertex i turned and stretched: where it should go.
    truth = vtk_to_numpy(servermanager.Fetch(correspondence.Target).GetPoints().GetData())
    errors = np.linalg.norm(vtk_to_numpy(mapped.GetPoints().GetData()) - truth, axis=1)
    median = np.median(errors) / np.linalg.norm(truth.max(axis=0) - truth.min(axis=0))
    # A map turned or flipped by a wrong alignment is off by a large part of the diagonal.
    assert median < 0.02, f"median map error {median:.3g} of the target's diagonal"
    display = servermanager.GetRepresentation(correspondence, views[1])
    assert display is not None and display.Visibility, "the mapped source is not shown in the middle view"
    shown = [sum(1 for rep in view.Representations if rep.Visibility) for view in views]
    assert all(count >= 1 for count in shown), f"shown per view: {shown}"
    SaveScreenshot(screenshot, layouts[0], ImageResolution=[1200, 400])
    reader = vtkPNGReader()
    reader.SetFileName(screenshot)
    reader.Update()
    pixels = vtk_to_numpy(reader.GetOutput().GetPointData().GetScalars())
    colors = len(np.unique(pixels[:, :3], axis=0))
    # Three views of colored surfaces: many colors; an empty or black picture has one or two.
    assert colors > 200, f"{screenshot}: only {colors} colors"
    return (f"layout '{[name for (name, _) in GetLayouts() if name.startswith('Mobius')][0]}': 3 views, "
            f"{cow_points} source vertices mapped (median error {median:.2g} of the diagonal), screenshot {screenshot} with {colors} colors")
