"""Spherical orbifold maps with n-fold cyclic symmetry (the paper's Section 7.2) of one mesh,
for several n: their symmetry, checked here independently of the filter's own figure, their
area distortion against the plain spherical map, and a picture of the coverings.

Usage (Debian's python3 with the built package on PYTHONPATH, or pvpython; the picture needs
an X display, e.g. xvfb-run -a):
    python3 orbifold_map.py --output DIR MESH [--copies 2 3 4] [--cones I J]

For each n, vtkSphericalOrbifoldMap (OutputCovering on) maps the n-fold cyclic covering of
MESH (n copies of it cut open between two cone vertices and glued in a ring) onto the sphere.
The script then measures, from the output's points alone:
  symmetry     the largest distance between a vertex of copy i turned by 2 pi / n about the
               axis through the two cones' images and the same vertex of copy i + 1 (0 for an
               exactly n-fold symmetric map);
  moved        the same for the map composed with a Möbius transformation (a dilation by
               --mobius-factor toward a random direction): another conformal map of the
               covering, not centered, and not symmetric;
  recentered   the same after vtkMobiusCenter centers the moved map again: the centered map
               is unique up to a rotation, so it is symmetric again;
  area         the area-weighted standard deviation of log(a triangle's share of the sphere /
               its share of the surface) over the covering (0: area-preserving), against the
               same figure for the plain centered spherical map (vtkMobiusCenter).
It writes
  DIR/orbifold_map.csv   one row per n with those figures and the filter's own;
  DIR/orbifold_map.png   the surface colored by position, with the cut (black) and the cones
                         (red: cone 1, blue: cone 0); its plain centered spherical map; and
                         the coverings seen from cone 1's pole, in the same colors, the
                         images of the cut separating the n copies.
"""
import argparse
import math
import os
import sys

import numpy as np
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkPolyData

from mobiusregistration import vtkMobiusCenter, vtkSphericalConformalMap, vtkSphericalOrbifoldMap

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from example_pictures import (write_csv, PanelPicture, field, points_of, principal_frame,  # noqa: E402
                              read_mesh, run_filter, std_log_area_ratio, triangles_of)


def with_points(data, points):
    copy = vtkPolyData()
    copy.DeepCopy(data)
    vtk_points = vtkPoints()
    vtk_points.SetData(numpy_to_vtk(np.ascontiguousarray(points, dtype=float), deep=True))
    copy.SetPoints(vtk_points)
    return copy


def point_array(data, name):
    return vtk_to_numpy(data.GetPointData().GetArray(name))


def cone_points(covering, cones):
    """Indices of the two cones' points in the covering (the points with Copy -1)."""
    ids, copy = point_array(covering, "InputPointId"), point_array(covering, "Copy")
    return [int(np.flatnonzero((ids == cone) & (copy == -1))[0]) for cone in cones]


def rotation(axis, angle):
    """Rotation by `angle` about the unit vector `axis` (Rodrigues)."""
    k = np.array([[0, -axis[2], axis[1]], [axis[2], 0, -axis[0]], [-axis[1], axis[0], 0]])
    return np.eye(3) + math.sin(angle) * k + (1 - math.cos(angle)) * k @ k


def symmetry_error(covering, points, cones, n):
    """max |R x(v, copy i) - x(v, copy i + 1)| over the covering's vertices, R the turn by
    2 pi / n (either way round, the better) about the axis through the cones' images."""
    ids, copy = point_array(covering, "InputPointId"), point_array(covering, "Copy")
    where = {(int(v), int(c)): k for k, (v, c) in enumerate(zip(ids, copy)) if c >= 0}
    pairs = np.array([(k, where[(v, (c + 1) % n)]) for (v, c), k in where.items()])
    south, north = (points[k] for k in cone_points(covering, cones))
    axis = (north - south) / np.linalg.norm(north - south)
    return min(np.linalg.norm(points[pairs[:, 0]] @ rotation(axis, s * 2 * math.pi / n).T - points[pairs[:, 1]],
                              axis=1).max() for s in (1, -1))


def moved_by_mobius(points, direction, factor):
    """The points moved by a Möbius transformation of the sphere: in stereographic
    coordinates from -direction, z -> factor * z (points crowd toward `direction`)."""
    t = points @ direction
    z = factor * (points - t[:, None] * direction) / np.maximum(1 + t, 1e-12)[:, None]
    r2 = (z * z).sum(axis=1)
    moved = ((1 - r2) / (1 + r2))[:, None] * direction + 2 * z / (1 + r2)[:, None]
    return moved / np.linalg.norm(moved, axis=1)[:, None]


# One color per copy of the surface in the covering (matplotlib's tab10).
COPY_COLORS = np.array([(31, 119, 180), (255, 127, 14), (44, 160, 44), (214, 39, 40), (148, 103, 189),
                        (140, 86, 75), (227, 119, 194), (127, 127, 127)]) / 255.0


def checker_colors(data, surface_points, cell_copy, square):
    """Per triangle: its copy's color, lighter or darker as a 3-D checkerboard of squares of
    side `square` on the surface (at the triangle's centroid): the same pattern on every copy."""
    triangles = triangles_of(data)
    centroid = surface_points[triangles].mean(axis=1)
    checker = np.floor(centroid / square).astype(int).sum(axis=1) % 2
    return COPY_COLORS[cell_copy % len(COPY_COLORS)] * (0.62 + 0.38 * checker)[:, None]


def orbifold_maps(mesh, copies, cones, factor, seed):
    conformal = vtkSphericalConformalMap()
    conformal.SetInputData(mesh)
    sphere_map, _ = run_filter(conformal, "spherical conformal map")
    center = vtkMobiusCenter()
    center.SetInputData(sphere_map)
    plain, _ = run_filter(center, "centering the plain map")
    plain_area = std_log_area_ratio(plain, points_of(plain))

    rows, coverings = [], {}
    direction = np.random.default_rng(seed).normal(size=3)
    direction /= np.linalg.norm(direction)
    for n in copies:
        orbifold = vtkSphericalOrbifoldMap()
        orbifold.SetInputData(sphere_map)  # its InputPointId names the cones: the file's numbering
        orbifold.SetNumberOfCopies(n)
        orbifold.SetConeIds(*(cones or (-1, -1)))
        orbifold.OutputCoveringOn()
        covering, warnings = run_filter(orbifold, f"orbifold map, n = {n}")
        for warning in warnings:
            print(f"n = {n}: warning: {warning}")
        used = [int(field(covering, "ConeIds", k)) for k in range(2)]
        x = points_of(covering)
        moved = with_points(covering, moved_by_mobius(x, direction, factor))
        recenter = vtkMobiusCenter()
        recenter.SetInputData(moved)
        recentered, _ = run_filter(recenter, f"centering the moved covering, n = {n}")
        row = dict(
            copies=n, cone0=used[0], cone1=used[1], points=covering.GetNumberOfPoints(),
            symmetry_error=f"{symmetry_error(covering, x, used, n):.3g}",
            moved_symmetry_error=f"{symmetry_error(covering, points_of(moved), used, n):.3g}",
            recentered_symmetry_error=f"{symmetry_error(covering, points_of(recentered), used, n):.3g}",
            std_log_area_ratio=f"{std_log_area_ratio(covering, x):.4f}",
            plain_std_log_area_ratio=f"{plain_area:.4f}",
            filter_symmetry_error=f"{field(covering, 'SymmetryError'):.3g}",
            filter_std_log_area_ratio=f"{field(covering, 'StdLogAreaRatio'):.4f}",
            filter_plain_std_log_area_ratio=f"{field(covering, 'PlainStdLogAreaRatio'):.4f}",
            flipped_triangles=int(field(covering, "FlippedTriangles")),
            flow_iterations=int(field(covering, "ConformalFlowIterations")))
        rows.append(row)
        coverings[n] = covering
        print(f"n = {n}: cones {used[0]} {used[1]}, symmetry error {row['symmetry_error']} (moved by a Möbius "
              f"transformation {row['moved_symmetry_error']}, centered again {row['recentered_symmetry_error']}); "
              f"std of log area ratio {row['std_log_area_ratio']} (plain map {row['plain_std_log_area_ratio']}); "
              f"{row['flipped_triangles']} flipped triangles", flush=True)
    return plain, coverings, rows


def cut_polyline(covering, points, cut, copy):
    """The image on copy `copy` of the cut path (input ids, cone to cone)."""
    ids, copies = point_array(covering, "InputPointId"), point_array(covering, "Copy")
    lookup = {(int(v), int(c)): k for k, (v, c) in enumerate(zip(ids, copies))}
    return np.array([points[lookup.get((v, copy), lookup.get((v, -1)))] for v in cut])


def render(mesh, name, plain, coverings, rows, path):
    surface = points_of(mesh)
    mean, frame = principal_frame(surface)
    size = np.linalg.norm(surface.max(axis=0) - surface.min(axis=0))
    square = size / 12

    def colors(data, cell_copy=None):
        points = point_array(data, "SurfacePoints").astype(float) if data is not mesh else surface
        copies = np.zeros(data.GetNumberOfCells(), dtype=int) if cell_copy is None else cell_copy
        return checker_colors(data, points, copies, square)

    picture = PanelPicture(2 + len(coverings), 330, 330)
    first = next(iter(coverings.values()))
    cones = [int(field(first, "ConeIds", k)) for k in range(2)]
    cut_array = first.GetFieldData().GetArray("CutPathPointIds")
    cut = [int(cut_array.GetComponent(k, 0)) for k in range(cut_array.GetNumberOfTuples())]
    picture.add_surface(0, mesh, cell_rgb=colors(mesh))
    # InputPointId numbers the file's vertices, which are the reader's points.
    picture.add_polyline(0, surface[cut], (0, 0, 0), 0.005 * size)
    for cone in cones:
        picture.add_ball(0, surface[cone], 0.015 * size, (0.1, 0.1, 0.1))
    # From beside the shape and a little toward the cut (along the cow's back), the cut's
    # side up.
    side = surface[cut].mean(axis=0) - mean
    side -= (side @ frame[:, 2]) * frame[:, 2]
    side = side / np.linalg.norm(side) if np.linalg.norm(side) > 0 else frame[:, 0]
    across = np.cross(side, frame[:, 2])
    picture.look(0, mean, 0.6 * side - across, side, 1.15)
    picture.add_text(0, [f"{name}: the cut between the cones"])

    plain_points = points_of(plain)
    ids = point_array(plain, "InputPointId")
    north = plain_points[int(np.flatnonzero(ids == cones[1])[0])]
    up = np.cross(north, frame[:, 0] if abs(north @ frame[:, 0]) < 0.9 else frame[:, 1])
    picture.add_surface(1, plain, cell_rgb=colors(plain))
    picture.look(1, (0, 0, 0), north, up, 1.15)
    picture.add_text(1, ["plain spherical map, centered", f"area distortion {rows[0]['plain_std_log_area_ratio']}",
                         "seen from cone 1"])

    for panel, (row, (n, covering)) in enumerate(zip(rows, coverings.items()), start=2):
        x = points_of(covering)
        cell_copy = vtk_to_numpy(covering.GetCellData().GetArray("Copy")).astype(int)
        picture.add_surface(panel, covering, cell_rgb=colors(covering, cell_copy))
        for copy in range(n):
            picture.add_polyline(panel, 1.003 * cut_polyline(covering, x, cut, copy), (0, 0, 0), 0.008)
        picture.add_ball(panel, (0, 0, 1), 0.03, (0.1, 0.1, 0.1))
        picture.look(panel, (0, 0, 0), (0, 0, 1), (0, 1, 0), 1.15)
        picture.add_text(panel, [f"n = {n}: the covering, from cone 1", f"area distortion {row['std_log_area_ratio']}",
                                 f"symmetry error {float(row['symmetry_error']):.0e}"])
    picture.write(path)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("mesh", help="a closed genus-0 mesh (.off .obj .ply .stl .vtp .vtk)")
    parser.add_argument("--output", default="orbifold_map_output", help="folder for the results")
    parser.add_argument("--copies", type=int, nargs="+", default=[2, 3, 4], help="the values of n (2..8)")
    parser.add_argument("--cones", type=int, nargs=2, metavar=("I", "J"),
                        help="the cone vertices (vertex numbers in the file); default two far-apart ones")
    parser.add_argument("--mobius-factor", type=float, default=3.0,
                        help="the dilation of the 'moved' maps' Möbius transformation")
    parser.add_argument("--no-picture", action="store_true", help="only the table (no X display needed)")
    args = parser.parse_args()
    os.makedirs(args.output, exist_ok=True)
    name = os.path.splitext(os.path.basename(args.mesh))[0]
    try:
        mesh = read_mesh(args.mesh)
        plain, coverings, rows = orbifold_maps(mesh, args.copies, args.cones, args.mobius_factor, seed=7)
    except RuntimeError as error:
        raise SystemExit(f"{args.mesh}: {error}")
    table = os.path.join(args.output, "orbifold_map.csv")
    write_csv(rows, table)
    print("wrote", table)
    if not args.no_picture:
        picture = os.path.join(args.output, "orbifold_map.png")
        render(mesh, name, plain, coverings, rows, picture)
        print("wrote", picture)


if __name__ == "__main__":
    sys.exit(main())
