"""The paper's Figures 8 and 9 on the meshes at hand: bilateral symmetry distances with and
without centering, and a shape colored by its asymmetry next to its centered spherical map.

Usage (Debian's python3 with the built package on PYTHONPATH, or pvpython):
    python3 symmetry_distances.py --output DIR MESH...    (e.g. build/data/meshes/*.off)

For each mesh and for a bent copy of it, runs vtkSymmetryDetection on three spherical maps:
  centered    `Centering` on: the paper's method (centering between the flow's steps, then
              vtkMobiusCenter);
  uncentered  `Centering` off: the flow without any centering (it drifts; the map is often
              degenerate, which the table notes);
  moved       the flow's converged map composed with a Möbius transformation (a dilation by
              --mobius-factor toward a random direction), `Centering` off: an arbitrary
              conformal map of the shape, the paper's "uncentered" parameterization;
and writes
  DIR/symmetry_distances.csv   one row per run: the symmetry distance (0 symmetric, about 0.71
                               no better than an unrelated signal), the flow's degenerate-map
                               reason if any, the seconds; meshes that cannot be mapped (two
                               parts of one size, ...) get their error instead;
  DIR/symmetry_distances.png   the cumulative distribution of the distances for each
                               variant (Figure 8; matplotlib);
  DIR/symmetry_asymmetry.png   the first mesh colored by its per-vertex Asymmetry, and its
                               centered spherical map pushed out along the normal by the log
                               of the conformal scale factor, with the mirror plane that the
                               best reflection found (Figure 9; VTK, needs an X display).

The bent copy is mobius-benchmark's BentCopy without its rigid rotation (a rotation changes
no spherical map up to rotation): the mesh, in its principal axes (x smallest, z largest
variance), bent about an axis parallel to x at distance 5 standard deviations of z, i.e.
bent in the plane of its two largest axes. The symmetry distance depends only on the
registration, so the runs skip the refinement (`Refine` off); the picture's run refines.
"""
import argparse
import math
import os
import sys
import time

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from mobiusregistration import vtkMobiusCenter, vtkSphericalConformalMap, vtkSymmetryDetection

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from example_pictures import Messages, read_mesh, write_csv  # noqa: E402


def points_of(mesh):
    return vtk_to_numpy(mesh.GetPoints().GetData()).astype(float)


def bent_copy(mesh):
    """The mesh bent along its longest principal axis (mobius-benchmark's BentCopy)."""
    p = points_of(mesh)
    mean = p.mean(axis=0)
    values, frame = np.linalg.eigh(np.cov((p - mean).T, bias=True))  # ascending variances
    radius = 5 * math.sqrt(values[2])
    y = (p - mean) @ frame
    angle = y[:, 2] / radius
    bent = np.column_stack([y[:, 0], (radius + y[:, 1]) * np.cos(angle) - radius,
                            (radius + y[:, 1]) * np.sin(angle)])
    copy = vtkPolyData()
    copy.DeepCopy(mesh)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(bent @ frame.T), deep=True))
    copy.SetPoints(points)
    return copy


def detect(data, centering, refine, resolution):
    """Runs vtkSymmetryDetection on a mesh or a spherical map; returns (output, messages)."""
    symmetry = vtkSymmetryDetection()
    symmetry.SetInputData(data)
    symmetry.SetCentering(centering)
    symmetry.SetRefine(refine)
    symmetry.SetResolution(resolution)
    messages = Messages(symmetry, symmetry.GetExecutive())
    symmetry.Update()
    return symmetry.GetOutput(), messages


def field(data, name, component=None):
    array = data.GetFieldData().GetAbstractArray(name)
    if array is None:
        return None
    if component is None:
        return array.GetValue(0)
    return [array.GetComponent(0, k) for k in range(array.GetNumberOfComponents())]


def spherical_map(mesh):
    """vtkSphericalConformalMap with its defaults (centering between flow steps: converges)."""
    conformal = vtkSphericalConformalMap()
    conformal.SetInputData(mesh)
    messages = Messages(conformal, conformal.GetExecutive())
    conformal.Update()
    if messages.errors:
        raise RuntimeError(messages.errors[0])
    result = vtkPolyData()
    result.DeepCopy(conformal.GetOutput())
    return result


def moved_by_mobius(sphere_map, direction, factor):
    """The map composed with a Möbius transformation of the sphere: in stereographic
    coordinates from -direction, z -> factor * z (points crowd toward `direction`). It stays
    a conformal map of the same surface, as arbitrary as any uncentered one."""
    x = points_of(sphere_map)
    t = x @ direction
    w = x - t[:, None] * direction
    z = factor * w / np.maximum(1 + t, 1e-12)[:, None]
    r2 = (z * z).sum(axis=1)
    moved = ((1 - r2) / (1 + r2))[:, None] * direction + 2 * z / (1 + r2)[:, None]
    result = vtkPolyData()
    result.DeepCopy(sphere_map)
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(moved / np.linalg.norm(moved, axis=1)[:, None]), deep=True))
    result.SetPoints(points)
    return result


# The three ways of mapping a shape before looking for its reflection.
VARIANTS = ("centered", "uncentered", "moved")


def sweep(paths, resolution, factor):
    rows = []
    directions = np.random.default_rng(8).normal(size=(len(paths) * 2, 3))
    for index, path in enumerate(paths):
        name = os.path.splitext(os.path.basename(path))[0]
        try:
            mesh = read_mesh(path)
            shapes = (("original", mesh), ("bent", bent_copy(mesh)))
            for shape_index, (shape, surface) in enumerate(shapes):
                direction = directions[2 * index + shape_index] / np.linalg.norm(directions[2 * index + shape_index])
                for variant in VARIANTS:
                    start = time.perf_counter()
                    if variant == "moved":
                        data = moved_by_mobius(spherical_map(surface), direction, factor)
                    else:
                        data = surface
                    output, messages = detect(data, variant == "centered", False, resolution)
                    seconds = time.perf_counter() - start
                    distance = field(output, "SymmetryDistance")
                    if distance is None:
                        raise RuntimeError(messages.errors[0] if messages.errors else "no output")
                    row = dict(mesh=name, shape=shape, variant=variant, vertices=mesh.GetNumberOfPoints(),
                               distance=f"{distance:.4f}", degenerate=field(output, "DegenerateMapReason") or "",
                               seconds=f"{seconds:.1f}", error="")
                    rows.append(row)
                    print(f"{name:>10} {shape:>8} {variant:>10}: distance {row['distance']}"
                          + (" (degenerate map)" if row["degenerate"] else "") + f", {row['seconds']} s", flush=True)
        except RuntimeError as error:
            # The same mesh fails the same way in every variant (genus > 0, not closed, ...).
            message = " ".join(str(error).split())
            message = message[message.find("Cannot"):] if "Cannot" in message else message
            rows.append(dict(mesh=name, shape="", variant="", vertices="", distance="", degenerate="",
                             seconds="", error=message))
            print(f"{name:>10}: {message}", flush=True)
    return rows


def plot_distribution(rows, path):
    import matplotlib
    matplotlib.use("Agg")  # files only, no display
    import matplotlib.pyplot as plt

    figure, axes = plt.subplots(figsize=(6.4, 4.2), dpi=100)
    styles = {"centered": ("centered (Centering on)", "tab:blue", "-"),
              "uncentered": ("Centering off (flow without centering)", "tab:red", "--"),
              "moved": ("Centering off, map moved by a Möbius transformation", "tab:orange", "-")}
    for variant in VARIANTS:
        label, color, style = styles[variant]
        runs = [r for r in rows if r["distance"] != "" and r["variant"] == variant]
        values = sorted(float(r["distance"]) for r in runs)
        if not values:
            continue
        # A step at each distance: the fraction of runs at or below it.
        x = [0.0] + [v for v in values for _ in (0, 1)] + [1.0]
        y = [0.0] + [f for i in range(len(values)) for f in (i / len(values), (i + 1) / len(values))] + [1.0]
        degenerate = sum(1 for r in runs if r["degenerate"])
        label += f"\nmedian {np.median(values):.3f}" + (f", {degenerate} of {len(values)} maps degenerate" if degenerate else "")
        axes.plot(x, y, color=color, linestyle=style, linewidth=2, label=label)
    axes.set_xlim(0, 1)
    axes.set_ylim(0, 1.02)
    axes.set_xlabel("symmetry distance (0 symmetric, 0.71 unrelated)")
    axes.set_ylabel("fraction of shapes")
    axes.set_title("Bilateral symmetry distance, CGAL meshes and bent copies")
    axes.axvline(math.sqrt(0.5), color="gray", linestyle=":", linewidth=1)
    axes.grid(alpha=0.3)
    axes.legend(loc="lower right", fontsize=8)
    figure.tight_layout()
    figure.savefig(path)
    plt.close(figure)


def scale_factor_sphere(mesh):
    """The centered spherical map, each vertex pushed along the normal by the log of its
    conformal scale factor (vertex area on the surface / on the sphere, both normalized),
    less its median, scaled so that its 90th percentile is 1 and clipped to [-1, 1]."""
    conformal = vtkSphericalConformalMap()
    conformal.SetInputData(mesh)
    center = vtkMobiusCenter()
    center.SetInputConnection(conformal.GetOutputPort())
    Messages(conformal, conformal.GetExecutive(), center, center.GetExecutive())
    center.Update()
    sphere = vtkPolyData()
    sphere.DeepCopy(center.GetOutput())
    x = points_of(sphere)
    s = vtk_to_numpy(sphere.GetPointData().GetArray("SurfacePoints")).astype(float)
    faces = vtk_to_numpy(sphere.GetPolys().GetConnectivityArray()).reshape(-1, 3)

    def vertex_areas(p):
        a = 0.5 * np.linalg.norm(np.cross(p[faces[:, 1]] - p[faces[:, 0]], p[faces[:, 2]] - p[faces[:, 0]]), axis=1)
        areas = np.zeros(len(p))
        for k in range(3):
            np.add.at(areas, faces[:, k], a / 3)
        return areas / a.sum()

    log_factor = 0.5 * np.log(np.maximum(vertex_areas(s), 1e-300) / np.maximum(vertex_areas(x), 1e-300))
    log_factor -= np.median(log_factor)
    # A few vertices (tips of horns, fingers) have extreme factors: scale by the 90th percentile.
    scale = max(np.percentile(np.abs(log_factor), 90), 1e-12)
    log_factor = np.clip(log_factor / scale, -1, 1)
    pushed = x * (1 + 0.25 * log_factor)[:, None]
    points = vtkPoints()
    points.SetData(numpy_to_vtk(np.ascontiguousarray(pushed), deep=True))
    sphere.SetPoints(points)
    values = numpy_to_vtk(log_factor, deep=True)
    values.SetName("LogScaleFactor")
    sphere.GetPointData().AddArray(values)
    return sphere


def render_picture(mesh, name, output, path):
    """Figure 9: left the surface colored by Asymmetry, right its centered spherical map with
    the scale factor as a normal offset and the best reflection's mirror plane."""
    from vtkmodules.vtkFiltersCore import vtkTubeFilter
    from vtkmodules.vtkFiltersSources import vtkRegularPolygonSource
    from vtkmodules.vtkIOImage import vtkPNGWriter
    from vtkmodules.vtkRenderingAnnotation import vtkScalarBarActor
    from vtkmodules.vtkRenderingCore import (vtkActor, vtkColorTransferFunction, vtkPolyDataMapper,
                                             vtkRenderer, vtkRenderWindow, vtkTextActor,
                                             vtkWindowToImageFilter)
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401 (the rendering backend)
    import vtkmodules.vtkRenderingFreeType  # noqa: F401 (text)

    def colors(low, high, stops):
        lut = vtkColorTransferFunction()
        for t, rgb in stops:
            lut.AddRGBPoint(low + t * (high - low), *rgb)
        return lut

    inferno = [(0.0, (0.0, 0.0, 0.02)), (0.25, (0.34, 0.06, 0.43)), (0.5, (0.73, 0.21, 0.33)),
               (0.75, (0.98, 0.55, 0.04)), (1.0, (0.99, 1.0, 0.64))]
    cool_warm = [(0.0, (0.23, 0.30, 0.75)), (0.5, (0.87, 0.87, 0.87)), (1.0, (0.71, 0.02, 0.15))]

    window = vtkRenderWindow()
    window.SetOffScreenRendering(True)
    window.SetSize(1200, 560)
    p = points_of(output)
    mean = p.mean(axis=0)
    _, frame = np.linalg.eigh(np.cov((p - mean).T, bias=True))
    asymmetry = output.GetPointData().GetArray("Asymmetry")
    high = max(asymmetry.GetRange()[1], 1e-6)

    # The surface: a three-quarter view in its principal frame.
    left = vtkRenderer()
    left.SetViewport(0, 0, 0.5, 1)
    left.SetBackground(1, 1, 1)
    mapper = vtkPolyDataMapper()
    mapper.SetInputData(output)
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("Asymmetry")
    lut = colors(0.0, high, inferno)
    mapper.SetLookupTable(lut)
    mapper.SetUseLookupTableScalarRange(True)
    actor = vtkActor()
    actor.SetMapper(mapper)
    left.AddActor(actor)
    bar = vtkScalarBarActor()
    bar.SetLookupTable(lut)
    bar.SetTitle("Asymmetry")
    bar.SetNumberOfLabels(3)
    bar.SetWidth(0.1)
    bar.SetHeight(0.5)
    bar.SetPosition(0.87, 0.1)
    for text in (bar.GetTitleTextProperty(), bar.GetLabelTextProperty()):
        text.SetColor(0, 0, 0)
    left.AddActor2D(bar)
    direction = frame[:, 0] + 0.6 * frame[:, 1] + 0.6 * frame[:, 2]
    camera = left.GetActiveCamera()
    camera.SetFocalPoint(*mean)
    camera.SetPosition(*(mean + direction))
    camera.SetViewUp(*frame[:, 1])
    left.ResetCamera()
    window.AddRenderer(left)

    # The centered sphere, offset by the scale factor, and the mirror plane x . n = 0.
    right = vtkRenderer()
    right.SetViewport(0.5, 0, 1, 1)
    right.SetBackground(1, 1, 1)
    sphere = scale_factor_sphere(mesh)
    extent = 1.0  # the factor's log, scaled to [-1, 1]
    sphere_mapper = vtkPolyDataMapper()
    sphere_mapper.SetInputData(sphere)
    sphere_mapper.SetScalarModeToUsePointFieldData()
    sphere_mapper.SelectColorArray("LogScaleFactor")
    sphere_mapper.SetLookupTable(colors(-extent, extent, cool_warm))
    sphere_mapper.SetUseLookupTableScalarRange(True)
    sphere_actor = vtkActor()
    sphere_actor.SetMapper(sphere_mapper)
    right.AddActor(sphere_actor)
    # The mirror plane's great circle, just outside the pushed-out sphere.
    normal = np.array(field(output, "MirrorPlaneNormal", component=True))
    circle = vtkRegularPolygonSource()
    circle.SetNumberOfSides(180)
    circle.SetRadius(1.3)
    circle.SetNormal(*normal)
    circle.GeneratePolygonOff()
    tube = vtkTubeFilter()
    tube.SetInputConnection(circle.GetOutputPort())
    tube.SetRadius(0.012)
    tube.SetNumberOfSides(12)
    circle_mapper = vtkPolyDataMapper()
    circle_mapper.SetInputConnection(tube.GetOutputPort())
    circle_actor = vtkActor()
    circle_actor.SetMapper(circle_mapper)
    circle_actor.GetProperty().SetColor(0.1, 0.6, 0.2)
    right.AddActor(circle_actor)
    # Look along the plane, so that it shows as a vertical line between the two halves that
    # the reflection swaps, from the side where the scale factor varies most.
    x = points_of(sphere)
    x /= np.linalg.norm(x, axis=1)[:, None]
    values = vtk_to_numpy(sphere.GetPointData().GetArray("LogScaleFactor"))
    helper = np.array([0.0, 0.0, 1.0]) if abs(normal[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
    u = np.cross(normal, helper)
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    candidates = [math.cos(a) * u + math.sin(a) * v for a in np.linspace(0, 2 * math.pi, 24, endpoint=False)]
    view = max(candidates, key=lambda d: values[x @ d > 0.3].std() if (x @ d > 0.3).sum() > 2 else 0)
    sphere_camera = right.GetActiveCamera()
    sphere_camera.SetFocalPoint(0, 0, 0)
    sphere_camera.SetPosition(*(5 * view))
    sphere_camera.SetViewUp(*np.cross(normal, view))
    right.ResetCamera()
    window.AddRenderer(right)

    for text, x in ((f"{name}: symmetry distance {field(output, 'SymmetryDistance'):.3f}", 10),
                    ("centered map, offset by the log scale factor; mirror plane", 610)):
        label = vtkTextActor()
        label.SetInput(text)
        label.SetDisplayPosition(x, 530)
        label.GetTextProperty().SetColor(0, 0, 0)
        label.GetTextProperty().SetFontSize(18)
        (left if x < 600 else right).AddActor2D(label)

    window.Render()
    grab = vtkWindowToImageFilter()
    grab.SetInput(window)
    grab.Update()
    writer = vtkPNGWriter()
    writer.SetFileName(path)
    writer.SetInputConnection(grab.GetOutputPort())
    writer.Write()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("meshes", nargs="+", help="meshes (.off .obj .ply .stl .vtp .vtk); one that is no closed genus-0 surface is repaired into one")
    parser.add_argument("--output", default="symmetry_distances_output", help="folder for the results")
    parser.add_argument("--resolution", type=int, default=128, help="scale-factor grid size")
    parser.add_argument("--mobius-factor", type=float, default=3.0,
                        help="the dilation of the 'moved' maps' Möbius transformation")
    parser.add_argument("--picture", help="the mesh for the asymmetry picture (default: the first "
                        "that maps); 'none' for no picture (no X display needed)")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)

    rows = sweep(args.meshes, args.resolution, args.mobius_factor)
    write_csv(rows, os.path.join(args.output, "symmetry_distances.csv"))
    if not any(r["distance"] != "" for r in rows):
        raise SystemExit("no mesh could be mapped: nothing to plot")
    plot_distribution(rows, os.path.join(args.output, "symmetry_distances.png"))
    for variant in VARIANTS:
        values = [float(r["distance"]) for r in rows if r["distance"] != "" and r["variant"] == variant]
        print(f"{variant:>10}: {len(values)} runs, median {np.median(values):.4f}, "
              f"quartiles {np.percentile(values, 25):.4f} {np.percentile(values, 75):.4f}")

    if args.picture == "none":
        return
    picture = args.picture or next(m for m in args.meshes if any(
        r["mesh"] == os.path.splitext(os.path.basename(m))[0] and r["distance"] != "" for r in rows))
    if not os.environ.get("DISPLAY"):
        raise SystemExit("the asymmetry picture needs an X display (Debian's VTK renders through "
                         "GLX): run under xvfb-run, or pass --picture none")
    mesh = read_mesh(picture)
    output, messages = detect(mesh, True, True, args.resolution)
    if field(output, "SymmetryDistance") is None:
        raise SystemExit(f"{picture}: " + (messages.errors[0] if messages.errors else "no output"))
    name = os.path.splitext(os.path.basename(picture))[0]
    render_picture(mesh, name, output, os.path.join(args.output, "symmetry_asymmetry.png"))
    print(f"{name}: mean asymmetry {field(output, 'MeanAsymmetry'):.4f}, maximum "
          f"{field(output, 'MaximumAsymmetry'):.4f} of sqrt(area)")
    print("wrote", ", ".join(os.path.join(args.output, f) for f in (
        "symmetry_distances.csv", "symmetry_distances.png", "symmetry_asymmetry.png")))


if __name__ == "__main__":
    sys.exit(main())
