"""ParaView macro: turns a point selected on the source mesh and one selected on the target mesh
into a landmark pair of a Mobius Registration filter, and shows the pairs as numbered glyphs.

Installed beside MobiusRegistrationPipeline.py (Macros menu), or added with Macros -> Import
new macro.... Use:
  1. Open two meshes and add Filters -> Mobius Registration -> Mobius Registration (Apply can
     wait until the landmarks are in), or run the MobiusRegistrationPipeline macro.
  2. Run this macro with nothing selected: it opens a layout tab "Mobius landmarks: <filter>"
     with the filter's Source (left) and Target (right) side by side.
  3. Select one point on the source with ParaView's own tools (Select Points On, key d, or
     Interactive Select Points On) and run the macro: the point is kept as a pending
     landmark (a sphere on the source). Select its partner on the target and run the macro
     again: the pair is appended to the filter's Landmarks property. The order does not
     matter (target first works too), and a selection on each mesh at once makes a pair in
     one run. ParaView keeps one selection at a time: a selection on the target clears the
     one on the source, hence the pending landmark.
  4. Click Apply (the macro leaves the filter modified and active): the map respects the
     landmarks and reports each landmark's residual in its field data (LandmarkResidual,
     LandmarkCount: the Information panel).
The glyphs are spheres colored by landmark number, the same colors on both meshes (the
color legend gives the numbers). They are pipeline objects of their own: per mesh, the
landmarks' points ("Landmarks on source of <filter>", an ExtractSelection whose selection
input, "Landmark ids on source of <filter>", holds their point ids), their ids as an array,
and the glyphs. They are redrawn from the filter's Landmarks at every run (edit the
property in the panel, then run the macro with nothing selected). A pick is refused with a
message when zero or several points are selected on a mesh or the point is a landmark
already (the filter refuses a vertex in two landmarks), and the macro stops with one when
no Mobius Registration filter exists. A selection elsewhere than on the filter's Source or
Target (or a mesh upstream of it with the same points) is not a pick.
"""
from paraview import servermanager
from paraview.simple import (
    Calculator, ClearSelection, ColorBy, CreateLayout, CreateView, Delete, ExtractSelection,
    FindSource, GetActiveSource, GetLayouts, GetScalarBar, GetSources, Glyph, Hide,
    IDSelectionSource, Render, SetActiveSource, SetActiveView, Show)

LANDMARK_ARRAY = "LandmarkPointId"  # the glyphs' array: the point id each sphere marks
GLYPH_SIZE = 0.04  # the glyph spheres' diameter, as a fraction of the mesh's bounding-box diagonal
SIDES = ("source", "target")
# Landmark k's color on both meshes (cycled past ten): distinct hues, light on dark.
PALETTE = [(0.90, 0.10, 0.10), (0.10, 0.55, 0.95), (0.15, 0.75, 0.20), (1.00, 0.60, 0.00),
           (0.60, 0.25, 0.85), (0.00, 0.80, 0.80), (0.95, 0.35, 0.70), (0.60, 0.40, 0.20),
           (0.95, 0.90, 0.10), (0.35, 0.35, 0.35)]


class LandmarkError(RuntimeError):
    """A pick or a pipeline the macro cannot use; the message says what to do."""


def proxy_name(proxy):
    """The name the Pipeline Browser shows for a pipeline object."""
    for (name, _), candidate in GetSources().items():
        if candidate == proxy:
            return name
    return proxy.GetXMLLabel()


def registrations():
    """The Mobius Registration filters, oldest first."""
    found = [(int(key), proxy) for (_, key), proxy in GetSources().items()
             if proxy.GetXMLName() == "MobiusRegistration"]
    return [proxy for _, proxy in sorted(found, key=lambda item: item[0])]


def selection_holders(mesh):
    """The mesh and the meshes upstream of it with the same points (e.g. the reader under
    the MobiusRegistrationPipeline macro's position-colors Calculator): a point selected on
    any of them has the same id in the mesh."""
    holders = [mesh]
    mesh.UpdatePipeline()
    count = mesh.GetDataInformation().GetNumberOfPoints()
    while "Input" in holders[-1].ListProperties():
        upstream = holders[-1].Input
        if not isinstance(upstream, servermanager.Proxy):
            break  # no input, or several
        upstream.UpdatePipeline()
        if upstream.GetDataInformation().GetNumberOfPoints() != count:
            break
        holders.append(upstream)
    return holders


def selected_points(proxy):
    """The ids of the points selected on a pipeline object (ParaView's selection of its
    first output port, whatever tool made it), or None when nothing is selected."""
    selection = proxy.SMProxy.GetSelectionInput(0)
    if selection is None:
        return None
    extract = ExtractSelection(Input=proxy, Selection=servermanager._getPyProxy(selection))
    try:
        data = servermanager.Fetch(extract)
    finally:
        Delete(extract)
    ids = data.GetPointData().GetArray("vtkOriginalPointIds") if data else None
    return sorted({int(ids.GetValue(i)) for i in range(ids.GetNumberOfTuples())}) if ids else []


def pick(registration, side):
    """The point picked on the registration's input `side` (a point id of that input), or
    None. Refuses zero or several selected points, and consumes the selection."""
    for holder in selection_holders(input_mesh(registration, side)):
        ids = selected_points(holder)
        if ids is None:
            continue
        if len(ids) != 1:
            raise LandmarkError(
                f"Add Landmark Pair: {len(ids)} points are selected on the {side} "
                f"({proxy_name(holder)}); select exactly one (Select Points On, then click a point)")
        ClearSelection(holder)
        return ids[0]
    return None


def pairs(registration):
    values = [int(v) for v in registration.Landmarks]
    return [(values[i], values[i + 1]) for i in range(0, len(values) - 1, 2)]


def input_mesh(registration, side):
    return registration.Source if side == "source" else registration.Target


def landmark_ids(registration, side):
    """The selection source holding the point ids of the landmarks on the registration's
    `side` (the pairs', then a pending pick, in order), with the filters that show them: the
    selected points, their ids as an array, sphere glyphs. Made on first use."""
    name = f"Landmark ids on {side} of {proxy_name(registration)}"
    ids = FindSource(name)
    if ids is not None:
        return ids
    ids = IDSelectionSource(registrationName=name, FieldType="POINT", IDs=[])
    points = ExtractSelection(registrationName=f"Landmarks on {side} of {proxy_name(registration)}",
                              Input=input_mesh(registration, side))
    # Set after creation: a new ExtractSelection takes its input's current selection (the
    # user's pick, when there is one) in place of the one given at creation.
    points.Selection = ids
    # ExtractSelection's vtkOriginalPointIds, under a name of their own, for the colors.
    numbered = Calculator(
        registrationName=f"Landmark point ids on {side} of {proxy_name(registration)}",
        Input=points, ResultArrayName=LANDMARK_ARRAY, Function="vtkOriginalPointIds")
    spheres = Glyph(registrationName=f"Landmark glyphs on {side} of {proxy_name(registration)}",
                    Input=numbered, GlyphType="Sphere")
    spheres.GlyphMode = "All Points"
    spheres.ScaleArray = ["POINTS", "No scale array"]
    return ids


def stored_ids(ids_source):
    return [int(v) for v in ids_source.IDs][1::2]  # (process, id) pairs


def pending_pick(ids_source, committed):
    """The pick on this side still waiting for its partner: the stored ids are the pairs'
    and then at most one more."""
    ids = stored_ids(ids_source)
    if len(ids) == len(committed) + 1 and ids[:-1] == committed:
        return ids[-1]
    return None


def show_landmarks(registration, side, ids, view):
    """Spheres at the landmarks on the registration's `side`, landmark k in color k of
    PALETTE (a categorical color map of its own, point id -> k, labelled k)."""
    ids_source = landmark_ids(registration, side)
    ids_source.IDs = [value for point_id in ids for value in (0, point_id)]
    mesh = input_mesh(registration, side)
    bounds = mesh.GetDataInformation().GetBounds()
    diagonal = sum((bounds[2 * a + 1] - bounds[2 * a]) ** 2 for a in range(3)) ** 0.5
    spheres = FindSource(f"Landmark glyphs on {side} of {proxy_name(registration)}")
    spheres.ScaleFactor = GLYPH_SIZE * diagonal
    if not ids:
        Hide(spheres, view)
        return
    spheres.UpdatePipeline()
    display = Show(spheres, view)
    # A color map of its own: the same numbers are other point ids on the other mesh.
    ColorBy(display, ("POINTS", LANDMARK_ARRAY), separate=True)
    colors = display.LookupTable
    colors.InterpretValuesAsCategories = 1
    colors.Annotations = [text for number, point_id in enumerate(ids, 1)
                          for text in (str(point_id), str(number))]
    colors.IndexedColors = [c for number in range(len(ids)) for c in PALETTE[number % len(PALETTE)]]
    display.SetScalarBarVisibility(view, True)
    GetScalarBar(colors, view).Title = "Landmark"


def landmark_layout(registration):
    """The layout tab with the source (left) and the target (right), made on first use."""
    title = f"Mobius landmarks: {proxy_name(registration)}"
    for (name, _), layout in GetLayouts().items():
        if name == title:
            views = [layout.GetView(cell) for cell in (1, 2)]
            if None not in views:
                return [servermanager._getPyProxy(view) for view in views], False
    layout = CreateLayout(title)
    layout.SplitHorizontal(0, 0.5)
    views = []
    for cell, mesh in ((1, registration.Source), (2, registration.Target)):
        view = CreateView("RenderView")
        view.OrientationAxesVisibility = 0
        layout.AssignView(cell, view)
        Show(mesh, view)
        views.append(view)
    return views, True


def chosen_registration():
    """The active Mobius Registration filter, else the newest one (with a message)."""
    found = registrations()
    if not found:
        raise LandmarkError(
            "Add Landmark Pair: no Mobius Registration filter; add Filters -> Mobius "
            "Registration -> Mobius Registration to the two meshes first (or run the "
            "MobiusRegistrationPipeline macro)")
    active = GetActiveSource()
    if active in found:
        return active
    if len(found) > 1:
        print(f"Add Landmark Pair: {len(found)} Mobius Registration filters; using the newest, "
              f"{proxy_name(found[-1])} (select another in the Pipeline Browser to use it)")
    return found[-1]


def add_landmark_pair():
    registration = chosen_registration()
    committed = pairs(registration)
    stored = {side: landmark_ids(registration, side) for side in SIDES}
    picks = {side: pick(registration, side) for side in SIDES}
    for index, side in enumerate(SIDES):
        side_ids = [pair[index] for pair in committed]
        if picks[side] in side_ids:
            # The filter refuses a vertex in two landmarks: say so now, naming the landmark.
            raise LandmarkError(
                f"Add Landmark Pair: {side} point {picks[side]} is landmark "
                f"{side_ids.index(picks[side]) + 1}'s already; select another point")
        if picks[side] is None:
            picks[side] = pending_pick(stored[side], side_ids)
    if picks["source"] is not None and picks["target"] is not None:
        committed.append((picks["source"], picks["target"]))
        registration.Landmarks = [i for pair in committed for i in pair]
        message = (f"landmark {len(committed)} added: source point {picks['source']} -> target "
                   f"point {picks['target']}; Apply the filter to use the "
                   f"{len(committed)} landmark(s)")
        picks = {side: None for side in SIDES}
    elif picks["source"] is None and picks["target"] is None:
        message = (f"{len(committed)} landmark(s); select one point on the source or the "
                   "target (Select Points On) and run the macro again")
    else:
        waiting = "source" if picks["source"] is not None else "target"
        other = "target" if waiting == "source" else "source"
        message = (f"landmark {len(committed) + 1}: {waiting} point {picks[waiting]} kept; "
                   f"select its partner on the {other} and run the macro again")

    views, new_layout = landmark_layout(registration)
    ids = {}
    for index, side in enumerate(SIDES):
        pending = [] if picks[side] is None else [picks[side]]
        ids[side] = [pair[index] for pair in committed] + pending
    for side, view in zip(SIDES, views):
        show_landmarks(registration, side, ids[side], view)
    for view in views:
        if new_layout:  # later runs keep the user's camera
            view.ResetCamera()
        Render(view)
    SetActiveView(views[0])
    SetActiveSource(registration)
    print("Add Landmark Pair:", message)
    return registration


add_landmark_pair()
