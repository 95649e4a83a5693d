"""The paper's Figure 5 on one mesh: its centered spherical map at several generalized-centering
degrees (vtkMobiusCenter's Degree), colored by how much area each triangle gets, with the area
and angle distortion of each.

Usage (Debian's python3 with the built package on PYTHONPATH, or pvpython; the picture needs
an X display, e.g. xvfb-run -a):
    python3 generalized_centering.py --output DIR MESH [--degrees 1 2 3]

Degree 1 is the paper's Möbius centering (a conformal map); a higher degree L goes on to
advect the map until its area has no component along the spherical harmonics of degree 1 to
L, spreading area more evenly at the cost of conformality. Per degree it measures
  area distortion    the area-weighted standard deviation over the triangles of
                     log(share of the sphere / share of the surface), 0 if area-preserving;
  angle distortion   the area-weighted mean of the filter's QuasiConformalDistortion
                     (sigma_max / sigma_min of each triangle's map), 1 if conformal;
  steps, moments     the advection steps taken and the norm of the moments left
                     (CenterOfMassNorm; the steps stop at GeneralizedTolerance, at
                     GeneralizedMaximumNumberOfIterations, or when no step can lower the
                     moments without flipping a triangle);
  flipped            triangles facing inward on the sphere (the advection allows none);
and writes
  DIR/generalized_centering.csv   one row per degree;
  DIR/generalized_centering.png   the surface, then the map at each degree colored by
                                  LogAreaRatio (log2 of the triangle's share of the sphere
                                  over its share of the surface; blue: squeezed, red:
                                  enlarged), all seen from the same direction.
"""
import argparse
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy

from mobiusregistration import vtkMobiusCenter, vtkSphericalConformalMap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from example_pictures import (write_csv, PanelPicture, diverging_lookup_table, field,  # noqa: E402
                              points_of, principal_frame, read_mesh, run_filter,
                              std_log_area_ratio, triangles_of)


def flipped_triangles(sphere_map):
    """Triangles of the map whose normal points into the sphere."""
    x = points_of(sphere_map)
    a, b, c = (x[triangles_of(sphere_map)[:, k]] for k in range(3))
    return int((np.einsum("ij,ij->i", np.cross(b - a, c - a), a + b + c) < 0).sum())


def centered_maps(mesh, degrees):
    conformal = vtkSphericalConformalMap()
    conformal.SetInputData(mesh)
    sphere_map, _ = run_filter(conformal, "spherical conformal map")
    maps, rows = {}, []
    for degree in degrees:
        center = vtkMobiusCenter()
        center.SetInputData(sphere_map)
        center.SetDegree(degree)
        centered, warnings = run_filter(center, f"centering at degree {degree}")
        surface_area = vtk_to_numpy(centered.GetCellData().GetArray("SurfaceArea")).astype(float)
        quasi_conformal = vtk_to_numpy(centered.GetCellData().GetArray("QuasiConformalDistortion"))
        row = dict(degree=degree,
                   area_distortion=f"{std_log_area_ratio(centered, points_of(centered)):.4f}",
                   angle_distortion=f"{np.sum(surface_area * quasi_conformal) / surface_area.sum():.4f}",
                   steps=int(field(centered, "GeneralizedCenteringIterations")),
                   moments_left=f"{field(centered, 'CenterOfMassNorm'):.2g}",
                   converged=int(not warnings),  # the filter warns when it stops above its tolerance
                   flipped_triangles=flipped_triangles(centered))
        rows.append(row)
        maps[degree] = centered
        print(f"degree {degree}: area distortion {row['area_distortion']}, angle distortion "
              f"{row['angle_distortion']}, {row['steps']} steps, moments left {row['moments_left']}"
              + ("" if row["converged"] else " (not converged)")
              + f", {row['flipped_triangles']} flipped triangles", flush=True)
    return maps, rows


def render(mesh, name, maps, rows, path, limit):
    surface = points_of(mesh)
    mean, frame = principal_frame(surface)
    picture = PanelPicture(1 + len(maps), 330, 380)
    picture.add_surface(0, mesh)
    picture.look(0, mean, frame[:, 0] + 0.4 * frame[:, 1], frame[:, 2], 0.95, lower=0.05)
    picture.add_text(0, [f"{name}, {mesh.GetNumberOfPoints():,} vertices"])
    table = diverging_lookup_table(-limit, limit)
    # The degree-1 map's most squeezed region (its smallest LogAreaRatio, the shape's thin
    # parts) faces the viewer: the higher degrees spread it out.
    first = next(iter(maps.values()))
    log_ratio = vtk_to_numpy(first.GetCellData().GetArray("LogAreaRatio"))
    x = points_of(first)
    centroids = x[triangles_of(first)].mean(axis=1)
    view = centroids[log_ratio < np.percentile(log_ratio, 10)].mean(axis=0)
    view = view / np.linalg.norm(view) if np.linalg.norm(view) > 1e-6 else np.array([0.0, 0.0, 1.0])
    up = np.cross(view, [1.0, 0.0, 0.0] if abs(view[0]) < 0.9 else [0.0, 1.0, 0.0])
    for panel, (row, (degree, centered)) in enumerate(zip(rows, maps.items()), start=1):
        picture.add_surface(panel, centered, scalars="LogAreaRatio", lookup_table=table)
        picture.look(panel, (0, 0, 0), view, up, 1.1)
        picture.add_text(panel, [f"degree {degree}" + (" (Moebius centering)" if degree == 1 else ""),
                                 f"area distortion {row['area_distortion']}",
                                 f"angle distortion {row['angle_distortion']}"]
                         + ([] if degree == 1 else [f"{row['steps']} steps, moments left {row['moments_left']}"]))
    picture.add_scalar_bar(0, table, "log2 area ratio")
    picture.write(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", help="a closed genus-0 mesh (.off .obj .ply .stl .vtp .vtk)")
    parser.add_argument("--output", default="generalized_centering_output", help="folder for the results")
    parser.add_argument("--degrees", type=int, nargs="+", default=[1, 2, 3], help="centering degrees (1..8)")
    parser.add_argument("--color-limit", type=float, default=3.0,
                        help="the colors span log2 area ratios from -LIMIT to LIMIT")
    parser.add_argument("--no-picture", action="store_true", help="only the table (no X display needed)")
    args = parser.parse_args()
    if any(not 1 <= d <= 8 for d in args.degrees):
        parser.error("--degrees: each degree must be from 1 to 8")
    os.makedirs(args.output, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.mesh))[0]
    try:
        mesh = read_mesh(args.mesh)
        maps, rows = centered_maps(mesh, args.degrees)
    except RuntimeError as error:
        raise SystemExit(f"{args.mesh}: {error}")
    table = os.path.join(args.output, "generalized_centering.csv")
    write_csv(rows, table)
    print("wrote", table)
    if not args.no_picture:
        picture = os.path.join(args.output, "generalized_centering.png")
        render(mesh, name, maps, rows, picture, args.color_limit)
        print("wrote", picture)


if __name__ == "__main__":
    sys.exit(main())
