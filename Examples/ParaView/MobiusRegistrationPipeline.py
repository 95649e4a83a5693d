"""ParaView macro: the whole Moebius registration pipeline on two loaded meshes, shown as a
correspondence view.

The Debian package installs it in ParaView's Macros menu (a link in /usr/bin/Macros, where
ParaView lists macros) with the plugin loaded at start-up. Otherwise add it with Macros ->
Import new macro... (installed as <prefix>/share/mobius-registration/macros/; the plugin
must be loaded: Tools -> Manage Plugins, or PV_PLUGIN_PATH). Open two meshes, select the
one to map from (the source), and click the macro. It adds the plugin's "Mobius
Registration" filter (Source, Target), which runs the whole pipeline (conformal map and
centering of each mesh, rotational alignment, refined correspondence) with its defaults,
and opens a new layout tab "Mobius correspondence N" with linked render views side by side:
  - left, the source, colored by its position (red-green-blue from x-y-z), or by the point
    array it is colored by in the active view when the macro runs;
  - middle, the map's result: the target's own mesh (the filter's output port 3) in the
    colors the map carries over from the source, so the same colors on both sides mean
    corresponding points;
  - right (SHOW_SPHERES), the two centered spherical maps side by side (the filter's output
    ports 1 and 2), the source's turned by the rotational alignment, in the same colors.
The target is the other mesh without an input in the pipeline; if the selected mesh is not
one of the two, the first loaded mesh is the source. It can be run again (on the same or
other meshes): each run adds a pipeline and a layout.
"""
import paraview.simple
from paraview import servermanager
from paraview.simple import (
    AddCameraLink, Calculator, ColorBy, CreateLayout, CreateView,
    GetActiveSource, GetActiveView, GetLayouts, GetSources, Hide,
    OutputPort, Render, SetActiveSource, SetActiveView, Show, Text, Transform)


def plugin_filter(name):
    """The plugin's filter `name` as paraview.simple makes it. The module gets a function
    per proxy when the session starts and in LoadPlugin; ParaView's Macros menu runs the
    macro in a namespace made before the plugin loaded at start-up, so the module itself is
    asked, and refreshed if the plugin came after it."""
    function = getattr(paraview.simple, name, None)
    if function is None:
        paraview.simple._add_functions(vars(paraview.simple))
        function = getattr(paraview.simple, name, None)
    if function is None:
        raise RuntimeError(f"Mobius registration macro: the plugin's filter {name} is not loaded "
                           "(Tools -> Manage Plugins -> MobiusRegistration)")
    return function


SHOW_SPHERES = True  # the third view, with the two centered spherical maps
POSITION_COLORS = "PositionColor"  # the position as red-green-blue in [0, 1]
LABEL_PREFIX = "Mobius label"  # the views' titles: Text sources, not meshes


def has_input(proxy):
    """Whether a pipeline object takes an input (a filter: Input, or Source and Target)."""
    return any(proxy.SMProxy.GetProperty(name) is not None
               and proxy.SMProxy.GetProperty(name).IsA("vtkSMInputProperty")
               for name in proxy.ListProperties())


def loaded_meshes():
    """The two readers or sources (no input, not this macro's labels, nor selection sources
    such as the Add Landmark Pair macro's), source first."""
    roots = [proxy for (name, key), proxy in sorted(GetSources().items(), key=lambda item: int(item[0][1]))
             if not has_input(proxy) and not name.startswith(LABEL_PREFIX)
             and not proxy.GetXMLName().endswith("SelectionSource")]
    if len(roots) != 2:
        raise RuntimeError("Mobius registration macro: load exactly two meshes first "
                           f"(found {len(roots)} readers or sources)")
    if GetActiveSource() is roots[1]:
        roots.reverse()
    return roots


def chosen_point_array(mesh):
    """The point array the mesh is colored by in the active view, if any."""
    view = GetActiveView()
    if view is None:
        return None
    # servermanager's lookup: simple.GetDisplayProperties would show the mesh in that view.
    display = servermanager.GetRepresentation(mesh, view)
    if display is None or not display.Visibility:
        return None
    association, name = display.ColorArrayName
    if association == "POINTS" and name and name in mesh.PointData.keys():
        return name
    return None


def with_position_colors(mesh):
    """The mesh with a point array of its position scaled to [0, 1] per axis."""
    mesh.UpdatePipeline()
    bounds = mesh.GetDataInformation().GetBounds()
    terms = []
    for axis, unit in enumerate(("iHat", "jHat", "kHat")):
        low, high = bounds[2 * axis], bounds[2 * axis + 1]
        coordinate = "coords" + "XYZ"[axis]
        terms.append(f"{unit}*({coordinate}-({low!r}))/{max(high - low, 1e-30)!r}")
    return Calculator(Input=mesh, ResultArrayName=POSITION_COLORS, Function="+".join(terms))


def new_layout():
    """A layout tab of its own, numbered after the ones earlier runs made."""
    taken = {name for name, _ in GetLayouts()}
    number = 1
    while f"Mobius correspondence {number}" in taken:
        number += 1
    return CreateLayout(f"Mobius correspondence {number}"), number


def show_colored(proxy, view, array):
    display = Show(proxy, view)
    ColorBy(display, ("POINTS", array))
    if array == POSITION_COLORS:
        display.MapScalars = 0  # the three components are the color itself
    else:
        display.SetScalarBarVisibility(view, True)
    return display


def label(view, text, number):
    title = Text(registrationName=f"{LABEL_PREFIX} {number}: {text}", Text=text)
    display = Show(title, view)
    display.WindowLocation = "Upper Center"
    display.FontSize = 12
    display.Color = [0.1, 0.1, 0.1]


def build_pipeline():
    source, target = loaded_meshes()
    array = chosen_point_array(source)
    colored = source if array else with_position_colors(source)
    array = array or POSITION_COLORS

    # The Möbius map refined spectrally (from every candidate rotation): the accurate map.
    # Its output is the source's connectivity and point arrays at the mapped points; ports
    # 1 and 2 are the source's centered map turned by the alignment and the target's, port 3
    # the target's mesh with the source's arrays carried back.
    correspondence = plugin_filter("MobiusRegistration")(Source=colored, Target=target)

    previous = GetActiveView()
    if previous is not None:
        for mesh in (source, target):
            Hide(mesh, previous)
    layout, number = new_layout()
    # Cells: split the root (0) into 1 | 2, then 2 into 5 | 6 for the spheres.
    if SHOW_SPHERES:
        layout.SplitHorizontal(0, 1.0 / 3.0)
        layout.SplitHorizontal(2, 0.5)
        cells = (1, 5, 6)
    else:
        layout.SplitHorizontal(0, 0.5)
        cells = (1, 2)
    views = []
    for cell in cells:
        view = CreateView("RenderView")
        view.OrientationAxesVisibility = 0
        layout.AssignView(cell, view)
        views.append(view)

    show_colored(colored, views[0], array)
    label(views[0], "source", number)
    # Port 3: the target's own mesh, each vertex with the source's arrays where the map
    # comes from (port 0, the source placed on the target, folds where the map is
    # many-to-one).
    show_colored(OutputPort(correspondence, 3), views[1], array)
    label(views[1], "target: the source's colors, carried by the map", number)
    # The source and the target are seen from the same side.
    AddCameraLink(views[0], views[1], f"Mobius correspondence {number}")
    if SHOW_SPHERES:
        show_colored(OutputPort(correspondence, 1), views[2], array)
        beside = Transform(Input=OutputPort(correspondence, 2))
        beside.Transform.Translate = [2.5, 0.0, 0.0]
        sphere = Show(beside, views[2])
        sphere.ColorArrayName = ["POINTS", ""]
        sphere.DiffuseColor = [0.85, 0.85, 0.85]
        sphere.Representation = "Surface With Edges"
        sphere.EdgeColor = [0.45, 0.45, 0.5]
        label(views[2], "centered maps: source (turned), target", number)
    for view in views:
        view.ResetCamera()
        Render(view)
    SetActiveView(views[1])
    SetActiveSource(correspondence)
    return correspondence


build_pipeline()
