"""Runs check_candidates.py on CGAL's cow (CC0) and a copy of it turned half a turn about the
z axis, and checks what it wrote:
the kept map is the right one (each vertex near its own copy), its candidate has the lowest
curvature difference of the candidates of its orientation (or, when two finished maps were
compared, the lower product of curvature difference and map stretch of the two), and asking
for the runner-up gives another map (the script wrote it) that is worse.

Usage: python3 test_check_candidates.py MESH_DIR OUTPUT_DIR   (the package on PYTHONPATH)
"""
import csv
import os
import subprocess
import sys

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLPolyDataReader

mesh_dir, output = sys.argv[1:3]
os.makedirs(output, exist_ok=True)
script = os.path.join(os.path.dirname(os.path.abspath(__file__)), "check_candidates.py")


def read_off(path):
    with open(path) as f:
        tokens = f.read().split()
    n, m = int(tokens[1]), int(tokens[2])
    points = np.array(tokens[4:4 + 3 * n], dtype=float).reshape(n, 3)
    faces = np.array(tokens[4 + 3 * n:4 + 3 * n + 4 * m], dtype=int).reshape(m, 4)[:, 1:]
    return points, faces


points, faces = read_off(os.path.join(mesh_dir, "cow.off"))
turned = points @ np.diag([-1.0, -1.0, 1.0])  # half a turn about z
copy = os.path.join(output, "cow-turned.off")
with open(copy, "w") as f:
    f.write(f"OFF\n{len(turned)} {len(faces)} 0\n")
    f.writelines(f"{x:.9g} {y:.9g} {z:.9g}\n" for x, y, z in turned)
    f.writelines(f"3 {a} {b} {c}\n" for a, b, c in faces)

result = subprocess.run([sys.executable, script, os.path.join(mesh_dir, "cow.off"), copy,
                         "--output", output], check=True, capture_output=True, text=True)
print(result.stdout)


def mean_error(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutput().GetPointData()
    mapped = vtk_to_numpy(data.GetArray("MappedPoints"))
    ids = vtk_to_numpy(data.GetArray("InputPointId")).astype(int)
    area = 0.5 * np.linalg.norm(np.cross(points[faces[:, 1]] - points[faces[:, 0]],
                                         points[faces[:, 2]] - points[faces[:, 0]]), axis=1).sum()
    return np.linalg.norm(mapped - turned[ids], axis=1).mean() / np.sqrt(area)


kept_error = mean_error(os.path.join(output, "kept.vtp"))
print(f"kept map: mean error {kept_error:.4f} sqrt(area)")
assert kept_error < 0.02, kept_error
with open(os.path.join(output, "candidates.csv")) as table:
    rows = list(csv.DictReader(table))
kept = [r for r in rows if r["kept"] == "1"]
assert len(kept) == 1, rows
same_side = [r for r in rows if (float(r["orientation_agreement"]) > 0.5) ==
             (float(kept[0]["orientation_agreement"]) > 0.5)]
finished = [r for r in rows if r["map_stretch"] != ""]
if len(finished) == 2:
    def product(r):
        return float(r["curvature_difference"]) * float(r["map_stretch"])
    assert product(kept[0]) == min(product(r) for r in finished), rows
else:
    assert float(kept[0]["curvature_difference"]) == min(float(r["curvature_difference"]) for r in same_side), rows
if os.path.exists(os.path.join(output, "runner-up.vtp")):
    other_error = mean_error(os.path.join(output, "runner-up.vtp"))
    print(f"runner-up map: mean error {other_error:.4f} sqrt(area)")
    assert other_error > kept_error + 0.05, (other_error, kept_error)
print("ok")
