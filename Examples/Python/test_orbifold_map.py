"""Runs orbifold_map.py on CGAL's cow (CC0) for n = 2, 3, 4 and checks what it wrote: the
coverings are n-fold symmetric by the script's own measure (from the output points alone) and
the filter's, a Möbius-moved copy is not and is again once centered, no triangle is flipped,
the orbifold maps have less area distortion than the plain map, and the picture shows the n
copies of each covering in their n colors.

Usage: python3 test_orbifold_map.py MESH_DIR OUTPUT_DIR   (the package on PYTHONPATH, X display)
"""
import colorsys
import csv
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

mesh_dir, output = sys.argv[1:3]
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "orbifold_map.py")
cow = os.path.join(mesh_dir, "cow.off")
subprocess.run([sys.executable, script, cow, "--output", output, "--copies", "2", "3", "4"], check=True)
with open(cow) as f:
    f.readline()
    vertices = int(f.readline().split()[0])

with open(os.path.join(output, "orbifold_map.csv")) as table:
    rows = list(csv.DictReader(table))
assert [int(r["copies"]) for r in rows] == [2, 3, 4], rows
for r in rows:
    n = int(r["copies"])
    number = lambda key: float(r[key])
    assert int(r["points"]) == n * (vertices - 2) + 2, r
    # Symmetric to far below the vertex spacing (the cow's squeezed tail tip, 1e-7 from the
    # pole at n = 2, is the worst), as the filter reports too.
    assert number("symmetry_error") < 1e-6 and number("filter_symmetry_error") < 1e-6, r
    assert number("moved_symmetry_error") > 0.05, r
    assert number("recentered_symmetry_error") < 1e-6, r
    assert int(r["flipped_triangles"]) == 0, r
    # The area distortion the filter reports is the one measured here, and the cow, whose
    # automatic cones are its two ends, gets less of it than from the plain map.
    assert abs(number("std_log_area_ratio") - number("filter_std_log_area_ratio")) < 1e-3, r
    assert abs(number("plain_std_log_area_ratio") - number("filter_plain_std_log_area_ratio")) < 1e-3, r
    assert number("std_log_area_ratio") < 0.9 * number("plain_std_log_area_ratio"), r
areas = [float(r["std_log_area_ratio"]) for r in rows]
assert areas[0] > areas[1] > areas[2], areas

reader = vtkPNGReader()
reader.SetFileName(os.path.join(output, "orbifold_map.png"))
reader.Update()
image = reader.GetOutput()
width, height = image.GetDimensions()[:2]
assert (width, height) == (5 * 330, 330), (width, height)
pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(height, width, 3) / 255.0


def hues(panel):
    """Hues (degrees) of the panel's saturated pixels, and the panel's pixel count."""
    block = pixels[:, panel * 330:(panel + 1) * 330].reshape(-1, 3)
    hsv = np.array([colorsys.rgb_to_hsv(*p) for p in block[::3]])
    saturated = hsv[(hsv[:, 1] > 0.45) & (hsv[:, 2] > 0.25)]
    return saturated[:, 0] * 360, len(hsv)


# The copies' colors (orbifold_map.COPY_COLORS): blue, orange, green, red.
copy_hues = [205, 28, 120, 359]
for panel, n in ((2, 2), (3, 3), (4, 4)):
    h, count = hues(panel)
    share = [np.mean(np.minimum(abs(h - c), 360 - abs(h - c)) < 12) * len(h) / count for c in copy_hues]
    print(f"n = {n}: shares of the copies' hues", [round(s, 4) for s in share])
    assert all(s > 0.02 for s in share[:n]) and all(s < 0.002 for s in share[n:]), (n, share)
    # Seen from the pole, an n-fold symmetric map gives each copy the same share of the disk.
    assert max(share[:n]) < 1.25 * min(share[:n]), (n, share)
h, count = hues(0)
assert len(h) / count > 0.03, "the surface panel is blank"
print("orbifold_map.py: n = 2, 3, 4 symmetric, less area distortion than the plain map, picture as expected")
