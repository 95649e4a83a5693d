"""Shared by the example scripts that draw spherical maps (orbifold_map.py,
generalized_centering.py): reading a mesh with the filters' errors caught, and an offscreen
VTK window split into side-by-side panels, written to a PNG.

Rendering needs an X display (Debian's VTK renders through GLX): run the scripts under
`xvfb-run -a` on a machine without one.
"""
import os

import csv

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkPolyData

from mobiusregistration import vtkSurfaceMeshReader


class Messages:
    """Collects a VTK object's errors and warnings instead of letting VTK print them."""

    def __init__(self, *objects):
        self.errors, self.warnings = [], []
        for obj in objects:
            obj.AddObserver(vtkCommand.ErrorEvent, self._error)
            obj.AddObserver(vtkCommand.WarningEvent, self._warning)

    # VTK passes the message as call data when the callback asks for a string.
    def _error(self, obj, event, message=None):
        self.errors.append(" ".join(str(message).split()))

    def _warning(self, obj, event, message=None):
        self.warnings.append(" ".join(str(message).split()))

    _error.CallDataType = 13  # VTK_STRING
    _warning.CallDataType = 13


def run_filter(algorithm, what):
    """Updates `algorithm`; raises RuntimeError with its first error (or 'no output') if it
    failed. Returns a copy of its output and the warnings it gave."""
    messages = Messages(algorithm, algorithm.GetExecutive())
    algorithm.Update()
    output = algorithm.GetOutput()
    if messages.errors or output.GetNumberOfPoints() == 0:
        message = messages.errors[0] if messages.errors else "no output"
        # VTK's prefix (class, address) says nothing to a user; keep the sentence.
        message = message[message.find("): ") + 3:] if "): " in message else message
        raise RuntimeError(f"{what}: {message}")
    copy = vtkPolyData()
    copy.DeepCopy(output)
    return copy, messages.warnings


def write_csv(rows, path):
    """Rows (dicts with the same keys) as a CSV table with a header."""
    with open(path, "w", newline="") as out:
        writer = csv.DictWriter(out, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


def read_mesh(path):
    reader = vtkSurfaceMeshReader()
    reader.SetFileName(path)
    mesh, _ = run_filter(reader, path)
    return mesh


def points_of(data):
    return vtk_to_numpy(data.GetPoints().GetData()).astype(float)


def triangles_of(data):
    return vtk_to_numpy(data.GetPolys().GetConnectivityArray()).reshape(-1, 3)


def field(data, name, component=0):
    array = data.GetFieldData().GetArray(name)
    return None if array is None else array.GetComponent(0, component)


def std_log_area_ratio(data, points):
    """Area distortion of the map of `data` (cell array SurfaceArea: the triangles' areas on
    the surface) to `points`: the area-weighted standard deviation over the triangles of
    log(share of the mapped area / share of the surface area), 0 for an area-preserving map.
    Triangles of zero area on either side are left out."""
    triangles = triangles_of(data)
    surface = vtk_to_numpy(data.GetCellData().GetArray("SurfaceArea")).astype(float)
    a, b, c = (points[triangles[:, k]] for k in range(3))
    mapped = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1)
    keep = (surface > 0) & (mapped > 0)
    weight = surface[keep] / surface[keep].sum()
    log_ratio = np.log(mapped[keep] / mapped[keep].sum() / weight)
    mean = np.sum(weight * log_ratio)
    return float(np.sqrt(np.sum(weight * (log_ratio - mean) ** 2)))


def principal_frame(points):
    """Mean and principal axes (columns, ascending variance) of a point set."""
    mean = points.mean(axis=0)
    _, frame = np.linalg.eigh(np.cov((points - mean).T, bias=True))
    return mean, frame


def require_display():
    if not os.environ.get("DISPLAY"):
        raise SystemExit("the picture needs an X display (Debian's VTK renders through GLX): "
                         "run under xvfb-run -a")


class PanelPicture:
    """An offscreen window of `count` panels side by side on white, each a vtkRenderer."""

    def __init__(self, count, panel_width, height):
        import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the rendering backend)
        from vtkmodules.vtkRenderingCore import vtkRenderer, vtkRenderWindow

        require_display()
        self.window = vtkRenderWindow()
        self.window.SetOffScreenRendering(True)
        self.window.SetSize(count * panel_width, height)
        self.height = height
        self.panels = []
        for k in range(count):
            renderer = vtkRenderer()
            renderer.SetViewport(k / count, 0, (k + 1) / count, 1)
            renderer.SetBackground(1, 1, 1)
            self.window.AddRenderer(renderer)
            self.panels.append(renderer)

    def add_surface(self, panel, data, rgb=None, cell_rgb=None, scalars=None, lookup_table=None):
        """Draws `data` in panel `panel`: with per-point (`rgb`) or per-cell (`cell_rgb`)
        colors (N x 3 floats in [0, 1]), or colored by the cell array `scalars` through
        `lookup_table`. Returns the actor."""
        from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

        shown = vtkPolyData()
        shown.ShallowCopy(data)
        mapper = vtkPolyDataMapper()
        if rgb is not None or cell_rgb is not None:
            colors = numpy_to_vtk(np.ascontiguousarray(np.clip(255 * (rgb if rgb is not None else cell_rgb),
                                                               0, 255).astype(np.uint8)), deep=True)
            colors.SetName("PictureColors")
            target = shown.GetPointData() if rgb is not None else shown.GetCellData()
            target.AddArray(colors)
            if rgb is not None:
                mapper.SetScalarModeToUsePointFieldData()
            else:
                mapper.SetScalarModeToUseCellFieldData()
            mapper.SelectColorArray("PictureColors")
            mapper.SetColorModeToDirectScalars()
            mapper.ScalarVisibilityOn()
        elif scalars is not None:
            mapper.SetScalarModeToUseCellFieldData()
            mapper.SelectColorArray(scalars)
            mapper.SetLookupTable(lookup_table)
            mapper.SetUseLookupTableScalarRange(True)
        else:
            mapper.ScalarVisibilityOff()
        mapper.SetInputData(shown)
        actor = vtkActor()
        actor.SetMapper(mapper)
        self.panels[panel].AddActor(actor)
        return actor

    def add_polyline(self, panel, points, color, radius):
        """A tube along the points (a path drawn on a surface or a sphere)."""
        from vtkmodules.vtkCommonCore import vtkPoints
        from vtkmodules.vtkCommonDataModel import vtkCellArray
        from vtkmodules.vtkFiltersCore import vtkTubeFilter
        from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

        line = vtkPolyData()
        vtk_points = vtkPoints()
        vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=True))
        line.SetPoints(vtk_points)
        cells = vtkCellArray()
        cells.InsertNextCell(len(points))
        for k in range(len(points)):
            cells.InsertCellPoint(k)
        line.SetLines(cells)
        tube = vtkTubeFilter()
        tube.SetInputData(line)
        tube.SetRadius(radius)
        tube.SetNumberOfSides(10)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(tube.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*color)
        self.panels[panel].AddActor(actor)

    def add_ball(self, panel, center, radius, color):
        from vtkmodules.vtkFiltersSources import vtkSphereSource
        from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

        ball = vtkSphereSource()
        ball.SetCenter(*center)
        ball.SetRadius(radius)
        ball.SetThetaResolution(16)
        ball.SetPhiResolution(12)
        mapper = vtkPolyDataMapper()
        mapper.SetInputConnection(ball.GetOutputPort())
        actor = vtkActor()
        actor.SetMapper(mapper)
        actor.GetProperty().SetColor(*color)
        self.panels[panel].AddActor(actor)

    def add_scalar_bar(self, panel, lookup_table, title):
        from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor

        bar = vtkScalarBarActor()
        bar.SetLookupTable(lookup_table)
        bar.SetTitle(title)
        bar.SetNumberOfLabels(5)
        bar.SetOrientationToHorizontal()
        bar.SetWidth(0.8)
        bar.SetHeight(0.12)
        bar.SetPosition(0.1, 0.02)
        for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
            text.SetColor(0, 0, 0)
            text.ItalicOff()
            text.ShadowOff()
        self.panels[panel].AddActor2D(bar)

    def add_text(self, panel, lines, size=15):
        """Lines of text at the panel's top left."""
        from vtkmodules.vtkRenderingCore import vtkTextActor

        # Display coordinates are the window's: start at the panel's left edge.
        left = int(round(self.window.GetSize()[0] * panel / len(self.panels)))
        for k, text in enumerate(lines):
            label = vtkTextActor()
            label.SetInput(text)
            label.SetDisplayPosition(left + 8, self.height - 24 - (size + 5) * k)
            label.GetTextProperty().SetColor(0, 0, 0)
            label.GetTextProperty().SetFontSize(size)
            self.panels[panel].AddActor2D(label)

    def look(self, panel, focal_point, direction, view_up, zoom=1.0, lower=0.15):
        """Points panel's camera at `focal_point` from along `direction`, then fits the view,
        shifted down by `lower` of the panel's half height (room for the text on top)."""
        renderer = self.panels[panel]
        camera = renderer.GetActiveCamera()
        camera.SetFocalPoint(*focal_point)
        camera.SetPosition(*(np.asarray(focal_point) + 10 * np.asarray(direction) / np.linalg.norm(direction)))
        camera.SetViewUp(*view_up)
        renderer.ResetCamera()
        camera.Zoom(zoom)
        camera.SetWindowCenter(0, lower)

    def write(self, path):
        from vtkmodules.vtkIOImage import vtkPNGWriter
        from vtkmodules.vtkRenderingCore import vtkWindowToImageFilter

        self.window.Render()
        grab = vtkWindowToImageFilter()
        grab.SetInput(self.window)
        grab.Update()
        writer = vtkPNGWriter()
        writer.SetFileName(path)
        writer.SetInputConnection(grab.GetOutputPort())
        writer.Write()


def diverging_lookup_table(low, high):
    """Blue - light grey - red over [low, high] (ParaView's Cool to Warm)."""
    from vtkmodules.vtkRenderingCore import vtkColorTransferFunction

    table = vtkColorTransferFunction()
    table.SetColorSpaceToDiverging()
    table.AddRGBPoint(low, 0.23, 0.30, 0.75)
    table.AddRGBPoint(0.5 * (low + high), 0.87, 0.87, 0.87)
    table.AddRGBPoint(high, 0.71, 0.02, 0.15)
    return table
