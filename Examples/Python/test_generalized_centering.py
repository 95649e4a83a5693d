"""Runs generalized_centering.py on CGAL's hand (CC0) at degrees 1, 2 and 3 and checks what it
wrote: degree 1 is the Möbius centering (no advection), degree 2 converges and trades angle
distortion for area distortion (the paper's Figure 5), no triangle flips, and the picture
shows the maps colored by the log area ratio.

Usage: python3 test_generalized_centering.py MESH_DIR OUTPUT_DIR   (the package on PYTHONPATH,
X display)
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
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "generalized_centering.py")
hand = os.path.join(mesh_dir, "hand.off")
subprocess.run([sys.executable, script, hand, "--output", output, "--degrees", "1", "2", "3"], check=True)

with open(os.path.join(output, "generalized_centering.csv")) as table:
    rows = {int(r["degree"]): r for r in csv.DictReader(table)}
assert sorted(rows) == [1, 2, 3], rows
area = {d: float(r["area_distortion"]) for d, r in rows.items()}
angle = {d: float(r["angle_distortion"]) for d, r in rows.items()}
assert all(int(r["flipped_triangles"]) == 0 for r in rows.values()), rows
# Degree 1: the Möbius centering alone, a conformal map up to discretization.
assert int(rows[1]["steps"]) == 0 and float(rows[1]["moments_left"]) < 1e-9, rows[1]
assert 1.0 <= angle[1] < 1.2, angle
# Degree 2 reaches its tolerance: the moments of degrees 1 and 2 vanish.
assert rows[2]["converged"] == "1" and 0 < int(rows[2]["steps"]) < 200, rows[2]
assert float(rows[2]["moments_left"]) < 1e-9, rows[2]
# ... and spreads area more evenly at the cost of conformality; degree 3 further still.
assert area[3] < area[2] < area[1] and angle[1] < angle[2] < angle[3], (area, angle)
assert area[2] < 0.97 * area[1] and angle[2] > 1.1 * angle[1], (area, angle)

reader = vtkPNGReader()
reader.SetFileName(os.path.join(output, "generalized_centering.png"))
reader.Update()
image = reader.GetOutput()
width, height = image.GetDimensions()[:2]
assert (width, height) == (4 * 330, 380), (width, height)
pixels = vtk_to_numpy(image.GetPointData().GetScalars())[:, :3].reshape(height, width, 3) / 255.0
for panel in (1, 2, 3):
    block = pixels[:, panel * 330:(panel + 1) * 330].reshape(-1, 3)[::3]
    hsv = np.array([colorsys.rgb_to_hsv(*p) for p in block])
    saturated = hsv[hsv[:, 1] > 0.35]
    red = np.mean((saturated[:, 0] < 0.05) | (saturated[:, 0] > 0.95)) * len(saturated) / len(hsv)
    blue = np.mean(abs(saturated[:, 0] - 0.63) < 0.06) * len(saturated) / len(hsv)
    print(f"panel {panel}: red {red:.3f}, blue {blue:.3f} of the pixels")
    # Each map shows enlarged (red) and squeezed (blue) triangles.
    assert red > 0.01 and blue > 0.003, (panel, red, blue)
print("generalized_centering.py: degrees 1-3 as in Figure 5, picture as expected")
