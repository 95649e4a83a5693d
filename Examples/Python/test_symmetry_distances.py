"""Runs symmetry_distances.py on two small CC0 meshes and checks what it wrote, so that the
Figure 8 and 9 script of docs/symmetry.md keeps working.

Usage: python3 test_symmetry_distances.py MESH_DIR OUTPUT_DIR   (the package on PYTHONPATH)
"""
import csv
import os
import subprocess
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

mesh_dir, output = sys.argv[1:3]
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "symmetry_distances.py")
meshes = [os.path.join(mesh_dir, name) for name in ("cow.off", "hand.off", "eight.off")]
subprocess.run([sys.executable, script, "--output", output, "--resolution", "64", *meshes], check=True)

with open(os.path.join(output, "symmetry_distances.csv")) as table:
    rows = list(csv.DictReader(table))
runs = [r for r in rows if r["distance"]]
# Three meshes x (original, bent) x (centered, uncentered, moved): the genus-2 eight is
# repaired into a genus-0 proxy (its two handles cut) and run like the others.
assert len(runs) == 18, rows
assert {(r["mesh"], r["shape"], r["variant"]) for r in runs} == {
    (m, s, v) for m in ("cow", "hand", "eight") for s in ("original", "bent") for v in ("centered", "uncentered", "moved")}
assert all(0 <= float(r["distance"]) <= 1 for r in runs)


def distance(mesh, shape, variant):
    return next(float(r["distance"]) for r in runs if (r["mesh"], r["shape"], r["variant"]) == (mesh, shape, variant))


# The cow is nearly symmetric once centered (0.04 at this resolution); an arbitrary Möbius
# transformation of its map hides the symmetry (0.22), which centering undoes.
assert distance("cow", "original", "centered") < 0.08
assert distance("cow", "original", "moved") > 2 * distance("cow", "original", "centered")


def image(name):
    reader = vtkPNGReader()
    reader.SetFileName(os.path.join(output, name))
    reader.Update()
    data = reader.GetOutput()
    pixels = vtk_to_numpy(data.GetPointData().GetScalars())
    return data.GetDimensions()[:2], pixels[:, :3].astype(int)


size, pixels = image("symmetry_distances.png")
assert size == (640, 420), size
# The three curves: blue (centered), red (Centering off), orange (moved) pixels.
for rgb in ((31, 119, 180), (214, 39, 40), (255, 127, 14)):
    assert (abs(pixels - rgb).sum(axis=1) < 30).sum() > 100, rgb
size, pixels = image("symmetry_asymmetry.png")
assert size == (1200, 560), size
# Not blank: the colored cow and sphere cover part of the white background.
assert (pixels.sum(axis=1) < 600).mean() > 0.05
print("symmetry_distances.py: 12 runs, figures written")
