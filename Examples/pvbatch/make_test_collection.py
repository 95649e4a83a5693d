"""Writes a bent, rotated copy of each mesh given: a collection of near-isometric pairs to try
the collection driver on (vertex i of a copy is vertex i of its original, so the maps can be
scored with mobius-score). Plain python3 with numpy; reads and writes OFF.

The bend: the mesh is bent into an arc along its longest principal axis, of radius 5 times
the spread along that axis (lengths across the axis change by a few percent), then rotated.

Usage: python3 make_test_collection.py OUTPUT_DIR MESH.off...
       (writes OUTPUT_DIR/NAME.off, a copy, and OUTPUT_DIR/NAME_bent.off for each mesh)
"""
import os
import shutil
import sys

import numpy as np


def read_off(path):
    with open(path) as f:
        tokens = f.read().split()
    if not tokens or tokens[0] != "OFF":
        raise SystemExit(f"{path}: not an OFF file")
    vertices, faces = int(tokens[1]), int(tokens[2])
    position = 4
    points = np.array(tokens[position:position + 3 * vertices], dtype=float).reshape(vertices, 3)
    position += 3 * vertices
    polygons = []
    for _ in range(faces):
        count = int(tokens[position])
        polygons.append(tokens[position + 1:position + 1 + count])
        position += 1 + count
    return points, polygons


def bent_copy(points):
    centered = points - points.mean(axis=0)
    spreads, frame = np.linalg.eigh(centered.T @ centered / len(points))  # ascending
    radius = 5 * np.sqrt(spreads[2])
    y = centered @ frame
    angle = y[:, 2] / radius
    arc = np.stack([y[:, 0], (radius + y[:, 1]) * np.cos(angle) - radius,
                    (radius + y[:, 1]) * np.sin(angle)], axis=1)
    c, s = np.cos(0.7), np.sin(0.7)
    rotation = np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]]) @ np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    return (arc @ frame.T) @ rotation.T


def write_off(path, points, polygons):
    with open(path, "w") as f:
        f.write(f"OFF\n{len(points)} {len(polygons)} 0\n")
        f.writelines("%.9g %.9g %.9g\n" % tuple(p) for p in points)
        f.writelines(f"{len(p)} {' '.join(p)}\n" for p in polygons)


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    output = sys.argv[1]
    os.makedirs(output, exist_ok=True)
    for mesh in sys.argv[2:]:
        name = os.path.splitext(os.path.basename(mesh))[0]
        points, polygons = read_off(mesh)
        shutil.copyfile(mesh, os.path.join(output, name + ".off"))
        write_off(os.path.join(output, name + "_bent.off"), bent_copy(points), polygons)
        print(f"{name}: {len(points)} vertices, bent copy written")


if __name__ == "__main__":
    main()
